// Replaces the global operator new and delete with malloc-based ones that count every
// allocation in g_allocations, so a test can check that a per-frame path allocates nothing.
// Include it in exactly one source file of a test executable: the replacements are
// definitions, global to the whole program.
#pragma once

#include <atomic>
#include <cstdlib>
#include <new>

inline std::atomic<long> g_allocations{0};

// GCC cannot see that the replaced operator new below is malloc-based and warns that its
// free() does not match; the pairing is ours and correct.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"

void* operator new(std::size_t size) {
  ++g_allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) { return operator new(size); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
