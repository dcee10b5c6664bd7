// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTRINSIC_GEOMETRY_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTRINSIC_GEOMETRY_H

#include <CGAL/Surface_mesh_direction_fields/intrinsic_triangle.h>
#include <CGAL/Surface_mesh_direction_fields/Euclidean_edge_length_map.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh_arrays.h>
#include <CGAL/Surface_mesh_direction_fields/internal/development.h>

#include <CGAL/boost/graph/iterator.h>

#include <array>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsIntrinsic
/// Returns the interior angle of `face(h, tm)` at `target(h, tm)`, computed from edge lengths
/// only (see corner_angle(double,double,double)).
/// \pre `h` is not a border halfedge and `face(h, tm)` is a triangle.
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{edge_length_map}
///     \cgalParamDescription{the intrinsic metric: a length per edge}
///     \cgalParamType{a readable property map with `edge_descriptor` keys and `double` values}
///     \cgalParamDefault{Euclidean lengths from `vertex_point_map` (`Euclidean_edge_length_map`)}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the vertex positions, used only when no `edge_length_map` is given}
///     \cgalParamType{a readable property map with `vertex_descriptor` keys and 3D point values}
///     \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters
#ifndef DOXYGEN_RUNNING
          // not a candidate for corner_angle(opposite, a, b) of three lengths (clang instantiates
          // graph_traits<double> otherwise, a hard error)
          , typename = std::enable_if_t<!std::is_arithmetic<TriangleMesh>::value>
#endif
          >
double corner_angle(typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h,
                    const TriangleMesh& tm,
                    const NamedParameters& np = parameters::default_values())
{
  auto len = get_edge_length_map(tm, np);
  const auto n = next(h, tm);
  return corner_angle(double(get(len, edge(next(n, tm), tm))),  // opposite to target(h)
                      double(get(len, edge(h, tm))), double(get(len, edge(n, tm))));
}

/// \ingroup PkgSurfaceMeshDirectionFieldsIntrinsic
/// Returns the cotangent weight \f$w_e = \frac{1}{2}(\cot\alpha + \cot\beta)\f$ of the edge `e`,
/// where \f$\alpha, \beta\f$ are the angles opposite to `e` in its incident faces (one term on a
/// boundary edge). The weight may be negative when \f$\alpha + \beta > \pi\f$; clamping is the
/// caller's choice. Named parameters as in corner_angle().
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
double cotangent_weight(typename boost::graph_traits<TriangleMesh>::edge_descriptor e,
                        const TriangleMesh& tm,
                        const NamedParameters& np = parameters::default_values())
{
  auto len = get_edge_length_map(tm, np);
  double w = 0;
  const auto h0 = halfedge(e, tm);
  for(auto h : {h0, opposite(h0, tm)}) {
    if(is_border(h, tm)) continue;
    const auto n = next(h, tm);
    w += 0.5 * corner_cotangent(double(get(len, e)), double(get(len, edge(n, tm))),
                                double(get(len, edge(next(n, tm), tm))));
  }
  return w;
}

/// \ingroup PkgSurfaceMeshDirectionFieldsIntrinsic
/// Returns the discrete curvature of the vertex `v`: the angle defect
/// \f$K_v = 2\pi - \sum_{\text{corners at } v}\theta\f$ at an interior vertex and the
/// geodesic curvature \f$\kappa_v = \pi - \sum\theta\f$ at a boundary vertex.
/// By the discrete Gauss-Bonnet theorem their sum over a mesh is \f$2\pi\chi\f$
/// (see total_angle_defect()). Named parameters as in corner_angle().
/// \pre `v` is not isolated.
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
double vertex_curvature(typename boost::graph_traits<TriangleMesh>::vertex_descriptor v,
                        const TriangleMesh& tm,
                        const NamedParameters& np = parameters::default_values())
{
  bool boundary = false;
  double sum = 0;
  for(auto h : CGAL::halfedges_around_target(v, tm)) {
    if(is_border(h, tm)) { boundary = true; continue; }
    sum += corner_angle(h, tm, np);
  }
  return (boundary ? CGAL_PI : 2 * CGAL_PI) - sum;
}

/// \ingroup PkgSurfaceMeshDirectionFieldsIntrinsic
/// Returns the angle defect \f$2\pi - \sum\theta\f$ of the interior vertex `v`: the
/// holonomy of the Levi-Civita connection around the dual cell of `v`.
/// Throws `Input_error` if `v` is a boundary vertex (use geodesic_curvature()).
/// Named parameters as in corner_angle().
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
double angle_defect(typename boost::graph_traits<TriangleMesh>::vertex_descriptor v,
                    const TriangleMesh& tm,
                    const NamedParameters& np = parameters::default_values())
{
  if(is_border(v, tm))
    throw Input_error(Input_error::INVALID_ARGUMENT,
                      "angle_defect() called on a boundary vertex; use geodesic_curvature()");
  return vertex_curvature(v, tm, np);
}

/// \ingroup PkgSurfaceMeshDirectionFieldsIntrinsic
/// Returns the geodesic curvature \f$\pi - \sum\theta\f$ of the boundary at the boundary
/// vertex `v` (positive where the boundary turns left, i.e. is convex).
/// Throws `Input_error` if `v` is an interior vertex. Named parameters as in corner_angle().
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
double geodesic_curvature(typename boost::graph_traits<TriangleMesh>::vertex_descriptor v,
                          const TriangleMesh& tm,
                          const NamedParameters& np = parameters::default_values())
{
  if(!is_border(v, tm))
    throw Input_error(Input_error::INVALID_ARGUMENT,
                      "geodesic_curvature() called on an interior vertex; use angle_defect()");
  return vertex_curvature(v, tm, np);
}

/// \ingroup PkgSurfaceMeshDirectionFieldsIntrinsic
/// Writes vertex_curvature() of every non-isolated vertex into `curvature` (isolated vertices
/// get 0) and returns the sum, \f$2\pi\chi\f$ up to rounding.
/// Validates the mesh: throws `Input_error` for non-triangle faces, non-manifold vertices and
/// degenerate faces of the metric.
/// Named parameters as in corner_angle().
///
/// \tparam VertexCurvatureMap a writable property map with `vertex_descriptor` keys and `double` values
template <typename TriangleMesh, typename VertexCurvatureMap,
          typename NamedParameters = parameters::Default_named_parameters>
double compute_vertex_curvatures(const TriangleMesh& tm, VertexCurvatureMap curvature,
                                 const NamedParameters& np = parameters::default_values())
{
  internal::Mesh_arrays<TriangleMesh> m(tm, np);
  std::vector<double> k;
  internal::vertex_curvatures(m, k);
  double total = 0;
  for(std::size_t v = 0; v < k.size(); ++v) {
    put(curvature, m.vertices[v], k[v]);
    total += k[v];
  }
  return total;
}

/// \ingroup PkgSurfaceMeshDirectionFieldsIntrinsic
/// Returns the total curvature of the metric: the sum of angle defects over interior vertices
/// plus the sum of geodesic curvatures over boundary vertices. By the discrete Gauss-Bonnet
/// theorem it equals \f$2\pi\chi\f$ for every metric; the difference measures rounding.
/// Named parameters and validation as in compute_vertex_curvatures().
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
double total_angle_defect(const TriangleMesh& tm,
                          const NamedParameters& np = parameters::default_values())
{
  internal::Mesh_arrays<TriangleMesh> m(tm, np);
  std::vector<double> k;
  internal::vertex_curvatures(m, k);
  // Kahan summation: on 1M vertices a plain sum loses ~1e-10 relative.
  double s = 0, c = 0;
  for(double x : k) { const double y = x - c; const double t = s + y; c = (t - s) - y; s = t; }
  return s;
}

/// \ingroup PkgSurfaceMeshDirectionFieldsIntrinsic
/// Lays out the faces met by a dual path in the plane, each unfolded isometrically onto the
/// previous one across their shared edge (a development, as in Figure 4 of Crane et al.).
///
/// The path starts in `face(opposite(h_1))` and crosses, for each halfedge \f$h_i\f$ of
/// `crossings`, from `face(opposite(h_i))` into `face(h_i)` (the package's orientation of dual
/// edges). The first face is laid out with `source(halfedge(f))` at the origin and
/// `target(halfedge(f))` on the positive x axis. For each of the `crossings.size() + 1` faces,
/// writes a `std::array<Point_2, 3>` with the positions of the sources of `halfedge(f)`,
/// `next(halfedge(f))` and `next(next(halfedge(f)))` to `out`.
/// Throws `Input_error` if consecutive crossings do not share a face or a crossing is a border
/// edge. Named parameters as in corner_angle().
template <typename TriangleMesh, typename HalfedgeRange, typename OutputIterator,
          typename NamedParameters = parameters::Default_named_parameters>
OutputIterator unfold_triangle_strip(const TriangleMesh& tm, const HalfedgeRange& crossings,
                                     OutputIterator out,
                                     const NamedParameters& np = parameters::default_values())
{
  internal::Mesh_arrays<TriangleMesh> m(tm, np);
  std::vector<int> path;
  for(auto h : crossings) path.push_back(m.halfedge_index(h, tm));
  internal::check_dual_path(m, path, false);
  internal::develop(m, path, [&](int, const std::array<Point_2, 3>& p) { *out++ = p; });
  return out;
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTRINSIC_GEOMETRY_H
