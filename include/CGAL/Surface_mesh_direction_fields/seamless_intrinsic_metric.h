// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_SEAMLESS_INTRINSIC_METRIC_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_SEAMLESS_INTRINSIC_METRIC_H

// Metric compensation, rotational part, with intrinsic flips: the seamless metric of
// seamless_metric.h solved in Penner coordinates on the intrinsic Delaunay triangulation of the
// current metric (Capouellez and Zorin 2023), so that the holonomies can move as far as they
// must, and its correspondence with the input kept through every flip.

#include <CGAL/Surface_mesh_direction_fields/Cholmod_cholesky.h>
#include <CGAL/Surface_mesh_direction_fields/Intrinsic_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/Intrinsic_triangulation.h>
#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/parameters.h>
#include <CGAL/Surface_mesh_direction_fields/seamless_metric.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Seamless_metric/loops_through_flips.h>
#include <CGAL/Surface_mesh_direction_fields/internal/common_subdivision.h>
#include <CGAL/Surface_mesh_direction_fields/internal/holonomy_loops.h>
#include <CGAL/Surface_mesh_direction_fields/internal/topology.h>
#include <CGAL/Surface_mesh_direction_fields/internal/tree_cotree.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// Outcome of seamless_intrinsic_cone_metric(): that of seamless_cone_metric() and the
/// triangulation that carries the metric.
struct Seamless_intrinsic_metric_status : Seamless_metric_status
{
  std::size_t cone_metric_flips = 0;  ///< Ptolemy flips from the input to the input metric's Delaunay triangulation
  std::size_t edge_flips = 0;         ///< Ptolemy flips made by the Newton steps after those
  /// the seamless metric (its lengths) on its Delaunay triangulation, with its common subdivision
  /// with the input when `success` and the correspondence passed its own checks
  Intrinsic_triangulation intrinsic_triangulation;
  std::string correspondence_message;   ///< why there is no common subdivision, if so
};

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// Makes a flat cone metric seamless as seamless_cone_metric() does (same curvature at every
/// vertex, the holonomy around every handle loop and the turning between boundary loops a
/// multiple of \f$2\pi/N\f$, the multiple nearest to the input metric's), but with intrinsic edge
/// flips, so that no triangle of the input limits how far a holonomy can move.
///
/// The flat cone metric is given by conformal factors \f$u\f$ on the input (compute_cone_metric()'s
/// `conformal_factor_map`) and the lengths \f$\ell^0_{ij} e^{(u_i + u_j)/2}\f$ they give the input's
/// edges: on the intrinsic Delaunay triangulation reached from the input by Ptolemy flips when
/// compute_cone_metric() flipped (its status' `triangulation_changed`), on the input's own edges
/// when it did not (pass `intrinsic_edge_flips(false)`; that metric is then made Delaunay by flips
/// that keep it).
///
/// <b>Method.</b> Penner coordinates (the log lengths of the current triangulation's edges) are the
/// unknowns, and the metric they stand for is the Euclidean metric of their intrinsic Delaunay
/// triangulation, reached by Ptolemy flips \f$\ell_{cd} \ell_{ab} = \ell_{ac} \ell_{bd} + \ell_{ad}
/// \ell_{bc}\f$ (Gillespie, Springborn, Crane 2021; Capouellez and Zorin 2023). Each Newton step is
/// that of seamless_cone_metric() (least change, curvatures and holonomies together, one sparse
/// factorisation of \f$J J^T\f$), on the current triangulation; every trial step is made Delaunay
/// by flips before it is measured, and the handle loops are carried through the flips (a stretch
/// of a loop inside a flipped quadrilateral is replaced by the path between the same sides). The
/// holonomies move to their goals in stages of at most 0.15 rad. The flips from the input are
/// replayed on its common subdivision (normal coordinates, as for compute_cone_metric()), so the
/// result maps to the input: a point keeps its projective coordinates under the factors \f$u\f$
/// in its intrinsic face, now a triangle of the seamless lengths.
///
/// \param tm a triangle mesh of one component
/// \param conformal_factors a readable vertex property map: \f$u_v\f$ (finite)
/// \param np the input metric (`edge_length_map` or `vertex_point_map`), `intrinsic_edge_flips`
///   (default `true`: the factors' metric lives on their Delaunay triangulation, as above), `symmetry_order` (\f$N\f$,
///   default 4), `curvature_tolerance` (default \f$10^{-10}\f$, curvatures and holonomies),
///   `number_of_iterations` (default 100, Newton steps over all stages)
///
/// Throws `Input_error` for several components, \f$N < 1\f$, a non-finite factor or an invalid mesh.
template <typename TriangleMesh, typename VertexFactorMap, typename NamedParameters = parameters::Default_named_parameters>
Seamless_intrinsic_metric_status seamless_intrinsic_cone_metric(const TriangleMesh& tm, const VertexFactorMap& conformal_factors,
                                                                const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef internal::Loop_turn Turn;
  Seamless_intrinsic_metric_status st;
  const int N = choose_parameter(get_parameter(np, internal_np::symmetry_order), 4);
  if(N < 1) throw Input_error(Input_error::INVALID_ARGUMENT, "symmetry order N must be at least 1, got " + std::to_string(N));
  const double tol = choose_parameter(get_parameter(np, internal_np::curvature_tolerance), 1e-10);
  const int max_iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 100);
  const Intrinsic_mesh<TriangleMesh> im = internal::get_intrinsic_mesh(tm, np);
  const internal::Mesh_arrays<TriangleMesh>& m = im.arrays();
  if(im.topology_arrays().components.size() != 1)
    throw Input_error(Input_error::INVALID_ARGUMENT, "seamless_intrinsic_cone_metric() needs a mesh of one component");
  const std::size_t nv = m.number_of_vertices(), ne = m.number_of_edges(), nf = m.number_of_faces();
  std::vector<double> u(nv, 0.);
  for(std::size_t v = 0; v < nv; ++v) {
    u[v] = double(get(conformal_factors, m.vertices[v]));
    if(!std::isfinite(u[v])) throw Input_error(Input_error::INVALID_GEOMETRY, "conformal factor of vertex " + std::to_string(v) + " is not finite");
  }
  const double period = 2 * CGAL_PI / N;

  const bool flipped_metric = choose_parameter(get_parameter(np, internal_np::intrinsic_edge_flips), true);
  const std::size_t budget = 100 * ne + 1000;

  // the input metric on its Delaunay triangulation, reached from the input's edges
  internal::Flippable_triangulation tri;
  tri.next = m.next;
  tri.target = m.target;
  tri.face = m.face;
  tri.face_halfedge = m.face_halfedge;
  std::vector<double> len(ne);
  for(std::size_t e = 0; e < ne; ++e) len[e] = m.length[e] * std::exp(0.5 * (u[std::size_t(m.target[2 * e])] + u[std::size_t(m.target[2 * e + 1])]));
  if(!flipped_metric)
    for(std::size_t f = 0; f < nf; ++f) {
      const int h0 = m.face_halfedge[f], h1 = m.next[std::size_t(h0)], h2 = m.next[std::size_t(h1)];
      const double a = len[std::size_t(h0 >> 1)], b = len[std::size_t(h1 >> 1)], c = len[std::size_t(h2 >> 1)];
      if(!(a < b + c && b < a + c && c < a + b)) {
        st.message = "face " + std::to_string(f) + " violates the triangle inequality under these factors without flips";
        return st;
      }
    }
  std::vector<internal::Flip_record> start_log;
  if(!internal::delaunay_flips(tri, len, start_log, budget, flipped_metric)) {
    st.message = "the flips to the input metric's Delaunay triangulation do not end";
    return st;
  }
  st.cone_metric_flips = start_log.size();
  const internal::Flippable_triangulation tri0 = tri;
  std::vector<int> flip_log;   // every flip from the input, for the correspondence
  for(const internal::Flip_record& r : start_log) flip_log.push_back(r.e);
  const std::size_t start_flips = flip_log.size();

  // its handle loops and boundary paths (tree-cotree on that triangulation)
  std::vector<std::vector<Turn>> loops;
  std::size_t closed_loops = 0;
  {
    internal::Mesh_arrays<TriangleMesh> t0 = m;
    t0.next = tri.next;
    t0.target = tri.target;
    t0.face = tri.face;
    t0.face_halfedge = tri.face_halfedge;
    // an outgoing halfedge per vertex, on the boundary the one after the border (never flipped)
    t0.vertex_out.assign(nv, -1);
    for(std::size_t h = 0; h < 2 * ne; ++h)
      if(tri.face[h] >= 0 && (t0.vertex_out[std::size_t(tri.source(int(h)))] < 0 || tri.face[h ^ 1] < 0))
        t0.vertex_out[std::size_t(tri.source(int(h)))] = int(h);
    const internal::Topology_arrays topology(t0);
    const std::vector<internal::Generator_arrays> generators = internal::tree_cotree(t0, topology);
    for(const auto& g : generators) if(g.handle && !g.dual.empty()) ++closed_loops;
    loops = internal::holonomy_loops(t0, topology, generators);
  }
  st.loops = loops.size();

  std::vector<double> angle(2 * ne, 0.);   // per halfedge with a face: the angle at its source
  auto angles_of = [&](const internal::Flippable_triangulation& t, const std::vector<double>& l) {
    return internal::corner_angles_of(t, l, angle);
  };
  auto curvature = [&](const internal::Flippable_triangulation& t, std::vector<double>& K) {
    internal::vertex_curvatures_of(m, t, angle, K);
  };
  const double start_min_angle = angles_of(tri, len);
  if(!(start_min_angle > 0)) { st.message = "the input metric's Delaunay triangulation is degenerate"; return st; }
  // as seamless_cone_metric(), but no stricter than half the input metric's own smallest angle
  const double min_angle = (std::min)(1e-3, 0.5 * start_min_angle);
  std::vector<double> K0, K;
  curvature(tri, K0);
  // the goal curvatures: those of the input metric, made exact multiples of 2 pi / N where they are
  // within 1e-6 (a cone metric's, solved to a tolerance; on a torus without cones the holonomy is
  // exactly 0 only for exactly flat vertices)
  for(double& k : K0)
    if(std::abs(k / period - std::round(k / period)) < 1e-6) k = period * std::round(k / period);
  // holonomies unwrapped: a loop carried through flips keeps its holonomy up to multiples of 2 pi
  std::vector<double> H(loops.size());
  auto holonomies = [&](const internal::Flippable_triangulation& t, const std::vector<std::vector<Turn>>& ls,
                        const std::vector<double>& near, std::vector<double>& out) {
    out.resize(ls.size());
    for(std::size_t i = 0; i < ls.size(); ++i) {
      const double raw = internal::loop_holonomy(t, angle, ls[i]);
      out[i] = near.empty() ? raw : raw + 2 * CGAL_PI * std::round((near[i] - raw) / (2 * CGAL_PI));
    }
  };
  holonomies(tri, loops, {}, H);
  std::vector<double> start = H, goal(loops.size()), target(loops.size());
  for(std::size_t i = 0; i < loops.size(); ++i) {
    goal[i] = period * std::round(start[i] / period);
    st.initial_holonomy_error = (std::max)(st.initial_holonomy_error, std::abs(start[i] - goal[i]));
  }
  int nrows = 0;
  const std::vector<int> row = m.indices_but_first_vertex(nrows);
  const int loop_row0 = nrows;
  nrows += int(loops.size());
  auto residual = [&](const std::vector<double>& Hs, Eigen::VectorXd& F) {   // angles of the triangulation measured
    F = Eigen::VectorXd::Zero(nrows);
    double ck = 0, hk = 0;
    for(std::size_t v = 0; v < nv; ++v)
      if(row[v] >= 0) { F[row[v]] = K[v] - K0[v]; ck = (std::max)(ck, std::abs(F[row[v]])); }
    for(std::size_t i = 0; i < loops.size(); ++i) {
      F[loop_row0 + int(i)] = Hs[i] - target[i];
      hk = (std::max)(hk, std::abs(F[loop_row0 + int(i)]));
    }
    st.curvature_error = ck;
    st.holonomy_error = hk;
  };
  const std::vector<double> l0 = len;
  std::vector<int> count(nf, 0);
  auto measure = [&]() {   // the current state's angles and curvatures
    angles_of(tri, len);
    curvature(tri, K);
  };
  Eigen::VectorXd F;
  measure();
  for(std::size_t i = 0; i < loops.size(); ++i) target[i] = goal[i];
  residual(H, F);
  if(loops.empty() || st.holonomy_error <= tol) {
    st.success = st.curvature_error <= tol;
    if(!st.success) st.message = "the input metric's curvatures are not consistent";
  } else {
    Cholmod_cholesky chol;
    // stages of at most 0.15 rad (four at least, as seamless_cone_metric())
    const int stages = (std::max)(4, int(std::ceil(st.initial_holonomy_error / 0.15)));
    bool stuck = false;
    int slow_steps = 0, it = 0;
    for(int stage = 1; stage <= stages && !stuck; ++stage) {
      for(std::size_t i = 0; i < loops.size(); ++i) target[i] = start[i] + (goal[i] - start[i]) * stage / stages;
      measure();
      residual(H, F);
      const double stage_tol = stage == stages ? tol : 1e-6;
      for(; it < max_iterations; ++it) {
        if(st.curvature_error <= stage_tol && st.holonomy_error <= stage_tol) break;
        const Eigen::SparseMatrix<double> J = internal::seamless_jacobian(tri, angle, row, loop_row0, loops, ne);
        Eigen::SparseMatrix<double> JJt = J * Eigen::SparseMatrix<double>(J.transpose());
        // a relative 1e-12 on the diagonal: on a torus without cones a holonomy row is a
        // combination of curvature rows (a flat torus has no rotational holonomy)
        double diagonal = 0;
        for(int r = 0; r < nrows; ++r) diagonal = (std::max)(diagonal, JJt.coeff(r, r));
        for(int r = 0; r < nrows; ++r) JJt.coeffRef(r, r) += 1e-12 * diagonal;
        Cholmod_cholesky::Matrix lower = JJt.triangularView<Eigen::Lower>();
        std::string msg;
        if(!chol.factor(lower, msg)) { st.message = "the Newton system could not be factored: " + msg; stuck = true; break; }
        const Eigen::VectorXd dl = J.transpose() * chol.solve(Eigen::VectorXd(-F));
        const double merit = F.squaredNorm();
        bool moved = false;
        for(double t = 1; t >= 1. / 1024; t /= 2) {
          internal::Flippable_triangulation tt = tri;
          std::vector<double> lt(ne);
          for(std::size_t e = 0; e < ne; ++e) lt[e] = len[e] * std::exp(t * dl[Eigen::Index(e)]);
          std::vector<internal::Flip_record> log;
          if(!internal::delaunay_flips(tt, lt, log, budget)) continue;
          if(!(angles_of(tt, lt) > min_angle)) continue;
          std::vector<std::vector<Turn>> lst = loops;
          try {
            if(!log.empty())
              for(std::size_t i = 0; i < lst.size(); ++i) internal::carry_loop_through_flips(lst[i], i < closed_loops, log, count);
          } catch(const std::runtime_error&) {
            std::fill(count.begin(), count.end(), 0);
            continue;
          }
          curvature(tt, K);
          std::vector<double> Ht;
          holonomies(tt, lst, H, Ht);
          Eigen::VectorXd Ft;
          residual(Ht, Ft);
          if(!(Ft.squaredNorm() < merit)) continue;
          tri = std::move(tt);
          len = std::move(lt);
          loops = std::move(lst);
          H = std::move(Ht);
          F = Ft;
          for(const internal::Flip_record& r : log) flip_log.push_back(r.e);
          moved = true;
          break;
        }
        st.iterations = it + 1;
        // stalled: 3 steps in a row that took off less than a tenth of |F|^2 (far from the goal,
        // where a step makes hundreds of flips, Newton takes off a third to a half per step)
        slow_steps = moved && F.squaredNorm() > 0.9 * merit ? slow_steps + 1 : 0;
        if(!moved || slow_steps >= 3) { stuck = true; break; }
      }
    }
    measure();
    residual(H, F);
    st.success = st.curvature_error <= tol && st.holonomy_error <= tol;
    if(!st.success && st.message.empty())
      st.message = "Newton stopped after " + std::to_string(st.iterations) + " steps with the holonomy " + std::to_string(st.holonomy_error) +
                   " and the curvature " + std::to_string(st.curvature_error) + " rad off";
  }
  st.min_angle = angles_of(tri, len);
  // the log change of the lengths of the edges that were not flipped
  for(std::size_t e = 0; e < ne; ++e)
    if(tri.target[2 * e] == tri0.target[2 * e] && tri.target[2 * e + 1] == tri0.target[2 * e + 1])
      st.max_log_length_change = (std::max)(st.max_log_length_change, std::abs(std::log(len[e] / l0[e])));
  st.edge_flips = flip_log.size() - start_flips;
  if(!st.success) {   // the input metric's triangulation, not a metric half way
    tri = tri0;
    len = l0;
    flip_log.resize(start_flips);
  }
  // the flips replayed on the input with its crossings (normal coordinates), as compute_cone_metric()
  internal::Tracked_delaunay_flips<TriangleMesh> tf(m);
  try {
    tf.replay(flip_log);
    if(tf.tri.next != tri.next || tf.tri.target != tri.target)
      throw internal::internal_correspondence_error("the replayed flips do not give the Newton steps' triangulation");
  } catch(const std::runtime_error& e) {
    st.correspondence_message = e.what();
  }
  std::vector<long> input_edge(tf.coincident.begin(), tf.coincident.end());
  st.intrinsic_triangulation = Intrinsic_triangulation(nv, tri.next, tri.target, tri.face, tri.face_halfedge, len, std::move(input_edge));
  if(st.correspondence_message.empty()) {
    try {
      internal::build_common_subdivision(m, tf, u, len, st.intrinsic_triangulation);
    } catch(const std::runtime_error& e) {
      st.correspondence_message = e.what();
    }
  }
  return st;
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_SEAMLESS_INTRINSIC_METRIC_H
