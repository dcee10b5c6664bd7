// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_HOMOLOGY_GENERATORS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_HOMOLOGY_GENERATORS_H

#include <CGAL/Surface_mesh_direction_fields/internal/Mesh_arrays.h>
#include <CGAL/Surface_mesh_direction_fields/internal/topology.h>
#include <CGAL/Surface_mesh_direction_fields/internal/tree_cotree.h>

#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsTopology
/// The two kinds of homology generators.
enum Generator_kind {
  HANDLE_GENERATOR,   ///< a non-contractible loop of a handle (2g per component)
  BOUNDARY_GENERATOR  ///< a loop around a boundary component (all but one per component)
};

/// \ingroup PkgSurfaceMeshDirectionFieldsTopology
/// One generator of the first homology group of a mesh, given both as a dual cycle and as a
/// primal edge loop. See tree_cotree_generators().
template <typename TriangleMesh>
struct Homology_generator
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;

  /// handle loop or boundary loop
  Generator_kind kind;
  /// index of the connected component, as in mesh_topology()
  std::size_t component;
  /// The dual cycle, as the sequence of halfedges it crosses: the \f$i\f$-th element `h`
  /// means "cross the edge of `h` from `face(opposite(h))` into `face(h)`". Consecutive
  /// elements share a face, and the last element enters the face the first one leaves.
  std::vector<halfedge_descriptor> dual_cycle;
  /// A primal edge loop: halfedges with `target` of each equal to `source` of the next,
  /// closing up. For a handle generator it is the tree loop of the same leftover edge as
  /// `dual_cycle` (they cross exactly once); for a boundary generator it is the boundary loop,
  /// oriented with the mesh on its left, and `dual_cycle` runs beside it.
  std::vector<halfedge_descriptor> primal_loop;
};

namespace internal {

// Index-based generators to descriptor-based ones.
template <typename TriangleMesh>
std::vector<Homology_generator<TriangleMesh>>
to_homology_generators(const Mesh_arrays<TriangleMesh>& m, const std::vector<Generator_arrays>& gens,
                       const TriangleMesh& tm)
{
  std::vector<Homology_generator<TriangleMesh>> out;
  for(const auto& g : gens) {
    Homology_generator<TriangleMesh> r;
    r.kind = g.handle ? HANDLE_GENERATOR : BOUNDARY_GENERATOR;
    r.component = std::size_t(g.component);
    for(int h : g.dual) r.dual_cycle.push_back(m.halfedge_descriptor_of(h, tm));
    for(int h : g.primal) r.primal_loop.push_back(m.halfedge_descriptor_of(h, tm));
    out.push_back(std::move(r));
  }
  return out;
}

} // namespace internal

/// \ingroup PkgSurfaceMeshDirectionFieldsTopology
/// Computes a basis of the first homology group \f$H_1(M;\mathbb{Z})\f$ of every connected
/// component of `tm` by the tree-cotree decomposition (Eppstein 2003), extended to surfaces with
/// boundary as in section 2.6 of Crane, Desbrun and Schröder (2010).
///
/// Each boundary loop is treated as if it were capped by a virtual face. A primal spanning tree
/// \f$T\f$ (breadth-first) contains every boundary loop minus one edge; a dual spanning tree
/// \f$T^*\f$ joins the faces through edges not in \f$T\f$, with each virtual face a leaf on its
/// one remaining boundary edge. Each of the \f$2g\f$ edges in neither tree closes one dual cycle
/// in \f$T^*\f$ (which therefore never crosses the boundary) and one primal loop in \f$T\f$:
/// the handle generators. Then every boundary loop but the last of its component is added as a
/// boundary generator (the last one is the negated sum of the others plus the dual cells of
/// the interior vertices). Per component, the number of generators is the first Betti number
/// \f$b_1 = 2g\f$ when closed and \f$2g + b - 1\f$ with \f$b \ge 1\f$ boundary loops, and
/// together with the dual cells of interior vertices they span all dual cycles.
///
/// Handle generators come first (ordered by leftover edge index), then boundary generators
/// (ordered as the loops of mesh_topology()). Runs in linear time.
/// Throws `Input_error` for non-triangle faces and non-manifold vertices.
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
/// Named parameters: `vertex_index_map`, `face_index_map`, `edge_index_map` as in mesh_topology().
/// The generators depend on the numbering (the trees grow in index order).
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
std::vector<Homology_generator<TriangleMesh>>
tree_cotree_generators(const TriangleMesh& tm, const NamedParameters& np = parameters::default_values())
{
  internal::Mesh_arrays<TriangleMesh> m(tm, np, typename internal::Mesh_arrays<TriangleMesh>::Connectivity_only());
  internal::Topology_arrays t(m);
  return internal::to_homology_generators(m, internal::tree_cotree(m, t), tm);
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_HOMOLOGY_GENERATORS_H
