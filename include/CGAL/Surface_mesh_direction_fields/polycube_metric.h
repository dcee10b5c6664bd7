// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_POLYCUBE_METRIC_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_POLYCUBE_METRIC_H

// Metric compensation by a polyhedron (Lai et al. 2010, section 4.1.3.2): a genus-0 surface
// with a corner vertex per corner of P is cut along paths between them into P's faces, each
// mapped onto its polygon, and the metric is P's, whose holonomy lies in the grid's symmetry
// group. box_polycube_metric() for a box (scaled along its axes), polyhedron_metric() for any
// sphere of squares and equilateral triangles; the engine is in internal/polyhedron_charts.h.

#include <CGAL/Surface_mesh_direction_fields/Intrinsic_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/polyhedron_metric_status.h>
#include <CGAL/Surface_mesh_direction_fields/internal/polyhedron_charts.h>

#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// Whether the polyhedron of `faces` (cycles of corner indices \f$0 \ldots 7\f$, counterclockwise
/// seen from outside, as for polyhedron_metric()) is a box: six quadrilaterals, three at every
/// corner, glued as a cube's. If so, `order[i]` is set to the corner that box_polycube_metric()
/// places at \f$(i \& 1, (i \gg 1) \& 1, (i \gg 2) \& 1)\f$, with the same faces and
/// orientation, so that a box given as a list of faces can get the box's own scaling along its
/// three axes (`smdf remesh --polycube FILE` does this).
inline bool box_corner_order(const std::vector<std::vector<int>>& faces, std::array<int, 8>& order)
{
  if(faces.size() != 6) return false;
  for(const auto& f : faces) {
    if(f.size() != 4) return false;
    for(int c : f) if(c < 0 || c > 7) return false;
  }
  std::vector<std::vector<int>> box;
  std::vector<std::array<int, 2>> axes;
  internal::box_faces(box, axes);
  const std::vector<std::vector<int>> turn = internal::corner_turns(faces, 8), box_turn = internal::corner_turns(box, 8);
  int q0 = -1;   // a neighbour of corner 0
  for(int q = 0; q < 8 && q0 < 0; ++q) if(turn[0][std::size_t(q)] >= 0) q0 = q;
  if(q0 < 0) return false;
  // corner 0 at the box's corner 0 and q0 at corner 1; the box's rotations about its diagonal
  // give the other two choices, equally good
  std::array<int, 8> o;
  o.fill(-1);
  o[0] = 0;
  int q = q0, b = 1;
  for(int k = 0; k < 3; ++k) {
    if(q < 0) return false;
    o[std::size_t(b)] = q;
    q = turn[0][std::size_t(q)];
    b = box_turn[0][std::size_t(b)];
  }
  if(q != q0) return false;   // corner 0 has three faces
  auto common = [&](int x, int y) {   // the corner other than 0 next to both
    int found = -1;
    for(int c = 1; c < 8; ++c)
      if(c != x && c != y && turn[std::size_t(c)][std::size_t(x)] >= 0 && turn[std::size_t(c)][std::size_t(y)] >= 0) {
        if(found >= 0) return -1;
        found = c;
      }
    return found;
  };
  o[3] = common(o[1], o[2]);
  o[5] = common(o[1], o[4]);
  o[6] = common(o[2], o[4]);
  std::array<char, 8> used{};
  for(int i = 0; i < 7; ++i)
    if(o[std::size_t(i)] < 0 || used[std::size_t(o[std::size_t(i)])]++) return false;
  for(int c = 0; c < 8; ++c) if(!used[std::size_t(c)]) o[7] = c;
  // every face of the box, relabelled, must be a face of the polyhedron, in the same direction
  for(const auto& bf : box) {
    bool found = false;
    for(const auto& f : faces)
      for(std::size_t r = 0; r < 4 && !found; ++r) {
        bool same = true;
        for(std::size_t k = 0; k < 4; ++k) same = same && f[(k + r) % 4] == o[std::size_t(bf[k])];
        found = same;
      }
    if(!found) return false;
  }
  order = o;
  return true;
}

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// Metric compensation with a box (Lai et al. 2010, section 4.1.3.2, for the polycube with one
/// cube): the eight `corners` of a closed genus-0 mesh (corner \f$i\f$ goes to the box corner
/// \f$(i \& 1, (i \gg 1) \& 1, (i \gg 2) \& 1)\f$) are joined by the twelve shortest edge paths
/// of the box's edges (Dijkstra, each path avoiding the earlier ones and the other corners;
/// for Lai et al. under the flat cone metric with cones of \f$\pi/2\f$ at the corners, given by
/// its conformal factors), which cut the mesh into six disks; each disk is mapped onto its face
/// of the box by a Tutte embedding with symmetrised mean value weights (Floater 2003; any
/// positive weights make it bijective onto the convex rectangle), its boundary placed by arc length on the input
/// surface along the four paths. The embedding is then made as close to an isometry of the input
/// surface as its bijectivity allows, in two stages: a second Tutte embedding whose weights are
/// divided by the L2 stretch of the first at their far ends (one round of Yoshizawa, Belyaev and
/// Seidel 2004, kept if the stretch falls; more rounds lower it further but leave the next stage
/// more sheared triangles); then as-rigid-as-possible steps (Liu et al. 2008) over all six faces
/// at once, the path vertices sliding along the box's edges (one unknown each, shared by the two
/// faces beside the path), every step cut short where a triangle would lose half its area; last,
/// the vertices within 8 edges of each path are relaxed once more in the plane where the two box
/// faces beside it are unfolded, without the path, so that its zigzag along the mesh's edges
/// does not shear the triangles beside it (`seam_relaxed_vertices` in the status). The
/// box's sides are the mean lengths on the surface of their four parallel paths, scaled so that
/// the box has the surface's area and rounded to multiples of `edge_length`. The output metric
/// (`lengths`, on `tm`'s triangulation) is the box's: flat but for cones of \f$\pi/2\f$ at the
/// corners, with cut-graph motions that are symmetries of the square grid of edge length
/// `edge_length`, so tessellate_flat_metric() accepts it.
///
/// Lai et al. flatten each disk to a rectangle by Ricci flow with corner curvatures
/// \f$\pi/2\f$ and then scale the rectangles: `segment_flattening(RICCI_FLOW_SEGMENTS)`. The two
/// sides of a path then disagree on where its vertices go (their mean is taken), and a conformal
/// map shrinks protrusions exponentially (a remesh then cuts them off). The default,
/// `RELAXED_SEGMENTS`, shares each path vertex between its two sides, which keeps the sides
/// consistent by construction, and its relaxation towards the input's own triangles gives every
/// part of the surface grid cells of about the same size: on Spot, the remesh's area is within
/// 0.5 % of the input's and every input vertex within one edge length of it, against 2.8 % and
/// up to 5 edge lengths with the plain Tutte embedding (the manual compares the two methods).
///
/// Named parameters: `edge_length_map` (the metric \f$\ell\f$ of the path lengths and of the
/// angles of the first mean value weights; default: Euclidean lengths) or `intrinsic_mesh`;
/// `conformal_factor_map` (a readable vertex map of conformal factors \f$u\f$: the paths are
/// then shortest under the lengths \f$\ell_{ij} e^{(u_i + u_j)/2}\f$ of the mesh's edges, the
/// flat cone metric of Lai et al. when \f$u\f$ is the `conformal_factor_map` output of
/// compute_cone_metric() with these cones; this works whatever triangulation the flow ended
/// on, intrinsic edge flips included, since the factors live on the vertices; a
/// `curvature_tolerance` of \f$10^{-6}\f$ is plenty for edge paths and saves a Newton step or
/// two on large meshes; default: none);
/// `number_of_iterations` (default 10: at most that many as-rigid-as-possible steps, after the
/// one reweighting round, fewer once a triangle about to fold throttles a step below 1 % of its
/// length; 0 keeps the plain Tutte embedding, the path lengths and the arc lengths then
/// in the metric of `edge_length_map`, the box's sides unscaled); `vertex_point_map` (the input
/// surface the relaxation measures against); `seam_relaxation_rings` (default 8: the width, in
/// edges, of the bands beside the paths relaxed across the box's edges; 0 leaves the paths
/// straight; on Spot at 100k faces and as many quads, 8 rings give 5 quads with a negative scaled
/// Jacobian, 4 rings 14, 16 rings 12, none 145); `segment_flattening` (default
/// `RELAXED_SEGMENTS`; `RICCI_FLOW_SEGMENTS` for Lai et al.'s segments, which ignores
/// `number_of_iterations` and `seam_relaxation_rings` but for the box's sides); and the index maps.
/// Failures (a path that cannot avoid the earlier ones, pieces that do not match the box's
/// faces, a degenerate triangle) are in the status; `Input_error` for a mesh that is not a
/// closed genus-0 surface or corners that are not eight distinct vertices.
template <typename TriangleMesh, typename EdgeLengthMap, typename NamedParameters = parameters::Default_named_parameters>
Polycube_metric_status box_polycube_metric(const TriangleMesh& tm,
                                           const std::array<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, 8>& corners,
                                           double edge_length, EdgeLengthMap lengths,
                                           const NamedParameters& np = parameters::default_values())
{
  if(!(edge_length > 0) || !std::isfinite(edge_length))
    throw Input_error(Input_error::INVALID_ARGUMENT, "the edge length must be positive, got " + std::to_string(edge_length));
  const Intrinsic_mesh<TriangleMesh> im = internal::genus_zero_mesh(tm, np, "box_polycube_metric()");
  const internal::Mesh_arrays<TriangleMesh>& m = im.arrays();
  std::vector<int> cv;
  for(const auto& v : corners) cv.push_back(m.vertex_index(v));
  std::vector<std::vector<int>> pfaces;
  std::vector<std::array<int, 2>> plane_axes;
  internal::box_faces(pfaces, plane_axes);
  const internal::Chart_inputs in = internal::chart_inputs(tm, m, np);
  std::array<double, 3> dims{{0, 0, 0}};
  bool dims_known = false;
  auto polygon = [&](std::size_t j, const std::function<double(int, int)>& path_length) {
    if(!dims_known) {   // each side: the mean of its four paths, the box scaled to the input's area, in multiples of the edge length
      std::array<double, 3> mean{{0, 0, 0}};
      for(int a = 0; a < 3; ++a)
        for(int i = 0; i < 8; ++i) if(!(i & (1 << a))) mean[std::size_t(a)] += path_length(i, i | (1 << a)) / 4;
      const double box_area = 2 * (mean[0] * mean[1] + mean[1] * mean[2] + mean[2] * mean[0]);
      const double scale = in.iterations > 0 && box_area > 0 ? std::sqrt(in.area / box_area) : 1.;
      for(int a = 0; a < 3; ++a) dims[std::size_t(a)] = edge_length * (std::max)(1., std::round(scale * mean[std::size_t(a)] / edge_length));
      dims_known = true;
    }
    const int x = plane_axes[j][0], y = plane_axes[j][1];
    std::vector<Point_2> p;
    for(int c : pfaces[j]) p.push_back(Point_2(((c >> x) & 1) * dims[std::size_t(x)], ((c >> y) & 1) * dims[std::size_t(y)]));
    return p;
  };
  std::vector<double> l;
  Polycube_metric_status st = internal::polyhedron_metric_core(m, cv, pfaces, polygon, in, l);
  st.dimensions = dims;
  if(st.success) for(std::size_t e = 0; e < l.size(); ++e) put(lengths, m.edges[e], l[e]);
  return st;
}

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// Metric compensation with a polyhedron P made of squares and equilateral triangles of side
/// `side_length` (Lai et al. 2010, section 4.1.3.2: P's vertices are the cones, its faces
/// quadrilaterals or triangles): `corners` are the mesh vertices of P's vertices, `faces` P's
/// faces as cycles of indices into `corners`, counterclockwise seen from outside. The mesh is cut
/// along shortest edge paths of P's edges and every piece embedded onto its square or triangle
/// as in box_polycube_metric(). The output metric has a cone at each of P's vertices of
/// curvature \f$2\pi\f$ minus its polygons' angles (\f$\pi/2\f$ per square, \f$\pi/3\f$ per
/// triangle): the octahedron's six cones of \f$2\pi/3\f$, an obelisk's mix. Its holonomy is in
/// the square grid's group when P has only squares, in the triangular grid's when it has only
/// triangles; a side length that is a multiple of the grid's edge length makes the cones grid
/// points. The embedding is relaxed towards the input's triangles as in box_polycube_metric()
/// (a `side_length` that gives P the surface's area suits it best). Named parameters and
/// failures as for box_polycube_metric(); `Input_error` also for a P that is not a closed
/// oriented sphere or has faces other than triangles and quadrilaterals.
template <typename TriangleMesh, typename EdgeLengthMap, typename NamedParameters = parameters::Default_named_parameters>
Polycube_metric_status polyhedron_metric(const TriangleMesh& tm,
                                         const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& corners,
                                         const std::vector<std::vector<int>>& faces, double side_length, EdgeLengthMap lengths,
                                         const NamedParameters& np = parameters::default_values())
{
  if(!(side_length > 0) || !std::isfinite(side_length))
    throw Input_error(Input_error::INVALID_ARGUMENT, "the side length must be positive, got " + std::to_string(side_length));
  for(const auto& f : faces)
    if(f.size() != 3 && f.size() != 4)
      throw Input_error(Input_error::INVALID_ARGUMENT, "the polyhedron's faces must be triangles or quadrilaterals, got one with " +
                                                           std::to_string(f.size()) + " corners");
  const Intrinsic_mesh<TriangleMesh> im = internal::genus_zero_mesh(tm, np, "polyhedron_metric()");
  const internal::Mesh_arrays<TriangleMesh>& m = im.arrays();
  std::vector<int> cv;
  for(const auto& v : corners) cv.push_back(m.vertex_index(v));
  const double L = side_length;
  auto polygon = [&](std::size_t j, const std::function<double(int, int)>&) {
    return faces[j].size() == 4 ? std::vector<Point_2>{Point_2(0, 0), Point_2(L, 0), Point_2(L, L), Point_2(0, L)}
                                : std::vector<Point_2>{Point_2(0, 0), Point_2(L, 0), Point_2(L / 2, L * std::sqrt(3.) / 2)};
  };
  std::vector<double> l;
  Polycube_metric_status st = internal::polyhedron_metric_core(m, cv, faces, polygon, internal::chart_inputs(tm, m, np), l);
  if(st.success) for(std::size_t e = 0; e < l.size(); ++e) put(lengths, m.edges[e], l[e]);
  return st;
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_POLYCUBE_METRIC_H
