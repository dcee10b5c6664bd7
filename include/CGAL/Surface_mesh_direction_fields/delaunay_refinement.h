// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_DELAUNAY_REFINEMENT_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_DELAUNAY_REFINEMENT_H

// A refinement of a triangle mesh that keeps its surface and makes every edge Delaunay: new
// vertices only on the input's edges, each input triangle re-triangulated inside itself. A
// metric that the input triangulation cannot carry without intrinsic flips (compute_cone_metric())
// often lives on this refinement, which is a triangulation of the same surface: a remesh pulled
// back through it lies on the input surface (regular remeshing, Lai et al. 2010, section 5).

#include <CGAL/Surface_mesh_direction_fields/Intrinsic_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/parameters.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// Outcome of conforming_delaunay_refinement(), with the correspondence of the refinement to
/// the input mesh.
struct Delaunay_refinement_status
{
  /// every interior edge of the output is locally Delaunay: the two angles opposite it sum to
  /// at most \f$\pi\f$ (read back from the output's lengths)
  bool success = false;
  std::string message;                 ///< empty on success
  std::size_t vertices = 0, faces = 0; ///< of the output
  /// the vertices added, in the order of creation after the input's vertices: vertex
  /// `n + k` of the output (`n` the number of input vertices) lies on the input edge of index
  /// `inserted[k].first` at parameter `inserted[k].second` in (0, 1) from the source of its
  /// halfedge `halfedge(e, tm)`
  std::vector<std::pair<std::size_t, double>> inserted;
  /// per output face, in the order of creation: the index of the input face that contains it
  std::vector<std::size_t> face_origin;
  /// the largest sum of the two angles opposite an interior edge of the output, in radians
  double max_opposite_angle_sum = 0;
  std::size_t non_delaunay_edges = 0;  ///< interior edges of the output whose sum exceeds \f$\pi + 10^{-9}\f$
};

namespace internal {

// The per-face state of the refinement: the layout of an input triangle in the plane (from its
// lengths), and the points of the refinement on its three edges.
template <typename TriangleMesh>
struct Delaunay_refiner
{
  const Mesh_arrays<TriangleMesh>& m;
  std::vector<std::vector<double>> inner;   // per edge: sorted parameters in (0, 1) from source(2e)
  mutable std::size_t tests = 0;            // points tested by apex_cot(), the refinement's work
  explicit Delaunay_refiner(const Mesh_arrays<TriangleMesh>& arrays) : m(arrays), inner(arrays.number_of_edges()) {}

  struct P2 { double x, y; };
  static double dot(P2 a, P2 b, P2 c) { return (a.x - c.x) * (b.x - c.x) + (a.y - c.y) * (b.y - c.y); }     // (a-c).(b-c)
  static double orient(P2 a, P2 b, P2 c) { return (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y); }

  // corners of face f, in the order of its halfedges from face_halfedge (corner k = source(h_k)):
  // canonical_layout() by the law of cosines, recomputed per test (its trigonometry, or a cache
  // of it, made the refinement 1.5-1.8x slower: 100k faces 110 -> 180-190 ms)
  void layout(int f, std::array<int, 3>& h, std::array<P2, 3>& c) const
  {
    h[0] = m.face_halfedge[std::size_t(f)];
    h[1] = m.next[std::size_t(h[0])];
    h[2] = m.next[std::size_t(h[1])];
    const double a = m.edge_length(h[0]), b = m.edge_length(h[1]), d = m.edge_length(h[2]);
    const double x = (a * a + d * d - b * b) / (2 * a);
    c[0] = {0, 0};
    c[1] = {a, 0};
    c[2] = {x, std::sqrt((std::max)(0., d * d - x * x))};
  }
  // parameter along halfedge h of the i-th inner point of its edge
  double along(int h, std::size_t i) const
  {
    const std::vector<double>& t = inner[std::size_t(h >> 1)];
    return (h & 1) ? 1 - t[t.size() - 1 - i] : t[i];
  }
  // the boundary of face f, counterclockwise: corners and inner points, with vertex numbers
  // (input vertex, or first_inner[e] + i), and for each the halfedge slot k (0..2) it starts
  // and its parameter along h_k
  void boundary(int f, const std::vector<std::size_t>& first_inner, std::vector<P2>& p, std::vector<std::size_t>& id,
                std::vector<int>& slot, std::vector<double>& param, std::array<int, 3>& h) const
  {
    std::array<P2, 3> c;
    layout(f, h, c);
    p.clear();
    id.clear();
    slot.clear();
    param.clear();
    for(int k = 0; k < 3; ++k) {
      const P2 a = c[std::size_t(k)], b = c[std::size_t((k + 1) % 3)];
      p.push_back(a);
      id.push_back(std::size_t(m.source(h[std::size_t(k)])));
      slot.push_back(k);
      param.push_back(0);
      const std::size_t e = std::size_t(h[std::size_t(k)] >> 1), n = inner[e].size();
      for(std::size_t i = 0; i < n; ++i) {
        const double s = along(h[std::size_t(k)], i);
        p.push_back({a.x + s * (b.x - a.x), a.y + s * (b.y - a.y)});
        id.push_back(first_inner[e] + ((h[std::size_t(k)] & 1) ? n - 1 - i : i));
        slot.push_back(k);
        param.push_back(s);
      }
    }
  }
  // The cotangent of the angle under which the apex of a sub-segment of edge e (parameters
  // t0 < t1) sees it in the face of halfedge h (h >> 1 == e): the apex is the point of that
  // face (the opposite corner, the inner points of the two other edges) that sees it under the
  // largest angle, the third corner of its triangle in the face's Delaunay triangulation (a
  // sub-segment is on the convex hull of the face's points, so it is an edge of that
  // triangulation). `foot` receives the relative position in [0, 1], in the edge's direction,
  // of the apex's foot on it.
  double apex_cot(int h, double t0, double t1, double& foot) const
  {
    std::array<int, 3> hs;
    std::array<P2, 3> c;
    const int f = m.face[std::size_t(h)];
    layout(f, hs, c);
    int k = 0;
    while(hs[std::size_t(k)] != h) ++k;
    const P2 a = c[std::size_t(k)], b = c[std::size_t((k + 1) % 3)];
    const double s0 = (h & 1) ? 1 - t1 : t0, s1 = (h & 1) ? 1 - t0 : t1;
    const P2 p{a.x + s0 * (b.x - a.x), a.y + s0 * (b.y - a.y)}, q{a.x + s1 * (b.x - a.x), a.y + s1 * (b.y - a.y)};
    double best = HUGE_VAL;
    auto test = [&](P2 x) {
      ++tests;   // the points of the face lie to the left of p -> q
      const double o = orient(p, q, x);
      if(!(o > 0)) return;
      const double cot = dot(p, q, x) / o;   // cotangents: no trigonometry in the inner loop
      if(cot >= best) return;
      best = cot;
      const double pq = dot(p, p, q);
      double u = ((x.x - p.x) * (q.x - p.x) + (x.y - p.y) * (q.y - p.y)) / pq;
      if(h & 1) u = 1 - u;
      foot = (std::min)(1., (std::max)(0., u));
    };
    test(c[std::size_t((k + 2) % 3)]);
    for(int j = 1; j <= 2; ++j) {
      const int g = hs[std::size_t((k + j) % 3)];
      const P2 u = c[std::size_t((k + j) % 3)], w = c[std::size_t((k + j + 1) % 3)];
      for(std::size_t i = 0; i < inner[std::size_t(g >> 1)].size(); ++i) {
        const double s = along(g, i);
        test(P2{u.x + s * (w.x - u.x), u.y + s * (w.y - u.y)});
      }
    }
    return best;
  }
};

} // namespace internal

namespace internal {

// Steps 2 and 3 of a refinement: the output mesh from the points r.inner on the input's edges,
// each input triangle the Delaunay triangulation of its points; fills the status (vertices,
// faces, inserted, face_origin, the Delaunay statistics) and returns false with its message
// when a face cannot be added.
template <typename TriangleMesh, typename PolygonMesh, typename NamedParameters, typename NamedParametersOut>
bool write_refinement(const TriangleMesh& tm, const Mesh_arrays<TriangleMesh>& m, const Delaunay_refiner<TriangleMesh>& r,
                      PolygonMesh& out, const NamedParameters& np, const NamedParametersOut& np_out, Delaunay_refinement_status& st)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef Delaunay_refiner<TriangleMesh> Refiner;
  typedef typename Refiner::P2 P2;
  typedef boost::graph_traits<PolygonMesh> OGT;
  const std::size_t nv = m.number_of_vertices(), ne = m.number_of_edges(), nf = m.number_of_faces();
  // 2. the output's vertices: the input's, then the inner points edge by edge
  std::vector<std::size_t> first_inner(ne);
  std::size_t n_out = nv;
  for(std::size_t e = 0; e < ne; ++e) {
    first_inner[e] = n_out;
    for(double t : r.inner[e]) st.inserted.emplace_back(e, t);
    n_out += r.inner[e].size();
  }
  typedef typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
  const VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  typedef typename CGAL::GetVertexPointMap<PolygonMesh, NamedParametersOut>::type OVPM;
  OVPM opm = choose_parameter(get_parameter(np_out, CGAL::internal_np::vertex_point), get_property_map(CGAL::vertex_point, out));
  typedef typename boost::property_traits<OVPM>::value_type Out_point;
  auto point3 = [&](std::size_t v) {
    const auto& p = get(vpm, m.vertices[v]);
    return std::array<double, 3>{{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
  };
  std::vector<typename OGT::vertex_descriptor> ov(n_out);
  for(std::size_t v = 0; v < n_out; ++v) {
    std::array<double, 3> x;
    if(v < nv) x = point3(v);
    else {
      const std::pair<std::size_t, double>& in = st.inserted[v - nv];
      const std::array<double, 3> a = point3(std::size_t(m.source(int(2 * in.first)))), b = point3(std::size_t(m.target[2 * in.first]));
      for(int j = 0; j < 3; ++j) x[std::size_t(j)] = a[std::size_t(j)] + in.second * (b[std::size_t(j)] - a[std::size_t(j)]);
    }
    ov[v] = add_vertex(out);
    put(opm, ov[v], Out_point(x[0], x[1], x[2]));
  }

  // 3. each input face: the Delaunay triangulation of its boundary points (a convex polygon):
  // the triangle on chord (i, j) takes the point between them that sees it under the largest
  // angle (smallest cotangent). The angles opposite each edge are summed on the way: a chord's
  // two triangles are made one after the other, a sub-segment's in the two input faces.
  std::vector<std::size_t> seg_base(ne + 1, 0);   // sub-segment j of edge e: seg_base[e] + j
  for(std::size_t e = 0; e < ne; ++e) seg_base[e + 1] = seg_base[e] + r.inner[e].size() + 1;
  std::vector<double> seg_angle(seg_base[ne], 0.);
  std::vector<P2> p;
  std::vector<std::size_t> id;
  std::vector<int> slot;
  std::vector<double> param;
  std::array<int, 3> fh;
  struct Chord { std::size_t i, j; double angle; };   // angle: opposite it in the triangle made first (-1 for the root)
  std::vector<Chord> chords;
  constexpr bool has_lengths = !parameters::is_default_parameter<NamedParametersOut, internal_np::edge_length_t>::value;
  for(std::size_t f = 0; f < nf; ++f) {
    r.boundary(int(f), first_inner, p, id, slot, param, fh);
    const std::size_t n = p.size();
    std::array<std::size_t, 3> corner{{0, 0, 0}};   // the index of each corner among the points
    for(std::size_t a = n; a-- > 0;) corner[std::size_t(slot[a])] = a;
    // boundary sub-segment from point a to point a + 1 (mod n): its index among all sub-segments
    auto segment = [&](std::size_t a) {
      const int h = fh[std::size_t(slot[a])];
      const std::size_t e = std::size_t(h >> 1), nsub = r.inner[e].size() + 1, j = a - corner[std::size_t(slot[a])];
      return seg_base[e] + ((h & 1) ? nsub - 1 - j : j);
    };
    auto angle_at = [&](std::size_t a, std::size_t b, std::size_t c) {   // at c, opposite (a, b)
      return std::atan2(std::abs(Refiner::orient(p[a], p[b], p[c])), Refiner::dot(p[a], p[b], p[c]));
    };
    chords.assign(1, Chord{0, n - 1, -1.});
    while(!chords.empty()) {
      const Chord c = chords.back();
      chords.pop_back();
      if(c.j - c.i < 2) { seg_angle[segment(c.i)] += c.angle; continue; }   // a side of the polygon
      std::size_t best = c.i + 1;
      double best_cot = HUGE_VAL;
      for(std::size_t k = c.i + 1; k < c.j; ++k) {
        const double o = Refiner::orient(p[c.i], p[k], p[c.j]);
        if(!(o > 0)) continue;   // on the chord's line (a point of the same input edge)
        const double cot = Refiner::dot(p[c.i], p[c.j], p[k]) / o;
        if(cot < best_cot) { best_cot = cot; best = k; }
      }
      const double opposite = angle_at(c.i, c.j, best);
      if(c.angle < 0) seg_angle[segment(n - 1)] += opposite;   // the root: the side from n - 1 to 0
      else {
        st.max_opposite_angle_sum = (std::max)(st.max_opposite_angle_sum, c.angle + opposite);
        if(c.angle + opposite > CGAL_PI + 1e-9) ++st.non_delaunay_edges;
      }
      chords.push_back(Chord{c.i, best, angle_at(c.i, best, c.j)});
      chords.push_back(Chord{best, c.j, angle_at(best, c.j, c.i)});
      const std::array<std::size_t, 3> tr{{c.i, best, c.j}};
      std::vector<typename OGT::vertex_descriptor> vs{ov[id[tr[0]]], ov[id[tr[1]]], ov[id[tr[2]]]};
      const typename OGT::face_descriptor of = CGAL::Euler::add_face(vs, out);
      if(of == OGT::null_face()) {
        st.message = "the refinement of face " + std::to_string(f) + " is not manifold (degenerate input face?)";
        return false;
      }
      st.face_origin.push_back(f);
      if constexpr(has_lengths) {
        auto olm = get_parameter(np_out, internal_np::edge_length);
        for(typename OGT::halfedge_descriptor oh : CGAL::halfedges_around_face(halfedge(of, out), out)) {
          int k = 0;
          while(vs[std::size_t(k)] != source(oh, out)) ++k;
          const std::size_t a = tr[std::size_t(k)], b = tr[std::size_t((k + 1) % 3)];
          // along an input edge: its length times the span (the same from both sides)
          const double l = b == (a + 1) % n ? m.edge_length(fh[std::size_t(slot[a])]) * ((slot[b] == slot[a] ? param[b] : 1.) - param[a])
                                            : std::hypot(p[b].x - p[a].x, p[b].y - p[a].y);
          put(olm, edge(oh, out), l);
        }
      }
    }
  }
  for(std::size_t e = 0; e < ne; ++e)
    if(!m.is_border_edge(int(e)))
      for(std::size_t j = seg_base[e]; j < seg_base[e + 1]; ++j) {
        st.max_opposite_angle_sum = (std::max)(st.max_opposite_angle_sum, seg_angle[j]);
        if(seg_angle[j] > CGAL_PI + 1e-9) ++st.non_delaunay_edges;
      }
  st.vertices = num_vertices(out);
  st.faces = num_faces(out);
  return true;
}

} // namespace internal

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// Refines `tm` into `out`, a triangulation of the same surface in which every edge is locally
/// Delaunay, by adding vertices on the edges of `tm` only (a conforming Delaunay refinement).
///
/// Each input triangle, with the points of the refinement on its edges, is triangulated by the
/// Delaunay triangulation of these points (a convex polygon, whose sides, the sub-segments of
/// the input edges, are therefore edges of it); edges inside a triangle are then Delaunay. An
/// input edge is split until each of its sub-segments is Delaunay too: the two apexes (the
/// points of the two adjacent triangles that see it under the largest angle) see it under at
/// most \f$\pi\f$ together. A sub-segment is split at the foot of the wider apex, kept within
/// its middle 60 %; one at an input vertex at a power of two of its length from that vertex
/// (Ruppert's concentric shells), which keeps small input angles from splitting without end.
///
/// Use: `compute_cone_metric()` without intrinsic flips needs a triangulation that stays valid
/// under the target metric; a Delaunay one usually does (e.g. Cheburashka with eight cones of
/// \f$\pi/2\f$: no convergence on the 13,334 input faces, converged on their 23,196-face
/// refinement). Every output face lies inside one input face (`face_origin`), so a remesh pulled
/// back through `out` lies on the input surface.
///
/// `out` must be empty (its property maps may exist already, e.g. those of `np_out`). The
/// input vertices become the first output vertices, in the order of `vertex_index_map`;
/// the others are listed in the status. Throws `Input_error` for the invalid inputs of
/// `Intrinsic_mesh`.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{edge_length_map}
///     \cgalParamDescription{the metric whose Delaunay property is wanted}
///     \cgalParamDefault{Euclidean lengths from `vertex_point_map`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the positions of `tm`'s vertices; the new vertices are placed by linear interpolation along the input edges}
///     \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{the largest number of vertices to add; beyond it, beyond 1024 on one
///       input edge (next to a needle triangle), or beyond \f$4096 F + 10^8\f$ points tested for
///       the Delaunay property (\f$F\f$ input faces; 60 to 310 per face on ordinary meshes), the
///       status fails with a message}
///     \cgalParamDefault{64 times the number of faces, plus 4096}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map, edge_index_map, face_index_map}
///     \cgalParamDescription{as for `Intrinsic_mesh`: the numbers used in the status}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// `np_out`: `edge_length_map`, a writable property map of `out`'s edges that receives the
/// refinement's lengths in the metric (along an input edge its length times the parameter
/// span, inside an input triangle the distance in its layout);
/// `vertex_point_map` of `out`.
/// \tparam PolygonMesh a model of `MutableFaceGraph` whose vertex points are constructible from
/// three doubles
template <typename TriangleMesh, typename PolygonMesh, typename NamedParameters = parameters::Default_named_parameters,
          typename NamedParametersOut = parameters::Default_named_parameters>
Delaunay_refinement_status conforming_delaunay_refinement(const TriangleMesh& tm, PolygonMesh& out,
                                                          const NamedParameters& np = parameters::default_values(),
                                                          const NamedParametersOut& np_out = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const Intrinsic_mesh<TriangleMesh> im(tm, np);
  const internal::Mesh_arrays<TriangleMesh>& m = im.arrays();
  const std::size_t ne = m.number_of_edges(), nf = m.number_of_faces();
  const std::size_t budget = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 64 * nf + 4096);
  Delaunay_refinement_status st;
  if(!CGAL::is_empty(out))   // not cleared: that would remove the property maps of np_out
    throw Input_error(Input_error::INVALID_ARGUMENT, "conforming_delaunay_refinement: the output mesh must be empty");
  internal::Delaunay_refiner<TriangleMesh> r(m);

  // 1. split the sub-segments that are not Delaunay, edge by edge, until none is left
  std::vector<int> work;
  std::vector<char> queued(ne, 1);
  for(std::size_t e = ne; e-- > 0;) work.push_back(int(e));
  std::size_t added = 0;
  while(!work.empty()) {
    const int e = work.back();
    work.pop_back();
    queued[std::size_t(e)] = 0;
    std::vector<double>& t = r.inner[std::size_t(e)];
    const double L = m.length[std::size_t(e)];
    for(std::size_t i = 0; i <= t.size();) {
      const double t0 = i == 0 ? 0. : t[i - 1], t1 = i == t.size() ? 1. : t[i];
      // Delaunay across the input edge: the apexes on its two sides see it under at most pi
      if(m.is_border_edge(e)) break;
      double foot0 = 0, foot1 = 0;
      const double c0 = r.apex_cot(2 * e, t0, t1, foot0), c1 = r.apex_cot(2 * e + 1, t0, t1, foot1);
      if(c0 + c1 >= -1e-12) { ++i; continue; }   // angles summing to at most pi
      const double foot = c0 <= c1 ? foot0 : foot1;
      // at the foot of the wider apex (kept off the ends): fewer splits than the middle
      double s = t0 + (t1 - t0) * (std::min)(0.8, (std::max)(0.2, foot));
      if((i == 0) != (i == t.size())) {
        // one end is an input vertex: split at a power of two from it (points at equal
        // distances on two edges never encroach each other)
        const double d = std::exp2(std::round(std::log2((t1 - t0) * L / 2))) / L;
        s = i == 0 ? d : 1 - d;
      }
      // A needle (angle theta) takes about 1/theta points along its long sides, and each test
      // scans the points of a face: 1024 per edge bounds that (quadratic) work, and a cap on the
      // points tested the sum of it (60 to 310 per input face on the shared and benchmark meshes).
      const bool too_much_work = r.tests > 4096 * nf + 100000000;
      if(!(s > t0 && s < t1) || (t1 - t0) < 1e-13 || t.size() >= 1024 || ++added > budget || too_much_work) {
        std::ostringstream os;
        if(added > budget) os << "more than " << budget << " vertices needed (number_of_iterations)";
        else if(too_much_work) os << "more than " << r.tests << " point tests needed (many needle triangles?)";
        else {
          double smallest = CGAL_PI;
          for(int side = 0; side < 2; ++side)
            for(int g = 2 * e + side, k = 0; k < 3; ++k, g = m.next[std::size_t(g)]) smallest = (std::min)(smallest, m.angle[std::size_t(g)]);
          os << "edge " << e << " needs more than " << (t.size() >= 1024 ? "1024 points" : "splits below 1e-13 of its length")
             << ": its triangles are too thin (smallest angle " << smallest * 180 / CGAL_PI << " degrees)";
        }
        st.message = os.str();
        return st;
      }
      t.insert(t.begin() + std::ptrdiff_t(i), s);   // sub-segment i is now (t0, s): check it again
      for(int side = 0; side < 2; ++side) {
        const int h = 2 * e + side;
        if(m.face[std::size_t(h)] < 0) continue;
        for(int g : {m.next[std::size_t(h)], m.prev(h)})
          if(!queued[std::size_t(g >> 1)]) { queued[std::size_t(g >> 1)] = 1; work.push_back(g >> 1); }
      }
    }
  }

  if(!internal::write_refinement(tm, m, r, out, np, np_out, st)) return st;
  st.success = st.non_delaunay_edges == 0;
  if(!st.success)
    st.message = std::to_string(st.non_delaunay_edges) + " edges are not Delaunay (largest opposite angle sum " +
                 std::to_string(st.max_opposite_angle_sum) + " rad)";
  return st;
}

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// Refines `tm` into `out` by vertices at given points of its edges, each input triangle
/// re-triangulated inside itself by the Delaunay triangulation (in the metric) of its corners
/// and of the points on its sides. `out` is a triangulation of the same surface, e.g. `tm` with
/// border edges split where a flat cone metric with a geodesic boundary needs a vertex (a cone
/// next to the boundary: see `smdf rosy`), and transfer_face_field_from_refinement() brings a
/// face field on `out` back to `tm`.
///
/// `points` lists (edge index in `edge_index_map`, parameter in (0, 1) from the source of
/// `halfedge(e, tm)`); repeated points are added once. The status is conforming_delaunay_refinement()'s:
/// `inserted` (the points in the order of their vertices, after the input's), `face_origin`, and
/// the largest angle sum opposite an input edge's piece; `success` says that `out` was built (the
/// refinement need not be Delaunay). Named parameters: `edge_length_map`, `vertex_point_map` and
/// the index maps (input); `np_out` as for conforming_delaunay_refinement(). Throws
/// `Input_error` for a parameter outside (0, 1), an edge index out of range, a non-empty `out`
/// and the invalid inputs of `Intrinsic_mesh`.
template <typename TriangleMesh, typename PolygonMesh, typename NamedParameters = parameters::Default_named_parameters,
          typename NamedParametersOut = parameters::Default_named_parameters>
Delaunay_refinement_status refine_at_edge_points(const TriangleMesh& tm, const std::vector<std::pair<std::size_t, double>>& points,
                                                 PolygonMesh& out, const NamedParameters& np = parameters::default_values(),
                                                 const NamedParametersOut& np_out = parameters::default_values())
{
  const Intrinsic_mesh<TriangleMesh> im(tm, np);
  const internal::Mesh_arrays<TriangleMesh>& m = im.arrays();
  if(!CGAL::is_empty(out))
    throw Input_error(Input_error::INVALID_ARGUMENT, "refine_at_edge_points: the output mesh must be empty");
  internal::Delaunay_refiner<TriangleMesh> r(m);
  for(const std::pair<std::size_t, double>& p : points) {
    if(p.first >= m.number_of_edges() || !(p.second > 0 && p.second < 1))
      throw Input_error(Input_error::INVALID_ARGUMENT, "refine_at_edge_points: point (" + std::to_string(p.first) + ", " +
                                                           std::to_string(p.second) + ") is not inside an edge of the mesh (" +
                                                           std::to_string(m.number_of_edges()) + " edges, parameters in (0, 1))");
    r.inner[p.first].push_back(p.second);
  }
  for(std::vector<double>& t : r.inner) {
    std::sort(t.begin(), t.end());
    t.erase(std::unique(t.begin(), t.end()), t.end());
  }
  Delaunay_refinement_status st;
  st.success = internal::write_refinement(tm, m, r, out, np, np_out, st);
  return st;
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_DELAUNAY_REFINEMENT_H
