// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_GRID_TESSELLATION_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_GRID_TESSELLATION_H

// Regular remeshing (Lai et al. 2010, section 5): the square or triangular grid of the plane,
// carried onto the surface by the development of a flat cone metric whose holonomy lies in
// the grid's symmetry group. The grid points become the output vertices (placed on the input
// triangles by barycentric coordinates), the grid's unit squares or triangles its faces.

#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/flat_development.h>
#include <CGAL/Surface_mesh_direction_fields/holonomy_group.h>
#include <CGAL/Surface_mesh_direction_fields/Intrinsic_triangulation.h>
#include <CGAL/Surface_mesh_direction_fields/internal/inversion.h>
#include <CGAL/Surface_mesh_direction_fields/internal/two_threads.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// Outcome of tessellate_flat_metric().
struct Grid_tessellation_status
{
  bool success = false;   ///< the output is a valid mesh whose irregular vertices are the cones
  std::string message;    ///< empty on success
  /// the holonomy test of the cut graph's motions (Theorem 3.5) for the grid of the requested
  /// edge length (tessellation_compatibility_at()), from which the grid's orientation and origin
  /// come; when it fails, the coarsest lattice's test (tessellation_compatibility()), whose
  /// `spacing` is then the metric's own: the edge length must divide it
  Tessellation_compatibility compatibility;
  /// edges of the cut graph (indices of the input's index map) whose motion is not a symmetry
  /// of the grid, and on open meshes the boundary edge ending at every boundary corner (geodesic
  /// curvature not 0) that is no grid point
  std::vector<std::size_t> failing_edges;
  /// per failing edge: how far its motion's rotation is from the grid's (radians) and its
  /// translation from the lattice (in units of `compatibility.spacing`)
  std::vector<double> failing_rotation_deviations, failing_translation_deviations;
  double edge_length = 0;              ///< the grid's edge length on the surface
  std::size_t vertices = 0, faces = 0; ///< of the output
  /// of the output, which success requires to be the input's: its Euler characteristic and its
  /// number of boundary loops
  long euler_characteristic = 0;
  std::size_t boundary_loops = 0;
  /// valence histogram of the output's interior vertices: `valences[k]` vertices of valence k
  std::vector<std::size_t> valences;
  /// output vertices of irregular valence, each with the input cone it lies on (-1 if none)
  std::vector<std::pair<std::size_t, long>> irregular_vertices;
  /// per output vertex (in the order of `vertices(out)`), where it lies on `tm`: the face (index
  /// in `faces(tm)` order) and the barycentric coordinates of its corners `source(halfedge(f))`,
  /// `target(halfedge(f))`, `target(next(halfedge(f)))`. When `tm` is a copy of an
  /// `Intrinsic_triangulation`, place_tessellation_on_input() moves the output onto the input
  /// surface with them.
  std::vector<Surface_point> vertex_locations;
  /// output faces whose area vector points against the input's normals under their corners
  /// (inverted in space: the metric stretches too much for the edge length), counted last, once
  /// every other check has passed; success needs none (untangle_remesh() can unfold them)
  std::size_t inverted_faces = 0;
};

namespace internal {

// An integer-exact affine map of lattice coordinates: p -> R p + t, R a rotation of the grid
// (entries in {-1, 0, 1}), t integer. Applied to coordinates that are multiples of 2^-30 below
// 2^21 in magnitude it is exact in double precision.
struct Lattice_motion
{
  int r[4] = {1, 0, 0, 1};
  double t[2] = {0, 0};
  Point_2 operator()(const Point_2& p) const
  {
    return Point_2(r[0] * p.x() + r[1] * p.y() + t[0], r[2] * p.x() + r[3] * p.y() + t[1]);
  }
  std::array<double, 2> rotate(double x, double y) const { return {{r[0] * x + r[1] * y, r[2] * x + r[3] * y}}; }
  Lattice_motion inverse() const
  {
    Lattice_motion m;   // R is orthogonal in the square grid; in the triangular one det R = 1
    m.r[0] = r[3]; m.r[1] = -r[1]; m.r[2] = -r[2]; m.r[3] = r[0];
    m.t[0] = -(m.r[0] * t[0] + m.r[1] * t[1]);
    m.t[1] = -(m.r[2] * t[0] + m.r[3] * t[1]);
    return m;
  }
  friend Lattice_motion operator*(const Lattice_motion& a, const Lattice_motion& b)   // a after b
  {
    Lattice_motion c;
    c.r[0] = a.r[0] * b.r[0] + a.r[1] * b.r[2]; c.r[1] = a.r[0] * b.r[1] + a.r[1] * b.r[3];
    c.r[2] = a.r[2] * b.r[0] + a.r[3] * b.r[2]; c.r[3] = a.r[2] * b.r[1] + a.r[3] * b.r[3];
    const Point_2 t = a(Point_2(b.t[0], b.t[1]));
    c.t[0] = t.x(); c.t[1] = t.y();
    return c;
  }
};

inline double dyadic(double x) { return std::round(x * 1073741824.) / 1073741824.; }   // 2^30

} // namespace internal

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// Tessellates a developed flat cone metric with the square grid (quads) or the triangular grid
/// (triangles), Lai et al. 2010, section 5. Works for any genus and boundary as long as the
/// motions of the cut graph are symmetries of the grid (Theorem 3.5: rotations by multiples of
/// \f$\pi/2\f$ or \f$\pi/3\f$, translations in the lattice of edge length `edge_length`, placed at
/// the first cone) and every cone lies on a grid point; otherwise the status names the failing
/// edges. In the output, a cone of curvature \f$K\f$ becomes a vertex of valence
/// \f$4 - K/(\pi/2)\f$ (\f$6 - K/(\pi/3)\f$), every other interior vertex has valence 4 (6).
///
/// Exactness: the layout is converted to lattice coordinates, rounded to multiples of
/// \f$2^{-30}\f$, the motions rounded to exact lattice symmetries, and the corners of every vertex
/// re-derived from one of them through those motions, so that the layouts on both sides of every
/// seam are exact images of each other. Grid points are then classified against the triangles
/// with exact orientation predicates (`Exact_predicates_inexact_constructions_kernel`): a point
/// on a seam or at a vertex is found once, whichever side looks at it, and no face is lost or
/// doubled. Grid edges are followed across triangles and seams by a straight walk with the same
/// predicates. Output vertices are placed on the input triangle (edge, vertex) that contains them
/// by barycentric coordinates of the development, so every output vertex lies on the input
/// surface. The development must be of `tm`'s own triangulation (`develop_flat_metric()` with an
/// `edge_length_map` on `tm`).
///
/// Named parameters: `vertex_point_map` of `tm` (the positions of the output vertices' input
/// triangles). Returns the status. `out` is cleared; it receives the remesh when the faces could
/// be built, also when a read-back check then fails (inverted faces, valences), for inspection.
/// \tparam PolygonMesh a model of `MutableFaceGraph` whose vertex points are constructible from
/// three doubles
template <typename TriangleMesh, typename PolygonMesh, typename NamedParameters = parameters::Default_named_parameters>
Grid_tessellation_status tessellate_flat_metric(const TriangleMesh& tm, const Flat_development<TriangleMesh>& dev,
                                                Planar_tessellation grid, double edge_length, PolygonMesh& out,
                                                const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef CGAL::Exact_predicates_inexact_constructions_kernel EK;
  typedef EK::Point_2 EP;
  typedef boost::graph_traits<PolygonMesh> OGT;
  typedef typename OGT::vertex_descriptor out_vertex;
  const internal::Mesh_arrays<TriangleMesh>& m = dev.im_.arrays();
  const std::size_t nf = m.number_of_faces(), ne = m.number_of_edges(), nv = m.number_of_vertices();
  Grid_tessellation_status st;
  if(!(edge_length > 0) || !std::isfinite(edge_length))
    throw Input_error(Input_error::INVALID_ARGUMENT, "the grid's edge length must be positive, got " + std::to_string(edge_length));
  const bool square = grid == SQUARE_GRID;
  const int sides = square ? 4 : 3;
  const internal::Topology_arrays& topo = dev.im_.topology_arrays();
  if(topo.components.size() != 1)   // one frame per component: the holonomy test would mix them
    throw Input_error(Input_error::INVALID_ARGUMENT, "the mesh has " + std::to_string(topo.components.size()) +
                                                         " connected components; tessellate each one separately");

  // 1. the holonomy test on the cut graph's motions, in the one frame of the development
  Holonomy_group group;
  std::vector<std::size_t> group_edge;
  for(std::size_t e = 0; e < ne; ++e)
    if(dev.cut_[e]) {
      group.motions.push_back(dev.motions_[e]);
      const double r = dev.motions_[e].rotation;
      group.rotations.push_back(r < 0 ? r + 2 * CGAL_PI : r);
      group_edge.push_back(e);
    }
  auto corner_position = [&](int h) {   // source(h) as laid out in face(h)
    const int f = m.face[std::size_t(h)];
    int g = m.face_halfedge[std::size_t(f)], k = 0;
    while(g != h) { g = m.next[std::size_t(g)]; ++k; }
    return dev.corners_[std::size_t(f)][std::size_t(k)];
  };
  for(auto v : dev.cones_)   // a cone's position: any corner at it
    group.cone_positions.push_back(corner_position(m.vertex_out[std::size_t(m.vertex_index(v))]));
  // Open meshes: the boundary must run along grid lines. Its corners (boundary vertices whose
  // geodesic curvature is not 0, within the development's tolerance) must be grid points: each
  // enters the test as a pure translation from the grid's origin (the first cone, or else the
  // first corner) to it, reported as the corner's boundary edge if it fails. Between corners the
  // boundary is straight, and with corners at grid points and turning by the grid's angles it
  // follows the grid's lines.
  {
    const std::vector<double>& Kb = dev.im_.curvatures();
    std::vector<std::pair<Point_2, std::size_t>> corners;
    for(const auto& loop : topo.loops)
      for(int hb : loop) {
        const int v = m.target[std::size_t(hb)];
        if(!(std::abs(Kb[std::size_t(v)]) > 1e-6)) continue;
        corners.emplace_back(corner_position(hb ^ 1), std::size_t(hb >> 1));   // from v along the border edge, inside
      }
    if(!corners.empty()) {
      if(group.cone_positions.empty()) group.cone_positions.push_back(corners.front().first);
      const Point_2 o = group.cone_positions.front();
      for(const auto& c : corners) {
        Rigid_motion_2 t;
        t.rotation = 0;
        t.translation = Vector_2(c.first.x() - o.x(), c.first.y() - o.y());
        group.motions.push_back(t);
        group.rotations.push_back(0.);
        group_edge.push_back(c.second);
      }
    }
  }
  // The grid of this edge length first: only its orientation is searched, exactly at any size.
  const double h = edge_length;
  st.compatibility = tessellation_compatibility_at(group, grid, h, 1e-6);
  if(!st.compatibility.compatible) {
    // Why not: the motions are no symmetries of any grid, or h does not divide the metric's
    // lattice. The coarsest lattice, searched among vectors as long as the longest translation
    // (up to 128 edge lengths), tells which, and becomes the status's compatibility.
    const bool rotations_ok = st.compatibility.max_rotation_deviation <= 1e-6;   // the same test as the coarse one's
    double longest = 0;
    const Point_2 o = st.compatibility.origin;
    for(const Rigid_motion_2& r : group.motions) {
      const Point_2 q = r(o);
      longest = (std::max)(longest, std::sqrt((q.x() - o.x()) * (q.x() - o.x()) + (q.y() - o.y()) * (q.y() - o.y())));
    }
    const int reach = rotations_ok ? int((std::min)(std::ceil(longest / h) + 2, 128.)) : 1;
    const Tessellation_compatibility coarse = tessellation_compatibility(group, grid, 1e-6, (std::max)(8, reach));
    st.compatibility = coarse;
    std::ostringstream os;
    if(coarse.compatible) {
      const double spacing = coarse.spacing;
      os << "edge length " << h << " does not divide the lattice of the metric (spacing " << spacing
         << "): the edge length must be the spacing over the length of a lattice vector, e.g. " << spacing / 2 << ", "
         << spacing / 3 << ", " << spacing / 4 << (square ? " or spacing / sqrt(2), spacing / sqrt(5)" : " or spacing / sqrt(3), spacing / sqrt(7)");
    } else {
      os << coarse.failing_loops.size() << " edges of the cut graph glue the development by motions that are not symmetries of the "
         << (square ? "square" : "triangular") << " grid (rotation off by up to " << coarse.max_rotation_deviation
         << " rad, translation by " << coarse.max_translation_deviation << " grid edges); first edge "
         << (coarse.failing_loops.empty() ? 0 : group_edge[coarse.failing_loops.front()]);
    }
    for(std::size_t i : st.compatibility.failing_loops) st.failing_edges.push_back(group_edge[i]);
    st.failing_rotation_deviations = st.compatibility.failing_rotation_deviations;
    st.failing_translation_deviations = st.compatibility.failing_translation_deviations;
    st.message = os.str();
    return st;
  }
  const double orientation = st.compatibility.orientation;
  st.edge_length = h;
  // lattice coordinates: z = (p - origin) e^{-i orientation} / h in the basis (1, w)
  const double wx = square ? 0. : 0.5, wy = square ? 1. : std::sqrt(3.) / 2;
  const double co = std::cos(orientation), so = std::sin(orientation);
  const Point_2 origin = st.compatibility.origin;
  auto lattice = [&](const Point_2& p) {
    const double x = p.x() - origin.x(), y = p.y() - origin.y();
    const double zx = (co * x + so * y) / h, zy = (-so * x + co * y) / h;
    const double b = zy / wy;
    return Point_2(zx - b * wx, b);
  };
  // the grid's rotations in lattice coordinates: by pi/2 (square) or pi/3 (triangular)
  const internal::Lattice_motion step_rotation = [&] {
    internal::Lattice_motion r;
    if(square) { r.r[0] = 0; r.r[1] = -1; r.r[2] = 1; r.r[3] = 0; }
    else { r.r[0] = 0; r.r[1] = -1; r.r[2] = 1; r.r[3] = 1; }
    return r;
  }();
  const double step = square ? CGAL_PI / 2 : CGAL_PI / 3;

  // 2. exact layout: lattice coordinates on 2^-30 (2^-20 collapsed a feline triangle a millionth of a
  // grid unit wide; coordinates below 2^21 stay exact under the lattice motions), motions
  // rounded to lattice symmetries
  std::vector<std::array<Point_2, 3>> uv(nf);
  for(std::size_t f = 0; f < nf; ++f)
    for(int k = 0; k < 3; ++k) {
      const Point_2 p = lattice(dev.corners_[f][std::size_t(k)]);
      uv[f][std::size_t(k)] = Point_2(internal::dyadic(p.x()), internal::dyadic(p.y()));
    }
  auto corner_index = [&](int f, int v) {
    int g = m.face_halfedge[std::size_t(f)];
    for(int k = 0; k < 3; ++k, g = m.next[std::size_t(g)]) if(m.source(g) == v) return k;
    return -1;
  };
  std::vector<internal::Lattice_motion> motion(ne);   // from face(2e + 1) to face(2e), exact
  for(std::size_t e = 0; e < ne; ++e) {
    if(dev.tree_[e] || m.face[2 * e] < 0 || m.face[2 * e + 1] < 0) continue;
    const int turns = int(std::lround(dev.motions_[e].rotation / step));
    internal::Lattice_motion r;
    const int n_rot = square ? 4 : 6;
    for(int i = 0; i < ((turns % n_rot) + n_rot) % n_rot; ++i) r = step_rotation * r;
    const int fb = m.face[2 * e], fa = m.face[2 * e + 1], a = m.source(int(2 * e));
    const Point_2 pa = uv[std::size_t(fa)][std::size_t(corner_index(fa, a))], pb = uv[std::size_t(fb)][std::size_t(corner_index(fb, a))];
    const Point_2 ra = r(pa);
    r.t[0] = std::round(pb.x() - ra.x());
    r.t[1] = std::round(pb.y() - ra.y());
    motion[e] = r;
  }
  // per vertex: walk around it, deriving each face's corner from the previous one's
  for(std::size_t v = 0; v < nv; ++v) {
    if(m.is_isolated(int(v))) continue;
    const int h0 = m.vertex_out[v];   // boundary vertices: the boundary halfedge's face comes first
    int f0 = m.face[std::size_t(h0)];
    Point_2 p = uv[std::size_t(f0)][std::size_t(corner_index(f0, int(v)))];
    if(dev.cone_index_[v] >= 0) {
      const Point_2 snapped(std::round(p.x()), std::round(p.y()));
      if(std::abs(snapped.x() - p.x()) > 1e-5 || std::abs(snapped.y() - p.y()) > 1e-5) {
        std::ostringstream os;
        os << "cone " << v << " is not on a grid point (" << p.x() << ", " << p.y() << " in grid coordinates)";
        st.message = os.str();
        return st;
      }
      p = snapped;
    }
    int hh = h0;
    for(;;) {
      const int f = m.face[std::size_t(hh)];
      uv[std::size_t(f)][std::size_t(corner_index(f, int(v)))] = p;
      const int prev = m.next[std::size_t(m.next[std::size_t(hh)])];   // ends at v
      const int g = m.face[std::size_t(prev ^ 1)];
      if(g < 0) break;                                                // reached the boundary
      const int e = prev >> 1;
      if(!dev.tree_[std::size_t(e)]) p = (prev & 1) ? motion[std::size_t(e)](p) : motion[std::size_t(e)].inverse()(p);
      hh = prev ^ 1;
      if(hh == h0) {   // closed around v: the composed motions must give back the first corner
        const Point_2 q = uv[std::size_t(f0)][std::size_t(corner_index(f0, int(v)))];
        if(q != p) {
          std::ostringstream os;
          os << "the rounded motions do not close up around vertex " << v << " (is the metric flat there?)";
          st.message = os.str();
          return st;
        }
        break;
      }
    }
  }
  for(std::size_t f = 0; f < nf; ++f)
    if(CGAL::orientation(EP(uv[f][0].x(), uv[f][0].y()), EP(uv[f][1].x(), uv[f][1].y()), EP(uv[f][2].x(), uv[f][2].y())) != CGAL::LEFT_TURN) {
      st.message = "face " + std::to_string(f) + " is degenerate or flipped in the development (grid too fine for the metric?)";
      return st;
    }

  // 3. grid points, each once: owner face (inside), edge (on it, in face(2e)'s frame) or vertex
  auto ep = [](const Point_2& p) { return EP(p.x(), p.y()); };
  struct Where { int kind = -1; int id = -1; double x = 0, y = 0; };   // kind 0 face, 1 edge, 2 vertex
  auto classify = [&](int f, const Point_2& q) {   // q on the closed face f
    Where w;
    int zeros = 0, zero_edge = -1;
    int g = m.face_halfedge[std::size_t(f)];
    for(int k = 0; k < 3; ++k, g = m.next[std::size_t(g)]) {
      const CGAL::Orientation o = CGAL::orientation(ep(uv[std::size_t(f)][std::size_t(k)]), ep(uv[std::size_t(f)][std::size_t((k + 1) % 3)]), ep(q));
      if(o == CGAL::RIGHT_TURN) return w;   // outside
      if(o == CGAL::COLLINEAR) { ++zeros; zero_edge = g; }
    }
    if(zeros == 0) { w.kind = 0; w.id = f; w.x = q.x(); w.y = q.y(); return w; }
    if(zeros >= 2) {   // at a corner
      g = m.face_halfedge[std::size_t(f)];
      for(int k = 0; k < 3; ++k, g = m.next[std::size_t(g)])
        if(uv[std::size_t(f)][std::size_t(k)] == q) { w.kind = 2; w.id = m.source(g); return w; }
      return w;
    }
    const int e = zero_edge >> 1;
    Point_2 c = q;
    if(zero_edge & 1) c = motion[std::size_t(e)](q);   // into the frame of face(2e)
    if(m.face[std::size_t(zero_edge ^ 1)] < 0) c = q;   // boundary edge: one frame only
    w.kind = 1; w.id = e; w.x = c.x(); w.y = c.y();
    return w;
  };
  // The grid points by where they are: per face its inner points, per edge the points on it
  // (lists of a few, linked through next_point), per vertex its point. Arrays, not a hash
  // table: the walks below look a point up at every grid edge (433k faces: points and faces
  // 0.98 -> 0.56 s).
  const std::size_t npos = std::size_t(-1);
  std::vector<std::size_t> face_head(nf, npos), edge_head(ne, npos), vertex_point(nv, npos), next_point;
  std::vector<Where> points;
  auto find_point = [&](const Where& w) {
    if(w.kind == 2) return vertex_point[std::size_t(w.id)];
    std::size_t i = (w.kind == 0 ? face_head : edge_head)[std::size_t(w.id)];
    while(i != npos && !(points[i].x == w.x && points[i].y == w.y)) i = next_point[i];
    return i;
  };
  std::vector<std::pair<int, Point_2>> seat;   // per grid point: a face containing it and its coordinates there
  for(std::size_t f = 0; f < nf; ++f) {
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    for(const Point_2& p : uv[f]) {
      lo[0] = (std::min)(lo[0], p.x()); lo[1] = (std::min)(lo[1], p.y());
      hi[0] = (std::max)(hi[0], p.x()); hi[1] = (std::max)(hi[1], p.y());
    }
    for(double a = std::ceil(lo[0]); a <= hi[0]; ++a)
      for(double b = std::ceil(lo[1]); b <= hi[1]; ++b) {
        const Point_2 q(a, b);
        const Where w = classify(int(f), q);
        if(w.kind < 0) continue;
        if(find_point(w) != npos) continue;
        if(w.kind == 2) { vertex_point[std::size_t(w.id)] = points.size(); next_point.push_back(npos); }
        else {
          std::size_t& head = (w.kind == 0 ? face_head : edge_head)[std::size_t(w.id)];
          next_point.push_back(head);
          head = points.size();
        }
        points.push_back(w);
        seat.emplace_back(int(f), q);
      }
  }
  if(points.size() > 50000000) { st.message = "more than 5e7 grid points: edge length too small"; return st; }

  // 4. faces: from every grid point that is not a cone, the unit squares (triangles) at it, walked
  // the halfedge of face f that leaves its corner at p (exactly), or -1
  auto corner_at = [&](int f, const Point_2& p) {
    int g = m.face_halfedge[std::size_t(f)];
    for(int k = 0; k < 3; ++k, g = m.next[std::size_t(g)])
      if(uv[std::size_t(f)][std::size_t(k)] == p) return g;
    return -1;
  };
  // whether the direction from the corner of f at halfedge g's source towards `to` lies in the
  // face's closed angle there
  auto in_angle = [&](int f, int g, const Point_2& to) {
    int k = 0;
    for(int x = m.face_halfedge[std::size_t(f)]; x != g; x = m.next[std::size_t(x)]) ++k;
    const EP p = ep(uv[std::size_t(f)][std::size_t(k)]), a = ep(uv[std::size_t(f)][std::size_t((k + 1) % 3)]),
             b = ep(uv[std::size_t(f)][std::size_t((k + 2) % 3)]);
    return CGAL::orientation(p, a, ep(to)) != CGAL::RIGHT_TURN && CGAL::orientation(p, b, ep(to)) != CGAL::LEFT_TURN;
  };
  // the face across halfedge h (-1 at the boundary), with from, to and the carried motion moved
  // into its frame when h is on the cut graph
  auto cross_edge = [&](int h, Point_2& from, Point_2& to, internal::Lattice_motion& carried) {
    const int next_face = m.face[std::size_t(h ^ 1)];
    const int e = h >> 1;
    if(next_face >= 0 && !dev.tree_[std::size_t(e)]) {
      const internal::Lattice_motion t = (h & 1) ? motion[std::size_t(e)] : motion[std::size_t(e)].inverse();
      from = t(from);
      to = t(to);
      carried = t * carried;
    }
    return next_face;
  };
  auto walk = [&](int f, Point_2 from, Point_2 to, internal::Lattice_motion& carried, int& where) -> bool {
    // Starting at a boundary vertex or a cone: first turn around it to the face whose angle holds
    // the direction, counterclockwise, or clockwise where the boundary stops that way (a straight
    // walk from the wrong face would leave the surface, or go round a cone the long way, whose
    // angle is not 2 pi; at a regular interior vertex the walk turns by itself).
    const int g0 = corner_at(f, from);
    const bool at_cone = g0 >= 0 && dev.cone_index_[std::size_t(m.source(g0))] >= 0;
    if(g0 >= 0 && (m.is_boundary_vertex(m.source(g0)) || at_cone) && !in_angle(f, g0, to)) {
      // around a cone both ways reach a face holding the direction, at different angles: the
      // one reached by the smaller turn is the grid's
      bool turned = false;
      double best_turn = 1e300;
      int bf = f; Point_2 bfrom = from, bto = to; internal::Lattice_motion bc = carried;
      for(int way = 0; way < 2 && (!turned || at_cone); ++way) {
        int ff = f, g = g0;
        Point_2 fr = from, tt = to;
        internal::Lattice_motion c = carried;
        double turn = 0;
        bool found = false;
        for(std::size_t step = 0; step <= nf && !found; ++step) {
          const int cross = way == 0 ? m.next[std::size_t(m.next[std::size_t(g)])] : g;   // into the corner, or out of it
          turn += m.angle[std::size_t(g)];
          const int nf2 = cross_edge(cross, fr, tt, c);
          if(nf2 < 0) break;
          ff = nf2;
          g = corner_at(ff, fr);
          if(g < 0) break;
          if(in_angle(ff, g, tt)) found = true;
        }
        if(found && turn < best_turn) { best_turn = turn; bf = ff; bfrom = fr; bto = tt; bc = c; turned = true; }
      }
      if(turned) { f = bf; from = bfrom; to = bto; carried = bc; }
    }
    for(std::size_t it = 0; it < 4 * nf + 16; ++it) {
      int exit = -1, any = -1;
      int g = m.face_halfedge[std::size_t(f)];
      for(int k = 0; k < 3; ++k, g = m.next[std::size_t(g)]) {
        const EP a = ep(uv[std::size_t(f)][std::size_t(k)]), b = ep(uv[std::size_t(f)][std::size_t((k + 1) % 3)]);
        if(CGAL::orientation(a, b, ep(to)) != CGAL::RIGHT_TURN) continue;
        any = g;
        if(CGAL::orientation(ep(from), ep(to), a) == CGAL::RIGHT_TURN && CGAL::orientation(ep(from), ep(to), b) != CGAL::RIGHT_TURN) exit = g;
      }
      if(any < 0) { where = f; return true; }   // `to` is in the closed face
      if(exit < 0) exit = any;
      const int next_face = cross_edge(exit, from, to, carried);
      if(next_face < 0) return false;   // left the surface through its boundary
      f = next_face;
    }
    return false;
  };
  // The grid's edges first: from every grid point that is not a cone, one walk of one edge
  // length in each of the grid's directions (in the frame of the point's seat) to the point
  // where it ends. A face is then read off these edges with the rotation system of the grid:
  // having arrived at point j from i, the face's next edge leaves j in the direction before the
  // one that leads back to i (directions counterclockwise). So each face costs no walk of its
  // own, and each edge is walked twice (once from each end) instead of twice per face corner.
  // Faces with a cone at a corner the reading would turn at (whose directions are not the grid's),
  // or where the edges are ambiguous, are taken from their first corner's own edges and diagonal.
  const int dirs = square ? 4 : 6;
  const std::size_t none = std::size_t(-1), off = std::size_t(-2);   // across the boundary; ends off the grid points
  auto is_cone = [&](std::size_t i) { return points[i].kind == 2 && dev.cone_index_[std::size_t(points[i].id)] >= 0; };
  const std::vector<internal::Lattice_motion>::size_type direction_count = std::size_t(dirs);
  std::vector<internal::Lattice_motion> rotation_of(direction_count);   // the step rotation to the power dir
  for(int dir = 1; dir < dirs; ++dir) rotation_of[std::size_t(dir)] = step_rotation * rotation_of[std::size_t(dir - 1)];
  // the grid point reached from point i's seat by the segment from `at` to `to` in face f's frame
  auto reach = [&](int f, const Point_2& at, const Point_2& to, internal::Lattice_motion& carried, int& where, Point_2& target) -> std::size_t {
    internal::Lattice_motion c = carried;
    if(!walk(f, at, to, c, where)) return none;
    target = (c * carried.inverse())(to);
    carried = c;
    const Where w = classify(where, target);
    const std::size_t j = w.kind < 0 ? npos : find_point(w);
    return j == npos ? off : j;
  };
  std::vector<std::size_t> neighbour(points.size() * std::size_t(dirs), none);   // per point and direction: the point at the edge's other end
  bool off_grid[2] = {false, false};
  auto walk_edges = [&](std::size_t begin, std::size_t end, int part) {
    for(std::size_t i = begin; i < end && !off_grid[part]; ++i) {
      if(is_cone(i)) continue;
      for(int dir = 0; dir < dirs; ++dir) {
        const std::array<double, 2> d = rotation_of[std::size_t(dir)].rotate(1, 0);
        const Point_2 at = seat[i].second, to(at.x() + d[0], at.y() + d[1]);
        internal::Lattice_motion carried;
        int where = -1;
        Point_2 target;
        const std::size_t j = reach(seat[i].first, at, to, carried, where, target);
        if(j == off) { off_grid[part] = true; break; }
        neighbour[i * std::size_t(dirs) + std::size_t(dir)] = j;
      }
    }
  };
  const std::size_t half = points.size() / 2;
  const bool concurrent = points.size() >= 20000;
  internal::run_on_two_threads([&](int part) { walk_edges(part == 0 ? 0 : half, part == 0 ? half : points.size(), part); }, concurrent);
  // The face at point i left of its edge in direction dir, from i's own edges: a triangle is i
  // and the ends of its edges in directions dir and dir + 1; a square adds the corner diagonal to
  // i, reached by a straight walk from i through the square. Point i is no cone, and no cone lies
  // inside a face, so no walk turns at a cone (where two ways round would give two faces).
  typedef std::array<std::size_t, 5> Found;   // the corners (unused ones -1), then their count
  auto face_by_diagonal = [&](std::size_t i, int dir, Found& corners) -> std::size_t {   // none, off, or the corner count
    const std::size_t a = neighbour[i * std::size_t(dirs) + std::size_t(dir)], b = neighbour[i * std::size_t(dirs) + std::size_t((dir + 1) % dirs)];
    if(a == none || b == none) return none;
    corners[1] = a;
    if(!square) { corners[2] = b; return 3; }
    const std::array<double, 2> d = rotation_of[std::size_t(dir)].rotate(1, 0), e = rotation_of[std::size_t((dir + 1) % dirs)].rotate(1, 0);
    const Point_2 at = seat[i].second, to(at.x() + d[0] + e[0], at.y() + d[1] + e[1]);
    internal::Lattice_motion carried;
    int where = -1;
    Point_2 target;
    const std::size_t j = reach(seat[i].first, at, to, carried, where, target);
    if(j == none || j == off) return j;
    corners[2] = j;
    corners[3] = b;
    return 4;
  };
  // the same face read off the edges: none when it crosses the boundary, off when it must be walked
  auto read_face = [&](std::size_t i, int dir, Found& corners) -> std::size_t {
    std::size_t from = i, at = neighbour[i * std::size_t(dirs) + std::size_t(dir)];
    for(int k = 1; k < sides; ++k) {
      if(at == none) return none;
      corners[std::size_t(k)] = at;
      if(k + 1 == sides) break;
      if(is_cone(at)) return off;
      int back = -1;
      for(int b = 0; b < dirs; ++b)
        if(neighbour[at * std::size_t(dirs) + std::size_t(b)] == from) { if(back >= 0) return off; back = b; }
      if(back < 0) return off;
      from = at;
      at = neighbour[from * std::size_t(dirs) + std::size_t((back + dirs - 1) % dirs)];
    }
    return std::size_t(sides);
  };
  // On an open mesh a face's edges can all lie on the surface around a hole smaller than the
  // face: it is kept only if the walk from its corner to its centre stays on the surface.
  const bool open = !topo.loops.empty();
  auto centre_on_surface = [&](std::size_t i, int dir) {
    const std::array<double, 2> d = rotation_of[std::size_t(dir)].rotate(1, 0), e = step_rotation.rotate(d[0], d[1]);
    const double w = square ? 0.5 : 1. / 3;
    const Point_2 at = seat[i].second, centre(at.x() + w * (d[0] + e[0]), at.y() + w * (d[1] + e[1]));
    internal::Lattice_motion c;
    int where = -1;
    return walk(seat[i].first, at, centre, c, where);
  };
  // Each face is kept by the first of its corners (in point order) that is not a cone: from that
  // corner only, so no face is kept twice. Two threads, each over half of the points.
  std::vector<Found> found[2];
  auto find_faces = [&](std::size_t begin, std::size_t end, int part) {
    for(std::size_t i = begin; i < end && !off_grid[part]; ++i) {
      if(is_cone(i)) continue;
      for(int dir = 0; dir < dirs; ++dir) {
        Found corners;
        corners.fill(none);
        corners[0] = i;
        std::size_t count = read_face(i, dir, corners);
        if(count == off) count = face_by_diagonal(i, dir, corners);
        if(count == off) { off_grid[part] = true; break; }
        if(count == none) continue;   // a face across the boundary: none there
        bool first = true;
        for(std::size_t k = 1; k < count; ++k) if(corners[k] < i && !is_cone(corners[k])) first = false;
        corners[4] = count;
        if(first && open && !centre_on_surface(i, dir)) continue;   // its edges run around a hole
        if(first) found[part].push_back(corners);
      }
    }
  };
  if(!off_grid[0] && !off_grid[1])
    internal::run_on_two_threads([&](int part) { find_faces(part == 0 ? 0 : half, part == 0 ? half : points.size(), part); }, concurrent);
  if(off_grid[0] || off_grid[1]) {
    st.message = "a grid edge ends off the grid points (inconsistent development)";
    return st;
  }
  // Faces whose corners are all cones (cones at the four corners of a unit square: valid, if
  // crowded) have no corner to be read from above. A cone's grid edges are walked from the corner
  // of its fan whose angle holds their direction (half-open: a direction along a mesh edge belongs
  // to the corner that starts there), counterclockwise: its rotation system, with which such a
  // face is read like any other, and kept by its first corner.
  if(!off_grid[0] && !off_grid[1]) {
    std::vector<int> cone_slot(points.size(), -1);
    std::vector<std::vector<std::size_t>> cone_edges;
    for(std::size_t i = 0; i < points.size(); ++i) {
      if(!is_cone(i) || m.is_boundary_vertex(points[i].id)) continue;
      cone_slot[i] = int(cone_edges.size());
      cone_edges.emplace_back();
      const int v = points[i].id;
      int g = m.vertex_out[std::size_t(v)];
      const int g0 = g;
      do {
        const int f = m.face[std::size_t(g)];
        int k = 0;
        for(int x = m.face_halfedge[std::size_t(f)]; x != g; x = m.next[std::size_t(x)]) ++k;
        const Point_2 &p = uv[std::size_t(f)][std::size_t(k)], &a = uv[std::size_t(f)][std::size_t((k + 1) % 3)],
                      &b = uv[std::size_t(f)][std::size_t((k + 2) % 3)];
        std::vector<std::pair<double, int>> in_corner;   // (angle from p->a, direction)
        for(int dir = 0; dir < dirs; ++dir) {
          const std::array<double, 2> d = rotation_of[std::size_t(dir)].rotate(1, 0);
          const Point_2 to(p.x() + d[0], p.y() + d[1]);
          const CGAL::Orientation oa = CGAL::orientation(ep(p), ep(a), ep(to));
          const double ax = a.x() - p.x(), ay = a.y() - p.y();
          const bool from_a = oa == CGAL::LEFT_TURN || (oa == CGAL::COLLINEAR && ax * d[0] + ay * d[1] > 0);
          if(!from_a || CGAL::orientation(ep(p), ep(b), ep(to)) != CGAL::RIGHT_TURN) continue;
          in_corner.emplace_back(std::atan2(ax * d[1] - ay * d[0], ax * d[0] + ay * d[1]), dir);
        }
        std::sort(in_corner.begin(), in_corner.end());
        for(const auto& c : in_corner) {
          const std::array<double, 2> d = rotation_of[std::size_t(c.second)].rotate(1, 0);
          internal::Lattice_motion carried;
          int where = -1;
          Point_2 target;
          const std::size_t j = reach(f, p, Point_2(p.x() + d[0], p.y() + d[1]), carried, where, target);
          if(j == off || j == none) { off_grid[0] = true; break; }
          cone_edges.back().push_back(j);
        }
        g = m.ccw_out(g);
      } while(g != g0 && !off_grid[0]);
      if(off_grid[0]) break;
    }
    // the edges at point p counterclockwise, as (first, count)
    auto edges_at = [&](std::size_t p) -> std::pair<const std::size_t*, int> {
      if(cone_slot[p] >= 0) return {cone_edges[std::size_t(cone_slot[p])].data(), int(cone_edges[std::size_t(cone_slot[p])].size())};
      if(is_cone(p)) return {nullptr, 0};
      return {neighbour.data() + p * std::size_t(dirs), dirs};
    };
    for(std::size_t i = 0; i < points.size() && !off_grid[0]; ++i) {
      if(cone_slot[i] < 0) continue;
      const auto own = edges_at(i);
      for(int t = 0; t < own.second; ++t) {
        Found corners;
        corners.fill(none);
        corners[0] = i;
        std::size_t from = i, at = own.first[t];
        bool keep = true;
        for(int k = 1; k <= sides && keep; ++k) {   // the sides corners, then back at i
          if(at == none || !is_cone(at) || (k < sides && at < i)) { keep = false; break; }
          if(k == sides) { keep = at == i; break; }
          corners[std::size_t(k)] = at;
          const auto e = edges_at(at);
          int back = -1;
          for(int q = 0; q < e.second; ++q)
            if(e.first[q] == from) { if(back >= 0) keep = false; back = q; }
          if(back < 0 || !keep) { keep = false; break; }
          from = at;
          at = e.first[(back + e.second - 1) % e.second];
        }
        if(!keep) continue;
        corners[4] = std::size_t(sides);
        found[0].push_back(corners);
      }
    }
    if(off_grid[0]) {
      st.message = "a grid edge from a cone ends off the grid points (inconsistent development)";
      return st;
    }
  }
  std::vector<std::vector<std::size_t>> out_faces;
  for(const std::vector<Found>& part : found)
    for(const Found& corners : part) out_faces.emplace_back(corners.begin(), corners.begin() + std::ptrdiff_t(corners[4]));

  // 5. the output mesh
  typedef typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
  VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  typedef typename boost::property_traits<typename boost::property_map<PolygonMesh, CGAL::vertex_point_t>::type>::value_type Out_point;
  auto point3 = [&](int v) {
    const auto& p = get(vpm, m.vertices[std::size_t(v)]);
    return std::array<double, 3>{{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
  };
  CGAL::clear(out);
  std::vector<out_vertex> ov(points.size());
  auto opm = get(CGAL::vertex_point, out);
  st.vertex_locations.assign(points.size(), Surface_point());
  for(std::size_t i = 0; i < points.size(); ++i) {
    const Where& w = points[i];
    std::array<double, 3> x{{0, 0, 0}};
    Surface_point& location = st.vertex_locations[i];
    if(w.kind == 2) {
      x = point3(w.id);
      int g = m.vertex_out[std::size_t(w.id)];
      if(m.face[std::size_t(g)] < 0) g = m.ccw_out(g);   // a boundary vertex's border halfedge: the next one has a face
      location.face = m.face[std::size_t(g)];
      int k = 0;
      for(int y = m.face_halfedge[std::size_t(location.face)]; y != g; y = m.next[std::size_t(y)]) ++k;
      location.barycentric[std::size_t(k)] = 1;
    } else {
      const int f = w.kind == 0 ? w.id : m.face[std::size_t(2 * w.id)] >= 0 ? m.face[std::size_t(2 * w.id)] : m.face[std::size_t(2 * w.id + 1)];
      const Point_2 q(w.x, w.y);
      const std::array<Point_2, 3>& c = uv[std::size_t(f)];
      const double area = (c[1].x() - c[0].x()) * (c[2].y() - c[0].y()) - (c[2].x() - c[0].x()) * (c[1].y() - c[0].y());
      double bary[3];
      for(int k = 0; k < 3; ++k) {
        const Point_2 &a = c[std::size_t((k + 1) % 3)], &b = c[std::size_t((k + 2) % 3)];
        bary[k] = ((b.x() - a.x()) * (q.y() - a.y()) - (q.x() - a.x()) * (b.y() - a.y())) / area;
      }
      location.face = f;
      const double total = (std::max)(0., bary[0]) + (std::max)(0., bary[1]) + (std::max)(0., bary[2]);
      for(int k = 0; k < 3; ++k) location.barycentric[std::size_t(k)] = (std::max)(0., bary[k]) / total;
      int g = m.face_halfedge[std::size_t(f)];
      for(int k = 0; k < 3; ++k, g = m.next[std::size_t(g)]) {
        const std::array<double, 3> p = point3(m.source(g));
        for(int j = 0; j < 3; ++j) x[std::size_t(j)] += bary[k] * p[std::size_t(j)];
      }
    }
    ov[i] = add_vertex(out);
    put(opm, ov[i], Out_point(x[0], x[1], x[2]));
  }
  for(const auto& fc : out_faces) {
    std::vector<out_vertex> vs;
    for(std::size_t i : fc) vs.push_back(ov[i]);
    if(CGAL::Euler::add_face(vs, out) == OGT::null_face()) {
      CGAL::clear(out);
      st.message = "the grid's faces do not form a manifold surface (a face is found twice or the cones are too close for this edge length)";
      return st;
    }
  }
  // 6. read-back: valences; irregular vertices must be the cones, with valence 4 - K/(pi/2)
  const int regular = square ? 4 : 6;
  const std::vector<double>& K = dev.im_.curvatures();
  bool cones_ok = true;
  for(std::size_t i = 0; i < points.size(); ++i) {
    const out_vertex v = ov[i];
    if(CGAL::is_border(v, out)) continue;
    const std::size_t val = degree(v, out);
    if(st.valences.size() <= val) st.valences.resize(val + 1, 0);
    ++st.valences[val];
    const bool at_cone = points[i].kind == 2 && dev.cone_index_[std::size_t(points[i].id)] >= 0;
    const long expected = at_cone ? std::lround(regular - K[std::size_t(points[i].id)] / step) : regular;
    if(long(val) != regular) st.irregular_vertices.emplace_back(i, at_cone ? long(points[i].id) : -1L);
    if(long(val) != expected) cones_ok = false;
  }
  st.vertices = num_vertices(out);
  st.faces = num_faces(out);
  // the input's topology: its Euler characteristic and boundary loops (a grid point left without
  // a face, or faces missing along the boundary, would change them)
  {
    std::size_t loops = 0;
    auto seen = get(CGAL::dynamic_halfedge_property_t<int>(), out);
    for(auto hd : halfedges(out)) put(seen, hd, 0);
    for(auto hd : halfedges(out)) {
      if(!CGAL::is_border(hd, out) || get(seen, hd)) continue;
      ++loops;
      for(auto g = hd; !get(seen, g); g = next(g, out)) put(seen, g, 1);
    }
    const long chi_in = topo.components[0].euler_characteristic();
    const long chi_out = long(num_vertices(out)) - long(num_edges(out)) + long(num_faces(out));
    st.euler_characteristic = chi_out;
    st.boundary_loops = loops;
    if(chi_out != chi_in || loops != topo.loops.size()) {
      st.message = "the remesh has Euler characteristic " + std::to_string(chi_out) + " and " + std::to_string(loops) +
                   " boundary loops, the input " + std::to_string(chi_in) + " and " + std::to_string(topo.loops.size()) +
                   " (faces are missing along the boundary, or a grid point got none)";
      return st;
    }
  }
  if(!cones_ok) {
    st.message = "an output vertex has a valence its cone does not explain";
    return st;
  }
  // inverted faces: the polygon's area vector against the sum of the input normals under its corners
  auto input_normal = [&](const Where& w) {
    return w.kind == 0 ? internal::face_normal(m, w.id, point3) : w.kind == 1 ? internal::edge_normal(m, 2 * w.id, point3)
                                                                              : internal::vertex_normal(m, w.id, point3);
  };
  for(const auto& fc : out_faces) {
    auto corner = [&](std::size_t k) {
      const Out_point& p = get(opm, ov[fc[k]]);
      return internal::Vec3{{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
    };
    st.inverted_faces += internal::turns_against_input(fc.size(), corner, [&](std::size_t k) { return input_normal(points[fc[k]]); });
  }
  if(st.inverted_faces > 0) {
    st.message = std::to_string(st.inverted_faces) + " faces are inverted in space (their corners turn against the input's normals: "
                 "the metric stretches too much for this edge length)";
    return st;
  }
  st.success = true;
  return st;
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_GRID_TESSELLATION_H
