// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_CONE_METRIC_PHASES_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_CONE_METRIC_PHASES_H

// The phases of compute_cone_metric() (cone_metric.h), in their order: the targets and their
// validation, the Newton flow, the area normalisation and the output. The cones of index >= 1
// (holes) are in cone_holes.h.

#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/parameters.h>
#include <CGAL/Surface_mesh_direction_fields/intrinsic_triangle.h>
#include <CGAL/Surface_mesh_direction_fields/Intrinsic_triangulation.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh_arrays.h>
#include <CGAL/Surface_mesh_direction_fields/internal/topology.h>
#include <CGAL/Surface_mesh_direction_fields/internal/ricci_flow.h>
#include <CGAL/Surface_mesh_direction_fields/internal/common_subdivision.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

inline double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// --- 1. the targets

// Reads the target of every vertex that is not isolated (0 for isolated ones); throws
// Input_error if one is not finite or a boundary target is >= pi. punched: the interior vertices
// with a target >= 2 pi (cones of index >= 1), in vertex order.
template <typename TM, typename VertexCurvatureMap>
void read_target_curvatures(const Mesh_arrays<TM>& m, VertexCurvatureMap target_curvature,
                            std::vector<double>& target, std::vector<int>& punched)
{
  const std::size_t nv = m.number_of_vertices();
  target.assign(nv, 0.);
  punched.clear();
  for(std::size_t v = 0; v < nv; ++v) {
    if(m.is_isolated(int(v))) continue;
    const double k = double(get(target_curvature, m.vertices[v]));
    const bool boundary = m.is_boundary_vertex(int(v));
    std::ostringstream os;
    os.precision(17);
    if(!std::isfinite(k)) {
      os << "target curvature of vertex " << v << " is not finite";
      throw Input_error(Input_error::INVALID_ARGUMENT, os.str());
    }
    if(!boundary && k >= 2 * CGAL_PI) punched.push_back(int(v));
    if(boundary && k >= CGAL_PI) {
      os << "target geodesic curvature " << k << " of boundary vertex " << v << " is >= pi";
      throw Input_error(Input_error::INVALID_ARGUMENT, os.str());
    }
    target[v] = k;
  }
}

// Gauss-Bonnet: throws Input_error (INCONSISTENT_INDICES) if the targets of a connected
// component do not sum to 2 pi chi.
template <typename TM>
void check_gauss_bonnet(const Mesh_arrays<TM>& m, const Topology_arrays& topo, const std::vector<double>& target)
{
  std::vector<double> sum(topo.components.size(), 0.);
  for(std::size_t v = 0; v < m.number_of_vertices(); ++v)
    if(!m.is_isolated(int(v))) sum[topo.vertex_component[v]] += target[v];
  for(std::size_t c = 0; c < topo.components.size(); ++c) {
    const double chi = double(topo.components[c].euler_characteristic());
    const double expected = 2 * CGAL_PI * chi;
    if(std::abs(sum[c] - expected) > 1e-8 * (std::max)(1., std::abs(expected))) {
      std::ostringstream os;
      os.precision(17);
      os << "Gauss-Bonnet: the target curvatures of component " << c << " sum to " << sum[c]
         << " but 2*pi*chi = " << expected << " (Euler characteristic " << chi << ")";
      throw Input_error(Input_error::INCONSISTENT_INDICES, os.str());
    }
  }
}

// --- 3. the Newton flow (Flow: Vertex_scaling_flow)

// Newton, first on the input triangulation (unless input_first is false), then (if needed and
// allowed) with intrinsic flips. u: the conformal factors, 0 on input; len: the lengths of the
// result.
template <typename Flow, typename Visitor>
Vertex_scaling_result run_vertex_scaling(Flow& flow, const std::vector<double>& target,
                                         std::vector<double>& u, std::vector<double>& len,
                                         int max_iterations, double tol, Visitor& visitor,
                                         bool allow_flips, bool input_first = true)
{
  if(allow_flips && !input_first)
    return flow.run(target, u, len, max_iterations, tol, visitor, Flow::FLIPS);
  // With flips available, the input triangulation is abandoned after a step cut to t <= 1/8 by
  // degenerating triangles (before taking it if it is the first step), 2 consecutive steps cut
  // to t <= 1/4, or 3 cut steps without 10% progress: on a decimated 20k-face armadillo with 8 cones the cut steps keep shrinking (t = 1/8 ... 1/128) while the
  // Delaunay flow then converges in 5 full steps; steps cut to t = 1/2 usually still converge
  // on the input triangulation (armadillo, 52k faces, 7 iterations).
  Vertex_scaling_result r =
      flow.run(target, u, len, max_iterations, tol, visitor, allow_flips ? Flow::FIXED_BEFORE_FLIPS : Flow::FIXED);
  if(!r.converged && allow_flips && r.iterations < max_iterations) {
    Vertex_scaling_result r2 =
        flow.run(target, u, len, max_iterations - r.iterations, tol, visitor, Flow::FLIPS, r.iterations, true);
    r2.iterations += r.iterations;
    r = r2;
  }
  return r;
}

// --- 4. area normalisation per component: shift u so that the total area is preserved

// u2: u shifted on every component whose area differs from the input's (in the metric `len` of
// u on the flow's triangulation); false if no component needed it.
template <typename TM>
bool area_preserving_factors(const Mesh_arrays<TM>& m, const Topology_arrays& topo,
                             const Flippable_triangulation& tri, const std::vector<double>& len,
                             const std::vector<double>& u, std::vector<double>& u2)
{
  std::vector<double> a0(topo.components.size(), 0.), a1(topo.components.size(), 0.);
  for(std::size_t f = 0; f < m.number_of_faces(); ++f) {
    const int c = topo.face_component[f];
    int h0 = m.face_halfedge[f], h1 = m.next[h0], h2 = m.next[h1];
    a0[c] += triangle_area(m.length[h0 >> 1], m.length[h1 >> 1], m.length[h2 >> 1]);
    h0 = tri.face_halfedge[f]; h1 = tri.next[h0]; h2 = tri.next[h1];
    a1[c] += triangle_area(len[h0 >> 1], len[h1 >> 1], len[h2 >> 1]);
  }
  bool rescaled = false;
  u2 = u;
  for(std::size_t c = 0; c < topo.components.size(); ++c) {
    if(!(a1[c] > 0) || a0[c] == a1[c]) continue;
    const double shift = 0.5 * std::log(a0[c] / a1[c]);   // lengths scale like e^c, areas like e^{2c}
    if(!std::isfinite(shift)) continue;
    for(std::size_t v = 0; v < m.number_of_vertices(); ++v)
      if(topo.vertex_component[v] == int(c)) u2[v] += shift;
    rescaled = true;
  }
  return rescaled;
}

// Replaces u, len and the errors of r by those of the area-preserving factors, unless that costs
// the convergence.
template <typename TM, typename Flow>
void normalise_areas(const Mesh_arrays<TM>& m, const Topology_arrays& topo, Flow& flow,
                     const std::vector<double>& target, double tol, std::vector<double>& u,
                     std::vector<double>& len, Vertex_scaling_result& r)
{
  std::vector<double> u2;
  if(!area_preserving_factors(m, topo, flow.triangulation(), len, u, u2)) return;
  std::vector<double> len2, ang, sens, k, rho;
  flow.lengths(u2, len2);   // a uniform scaling keeps the triangulation Delaunay
  if(flow.angles(len2, u2, ang, sens)) {
    flow.curvatures(ang, sens, k, rho);
    const double err = flow.scaled_error(k, rho, target);
    // keep the normalisation unless it costs the convergence (rounding only)
    if(err <= tol || !r.converged) {
      len.swap(len2); u.swap(u2);
      r.max_error = flow.max_error(k, target); r.scaled_error = err; r.converged = err <= tol;
      r.rounding_level = *std::max_element(rho.begin(), rho.end());
    }
  }
}

// --- 5. the output

// The flow kept the input triangulation: len are the lengths of the input edges.
template <typename TM, typename EdgeLengthMap>
void put_input_edge_lengths(const Mesh_arrays<TM>& m, const std::vector<double>& len, EdgeLengthMap output_lengths)
{
  for(std::size_t e = 0; e < m.number_of_edges(); ++e) put(output_lengths, m.edges[e], len[e]);
}

// The angle sum at every vertex of a triangulation with lengths `len`.
inline std::vector<double> vertex_angle_sums(const Flippable_triangulation& tri, const std::vector<double>& len, std::size_t nv)
{
  std::vector<double> sum(nv, 0.);
  for(std::size_t f = 0; f < tri.face_halfedge.size(); ++f) {
    const int h0 = tri.face_halfedge[f], h1 = tri.next[std::size_t(h0)], h2 = tri.next[std::size_t(h1)];
    const std::array<double, 3> a = triangle_angles(len[std::size_t(h0 >> 1)], len[std::size_t(h1 >> 1)], len[std::size_t(h2 >> 1)]);
    sum[std::size_t(tri.target[std::size_t(h2)])] += a[1];   // at source(h0), opposite next(h0)
    sum[std::size_t(tri.target[std::size_t(h0)])] += a[2];
    sum[std::size_t(tri.target[std::size_t(h1)])] += a[0];
  }
  return sum;
}

// The flow flipped edges: the intrinsic Delaunay triangulation of its final factors u is made
// again from the input, each flip carrying the crossings of the input edges (tracking them in
// the flow itself would copy them at every snapshot of its line searches). Its flips go straight
// to the end: the flow's go back and forth between Newton steps, and every flip rounds the
// crossings it carries (cheese, 1068 cones: 20,858 flips and a residual of 2.5e-11, against
// 174,470 and 4.7e-7 replaying the flow's). Its triangulation is Delaunay for the flow's metric
// (the flow's own up to cocircular quadrilaterals), its lengths the flow's up to rounding. If
// that fails, the flow's flips (flip_log(), without those of rejected trial points) are replayed:
// the same Ptolemy updates give its triangulation and Penner coordinates bit for bit. `it`
// receives the triangulation with its lengths and its common subdivision, output_lengths the
// lengths of the input edges that are still edges (a quiet NaN for the others). If the
// correspondence fails its own checks (or is not wanted), `it` is the flow's triangulation
// without common subdivision and correspondence_message says why.
template <typename TM, typename Flow, typename EdgeLengthMap>
void output_intrinsic_triangulation(const Mesh_arrays<TM>& m, const Flow& flow, const std::vector<double>& u,
                                    const std::vector<double>& len, const std::vector<double>& target, double tol,
                                    EdgeLengthMap output_lengths,
                                    Intrinsic_triangulation& it, std::string& correspondence_message,
                                    bool with_subdivision = true)
{
  const Flippable_triangulation* tri = &flow.triangulation();
  const std::vector<double>* lengths = &len;
  Tracked_delaunay_flips<TM> tf(m);
  std::vector<double> direct_len;
  bool tracked = with_subdivision;
  if(tracked) {
    try {
      direct_len = tf.make_delaunay(u);
      // it must meet the flow's convergence test, with the rounding allowance of the flow's own
      // triangulation (cheese, random cones: 1.3e-10 against a tolerance of 1e-10): the rounding of
      // its flips can undo it around a cone of hundreds of turns, reached by millions of flips;
      // the replay then gives the flow's metric itself
      std::vector<double> angles, sensitivity, k, rounding;
      if(!flow.angles(len, u, angles, sensitivity))
        throw internal_correspondence_error("the flow's triangulation has a degenerate face");
      flow.curvatures(angles, sensitivity, k, rounding);
      const std::vector<double> sums = vertex_angle_sums(tf.tri, direct_len, m.number_of_vertices());
      for(std::size_t v = 0; v < sums.size(); ++v) {
        if(m.is_isolated(int(v))) continue;
        const double full = m.is_boundary_vertex(int(v)) ? CGAL_PI : 2 * CGAL_PI;
        if(!(std::abs(full - sums[v] - target[v]) <= tol * (std::max)(1., (full - target[v]) / (2 * CGAL_PI)) + rounding[v]))
          throw internal_correspondence_error("the rebuilt triangulation misses the curvature tolerance");
      }
      tri = &tf.tri;
      lengths = &direct_len;
    } catch(const std::runtime_error&) {
      try {
        tf = Tracked_delaunay_flips<TM>(m);
        tf.replay(flow.flip_log());
        if(tf.tri.next != flow.triangulation().next || tf.tri.target != flow.triangulation().target || tf.l0 != flow.base_lengths())
          throw internal_correspondence_error("the replayed flips do not give the flow's triangulation");
      } catch(const std::runtime_error& e) {
        correspondence_message = e.what();
        tracked = false;
      }
    }
  }
  std::vector<long> input_edge(m.number_of_edges(), -1);
  if(tracked) input_edge.assign(tf.coincident.begin(), tf.coincident.end());
  else {
    // an edge is an input edge if it joins the same vertices with the same Penner coordinate (a
    // flipped-back edge has exactly its old one: Ptolemy is an involution; input edges sorted by
    // their end points)
    const std::size_t nv = m.number_of_vertices();
    auto key = [nv](int a, int b) { return (long long)(std::min)(a, b) * (long long)nv + (std::max)(a, b); };
    std::vector<std::pair<long long, int>> by_ends(m.number_of_edges());
    for(std::size_t e = 0; e < m.number_of_edges(); ++e) by_ends[e] = std::make_pair(key(m.target[2 * e], m.target[2 * e + 1]), int(e));
    std::sort(by_ends.begin(), by_ends.end());
    for(std::size_t e = 0; e < m.number_of_edges(); ++e) {
      const long long k = key(tri->target[2 * e], tri->target[2 * e + 1]);
      for(auto p = std::lower_bound(by_ends.begin(), by_ends.end(), std::make_pair(k, -1)); p != by_ends.end() && p->first == k; ++p)
        if(std::abs(flow.base_lengths()[e] - m.length[std::size_t(p->second)]) <= 1e-12 * m.length[std::size_t(p->second)]) {
          input_edge[e] = p->second;
          break;
        }
    }
  }
  std::vector<double> out(m.number_of_edges(), std::numeric_limits<double>::quiet_NaN());
  for(std::size_t e = 0; e < m.number_of_edges(); ++e)
    if(input_edge[e] >= 0) out[std::size_t(input_edge[e])] = (*lengths)[e];
  for(std::size_t e = 0; e < m.number_of_edges(); ++e) put(output_lengths, m.edges[e], out[e]);
  it = Intrinsic_triangulation(m.number_of_vertices(), tri->next, tri->target, tri->face, tri->face_halfedge, *lengths, std::move(input_edge));
  if(tracked) try {
    build_common_subdivision(m, tf, u, *lengths, it);
  } catch(const std::runtime_error& e) {
    correspondence_message = e.what();
  }
}

// Writes conformal_factor(v) of every vertex v to the conformal_factor_map of np, if given.
template <typename TM, typename NamedParameters, typename ConformalFactor>
void put_conformal_factors(const Mesh_arrays<TM>& m, const NamedParameters& np,
                           const ConformalFactor& conformal_factor)
{
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::conformal_factor_t>::value) {
    auto ufm = parameters::get_parameter(np, internal_np::conformal_factor);
    for(std::size_t v = 0; v < m.number_of_vertices(); ++v) put(ufm, m.vertices[v], conformal_factor(v));
  }
}

// Copies the outcome of the flow into the status (a Cone_metric_status).
template <typename Status>
void put_flow_outcome(Vertex_scaling_result& r, Status& st)
{
  if(r.converged) r.message.clear();
  else if(r.message.empty()) r.message = "curvature tolerance not reached";
  st.edge_flips = r.flips;
  st.converged = r.converged;
  st.iterations = r.iterations;
  st.max_curvature_error = r.max_error;
  st.rounding_level = r.rounding_level;
  st.message = r.message;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_CONE_METRIC_PHASES_H
