// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_VERTEX_FIELD_EMBEDDING_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_VERTEX_FIELD_EMBEDDING_H

// Vertex-based fields (Lai et al. 2010, section 4.1) and the embedding: each vertex's tangent
// frame in 3D, and the conversions between vertex angles and 3D vectors.

#include <CGAL/Surface_mesh_direction_fields/Intrinsic_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/parameters.h>

#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

namespace internal {

// The embedded tangent frame of every vertex (Lai et al., section 4.1): the unit normal is the
// area-weighted mean of the face normals, e1 the reference halfedge vertex_out[v] projected on
// the tangent plane, e2 = n x e1; zero vectors at isolated vertices.
struct Embedded_vertex_frames
{
  typedef std::array<double, 3> V3;
  std::vector<V3> e1, e2;

  template <typename TM, typename VPM>
  Embedded_vertex_frames(const Mesh_arrays<TM>& m, const VPM& vpm)
    : e1(m.number_of_vertices(), V3{{0, 0, 0}}), e2(m.number_of_vertices(), V3{{0, 0, 0}})
  {
    auto point = [&](int v) {
      const auto& p = get(vpm, m.vertices[std::size_t(v)]);
      return V3{{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
    };
    std::vector<V3> normal(m.number_of_vertices(), V3{{0, 0, 0}});
    for(std::size_t f = 0; f < m.number_of_faces(); ++f) {
      const int h0 = m.face_halfedge[f], h1 = m.next[std::size_t(h0)];
      const int a = m.source(h0), b = m.target[std::size_t(h0)], c = m.target[std::size_t(h1)];
      const V3 n = cross(sub(point(b), point(a)), sub(point(c), point(a)));   // twice the area times the unit normal
      for(int v : {a, b, c}) for(std::size_t i = 0; i < 3; ++i) normal[std::size_t(v)][i] += n[i];
    }
    for(std::size_t v = 0; v < m.number_of_vertices(); ++v) {
      if(m.is_isolated(int(v))) continue;
      V3 n = normal[v];
      const double nn = std::sqrt(dot(n, n));
      for(double& x : n) x /= (nn > 0 ? nn : 1);
      V3 e = sub(point(m.target[std::size_t(m.vertex_out[v])]), point(int(v)));
      const double en = dot(e, n);
      for(std::size_t i = 0; i < 3; ++i) e[i] -= en * n[i];
      const double el = std::sqrt(dot(e, e));
      for(double& x : e) x /= (el > 0 ? el : 1);
      e1[v] = e;
      e2[v] = cross(n, e);
    }
  }
  static V3 sub(const V3& a, const V3& b) { return V3{{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; }
  static V3 cross(const V3& a, const V3& b) { return V3{{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}}; }
  static double dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
};

} // namespace internal

/// \ingroup PkgSurfaceMeshDirectionFieldsFieldDesign
/// Pulls a vertex-based field back to the embedding (Lai et al., section 4.1): the tangent plane
/// at a vertex is orthogonal to the area-weighted mean of its face normals, and the direction of
/// angle \f$a\f$ (in the vertex frames of rotation_compensated_field()) is the reference
/// halfedge projected on that plane and turned by \f$a\f$ counterclockwise about the normal.
/// Named parameters: `vertex_point_map` and the index maps (as given to
/// rotation_compensated_field(), so that the reference halfedges are the same).
template <typename TriangleMesh, typename VertexAngleMap, typename VertexVectorMap,
          typename NamedParameters = parameters::Default_named_parameters>
void vertex_field_to_vectors(const TriangleMesh& tm, const VertexAngleMap& angles, VertexVectorMap vectors,
                             const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename boost::property_traits<VertexVectorMap>::value_type Vector;
  const Intrinsic_mesh<TriangleMesh> im = internal::get_intrinsic_mesh(tm, np);
  const internal::Mesh_arrays<TriangleMesh>& m = im.arrays();
  const internal::Embedded_vertex_frames frames(
      m, choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm)));
  for(std::size_t v = 0; v < m.number_of_vertices(); ++v) {
    const auto& e = frames.e1[v];
    const auto& t = frames.e2[v];
    const double a = double(get(angles, m.vertices[v]));
    put(vectors, m.vertices[v], Vector(std::cos(a) * e[0] + std::sin(a) * t[0], std::cos(a) * e[1] + std::sin(a) * t[1],
                                      std::cos(a) * e[2] + std::sin(a) * t[2]));
  }
}

/// \ingroup PkgSurfaceMeshDirectionFieldsFieldDesign
/// The inverse of vertex_field_to_vectors(): the angle, in the vertex frames of
/// rotation_compensated_field() and in \f$[0, 2\pi)\f$, of each vertex's 3D vector projected on
/// the vertex's tangent plane (e.g. a direction constraint for `Rosy_vertex_field_editor`
/// given in 3D). A vector along the normal, or zero, gives angle 0. Named parameters as for
/// vertex_field_to_vectors().
template <typename TriangleMesh, typename VertexVectorMap, typename VertexAngleMap,
          typename NamedParameters = parameters::Default_named_parameters>
void vertex_vectors_to_angles(const TriangleMesh& tm, const VertexVectorMap& vectors, VertexAngleMap angles,
                              const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const Intrinsic_mesh<TriangleMesh> im = internal::get_intrinsic_mesh(tm, np);
  const internal::Mesh_arrays<TriangleMesh>& m = im.arrays();
  const internal::Embedded_vertex_frames frames(
      m, choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm)));
  for(std::size_t v = 0; v < m.number_of_vertices(); ++v) {
    const auto& x = get(vectors, m.vertices[v]);
    const internal::Embedded_vertex_frames::V3 d{{CGAL::to_double(x[0]), CGAL::to_double(x[1]), CGAL::to_double(x[2])}};
    const double c = internal::Embedded_vertex_frames::dot(d, frames.e1[v]), s = internal::Embedded_vertex_frames::dot(d, frames.e2[v]);
    const double a = (c == 0 && s == 0) ? 0. : std::atan2(s, c);
    put(angles, m.vertices[v], a < 0 ? a + 2 * CGAL_PI : a);
  }
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_VERTEX_FIELD_EMBEDDING_H
