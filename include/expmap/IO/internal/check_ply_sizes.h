// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_IO_INTERNAL_CHECK_PLY_SIZES_H
#define EXPMAP_IO_INTERNAL_CHECK_PLY_SIZES_H

/// \file check_ply_sizes.h
/// The counts a PLY file declares, checked against its size before CGAL's
/// reader allocates for them: CGAL 5.5 reserves room for each element's
/// declared count, and resizes each list property (a face's vertices) to the
/// length stored in front of it.

#include <expmap/IO/internal/Declared_size_scanner.h>

#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

namespace expmap {
namespace IO {
namespace internal {

/// Size in bytes of a PLY scalar type, 0 if the name is unknown.
inline std::uint64_t ply_type_size(const std::string& type) {
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" ||
      type == "float32")
    return 4;
  if (type == "double" || type == "float64") return 8;
  return 0;
}

struct Ply_property {
  std::uint64_t value_size = 0;  // bytes of a scalar, or of each list item
  std::uint64_t count_size = 0;  // bytes of a list's length; 0 for a scalar
};

struct Ply_element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Ply_property> properties;
};

/// Reads a list length or scalar stored in `bytes` bytes, as an integer.
inline bool read_ply_binary_count(std::istream& in, std::uint64_t bytes, bool big_endian,
                                  std::uint64_t& value) {
  unsigned char b[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  if (!in.read(reinterpret_cast<char*>(b), static_cast<std::streamsize>(bytes))) return false;
  value = 0;
  for (std::uint64_t i = 0; i < bytes; ++i)
    value |= std::uint64_t(b[big_endian ? i : bytes - 1 - i]) << (8 * (bytes - 1 - i));
  return true;  // a signed length with its sign bit set reads as huge: refused by size
}

/// Checks a PLY file (ASCII or binary): each element's count against the
/// bytes after the header, then every list length against the bytes left.
/// Leaves files without a PLY header to CGAL's reader.
/// \throws Invalid_input naming the count that cannot fit.
inline void check_ply_sizes(Declared_size_scanner& file) {
  std::istream& in = file.stream();
  std::string line;
  if (!std::getline(in, line) || line.substr(0, 3) != "ply") return;
  std::string format;
  std::vector<Ply_element> elements;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string word;
    words >> word;
    if (word == "end_header") break;
    if (word == "format") {
      words >> format;
    } else if (word == "element") {
      Ply_element element;
      std::string count;
      words >> element.name >> count;
      long long value = 0;
      if (!parse_integer(count, value) || value < 0)
        file.fail("PLY element '" + element.name + "' has count '" + count +
                  "', not a non-negative integer");
      element.count = static_cast<std::uint64_t>(value);
      elements.push_back(element);
    } else if (word == "property" && !elements.empty()) {
      std::string type;
      words >> type;
      Ply_property property;
      if (type == "list") {
        std::string count_type, item_type;
        words >> count_type >> item_type;
        property.count_size = ply_type_size(count_type);
        property.value_size = ply_type_size(item_type);
        if (!property.count_size || !property.value_size) return;  // CGAL refuses it
      } else {
        property.value_size = ply_type_size(type);
        if (!property.value_size) return;
      }
      elements.back().properties.push_back(property);
    }
  }
  if (!in) return;  // no end_header: CGAL refuses it
  const bool ascii = format == "ascii";
  const bool big_endian = format == "binary_big_endian";
  if (!ascii && !big_endian && format != "binary_little_endian") return;

  // ASCII: at least a digit and a separator per value; binary: the sizes.
  for (const Ply_element& element : elements) {
    std::uint64_t least = 0;
    for (const Ply_property& p : element.properties)
      least += ascii ? 2 : (p.count_size ? p.count_size : p.value_size);
    file.require_room(element.count, least, "PLY element '" + element.name + "' declares count");
  }

  for (const Ply_element& element : elements)
    for (std::uint64_t item = 0; item < element.count; ++item)
      for (const Ply_property& p : element.properties) {
        const std::string where = "item " + std::to_string(item) + " of PLY element '" +
                                  element.name + "'";
        if (ascii) {
          std::string token;
          if (!(in >> token)) return;  // truncated: CGAL reports it
          if (!p.count_size) continue;
          long long length = 0;
          if (!parse_integer(token, length) || length < 0)
            file.fail(where + " has list length '" + token + "'");
          if (worth_checking(static_cast<std::uint64_t>(length)))
            file.require_room(static_cast<std::uint64_t>(length), 2, where + " declares list length");
          for (long long k = 0; k < length; ++k) in >> token;
        } else if (!p.count_size) {
          in.seekg(static_cast<std::streamoff>(p.value_size), std::ios::cur);
        } else {
          std::uint64_t length = 0;
          if (!read_ply_binary_count(in, p.count_size, big_endian, length)) return;
          if (worth_checking(length))
            file.require_room(length, p.value_size, where + " declares list length");
          in.seekg(static_cast<std::streamoff>(length * p.value_size), std::ios::cur);
        }
      }
}

}  // namespace internal
}  // namespace IO
}  // namespace expmap

#endif  // EXPMAP_IO_INTERNAL_CHECK_PLY_SIZES_H
