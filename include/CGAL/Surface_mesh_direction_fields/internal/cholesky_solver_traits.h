// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_CHOLESKY_SOLVER_TRAITS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_CHOLESKY_SOLVER_TRAITS_H

// How the algorithms obtain and drive a SparseCholeskySolver: the type from the
// `sparse_linear_solver` named parameter (default Cholmod_cholesky), CGAL's
// SparseLinearAlgebraWithFactorTraits_d models (Eigen_solver_traits) wrapped to the package's
// concept, and the optional Cholesky_hints overload of factor().

#include <CGAL/Surface_mesh_direction_fields/Cholmod_cholesky.h>
#include <CGAL/Surface_mesh_direction_fields/parameters.h>

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include <limits>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// A model of CGAL's SparseLinearAlgebraWithFactorTraits_d: factor(Matrix, NT&) and
// linear_solver(Vector, Vector&).
template <typename T, typename = void>
struct Is_cgal_factor_traits : std::false_type {};
template <typename T>
struct Is_cgal_factor_traits<T, std::void_t<
    typename T::Matrix, typename T::Vector, typename T::NT,
    decltype(std::declval<T&>().factor(std::declval<const typename T::Matrix&>(), std::declval<typename T::NT&>())),
    decltype(std::declval<T&>().linear_solver(std::declval<const typename T::Vector&>(),
                                              std::declval<typename T::Vector&>()))>> : std::true_type {};

// CGAL's solver traits seen as a SparseCholeskySolver: the lower triangle is copied into the
// traits' matrix type (both triangles; symmetric matrix types keep the lower one).
template <typename Traits>
class Cgal_factor_traits_cholesky
{
public:
  typedef Eigen::SparseMatrix<double, Eigen::ColMajor, int> Matrix;

  Cgal_factor_traits_cholesky() = default;
  explicit Cgal_factor_traits_cholesky(const Traits& t) : traits_(t) {}
  Cgal_factor_traits_cholesky(const Cgal_factor_traits_cholesky& o) : traits_(o.traits_) {}
  Cgal_factor_traits_cholesky& operator=(const Cgal_factor_traits_cholesky& o)
  {
    traits_ = o.traits_;
    matrix_.reset();
    return *this;
  }

  bool factor(const Matrix& lower, std::string& message)
  {
    const Eigen::Index n = lower.rows();
    matrix_.reset(new typename Traits::Matrix(int(n), int(n)));
    for(Eigen::Index j = 0; j < lower.outerSize(); ++j)
      for(Matrix::InnerIterator it(lower, j); it; ++it) {
        if(it.row() < j) continue;   // upper entries are ignored, as by the other models
        matrix_->set_coef(std::size_t(it.row()), std::size_t(j), it.value(), true);
        if(it.row() != j) matrix_->set_coef(std::size_t(j), std::size_t(it.row()), it.value(), true);
      }
    typename Traits::NT d;
    if(!traits_.factor(*matrix_, d)) {
      message = "the sparse_linear_solver could not factor the matrix";
      return false;
    }
    return true;
  }
  bool refactor(const Matrix& lower, std::string& message) { return factor(lower, message); }

  Eigen::VectorXd solve(const Eigen::VectorXd& b) const
  {
    typename Traits::Vector B(int(b.size())), X(int(b.size()));
    for(Eigen::Index i = 0; i < b.size(); ++i) B[i] = b[i];
    Eigen::VectorXd x(b.size());
    if(!traits_.linear_solver(B, X)) x.setConstant(std::numeric_limits<double>::quiet_NaN());
    else for(Eigen::Index i = 0; i < b.size(); ++i) x[i] = X[i];
    return x;
  }

private:
  mutable Traits traits_;   // CGAL's linear_solver() is not const
  std::unique_ptr<typename Traits::Matrix> matrix_;   // the traits keep a pointer to it
};

template <typename S, bool = Is_cgal_factor_traits<S>::value>
struct Cholesky_solver_of { typedef S type; };
template <typename S>
struct Cholesky_solver_of<S, true> { typedef Cgal_factor_traits_cholesky<S> type; };

// The SparseCholeskySolver type of a named-parameter pack.
template <typename NamedParameters, typename Default = Cholmod_cholesky>
struct Get_cholesky_solver
{
  typedef typename CGAL::internal_np::Lookup_named_param_def<CGAL::internal_np::sparse_linear_solver_t,
                                                             NamedParameters, Default>::type Given;
  typedef typename Cholesky_solver_of<Given>::type type;
};

// The solver of `np` (a copy of the one given, wrapped if it is CGAL's solver traits), else a
// default-constructed Solver; Solver must be Get_cholesky_solver<NamedParameters, Solver>::type.
template <typename Solver, typename NamedParameters>
Solver make_cholesky_solver(const NamedParameters& np)
{
  static_assert(std::is_same<typename Get_cholesky_solver<NamedParameters, Solver>::type, Solver>::value,
                "the sparse_linear_solver parameter does not match the class's SparseCholeskySolver");
  if constexpr(parameters::is_default_parameter<NamedParameters, CGAL::internal_np::sparse_linear_solver_t>::value)
    return Solver();
  else
    return Solver(parameters::get_parameter(np, CGAL::internal_np::sparse_linear_solver));
}

template <typename S, typename = void>
struct Accepts_cholesky_hints : std::false_type {};
template <typename S>
struct Accepts_cholesky_hints<S, std::void_t<decltype(std::declval<S&>().factor(
    std::declval<const Cholmod_cholesky::Matrix&>(), std::declval<const Cholesky_hints&>(),
    std::declval<std::string&>()))>> : std::true_type {};

// factor() with the hints when the solver takes them.
template <typename S>
bool factor_with_hints(S& solver, const Cholmod_cholesky::Matrix& lower, const Cholesky_hints& hints,
                       std::string& message)
{
  if constexpr(Accepts_cholesky_hints<S>::value) return solver.factor(lower, hints, message);
  else return solver.factor(lower, message);
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_CHOLESKY_SOLVER_TRAITS_H
