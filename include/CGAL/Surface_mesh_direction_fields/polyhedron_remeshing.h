// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_POLYHEDRON_REMESHING_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_POLYHEDRON_REMESHING_H

// Regular remeshing through a polyhedron of squares and equilateral triangles (Lai et al. 2010,
// Figure 1d: the obelisk's mixed quad and triangle mesh): every face of the polyhedron carries
// its own grid, squares a square grid and triangles a triangular one, of n edges per side, so the
// grids meet along the polyhedron's edges at the same points.

#include <CGAL/Surface_mesh_direction_fields/internal/inversion.h>
#include <CGAL/Surface_mesh_direction_fields/polycube_metric.h>
#include <CGAL/Surface_mesh_direction_fields/polyhedron_compatibility.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// Outcome of polyhedron_remesh().
struct Polyhedron_remesh_status
{
  bool success = false;
  std::string message;                 ///< empty on success
  Polycube_metric_status metric;       ///< the cut and embedding of the polyhedron's faces
  /// read-back of the metric: polyhedron_compatibility() of the embedding's edge lengths, at the
  /// grid's edge length (P's faces, developed again from the lengths, must be the gridded
  /// squares and triangles); success needs it compatible
  Polyhedron_compatibility compatibility;
  std::size_t quads = 0, triangles = 0, vertices = 0;
  /// valence histogram of the output's vertices: `valences[k]` vertices of valence k
  std::vector<std::size_t> valences;
  /// vertices whose valence differs from what their place on the polyhedron asks (4 inside a
  /// square, 6 inside a triangle, 4, 5 or 6 on an edge between squares and / or triangles, the
  /// number of faces at a corner); success needs none
  std::size_t unexpected_valences = 0;
  /// faces whose area vector points against the input's normals under their corners, counted
  /// last, once every other check has passed (untangle_remesh() can unfold them)
  std::size_t inverted_faces = 0;
};

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// Remeshes a closed genus-0 mesh through a polyhedron P of squares and equilateral triangles
/// (`corners`, `faces` as for polyhedron_metric(), whose cut and embedding it uses): each face of
/// P is divided into \f$n \times n\f$ squares or \f$n^2\f$ triangles (`subdivisions` \f$= n\f$) and
/// the grid carried to the surface through the face's embedding: grid points inside a face are
/// placed by barycentric coordinates in the input triangle that contains them, points on P's
/// edges on the path of the edge, evenly in the chart (by arc length without relaxation), P's corners at their vertices. Quad faces of P
/// give quads, triangle faces triangles: a mixed mesh when P has both (the obelisk of Lai et
/// al., Figure 1d). Every output vertex has the valence its place on P asks: 4 inside squares, 6
/// inside triangles, 4, 5 or 6 on P's edges, and at a corner the number of P's faces there (a
/// cone of curvature \f$2\pi - \sum\f$ angles).
///
/// The faces' embeddings are relaxed towards the input's triangles as in box_polycube_metric(),
/// P's sides then of the length that gives P the surface's area; grid points on P's edges
/// follow the relaxed paths.
///
/// Named parameters: `edge_length_map` (the metric of the paths and of the embedding's first
/// weights; default: Euclidean lengths) or `intrinsic_mesh`; `conformal_factor_map` (the
/// paths under the conformal scaling of that metric, e.g. the flat cone metric with P's cones,
/// as for box_polycube_metric());
/// `number_of_iterations` (as for box_polycube_metric(), default 10), `segment_flattening`
/// (as for box_polycube_metric(), default `RELAXED_SEGMENTS`), `vertex_point_map`, and
/// the index maps. `out` is cleared and receives the remesh when its faces could be built.
template <typename TriangleMesh, typename PolygonMesh, typename NamedParameters = parameters::Default_named_parameters>
Polyhedron_remesh_status polyhedron_remesh(const TriangleMesh& tm,
                                           const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& corners,
                                           const std::vector<std::vector<int>>& faces, int subdivisions, PolygonMesh& out,
                                           const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef boost::graph_traits<PolygonMesh> OGT;
  typedef typename OGT::vertex_descriptor out_vertex;
  Polyhedron_remesh_status st;
  if(subdivisions < 1 || subdivisions > 100000)
    throw Input_error(Input_error::INVALID_ARGUMENT, "subdivisions must be between 1 and 100000, got " + std::to_string(subdivisions));
  for(const auto& f : faces)
    if(f.size() != 3 && f.size() != 4)
      throw Input_error(Input_error::INVALID_ARGUMENT, "the polyhedron's faces must be triangles or quadrilaterals");
  const Intrinsic_mesh<TriangleMesh> im = internal::genus_zero_mesh(tm, np, "polyhedron_remesh()");
  const internal::Mesh_arrays<TriangleMesh>& m = im.arrays();
  std::vector<int> cv;
  for(const auto& v : corners) cv.push_back(m.vertex_index(v));
  const int n = subdivisions;
  const double r3 = std::sqrt(3.) / 2;
  const internal::Chart_inputs in = internal::chart_inputs(tm, m, np);
  double L = 0;   // the polygons' side: P's area that of the input (relaxed) or the mean length of the paths
  auto polygon = [&](std::size_t j, const std::function<double(int, int)>& path_length) {
    if(L == 0) {
      double sum = 0, unit_area = 0;
      int count = 0;
      for(const auto& f : faces) {
        for(std::size_t i = 0; i < f.size(); ++i) { sum += path_length(f[i], f[(i + 1) % f.size()]); ++count; }
        unit_area += f.size() == 4 ? 1. : r3 / 2;
      }
      L = in.iterations > 0 ? std::sqrt(in.area / unit_area) : sum / count;
    }
    return faces[j].size() == 4 ? std::vector<Point_2>{Point_2(0, 0), Point_2(L, 0), Point_2(L, L), Point_2(0, L)}
                                : std::vector<Point_2>{Point_2(0, 0), Point_2(L, 0), Point_2(L / 2, L * r3)};
  };
  std::vector<double> lengths;
  internal::Polyhedron_charts ch;
  st.metric = internal::polyhedron_metric_core(m, cv, faces, polygon, in, lengths, &ch);
  if(!st.metric.success) { st.message = st.metric.message; return st; }
  {
    internal::Mesh_arrays<TriangleMesh> metric = m;
    metric.set_lengths(lengths);
    st.compatibility = internal::polyhedron_compatibility_core(metric, cv, faces, L / n, 1e-6);
    if(!st.compatibility.compatible) {
      st.message = !st.compatibility.message.empty() ? "read-back of the metric: " + st.compatibility.message
                   : "read-back of the metric: " + std::to_string(st.compatibility.failing_faces.size()) + " faces of the polyhedron are not "
                     "whole grid polygons (angles off by up to " + std::to_string(st.compatibility.max_angle_deviation) + " rad, sides by " +
                     std::to_string(st.compatibility.max_side_deviation) + " edge lengths) and " + std::to_string(st.compatibility.curved_vertices) +
                     " other vertices are not flat";
      return st;
    }
  }
  typedef typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
  VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  typedef std::array<double, 3> V3;
  auto point3 = [&](int v) {
    const auto& p = get(vpm, m.vertices[std::size_t(v)]);
    return V3{{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
  };
  std::map<std::pair<int, int>, int> edge_of;
  for(std::size_t k = 0; k < ch.pedges.size(); ++k)
    edge_of[std::make_pair((std::min)(ch.pedges[k][0], ch.pedges[k][1]), (std::max)(ch.pedges[k][0], ch.pedges[k][1]))] = int(k);

  // output vertices: P's corners, the points inside P's edges, the points inside P's faces
  std::vector<V3> position;
  // per output vertex, for the inversion test: the input face it lies in (kind 0), the edge
  // of the halfedge it lies on (1) or the input vertex it is (2)
  std::vector<std::pair<int, int>> under;
  std::vector<int> expected;   // per output vertex: the valence its place asks
  std::vector<int> corner_id(cv.size());
  std::vector<int> faces_at_corner(cv.size(), 0);
  for(const auto& f : faces) for(int c : f) ++faces_at_corner[std::size_t(c)];
  for(std::size_t i = 0; i < cv.size(); ++i) {
    corner_id[i] = int(position.size());
    position.push_back(point3(cv[i]));
    under.emplace_back(2, cv[i]);
    expected.push_back(faces_at_corner[i]);
  }
  // per P edge: its n - 1 inner points along the path, evenly in the charts; valence from its two faces
  std::vector<int> edge_sides(ch.pedges.size(), 0);   // 4 + 4 = 8 (squares), 6 + 6, 4 + 6 ...
  for(const auto& f : faces)
    for(std::size_t i = 0; i < f.size(); ++i)
      edge_sides[std::size_t(edge_of.at(std::make_pair((std::min)(f[i], f[(i + 1) % f.size()]), (std::max)(f[i], f[(i + 1) % f.size()]))))] +=
          f.size() == 4 ? 1 : 2;   // grid edges a face adds at a point inside its side: 1 (square) or 2 (triangle)
  std::vector<int> edge_first(ch.pedges.size());
  for(std::size_t k = 0; k < ch.pedges.size(); ++k) {
    edge_first[k] = int(position.size());
    const std::vector<int>& p = ch.paths[k];
    double total = 0;
    for(double x : ch.steps[k]) total += x;
    std::size_t seg = 0;
    double at = 0;   // arc length at the start of segment seg
    for(int i = 1; i < n; ++i) {
      const double s = total * i / n;
      while(seg + 1 < ch.steps[k].size() && at + ch.steps[k][seg] < s) { at += ch.steps[k][seg]; ++seg; }
      const double t = ch.steps[k][seg] > 0 ? (std::min)(1., (std::max)(0., (s - at) / ch.steps[k][seg])) : 0.;
      const V3 a = point3(p[seg]), b = point3(p[seg + 1]);
      position.push_back(V3{{(1 - t) * a[0] + t * b[0], (1 - t) * a[1] + t * b[1], (1 - t) * a[2] + t * b[2]}});
      if(t == 0 || t == 1) under.emplace_back(2, t == 0 ? p[seg] : p[seg + 1]);   // at a vertex of the path
      else under.emplace_back(1, ch.path_halfedges[k][seg]);
      expected.push_back(2 + edge_sides[k]);
    }
  }
  // the id of grid point (a, b) of P face j: corner, edge point or (new) inner point
  std::vector<std::map<std::pair<int, int>, int>> inner(faces.size());
  auto side_point = [&](int from, int to, int i) {   // point i (0..n) from corner `from` along P's edge to `to`
    if(i == 0) return corner_id[std::size_t(from)];
    if(i == n) return corner_id[std::size_t(to)];
    const int k = edge_of.at(std::make_pair((std::min)(from, to), (std::max)(from, to)));
    return edge_first[std::size_t(k)] + (ch.pedges[std::size_t(k)][0] == from ? i : n - i) - 1;
  };
  auto id_of = [&](std::size_t j, int a, int b) -> int {
    const std::vector<int>& c = faces[j];
    if(c.size() == 4) {
      if(b == 0) return side_point(c[0], c[1], a);
      if(a == n) return side_point(c[1], c[2], b);
      if(b == n) return side_point(c[2], c[3], n - a);
      if(a == 0) return side_point(c[3], c[0], n - b);
    } else {
      if(b == 0) return side_point(c[0], c[1], a);
      if(a + b == n) return side_point(c[1], c[2], b);
      if(a == 0) return side_point(c[2], c[0], n - b);
    }
    return inner[j].at(std::make_pair(a, b));
  };
  // inner points: located in the mesh triangles of their face's chart
  for(std::size_t f = 0; f < m.number_of_faces(); ++f) {
    const std::size_t j = std::size_t(ch.pface[f]);
    const bool square = faces[j].size() == 4;
    const std::array<Point_2, 3>& c = ch.chart[f];
    // lattice coordinates of the corners: square (x, y); triangle (x - y / sqrt(3), y / r3)
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    std::array<std::array<double, 2>, 3> q;
    for(int k = 0; k < 3; ++k) {
      const double x = c[std::size_t(k)].x() * n / L, y = c[std::size_t(k)].y() * n / L;   // in grid edges
      q[std::size_t(k)] = square ? std::array<double, 2>{{x, y}} : std::array<double, 2>{{x - 0.5 * y / r3, y / r3}};
      for(int d = 0; d < 2; ++d) { lo[d] = (std::min)(lo[d], q[std::size_t(k)][std::size_t(d)]); hi[d] = (std::max)(hi[d], q[std::size_t(k)][std::size_t(d)]); }
    }
    const double det = (q[1][0] - q[0][0]) * (q[2][1] - q[0][1]) - (q[2][0] - q[0][0]) * (q[1][1] - q[0][1]);
    for(int a = int(std::ceil(lo[0] - 1e-9)); a <= int(std::floor(hi[0] + 1e-9)); ++a)
      for(int b = int(std::ceil(lo[1] - 1e-9)); b <= int(std::floor(hi[1] + 1e-9)); ++b) {
        if(a <= 0 || b <= 0 || (square ? (a >= n || b >= n) : a + b >= n)) continue;   // on P's boundary: not an inner point
        if(inner[j].count(std::make_pair(a, b))) continue;
        // barycentric coordinates in the chart triangle
        const double l1 = ((double(a) - q[0][0]) * (q[2][1] - q[0][1]) - (q[2][0] - q[0][0]) * (double(b) - q[0][1])) / det;
        const double l2 = ((q[1][0] - q[0][0]) * (double(b) - q[0][1]) - (double(a) - q[0][0]) * (q[1][1] - q[0][1])) / det;
        const double l0 = 1 - l1 - l2;
        if(l0 < -1e-12 || l1 < -1e-12 || l2 < -1e-12) continue;
        const int h0 = m.face_halfedge[f];
        const V3 p0 = point3(m.source(h0)), p1 = point3(m.target[std::size_t(h0)]), p2 = point3(m.target[std::size_t(m.next[std::size_t(h0)])]);
        inner[j][std::make_pair(a, b)] = int(position.size());
        position.push_back(V3{{l0 * p0[0] + l1 * p1[0] + l2 * p2[0], l0 * p0[1] + l1 * p1[1] + l2 * p2[1], l0 * p0[2] + l1 * p1[2] + l2 * p2[2]}});
        under.emplace_back(0, int(f));
        expected.push_back(square ? 4 : 6);
      }
  }
  // faces: the cells of every P face
  std::vector<std::vector<int>> cells;
  try {
    for(std::size_t j = 0; j < faces.size(); ++j) {
      if(faces[j].size() == 4) {
        for(int a = 0; a < n; ++a)
          for(int b = 0; b < n; ++b) cells.push_back({id_of(j, a, b), id_of(j, a + 1, b), id_of(j, a + 1, b + 1), id_of(j, a, b + 1)});
      } else {
        for(int a = 0; a < n; ++a)
          for(int b = 0; a + b < n; ++b) {
            cells.push_back({id_of(j, a, b), id_of(j, a + 1, b), id_of(j, a, b + 1)});
            if(a + b + 1 < n) cells.push_back({id_of(j, a + 1, b), id_of(j, a + 1, b + 1), id_of(j, a, b + 1)});
          }
      }
    }
  } catch(const std::out_of_range&) {
    st.message = "a grid point inside a face of the polyhedron was not found in its embedding";
    return st;
  }
  if(ch.mirrored) for(auto& c : cells) std::reverse(c.begin(), c.end());
  CGAL::clear(out);
  typedef typename boost::property_traits<typename boost::property_map<PolygonMesh, CGAL::vertex_point_t>::type>::value_type Out_point;
  auto opm = get(CGAL::vertex_point, out);
  std::vector<out_vertex> ov(position.size());
  for(std::size_t i = 0; i < position.size(); ++i) { ov[i] = add_vertex(out); put(opm, ov[i], Out_point(position[i][0], position[i][1], position[i][2])); }
  for(const auto& c : cells) {
    std::vector<out_vertex> vs;
    for(int i : c) vs.push_back(ov[std::size_t(i)]);
    if(CGAL::Euler::add_face(vs, out) == OGT::null_face()) {
      CGAL::clear(out);
      st.message = "the grid's cells do not form a manifold surface";
      return st;
    }
    (c.size() == 4 ? st.quads : st.triangles) += 1;
  }
  // read-back: valences against the places, and inversions against the input's normals
  for(std::size_t i = 0; i < position.size(); ++i) {
    const std::size_t d = degree(ov[i], out);
    if(st.valences.size() <= d) st.valences.resize(d + 1, 0);
    ++st.valences[d];
    st.unexpected_valences += int(d) != expected[i];
  }
  st.vertices = num_vertices(out);
  if(st.unexpected_valences) { st.message = std::to_string(st.unexpected_valences) + " vertices have a valence their place does not explain"; return st; }
  auto input_normal = [&](const std::pair<int, int>& w) {
    return w.first == 0 ? internal::face_normal(m, w.second, point3) : w.first == 1 ? internal::edge_normal(m, w.second, point3)
                                                                                    : internal::vertex_normal(m, w.second, point3);
  };
  for(const auto& c : cells)
    st.inverted_faces += internal::turns_against_input(c.size(), [&](std::size_t k) { return position[std::size_t(c[k])]; },
                                                       [&](std::size_t k) { return input_normal(under[std::size_t(c[k])]); });
  if(st.inverted_faces) {
    st.message = std::to_string(st.inverted_faces) + " faces are inverted in space (their corners turn against the input's normals)";
    return st;
  }
  st.success = true;
  return st;
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_POLYHEDRON_REMESHING_H
