// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

/*!
\ingroup PkgSurfaceMeshDirectionFieldsConcepts
\brief A sparse Cholesky solver: it factors a sparse symmetric positive definite matrix once and
then solves many linear systems with that factorisation.

\cgalConcept

It is what
`CGAL::Surface_mesh_direction_fields::Trivial_connection` uses to factor the normal equations
\f$A W A^\top\f$ of the trivial-connection problem (second template parameter, and the
`sparse_linear_solver` named parameter of its constructor and of
`CGAL::Surface_mesh_direction_fields::compute_trivial_connection()`).

The matrix is handed over as its lower triangle (diagonal included) in compressed
column-major storage; entries above the diagonal, if any, must be ignored. A solver is used
in this order: one `factor()` for a new sparsity pattern, any number of `solve()` calls, and,
when only the values change, `refactor()` followed by more solves. Every `solve()` uses the
last successful factorisation. Calls come from one thread at a time; a model may use several
threads inside a call (`CGAL::Surface_mesh_direction_fields::Cholmod_cholesky` does for large
matrices).

Copying a solver copies its settings (e.g. the options of the underlying library), not a
factorisation: a copy must be factored before it solves. This is how the `sparse_linear_solver`
named parameter works: the algorithm copies the solver it is given and factors the copy.

\cgalHasModelsBegin
\cgalHasModels{`CGAL::Surface_mesh_direction_fields::Cholmod_cholesky` (the default)}
\cgalHasModels{`CGAL::Surface_mesh_direction_fields::Eigen_sparse_cholesky`}
\cgalHasModelsEnd

\cgal's `Eigen_solver_traits` (a model of \cgal's concept `SparseLinearAlgebraWithFactorTraits_d`)
is not a model, but `CGAL::Surface_mesh_direction_fields::compute_trivial_connection()` accepts
it through its `sparse_linear_solver` named parameter and wraps it into one (see
\ref SMDFSecSolvers).

\sa \ref SMDFSecSolvers
*/
class SparseCholeskySolver
{
public:
  /// \name Types
  /// @{

  /// The matrix type. Exactly this type: the lower triangle of a symmetric positive definite
  /// matrix, stored by compressed columns with `int` indices.
  typedef Eigen::SparseMatrix<double, Eigen::ColMajor, int> Matrix;

  /// @}

  /// \name Creation
  /// @{

  /// Default constructor: a solver with default settings and no factorisation.
  SparseCholeskySolver();

  /// Copy constructor: copies the settings of `other`, not its factorisation.
  SparseCholeskySolver(const SparseCholeskySolver& other);

  /// @}

  /// \name Factorisation
  /// @{

  /// Analyses the sparsity pattern of `lower` (e.g. computes a fill-reducing ordering) and
  /// computes its numeric factorisation. Returns `true` on success; returns `false` and sets
  /// `message` to a short explanation if the factorisation fails, e.g. because the matrix is
  /// not positive definite.
  bool factor(const Matrix& lower, std::string& message);

  /// Numeric factorisation of a matrix with the same sparsity pattern as the matrix of the
  /// last successful `factor()`, but new values; the analysis of `factor()` may be reused.
  /// Returns `true` on success, `false` with a `message` as `factor()` does.
  bool refactor(const Matrix& lower, std::string& message);

  /// Optional overload of `factor(lower, message)` that also receives what the caller knows
  /// about the matrix: rows already in a fill-reducing order, a split into two independent
  /// domains and a separator, many solves to come (see
  /// `CGAL::Surface_mesh_direction_fields::Cholesky_hints`).
  ///
  /// A model need not have it. Algorithms call this overload when the model has it and
  /// `factor(lower, message)` otherwise; a model may ignore any of the hints.
  bool factor(const Matrix& lower,
              const CGAL::Surface_mesh_direction_fields::Cholesky_hints& hints,
              std::string& message);

  /// @}

  /// \name Solving
  /// @{

  /// Returns the solution \f$x\f$ of \f$M x = b\f$, where \f$M\f$ is the symmetric matrix
  /// whose lower triangle was given to the last successful `factor()` or `refactor()`.
  /// `b` has as many entries as \f$M\f$ has rows.
  /// \pre the last call of `factor()` or `refactor()` succeeded.
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;

  /// @}
};
