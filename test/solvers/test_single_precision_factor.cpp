// A factor kept in single precision: the same solves, to the round-off of
// floats, in half the memory.
#include <expmap/Cholmod_solver.h>
#include <expmap/internal/solver/Localized_cholesky_solver.h>

#include "Solutions_to_compare.h"
#include "Random_grid_operator.h"

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace {

using expmap::Factor_precision;
using expmap::internal::Localized_cholesky_solver;
using expmap::internal::Rhs_entry;

// One matrix factored once, its localized solver in both precisions.
struct Both_precisions {
  Both_precisions(int nx, int ny, double diagonal, double weight_scale) {
    const auto A = expmap_test::random_grid_operator(nx, ny, 3, diagonal, weight_scale);
    n = static_cast<int>(A.rows());
    solver.factor(A);
    exact = Localized_cholesky_solver(solver.factor_view());
    single = Localized_cholesky_solver(solver.factor_view(), Factor_precision::single_precision);
  }
  int n = 0;
  expmap::Cholmod_solver solver;
  Localized_cholesky_solver exact, single;
};

}  // namespace

BOOST_AUTO_TEST_CASE(single_precision_halves_the_entries_memory) {
  const Both_precisions f(40, 30, 1.0, 10.0);
  BOOST_TEST((f.exact.precision() == Factor_precision::double_precision));
  BOOST_TEST((f.single.precision() == Factor_precision::single_precision));
  BOOST_TEST(f.single.number_of_entries() == f.exact.number_of_entries());
  BOOST_TEST(f.exact.entry_bytes() == f.exact.number_of_entries() * sizeof(double));
  BOOST_TEST(2 * f.single.entry_bytes() == f.exact.entry_bytes());
}

// A heat system is an M-matrix: its factor's off-diagonal entries are
// non-positive, so a nonnegative right-hand side is solved without
// cancellation and rounding the factor perturbs every value by a small
// multiple of float round-off relative to itself, as long as the factor's
// entries stay above the smallest float (below, supernodes_beyond_the_
// float_range_stay_double).
BOOST_AUTO_TEST_CASE(heat_values_keep_their_relative_accuracy) {
  const Both_precisions f(60, 50, 1.0, 1.0);
  const std::vector<Rhs_entry> b{{25 * 60 + 30, 0, 1.0}};
  const std::vector<double> x = expmap_test::solve_every_row(f.exact, b, 1),
                            y = expmap_test::solve_every_row(f.single, b, 1);
  double worst = 0, smallest = 1;
  for (std::size_t i = 0; i < x.size(); ++i) {
    BOOST_TEST_REQUIRE(x[i] > 0);
    worst = std::max(worst, std::abs(y[i] - x[i]) / x[i]);
    smallest = std::min(smallest, x[i]);
  }
  BOOST_TEST_MESSAGE("heat from 1 to " << smallest << ": largest relative change " << worst);
  BOOST_TEST(smallest < 1e-12);  // the heat spans many binades
  BOOST_TEST(worst < 1e-6);
  BOOST_TEST(worst > 0);  // the entries were rounded
}

// A heat system with fast decay: the factor's entries between far vertices
// of a separator fall below the smallest float. Those supernodes stay in
// double precision, and the heat keeps its relative accuracy down to values
// far below the float range.
BOOST_AUTO_TEST_CASE(supernodes_beyond_the_float_range_stay_double) {
  const Both_precisions f(60, 50, 1.0, 0.02);
  BOOST_TEST(f.single.entry_bytes() > 4 * f.single.number_of_entries());  // some in double
  BOOST_TEST(f.single.entry_bytes() < 6 * f.single.number_of_entries());  // most in floats
  const std::vector<Rhs_entry> b{{25 * 60 + 30, 0, 1.0}};
  const std::vector<double> x = expmap_test::solve_every_row(f.exact, b, 1),
                            y = expmap_test::solve_every_row(f.single, b, 1);
  double worst = 0, smallest = 1;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!(x[i] > 1e-280)) continue;
    worst = std::max(worst, std::abs(y[i] - x[i]) / x[i]);
    smallest = std::min(smallest, x[i]);
  }
  BOOST_TEST_MESSAGE("heat down to " << smallest << ": largest relative change " << worst);
  BOOST_TEST(smallest < 1e-60);
  BOOST_TEST(worst < 1e-6);
}

// A signed right-hand side (the Poisson step's, the star gradient's) can
// cancel: the change is bounded relative to the solution's largest value.
BOOST_AUTO_TEST_CASE(signed_solves_keep_their_accuracy_relative_to_the_solution) {
  const Both_precisions f(60, 50, 0.01, 1.0);
  const std::vector<Rhs_entry> b{
      {10 * 60 + 10, 0, 1.0}, {40 * 60 + 50, 0, -1.0}, {30 * 60 + 30, 1, 2.0}, {31 * 60 + 30, 1, -2.0}};
  const std::vector<double> x = expmap_test::solve_every_row(f.exact, b, 2),
                            y = expmap_test::solve_every_row(f.single, b, 2);
  for (int c = 0; c < 2; ++c) {
    double scale = 0, worst = 0;
    for (int i = 0; i < f.n; ++i) scale = std::max(scale, std::abs(x[2 * i + c]));
    for (int i = 0; i < f.n; ++i) worst = std::max(worst, std::abs(y[2 * i + c] - x[2 * i + c]));
    BOOST_TEST_MESSAGE("column " << c << ": largest change " << worst / scale << " of the largest value");
    BOOST_TEST(worst < 1e-6 * scale);
  }
}

// The largest-first search and the pruned solves run on the rounded entries
// as on the exact ones.
BOOST_AUTO_TEST_CASE(largest_first_and_pruned_solves_work_in_single_precision) {
  const Both_precisions f(90, 80, 1.0, 20.0);
  const std::vector<Rhs_entry> b{{40 * 90 + 45, 0, 1.0}};
  BOOST_TEST(expmap_test::largest_rows(f.single, b, 700) ==
             expmap_test::largest_rows(f.exact, b, 700));

  std::vector<int> rows(static_cast<std::size_t>(f.n));
  std::iota(rows.begin(), rows.end(), 0);
  const std::vector<double> x = expmap_test::solve_every_row(f.exact, b, 1);
  std::vector<double> pruned(rows.size());
  auto ws = f.single.make_workspace();
  const double smallest = *std::min_element(x.begin(), x.end());
  f.single.solve(b, 1, rows.data(), rows.size(), pruned.data(), *ws, 1e-14 * smallest);
  for (std::size_t i = 0; i < x.size(); ++i)
    BOOST_TEST(std::abs(pruned[i] - x[i]) < 2e-6 * x[i]);
}
