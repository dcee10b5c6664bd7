// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_REMESHING_CONES_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_REMESHING_CONES_H

// Cones for regular remeshing: few vertices whose curvatures are multiples of 2 pi / N,
// placed where a flat metric would otherwise stretch the surface most (greedy placement of
// Ben-Chen, Gotsman and Bunin 2008, as used by Gillespie, Springborn and Crane 2021), then
// read back on the flat cone metric they give.

#include <CGAL/Surface_mesh_direction_fields/Cholmod_cholesky.h>
#include <CGAL/Surface_mesh_direction_fields/Intrinsic_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/cone_metric.h>
#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/parameters.h>
#include <CGAL/Surface_mesh_direction_fields/internal/cotan_weights.h>
#include <CGAL/Surface_mesh_direction_fields/internal/development.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <functional>
#include <limits>
#include <queue>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// Outcome of place_remeshing_cones().
template <typename TriangleMesh>
struct Remeshing_cones_status
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  /// the flat cone metric with `cones` converged and its scale spread is at most the bound
  bool success = false;
  std::string message;        ///< why not; empty on success
  int N = 4;                  ///< cone curvatures are multiples of \f$2\pi/N\f$
  double distortion_bound = 0; ///< the bound used
  /// the cones: interior vertices with their curvature \f$K\f$, boundary vertices (corners of
  /// the remesh's boundary) with their turning \f$\kappa = \pi - \sum\theta\f$; each
  /// \f$2\pi/N\f$ or \f$-2\pi k/N\f$ with \f$1 \le k \le\f$ `negative_cone_quanta`, summing to
  /// \f$2\pi\chi\f$, no two adjacent, in vertex order. On a quad remesh an interior cone
  /// becomes a vertex of valence \f$4 - K/(\pi/2)\f$.
  std::vector<std::pair<vertex_descriptor, double>> cones;
  /// \f$\max_v u_v - \min_v u_v\f$ of the flat cone metric with `cones` (its conformal factors
  /// \f$u\f$, lengths scaled by \f$e^{u}\f$): the logarithm of the ratio of its largest to its
  /// smallest length scale, away from the cones and their neighbours (and, when
  /// `minimum_cone_distance` is given, from the vertices within that distance of a cone). Read
  /// back from the metric, not predicted.
  double scale_spread = 0;
  /// the same spread predicted by the linearised placement, before the curvatures were rounded
  double linear_scale_spread = 0;
  int greedy_steps = 0;       ///< greedy steps (one per cone)
  /// the most quanta of \f$-2\pi/N\f$ one cone may take (`maximum_negative_cone_quanta`, or its
  /// default for this mesh: 2 when \f$2\pi\chi\f$ alone would take more than half of
  /// `maximum_number_of_cones` cones of one quantum, else 1)
  int negative_cone_quanta = 1;
  /// cones placed closer than `minimum_cone_distance` to an earlier one, for want of any other
  /// vertex of the sign needed (0 when every pair of cones is at least that far apart)
  int crowded_cones = 0;
  int placement_rounds = 0;   ///< rounds of placement and read-back (the linear bound is tightened after each miss)
  Cone_metric_status metric;       ///< the flat cone metric with `cones` (its intrinsic triangulation when it flipped)
};

namespace internal {

// The linearised setting of the greedy placement (Ben-Chen et al. 2008): the log scale u of the
// flat metric with curvature Khat solves L u = K - Khat (L the cotan Laplacian, K the angle
// defect, the boundary's turning at boundary vertices). One factorisation, with the first vertex
// removed (u is defined up to a constant), serves every cone set.
template <typename TM>
class Greedy_cone_placement
{
public:
  Greedy_cone_placement(const Mesh_arrays<TM>& m, std::string& message)
  {
    const std::size_t nv = m.number_of_vertices();
    vertex_curvatures(m, K_);
    const std::vector<double> w = floored_cotan_edge_weights(m);
    // columns: every vertex with an edge but the first one (u is defined up to a constant)
    int n = 0;
    col_ = m.indices_but_first_vertex(n);
    std::vector<Eigen::Triplet<double>> t;
    t.reserve(3 * m.number_of_edges());
    for(std::size_t e = 0; e < m.number_of_edges(); ++e) {
      const int a = col_[std::size_t(m.source(int(2 * e)))], b = col_[std::size_t(m.target[2 * e])];
      if(a == b) continue;
      if(a >= 0) t.emplace_back(a, a, w[e]);
      if(b >= 0) t.emplace_back(b, b, w[e]);
      if(a >= 0 && b >= 0) t.emplace_back((std::max)(a, b), (std::min)(a, b), -w[e]);
    }
    if(n == 0) { message = "the mesh has fewer than two connected vertices"; return; }
    rows_ = n;
    Cholmod_cholesky::Matrix A(n, n);
    A.setFromTriplets(t.begin(), t.end());
    A.makeCompressed();
    Cholesky_hints hints;
    hints.many_solves = true;   // one back-substitution per greedy step: simplicial solves are faster
    ok_ = chol_.factor(A, hints, message);
    if(!ok_) message = "the cotan Laplacian could not be factored: " + message;
    area_.assign(nv, 0.);
    for(std::size_t f = 0; f < m.number_of_faces(); ++f) {
      const int h0 = m.face_halfedge[f], h1 = m.next[std::size_t(h0)], h2 = m.next[std::size_t(h1)];
      const double a = triangle_area(m.edge_length(h0), m.edge_length(h1), m.edge_length(h2)) / 3;
      for(int h : {h0, h1, h2}) area_[std::size_t(m.source(h))] += a;
    }
  }
  bool ok() const { return ok_; }

  // A^-1 b, extended by 0 at the vertex left out and at isolated vertices
  std::vector<double> solve(const std::vector<double>& b) const
  {
    const std::size_t nv = b.size();
    Eigen::VectorXd r(rows_);
    for(std::size_t v = 0; v < nv; ++v) if(col_[v] >= 0) r[col_[v]] = b[v];
    const Eigen::VectorXd x = chol_.solve(r);
    std::vector<double> u(nv, 0.);
    for(std::size_t v = 0; v < nv; ++v) if(col_[v] >= 0) u[v] = x[col_[v]];
    return u;
  }

  // The log scale of the metric with curvature k_v q at every vertex and the rest of the total
  // spread evenly by area (flat elsewhere when the cones hold the total), up to a constant
  std::vector<double> scale(const std::vector<int>& k, double q, double total) const
  {
    double A = 0, held = 0;
    for(double a : area_) A += a;
    for(int x : k) held += x * q;
    std::vector<double> b(K_.size());
    for(std::size_t v = 0; v < b.size(); ++v) b[v] = K_[v] - k[v] * q - (total - held) * area_[v] / A;
    return solve(b);
  }

  double mean(const std::vector<double>& u) const
  {
    double s = 0, A = 0;
    for(std::size_t v = 0; v < u.size(); ++v) { s += area_[v] * u[v]; A += area_[v]; }
    return s / A;
  }

private:
  std::vector<int> col_;
  int rows_ = 0;
  std::vector<double> K_, area_;
  Cholmod_cholesky chol_;
  bool ok_ = false;
};

// max - min of u away from the cones and their neighbours (at a cone the log scale of a flat
// cone metric is singular: its values there say nothing about the stretch around it)
inline double spread(const std::vector<double>& u, const std::vector<char>& near_cone)
{
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for(std::size_t v = 0; v < u.size(); ++v)
    if(!near_cone[v]) { lo = (std::min)(lo, u[v]); hi = (std::max)(hi, u[v]); }
  return hi >= lo ? hi - lo : 0.;
}

} // namespace internal

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// Places cones for a regular remesh (quads for \f$N = 4\f$, triangles for \f$N = 6\f$): few
/// vertices with curvatures that are multiples of \f$2\pi/N\f$, summing to \f$2\pi\chi\f$, such
/// that the flat cone metric with those cones stretches lengths by factors within
/// \f$e^{\pm B}\f$ of each other, \f$B\f$ the `distortion_bound`.
///
/// <b>Placement.</b> The greedy method of Ben-Chen, Gotsman and Bunin (2008), as in Gillespie,
/// Springborn and Crane (2021), in quanta: in the linearised setting, the log scale \f$u\f$ of the
/// flat metric with curvature \f$\hat K\f$ solves \f$L u = K - \hat K\f$ (\f$L\f$ the cotan
/// Laplacian, \f$K\f$ the angle defect, and at boundary vertices the boundary's turning, whose
/// target 0 makes the boundary straight between corners). With the current cones, and the rest
/// of the total curvature spread evenly by area, the vertex where \f$u\f$ is farthest from its
/// area-weighted mean becomes a cone of \f$\pm 2\pi/N\f$, of the sign that flattens it there
/// (a quad vertex of valence 3 or 5; a boundary corner of angle \f$\pi/2\f$ or \f$3\pi/2\f$),
/// never next to another cone, and on the boundary only where the boundary itself turns that way
/// (a convex corner where the input's angle is below \f$3\pi/4\f$, a concave one above
/// \f$5\pi/4\f$: elsewhere the corner's quads would have an angle near \f$\pi\f$). On a mesh of
/// high genus, whose total \f$2\pi\chi\f$ alone needs many cones, a negative cone may take
/// several quanta where the total still needs them (`maximum_negative_cone_quanta`: with 2, a quad
/// vertex of valence 6, half as many cones; the cheese of genus 133 needs 1,056 cones of one
/// quantum). Placement goes on until the spread \f$\max u - \min u\f$ away from the cones and
/// their neighbours (where the log scale of a cone metric is singular) is within the bound and
/// the cones sum to \f$2\pi\chi\f$. One sparse Cholesky factorisation serves every step (one
/// back-substitution each).
///
/// <b>Read-back.</b> The flat cone metric with the cones is then computed by compute_cone_metric()
/// (edge flips allowed) and its spread read back from its conformal factors. If it exceeds the
/// bound, placement goes on with the linear bound tightened by the ratio missed, up to 6 rounds.
/// If `maximum_number_of_cones` is reached first, the cones are completed to the total and the
/// status reports the spread reached, with `success` false.
///
/// \param tm a triangle mesh of one component (isolated vertices are ignored)
/// \param output_lengths receives the flat cone metric with the placed cones, per edge of `tm`
///   (as compute_cone_metric(): when the metric needed flips, it lives on the status's
///   `metric.intrinsic_triangulation` and these lengths are those of the input's edges there)
/// \param np `symmetry_order` (\f$N\f$, default 4), `distortion_bound` (\f$B\f$, default 2:
///   lengths within a factor \f$e^2 \approx 7.4\f$ of each other; the manual tabulates the cones
///   this takes on the shared meshes), `maximum_number_of_cones` (default 500),
///   `maximum_negative_cone_quanta` (at least 1; default 2 when \f$2\pi\chi\f$ alone would take
///   more than half of `maximum_number_of_cones` cones of \f$-2\pi/N\f$, else 1),
///   `minimum_cone_distance` (default 0: only adjacent cones are excluded; a length of the input
///   metric, along edges: a new cone goes closer than that to another only when no other vertex
///   of the sign needed is left; a remesh of edge length \f$h\f$ wants its cones a few \f$h\f$
///   apart), `minimum_boundary_distance` (default: `minimum_cone_distance`; the same for interior
///   cones and the boundary), `edge_length_map` or
///   `vertex_point_map` (the input metric), `conformal_factor_map` (receives \f$u\f$) and the
///   index maps.
///
/// Throws `Input_error` for invalid meshes, several components, \f$N < 1\f$ or a bound that is
/// not positive. Failure to converge or to meet the bound is reported in the status.
template <typename TriangleMesh, typename OutputEdgeLengthMap, typename NamedParameters = parameters::Default_named_parameters>
Remeshing_cones_status<TriangleMesh> place_remeshing_cones(const TriangleMesh& tm, OutputEdgeLengthMap output_lengths,
                                                           const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Remeshing_cones_status<TriangleMesh> st;
  const int N = choose_parameter(get_parameter(np, internal_np::symmetry_order), 4);
  if(N < 1) throw Input_error(Input_error::INVALID_ARGUMENT, "symmetry order N must be at least 1, got " + std::to_string(N));
  const double bound = choose_parameter(get_parameter(np, internal_np::distortion_bound), 2.0);
  if(!(bound > 0) || !std::isfinite(bound))
    throw Input_error(Input_error::INVALID_ARGUMENT, "distortion_bound must be positive and finite");
  const int max_cones = choose_parameter(get_parameter(np, internal_np::maximum_number_of_cones), 500);
  if(max_cones < 1) throw Input_error(Input_error::INVALID_ARGUMENT, "maximum_number_of_cones must be at least 1");
  constexpr bool quanta_given = !parameters::is_default_parameter<NamedParameters, internal_np::maximum_negative_cone_quanta_t>::value;
  const int given_quanta = choose_parameter(get_parameter(np, internal_np::maximum_negative_cone_quanta), 1);
  if(quanta_given && given_quanta < 1)
    throw Input_error(Input_error::INVALID_ARGUMENT, "maximum_negative_cone_quanta must be at least 1, got " + std::to_string(given_quanta));
  const double min_distance = choose_parameter(get_parameter(np, internal_np::minimum_cone_distance), 0.);
  if(!(min_distance >= 0) || !std::isfinite(min_distance))
    throw Input_error(Input_error::INVALID_ARGUMENT, "minimum_cone_distance must be finite and not negative");
  const double boundary_distance = choose_parameter(get_parameter(np, internal_np::minimum_boundary_distance), min_distance);
  if(!(boundary_distance >= 0) || !std::isfinite(boundary_distance))
    throw Input_error(Input_error::INVALID_ARGUMENT, "minimum_boundary_distance must be finite and not negative");
  st.N = N;
  st.distortion_bound = bound;
  const Intrinsic_mesh<TriangleMesh> im = internal::get_intrinsic_mesh(tm, np);
  const internal::Mesh_arrays<TriangleMesh>& m = im.arrays();
  const internal::Topology_arrays& topo = im.topology_arrays();
  if(topo.components.size() != 1)
    throw Input_error(Input_error::INVALID_ARGUMENT, "place_remeshing_cones() needs a mesh of one component; this one has " +
                                                     std::to_string(topo.components.size()));
  const std::size_t nv = m.number_of_vertices();
  internal::Greedy_cone_placement<TriangleMesh> greedy(m, st.message);
  if(!greedy.ok()) return st;
  const double q = 2 * CGAL_PI / N, total = 2 * CGAL_PI * double(topo.components[0].euler_characteristic());

  // cone curvatures k_v q: each step puts a quantum of curvature at the vertex where the metric
  // with the current cones (and the rest of the total spread evenly) stretches most, of the sign
  // that flattens it there, until that metric is within the bound and the cones hold the total
  const long target_k = std::lround(total / q);
  // a negative cone of two quanta (a vertex of valence 6) where the total alone would fill over
  // half the cones allowed: the map's dense system costs the cube of its cones and seams
  st.negative_cone_quanta = quanta_given ? given_quanta : (-target_k > max_cones / 2 ? 2 : 1);
  std::vector<int> k(nv, 0);
  // cones, their neighbours and isolated vertices: no new cone there, left out of the spread
  std::vector<char> near_cone(nv, 0);
  for(std::size_t v = 0; v < nv; ++v) near_cone[v] = m.is_isolated(int(v));
  // vertices closer than minimum_cone_distance to a cone (along edges): taken only when no
  // other vertex of the right sign is left
  std::vector<char> crowded(nv, 0);
  std::vector<double> reach(nv, std::numeric_limits<double>::infinity());
  auto crowd = [&](std::size_t c) {   // Dijkstra from c, bounded by the distance
    typedef std::pair<double, std::size_t> Item;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    std::vector<std::size_t> touched;
    reach[c] = 0;
    touched.push_back(c);
    queue.emplace(0., c);
    while(!queue.empty()) {
      const Item it = queue.top();
      queue.pop();
      if(it.first > reach[it.second]) continue;
      crowded[it.second] = 1;
      for(int h = m.vertex_out[it.second], h0 = h;;) {
        const std::size_t w = std::size_t(m.target[std::size_t(h)]);
        const double dw = it.first + m.length[std::size_t(h >> 1)];
        if(dw < min_distance && dw < reach[w]) { reach[w] = dw; touched.push_back(w); queue.emplace(dw, w); }
        if(m.face[std::size_t(h)] < 0) break;
        h = m.ccw_out(h);
        if(h == h0) break;
      }
    }
    for(std::size_t w : touched) reach[w] = std::numeric_limits<double>::infinity();
  };
  // a boundary vertex becomes a corner only where the boundary itself turns that way (its angle
  // below 3 pi/4 for a convex corner, a quad's corner there; above 5 pi/4 for a concave one,
  // three quads): a corner on a straight or smooth stretch gives a quad with an angle near pi
  std::vector<double> boundary_angle(nv, CGAL_PI);
  for(std::size_t v = 0; v < nv; ++v) {
    if(!m.is_boundary_vertex(int(v))) continue;
    double sum = 0;
    for(int h = m.vertex_out[v];; h = m.ccw_out(h)) { sum += m.angle[std::size_t(h)]; if(m.face[std::size_t(m.ccw_out(h))] < 0) break; }
    boundary_angle[v] = sum;
  }
  auto corner_fits = [&](std::size_t v, int sv) {
    return !m.is_boundary_vertex(int(v)) || (sv > 0 ? boundary_angle[v] < 0.75 * CGAL_PI : boundary_angle[v] > 1.25 * CGAL_PI);
  };
  // interior vertices closer than minimum_boundary_distance to the boundary (along edges): a
  // cone there only when no other vertex of the sign needed is left (its grid point would be
  // rounded onto the boundary's grid line, or across it)
  std::vector<char> near_boundary(nv, 0);
  if(boundary_distance > 0) {
    typedef std::pair<double, std::size_t> Item;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    std::vector<double> dist(nv, std::numeric_limits<double>::infinity());
    for(std::size_t v = 0; v < nv; ++v) if(m.is_boundary_vertex(int(v))) { dist[v] = 0; queue.emplace(0., v); }
    while(!queue.empty()) {
      const Item it = queue.top();
      queue.pop();
      if(it.first > dist[it.second]) continue;
      near_boundary[it.second] = !m.is_boundary_vertex(int(it.second));
      for(int h = m.vertex_out[it.second], h0 = h;;) {
        const std::size_t w = std::size_t(m.target[std::size_t(h)]);
        const double dw = it.first + m.length[std::size_t(h >> 1)];
        if(dw < boundary_distance && dw < dist[w]) { dist[w] = dw; queue.emplace(dw, w); }
        if(m.face[std::size_t(h)] < 0) break;
        h = m.ccw_out(h);
        if(h == h0) break;
      }
    }
  }
  long ksum = 0;
  auto step = [&](const std::vector<double>& u, int s) {
    // s = 0: either sign, by the farthest vertex's side of the mean
    const double mean = greedy.mean(u);
    std::size_t best = nv;
    for(int pass = 0; pass < 2 && best == nv; ++pass) {
      double best_d = 0;
      for(std::size_t v = 0; v < nv; ++v) {
        const double d = u[v] - mean;
        const int sv = s != 0 ? s : (d > 0 ? 1 : -1);
        if(d * sv <= 0 || near_cone[v] || (pass == 0 && (crowded[v] || near_boundary[v])) || !corner_fits(v, sv)) continue;   // one quantum per cone, none adjacent
        if(std::abs(d) > best_d) { best = v; best_d = std::abs(d); }
      }
    }
    if(best == nv) return false;
    st.crowded_cones += crowded[best];
    const int sv = s != 0 ? s : (u[best] > mean ? 1 : -1);
    // a negative cone takes as many quanta as the total still needs, up to the limit
    const int quanta = sv < 0 ? int((std::max)(1L, (std::min)(long(st.negative_cone_quanta), ksum - target_k))) : 1;
    k[best] += sv * quanta;
    ksum += sv * quanta;
    // no cone next to another: a grid needs room between them
    near_cone[best] = 1;
    for(int h = m.vertex_out[best], h0 = h;;) {
      near_cone[std::size_t(m.target[std::size_t(h)])] = 1;
      if(m.face[std::size_t(h)] < 0) break;   // a boundary vertex's fan ends at the border
      h = m.ccw_out(h);
      if(h == h0) break;
    }
    if(min_distance > 0) crowd(best);
    return true;
  };
  auto cone_count = [&] { std::size_t c = 0; for(int x : k) c += x != 0; return c; };
  // the vertices the spread leaves out: the cones' neighbourhoods, within minimum_cone_distance
  // when it is given (a peak there can take no cone of its own: counting it made the placement
  // add cones elsewhere up to the maximum, 80 -> 500 on homer at 2 quad sides), the same near
  // the boundary and on its straight or smooth stretches (500 cones on the alex and the beetle)
  std::vector<char> unmeasured;
  auto left_out = [&]() -> const std::vector<char>& {
    unmeasured = near_cone;
    for(std::size_t v = 0; v < nv; ++v)
      unmeasured[v] = unmeasured[v] || crowded[v] || near_boundary[v] || (!corner_fits(v, 1) && !corner_fits(v, -1));
    return unmeasured;
  };
  auto vertex_map = get(CGAL::dynamic_vertex_property_t<double>(), tm);
  auto u_map = choose_parameter(get_parameter(np, internal_np::conformal_factor), get(CGAL::dynamic_vertex_property_t<double>(), tm));
  auto input_length = get(CGAL::dynamic_edge_property_t<double>(), tm);
  for(std::size_t e = 0; e < m.number_of_edges(); ++e) put(input_length, m.edges[e], m.length[e]);
  const int max_rounds = 6, max_steps = 4 * max_cones;
  bool capped = false;
  int steps = 0;
  double linear_bound = bound;
  for(int round = 0; round < max_rounds; ++round) {
    st.placement_rounds = round + 1;
    for(;;) {
      const std::vector<double> u = greedy.scale(k, q, total);
      st.linear_scale_spread = internal::spread(u, left_out());
      const bool within = capped || st.linear_scale_spread <= linear_bound;
      if(within && ksum == target_k) break;
      if(!capped && (int(cone_count()) >= max_cones || steps >= max_steps)) { capped = true; continue; }
      ++steps;
      // the sign: within the bound (or out of cones) only what the total still needs; otherwise
      // that too, unless the other side of the mean is more than 1.5 times as far (measured on
      // the shared meshes: fewer cones than the farthest vertex alone, which adds +- pairs)
      const int need = ksum < target_k ? 1 : ksum > target_k ? -1 : 0;
      int sign = need;
      if(!within) {
        const double mean = greedy.mean(u);
        double above = 0, below = 0;
        for(std::size_t v = 0; v < nv; ++v)
          if(!unmeasured[v]) { above = (std::max)(above, u[v] - mean); below = (std::max)(below, mean - u[v]); }
        if((need > 0 && below > 1.5 * above) || (need < 0 && above > 1.5 * below)) sign = 0;
      }
      if(!step(u, sign)) {
        if(within) {
          st.message = "no vertex is left for a cone of curvature " + std::string(ksum < target_k ? "" : "-") + "2pi/" + std::to_string(N) +
                       " (the cones must not be adjacent and sum to 2 pi chi = " + std::to_string(total) + ")";
          return st;
        }
        capped = true;
      }
    }
    st.greedy_steps = steps;
    st.cones.clear();
    for(std::size_t v = 0; v < nv; ++v) {
      put(vertex_map, m.vertices[v], k[v] * q);
      if(k[v] != 0) st.cones.emplace_back(m.vertices[v], k[v] * q);
    }
    // the read-back: the flat cone metric with these cones, and its spread
    st.metric = compute_cone_metric(tm, vertex_map, output_lengths,
                                    parameters::edge_length_map(input_length).conformal_factor_map(u_map));
    if(!st.metric.converged) {
      st.message = "the flat cone metric with the placed cones did not converge: " + st.metric.message;
      return st;
    }
    std::vector<double> uu(nv);
    for(std::size_t v = 0; v < nv; ++v) uu[v] = get(u_map, m.vertices[v]);
    st.scale_spread = internal::spread(uu, left_out());
    if(st.scale_spread <= bound && int(st.cones.size()) <= max_cones) { st.success = true; st.message.clear(); return st; }
    if(capped) break;
    // the linear model missed: tighten its bound by the ratio missed
    linear_bound *= 0.98 * bound / st.scale_spread;
  }
  if(int(st.cones.size()) > max_cones)
    st.message = std::to_string(st.cones.size()) + " cones, more than maximum_number_of_cones = " + std::to_string(max_cones) +
                 " (the cones must sum to 2 pi chi = " + std::to_string(total) + "); their metric stretches lengths by up to e^" +
                 std::to_string(st.scale_spread);
  else
    st.message = "the flat cone metric with " + std::to_string(st.cones.size()) + " cones stretches lengths by up to e^" +
                 std::to_string(st.scale_spread) + ", more than the bound e^" + std::to_string(bound) +
                 (capped ? " (maximum_number_of_cones reached)" : " after " + std::to_string(st.placement_rounds) + " rounds");
  return st;
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_REMESHING_CONES_H
