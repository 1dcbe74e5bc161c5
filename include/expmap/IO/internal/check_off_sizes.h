// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_IO_INTERNAL_CHECK_OFF_SIZES_H
#define EXPMAP_IO_INTERNAL_CHECK_OFF_SIZES_H

/// \file check_off_sizes.h
/// The counts an OFF file declares, checked against its size before CGAL's
/// reader allocates for them. CGAL 5.5 resizes its arrays to the header's
/// vertex and face counts, and each face to the vertex count at the start of
/// its line, before reading them: a 170 KB file whose header claims 10^9
/// faces asks for 24 GB.

#include <expmap/IO/internal/Declared_size_scanner.h>

#include <cctype>
#include <cstdint>
#include <sstream>
#include <string>

namespace expmap {
namespace IO {
namespace internal {

/// Skips white space and `#` comment lines, as CGAL's OFF scanner does
/// before each vertex and face line.
inline void skip_off_comments(std::istream& in) {
  char c;
  while (in >> c) {
    if (c != '#') {
      in.putback(c);
      return;
    }
    std::string ignored;
    std::getline(in, ignored);
  }
}

inline std::int64_t read_big_endian_int32(std::istream& in) {
  unsigned char b[4] = {0, 0, 0, 0};
  in.read(reinterpret_cast<char*>(b), 4);
  const std::uint32_t u = (std::uint32_t(b[0]) << 24) | (std::uint32_t(b[1]) << 16) |
                          (std::uint32_t(b[2]) << 8) | std::uint32_t(b[3]);
  return static_cast<std::int32_t>(u);
}

/// Checks an OFF file (ASCII or plain binary): header counts, then each
/// face's vertex count against the numbers on its line (ASCII) or the bytes
/// left (binary). Leaves files that are not OFF to CGAL's reader, which
/// refuses them without allocating.
/// \throws Invalid_input naming the count that cannot fit.
inline void check_off_sizes(Declared_size_scanner& file) {
  std::istream& in = file.stream();
  skip_off_comments(in);
  std::string keyword;
  for (char c; in.get(c) && std::isalnum(static_cast<unsigned char>(c));) keyword += c;
  if (keyword.size() < 3 || keyword.compare(keyword.size() - 3, 3, "OFF") != 0) return;
  const std::string prefix = keyword.substr(0, keyword.size() - 3);
  const bool dimensional = prefix.find('n') != std::string::npos;

  skip_off_comments(in);
  bool binary = false;
  if (std::isalpha(in.peek())) {
    std::string word;
    in >> word;
    if (word != "BINARY") return;  // CGAL refuses it
    binary = true;
    std::string rest_of_line;
    std::getline(in, rest_of_line);
  }

  std::int64_t vertices = 0, faces = 0;
  if (binary) {
    if (!prefix.empty())
      file.fail("binary OFF with normals, colors, textures or extra dimensions (" + keyword +
                ") is not supported; write it as ASCII OFF");
    vertices = read_big_endian_int32(in);
    faces = read_big_endian_int32(in);
    read_big_endian_int32(in);  // edges, unused
    if (!in) file.fail("the binary OFF header is truncated");
  } else {
    std::string dimension, v, f, edges;
    if (dimensional) in >> dimension;
    in >> v >> f >> edges;  // the edge count is unused, but CGAL reads it
    long long value = 0;
    if (!in || !parse_integer(v, value)) return;  // CGAL refuses a malformed header
    vertices = value;
    if (!parse_integer(f, value)) return;
    faces = value;
  }
  if (vertices < 0 || faces < 0)
    file.fail("the OFF header declares a negative count (" + std::to_string(vertices) +
              " vertices, " + std::to_string(faces) + " faces)");

  // ASCII: a vertex takes at least "0 0 0\n" (6 bytes; 2 for the rare nOFF
  // of lower dimension), a face at least "0\n". Binary: 12 and 4 bytes.
  const std::uint64_t vertex_bytes = binary ? 12 : dimensional ? 2 : 6;
  const std::uint64_t face_bytes = binary ? 4 : 2;
  const std::uint64_t left = file.bytes_left();
  const auto nv = static_cast<std::uint64_t>(vertices), nf = static_cast<std::uint64_t>(faces);
  if (nv > left / vertex_bytes || nf > (left - nv * vertex_bytes) / face_bytes)
    file.fail("the OFF header declares " + std::to_string(nv) + " vertices and " +
              std::to_string(nf) + " faces, but only " + std::to_string(left) +
              " bytes follow it (the header is wrong or the file is truncated)");

  if (binary) {
    in.seekg(static_cast<std::streamoff>(nv * vertex_bytes), std::ios::cur);
    for (std::uint64_t face = 0; face < nf; ++face) {
      const std::int64_t corners = read_big_endian_int32(in);
      if (!in) file.fail("the file ends at face " + std::to_string(face) + " of " + std::to_string(nf));
      if (corners < 0) file.fail("face " + std::to_string(face) + " has a negative vertex count");
      if (worth_checking(static_cast<std::uint64_t>(corners)))
        file.require_room(static_cast<std::uint64_t>(corners), 4,
                          "face " + std::to_string(face) + " declares vertex count");
      in.seekg(static_cast<std::streamoff>(4 * corners), std::ios::cur);
    }
    return;
  }

  std::string line;
  for (std::uint64_t vertex = 0; vertex < nv; ++vertex) {
    skip_off_comments(in);
    if (!std::getline(in, line)) return;  // truncated: CGAL reports it
  }
  for (std::uint64_t face = 0; face < nf; ++face) {
    skip_off_comments(in);
    if (!std::getline(in, line)) return;
    line = line.substr(0, line.find('#'));
    std::istringstream numbers(line);
    std::string first;
    numbers >> first;
    const double corners = std::strtod(first.c_str(), nullptr);
    std::size_t indices = 0;
    for (std::string token; numbers >> token;) ++indices;
    // CGAL reads the count as a double and casts it to an unsigned size: a
    // negative, huge or non-finite count becomes an allocation of gigabytes.
    if (!(corners >= 0 && corners <= static_cast<double>(indices)))
      file.fail("face " + std::to_string(face) + " declares " + first + " vertices but its line lists " +
                std::to_string(indices) + " numbers after the count");
  }
}

}  // namespace internal
}  // namespace IO
}  // namespace expmap

#endif  // EXPMAP_IO_INTERNAL_CHECK_OFF_SIZES_H
