// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The two sorts a query's patch goes through, against std::sort:
// keep_nearest_sorted (the patch's `count` nearest vertices, by distance
// buckets) and sort_nearly_sorted (the assembled map, by insertion while few
// entries are out of place). Both must give exactly std::sort's order, cut to
// the count, for distances spread like a patch's, with ties, clusters and
// values the buckets cannot take.

#include <expmap/internal/Local_map_assembly.h>
#include <expmap/internal/Nearest_first.h>

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {

struct Key {
  double distance;
  int vertex;
  bool operator<(const Key& other) const {
    return distance < other.distance || (distance == other.distance && vertex < other.vertex);
  }
  bool operator==(const Key& other) const {
    return distance == other.distance && vertex == other.vertex;
  }
};

std::ostream& operator<<(std::ostream& out, const Key& k) {
  return out << "(" << k.distance << ", " << k.vertex << ")";
}

// `size` keys with distinct vertices: distances of a disk (the radius of a
// uniform point), a few exact ties, and a cluster of equal distances.
std::vector<Key> disk_keys(std::size_t size, std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<Key> keys(size);
  for (std::size_t i = 0; i < size; ++i)
    keys[i] = {2.5 * std::sqrt(unit(rng)), static_cast<int>((i * 7919) % (size + 13))};
  if (size > 2) keys[size / 2].distance = keys[0].distance;  // a tie, broken by the vertex
  for (std::size_t i = 1; i < size && i < 40; i += 3) keys[i].distance = 1.25;  // a cluster
  if (size > 0) keys[size - 1].distance = 0;  // the source
  return keys;
}

std::vector<Key> sorted_cut(std::vector<Key> keys, std::size_t count) {
  std::sort(keys.begin(), keys.end());
  keys.resize(std::min(count, keys.size()));
  return keys;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(nearest_first)

BOOST_AUTO_TEST_CASE(keep_nearest_sorted_equals_a_cut_std_sort) {
  std::mt19937 rng(5);
  std::vector<Key> scratch;
  std::vector<std::size_t> buckets;
  for (const std::size_t size : {0, 1, 2, 63, 64, 65, 1000, 8000}) {
    for (const double share : {0.0, 0.01, 0.5, 0.999, 1.0, 2.0}) {
      const auto count = static_cast<std::size_t>(share * static_cast<double>(size));
      BOOST_TEST_CONTEXT("size " << size << ", count " << count) {
        std::vector<Key> keys = disk_keys(size, rng);
        const std::vector<Key> expected = sorted_cut(keys, count);
        expmap::internal::keep_nearest_sorted(keys, count, scratch, buckets);
        BOOST_TEST(keys == expected, boost::test_tools::per_element());
      }
    }
  }
}

BOOST_AUTO_TEST_CASE(keep_nearest_sorted_takes_what_buckets_cannot) {
  // All equal (no spread to bucket by), denormal (the bucket scale would
  // overflow), infinite, negative and NaN-free mixtures: the comparison
  // sort's answer in every case.
  std::mt19937 rng(6);
  std::vector<Key> scratch;
  std::vector<std::size_t> buckets;
  const double specials[] = {0.0, std::numeric_limits<double>::denorm_min(), 1e-310,
                             std::numeric_limits<double>::infinity(), -1.0,
                             std::numeric_limits<double>::max()};
  for (const double special : specials) {
    BOOST_TEST_CONTEXT("special distance " << special) {
      std::vector<Key> keys = disk_keys(500, rng);
      for (std::size_t i = 0; i < keys.size(); i += 5) keys[i].distance = special;
      const std::vector<Key> expected = sorted_cut(keys, 300);
      expmap::internal::keep_nearest_sorted(keys, 300, scratch, buckets);
      BOOST_TEST(keys == expected, boost::test_tools::per_element());
    }
    BOOST_TEST_CONTEXT("every distance " << special) {
      std::vector<Key> keys = disk_keys(500, rng);
      for (Key& k : keys) k.distance = special;
      const std::vector<Key> expected = sorted_cut(keys, 300);
      expmap::internal::keep_nearest_sorted(keys, 300, scratch, buckets);
      BOOST_TEST(keys == expected, boost::test_tools::per_element());
    }
  }
}

BOOST_AUTO_TEST_CASE(sort_nearly_sorted_equals_std_sort) {
  std::mt19937 rng(7);
  for (const std::size_t size : {0, 1, 2, 3, 100, 5000}) {
    // Sorted; a few near entries moved (as the heat method's neighbours
    // are); then shuffled ever more, until the insertions give up.
    for (const std::size_t displaced : {std::size_t{0}, std::size_t{3}, size / 10, size}) {
      BOOST_TEST_CONTEXT("size " << size << ", displaced " << displaced) {
        std::vector<Key> keys = sorted_cut(disk_keys(size, rng), size);
        std::uniform_int_distribution<std::size_t> at(0, size == 0 ? 0 : size - 1);
        for (std::size_t d = 0; d < displaced && size > 1; ++d) std::swap(keys[at(rng)], keys[at(rng)]);
        if (displaced == size) std::shuffle(keys.begin(), keys.end(), rng);
        std::vector<Key> expected = keys;
        std::sort(expected.begin(), expected.end());
        expmap::internal::sort_nearly_sorted(keys.begin(), keys.end(), std::less<Key>());
        BOOST_TEST(keys == expected, boost::test_tools::per_element());
      }
    }
  }
  // Reversed: the worst case for insertion; the fallback keeps it n log n
  // and right.
  std::vector<Key> keys = sorted_cut(disk_keys(20000, rng), 20000);
  std::vector<Key> expected = keys;
  std::reverse(keys.begin(), keys.end());
  expmap::internal::sort_nearly_sorted(keys.begin(), keys.end(), std::less<Key>());
  BOOST_TEST(keys == expected, boost::test_tools::per_element());
}

BOOST_AUTO_TEST_SUITE_END()
