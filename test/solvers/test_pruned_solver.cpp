// A pruned localized solve of a heat system must keep every requested value
// to 1e-10 relative (each value against itself, not against the largest),
// and must actually skip work.
#include <expmap/Cholmod_solver.h>
#include <expmap/internal/solver/Localized_cholesky_solver.h>

#include "Random_grid_operator.h"

#include <boost/test/unit_test.hpp>

#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <vector>

namespace {

using expmap::internal::Localized_cholesky_solver;
using expmap::internal::Rhs_entry;

constexpr int side = 160;
int grid_id(int x, int y) { return y * side + x; }

// The heat from `centre` and its neighbours (one column each, as the angle
// step of a query solves it) read on a disk around it, pruned with
// drop_below = tolerance * (the smallest value on the disk) as the solver's
// documentation advises, against CHOLMOD's full solves.
void check_pruned_heat(double weight_scale, int cx, int cy, int radius) {
  const auto A = expmap_test::random_grid_operator(side, side, 11, /*diagonal=*/1.0, weight_scale);
  expmap::Cholmod_solver solver;
  solver.factor(A);
  const Localized_cholesky_solver local(solver.factor_view());
  auto ws = local.make_workspace();

  const std::vector<int> star{grid_id(cx, cy),     grid_id(cx + 1, cy),     grid_id(cx - 1, cy),
                              grid_id(cx, cy + 1), grid_id(cx, cy - 1),     grid_id(cx + 1, cy + 1),
                              grid_id(cx - 1, cy - 1)};
  const int width = static_cast<int>(star.size());
  std::vector<Rhs_entry> entries;
  for (int c = 0; c < width; ++c) entries.push_back({star[c], c, 1.0});
  std::vector<int> disk;
  for (int y = cy - radius; y <= cy + radius; ++y)
    for (int x = cx - radius; x <= cx + radius; ++x)
      if ((x - cx) * (x - cx) + (y - cy) * (y - cy) <= radius * radius) disk.push_back(grid_id(x, y));

  std::vector<double> full(disk.size() * width), pruned(disk.size() * width);
  const auto full_stats = local.solve(entries, width, disk.data(), disk.size(), full.data(), *ws);
  const double tolerance = 1e-12;
  const double smallest = Localized_cholesky_solver::smallest_magnitude(full.data(), full.size());
  BOOST_TEST_REQUIRE(smallest > 0.0);
  const double drop_below = tolerance * smallest;
  const auto pruned_stats =
      local.solve(entries, width, disk.data(), disk.size(), pruned.data(), *ws, drop_below);
  // The documented a posteriori check holds (the pruned values differ from
  // the full ones by far less than 1%).
  BOOST_TEST(drop_below <= 1.01 * tolerance * Localized_cholesky_solver::smallest_magnitude(
                                                  pruned.data(), pruned.size()));

  std::vector<Eigen::VectorXd> exact;  // CHOLMOD's own triangular solves
  for (int c = 0; c < width; ++c) {
    Eigen::VectorXd b = Eigen::VectorXd::Zero(A.rows());
    b[star[c]] = 1.0;
    exact.push_back(solver.solve(b));
  }
  auto check = [&](const std::vector<double>& values, const char* what) {
    for (int c = 0; c < width; ++c) {
      double worst = 0;
      for (std::size_t i = 0; i < disk.size(); ++i)
        worst = std::max(worst, std::abs(values[i * width + c] - exact[c][disk[i]]) /
                                    std::abs(exact[c][disk[i]]));
      BOOST_TEST(worst <= 1e-10, what << ", column " << c << ": relative error " << worst);
    }
  };
  check(pruned, "pruned");

  // A threshold from a guess of the smallest value (as a query guesses it
  // from an earlier solve), checked a posteriori: a good guess passes; one
  // far too large is caught, and the solve again with the smallest value
  // it returned (pruning only lowers this nonnegative inverse's values, so
  // that is below the true smallest) is accurate.
  const double largest = std::abs(*std::max_element(full.begin(), full.end(), [](double a, double b) {
    return std::abs(a) < std::abs(b);
  }));
  for (const double hint : {smallest, largest}) {
    std::vector<double> values(full.size());
    auto stats = local.solve(entries, width, disk.data(), disk.size(), values.data(), *ws,
                             tolerance * hint);
    const double smallest_returned =
        Localized_cholesky_solver::smallest_magnitude(values.data(), values.size());
    const bool caught = tolerance * hint > 2 * tolerance * smallest_returned;
    BOOST_TEST(caught == (hint == largest));
    if (caught)
      stats += local.solve(entries, width, disk.data(), disk.size(), values.data(), *ws,
                           tolerance * smallest_returned);
    check(values, hint == smallest ? "good hint" : "hint too large, solved again");
    if (hint == smallest) BOOST_TEST(stats.factor_entries == pruned_stats.factor_entries);
  }
  BOOST_TEST(pruned_stats.factor_entries < full_stats.factor_entries);
  BOOST_TEST_MESSAGE("pruned solve read " << pruned_stats.factor_entries << " of "
                                          << full_stats.factor_entries << " factor entries");
}

// The heat from `centre` on a disk, pruned and kept for extension, then
// extended to a wider disk (the source-heat solve of a query whose
// candidates grow): every value against CHOLMOD's full solve. The extended
// rows carry the pruning error of the rows above them (about drop_below),
// so they stay within 1e-10 of themselves while their heat is at least
// 1e-2 of the first disk's smallest (tolerance 1e-12).
void check_extended_pruned_heat(int cx, int cy, int radius, int wider) {
  const auto A = expmap_test::random_grid_operator(side, side, 5, /*diagonal=*/1.0, 1.0);
  expmap::Cholmod_solver solver;
  solver.factor(A);
  const Localized_cholesky_solver local(solver.factor_view());
  auto ws = local.make_workspace();
  auto disk = [&](int r) {
    std::vector<int> rows;
    for (int y = cy - r; y <= cy + r; ++y)
      for (int x = cx - r; x <= cx + r; ++x)
        if ((x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r) rows.push_back(grid_id(x, y));
    return rows;
  };
  const std::vector<int> inner = disk(radius), outer = disk(wider);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(A.rows());
  b[grid_id(cx, cy)] = 1.0;
  const Eigen::VectorXd exact = solver.solve(b);
  double smallest = exact[inner.front()];
  for (const int v : inner) smallest = std::min(smallest, exact[v]);
  const std::vector<Rhs_entry> entries{{grid_id(cx, cy), 0, 1.0}};

  std::vector<double> unpruned(inner.size()), pruned(inner.size()), extended(outer.size());
  const auto full_stats =
      local.solve_extendable(entries, 1, inner.data(), inner.size(), unpruned.data(), *ws);
  const auto pruned_stats = local.solve_extendable(entries, 1, inner.data(), inner.size(),
                                                   pruned.data(), *ws, 1e-12 * smallest);
  local.extend(outer.data(), outer.size(), extended.data(), *ws);
  auto worst_error = [&](const std::vector<int>& rows, const std::vector<double>& values) {
    double worst = 0;
    for (std::size_t i = 0; i < rows.size(); ++i)
      if (exact[rows[i]] >= 1e-2 * smallest)
        worst = std::max(worst, std::abs(values[i] - exact[rows[i]]) / exact[rows[i]]);
    return worst;
  };
  BOOST_TEST(worst_error(inner, pruned) <= 1e-10);
  BOOST_TEST(worst_error(outer, extended) <= 1e-10);
  BOOST_TEST(pruned_stats.factor_entries < full_stats.factor_entries);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(pruned_solver)

BOOST_AUTO_TEST_CASE(pruned_extendable_heat_stays_accurate_when_extended) {
  check_extended_pruned_heat(40, 100, 10, 14);
  check_extended_pruned_heat(90, 60, 16, 24);
}

// Fast decay (about 0.4 per grid step): most of the top separators is skipped.
BOOST_AUTO_TEST_CASE(pruned_heat_is_accurate_relative_to_each_value) {
  check_pruned_heat(1.0, 50, 70, 12);
  check_pruned_heat(1.0, 120, 30, 20);
}

// Slow decay (about 0.75 per grid step, like t = 10 h^2 on a mesh): the
// requested values span many orders of magnitude.
BOOST_AUTO_TEST_CASE(pruned_slowly_decaying_heat_is_accurate) {
  check_pruned_heat(10.0, 80, 80, 30);
}

BOOST_AUTO_TEST_CASE(pruned_solve_rejects_a_negative_threshold) {
  const auto A = expmap_test::random_grid_operator(10, 10, 1);
  expmap::Cholmod_solver solver;
  solver.factor(A);
  const Localized_cholesky_solver local(solver.factor_view());
  auto ws = local.make_workspace();
  std::vector<Rhs_entry> entries{{5, 0, 1.0}};
  int row = 5;
  double out = 0;
  for (const double bad : {-1.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
    BOOST_CHECK_THROW(local.solve(entries, 1, &row, 1, &out, *ws, bad), std::invalid_argument);
    BOOST_CHECK_THROW(local.solve_extendable(entries, 1, &row, 1, &out, *ws, bad),
                      std::invalid_argument);
  }
}

BOOST_AUTO_TEST_SUITE_END()
