// The SparseCholeskySolver concept, documented as CGAL documents concepts:
// a class that exists only for Doxygen (this file is never compiled).

/// \ingroup PkgExpmapConcepts
/// \cgalConcept
///
/// Factors a symmetric positive definite sparse matrix once and exposes the
/// factor as a `Cholesky_factor_view`. The localized triangular solves of
/// `Heat_exponential_map` are done by the package on that view, so a model
/// provides only the factorization; `Heat_exponential_map` copies the
/// factor once and then releases the model.
///
/// \cgalHasModel `expmap::Cholmod_solver` (the default), `expmap::Eigen_simplicial_solver`
///
/// \code
/// expmap::Heat_exponential_map<Mesh, CGAL::Default, expmap::Eigen_simplicial_solver> heat(mesh);
/// \endcode
class SparseCholeskySolver {
 public:
  /// Column-major sparse matrix of doubles with `int` indices:
  /// `Eigen::SparseMatrix<double, Eigen::ColMajor, int>`.
  using Matrix = unspecified_type;

  /// Default constructible; need not be copyable.
  SparseCholeskySolver();

  /// Factors `A`, reading only its lower triangle. May be called again to
  /// factor another matrix (the previous view becomes invalid).
  /// \throws std::runtime_error if `A` is not square or not positive definite.
  void factor(const Matrix& A);

  /// The factor: `A(P, P) = L D L^T` as compressed columns, valid while the
  /// model lives and is not re-factored.
  /// \pre `factor()` succeeded.
  expmap::Cholesky_factor_view factor_view() const;

  /// Number of stored entries of the factor, for memory reports.
  std::size_t factor_nonzeros() const;

  /// Full solve of `A x = b` with the model's own triangular solves; the
  /// tests use it as an independent oracle for the localized solves.
  /// \pre `factor()` succeeded.
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
};
