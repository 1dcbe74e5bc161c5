// The .npz writer: a zip archive read back here field by field, following
// the zip specification (PKWARE APPNOTE) and NumPy's .npy format, not the
// writer's code.
#include <expmap/IO/write_npz.h>

#include <boost/test/unit_test.hpp>

#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

namespace {

std::uint64_t read_le(const std::string& s, std::size_t at, int size) {
  BOOST_REQUIRE_LE(at + size, s.size());
  std::uint64_t v = 0;
  for (int i = size - 1; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(s[at + i]);
  return v;
}

struct Entry {
  std::string name, npy;  // the stored bytes: an .npy file
  std::uint32_t crc;
};

// Reads an archive from its end: the end record, the central directory, and
// through it each local header and its data.
std::vector<Entry> read_zip(const std::string& zip) {
  BOOST_REQUIRE_GE(zip.size(), 22u);
  const std::size_t end = zip.size() - 22;
  BOOST_REQUIRE_EQUAL(read_le(zip, end, 4), 0x06054b50u);
  const std::size_t count = read_le(zip, end + 10, 2);
  BOOST_CHECK_EQUAL(read_le(zip, end + 8, 2), count);
  const std::size_t directory_size = read_le(zip, end + 12, 4);
  std::size_t at = read_le(zip, end + 16, 4);
  BOOST_CHECK_EQUAL(at + directory_size, end);
  std::vector<Entry> entries;
  for (std::size_t i = 0; i < count; ++i) {
    BOOST_REQUIRE_EQUAL(read_le(zip, at, 4), 0x02014b50u);
    BOOST_CHECK_EQUAL(read_le(zip, at + 10, 2), 0u);  // stored
    const std::uint32_t crc = read_le(zip, at + 16, 4);
    const std::size_t compressed = read_le(zip, at + 20, 4), size = read_le(zip, at + 24, 4);
    BOOST_CHECK_EQUAL(compressed, size);
    const std::size_t name_length = read_le(zip, at + 28, 2);
    const std::size_t extra = read_le(zip, at + 30, 2), comment = read_le(zip, at + 32, 2);
    const std::size_t local = read_le(zip, at + 42, 4);
    const std::string name = zip.substr(at + 46, name_length);
    at += 46 + name_length + extra + comment;

    BOOST_REQUIRE_EQUAL(read_le(zip, local, 4), 0x04034b50u);
    BOOST_CHECK_EQUAL(read_le(zip, local + 14, 4), crc);
    BOOST_CHECK_EQUAL(read_le(zip, local + 22, 4), size);
    const std::size_t local_name = read_le(zip, local + 26, 2);
    const std::size_t local_extra = read_le(zip, local + 28, 2);
    BOOST_CHECK_EQUAL(zip.substr(local + 30, local_name), name);
    const std::size_t data = local + 30 + local_name + local_extra;
    BOOST_REQUIRE_LE(data + size, zip.size());
    entries.push_back({name, zip.substr(data, size), crc});
  }
  BOOST_CHECK_EQUAL(at, end);
  return entries;
}

// The .npy header's dictionary without its padding, checked for version
// 1.0 and for the 64-byte alignment of the data.
std::string npy_dictionary(const std::string& npy) {
  BOOST_REQUIRE_GE(npy.size(), 10u);
  BOOST_CHECK_EQUAL(npy.substr(0, 8), std::string("\x93NUMPY\x01\x00", 8));
  const std::size_t length = read_le(npy, 8, 2);
  BOOST_CHECK_EQUAL((10 + length) % 64, 0u);
  BOOST_REQUIRE_EQUAL(npy[10 + length - 1], '\n');
  std::string dictionary = npy.substr(10, length - 1);
  return dictionary.erase(dictionary.find_last_not_of(' ') + 1);  // the padding
}

template <class T>
std::vector<T> npy_values(const std::string& npy) {
  const std::size_t start = 10 + read_le(npy, 8, 2);
  BOOST_REQUIRE_EQUAL((npy.size() - start) % sizeof(T), 0u);
  std::vector<T> values((npy.size() - start) / sizeof(T));
  if (!values.empty()) std::memcpy(values.data(), npy.data() + start, npy.size() - start);
  return values;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(write_npz)

// The check value of CRC-32 in the zip specification's family (ITU V.42).
BOOST_AUTO_TEST_CASE(crc32_check_value) {
  const std::string digits = "123456789";
  BOOST_CHECK_EQUAL(expmap::IO::internal::crc32(
                        reinterpret_cast<const unsigned char*>(digits.data()), digits.size()),
                    0xCBF43926u);
  // Continued over two parts, the same.
  const auto* p = reinterpret_cast<const unsigned char*>(digits.data());
  BOOST_CHECK_EQUAL(expmap::IO::internal::crc32(p + 4, 5, expmap::IO::internal::crc32(p, 4)),
                    0xCBF43926u);
}

BOOST_AUTO_TEST_CASE(arrays_read_back) {
  const std::vector<double> r{0.0, 0.5, 1.25, -3e-300};
  const std::vector<std::int64_t> vertex{0, 7, -1, 1LL << 40};
  const std::vector<double> empty;
  std::ostringstream out(std::ios::binary);
  expmap::IO::write_npz(out, {expmap::IO::npy_array("r", r), expmap::IO::npy_array("vertex", vertex),
                              expmap::IO::npy_array("nothing", empty)});
  const std::vector<Entry> entries = read_zip(out.str());
  BOOST_REQUIRE_EQUAL(entries.size(), 3u);
  BOOST_CHECK_EQUAL(entries[0].name, "r.npy");
  BOOST_CHECK_EQUAL(entries[1].name, "vertex.npy");
  BOOST_CHECK_EQUAL(entries[2].name, "nothing.npy");
  for (const Entry& e : entries)
    BOOST_CHECK_EQUAL(e.crc, expmap::IO::internal::crc32(
                                 reinterpret_cast<const unsigned char*>(e.npy.data()), e.npy.size()));

  const std::string little = expmap::IO::npy_descr<double>().substr(0, 1);
  BOOST_CHECK(little == "<" || little == ">");
  BOOST_CHECK_EQUAL(npy_dictionary(entries[0].npy),
                    "{'descr': '" + little + "f8', 'fortran_order': False, 'shape': (4,), }");
  BOOST_CHECK_EQUAL(npy_dictionary(entries[1].npy),
                    "{'descr': '" + little + "i8', 'fortran_order': False, 'shape': (4,), }");
  BOOST_CHECK_EQUAL(npy_dictionary(entries[2].npy),
                    "{'descr': '" + little + "f8', 'fortran_order': False, 'shape': (0,), }");
  const std::vector<double> r_back = npy_values<double>(entries[0].npy);
  const std::vector<std::int64_t> vertex_back = npy_values<std::int64_t>(entries[1].npy);
  BOOST_CHECK_EQUAL_COLLECTIONS(r_back.begin(), r_back.end(), r.begin(), r.end());
  BOOST_CHECK_EQUAL_COLLECTIONS(vertex_back.begin(), vertex_back.end(), vertex.begin(), vertex.end());
  BOOST_CHECK(npy_values<double>(entries[2].npy).empty());
}

BOOST_AUTO_TEST_CASE(no_arrays_is_an_empty_archive) {
  std::ostringstream out(std::ios::binary);
  expmap::IO::write_npz(out, {});
  BOOST_CHECK_EQUAL(out.str().size(), 22u);
  BOOST_CHECK(read_zip(out.str()).empty());
}

BOOST_AUTO_TEST_CASE(types_and_shapes) {
  BOOST_CHECK_EQUAL(expmap::IO::npy_descr<float>().substr(1), "f4");
  BOOST_CHECK_EQUAL(expmap::IO::npy_descr<std::uint32_t>().substr(1), "u4");
  BOOST_CHECK_EQUAL(expmap::IO::npy_descr<std::int8_t>(), "|i1");
  expmap::IO::Npy_array matrix;
  matrix.name = "m";
  matrix.descr = "<f8";
  matrix.shape = {2, 3};
  BOOST_CHECK_EQUAL(npy_dictionary(expmap::IO::internal::npy_header(matrix)),
                    "{'descr': '<f8', 'fortran_order': False, 'shape': (2, 3), }");
}

// Beyond plain zip's 32-bit sizes the writer refuses before writing.
BOOST_AUTO_TEST_CASE(too_large_is_refused) {
  expmap::IO::Npy_array huge;
  huge.name = "huge";
  huge.descr = "<f8";
  huge.shape = {std::size_t(1) << 30};
  huge.bytes = std::size_t(8) << 30;
  static const unsigned char byte = 0;
  huge.data = &byte;  // never read: the size check comes first
  std::ostringstream out(std::ios::binary);
  BOOST_CHECK_THROW(expmap::IO::write_npz(out, {huge}), std::length_error);
  BOOST_CHECK(out.str().empty());
}

BOOST_AUTO_TEST_SUITE_END()
