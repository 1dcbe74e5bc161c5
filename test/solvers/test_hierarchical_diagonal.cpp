// The top separators' diagonal blocks kept in hierarchical form: every kind
// of solve gives the dense factor's answer to about the tolerance, reading
// fewer entries where the form is kept for that.
#include <expmap/Cholmod_solver.h>
#include <expmap/internal/Localized_cholesky_solver.h>

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
using expmap::internal::Diagonal_compression;
using expmap::internal::Localized_cholesky_solver;
using expmap::internal::Rhs_entry;
using expmap::internal::Rows_below_compression;
using expmap::internal::Vector3;

// The grid's vertices where random_grid_operator puts them.
std::vector<Vector3> grid_positions(int nx, int ny) {
  std::vector<Vector3> p(static_cast<std::size_t>(nx) * ny);
  for (int y = 0; y < ny; ++y)
    for (int x = 0; x < nx; ++x) p[static_cast<std::size_t>(y) * nx + x] = {1.0 * x, 1.0 * y, 0.0};
  return p;
}

// Small separators and leaves, every block kept in the form (max_fraction
// 1), so that the tests exercise it on many supernodes.
Diagonal_compression thorough(double tolerance) {
  Diagonal_compression c;
  c.tolerance = tolerance;
  c.min_columns = 48;
  c.leaf_columns = 12;
  c.max_fraction = 1.0;
  return c;
}

// One matrix factored once; its localized solver with dense diagonal blocks
// and with hierarchical ones (and, if asked, the rows below compressed
// after them).
struct Dense_and_hierarchical {
  Dense_and_hierarchical(int nx, double diagonal, double weight_scale,
                         const Diagonal_compression& c, bool rows_below = false) {
    const auto A = expmap_test::random_grid_operator(nx, nx, 7, diagonal, weight_scale);
    n = static_cast<int>(A.rows());
    solver.factor(A);
    dense = Localized_cholesky_solver(solver.factor_view());
    hierarchical = Localized_cholesky_solver(solver.factor_view());
    count = hierarchical.compress_diagonal_blocks(c, grid_positions(nx, nx));
    if (rows_below) {
      Rows_below_compression r;
      r.tolerance = c.tolerance;
      r.min_side = 48;
      hierarchical.compress_rows_below(r);
    }
  }
  int n = 0;
  std::size_t count = 0;
  expmap::Cholmod_solver solver;
  Localized_cholesky_solver dense, hierarchical;
};

// The solution at `rows` only.
std::vector<double> solve_at(const Localized_cholesky_solver& local,
                             const std::vector<Rhs_entry>& b, int width,
                             const std::vector<int>& rows,
                             Localized_cholesky_solver::Workspace& ws) {
  std::vector<double> out(rows.size() * static_cast<std::size_t>(width));
  local.solve(b, width, rows.data(), rows.size(), out.data(), ws);
  return out;
}

}  // namespace

BOOST_AUTO_TEST_CASE(hierarchical_solves_equal_dense_solves_of_every_width) {
  const int nx = 300;
  const Dense_and_hierarchical f(nx, 0.01, 1.0, thorough(1e-14));
  BOOST_TEST_MESSAGE(f.count << " of " << f.hierarchical.number_of_supernodes()
                     << " supernodes with a hierarchical diagonal block");
  BOOST_TEST_REQUIRE(f.count >= 10u);
  BOOST_TEST(f.hierarchical.number_of_hierarchical_supernodes() == f.count);
  BOOST_TEST(f.dense.number_of_hierarchical_supernodes() == 0u);
  for (const int width : {1, 2, 3, 5, 9, 16}) {
    const auto b = expmap_test::signed_rhs(nx, width);
    const auto x = expmap_test::solve_every_row(f.dense, b, width);
    const auto y = expmap_test::solve_every_row(f.hierarchical, b, width);
    const double change = expmap_test::relative_change(x, y);
    BOOST_TEST_MESSAGE("width " << width << ": change " << change << " of the largest value");
    BOOST_TEST(change < 1e-12);
  }
}

// A localized solve enters a hierarchical block at its first column and
// leaves the workspace's block zero: solves that follow on the same
// workspace, near and far, are right too.
BOOST_AUTO_TEST_CASE(localized_solves_in_a_row_on_one_workspace) {
  const int nx = 300;
  const Dense_and_hierarchical f(nx, 0.01, 1.0, thorough(1e-14), true);
  BOOST_TEST_REQUIRE(f.count >= 10u);
  auto dense_ws = f.dense.make_workspace();
  auto ws = f.hierarchical.make_workspace();
  for (const int corner : {20, 150, 260, 20}) {
    std::vector<Rhs_entry> b;
    std::vector<int> rows;
    for (int d = 0; d < 12; ++d)
      for (int e = 0; e < 12; ++e) {
        const int v = (corner + d) * nx + corner / 2 + e;
        rows.push_back(v);
        b.push_back({v, 0, (d + e) % 3 - 1.0});
      }
    const double change = expmap_test::relative_change(solve_at(f.dense, b, 1, rows, *dense_ws),
                                           solve_at(f.hierarchical, b, 1, rows, *ws));
    BOOST_TEST_MESSAGE("patch at row " << corner << ": change " << change);
    BOOST_TEST(change < 1e-12);
  }
}

BOOST_AUTO_TEST_CASE(extended_pruned_and_largest_first_solves_equal_dense_ones) {
  const int nx = 300;
  const Dense_and_hierarchical f(nx, 1.0, 30.0, thorough(1e-14), true);
  BOOST_TEST_REQUIRE(f.count >= 10u);
  std::vector<int> rows(static_cast<std::size_t>(f.n));
  std::iota(rows.begin(), rows.end(), 0);
  const std::vector<Rhs_entry> b{{150 * nx + 148, 0, 1.0}, {151 * nx + 148, 1, 1.0}};
  const std::size_t half = rows.size() / 2;
  auto solve_in_two = [&](const Localized_cholesky_solver& local) {
    std::vector<double> out(2 * rows.size());
    auto ws = local.make_workspace();
    local.solve_extendable(b, 2, rows.data() + half, rows.size() - half, out.data() + 2 * half,
                           *ws);
    local.extend(rows.data(), half, out.data(), *ws);
    return out;
  };
  BOOST_TEST(
      expmap_test::relative_change(solve_in_two(f.dense), solve_in_two(f.hierarchical)) < 1e-12);
  auto pruned = [&](const Localized_cholesky_solver& local) {
    std::vector<double> out(2 * rows.size());
    auto ws = local.make_workspace();
    local.solve_pruned(b, 2, rows.data(), rows.size(), out.data(), *ws, 1e-30);
    return out;
  };
  BOOST_TEST(expmap_test::relative_change(pruned(f.dense), pruned(f.hierarchical)) < 1e-12);
  const std::vector<Rhs_entry> source{{149 * nx + 151, 0, 1.0}};
  BOOST_TEST(expmap_test::largest_rows(f.hierarchical, source, 900) ==
             expmap_test::largest_rows(f.dense, source, 900));
}

// With the library's sizes (blocks from 256 columns, 128-column leaves, kept
// where they read at most 0.7 of the triangle) on a grid whose top
// separators are that long: fewer entries read, the same solution.
BOOST_AUTO_TEST_CASE(the_default_sizes_read_fewer_entries) {
  const int nx = 700;
  Diagonal_compression c;
  c.tolerance = 1e-14;
  const Dense_and_hierarchical f(nx, 0.01, 1.0, c);
  BOOST_TEST_REQUIRE(f.count >= 1u);
  std::vector<Rhs_entry> b;
  std::vector<int> rows;
  for (int d = 0; d < 20; ++d)
    for (int e = 0; e < 20; ++e) {
      const int v = (300 + d) * nx + 500 + e;
      rows.push_back(v);
      b.push_back({v, 0, (d * e) % 5 - 2.0});
    }
  auto read = [&](const Localized_cholesky_solver& local, std::vector<double>& out) {
    out.resize(rows.size());
    auto ws = local.make_workspace();
    return local.solve(b, 1, rows.data(), rows.size(), out.data(), *ws).factor_entries;
  };
  std::vector<double> x, y;
  const std::size_t dense_entries = read(f.dense, x), entries = read(f.hierarchical, y);
  BOOST_TEST_MESSAGE(f.count << " hierarchical blocks; entries read " << entries << " against "
                     << dense_entries << "; change " << expmap_test::relative_change(x, y));
  BOOST_TEST(entries < dense_entries);
  BOOST_TEST(expmap_test::relative_change(x, y) < 1e-12);
}

// The checks above can fail: a loose tolerance moves the solution visibly.
BOOST_AUTO_TEST_CASE(a_loose_tolerance_shows_in_the_hierarchical_solution) {
  const int nx = 300;
  const Dense_and_hierarchical f(nx, 0.01, 1.0, thorough(1e-3));
  BOOST_TEST_REQUIRE(f.count >= 10u);
  const auto b = expmap_test::signed_rhs(nx, 1);
  const double change = expmap_test::relative_change(expmap_test::solve_every_row(f.dense, b, 1),
                                        expmap_test::solve_every_row(f.hierarchical, b, 1));
  BOOST_TEST_MESSAGE("tolerance 1e-3: change " << change);
  BOOST_TEST(change > 1e-8);
}

BOOST_AUTO_TEST_CASE(hierarchical_settings_are_checked) {
  const auto A = expmap_test::random_grid_operator(20, 20, 1);
  expmap::Cholmod_solver solver;
  solver.factor(A);
  const auto positions = grid_positions(20, 20);
  auto rejects = [&](Diagonal_compression c, const std::vector<Vector3>& p) {
    Localized_cholesky_solver local(solver.factor_view());
    BOOST_CHECK_THROW(local.compress_diagonal_blocks(c, p), std::invalid_argument);
  };
  for (const double tolerance : {-1.0, 1.0, std::nan("")}) {
    Diagonal_compression c = thorough(1e-14);
    c.tolerance = tolerance;
    rejects(c, positions);
  }
  Diagonal_compression leaf = thorough(1e-14);
  leaf.leaf_columns = leaf.min_columns;
  rejects(leaf, positions);
  Diagonal_compression fraction = thorough(1e-14);
  fraction.max_fraction = 0;
  rejects(fraction, positions);
  rejects(thorough(1e-14), std::vector<Vector3>(10));
  // No tolerance: nothing changes. Single-precision supernodes are left
  // dense.
  Localized_cholesky_solver local(solver.factor_view());
  BOOST_TEST(local.compress_diagonal_blocks(thorough(0), positions) == 0u);
  Diagonal_compression small = thorough(1e-14);
  small.min_columns = 4;
  small.leaf_columns = 2;
  Localized_cholesky_solver single(solver.factor_view(), Factor_precision::single_precision);
  BOOST_TEST(single.compress_diagonal_blocks(small, positions) == 0u);
}
