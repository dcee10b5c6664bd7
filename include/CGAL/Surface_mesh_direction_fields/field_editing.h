// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_FIELD_EDITING_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_FIELD_EDITING_H

// Editing an N-RoSy field with direction and length constraints (Lai et al. 2010, section 4.2):
// a rotation angle psi and a log-length rho, harmonic away from the constraints, added to the
// field. Neither creates nor moves a singularity: psi is a function, so the rotation it adds
// around any loop telescopes to zero.

#include <CGAL/Surface_mesh_direction_fields/Cholmod_cholesky.h>
#include <CGAL/Surface_mesh_direction_fields/Intrinsic_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/internal/cholesky_solver_traits.h>
#include <CGAL/Surface_mesh_direction_fields/internal/cotan_weights.h>
#include <CGAL/Surface_mesh_direction_fields/intrinsic_triangle.h>

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsFieldDesign
/// Outcome of `Rosy_field_editor::edit()`.
struct Field_edit_status
{
  bool success = false;               ///< both solves succeeded
  std::string message;                ///< empty on success
  double max_direction_error = 0;     ///< largest distance of an edited direction to its constraint, over the nearest of the N directions (radians)
  double max_length_error = 0;        ///< largest relative distance of an edited length to its constraint
  double factor_seconds = 0;          ///< time spent factoring in this call (0 when the factorisations were reused)
  double solve_seconds = 0;           ///< time of the solves in this call
};

namespace internal {

// One scalar on the faces, harmonic for the dual Laplacian except at the constrained faces:
// hard constraints are Dirichlet values, soft ones add weight * (s_f - value)^2 to the energy
// s^T L s. Faces of components without a constraint keep 0. Factored once per set of
// constrained faces and weight; new values cost one solve.
class Face_harmonic_interpolation
{
public:
  template <typename TM>
  void set_up(const Mesh_arrays<TM>& m, const std::vector<double>& edge_weight)
  {
    nf_ = m.number_of_faces();
    adj_.clear();
    for(std::size_t e = 0; e < m.number_of_edges(); ++e) {
      const int f = m.face[2 * e], g = m.face[2 * e + 1];
      if(f >= 0 && g >= 0 && f != g) adj_.push_back({f, g, edge_weight[e]});
    }
    component_.assign(nf_, -1);   // components of the dual graph
    std::vector<std::vector<int>> nbr(nf_);
    for(const Link& l : adj_) { nbr[std::size_t(l.f)].push_back(l.g); nbr[std::size_t(l.g)].push_back(l.f); }
    int c = 0;
    for(std::size_t s = 0; s < nf_; ++s) {
      if(component_[s] >= 0) continue;
      std::vector<int> stack(1, int(s));
      component_[s] = c;
      while(!stack.empty()) {
        const int f = stack.back();
        stack.pop_back();
        for(int g : nbr[std::size_t(f)]) if(component_[std::size_t(g)] < 0) { component_[std::size_t(g)] = c; stack.push_back(g); }
      }
      ++c;
    }
    components_ = c;
    factored_ = false;
  }

  // The constrained faces (distinct) and the soft weight (0: hard); refactors on change.
  void set_constraints(const std::vector<int>& faces, double soft_weight)
  {
    if(faces != faces_ || soft_weight != weight_) factored_ = false;
    faces_ = faces;
    weight_ = soft_weight;
  }

  // s for the values of the constrained faces (in set_constraints() order)
  bool solve(const std::vector<double>& values, std::vector<double>& s, std::string& message, double& factor_seconds)
  {
    s.assign(nf_, 0.);
    if(faces_.empty()) return true;
    if(!factored_) {
      const auto t0 = std::chrono::steady_clock::now();
      if(!factor(message)) return false;
      factor_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    Eigen::VectorXd b = Eigen::VectorXd::Zero(Eigen::Index(unknowns_.size()));
    for(std::size_t k = 0; k < faces_.size(); ++k) {
      const int f = faces_[k];
      if(weight_ > 0) b[column_[std::size_t(f)]] += weight_ * values[k];
      else s[std::size_t(f)] = values[k];
    }
    if(weight_ <= 0)   // move the Dirichlet values to the right-hand side
      for(const Link& l : adj_) {
        const int cf = column_[std::size_t(l.f)], cg = column_[std::size_t(l.g)];
        if(cf >= 0 && cg < 0 && is_fixed_[std::size_t(l.g)]) b[cf] += l.w * s[std::size_t(l.g)];
        if(cg >= 0 && cf < 0 && is_fixed_[std::size_t(l.f)]) b[cg] += l.w * s[std::size_t(l.f)];
      }
    if(unknowns_.empty()) return true;
    const Eigen::VectorXd x = chol_.solve(b);
    for(std::size_t k = 0; k < unknowns_.size(); ++k) s[std::size_t(unknowns_[k])] = x[Eigen::Index(k)];
    for(double v : s)
      if(!std::isfinite(v)) { message = "the interpolation produced non-finite values"; return false; }
    return true;
  }

private:
  struct Link { int f, g; double w; };

  bool factor(std::string& message)
  {
    std::vector<char> constrained_component(std::size_t(components_), 0);
    is_fixed_.assign(nf_, 0);
    for(int f : faces_) {
      constrained_component[std::size_t(component_[std::size_t(f)])] = 1;
      if(weight_ <= 0) is_fixed_[std::size_t(f)] = 1;
    }
    // unknowns: faces of constrained components, minus the Dirichlet faces
    column_.assign(nf_, -1);
    unknowns_.clear();
    for(std::size_t f = 0; f < nf_; ++f)
      if(constrained_component[std::size_t(component_[f])] && !is_fixed_[f]) {
        column_[f] = int(unknowns_.size());
        unknowns_.push_back(int(f));
      }
    std::vector<Eigen::Triplet<double>> t;
    for(const Link& l : adj_) {
      const int cf = column_[std::size_t(l.f)], cg = column_[std::size_t(l.g)];
      if(cf >= 0) t.emplace_back(cf, cf, l.w);
      if(cg >= 0) t.emplace_back(cg, cg, l.w);
      if(cf >= 0 && cg >= 0) t.emplace_back((std::max)(cf, cg), (std::min)(cf, cg), -l.w);
    }
    if(weight_ > 0)
      for(int f : faces_) t.emplace_back(column_[std::size_t(f)], column_[std::size_t(f)], weight_);
    Cholmod_cholesky::Matrix L(Eigen::Index(unknowns_.size()), Eigen::Index(unknowns_.size()));
    L.setFromTriplets(t.begin(), t.end());
    L.makeCompressed();
    if(!unknowns_.empty() && !chol_.factor(L, message)) return false;
    factored_ = true;
    return true;
  }

  std::size_t nf_ = 0;
  std::vector<Link> adj_;
  std::vector<int> component_;
  int components_ = 0;
  std::vector<int> faces_;
  double weight_ = 0;
  bool factored_ = false;
  std::vector<char> is_fixed_;
  std::vector<int> column_, unknowns_;
  Cholmod_cholesky chol_;
};

} // namespace internal

/// \ingroup PkgSurfaceMeshDirectionFieldsFieldDesign
/// Edits a face-based N-RoSy field with direction and length constraints (Lai et al. 2010,
/// section 4.2). The edit is a rotation angle \f$\psi\f$ and a log-length \f$\rho\f$ per face,
/// each harmonic for the dual Laplacian of the metric (weights \f$1/w_e\f$ between the faces of
/// edge \f$e\f$, \f$w_e\f$ the cotan weight, kept at least \f$10^{-3}\f$ times its mean) away from
/// its constraints; the edited field is the input field rotated by \f$\psi\f$ with lengths
/// \f$e^\rho\f$. A direction constraint asks the face's direction closest to it (among the
/// \f$N\f$) to turn onto it: the target of \f$\psi\f$ is the difference taken in
/// \f$(-\pi/N, \pi/N]\f$. Constraints are hard (Dirichlet: met exactly) or soft (weight
/// \f$\lambda\f$: the energy \f$\psi^\top L \psi + \lambda \sum_c (\psi_c - \delta_c)^2\f$).
/// Components without a constraint keep their field.
///
/// Because \f$\psi\f$ is a function, the rotation it adds around any loop is zero: editing
/// neither creates nor moves a singularity, as long as \f$|\psi_f - \psi_g|\f$ stays below
/// \f$\pi/N\f$ across every edge (the matching is then unchanged; the tests read the field back
/// before and after every edit).
///
/// The factorisations are kept: new constraint values (same faces, same weight) cost one solve
/// each for \f$\psi\f$ and \f$\rho\f$.
/// \tparam TriangleMesh a model of `FaceListGraph`
template <typename TriangleMesh>
class Rosy_field_editor
{
  typedef boost::graph_traits<TriangleMesh> GT;

public:
  typedef typename GT::face_descriptor face_descriptor;

  /// Takes a copy of the field (one angle per face in the face frames of the metric, as
  /// `Trivial_connection::field_angles()` and parallel_rosy_field() produce). Named parameters:
  /// `edge_length_map` (the metric of the angles, default: Euclidean lengths) or
  /// `intrinsic_mesh`, and the index maps. Throws `Input_error` for \f$N < 1\f$ and the errors of
  /// `Intrinsic_mesh`.
  template <typename FaceAngleMap, typename NamedParameters = parameters::Default_named_parameters>
  Rosy_field_editor(const TriangleMesh& tm, int N, const FaceAngleMap& field,
                    const NamedParameters& np = parameters::default_values())
    : im_(internal::get_intrinsic_mesh(tm, np)), N_(N)
  {
    if(N < 1) throw Input_error(Input_error::INVALID_ARGUMENT, "symmetry order N must be at least 1, got " + std::to_string(N));
    const internal::Mesh_arrays<TriangleMesh>& m = im_.arrays();
    base_.resize(m.number_of_faces());
    for(std::size_t f = 0; f < base_.size(); ++f) base_[f] = double(get(field, m.faces[f]));
    // dual Laplacian weights 1 / w_e, w_e the cotan weight (raised to 1e-3 of the mean)
    std::vector<double> w = internal::cotan_edge_weights(m);
    double sum = 0;
    std::size_t count = 0;
    for(double x : w) if(x > 0 && std::isfinite(x)) { sum += x; ++count; }
    const double floor = 1e-3 * (count ? sum / double(count) : 1.);
    for(double& x : w) x = 1. / (x >= floor && std::isfinite(x) ? x : floor);
    rotation_.set_up(m, w);
    length_.set_up(m, w);
  }

  /// Replaces the direction constraints: pairs (face, angle in the face frame), each face once;
  /// `soft_weight` \f$\lambda > 0\f$ makes them soft, 0 hard. Throws `Input_error` for a face given
  /// twice, a non-finite angle or a negative weight.
  template <typename FaceAngleRange>
  void set_direction_constraints(const FaceAngleRange& constraints, double soft_weight = 0)
  {
    read_constraints(constraints, soft_weight, direction_faces_, direction_values_, "direction");
    rotation_.set_constraints(direction_faces_, soft_weight);
  }

  /// Replaces the length constraints: pairs (face, length > 0); `soft_weight` as for the
  /// directions (the soft energy is taken on \f$\rho = \log\f$ length).
  template <typename FaceLengthRange>
  void set_length_constraints(const FaceLengthRange& constraints, double soft_weight = 0)
  {
    read_constraints(constraints, soft_weight, length_faces_, length_values_, "length");
    for(double v : length_values_)
      if(!(v > 0)) throw Input_error(Input_error::INVALID_ARGUMENT, "length constraints must be positive, got " + std::to_string(v));
    length_.set_constraints(length_faces_, soft_weight);
  }

  /// Solves for \f$\psi\f$ and \f$\rho\f$ with the current constraints (factoring only when the
  /// constrained faces or the weights changed) and measures how far the edited field is from them.
  Field_edit_status edit()
  {
    Field_edit_status st;
    const auto t0 = std::chrono::steady_clock::now();
    const double period = 2 * CGAL_PI / N_;
    std::vector<double> delta(direction_faces_.size());
    for(std::size_t k = 0; k < delta.size(); ++k)
      delta[k] = -std::remainder(base_[std::size_t(direction_faces_[k])] - direction_values_[k], period);
    std::vector<double> logs(length_values_.size());
    for(std::size_t k = 0; k < logs.size(); ++k) logs[k] = std::log(length_values_[k]);
    double f1 = 0, f2 = 0;
    if(!rotation_.solve(delta, psi_, st.message, f1) || !length_.solve(logs, rho_, st.message, f2)) return st;
    st.factor_seconds = f1 + f2;
    st.solve_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() - st.factor_seconds;
    for(std::size_t k = 0; k < direction_faces_.size(); ++k) {
      const double a = base_[std::size_t(direction_faces_[k])] + psi_[std::size_t(direction_faces_[k])];
      st.max_direction_error = (std::max)(st.max_direction_error, std::abs(std::remainder(a - direction_values_[k], period)));
    }
    for(std::size_t k = 0; k < length_faces_.size(); ++k)
      st.max_length_error = (std::max)(st.max_length_error,
                                       std::abs(std::exp(rho_[std::size_t(length_faces_[k])]) - length_values_[k]) / length_values_[k]);
    st.success = true;
    return st;
  }

  /// The edited field: input angle plus \f$\psi\f$, in \f$[0, 2\pi)\f$.
  template <typename FaceAngleMap>
  void field_angles(FaceAngleMap angles) const
  {
    const internal::Mesh_arrays<TriangleMesh>& m = im_.arrays();
    for(std::size_t f = 0; f < base_.size(); ++f) {
      double a = base_[f] + (psi_.empty() ? 0. : psi_[f]);
      a -= 2 * CGAL_PI * std::floor(a / (2 * CGAL_PI));
      put(angles, m.faces[f], a);
    }
  }

  /// The lengths of the edited field, \f$e^\rho\f$ (1 before any length constraint).
  template <typename FaceLengthMap>
  void field_lengths(FaceLengthMap lengths) const
  {
    const internal::Mesh_arrays<TriangleMesh>& m = im_.arrays();
    for(std::size_t f = 0; f < base_.size(); ++f) put(lengths, m.faces[f], rho_.empty() ? 1. : std::exp(rho_[f]));
  }

  /// The rotation \f$\psi\f$ of face `f` in the last edit.
  double rotation(face_descriptor f) const
  {
    return psi_.empty() ? 0. : psi_[std::size_t(im_.arrays().face_index(f))];
  }

private:
  template <typename Range>
  void read_constraints(const Range& r, double weight, std::vector<int>& faces, std::vector<double>& values, const char* what)
  {
    if(!(weight >= 0) || !std::isfinite(weight))
      throw Input_error(Input_error::INVALID_ARGUMENT, std::string(what) + " constraint weight must be a non-negative number");
    const internal::Mesh_arrays<TriangleMesh>& m = im_.arrays();
    std::vector<int> f;
    std::vector<double> v;
    std::vector<char> seen(m.number_of_faces(), 0);
    for(const auto& c : r) {
      const int fi = m.face_index(c.first);
      if(fi < 0 || std::size_t(fi) >= seen.size())
        throw Input_error(Input_error::INVALID_ARGUMENT, std::string(what) + " constraint on a face that is not in the mesh");
      if(seen[std::size_t(fi)]++)
        throw Input_error(Input_error::INVALID_ARGUMENT, std::string(what) + " constraint: face " + std::to_string(fi) + " is given twice");
      if(!std::isfinite(double(c.second)))
        throw Input_error(Input_error::INVALID_ARGUMENT, std::string(what) + " constraint on face " + std::to_string(fi) + " is not finite");
      f.push_back(fi);
      v.push_back(double(c.second));
    }
    faces.swap(f);
    values.swap(v);
  }

  Intrinsic_mesh<TriangleMesh> im_;
  int N_;
  std::vector<double> base_, psi_, rho_;
  std::vector<int> direction_faces_, length_faces_;
  std::vector<double> direction_values_, length_values_;
  internal::Face_harmonic_interpolation rotation_, length_;
};

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_FIELD_EDITING_H
