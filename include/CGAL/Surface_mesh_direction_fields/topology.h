// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_TOPOLOGY_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_TOPOLOGY_H

#include <CGAL/Surface_mesh_direction_fields/internal/Mesh_arrays.h>
#include <CGAL/Surface_mesh_direction_fields/internal/topology.h>

#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsTopology
/// Counts and invariants of one connected component of a triangle mesh.
struct Component_topology
{
  std::size_t vertices;        ///< number of (non-isolated) vertices
  std::size_t edges;           ///< number of edges
  std::size_t faces;           ///< number of faces
  std::size_t boundary_loops;  ///< number of boundary loops \f$b\f$
  long euler_characteristic;   ///< \f$\chi = V - E + F\f$
  long genus;                  ///< \f$g = (2 - \chi - b)/2\f$
  long betti_1;                ///< first Betti number: \f$2g\f$ if closed, \f$2g + b - 1\f$ if \f$b \ge 1\f$
};

/// \ingroup PkgSurfaceMeshDirectionFieldsTopology
/// Topological summary of a triangle mesh, see mesh_topology().
template <typename TriangleMesh>
struct Mesh_topology
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;

  /// connected components (through shared edges), ordered by their first face
  std::vector<Component_topology> components;
  /// border halfedges of each boundary loop, in `next()` order
  std::vector<std::vector<halfedge_descriptor>> boundary_loops;
  /// index in `components` of each boundary loop
  std::vector<std::size_t> boundary_loop_component;
  /// vertices with no incident face; they belong to no component
  std::size_t isolated_vertices;

  /// \f$\chi\f$ of the whole mesh (isolated vertices excluded)
  long euler_characteristic() const
  {
    long chi = 0;
    for(const auto& c : components) chi += c.euler_characteristic;
    return chi;
  }
  /// `true` if the mesh has no boundary
  bool is_closed() const { return boundary_loops.empty(); }
  /// sum of the first Betti numbers of the components: the number of homology generators
  long betti_1() const
  {
    long b = 0;
    for(const auto& c : components) b += c.betti_1;
    return b;
  }
};

/// \ingroup PkgSurfaceMeshDirectionFieldsTopology
/// Computes the connected components, boundary loops, Euler characteristic and genus of every
/// component of `tm`.
/// Only connectivity is used; throws `Input_error` if a face is not a triangle or a vertex is
/// non-manifold (a halfedge data structure cannot hold non-manifold edges or inconsistent
/// orientations, so those are rejected when reading, see read_triangle_mesh()).
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{numbers the vertices 0 .. n-1 (the numbers used in error messages); must be a bijection}
///     \cgalParamType{a readable property map with `vertex_descriptor` keys and integer values}
///     \cgalParamDefault{vertices numbered in the order of `vertices(tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_index_map, edge_index_map}
///     \cgalParamDescription{the same for faces and edges}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
Mesh_topology<TriangleMesh> mesh_topology(const TriangleMesh& tm,
                                          const NamedParameters& np = parameters::default_values())
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  internal::Mesh_arrays<TriangleMesh> m(tm, np, typename internal::Mesh_arrays<TriangleMesh>::Connectivity_only());
  internal::Topology_arrays t(m);
  Mesh_topology<TriangleMesh> r;
  for(const auto& c : t.components)
    r.components.push_back(Component_topology{c.vertices, c.edges, c.faces, c.boundary_loops,
                                              c.euler_characteristic(), c.genus(), c.betti_1()});
  for(std::size_t i = 0; i < t.loops.size(); ++i) {
    std::vector<halfedge_descriptor> loop;
    for(int h : t.loops[i]) loop.push_back(m.halfedge_descriptor_of(h, tm));
    r.boundary_loops.push_back(loop);
    r.boundary_loop_component.push_back(std::size_t(t.loop_component[i]));
  }
  r.isolated_vertices = t.isolated_vertices;
  return r;
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_TOPOLOGY_H
