// ZeroedArray: a fixed-size array of plain values that starts all zero without writing them.
//
// Local search keeps per-variable arrays that must read zero at each start (tabu marks) but
// of which a run often touches only a small part: on 1,000,000-queens placement settles all
// but a few hundred variables, and the swaps that follow touch those few. A std::vector
// assign() writes every element, which at a million variables means faulting in and
// filling megabytes the run never reads. Here reset() takes the block from calloc: a large
// fresh block comes as untouched zero pages from the operating system, which are faulted in
// (and zeroed) only when first used; a block that reuses freed memory is zeroed by calloc
// itself, no worse than assign(). Only for types whose all-zero bytes are the value zero.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>
#include <type_traits>

namespace sightline::solvers::detail {

template <class T>
class ZeroedArray {
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>,
                "ZeroedArray holds plain values");

 public:
  // `size` elements, every byte zero; the old contents are dropped.
  void reset(std::size_t size) {
    data_.reset();
    size_ = 0;
    if (size == 0) return;
    data_.reset(static_cast<T*>(std::calloc(size, sizeof(T))));
    if (!data_) throw std::bad_alloc();
    size_ = size;
  }

  std::size_t size() const { return size_; }
  T& operator[](std::size_t i) { return data_.get()[i]; }
  const T& operator[](std::size_t i) const { return data_.get()[i]; }

 private:
  struct Free {
    void operator()(T* p) const { std::free(p); }
  };
  std::unique_ptr<T, Free> data_;
  std::size_t size_ = 0;
};

}  // namespace sightline::solvers::detail
