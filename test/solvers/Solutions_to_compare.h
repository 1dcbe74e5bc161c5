// What two localized solvers return for the same right-hand side, to compare
// them: the solution on every row, and the rows found largest first.
#ifndef EXPMAP_TEST_SOLUTIONS_TO_COMPARE_H
#define EXPMAP_TEST_SOLUTIONS_TO_COMPARE_H

#include <expmap/internal/solver/Localized_cholesky_solver.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <vector>

namespace expmap_test {

// The solution of A X = b (`width` columns) on every row, row-major; the
// solve's statistics in `stats` if given.
inline std::vector<double> solve_every_row(
    const expmap::internal::Localized_cholesky_solver& local,
    const std::vector<expmap::internal::Rhs_entry>& b, int width,
    expmap::Solve_statistics* stats = nullptr) {
  std::vector<int> rows(static_cast<std::size_t>(local.size()));
  std::iota(rows.begin(), rows.end(), 0);
  std::vector<double> out(rows.size() * static_cast<std::size_t>(width));
  auto ws = local.make_workspace();
  const auto s = local.solve(b, width, rows.data(), rows.size(), out.data(), *ws);
  if (stats) *stats = s;
  return out;
}

// The `count` rows of largest value that `local.solve_largest` returns for
// b, sorted by row (ties broken by the smaller row).
inline std::vector<int> largest_rows(const expmap::internal::Localized_cholesky_solver& local,
                                     const std::vector<expmap::internal::Rhs_entry>& b,
                                     std::size_t count) {
  std::vector<int> rows;
  std::vector<double> values;
  auto ws = local.make_workspace();
  local.solve_largest(b, count, rows, values, *ws);
  std::vector<std::size_t> order(rows.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t p, std::size_t q) {
    return values[p] > values[q] || (values[p] == values[q] && rows[p] < rows[q]);
  });
  std::vector<int> top;
  for (std::size_t k = 0; k < count && k < order.size(); ++k) top.push_back(rows[order[k]]);
  std::sort(top.begin(), top.end());
  return top;
}

// Largest |a - b| over largest |a|.
inline double relative_change(const std::vector<double>& a, const std::vector<double>& b) {
  double scale = 0, worst = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    scale = std::max(scale, std::abs(a[i]));
    worst = std::max(worst, std::abs(a[i] - b[i]));
  }
  return worst / scale;
}

// A signed right-hand side of `width` columns on an nx x nx grid operator
// (random_grid_operator), as the Poisson and star solves have: three
// entries per column, near a corner, near the opposite one and in the
// middle.
inline std::vector<expmap::internal::Rhs_entry> signed_rhs(int nx, int width) {
  std::vector<expmap::internal::Rhs_entry> b;
  for (int c = 0; c < width; ++c) {
    b.push_back({(10 + 3 * c) * nx + 12 + c, c, 1.0 + c});
    b.push_back({(nx - 100 - 2 * c) * nx + nx - 90 - c, c, -1.0});
    b.push_back({(nx / 2) * nx + nx / 2 - 1 + c, c, -static_cast<double>(c)});
  }
  return b;
}

}  // namespace expmap_test

#endif  // EXPMAP_TEST_SOLUTIONS_TO_COMPARE_H
