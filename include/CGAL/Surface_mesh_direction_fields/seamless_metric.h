// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_SEAMLESS_METRIC_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_SEAMLESS_METRIC_H

// Metric compensation, rotational part: a flat cone metric whose parallel transport around
// every handle is a rotation by a multiple of 2 pi / N (a seamless metric; Campen, Shen, Zhou
// and Zorin 2019), from a flat cone metric with the same cones, by Newton steps of least change
// in the log edge lengths.

#include <CGAL/Surface_mesh_direction_fields/Cholmod_cholesky.h>
#include <CGAL/Surface_mesh_direction_fields/Intrinsic_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/internal/holonomy_loops.h>
#include <CGAL/Surface_mesh_direction_fields/parameters.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// Outcome of seamless_cone_metric().
struct Seamless_metric_status
{
  bool success = false;     ///< every curvature, handle holonomy and path turning within the tolerance
  std::string message;      ///< why not
  int iterations = 0;       ///< Newton steps
  /// handle loops and boundary paths constrained (\f$2g + \max(b - 1, 0)\f$, \f$b\f$ boundary loops)
  std::size_t loops = 0;
  /// the largest distance of a handle's holonomy or a path's turning to a multiple of
  /// \f$2\pi/N\f$, before and after
  double initial_holonomy_error = 0, holonomy_error = 0;
  double curvature_error = 0;        ///< the largest change of a vertex's curvature from the input metric's
  double max_log_length_change = 0;  ///< \f$\max_e |\log(\ell_e / \ell^0_e)|\f$
  double min_angle = 0;              ///< the smallest corner angle of the result (radians)
};

namespace internal {

// Corner angle at source(c) of face(c) from its three side lengths (opposite: next(c)).
inline double corner_angle_of(double opposite, double a, double b)
{
  const double c = (a * a + b * b - opposite * opposite) / (2 * a * b);
  return std::acos((std::max)(-1., (std::min)(1., c)));
}

// The corner angles of every face of a triangulation `t` (Mesh_arrays or Flippable_triangulation)
// under the side lengths `len`, per halfedge at its source; returns the smallest, or -1 if a face
// violates the triangle inequality.
template <typename Arrays>
double corner_angles_of(const Arrays& t, const std::vector<double>& len, std::vector<double>& angle)
{
  double lo = CGAL_PI;
  for(std::size_t f = 0; f < t.face_halfedge.size(); ++f) {
    const int h0 = t.face_halfedge[f], h1 = t.next[std::size_t(h0)], h2 = t.next[std::size_t(h1)];
    const double a = len[std::size_t(h0 >> 1)], b = len[std::size_t(h1 >> 1)], c = len[std::size_t(h2 >> 1)];
    if(!(a < b + c && b < a + c && c < a + b)) return -1.;
    angle[std::size_t(h0)] = corner_angle_of(b, a, c);   // at source(h0): opposite side h1
    angle[std::size_t(h1)] = corner_angle_of(c, a, b);
    angle[std::size_t(h2)] = CGAL_PI - angle[std::size_t(h0)] - angle[std::size_t(h1)];
    lo = (std::min)(lo, (std::min)(angle[std::size_t(h0)], (std::min)(angle[std::size_t(h1)], angle[std::size_t(h2)])));
  }
  return lo;
}

// The curvature of every vertex (angle defect, geodesic curvature on the boundary) from the corner
// angles of a triangulation `t` (Mesh_arrays or Flippable_triangulation) of the mesh `m`.
template <typename TM, typename Arrays>
void vertex_curvatures_of(const Mesh_arrays<TM>& m, const Arrays& t, const std::vector<double>& angle, std::vector<double>& K)
{
  const std::size_t nv = m.number_of_vertices();
  K.assign(nv, 0.);
  for(std::size_t v = 0; v < nv; ++v) if(!m.is_isolated(int(v))) K[v] = m.is_boundary_vertex(int(v)) ? CGAL_PI : 2 * CGAL_PI;
  for(std::size_t f = 0; f < t.face_halfedge.size(); ++f) {
    int h = t.face_halfedge[f];
    for(int i = 0; i < 3; ++i, h = t.next[std::size_t(h)]) K[std::size_t(t.source(h))] -= angle[std::size_t(h)];
  }
}

// The Jacobian of a seamless metric's equations in the log lengths: rows `row[v]` (-1: none) the
// curvature of vertex v (minus its corner angles' derivatives), then from `loop_row0` one per loop.
template <typename Arrays>
Eigen::SparseMatrix<double> seamless_jacobian(const Arrays& t, const std::vector<double>& angle, const std::vector<int>& row,
                                              int loop_row0, const std::vector<std::vector<Loop_turn>>& loops, std::size_t ne)
{
  std::vector<Eigen::Triplet<double>> tr;
  for(std::size_t f = 0; f < t.face_halfedge.size(); ++f) {
    int h = t.face_halfedge[f];
    for(int i = 0; i < 3; ++i, h = t.next[std::size_t(h)]) {
      const int r = row[std::size_t(t.source(h))];
      if(r >= 0) corner_angle_derivative(t, angle, h, -1., [&](int e, double d) { tr.emplace_back(r, e, d); });
    }
  }
  for(std::size_t i = 0; i < loops.size(); ++i)
    loop_holonomy_derivative(t, angle, loops[i], [&](int e, double d) { tr.emplace_back(loop_row0 + int(i), e, d); });
  Eigen::SparseMatrix<double> J(loop_row0 + int(loops.size()), int(ne));
  J.setFromTriplets(tr.begin(), tr.end());
  return J;
}

} // namespace internal

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// Makes a flat cone metric seamless: returns edge lengths of the same triangulation with the
/// same curvature at every vertex (interior angle defect, geodesic curvature on the boundary) and
/// whose Levi-Civita holonomy around every handle loop (the tree-cotree generators of the package,
/// the dual cycles of `homology_generators()`) is a multiple of \f$2\pi/N\f$, the multiple nearest
/// to the input metric's. On an open mesh with several boundary loops, also the turning along a
/// path of faces from an edge of the first boundary loop to an edge of each other one (the angle
/// from the first edge's direction to the second's, transported along the path). A cross field
/// (\f$N = 4\f$) parallel in such a metric closes around every loop and, along straight
/// boundaries with corners of multiples of \f$2\pi/N\f$, follows every boundary loop once it
/// follows one, so an integer-grid map made on it can be exactly its development (metric
/// compensation, rotational part: Lai et al.'s general holonomy, Campen et al. 2019).
///
/// <b>Method.</b> A handle's holonomy is a sum of corner angles along its dual cycle (the turn
/// from the edge a cycle enters a face by to the edge it leaves by), and each corner angle a
/// function of the log lengths \f$\lambda_e\f$ of its triangle (\f$\partial\theta_i/\partial
/// \lambda_{jk} = \cot\theta_j + \cot\theta_k\f$, \f$\partial\theta_i/\partial\lambda_{ij} =
/// -\cot\theta_j\f$). Newton steps of least norm \f$\Delta\lambda = J^T (J J^T)^{-1} (-F)\f$
/// solve the curvatures and holonomies \f$F = 0\f$ together (one sparse factorisation of \f$J
/// J^T\f$ per step), each step halved until every triangle keeps its corner angles above
/// \f$10^{-3}\f$ rad and \f$|F|\f$ decreases, the holonomies moved to their goals in four
/// stages (continuation). The triangulation is not flipped: where the change would need it, the
/// status fails.
///
/// \param tm a triangle mesh of one component
/// \param input_lengths the flat cone metric (a readable edge property map)
/// \param output_lengths receives the seamless metric, or the input metric when the status fails
///   (may be the same map as `input_lengths`)
/// \param np `symmetry_order` (\f$N\f$, default 4), `curvature_tolerance` (default
///   \f$10^{-10}\f$, for the curvatures and the holonomies), `number_of_iterations` (default 60,
///   over all stages)
///
/// <b>Limits.</b> Without flips the triangulation bounds how far a holonomy can move: measured on
/// the closed shared meshes of genus 1 to 9 with placed cones, it converges where the input
/// metric's holonomies are within 0.3 rad of their goals (bob: 0.27, the triple torus: 0.03) and
/// stalls 0.04-0.18 rad short where they start 0.33-0.78 away (punctured torus, botijo, double
/// torus, eight, genus-3 part, rocker arm, fertility, casting): triangles reach the smallest
/// angle allowed, after up to 20 s on the 82k-face botijo. Beyond 0.3 rad the status therefore
/// fails at once; seamless_intrinsic_cone_metric() lifts that limit with intrinsic flips.
///
/// Throws `Input_error` for several components or \f$N < 1\f$.
template <typename TriangleMesh, typename InputLengthMap, typename OutputLengthMap,
          typename NamedParameters = parameters::Default_named_parameters>
Seamless_metric_status seamless_cone_metric(const TriangleMesh& tm, const InputLengthMap& input_lengths, OutputLengthMap output_lengths,
                                            const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Seamless_metric_status st;
  const int N = choose_parameter(get_parameter(np, internal_np::symmetry_order), 4);
  if(N < 1) throw Input_error(Input_error::INVALID_ARGUMENT, "symmetry order N must be at least 1, got " + std::to_string(N));
  const double tol = choose_parameter(get_parameter(np, internal_np::curvature_tolerance), 1e-10);
  const int max_iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 60);
  const Intrinsic_mesh<TriangleMesh> im(tm, parameters::edge_length_map(input_lengths));
  const internal::Mesh_arrays<TriangleMesh>& m = im.arrays();
  if(im.topology_arrays().components.size() != 1)
    throw Input_error(Input_error::INVALID_ARGUMENT, "seamless_cone_metric() needs a mesh of one component");
  const std::size_t nv = m.number_of_vertices(), ne = m.number_of_edges();
  const double period = 2 * CGAL_PI / N;
  std::vector<double> l0(ne), l(ne);
  for(std::size_t e = 0; e < ne; ++e) l0[e] = l[e] = m.length[e];
  auto write = [&] { for(std::size_t e = 0; e < ne; ++e) put(output_lengths, m.edges[e], l[e]); };

  typedef internal::Loop_turn Turn;
  std::vector<std::vector<Turn>> loops = internal::holonomy_loops(im);
  st.loops = loops.size();
  std::vector<double> angle(2 * ne, 0.);   // per halfedge with a face: the angle at its source
  auto angles_of = [&](const std::vector<double>& len) { return internal::corner_angles_of(m, len, angle); };
  auto holonomy = [&](const std::vector<Turn>& t) { return internal::loop_holonomy(m, angle, t); };
  // rows: the curvature of every vertex but the first (Gauss-Bonnet fixes its own), then the loops
  int nrows = 0;
  const std::vector<int> row = m.indices_but_first_vertex(nrows);
  const int loop_row0 = nrows;
  nrows += int(loops.size());
  auto curvature = [&](std::vector<double>& K) { internal::vertex_curvatures_of(m, m, angle, K); };
  if(angles_of(l) < 0) { st.message = "the input lengths violate the triangle inequality"; return st; }
  std::vector<double> K0, K;
  curvature(K0);
  std::vector<double> target(loops.size()), start(loops.size()), goal(loops.size());
  for(std::size_t i = 0; i < loops.size(); ++i) {
    start[i] = holonomy(loops[i]);
    goal[i] = target[i] = period * std::round(start[i] / period);
    st.initial_holonomy_error = (std::max)(st.initial_holonomy_error, std::abs(start[i] - target[i]));
  }
  auto residual = [&](Eigen::VectorXd& F) {
    curvature(K);
    F = Eigen::VectorXd::Zero(nrows);
    double ck = 0, hk = 0;
    for(std::size_t v = 0; v < nv; ++v) if(row[v] >= 0) { F[row[v]] = K[v] - K0[v]; ck = (std::max)(ck, std::abs(F[row[v]])); }
    for(std::size_t i = 0; i < loops.size(); ++i) { F[loop_row0 + int(i)] = holonomy(loops[i]) - target[i]; hk = (std::max)(hk, std::abs(F[loop_row0 + int(i)])); }
    st.curvature_error = ck;
    st.holonomy_error = hk;
  };
  Eigen::VectorXd F;
  residual(F);
  if(loops.empty() || st.holonomy_error <= tol) {
    st.success = st.curvature_error <= tol;
    st.min_angle = angles_of(l);
    write();
    if(!st.success) st.message = "the input metric's curvatures are not consistent";
    return st;
  }
  // measured on the closed shared meshes: from 0.33 rad on (the punctured torus, the botijo, ...)
  // Newton stalls short of the goal, 20 s on the botijo; below 0.3 it converged on every one
  const double reach = 0.3;
  if(st.initial_holonomy_error > reach) {
    st.message = "a handle's holonomy or a path's turning between boundary loops is " + std::to_string(st.initial_holonomy_error) +
                 " rad from a multiple of 2 pi / " + std::to_string(N) +
                 ", more than the fixed triangulation can move it (" + std::to_string(reach) + " rad; it would need flips)";
    st.min_angle = angles_of(l);
    write();
    return st;
  }
  const double min_angle = 1e-3;
  Cholmod_cholesky chol;
  // continuation: the holonomies moved to their goals in four stages, each solved by Newton (from
  // the conformal metric a full step asked for log length changes of 2.4 on the punctured torus)
  bool stuck = false;
  // stalled: 3 steps in a row that took off less than half of |F|^2 (cut to a quarter or less
  // against degenerating triangles; a Newton step that converges takes off far more); before
  // this, a stall ran to the iteration limit (8 s of a 9 s remesh of the triple torus at 1,000
  // quads, failing anyway)
  int slow_steps = 0;
  int it = 0;
  for(int stage = 1; stage <= 4 && !stuck; ++stage) {
  for(std::size_t i = 0; i < loops.size(); ++i) target[i] = start[i] + (goal[i] - start[i]) * stage / 4;
  residual(F);
  const double stage_tol = stage == 4 ? tol : 1e-6;
  for(; it < max_iterations; ++it) {
    if(st.curvature_error <= stage_tol && st.holonomy_error <= stage_tol) break;
    // J: d(curvature)/d(lambda) = -sum of the corner derivatives; d(holonomy)/d(lambda) likewise
    const Eigen::SparseMatrix<double> J = internal::seamless_jacobian(m, angle, row, loop_row0, loops, ne);
    const Eigen::SparseMatrix<double> JJt = J * Eigen::SparseMatrix<double>(J.transpose());
    Cholmod_cholesky::Matrix lower = JJt.triangularView<Eigen::Lower>();
    std::string msg;
    if(!chol.factor(lower, msg)) { st.message = "the Newton system could not be factored: " + msg; write(); return st; }
    const Eigen::VectorXd dl = J.transpose() * chol.solve(Eigen::VectorXd(-F));
    const double merit = F.squaredNorm();
    bool moved = false;
    for(double t = 1; t >= 1. / 1024; t /= 2) {
      std::vector<double> lt(ne);
      for(std::size_t e = 0; e < ne; ++e) lt[e] = l[e] * std::exp(t * dl[Eigen::Index(e)]);
      if(!(angles_of(lt) > min_angle)) continue;
      Eigen::VectorXd Ft;
      residual(Ft);
      if(!(Ft.squaredNorm() < merit)) continue;
      l = lt;
      F = Ft;
      moved = true;
      break;
    }
    st.iterations = it + 1;
    slow_steps = moved && F.squaredNorm() > 0.5 * merit ? slow_steps + 1 : 0;
    if(!moved || slow_steps >= 3) { angles_of(l); residual(F); stuck = true; break; }
  }
  }
  st.min_angle = angles_of(l);
  residual(F);
  for(std::size_t e = 0; e < ne; ++e) st.max_log_length_change = (std::max)(st.max_log_length_change, std::abs(std::log(l[e] / l0[e])));
  st.success = st.curvature_error <= tol && st.holonomy_error <= tol;
  if(!st.success) {
    st.message = "Newton stopped after " + std::to_string(st.iterations) + " steps with the holonomy " + std::to_string(st.holonomy_error) +
                 " and the curvature " + std::to_string(st.curvature_error) + " rad off (the triangulation would need flips)";
    l = l0;   // the input metric, not a metric half way
  }
  write();
  return st;
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_SEAMLESS_METRIC_H
