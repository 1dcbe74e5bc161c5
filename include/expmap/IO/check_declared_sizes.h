// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_IO_CHECK_DECLARED_SIZES_H
#define EXPMAP_IO_CHECK_DECLARED_SIZES_H

/// \file check_declared_sizes.h
/// A guard to call before CGAL reads a mesh file: the counts the file
/// declares must fit in its size, so that reading it needs memory in
/// proportion to the file, not to what its header claims.

#include <expmap/Errors.h>
#include <expmap/IO/internal/Declared_size_scanner.h>
#include <expmap/IO/internal/check_off_sizes.h>
#include <expmap/IO/internal/check_ply_sizes.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace expmap {
namespace IO {

/// \ingroup PkgExpmapIO
/// Checks that every count the mesh file at `path` declares fits in the
/// file: the vertex and face counts of an OFF header and the vertex count
/// at the start of each face line; the element counts of a PLY header and
/// the length of each list (a face's vertices). OBJ and STL declare no
/// counts (CGAL's readers grow with what they read), so they pass.
///
/// CGAL's readers allocate for the declared counts before reading: without
/// this check an OFF file of 170 KB whose header claims 10^9 faces makes
/// the reader ask for 24 GB. The check reads the file once, line by line
/// (about as long as parsing it), and allocates nothing in proportion to it.
///
/// \code
/// expmap::IO::check_declared_sizes(path);   // throws on a lying header
/// CGAL::IO::read_polygon_mesh(path, mesh);
/// \endcode
/// \throws Invalid_input if the file cannot be opened or declares more than
/// it can hold; the message names the file and the count.
inline void check_declared_sizes(const std::string& path) {
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  std::ifstream in(path, std::ios::binary);
  if (error || !in) throw Invalid_input("cannot open mesh file '" + path + "'");
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  internal::Declared_size_scanner file(in, size, path);
  if (extension == ".off")
    internal::check_off_sizes(file);
  else if (extension == ".ply")
    internal::check_ply_sizes(file);
}

}  // namespace IO
}  // namespace expmap

#endif  // EXPMAP_IO_CHECK_DECLARED_SIZES_H
