// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_IO_INTERNAL_DECLARED_SIZE_SCANNER_H
#define EXPMAP_IO_INTERNAL_DECLARED_SIZE_SCANNER_H

/// \file Declared_size_scanner.h
/// What the format checks share: a stream over one mesh file that knows how
/// many bytes are left, and the error naming the file.

#include <expmap/Errors.h>

#include <cstdint>
#include <istream>
#include <string>
#include <utility>

namespace expmap {
namespace IO {
namespace internal {

/// Reads a mesh file front to back and answers "can the rest of the file
/// hold that many items?". Counts a file declares are compared with
/// `bytes_left()` before anyone allocates for them.
class Declared_size_scanner {
 public:
  Declared_size_scanner(std::istream& in, std::uint64_t file_size, std::string path)
      : in_(in), file_size_(file_size), path_(std::move(path)) {}

  std::istream& stream() { return in_; }

  std::uint64_t bytes_left() {
    const auto position = in_.tellg();
    if (position < 0) return 0;
    const auto offset = static_cast<std::uint64_t>(position);
    return offset < file_size_ ? file_size_ - offset : 0;
  }

  /// Throws `Invalid_input` with `problem` after the file's name.
  [[noreturn]] void fail(const std::string& problem) const {
    throw Invalid_input("cannot read '" + path_ + "': " + problem);
  }

  /// Fails unless `count` items of at least `bytes_each` bytes (and at least
  /// one byte each, so that loops over them are bounded too) fit in the
  /// bytes left. Overflow-safe for any count.
  void require_room(std::uint64_t count, std::uint64_t bytes_each, const std::string& what) {
    const std::uint64_t left = bytes_left();
    const std::uint64_t each = bytes_each ? bytes_each : 1;
    if (count > left / each)
      fail(what + " " + std::to_string(count) + " but only " + std::to_string(left) +
           " bytes follow, room for at most " + std::to_string(left / each) +
           " (the header or a count in the file is wrong, or the file is truncated)");
  }

 private:
  std::istream& in_;
  std::uint64_t file_size_;
  std::string path_;
};

/// Lengths up to this are harmless whatever the file's size (half a
/// megabyte of indices at most); only longer ones are compared with the bytes
/// left, which costs a seek.
inline bool worth_checking(std::uint64_t length) { return length > 65535; }

/// The integer `text` spells exactly (optional sign, digits), or false.
inline bool parse_integer(const std::string& text, long long& value) {
  if (text.empty() || text.size() > 19) return false;
  std::size_t i = (text[0] == '-' || text[0] == '+') ? 1 : 0;
  if (i == text.size()) return false;
  long long v = 0;
  for (; i < text.size(); ++i) {
    if (text[i] < '0' || text[i] > '9') return false;
    v = 10 * v + (text[i] - '0');
  }
  value = text[0] == '-' ? -v : v;
  return true;
}

}  // namespace internal
}  // namespace IO
}  // namespace expmap

#endif  // EXPMAP_IO_INTERNAL_DECLARED_SIZE_SCANNER_H
