// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_VERTEX_FIELD_FROM_FACES_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_VERTEX_FIELD_FROM_FACES_H

// One vector per vertex from a face-based N-RoSy field (the per-vertex representation of Lai et
// al. 2010, section 4.1, for the fields that are computed per face: parallel, boundary-aligned,
// trivial connection, and any field carried to the input faces).

#include <CGAL/Surface_mesh_direction_fields/Intrinsic_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/field_singularities.h>
#include <CGAL/Surface_mesh_direction_fields/parallel_rosy_field.h>
#include <CGAL/Surface_mesh_direction_fields/rotation_compensation.h>

#include <cmath>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsFieldDesign
/// A vertex field of unit 3D vectors from a face field given by angles in the embedded face
/// frames (as transfer_face_field_to_input() and face_field_in_embedding() produce them, or any
/// field on the embedding's metric) and its matching. Each face's direction is first mapped to
/// 3D as field_angles_to_vectors() maps it; the tangent plane at a vertex is the one of
/// vertex_field_to_vectors() (orthogonal to the area-weighted mean normal). Then:
/// - at an interior vertex, the \f$N\f$-th power mean of the faces' directions projected on the
///   tangent plane, weighted by the corner angles (one of the \f$N\f$ directions; the others
///   are it turned by multiples of \f$2\pi/N\f$ about the normal);
/// - at a boundary vertex, the field of the face of one of its two border edges, at the same
///   angle to that edge projected on the tangent plane as in the face: a field along or across
///   the boundary on the boundary faces stays exactly so at the boundary vertices. The edge is
///   one its face's field is drawn against by field_angles_to_vectors() (a face's only border
///   edge; of two, the one that ends at their common corner), the outgoing one if it is;
/// - at a singularity of the field (read back with `matching`, a non-zero index), the zero
///   vector: no direction is defined there.
///
/// Returns the number of singular vertices. Named parameters: `vertex_point_map` and the index
/// maps. Throws `Input_error` for \f$N < 1\f$ and the errors of `Intrinsic_mesh`.
template <typename TriangleMesh, typename FaceAngleMap, typename EdgeMatchingMap, typename VertexVectorMap,
          typename NamedParameters = parameters::Default_named_parameters>
std::size_t vertex_field_from_face_field(const TriangleMesh& tm, int N, const FaceAngleMap& face_angles,
                                         const EdgeMatchingMap& matching, VertexVectorMap vectors,
                                         const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename boost::property_traits<VertexVectorMap>::value_type Vector;
  if(N < 1) throw Input_error(Input_error::INVALID_ARGUMENT, "symmetry order N must be at least 1, got " + std::to_string(N));
  const Intrinsic_mesh<TriangleMesh> im = internal::get_intrinsic_mesh(tm, np);
  const internal::Mesh_arrays<TriangleMesh>& m = im.arrays();
  const std::size_t nv = m.number_of_vertices(), nf = m.number_of_faces();
  auto fvec = get(CGAL::dynamic_face_property_t<Vector>(), tm);
  field_angles_to_vectors(tm, face_angles, fvec, np);
  std::vector<internal::Embedded_vertex_frames::V3> d(nf);
  for(std::size_t f = 0; f < nf; ++f) {
    const Vector x = get(fvec, m.faces[f]);
    d[f] = {{CGAL::to_double(x[0]), CGAL::to_double(x[1]), CGAL::to_double(x[2])}};
  }
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  const internal::Embedded_vertex_frames frames(m, vpm);
  std::vector<char> singular(nv, 0);
  const Field_topology<TriangleMesh> ft = field_singularities(tm, face_angles, parameters::symmetry_order(N).matching(matching));
  std::size_t count = 0;
  for(const auto& s : ft.singularities) {
    const auto v = std::size_t(m.vertex_index(s.first));
    if(!singular[v]) ++count;
    singular[v] = 1;
  }
  typedef internal::Embedded_vertex_frames F;
  for(std::size_t v = 0; v < nv; ++v) {
    double a = 0, c = 0, s = 0;
    bool defined = !singular[v] && !m.is_isolated(int(v));
    if(defined && m.is_boundary_vertex(int(v))) {
      // a border edge at v that its face's field is drawn against: the outgoing one, else the
      // incoming one (one of them is, internal::followed_border_halfedge())
      const int out = m.vertex_out[v];   // leaves v, its opposite on the border
      int b = out;                       // counterclockwise to the border halfedge leaving v
      for(std::size_t guard = 0; m.face[std::size_t(b)] >= 0 && guard < m.number_of_halfedges(); ++guard) b = m.ccw_out(b);
      const int in = b ^ 1;              // arrives at v, its opposite on the border
      int h = internal::followed_border_halfedge(m, m.face[std::size_t(out)]) == out ? out : in;
      if(internal::followed_border_halfedge(m, m.face[std::size_t(h)]) != h)
        h = internal::followed_border_halfedge(m, m.face[std::size_t(out)]);   // (a lone triangle)
      // the face's angle with that edge, kept against the edge projected on the tangent plane
      const std::size_t f = std::size_t(m.face[std::size_t(h)]);
      const auto p = get(vpm, m.vertices[std::size_t(m.source(h))]), q = get(vpm, m.vertices[std::size_t(m.target[std::size_t(h)])]);
      const F::V3 ev{{CGAL::to_double(q.x() - p.x()), CGAL::to_double(q.y() - p.y()), CGAL::to_double(q.z() - p.z())}};
      c = F::dot(ev, frames.e1[v]);
      s = F::dot(ev, frames.e2[v]);
      a = std::atan2(s, c) + double(get(face_angles, m.faces[f])) - internal::halfedge_direction(m, h);
      defined = c != 0 || s != 0;
    } else if(defined) {
      const int h0 = m.vertex_out[v];
      int h = h0;
      do {
        const std::size_t f = std::size_t(m.face[std::size_t(h)]);
        const double phi = std::atan2(F::dot(d[f], frames.e2[v]), F::dot(d[f], frames.e1[v]));
        c += m.angle[std::size_t(h)] * std::cos(N * phi);
        s += m.angle[std::size_t(h)] * std::sin(N * phi);
        h = m.ccw_out(h);
      } while(h != h0);
      a = std::atan2(s, c) / N;
      defined = c != 0 || s != 0;
    }
    if(!defined) { put(vectors, m.vertices[v], Vector(0, 0, 0)); continue; }
    const auto& e = frames.e1[v];
    const auto& t = frames.e2[v];
    put(vectors, m.vertices[v], Vector(std::cos(a) * e[0] + std::sin(a) * t[0], std::cos(a) * e[1] + std::sin(a) * t[1],
                                      std::cos(a) * e[2] + std::sin(a) * t[2]));
  }
  return count;
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_VERTEX_FIELD_FROM_FACES_H
