// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_FIELD_EDITING_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_FIELD_EDITING_H

// Editing an N-RoSy field with direction and length constraints (Lai et al. 2010, section 4.2),
// face-based or vertex-based: a rotation angle psi and a log-length rho, harmonic away from the
// constraints, added to the field. Neither creates nor moves a singularity: psi is a function, so the rotation it adds
// around any loop telescopes to zero.

#include <CGAL/Surface_mesh_direction_fields/Cholmod_cholesky.h>
#include <CGAL/Surface_mesh_direction_fields/Intrinsic_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/internal/cholesky_solver_traits.h>
#include <CGAL/Surface_mesh_direction_fields/internal/cotan_weights.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vertex_frames.h>
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

// One scalar per node of a weighted graph (the faces with the dual Laplacian, or the vertices
// with the cotan Laplacian), harmonic except at the constrained nodes: hard constraints are
// Dirichlet values, soft ones add weight * (s_i - value)^2 to the energy s^T L s. Nodes of
// components without a constraint keep 0. Factored once per set of constrained nodes and
// weight; new values cost one solve.
class Harmonic_interpolation
{
public:
  struct Link { int a, b; double w; };

  void set_up(std::size_t n, std::vector<Link> links)
  {
    n_ = n;
    links_.swap(links);
    component_.assign(n_, -1);   // components of the graph
    std::vector<std::vector<int>> nbr(n_);
    for(const Link& l : links_) { nbr[std::size_t(l.a)].push_back(l.b); nbr[std::size_t(l.b)].push_back(l.a); }
    int c = 0;
    for(std::size_t s = 0; s < n_; ++s) {
      if(component_[s] >= 0) continue;
      std::vector<int> stack(1, int(s));
      component_[s] = c;
      while(!stack.empty()) {
        const int i = stack.back();
        stack.pop_back();
        for(int j : nbr[std::size_t(i)]) if(component_[std::size_t(j)] < 0) { component_[std::size_t(j)] = c; stack.push_back(j); }
      }
      ++c;
    }
    components_ = c;
    factored_ = false;
  }

  // The constrained nodes (distinct) and their soft weights (0: hard), one per node or one for
  // all; refactors on change.
  void set_constraints(const std::vector<int>& nodes, const std::vector<double>& soft_weights)
  {
    std::vector<double> w(nodes.size(), soft_weights.empty() ? 0. : soft_weights.front());
    if(soft_weights.size() == nodes.size()) w = soft_weights;
    if(nodes != nodes_ || w != weights_) factored_ = false;
    nodes_ = nodes;
    weights_.swap(w);
  }

  // s for the values of the constrained nodes (in set_constraints() order)
  bool solve(const std::vector<double>& values, std::vector<double>& s, std::string& message, double& factor_seconds)
  {
    s.assign(n_, 0.);
    if(nodes_.empty()) return true;
    if(!factored_) {
      const auto t0 = std::chrono::steady_clock::now();
      if(!factor(message)) return false;
      factor_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    Eigen::VectorXd b = Eigen::VectorXd::Zero(Eigen::Index(unknowns_.size()));
    bool hard = false;
    for(std::size_t k = 0; k < nodes_.size(); ++k) {
      const int i = nodes_[k];
      if(weights_[k] > 0) b[column_[std::size_t(i)]] += weights_[k] * values[k];
      else { s[std::size_t(i)] = values[k]; hard = true; }
    }
    if(hard)   // move the Dirichlet values to the right-hand side
      for(const Link& l : links_) {
        const int ca = column_[std::size_t(l.a)], cb = column_[std::size_t(l.b)];
        if(ca >= 0 && cb < 0 && is_fixed_[std::size_t(l.b)]) b[ca] += l.w * s[std::size_t(l.b)];
        if(cb >= 0 && ca < 0 && is_fixed_[std::size_t(l.a)]) b[cb] += l.w * s[std::size_t(l.a)];
      }
    if(unknowns_.empty()) return true;
    const Eigen::VectorXd x = chol_.solve(b);
    for(std::size_t k = 0; k < unknowns_.size(); ++k) s[std::size_t(unknowns_[k])] = x[Eigen::Index(k)];
    for(double v : s)
      if(!std::isfinite(v)) { message = "the interpolation produced non-finite values"; return false; }
    return true;
  }

private:
  bool factor(std::string& message)
  {
    std::vector<char> constrained_component(std::size_t(components_), 0);
    is_fixed_.assign(n_, 0);
    for(std::size_t k = 0; k < nodes_.size(); ++k) {
      const int i = nodes_[k];
      constrained_component[std::size_t(component_[std::size_t(i)])] = 1;
      if(!(weights_[k] > 0)) is_fixed_[std::size_t(i)] = 1;
    }
    // unknowns: nodes of constrained components, minus the Dirichlet nodes
    column_.assign(n_, -1);
    unknowns_.clear();
    for(std::size_t i = 0; i < n_; ++i)
      if(constrained_component[std::size_t(component_[i])] && !is_fixed_[i]) {
        column_[i] = int(unknowns_.size());
        unknowns_.push_back(int(i));
      }
    std::vector<Eigen::Triplet<double>> t;
    for(const Link& l : links_) {
      const int ca = column_[std::size_t(l.a)], cb = column_[std::size_t(l.b)];
      if(ca >= 0) t.emplace_back(ca, ca, l.w);
      if(cb >= 0) t.emplace_back(cb, cb, l.w);
      if(ca >= 0 && cb >= 0) t.emplace_back((std::max)(ca, cb), (std::min)(ca, cb), -l.w);
    }
    for(std::size_t k = 0; k < nodes_.size(); ++k)
      if(weights_[k] > 0) t.emplace_back(column_[std::size_t(nodes_[k])], column_[std::size_t(nodes_[k])], weights_[k]);
    Cholmod_cholesky::Matrix L(Eigen::Index(unknowns_.size()), Eigen::Index(unknowns_.size()));
    L.setFromTriplets(t.begin(), t.end());
    L.makeCompressed();
    if(!unknowns_.empty() && !chol_.factor(L, message)) return false;
    factored_ = true;
    return true;
  }

  std::size_t n_ = 0;
  std::vector<Link> links_;
  std::vector<int> component_;
  int components_ = 0;
  std::vector<int> nodes_;
  std::vector<double> weights_;
  bool factored_ = false;
  std::vector<char> is_fixed_;
  std::vector<int> column_, unknowns_;
  Cholmod_cholesky chol_;
};

// What both editors share: an N-RoSy field as one angle per node, the constraints, and the two
// interpolations psi (rotation) and rho (log-length) on the same graph.
class Rosy_edit_core
{
public:
  void set_up(int N, std::vector<double> base, const std::vector<Harmonic_interpolation::Link>& links)
  {
    if(N < 1) throw Input_error(Input_error::INVALID_ARGUMENT, "symmetry order N must be at least 1, got " + std::to_string(N));
    N_ = N;
    base_.swap(base);
    rotation_.set_up(base_.size(), links);
    length_.set_up(base_.size(), links);
  }

  // (node, value) pairs checked; `node_of` maps the user's descriptor to a node (-1: not in the
  // mesh), `forbidden` names a node that cannot carry a constraint (or returns empty)
  template <typename Range, typename NodeOf, typename Forbidden>
  static void read(const Range& r, const std::vector<double>& weights, const char* what, const char* element, std::size_t n, NodeOf node_of,
                   Forbidden forbidden, std::vector<int>& nodes, std::vector<double>& values)
  {
    for(double weight : weights)
      if(!(weight >= 0) || !std::isfinite(weight))
        throw Input_error(Input_error::INVALID_ARGUMENT, std::string(what) + " constraint weight must be a non-negative number");
    std::vector<int> idx;
    std::vector<double> v;
    std::vector<char> seen(n, 0);
    for(const auto& c : r) {
      const int i = node_of(c.first);
      if(i < 0 || std::size_t(i) >= n)
        throw Input_error(Input_error::INVALID_ARGUMENT, std::string(what) + " constraint on a " + element + " that is not in the mesh");
      const std::string name = std::string(element) + " " + std::to_string(i);
      if(seen[std::size_t(i)]++)
        throw Input_error(Input_error::INVALID_ARGUMENT, std::string(what) + " constraint: " + name + " is given twice");
      if(!std::isfinite(double(c.second)))
        throw Input_error(Input_error::INVALID_ARGUMENT, std::string(what) + " constraint on " + name + " is not finite");
      const std::string why = forbidden(i);
      if(!why.empty()) throw Input_error(Input_error::INVALID_ARGUMENT, std::string(what) + " constraint on " + name + ": " + why);
      idx.push_back(i);
      v.push_back(double(c.second));
    }
    if(weights.size() != 1 && weights.size() != idx.size())
      throw Input_error(Input_error::INVALID_ARGUMENT, std::string(what) + " constraints: " + std::to_string(weights.size()) +
                                                           " weights for " + std::to_string(idx.size()) + " constraints (give one per constraint)");
    nodes.swap(idx);
    values.swap(v);
  }

  // weights: one per constraint, or one for all (0: hard)
  void set_directions(std::vector<int> nodes, std::vector<double> values, const std::vector<double>& weights)
  {
    direction_nodes_.swap(nodes);
    direction_values_.swap(values);
    rotation_.set_constraints(direction_nodes_, weights);
  }

  void set_lengths(std::vector<int> nodes, std::vector<double> values, const std::vector<double>& weights)
  {
    for(double v : values)
      if(!(v > 0)) throw Input_error(Input_error::INVALID_ARGUMENT, "length constraints must be positive, got " + std::to_string(v));
    length_nodes_.swap(nodes);
    length_values_.swap(values);
    length_.set_constraints(length_nodes_, weights);
  }

  Field_edit_status edit()
  {
    Field_edit_status st;
    const auto t0 = std::chrono::steady_clock::now();
    const double period = 2 * CGAL_PI / N_;
    std::vector<double> delta(direction_nodes_.size());
    for(std::size_t k = 0; k < delta.size(); ++k)
      delta[k] = -std::remainder(base_[std::size_t(direction_nodes_[k])] - direction_values_[k], period);
    std::vector<double> logs(length_values_.size());
    for(std::size_t k = 0; k < logs.size(); ++k) logs[k] = std::log(length_values_[k]);
    double f1 = 0, f2 = 0;
    if(!rotation_.solve(delta, psi_, st.message, f1) || !length_.solve(logs, rho_, st.message, f2)) return st;
    st.factor_seconds = f1 + f2;
    st.solve_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() - st.factor_seconds;
    for(std::size_t k = 0; k < direction_nodes_.size(); ++k)
      st.max_direction_error = (std::max)(st.max_direction_error, std::abs(std::remainder(angle(std::size_t(direction_nodes_[k])) - direction_values_[k], period)));
    for(std::size_t k = 0; k < length_nodes_.size(); ++k)
      st.max_length_error = (std::max)(st.max_length_error, std::abs(length(std::size_t(length_nodes_[k])) - length_values_[k]) / length_values_[k]);
    st.success = true;
    return st;
  }

  std::size_t size() const { return base_.size(); }
  double rotation(std::size_t i) const { return psi_.empty() ? 0. : psi_[i]; }
  double angle(std::size_t i) const { return base_[i] + rotation(i); }
  double wrapped_angle(std::size_t i) const
  {
    const double a = angle(i);
    return a - 2 * CGAL_PI * std::floor(a / (2 * CGAL_PI));
  }
  double length(std::size_t i) const { return rho_.empty() ? 1. : std::exp(rho_[i]); }

private:
  int N_ = 1;
  std::vector<double> base_, psi_, rho_;
  std::vector<int> direction_nodes_, length_nodes_;
  std::vector<double> direction_values_, length_values_;
  Harmonic_interpolation rotation_, length_;
};

} // namespace internal

/// \ingroup PkgSurfaceMeshDirectionFieldsFieldDesign
/// Edits a face-based N-RoSy field with direction and length constraints on faces (Lai et al.
/// 2010, section 4.2, on the faces; `Rosy_vertex_field_editor` is the paper's vertex version).
/// The edit is a rotation angle \f$\psi\f$ and a log-length \f$\rho\f$ per face,
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
    : im_(internal::get_intrinsic_mesh(tm, np))
  {
    const internal::Mesh_arrays<TriangleMesh>& m = im_.arrays();
    std::vector<double> base(m.number_of_faces());
    for(std::size_t f = 0; f < base.size(); ++f) base[f] = double(get(field, m.faces[f]));
    // dual Laplacian weights 1 / w_e between the faces of each interior edge
    const std::vector<double> w = internal::floored_cotan_edge_weights(m);
    std::vector<internal::Harmonic_interpolation::Link> links;
    for(std::size_t e = 0; e < m.number_of_edges(); ++e) {
      const int f = m.face[2 * e], g = m.face[2 * e + 1];
      if(f >= 0 && g >= 0 && f != g) links.push_back({f, g, 1. / w[e]});
    }
    core_.set_up(N, std::move(base), links);
  }

  /// Replaces the direction constraints: pairs (face, angle in the face frame), each face once;
  /// `soft_weight` \f$\lambda > 0\f$ makes them soft, 0 hard. Throws `Input_error` for a face given
  /// twice, a non-finite angle or a negative weight.
  template <typename FaceAngleRange>
  void set_direction_constraints(const FaceAngleRange& constraints, double soft_weight = 0)
  {
    set_direction_constraints(constraints, std::vector<double>(1, soft_weight));
  }

  /// As above, with one weight per constraint, in the order of `constraints` (0: that one is
  /// hard), so that hard and soft constraints can be mixed. Throws `Input_error` also when the
  /// number of weights is not that of the constraints.
  template <typename FaceAngleRange>
  void set_direction_constraints(const FaceAngleRange& constraints, const std::vector<double>& soft_weights)
  {
    std::vector<int> nodes;
    std::vector<double> values;
    read(constraints, soft_weights, "direction", nodes, values);
    core_.set_directions(std::move(nodes), std::move(values), soft_weights);
  }

  /// Replaces the length constraints: pairs (face, length > 0); `soft_weight` as for the
  /// directions (the soft energy is taken on \f$\rho = \log\f$ length).
  template <typename FaceLengthRange>
  void set_length_constraints(const FaceLengthRange& constraints, double soft_weight = 0)
  {
    set_length_constraints(constraints, std::vector<double>(1, soft_weight));
  }

  /// As above, with one weight per constraint (0: that one is hard).
  template <typename FaceLengthRange>
  void set_length_constraints(const FaceLengthRange& constraints, const std::vector<double>& soft_weights)
  {
    std::vector<int> nodes;
    std::vector<double> values;
    read(constraints, soft_weights, "length", nodes, values);
    core_.set_lengths(std::move(nodes), std::move(values), soft_weights);
  }

  /// Solves for \f$\psi\f$ and \f$\rho\f$ with the current constraints (factoring only when the
  /// constrained faces or the weights changed) and measures how far the edited field is from them.
  Field_edit_status edit() { return core_.edit(); }

  /// The edited field: input angle plus \f$\psi\f$, in \f$[0, 2\pi)\f$.
  template <typename FaceAngleMap>
  void field_angles(FaceAngleMap angles) const
  {
    const internal::Mesh_arrays<TriangleMesh>& m = im_.arrays();
    for(std::size_t f = 0; f < core_.size(); ++f) put(angles, m.faces[f], core_.wrapped_angle(f));
  }

  /// The lengths of the edited field, \f$e^\rho\f$ (1 before any length constraint).
  template <typename FaceLengthMap>
  void field_lengths(FaceLengthMap lengths) const
  {
    const internal::Mesh_arrays<TriangleMesh>& m = im_.arrays();
    for(std::size_t f = 0; f < core_.size(); ++f) put(lengths, m.faces[f], core_.length(f));
  }

  /// The rotation \f$\psi\f$ of face `f` in the last edit.
  double rotation(face_descriptor f) const { return core_.rotation(std::size_t(im_.arrays().face_index(f))); }

private:
  template <typename Range>
  void read(const Range& r, const std::vector<double>& weight, const char* what, std::vector<int>& nodes, std::vector<double>& values) const
  {
    const internal::Mesh_arrays<TriangleMesh>& m = im_.arrays();
    internal::Rosy_edit_core::read(r, weight, what, "face", m.number_of_faces(), [&](face_descriptor f) { return m.face_index(f); },
                                   [](int) { return std::string(); }, nodes, values);
  }

  Intrinsic_mesh<TriangleMesh> im_;
  internal::Rosy_edit_core core_;
};

/// \ingroup PkgSurfaceMeshDirectionFieldsFieldDesign
/// Edits a vertex-based N-RoSy field with direction and length constraints at vertices, as in
/// Lai et al. 2010, section 4.2: the rotation \f$\psi\f$ and log-length \f$\rho\f$ per vertex are
/// harmonic for the cotan Laplacian of the metric (\f$\sum_r w_{qr}(\psi_r - \psi_q) = 0\f$, the
/// weights kept at least \f$10^{-3}\f$ times their mean) except at the constrained vertices,
/// hard (Dirichlet: \f$\psi_p = \bar\psi_p\f$) or soft (the rows \f$\lambda \psi_p = \lambda
/// \bar\psi_p\f$ added in the least-squares sense). \f$\bar\psi_p\f$ turns the nearest of the
/// \f$N\f$ directions at \f$p\f$ onto the constraint. The field is the one of
/// rotation_compensated_field(): angles in its vertex frames, on the same metric; cones carry
/// no direction and take no constraint. Editing neither creates nor moves a singularity (the
/// tests read the face version back before and after every edit).
/// \tparam TriangleMesh a model of `FaceListGraph`
template <typename TriangleMesh>
class Rosy_vertex_field_editor
{
  typedef boost::graph_traits<TriangleMesh> GT;

public:
  typedef typename GT::vertex_descriptor vertex_descriptor;

  /// Takes a copy of the field (one angle per vertex in the vertex frames of
  /// rotation_compensated_field()). Named parameters: `edge_length_map` (the metric, default:
  /// Euclidean lengths) or `intrinsic_mesh`, and the index maps. Throws `Input_error` for
  /// \f$N < 1\f$ and the errors of `Intrinsic_mesh`.
  template <typename VertexAngleMap, typename NamedParameters = parameters::Default_named_parameters>
  Rosy_vertex_field_editor(const TriangleMesh& tm, int N, const VertexAngleMap& field,
                           const NamedParameters& np = parameters::default_values())
    : im_(internal::get_intrinsic_mesh(tm, np)), frames_(im_.arrays())
  {
    const internal::Mesh_arrays<TriangleMesh>& m = im_.arrays();
    std::vector<double> base(m.number_of_vertices());
    for(std::size_t v = 0; v < base.size(); ++v) base[v] = double(get(field, m.vertices[v]));
    const std::vector<double> w = internal::floored_cotan_edge_weights(m);
    std::vector<internal::Harmonic_interpolation::Link> links;
    for(std::size_t e = 0; e < m.number_of_edges(); ++e) {
      const int a = m.target[2 * e + 1], b = m.target[2 * e];
      if(a != b) links.push_back({a, b, w[e]});
    }
    core_.set_up(N, std::move(base), links);
  }

  /// Replaces the direction constraints: pairs (vertex, angle in the vertex frame), each vertex
  /// once, none at a cone; `soft_weight` \f$\lambda > 0\f$ makes them soft, 0 hard. Throws
  /// `Input_error` for a vertex given twice, a cone, a non-finite angle or a negative weight.
  template <typename VertexAngleRange>
  void set_direction_constraints(const VertexAngleRange& constraints, double soft_weight = 0)
  {
    set_direction_constraints(constraints, std::vector<double>(1, soft_weight));
  }

  /// As above, with one weight per constraint, in the order of `constraints` (0: that one is
  /// hard), so that hard and soft constraints can be mixed. Throws `Input_error` also when the
  /// number of weights is not that of the constraints.
  template <typename VertexAngleRange>
  void set_direction_constraints(const VertexAngleRange& constraints, const std::vector<double>& soft_weights)
  {
    std::vector<int> nodes;
    std::vector<double> values;
    read(constraints, soft_weights, "direction", nodes, values);
    core_.set_directions(std::move(nodes), std::move(values), soft_weights);
  }

  /// Replaces the length constraints: pairs (vertex, length > 0); `soft_weight` as for the
  /// directions (on \f$\rho = \log\f$ length).
  template <typename VertexLengthRange>
  void set_length_constraints(const VertexLengthRange& constraints, double soft_weight = 0)
  {
    set_length_constraints(constraints, std::vector<double>(1, soft_weight));
  }

  /// As above, with one weight per constraint (0: that one is hard).
  template <typename VertexLengthRange>
  void set_length_constraints(const VertexLengthRange& constraints, const std::vector<double>& soft_weights)
  {
    std::vector<int> nodes;
    std::vector<double> values;
    read(constraints, soft_weights, "length", nodes, values);
    core_.set_lengths(std::move(nodes), std::move(values), soft_weights);
  }

  /// Solves for \f$\psi\f$ and \f$\rho\f$ (factoring only when the constrained vertices or the
  /// weights changed) and measures how far the edited field is from the constraints.
  Field_edit_status edit() { return core_.edit(); }

  /// The edited vertex field: input angle plus \f$\psi\f$, in \f$[0, 2\pi)\f$.
  template <typename VertexAngleMap>
  void vertex_angles(VertexAngleMap angles) const
  {
    const internal::Mesh_arrays<TriangleMesh>& m = im_.arrays();
    for(std::size_t v = 0; v < core_.size(); ++v) put(angles, m.vertices[v], core_.wrapped_angle(v));
  }

  /// The edited field in the face frames of the metric, as rotation_compensated_field() makes it
  /// (each face from a corner that is not a cone): for field_singularities() on the same metric.
  template <typename FaceAngleMap>
  void face_angles(FaceAngleMap angles) const
  {
    std::vector<double> alpha(core_.size());
    for(std::size_t v = 0; v < alpha.size(); ++v) alpha[v] = core_.angle(v);
    internal::vertex_field_to_face_angles(im_.arrays(), frames_, im_.curvatures(), alpha, angles);
  }

  /// The lengths of the edited field, \f$e^\rho\f$ (1 before any length constraint).
  template <typename VertexLengthMap>
  void vertex_lengths(VertexLengthMap lengths) const
  {
    const internal::Mesh_arrays<TriangleMesh>& m = im_.arrays();
    for(std::size_t v = 0; v < core_.size(); ++v) put(lengths, m.vertices[v], core_.length(v));
  }

  /// The rotation \f$\psi\f$ of vertex `v` in the last edit.
  double rotation(vertex_descriptor v) const { return core_.rotation(std::size_t(im_.arrays().vertex_index(v))); }

private:
  template <typename Range>
  void read(const Range& r, const std::vector<double>& weight, const char* what, std::vector<int>& nodes, std::vector<double>& values) const
  {
    const internal::Mesh_arrays<TriangleMesh>& m = im_.arrays();
    const std::vector<double>& K = im_.curvatures();
    internal::Rosy_edit_core::read(r, weight, what, "vertex", m.number_of_vertices(), [&](vertex_descriptor v) { return m.vertex_index(v); },
                                   [&](int i) {
                                     return std::abs(K[std::size_t(i)]) > 1e-6 ? std::string("it is a cone (curvature ") + std::to_string(K[std::size_t(i)]) +
                                                                                      "), where the field has no direction"
                                                                                : std::string();
                                   },
                                   nodes, values);
  }

  Intrinsic_mesh<TriangleMesh> im_;
  internal::Vertex_frames<TriangleMesh> frames_;
  internal::Rosy_edit_core core_;
};

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_FIELD_EDITING_H
