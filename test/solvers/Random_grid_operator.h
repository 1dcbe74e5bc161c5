// A sparse symmetric positive definite test matrix with the sparsity of a mesh.
#ifndef EXPMAP_TEST_RANDOM_GRID_OPERATOR_H
#define EXPMAP_TEST_RANDOM_GRID_OPERATOR_H

#include <Eigen/Sparse>

#include <random>
#include <vector>

namespace expmap_test {

using Sparse_matrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

// diagonal + weight_scale * (graph Laplacian of an nx x ny grid with its
// diagonals, random edge weights in [0.1, 2]): with a small `diagonal` a
// screened Laplacian, with diagonal 1 a heat system M + tL (t = weight_scale)
// whose solutions decay exponentially away from the right-hand side.
inline Sparse_matrix random_grid_operator(int nx, int ny, unsigned seed, double diagonal = 0.01,
                                          double weight_scale = 1.0) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> weight(0.1, 2.0);
  std::vector<Eigen::Triplet<double>> t;
  auto id = [nx](int x, int y) { return y * nx + x; };
  auto edge = [&](int a, int b) {
    const double w = weight_scale * weight(rng);
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
      t.emplace_back(id(x, y), id(x, y), diagonal);
    }
  Sparse_matrix A(nx * ny, nx * ny);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

}  // namespace expmap_test

#endif  // EXPMAP_TEST_RANDOM_GRID_OPERATOR_H
