// Localized block solves must give the numbers of a full solve.
#include <expmap/Cholmod_solver.h>
#include <expmap/Eigen_simplicial_solver.h>
#include <expmap/internal/solver/Localized_cholesky_solver.h>

#include "Random_grid_operator.h"

#include <boost/test/unit_test.hpp>

#include <Eigen/Sparse>

#include <limits>
#include <random>
#include <vector>

namespace {

using Matrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

using expmap_test::random_grid_operator;
using expmap::internal::Localized_cholesky_solver;

// A random grid operator factored by a solver model, and its localized
// solver.
template <class Solver>
struct Factored_grid {
  explicit Factored_grid(unsigned seed) {
    const Matrix A = random_grid_operator(60, 50, seed);
    n = static_cast<int>(A.rows());
    solver.factor(A);
    local = expmap::internal::Localized_cholesky_solver(solver.factor_view());
  }
  int n = 0;
  Solver solver;
  expmap::internal::Localized_cholesky_solver local;
};

// Every requested row of a localized block solve (`out`, row-major, `width`
// columns) against the solver model's own full solve of the columns of B.
template <class Solver>
void check_rows_against_full_solve(Solver& solver, const Eigen::MatrixXd& B, int width,
                                   const std::vector<int>& rows, const std::vector<double>& out) {
  for (int c = 0; c < width; ++c) {
    const Eigen::VectorXd x = solver.solve(B.col(c));
    const double scale = x.cwiseAbs().maxCoeff();
    for (std::size_t i = 0; i < rows.size(); ++i)
      BOOST_TEST(std::abs(out[i * width + c] - x[rows[i]]) <= 1e-12 * scale);
  }
}

// Solves random sparse blocks (widths 1 to 20, split above the
// workspace's width) and compares every requested row with the solver
// model's own full solve; a pruned solve whose threshold drops only zeros
// (drop_below the smallest subnormal) must give the same numbers.
template <class Solver>
void check_against_full_solve(unsigned seed, bool pruned = false,
                              int max_width = Localized_cholesky_solver::max_block_width) {
  Factored_grid<Solver> grid(seed);
  const int n = grid.n;
  auto& local = grid.local;
  auto ws = local.make_workspace(max_width);
  std::mt19937 rng(seed + 7);
  std::uniform_int_distribution<int> pick(0, n - 1);
  for (int trial = 0; trial < 5; ++trial) {
    for (int width : {1, 2, 3, 7, 9, 20}) {
      std::vector<expmap::internal::Rhs_entry> entries;
      Eigen::MatrixXd B = Eigen::MatrixXd::Zero(n, width);
      for (int c = 0; c < width; ++c)
        for (int k = 0; k < 3; ++k) {
          const int row = pick(rng);
          const double v = 1.0 + k;
          entries.push_back({row, c, v});
          B(row, c) += v;
        }
      std::vector<int> rows;
      for (int k = 0; k < 200; ++k) rows.push_back(pick(rng));
      std::vector<double> out(rows.size() * width);
      const auto stats =
          local.solve(entries, width, rows.data(), rows.size(), out.data(), *ws,
                      pruned ? std::numeric_limits<double>::denorm_min() : 0.0);
      BOOST_TEST(stats.forward_nodes > 0u);
      check_rows_against_full_solve(grid.solver, B, width, rows, out);
    }
  }
}

// An extendable solve returns rows in three rounds (each adding new rows
// and repeating some old ones); every round must equal the full solve, and
// an ordinary solve on the same workspace afterwards too (the block was
// left clean).
template <class Solver>
void check_extensions_against_full_solve(unsigned seed) {
  Factored_grid<Solver> grid(seed);
  const int n = grid.n;
  auto& local = grid.local;
  auto ws = local.make_workspace();
  std::mt19937 rng(seed + 11);
  std::uniform_int_distribution<int> pick(0, n - 1);
  for (int trial = 0; trial < 4; ++trial) {
    for (int width : {1, 2, 3, 9}) {
      std::vector<expmap::internal::Rhs_entry> entries;
      Eigen::MatrixXd B = Eigen::MatrixXd::Zero(n, width);
      for (int c = 0; c < width; ++c) {
        const int row = pick(rng);
        entries.push_back({row, c, 1.0 + c});
        B(row, c) += 1.0 + c;
      }
      // Row sets that grow as a query's candidates do: a small set, then
      // larger ones that contain it (random rows, so some repeat).
      std::vector<int> rows;
      for (int round = 0; round < 3; ++round) {
        const int more = round == 0 ? 40 : 150;
        for (int k = 0; k < more; ++k) rows.push_back(pick(rng));
        std::vector<double> out(rows.size() * width);
        const auto stats =
            round == 0
                ? local.solve_extendable(entries, width, rows.data(), rows.size(), out.data(), *ws)
                : local.extend(rows.data(), rows.size(), out.data(), *ws);
        if (round == 0) BOOST_TEST(stats.forward_nodes > 0u);
        if (round > 0) BOOST_TEST(stats.forward_nodes == 0u);
        check_rows_against_full_solve(grid.solver, B, width, rows, out);
      }
    }
  }
  // An ordinary solve after an extendable one (released implicitly).
  std::vector<expmap::internal::Rhs_entry> entries{{pick(rng), 0, 1.0}};
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(n, 1);
  B(entries[0].row, 0) = 1.0;
  std::vector<int> rows(n);
  for (int i = 0; i < n; ++i) rows[i] = i;
  std::vector<double> out(rows.size());
  local.solve(entries, 1, rows.data(), rows.size(), out.data(), *ws);
  check_rows_against_full_solve(grid.solver, B, 1, rows, out);
  BOOST_CHECK_THROW(local.extend(rows.data(), rows.size(), out.data(), *ws), std::logic_error);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(localized_solver)

BOOST_AUTO_TEST_CASE(extended_solves_equal_full_solves) {
  check_extensions_against_full_solve<expmap::Cholmod_solver>(21);
  check_extensions_against_full_solve<expmap::Eigen_simplicial_solver>(22);
}

BOOST_AUTO_TEST_CASE(cholmod_localized_equals_full_solve) {
  check_against_full_solve<expmap::Cholmod_solver>(1);
}

BOOST_AUTO_TEST_CASE(eigen_localized_equals_full_solve) {
  check_against_full_solve<expmap::Eigen_simplicial_solver>(2);
}

BOOST_AUTO_TEST_CASE(pruned_solve_dropping_only_zeros_equals_full_solve) {
  check_against_full_solve<expmap::Cholmod_solver>(4, /*pruned=*/true);
  check_against_full_solve<expmap::Eigen_simplicial_solver>(5, /*pruned=*/true);
}

// A workspace holds blocks of the width it was made for (rounded up to a
// kernel's): solve() splits wider ones, solve_extendable() refuses them.
BOOST_AUTO_TEST_CASE(narrow_workspaces_split_wide_blocks) {
  check_against_full_solve<expmap::Cholmod_solver>(6, /*pruned=*/false, /*max_width=*/1);
  check_against_full_solve<expmap::Cholmod_solver>(7, /*pruned=*/true, /*max_width=*/3);
}

BOOST_AUTO_TEST_CASE(workspace_width_sizes_the_block) {
  Factored_grid<expmap::Cholmod_solver> grid(8);
  const auto& local = grid.local;
  auto narrow = local.make_workspace(1);
  auto wide = local.make_workspace();
  BOOST_TEST(narrow->max_width() == 1);
  BOOST_TEST(wide->max_width() == Localized_cholesky_solver::max_block_width);
  BOOST_TEST(local.make_workspace(3)->max_width() == 4);
  BOOST_TEST(local.make_workspace(40)->max_width() == Localized_cholesky_solver::max_block_width);
  BOOST_CHECK_THROW(local.make_workspace(0), std::invalid_argument);
  // The block is n x width doubles.
  const std::size_t n = static_cast<std::size_t>(grid.n);
  BOOST_TEST(wide->bytes() >= narrow->bytes() + 15 * n * sizeof(double));
  BOOST_TEST(narrow->bytes() < 2 * n * sizeof(double) + 32 * local.number_of_supernodes());

  const std::vector<expmap::internal::Rhs_entry> entries{{10, 0, 1.0}, {20, 1, 1.0}};
  std::vector<int> rows{10, 20, 30};
  std::vector<double> out(rows.size() * 2);
  BOOST_CHECK_THROW(
      local.solve_extendable(entries, 2, rows.data(), rows.size(), out.data(), *narrow),
      std::invalid_argument);
  auto two = local.make_workspace(2);
  local.solve_extendable(entries, 2, rows.data(), rows.size(), out.data(), *two);
  BOOST_CHECK_NO_THROW(local.extend(rows.data(), rows.size(), out.data(), *two));
}

// The heat and Poisson systems of a mesh share their sparsity, so the
// second factorization can take the first one's ordering.
BOOST_AUTO_TEST_CASE(cholmod_factor_with_a_given_ordering) {
  const Matrix first = random_grid_operator(40, 30, 8, 1.0, 10.0);
  const Matrix second = random_grid_operator(40, 30, 9);  // same pattern, other values
  expmap::Cholmod_solver ordered;
  ordered.factor(first);
  const auto view = ordered.factor_view();
  const std::vector<int> ordering(view.permutation, view.permutation + view.size);
  expmap::Cholmod_solver solver;
  solver.factor(second, ordering);
  expmap::internal::Localized_cholesky_solver local(solver.factor_view());
  auto ws = local.make_workspace();
  const int n = static_cast<int>(second.rows());
  std::vector<int> rows(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) rows[i] = i;
  std::vector<double> out(rows.size());
  const std::vector<expmap::internal::Rhs_entry> entries{{17, 0, 1.0}, {600, 0, -2.0}};
  local.solve(entries, 1, rows.data(), rows.size(), out.data(), *ws);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(n);
  b[17] = 1.0;
  b[600] = -2.0;
  Eigen::SimplicialLDLT<Matrix> reference(second);  // independent of CHOLMOD
  const Eigen::VectorXd x = reference.solve(b);
  for (int i = 0; i < n; ++i) BOOST_TEST(std::abs(out[i] - x[i]) <= 1e-12 * x.cwiseAbs().maxCoeff());

  std::vector<int> wrong = ordering;
  wrong[3] = wrong[4];
  BOOST_CHECK_THROW(solver.factor(second, wrong), std::runtime_error);
  wrong.pop_back();
  BOOST_CHECK_THROW(solver.factor(second, wrong), std::runtime_error);
}

BOOST_AUTO_TEST_CASE(localized_solve_touches_fewer_nodes_than_the_mesh) {
  const Matrix A = random_grid_operator(100, 100, 3);
  expmap::Cholmod_solver solver;
  solver.factor(A);
  expmap::internal::Localized_cholesky_solver local(solver.factor_view());
  auto ws = local.make_workspace();
  std::vector<expmap::internal::Rhs_entry> entries{{5050, 0, 1.0}};
  std::vector<int> rows{5050, 5051, 5150};
  std::vector<double> out(3);
  const auto stats = local.solve(entries, 1, rows.data(), rows.size(), out.data(), *ws);
  // Nested dissection keeps root paths short: far fewer than n nodes.
  BOOST_TEST(stats.forward_nodes < 2000u);
  BOOST_TEST(local.tree_height() < 2000);
  BOOST_TEST(local.tree_height() >= 100);  // at least the top separator
}

BOOST_AUTO_TEST_CASE(not_positive_definite_is_reported) {
  Matrix A(2, 2);
  A.insert(0, 0) = 1.0;
  A.insert(1, 0) = 2.0;
  A.insert(0, 1) = 2.0;
  A.insert(1, 1) = 1.0;
  expmap::Cholmod_solver c;
  BOOST_CHECK_THROW(c.factor(A), std::runtime_error);
  expmap::Eigen_simplicial_solver e;
  BOOST_CHECK_THROW(e.factor(A), std::runtime_error);
}

BOOST_AUTO_TEST_SUITE_END()
