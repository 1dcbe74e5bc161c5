// The rows a largest-first solve finds largest, for comparing two solvers.
#ifndef EXPMAP_TEST_LARGEST_ROWS_H
#define EXPMAP_TEST_LARGEST_ROWS_H

#include <expmap/internal/Localized_cholesky_solver.h>

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

namespace expmap_test {

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

}  // namespace expmap_test

#endif  // EXPMAP_TEST_LARGEST_ROWS_H
