// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_POLYHEDRON_COMPATIBILITY_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_POLYHEDRON_COMPATIBILITY_H

// Theorem 3.5 of Lai et al. for grids of squares and triangles together (the obelisk of their
// Figure 1c-d): whether a flat cone metric is a polyhedron P of rectangles and equilateral
// triangles whose sides are whole numbers of grid edges, tested face by face of P.

#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/intrinsic_triangle.h>
#include <CGAL/Surface_mesh_direction_fields/internal/development.h>
#include <CGAL/Surface_mesh_direction_fields/internal/polyhedron_paths.h>
#include <CGAL/Surface_mesh_direction_fields/polycube_metric.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// Outcome of polyhedron_compatibility().
struct Polyhedron_compatibility
{
  /// the metric is P's: flat but at P's corners, every face of P developed into a rectangle
  /// (squares) or an equilateral triangle whose sides are whole numbers of grid edges, so the
  /// square grid of each rectangle and the triangular grid of each triangle meet across P's edges
  bool compatible = false;
  std::string message;                     ///< why P could not be cut into the mesh (empty otherwise)
  double edge_length = 0;                  ///< the grid's edge length tested
  std::vector<std::array<int, 2>> edges;   ///< P's edges, as pairs of corner indices
  /// per edge of P (as in `edges`): its length in the metric, in grid edges, rounded to the
  /// nearest positive whole number
  std::vector<int> sides;
  /// the largest distance, over the corners of P's faces, of the face's angle at the corner in
  /// the metric to \f$\pi/2\f$ (squares) or \f$\pi/3\f$ (triangles), in radians
  double max_angle_deviation = 0;
  /// the largest distance, over the sides of P's faces, of the side's length (the distance of
  /// its corners in the face's development) to the nearest positive multiple of the edge length,
  /// in edge lengths
  double max_side_deviation = 0;
  /// vertices that are not corners of P and whose curvature exceeds the tolerance (cones that P
  /// does not have), and the largest such curvature in absolute value
  std::size_t curved_vertices = 0;
  double max_curvature_elsewhere = 0;
  /// the faces of P (indices into `faces`) whose angles or sides fail, each with its largest
  /// angle deviation (radians) and side deviation (edge lengths): the loops around P's faces
  /// whose development does not close into a polygon of the grid
  std::vector<std::size_t> failing_faces;
  std::vector<double> failing_face_angle_deviations, failing_face_side_deviations;
};

namespace internal {

// The test of polyhedron_compatibility() on the metric of `m` (P's corners as vertex indices).
template <typename TM>
Polyhedron_compatibility polyhedron_compatibility_core(const Mesh_arrays<TM>& m, const std::vector<int>& corner_vertex,
                                                       const std::vector<std::vector<int>>& faces, double edge_length, double tolerance)
{
  Polyhedron_compatibility r;
  r.edge_length = edge_length;
  for(const auto& f : faces)
    if(f.size() != 3 && f.size() != 4)
      throw Input_error(Input_error::INVALID_ARGUMENT, "the polyhedron's faces must be triangles or quadrilaterals, got one with " +
                                                           std::to_string(f.size()) + " corners");
  // cones that P does not have
  std::vector<char> is_corner(m.number_of_vertices(), 0);
  for(int v : corner_vertex)
    if(v >= 0 && std::size_t(v) < is_corner.size()) is_corner[std::size_t(v)] = 1;
  std::vector<double> k;
  vertex_curvatures(m, k);
  for(std::size_t v = 0; v < k.size(); ++v) {
    if(is_corner[v] || m.is_isolated(int(v))) continue;
    r.max_curvature_elsewhere = (std::max)(r.max_curvature_elsewhere, std::abs(k[v]));
    r.curved_vertices += std::abs(k[v]) > tolerance;
  }
  Polyhedron_cut cut;
  if(!cut_along_polyhedron(m, corner_vertex, faces, [&](int h) { return m.edge_length(h); }, cut, r.message)) return r;
  r.edges = cut.pedges;
  r.sides.assign(cut.pedges.size(), 0);
  // Each face of P as the loop around its piece: the boundary walked counterclockwise from
  // corner to corner, turning at every vertex by pi minus the piece's angle there. (Developing
  // the whole piece triangle by triangle put a side 0.04 grid edges off on the bunny's plain
  // Tutte box metric, whose pieces have needle triangles; walking the boundary alone closes it.)
  for(std::size_t j = 0; j < faces.size(); ++j) {
    const int piece = cut.region_of_face[j];
    const std::size_t nc = faces[j].size();
    // the piece's boundary halfedge out of its first corner (the piece on its left)
    const int c0 = corner_vertex[std::size_t(faces[j][0])], g0 = m.vertex_out[std::size_t(c0)];
    int start = -1, g = g0;
    do {
      const int f = m.face[std::size_t(g)];
      if(f >= 0 && cut.region[std::size_t(f)] == piece && cut.path_of_edge[std::size_t(g >> 1)] >= 0) { start = g; break; }
      g = m.ccw_out(g);
    } while(g != g0);
    std::vector<double> angle(nc, -1.);
    std::vector<Point_2> corner_at(nc);
    std::vector<int> order;   // the corners of P met along the loop
    double x = 0, y = 0, heading = 0;
    int h = start;
    for(std::size_t steps = 0; h >= 0 && steps < m.number_of_halfedges(); ++steps) {
      const int v = m.source(h);
      if(cut.corner_of[std::size_t(v)] >= 0) {
        order.push_back(cut.corner_of[std::size_t(v)]);
        for(std::size_t i = 0; i < nc; ++i) if(faces[j][i] == cut.corner_of[std::size_t(v)]) corner_at[i] = Point_2(x, y);
      }
      x += m.edge_length(h) * std::cos(heading);
      y += m.edge_length(h) * std::sin(heading);
      // the piece's angle at target(h), up to the next boundary halfedge
      const int t = m.target[std::size_t(h)];
      double theta = 0;
      int w = m.next[std::size_t(h)];
      for(;;) {
        theta += m.angle[std::size_t(w)];
        if(cut.path_of_edge[std::size_t(w >> 1)] >= 0) break;
        w = m.next[std::size_t(w ^ 1)];
      }
      const int c = cut.corner_of[std::size_t(t)];
      if(c >= 0) for(std::size_t i = 0; i < nc; ++i) if(faces[j][i] == c) angle[i] = theta;
      heading += CGAL_PI - theta;
      h = w;
      if(h == start) break;
    }
    // the corners must be met once each, in P's order (reversed on a mesh oriented inwards)
    bool in_order = order.size() == nc, reversed = in_order;
    for(std::size_t i = 0; i < order.size() && (in_order || reversed); ++i) {
      in_order = in_order && order[i] == faces[j][i];
      reversed = reversed && order[i] == faces[j][(nc - i) % nc];
    }
    if(!in_order && !reversed) {
      r.message = "the paths of the polyhedron's edges do not go around face " + std::to_string(j) + " in its corners' order";
      return r;
    }
    const double right = nc == 4 ? CGAL_PI / 2 : CGAL_PI / 3;
    double worst_angle = 0, worst_side = 0;
    for(std::size_t i = 0; i < nc; ++i) {
      worst_angle = (std::max)(worst_angle, std::abs(angle[i] - right));
      const int a = faces[j][i], b = faces[j][(i + 1) % nc];
      const Point_2 &p = corner_at[i], &q = corner_at[(i + 1) % nc];
      const double d = std::sqrt((q.x() - p.x()) * (q.x() - p.x()) + (q.y() - p.y()) * (q.y() - p.y())) / edge_length;
      const double n = (std::max)(1., std::round(d));
      worst_side = (std::max)(worst_side, std::abs(d - n));
      int& side = r.sides[std::size_t(cut.edge_of(a, b))];
      if(side == 0) side = int(n);
    }
    r.max_angle_deviation = (std::max)(r.max_angle_deviation, worst_angle);
    r.max_side_deviation = (std::max)(r.max_side_deviation, worst_side);
    if(worst_angle > tolerance || worst_side > tolerance) {
      r.failing_faces.push_back(j);
      r.failing_face_angle_deviations.push_back(worst_angle);
      r.failing_face_side_deviations.push_back(worst_side);
    }
  }
  r.compatible = r.curved_vertices == 0 && r.failing_faces.empty();
  return r;
}

} // namespace internal

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// Theorem 3.5 of Lai et al. for a grid of squares and triangles together (their obelisk,
/// Figure 1c-d), and for any polyhedron of squares or of triangles: whether the flat cone metric
/// of the named parameters is the metric of a polyhedron P whose faces are rectangles and
/// equilateral triangles with sides of whole numbers of grid edges of length `edge_length`. P is
/// given as for polyhedron_metric(): `corners` (mesh vertices, the cones) and `faces` (cycles of
/// indices into `corners`, counterclockwise seen from outside, 3 or 4 corners each).
///
/// The rotations and translations of the loops of a mixed grid generate a dense group (steps of
/// \f$\pi/6\f$, translations by unit vectors in twelve directions), so the test of
/// tessellation_compatibility() cannot decide it; instead each face of P is tested as the loop
/// around it: the mesh is cut along shortest edge paths (under the metric) between the corners
/// joined in P, the boundary of each piece developed into the plane (walked from corner to
/// corner, turning at each vertex by \f$\pi\f$ minus the piece's angle there), and the face's
/// angles in the metric compared with \f$\pi/2\f$ or \f$\pi/3\f$ and the distances between its
/// developed corners with whole multiples of the edge length; every other vertex must be flat. Then each square
/// face carries a square grid, each triangle a triangular one, and the grids agree along P's
/// edges. The faces that fail are listed with their deviations.
///
/// Named parameters: `edge_length_map` (the metric, default: Euclidean lengths) or
/// `intrinsic_mesh`, the index maps, and `compatibility_tolerance` (default \f$10^{-6}\f$: radians for angles
/// and curvatures, edge lengths for sides). Throws `Input_error` for a mesh that is not a closed
/// genus-0 surface, a non-positive edge length, and a P that is not a closed oriented sphere of
/// triangles and quadrilaterals on distinct vertices; a cut that fails (the paths cannot avoid
/// each other, or the pieces do not match P's faces) is reported in `message`.
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
Polyhedron_compatibility polyhedron_compatibility(const TriangleMesh& tm,
                                                  const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& corners,
                                                  const std::vector<std::vector<int>>& faces, double edge_length,
                                                  const NamedParameters& np = parameters::default_values())
{
  if(!(edge_length > 0) || !std::isfinite(edge_length))
    throw Input_error(Input_error::INVALID_ARGUMENT, "the edge length must be positive, got " + std::to_string(edge_length));
  const double tolerance = parameters::choose_parameter(parameters::get_parameter(np, internal_np::compatibility_tolerance), 1e-6);
  if(!(tolerance > 0)) throw Input_error(Input_error::INVALID_ARGUMENT, "the tolerance must be positive");
  const Intrinsic_mesh<TriangleMesh> im = internal::genus_zero_mesh(tm, np, "polyhedron_compatibility()");
  const internal::Mesh_arrays<TriangleMesh>& m = im.arrays();
  std::vector<int> cv;
  for(const auto& v : corners) cv.push_back(m.vertex_index(v));
  return internal::polyhedron_compatibility_core(m, cv, faces, edge_length, tolerance);
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_POLYHEDRON_COMPATIBILITY_H
