// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_TESSELLATION_ON_INPUT_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_TESSELLATION_ON_INPUT_H

// A remesh tessellated on an intrinsic triangulation, placed on the input surface through the
// triangulation's common subdivision with the input (DESIGN.md section 9).

#include <CGAL/Surface_mesh_direction_fields/Intrinsic_triangulation.h>
#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/grid_tessellation.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// Places a remesh made by tessellate_flat_metric() on a copy of an intrinsic triangulation
/// (copy_intrinsic_triangulation()) on the input surface: every output vertex goes to the input
/// point that its location on the intrinsic triangulation (`st.vertex_locations`) corresponds to
/// (`it.locate_on_input()`, the common subdivision's projective map), at the barycentric
/// combination of that input face's corners. Placed by the intrinsic triangles' corners instead,
/// the vertices would lie on chords across the surface.
///
/// \param it the intrinsic triangulation, with its common subdivision (`has_common_subdivision()`)
/// \param tm the input mesh `it` was computed for
/// \param st the status of the tessellation of `it`'s copy: `vertex_locations` has one entry per
///   vertex of `out`
/// \param out the remesh; its vertex points are replaced
/// \param np `vertex_point_map` of `tm`
///
/// Throws `Input_error` if `it` has no common subdivision or the locations do not match `out`.
template <typename TriangleMesh, typename PolygonMesh, typename NamedParameters = parameters::Default_named_parameters>
void place_tessellation_on_input(const Intrinsic_triangulation& it, const TriangleMesh& tm, const Grid_tessellation_status& st, PolygonMesh& out,
                                 const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  if(!it.has_common_subdivision())
    throw Input_error(Input_error::INVALID_ARGUMENT, "place_tessellation_on_input(): the triangulation has no common subdivision with the input");
  if(st.vertex_locations.size() != num_vertices(out))
    throw Input_error(Input_error::INVALID_ARGUMENT, "place_tessellation_on_input(): " + std::to_string(st.vertex_locations.size()) +
                                                         " locations for " + std::to_string(num_vertices(out)) + " vertices");
  typedef typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
  VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  typedef typename boost::property_traits<typename boost::property_map<PolygonMesh, CGAL::vertex_point_t>::type>::value_type Out_point;
  std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> input_faces(faces(tm).begin(), faces(tm).end());
  auto opm = get(CGAL::vertex_point, out);
  std::size_t i = 0;
  for(auto v : vertices(out)) {
    const Surface_point q = it.locate_on_input(st.vertex_locations[i++]);
    const auto h = halfedge(input_faces[std::size_t(q.face)], tm);
    const auto& a = get(vpm, source(h, tm));
    const auto& b = get(vpm, target(h, tm));
    const auto& c = get(vpm, target(next(h, tm), tm));
    const std::array<double, 3>& w = q.barycentric;
    put(opm, v, Out_point(w[0] * CGAL::to_double(a.x()) + w[1] * CGAL::to_double(b.x()) + w[2] * CGAL::to_double(c.x()),
                          w[0] * CGAL::to_double(a.y()) + w[1] * CGAL::to_double(b.y()) + w[2] * CGAL::to_double(c.y()),
                          w[0] * CGAL::to_double(a.z()) + w[1] * CGAL::to_double(b.z()) + w[2] * CGAL::to_double(c.z())));
  }
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_TESSELLATION_ON_INPUT_H
