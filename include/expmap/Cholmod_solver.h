// Copyright (c) 2026 expmap contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef EXPMAP_CHOLMOD_SOLVER_H
#define EXPMAP_CHOLMOD_SOLVER_H

/// \file Cholmod_solver.h
/// CHOLMOD (SuiteSparse) model of the `SparseCholeskySolver` concept.

#include <expmap/Cholesky_factor_view.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <cholmod.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace expmap {

/// \ingroup PkgExpmapSolvers
/// Factors a symmetric positive definite matrix with CHOLMOD, ordered by
/// METIS nested dissection, and exposes the factor for localized solves.
///
/// The factorization itself is supernodal (fast, BLAS based); the factor is
/// then converted once to a simplicial LL^T in compressed columns, the form
/// the localized triangular solves traverse column by column.
///
/// \cgalModels `SparseCholeskySolver`
class Cholmod_solver {
 public:
  /// Column-major sparse matrix type accepted by `factor()`.
  using Matrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

  Cholmod_solver() { cholmod_start(&m_common); configure(); }
  ~Cholmod_solver() { release(); cholmod_finish(&m_common); }
  Cholmod_solver(const Cholmod_solver&) = delete;
  Cholmod_solver& operator=(const Cholmod_solver&) = delete;

  /// Factors `A` (only its lower triangle is read).
  /// \throws std::runtime_error if `A` is not square or not positive definite.
  void factor(const Matrix& A) { factor_with(A, nullptr); }

  /// Factors `A` with a given fill-reducing ordering instead of METIS's:
  /// `ordering[k]` is the row of A that becomes pivot k. Pass the
  /// permutation of an earlier factor of a matrix with the same sparsity
  /// (`factor_view().permutation`, e.g. the heat system's for the Poisson
  /// system, whose pattern is the same or smaller): the METIS ordering is
  /// most of the factorization's time on large meshes (18 s of 28 s of CPU
  /// time on a 2.85M-vertex mesh, doc/paper_scale.md).
  /// \throws std::runtime_error as `factor(A)`, or if `ordering` is not a
  ///         permutation of 0..n-1.
  ///
  /// \code
  /// expmap::Cholmod_solver heat, poisson;
  /// heat.factor(heat_matrix);
  /// const auto v = heat.factor_view();
  /// poisson.factor(laplacian, std::vector<int>(v.permutation, v.permutation + v.size));
  /// \endcode
  void factor(const Matrix& A, const std::vector<int>& ordering) {
    const std::size_t n = static_cast<std::size_t>(A.rows());
    std::vector<char> seen(n, 0);
    bool permutation = ordering.size() == n;
    for (std::size_t k = 0; permutation && k < n; ++k) {
      const int row = ordering[k];
      permutation = row >= 0 && static_cast<std::size_t>(row) < n && !seen[row];
      if (permutation) seen[row] = 1;
    }
    if (!permutation)
      throw std::runtime_error("Cholmod_solver: the given ordering is not a permutation of the " +
                               std::to_string(n) + " rows");
    factor_with(A, ordering.data());
  }


  /// The factor, for localized solves. \pre `factor()` succeeded.
  Cholesky_factor_view factor_view() const {
    Cholesky_factor_view v;
    if (m_factor == nullptr) return v;
    v.size = static_cast<int>(m_factor->n);
    v.permutation = static_cast<const int*>(m_factor->Perm);
    v.column_start = static_cast<const int*>(m_factor->p);
    v.row_index = static_cast<const int*>(m_factor->i);
    v.value = static_cast<const double*>(m_factor->x);
    v.unit_diagonal = false;
    return v;
  }

  /// Full solve of A x = b with CHOLMOD's own triangular solves (an
  /// independent oracle for the localized kernel). \pre `factor()` succeeded.
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const {
    Eigen::VectorXd rhs = b;
    cholmod_dense dense{};
    dense.nrow = dense.d = static_cast<size_t>(rhs.size());
    dense.ncol = 1;
    dense.nzmax = dense.nrow;
    dense.x = rhs.data();
    dense.xtype = CHOLMOD_REAL;
    dense.dtype = CHOLMOD_DOUBLE;
    cholmod_common* common = const_cast<cholmod_common*>(&m_common);
    cholmod_dense* x = cholmod_solve(CHOLMOD_A, m_factor, &dense, common);
    if (x == nullptr) throw std::runtime_error("Cholmod_solver: solve failed");
    Eigen::VectorXd result =
        Eigen::Map<Eigen::VectorXd>(static_cast<double*>(x->x), rhs.size());
    cholmod_free_dense(&x, common);
    return result;
  }

  /// Number of stored entries of the factor (its memory is about 12 bytes each).
  std::size_t factor_nonzeros() const {
    return m_factor == nullptr ? 0 : static_cast<const int*>(m_factor->p)[m_factor->n];
  }

 private:
  void factor_with(const Matrix& A, const int* ordering) {
    if (A.rows() != A.cols())
      throw std::runtime_error("Cholmod_solver: the matrix is not square");
    release();
    Matrix lower = A.triangularView<Eigen::Lower>();
    lower.makeCompressed();
    cholmod_sparse view = sparse_view(lower);
    if (ordering == nullptr) {
      m_factor = cholmod_analyze(&view, &m_common);
    } else {
      // A given ordering is tried alone (and still postordered).
      const int nmethods = m_common.nmethods, method = m_common.method[0].ordering;
      m_common.nmethods = 1;
      m_common.method[0].ordering = CHOLMOD_GIVEN;
      m_factor = cholmod_analyze_p(&view, const_cast<int*>(ordering), nullptr, 0, &m_common);
      m_common.nmethods = nmethods;
      m_common.method[0].ordering = method;
    }
    if (m_factor == nullptr) throw_status("symbolic analysis");
    cholmod_factorize(&view, m_factor, &m_common);
    if (m_common.status != CHOLMOD_OK || m_factor->minor < m_factor->n)
      throw std::runtime_error(
          "Cholmod_solver: the matrix is not positive definite (pivot " +
          std::to_string(m_factor->minor) + " of " + std::to_string(m_factor->n) +
          " failed); the mesh may have degenerate or disconnected parts");
    if (!cholmod_change_factor(CHOLMOD_REAL, /*to_ll=*/1, /*to_super=*/0,
                               /*to_packed=*/1, /*to_monotonic=*/1, m_factor, &m_common))
      throw_status("conversion to a simplicial factor");
  }

  void configure() {
    // METIS nested dissection only: its balanced separators keep the
    // elimination tree shallow, which is what makes localized solves cheap.
    m_common.nmethods = 1;
    m_common.method[0].ordering = CHOLMOD_METIS;
    m_common.postorder = 1;
    m_common.supernodal = CHOLMOD_SUPERNODAL;
    m_common.print = 0;  // errors are reported by exceptions, not on stderr
  }

  static cholmod_sparse sparse_view(Matrix& lower) {
    cholmod_sparse s{};
    s.nrow = static_cast<size_t>(lower.rows());
    s.ncol = static_cast<size_t>(lower.cols());
    s.nzmax = static_cast<size_t>(lower.nonZeros());
    s.p = lower.outerIndexPtr();
    s.i = lower.innerIndexPtr();
    s.x = lower.valuePtr();
    s.stype = -1;  // symmetric, lower triangle stored
    s.itype = CHOLMOD_INT;
    s.xtype = CHOLMOD_REAL;
    s.dtype = CHOLMOD_DOUBLE;
    s.sorted = 1;
    s.packed = 1;
    return s;
  }

  void throw_status(const char* step) {
    throw std::runtime_error(std::string("Cholmod_solver: ") + step +
                             " failed (CHOLMOD status " + std::to_string(m_common.status) + ")");
  }

  void release() {
    if (m_factor != nullptr) cholmod_free_factor(&m_factor, &m_common);
  }

  cholmod_common m_common;
  cholmod_factor* m_factor = nullptr;
};

}  // namespace expmap

#endif  // EXPMAP_CHOLMOD_SOLVER_H
