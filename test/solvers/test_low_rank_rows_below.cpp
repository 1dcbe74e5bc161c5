// The rows below the large separators kept as truncated SVDs: every kind of
// solve gives the dense factor's answer to about the tolerance, reading
// fewer entries.
#include <expmap/Cholmod_solver.h>
#include <expmap/internal/solver/Localized_cholesky_solver.h>

#include "Solutions_to_compare.h"
#include "Random_grid_operator.h"

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <vector>

namespace {

using expmap::Factor_precision;
using expmap::internal::Localized_cholesky_solver;
using expmap::internal::Rhs_entry;
using expmap::internal::Rows_below_compression;

// One matrix factored once, its localized solver with dense and with
// compressed rows below (blocks of at least 64 x 64: a 260 x 260 grid has
// six that compress at 1e-14).
struct Dense_and_compressed {
  Dense_and_compressed(int nx, int ny, double diagonal, double weight_scale,
                       double tolerance = 1e-14) {
    const auto A = expmap_test::random_grid_operator(nx, ny, 5, diagonal, weight_scale);
    n = static_cast<int>(A.rows());
    solver.factor(A);
    dense = Localized_cholesky_solver(solver.factor_view());
    Rows_below_compression c;
    c.tolerance = tolerance;
    c.min_side = 64;
    compressed = Localized_cholesky_solver(solver.factor_view());
    compressed.compress_rows_below(c);
    rows.resize(static_cast<std::size_t>(n));
    std::iota(rows.begin(), rows.end(), 0);
  }
  int n = 0;
  std::vector<int> rows;
  expmap::Cholmod_solver solver;
  Localized_cholesky_solver dense, compressed;
};

}  // namespace

BOOST_AUTO_TEST_CASE(compressed_solves_equal_dense_solves_of_every_width) {
  const int nx = 260;
  const Dense_and_compressed f(nx, 260, 0.01, 1.0);
  BOOST_TEST_MESSAGE(f.compressed.number_of_compressed_supernodes() << " of "
                     << f.compressed.number_of_supernodes() << " supernodes compressed");
  BOOST_TEST_REQUIRE(f.compressed.number_of_compressed_supernodes() >= 4);
  BOOST_TEST(f.dense.number_of_compressed_supernodes() == 0u);
  for (const int width : {1, 2, 3, 5, 9, 16}) {
    const auto b = expmap_test::signed_rhs(nx, width);
    expmap::Solve_statistics dense_stats, compressed_stats;
    const auto x = expmap_test::solve_every_row(f.dense, b, width, &dense_stats);
    const auto y = expmap_test::solve_every_row(f.compressed, b, width, &compressed_stats);
    const double change = expmap_test::relative_change(x, y);
    BOOST_TEST_MESSAGE("width " << width << ": change " << change << " of the largest value, "
                       << compressed_stats.factor_entries << " entries read against "
                       << dense_stats.factor_entries);
    BOOST_TEST(change < 1e-12);
    BOOST_TEST(compressed_stats.factor_entries < dense_stats.factor_entries);
  }
}

BOOST_AUTO_TEST_CASE(compressed_extended_and_pruned_solves_equal_dense_ones) {
  const int nx = 260;
  const Dense_and_compressed f(nx, 260, 1.0, 30.0);
  BOOST_TEST_REQUIRE(f.compressed.number_of_compressed_supernodes() >= 4);
  const std::vector<Rhs_entry> b{{130 * nx + 128, 0, 1.0}, {131 * nx + 128, 1, 1.0}};
  // Extendable: half the rows first, then the rest.
  const std::size_t half = f.rows.size() / 2;
  auto solve_in_two = [&](const Localized_cholesky_solver& local) {
    std::vector<double> out(2 * f.rows.size());
    auto ws = local.make_workspace();
    local.solve_extendable(b, 2, f.rows.data() + half, f.rows.size() - half, out.data() + 2 * half,
                           *ws);
    local.extend(f.rows.data(), half, out.data(), *ws);
    return out;
  };
  BOOST_TEST(expmap_test::relative_change(solve_in_two(f.dense), solve_in_two(f.compressed)) <
             1e-12);
  // Pruned below 1e-30 of the source's heat: both prune the same columns
  // but for values at the threshold.
  auto pruned = [&](const Localized_cholesky_solver& local) {
    std::vector<double> out(2 * f.rows.size());
    auto ws = local.make_workspace();
    local.solve(b, 2, f.rows.data(), f.rows.size(), out.data(), *ws, 1e-30);
    return out;
  };
  const auto x = pruned(f.dense), y = pruned(f.compressed);
  BOOST_TEST(expmap_test::relative_change(x, y) < 1e-12);
  BOOST_TEST(expmap_test::relative_change(expmap_test::solve_every_row(f.dense, b, 2), y) < 1e-12);
}

BOOST_AUTO_TEST_CASE(compressed_largest_first_solve_finds_the_same_vertices) {
  const int nx = 260;
  const Dense_and_compressed f(nx, 260, 1.0, 30.0);
  BOOST_TEST_REQUIRE(f.compressed.number_of_compressed_supernodes() >= 4);
  const std::vector<Rhs_entry> b{{129 * nx + 131, 0, 1.0}};
  BOOST_TEST(expmap_test::largest_rows(f.compressed, b, 900) ==
             expmap_test::largest_rows(f.dense, b, 900));
}

// The check above can fail: a loose tolerance moves the solution visibly.
BOOST_AUTO_TEST_CASE(a_loose_tolerance_shows_in_the_solution) {
  const int nx = 260;
  const Dense_and_compressed f(nx, 260, 0.01, 1.0, 1e-3);
  BOOST_TEST_REQUIRE(f.compressed.number_of_compressed_supernodes() >= 4);
  const auto b = expmap_test::signed_rhs(nx, 1);
  const double change = expmap_test::relative_change(expmap_test::solve_every_row(f.dense, b, 1),
                                        expmap_test::solve_every_row(f.compressed, b, 1));
  BOOST_TEST_MESSAGE("tolerance 1e-3: change " << change);
  BOOST_TEST(change > 1e-8);
}

BOOST_AUTO_TEST_CASE(compression_settings_are_checked) {
  const auto A = expmap_test::random_grid_operator(20, 20, 1);
  expmap::Cholmod_solver solver;
  solver.factor(A);
  for (const double tolerance : {-1.0, 1.0, std::nan("")}) {
    Rows_below_compression c;
    c.tolerance = tolerance;
    Localized_cholesky_solver local(solver.factor_view());
    BOOST_CHECK_THROW(local.compress_rows_below(c), std::invalid_argument);
  }
  // Single-precision supernodes are left as they are without a tolerance
  // of their own.
  Rows_below_compression c;
  c.tolerance = 1e-14;
  c.min_side = 1;
  Localized_cholesky_solver single(solver.factor_view(), Factor_precision::single_precision);
  BOOST_TEST(single.compress_rows_below(c) == 0u);
  BOOST_TEST(single.number_of_compressed_supernodes() == 0u);
  c.single_tolerance = 2.0;
  BOOST_CHECK_THROW(single.compress_rows_below(c), std::invalid_argument);
}

// Blocks kept in floats, truncated near float precision: the solution stays
// within float round-off of the double-precision dense one, as the dense
// float factor's does (test_single_precision_factor.cpp), and fewer entries
// are read.
BOOST_AUTO_TEST_CASE(single_precision_blocks_compress_to_float_accuracy) {
  const int nx = 260;
  const auto A = expmap_test::random_grid_operator(nx, 260, 5, 0.01, 1.0);
  expmap::Cholmod_solver solver;
  solver.factor(A);
  const Localized_cholesky_solver exact(solver.factor_view());
  const Localized_cholesky_solver single(solver.factor_view(), Factor_precision::single_precision);
  Localized_cholesky_solver compressed(solver.factor_view(), Factor_precision::single_precision);
  Rows_below_compression c;
  c.tolerance = 1e-14;
  c.single_tolerance = 1e-7;
  c.min_side = 64;
  BOOST_TEST_REQUIRE(compressed.compress_rows_below(c) >= 4u);
  const auto b = expmap_test::signed_rhs(nx, 2);
  expmap::Solve_statistics single_stats, compressed_stats;
  const auto x = expmap_test::solve_every_row(exact, b, 2),
             y = expmap_test::solve_every_row(single, b, 2, &single_stats),
             z = expmap_test::solve_every_row(compressed, b, 2, &compressed_stats);
  const double rounding = expmap_test::relative_change(x, y), truncation = expmap_test::relative_change(x, z);
  BOOST_TEST_MESSAGE("change against double precision: floats " << rounding << ", floats "
                     "compressed at 1e-7 " << truncation);
  BOOST_TEST(truncation < 1e-6);
  BOOST_TEST(truncation < 10 * rounding);
  BOOST_TEST(compressed_stats.factor_entries < single_stats.factor_entries);
}
