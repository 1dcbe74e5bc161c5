// A largest-first solve (Localized_cholesky_solver::solve_largest) of an
// M-matrix must find the same largest values as a full solve, with the
// values of a full solve, while solving fewer rows than the matrix has.
#include <expmap/Cholmod_solver.h>
#include <expmap/internal/solver/Localized_cholesky_solver.h>

#include "Random_grid_operator.h"

#include <boost/test/unit_test.hpp>

#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <set>
#include <stdexcept>
#include <vector>

namespace {

using expmap::internal::Localized_cholesky_solver;
using expmap::internal::Rhs_entry;
using Matrix = expmap_test::Sparse_matrix;

// Two random heat systems M + tL (M = I) side by side, not coupled: the
// grid operator's parts of A.
Matrix two_parts(int nx, int ny, double t) {
  const Matrix a = expmap_test::random_grid_operator(nx, ny, 5, 1.0, t);
  const Matrix b = expmap_test::random_grid_operator(nx, ny, 6, 1.0, t);
  std::vector<Eigen::Triplet<double>> entries;
  for (const Matrix* part : {&a, &b}) {
    const int offset = part == &a ? 0 : static_cast<int>(a.rows());
    for (int k = 0; k < part->outerSize(); ++k)
      for (Matrix::InnerIterator it(*part, k); it; ++it)
        entries.emplace_back(static_cast<int>(it.row()) + offset, static_cast<int>(it.col()) + offset,
                             it.value());
  }
  Matrix A(a.rows() + b.rows(), a.cols() + b.cols());
  A.setFromTriplets(entries.begin(), entries.end());
  return A;
}

struct Heat_system {
  Heat_system(int nx, int ny, double t) : A(two_parts(nx, ny, t)) {
    solver.factor(A);
    local = Localized_cholesky_solver(solver.factor_view());
    ws = local.make_workspace();
  }
  // CHOLMOD's own full solve of A x = b.
  Eigen::VectorXd full(const std::vector<Rhs_entry>& entries) {
    Eigen::VectorXd b = Eigen::VectorXd::Zero(A.rows());
    for (const Rhs_entry& e : entries) b[e.row] += e.value;
    return solver.solve(b);
  }
  Matrix A;
  expmap::Cholmod_solver solver;
  Localized_cholesky_solver local;
  std::unique_ptr<Localized_cholesky_solver::Workspace> ws;
};

// The rows of the `count` largest values of x among `part` (all rows if
// fewer).
std::set<int> largest_rows(const Eigen::VectorXd& x, const std::vector<int>& part,
                           std::size_t count) {
  std::vector<int> rows = part;
  count = std::min(count, rows.size());
  std::partial_sort(rows.begin(), rows.begin() + static_cast<std::ptrdiff_t>(count), rows.end(),
                    [&](int a, int b) { return x[a] > x[b]; });
  return {rows.begin(), rows.begin() + static_cast<std::ptrdiff_t>(count)};
}

std::set<int> largest_rows(const std::vector<int>& rows, const std::vector<double>& values,
                           std::size_t count) {
  std::vector<std::size_t> order(rows.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  count = std::min(count, rows.size());
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(count), order.end(),
                    [&](std::size_t a, std::size_t b) { return values[a] > values[b]; });
  std::set<int> out;
  for (std::size_t i = 0; i < count; ++i) out.insert(rows[order[i]]);
  return out;
}

// Every value returned equals the full solve's (relative to the largest),
// each row once, all in the part the right-hand side touches.
void check_values(const Eigen::VectorXd& x, const std::vector<int>& rows,
                  const std::vector<double>& values, int part_begin, int part_end) {
  BOOST_TEST_REQUIRE(rows.size() == values.size());
  const double largest = x.maxCoeff();
  double worst = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    BOOST_TEST_REQUIRE((rows[i] >= part_begin && rows[i] < part_end));
    worst = std::max(worst, std::abs(values[i] - x[rows[i]]) / largest);
  }
  BOOST_TEST(worst <= 1e-13);
  BOOST_TEST(std::set<int>(rows.begin(), rows.end()).size() == rows.size());
}

}  // namespace

BOOST_AUTO_TEST_CASE(largest_first_finds_the_largest_values_of_a_full_solve) {
  const int nx = 90, ny = 80, n = nx * ny;
  std::vector<int> first_part(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) first_part[static_cast<std::size_t>(i)] = i;
  // A fast and a slow decay; a source inside, one in a corner, two at once.
  for (const double t : {4.0, 60.0}) {
    Heat_system heat(nx, ny, t);
    for (const std::vector<Rhs_entry>& b :
         {std::vector<Rhs_entry>{{40 * nx + 45, 0, 1.0}}, std::vector<Rhs_entry>{{0, 0, 2.0}},
          std::vector<Rhs_entry>{{20 * nx + 20, 0, 1.0}, {60 * nx + 70, 0, 0.5}}}) {
      const Eigen::VectorXd x = heat.full(b);
      for (const std::size_t count : {std::size_t{1}, std::size_t{50}, std::size_t{700},
                                      std::size_t{3000}, std::size_t(n), std::size_t(n) + 9}) {
        std::vector<int> rows;
        std::vector<double> values;
        heat.local.solve_largest(b, count, rows, values, *heat.ws);
        check_values(x, rows, values, 0, n);
        BOOST_TEST((largest_rows(rows, values, count) == largest_rows(x, first_part, count)),
                   "t " << t << ", source " << b.front().row << ", count " << count);
        if (count >= static_cast<std::size_t>(n)) BOOST_TEST(rows.size() == std::size_t(n));
        if (count == 700)
          BOOST_TEST(rows.size() < std::size_t(n) / 2, "solved " << rows.size() << " rows of " << n);
      }
    }
  }
}

BOOST_AUTO_TEST_CASE(an_extended_largest_first_solve_equals_a_larger_one) {
  const int nx = 90, ny = 80, n = nx * ny;
  Heat_system heat(nx, ny, 10.0);
  const std::vector<Rhs_entry> b{{30 * nx + 50, 0, 1.0}};
  std::vector<int> rows, direct_rows;
  std::vector<double> values, direct_values;
  heat.local.solve_largest(b, 300, rows, values, *heat.ws);
  heat.local.extend_largest(2500, rows, values, *heat.ws);
  const auto extended = largest_rows(rows, values, 2500);
  // The solve stays open for the ordinary extension of its rows as well.
  std::vector<double> corner(1);
  const int far_row = n - 1;
  heat.local.extend(&far_row, 1, corner.data(), *heat.ws);
  const Eigen::VectorXd x = heat.full(b);
  BOOST_TEST(std::abs(corner[0] - x[far_row]) <= 1e-13 * x.maxCoeff());
  check_values(x, rows, values, 0, n);
  heat.local.solve_largest(b, 2500, direct_rows, direct_values, *heat.ws);
  BOOST_TEST((extended == largest_rows(direct_rows, direct_values, 2500)));
}

BOOST_AUTO_TEST_CASE(a_pruned_largest_first_solve_keeps_the_largest_values) {
  const int nx = 90, ny = 80, n = nx * ny;
  std::vector<int> first_part(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) first_part[static_cast<std::size_t>(i)] = i;
  Heat_system heat(nx, ny, 4.0);
  const std::vector<Rhs_entry> b{{40 * nx + 45, 0, 1.0}};
  const Eigen::VectorXd x = heat.full(b);
  const std::size_t count = 900;
  const auto expected = largest_rows(x, first_part, count);
  double smallest = x.maxCoeff();
  for (const int row : expected) smallest = std::min(smallest, x[row]);
  std::vector<int> rows;
  std::vector<double> values;
  const auto pruned = heat.local.solve_largest(b, count, rows, values, *heat.ws, 1e-12 * smallest);
  const auto full = heat.local.solve_largest(b, count, rows, values, *heat.ws);
  heat.local.solve_largest(b, count, rows, values, *heat.ws, 1e-12 * smallest);
  BOOST_TEST((largest_rows(rows, values, count) == expected));
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (expected.count(rows[i]))
      BOOST_TEST(std::abs(values[i] - x[rows[i]]) <= 1e-10 * x[rows[i]]);
  BOOST_TEST(pruned.factor_entries < full.factor_entries);
}

BOOST_AUTO_TEST_CASE(a_threshold_solve_finds_every_value_above_it) {
  // solve_at_least: every row of the full solve with at least the
  // threshold, and an extension to a lower threshold equals a direct solve.
  const int nx = 90, ny = 80, n = nx * ny;
  for (const double t : {4.0, 60.0}) {
    Heat_system heat(nx, ny, t);
    const std::vector<Rhs_entry> b{{40 * nx + 45, 0, 1.0}, {60 * nx + 70, 0, 0.5}};
    const Eigen::VectorXd x = heat.full(b);
    auto above = [&](double threshold) {
      std::set<int> rows;
      for (int i = 0; i < n; ++i)
        if (x[i] >= threshold) rows.insert(i);
      return rows;
    };
    auto found = [](const std::vector<int>& rows, const std::vector<double>& values,
                    double threshold) {
      std::set<int> out;
      for (std::size_t i = 0; i < rows.size(); ++i)
        if (values[i] >= threshold) out.insert(rows[i]);
      return out;
    };
    // Thresholds between the values (a value on the threshold would be
    // decided by the last bit).
    std::vector<double> sorted(x.data(), x.data() + n);
    std::sort(sorted.begin(), sorted.end(), std::greater<double>());
    for (const std::size_t count : {std::size_t{1}, std::size_t{60}, std::size_t{900},
                                    std::size_t{4000}, std::size_t(n) - 1}) {
      const double threshold = 0.5 * (sorted[count - 1] + sorted[count]);
      BOOST_TEST_CONTEXT("t " << t << ", rows above " << count) {
        std::vector<int> rows;
        std::vector<double> values;
        heat.local.solve_at_least(b, threshold, rows, values, *heat.ws);
        check_values(x, rows, values, 0, n);
        const std::set<int> expected = above(threshold);
        BOOST_TEST(expected.size() == count);
        BOOST_TEST((found(rows, values, threshold) == expected));
        if (count == 900)
          BOOST_TEST(rows.size() < std::size_t(n) / 2, "solved " << rows.size() << " rows of " << n);
        // Continued to a lower threshold, by count and by threshold.
        const double lower = 0.5 * (sorted[2 * count - 1] + sorted[2 * count]);
        if (2 * count < std::size_t(n)) {
          heat.local.extend_at_least(lower, rows, values, *heat.ws);
          check_values(x, rows, values, 0, n);
          BOOST_TEST((found(rows, values, lower) == above(lower)));
          heat.local.solve_largest(b, count, rows, values, *heat.ws);
          heat.local.extend_at_least(lower, rows, values, *heat.ws);
          BOOST_TEST((found(rows, values, lower) == above(lower)));
        }
      }
    }
  }
  Heat_system heat(30, 20, 4.0);
  std::vector<int> rows;
  std::vector<double> values;
  const std::vector<Rhs_entry> b{{5, 0, 1.0}};
  for (const double bad : {0.0, -1.0, std::numeric_limits<double>::infinity(),
                           std::numeric_limits<double>::quiet_NaN()}) {
    BOOST_CHECK_THROW(heat.local.solve_at_least(b, bad, rows, values, *heat.ws),
                      std::invalid_argument);
  }
  BOOST_CHECK_THROW(heat.local.extend_at_least(1e-3, rows, values, *heat.ws), std::logic_error);
}

BOOST_AUTO_TEST_CASE(largest_first_solves_refuse_what_they_cannot_do) {
  const int nx = 30, ny = 20, n = nx * ny;
  Heat_system heat(nx, ny, 4.0);
  std::vector<int> rows;
  std::vector<double> values;
  BOOST_CHECK_THROW(heat.local.extend_largest(10, rows, values, *heat.ws), std::logic_error);
  const std::vector<Rhs_entry> negative{{5, 0, 1.0}, {7, 0, -0.5}};
  BOOST_CHECK_THROW(heat.local.solve_largest(negative, 10, rows, values, *heat.ws),
                    std::invalid_argument);
  const std::vector<Rhs_entry> second_column{{5, 1, 1.0}};
  BOOST_CHECK_THROW(heat.local.solve_largest(second_column, 10, rows, values, *heat.ws),
                    std::invalid_argument);
  const std::vector<Rhs_entry> b{{n + 33, 0, 1.0}};  // in the second part
  BOOST_CHECK_THROW(heat.local.solve_largest(b, 10, rows, values, *heat.ws, -1.0),
                    std::invalid_argument);
  // The refused calls left the workspace clean: the next solve is right.
  heat.local.solve_largest(b, 40, rows, values, *heat.ws);
  check_values(heat.full(b), rows, values, n, 2 * n);
  // Another solve on the workspace closes the largest-first one.
  std::vector<double> out(1);
  heat.local.solve(b, 1, &b.front().row, 1, out.data(), *heat.ws);
  BOOST_CHECK_THROW(heat.local.extend_largest(100, rows, values, *heat.ws), std::logic_error);
}
