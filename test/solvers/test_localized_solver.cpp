// Localized block solves must give the numbers of a full solve.
#include <expmap/Cholmod_solver.h>
#include <expmap/Eigen_simplicial_solver.h>
#include <expmap/internal/Localized_cholesky_solver.h>

#include <boost/test/unit_test.hpp>

#include <Eigen/Sparse>

#include <random>
#include <vector>

namespace {

using Matrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

// A screened graph Laplacian of an nx x ny grid with random positive edge
// weights: symmetric positive definite, with the sparsity of a mesh.
Matrix random_grid_operator(int nx, int ny, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> weight(0.1, 2.0);
  std::vector<Eigen::Triplet<double>> t;
  auto id = [nx](int x, int y) { return y * nx + x; };
  auto edge = [&](int a, int b) {
    const double w = weight(rng);
    t.emplace_back(a, b, -w);
    t.emplace_back(b, a, -w);
    t.emplace_back(a, a, w);
    t.emplace_back(b, b, w);
  };
  for (int y = 0; y < ny; ++y)
    for (int x = 0; x < nx; ++x) {
      if (x + 1 < nx) edge(id(x, y), id(x + 1, y));
      if (y + 1 < ny) edge(id(x, y), id(x, y + 1));
      if (x + 1 < nx && y + 1 < ny) edge(id(x, y), id(x + 1, y + 1));
      t.emplace_back(id(x, y), id(x, y), 0.01);
    }
  Matrix A(nx * ny, nx * ny);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

template <class Solver>
void check_against_full_solve(unsigned seed) {
  const Matrix A = random_grid_operator(60, 50, seed);
  const int n = static_cast<int>(A.rows());
  Solver solver;
  solver.factor(A);
  expmap::internal::Localized_cholesky_solver local(solver.factor_view());
  auto ws = local.make_workspace();
  std::mt19937 rng(seed + 7);
  std::uniform_int_distribution<int> pick(0, n - 1);
  for (int trial = 0; trial < 5; ++trial) {
    for (int width : {1, 3, 7, 9, 20}) {
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
      const auto stats = local.solve(entries, width, rows.data(), rows.size(), out.data(), *ws);
      BOOST_TEST(stats.forward_nodes > 0u);
      for (int c = 0; c < width; ++c) {
        const Eigen::VectorXd x = solver.solve(B.col(c));
        const double scale = x.cwiseAbs().maxCoeff();
        for (std::size_t i = 0; i < rows.size(); ++i)
          BOOST_TEST(std::abs(out[i * width + c] - x[rows[i]]) <= 1e-12 * scale);
      }
    }
  }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(localized_solver)

BOOST_AUTO_TEST_CASE(cholmod_localized_equals_full_solve) {
  check_against_full_solve<expmap::Cholmod_solver>(1);
}

BOOST_AUTO_TEST_CASE(eigen_localized_equals_full_solve) {
  check_against_full_solve<expmap::Eigen_simplicial_solver>(2);
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
