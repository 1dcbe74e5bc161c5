// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_IO_WRITE_NPZ_H
#define EXPMAP_IO_WRITE_NPZ_H

/// \file write_npz.h
/// NumPy's `.npz` format, written without NumPy: a zip archive whose
/// entries, stored uncompressed, are `.npy` files (format version 1.0).
/// `numpy.load()` reads it back as a dictionary of arrays.

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace expmap {
namespace IO {

/// \ingroup PkgExpmapIO
/// One array of an `.npz` file: a view of values the caller keeps alive
/// until `write_npz()` returns. Make it with `npy_array()`.
struct Npy_array {
  std::string name;                 ///< entry name in the archive, without `.npy`
  std::string descr;                ///< NumPy type, e.g. `<f8` (see `npy_descr()`)
  std::vector<std::size_t> shape;   ///< row-major (C order)
  const unsigned char* data = nullptr;  ///< `bytes` bytes of elements, owned by the caller
  std::size_t bytes = 0;            ///< product of `shape` times the element size
};

/// \ingroup PkgExpmapIO
/// NumPy's name of the type `T` (an arithmetic type other than bool) in
/// this machine's byte order, e.g. `<f8` for double on x86.
template <class T>
std::string npy_descr() {
  static_assert(std::is_arithmetic<T>::value && !std::is_same<T, bool>::value,
                "npy_descr: integers and floating-point types only");
  const std::uint16_t probe = 1;
  unsigned char first;
  std::memcpy(&first, &probe, 1);
  const char order = sizeof(T) == 1 ? '|' : (first == 1 ? '<' : '>');
  const char kind = std::is_floating_point<T>::value ? 'f' : (std::is_signed<T>::value ? 'i' : 'u');
  return std::string(1, order) + kind + std::to_string(sizeof(T));
}

/// \ingroup PkgExpmapIO
/// A one-dimensional array named `name` over `values` (not copied).
template <class T>
Npy_array npy_array(std::string name, const std::vector<T>& values) {
  return Npy_array{std::move(name), npy_descr<T>(), {values.size()},
                   reinterpret_cast<const unsigned char*>(values.data()), values.size() * sizeof(T)};
}

namespace internal {

/// CRC-32 (ISO 3309, the zip checksum) of `bytes`, continuing from `crc`
/// (0 for a fresh checksum).
inline std::uint32_t crc32(const unsigned char* bytes, std::size_t size, std::uint32_t crc = 0) {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t n = 0; n < 256; ++n) {
      std::uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  crc = ~crc;
  for (std::size_t i = 0; i < size; ++i) crc = table[(crc ^ bytes[i]) & 0xFF] ^ (crc >> 8);
  return ~crc;
}

/// The header of an `.npy` file of version 1.0: magic, version, length,
/// and the dictionary of type, order and shape, padded with spaces so that
/// the data starts at a multiple of 64 bytes, as NumPy writes it.
inline std::string npy_header(const Npy_array& a) {
  std::string shape = "(";
  for (std::size_t i = 0; i < a.shape.size(); ++i)
    shape += (i ? ", " : "") + std::to_string(a.shape[i]);
  shape += a.shape.size() == 1 ? ",)" : ")";
  std::string dict = "{'descr': '" + a.descr + "', 'fortran_order': False, 'shape': " + shape + ", }";
  const std::size_t preamble = 10;  // magic (6), version (2), header length (2)
  dict.append(63 - (preamble + dict.size()) % 64, ' ');
  dict += '\n';
  std::string header("\x93NUMPY\x01\x00", 8);
  header += static_cast<char>(dict.size() & 0xFF);
  header += static_cast<char>(dict.size() >> 8);
  return header + dict;
}

/// Little-endian fields of a zip record, as the format prescribes on every
/// machine.
class Zip_record {
 public:
  Zip_record& u16(std::uint32_t v) { return put(v, 2); }
  Zip_record& u32(std::uint64_t v) { return put(v, 4); }
  Zip_record& text(const std::string& s) {
    bytes += s;
    return *this;
  }
  std::string bytes;

 private:
  Zip_record& put(std::uint64_t v, int size) {
    for (int i = 0; i < size; ++i) bytes += static_cast<char>((v >> (8 * i)) & 0xFF);
    return *this;
  }
};

}  // namespace internal

/// \ingroup PkgExpmapIO
/// Writes `arrays` as an `.npz` archive to `out` (open it in binary mode):
/// one stored (uncompressed) zip entry `NAME.npy` per array, in the given
/// order, with CRC-32 checksums; entries carry the date 1980-01-01 so the
/// same arrays always give the same bytes.
///
/// \code
/// std::vector<double> r = ...;
/// std::vector<std::int64_t> vertex = ...;
/// std::ofstream out("maps.npz", std::ios::binary);
/// expmap::IO::write_npz(out, {expmap::IO::npy_array("r", r), expmap::IO::npy_array("vertex", vertex)});
/// // Python: numpy.load("maps.npz")["r"]
/// \endcode
/// \throws std::length_error if the archive would reach 4 GiB or hold
///         65,535 entries (the limits of zip without its zip64 extension),
///         before anything is written.
/// \returns `out`, whose state tells whether writing succeeded.
inline std::ostream& write_npz(std::ostream& out, const std::vector<Npy_array>& arrays) {
  const std::uint32_t dos_time = 0, dos_date = (0 << 9) | (1 << 5) | 1;  // 1980-01-01 00:00
  const std::uint32_t version = 20;                                       // zip 2.0
  std::vector<std::string> headers, names;
  std::uint64_t total = 22;  // end of central directory record
  for (const Npy_array& a : arrays) {
    headers.push_back(internal::npy_header(a));
    names.push_back(a.name + ".npy");
    total += 30 + 46 + 2 * names.back().size() + headers.back().size() + a.bytes;
  }
  if (arrays.size() >= 0xFFFF || total >= std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("the .npz archive would need " + std::to_string(total) + " bytes in " +
                            std::to_string(arrays.size()) +
                            " entries, beyond the 4 GiB and 65,535 entries of plain zip");

  internal::Zip_record directory;
  std::uint64_t offset = 0;
  for (std::size_t i = 0; i < arrays.size(); ++i) {
    const std::string& header = headers[i];
    const std::uint32_t crc = internal::crc32(
        arrays[i].data, arrays[i].bytes,
        internal::crc32(reinterpret_cast<const unsigned char*>(header.data()), header.size()));
    const std::uint64_t size = header.size() + arrays[i].bytes;
    internal::Zip_record local;
    local.u32(0x04034b50).u16(version).u16(0).u16(0).u16(dos_time).u16(dos_date);
    local.u32(crc).u32(size).u32(size).u16(names[i].size()).u16(0).text(names[i]);
    directory.u32(0x02014b50).u16(version).u16(version).u16(0).u16(0).u16(dos_time).u16(dos_date);
    directory.u32(crc).u32(size).u32(size).u16(names[i].size()).u16(0).u16(0).u16(0).u16(0);
    directory.u32(0).u32(offset).text(names[i]);
    out.write(local.bytes.data(), static_cast<std::streamsize>(local.bytes.size()));
    out.write(header.data(), static_cast<std::streamsize>(header.size()));
    out.write(reinterpret_cast<const char*>(arrays[i].data),
              static_cast<std::streamsize>(arrays[i].bytes));
    offset += local.bytes.size() + size;
  }
  internal::Zip_record end;
  end.u32(0x06054b50).u16(0).u16(0).u16(arrays.size()).u16(arrays.size());
  end.u32(directory.bytes.size()).u32(offset).u16(0);
  out.write(directory.bytes.data(), static_cast<std::streamsize>(directory.bytes.size()));
  out.write(end.bytes.data(), static_cast<std::streamsize>(end.bytes.size()));
  return out;
}

}  // namespace IO
}  // namespace expmap

#endif  // EXPMAP_IO_WRITE_NPZ_H
