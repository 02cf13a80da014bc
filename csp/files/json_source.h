// JsonSource: a JSON document's text, parsed by nlohmann's parser, and the positions a
// reader's messages name. Shared by the readers of JSON files (toulbar2's .cfn, the pose
// file), so that they refuse bad input the same way: text that is not JSON at the line and
// column where it stops being JSON, a key given twice in one object (JSON's own readers
// would silently keep the last), a number no double holds; and a reader's own checks at
// the line of the key they are about (the parsed document keeps no positions).
//
// Offsets are 1-based character positions in the text; 0 stands for "no position" (the
// file alone).
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "sightline/csp/input_error.h"

namespace sightline::csp {

class JsonSource {
 public:
  // `text` must outlive the source.
  JsonSource(std::string_view text, std::string origin) : text_(text), origin_(std::move(origin)) {}

  // The document, keys in file order. `hint` is appended to the message for text that is
  // not JSON (say, which near-JSON dialect is not read). Throws InputError.
  nlohmann::ordered_json parse(const std::string& hint = "") const;

  [[noreturn]] void fail(std::size_t offset, const std::string& message) const;
  SourceLocation location(std::size_t offset) const;
  // Where `"key":` appears at or after `from`; 0 when it does not.
  std::size_t find_key(const std::string& key, std::size_t from = 0) const;

  std::string_view text() const { return text_; }
  const std::string& origin() const { return origin_; }

 private:
  std::string_view text_;
  std::string origin_;
};

}  // namespace sightline::csp
