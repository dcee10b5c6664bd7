// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_HOMOTOPY_BASIS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_HOMOTOPY_BASIS_H

// A basis of the fundamental group of the punctured surface (Lai et al. 2010, section 3.2 and
// Figure 9): the mesh minus its cones, with every loop through one base face.

#include <CGAL/Surface_mesh_direction_fields/Intrinsic_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/internal/development.h>

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsHolonomy
/// The kinds of loops of a `Homotopy_basis`.
enum Homotopy_loop_kind {
  HANDLE_LOOP,    ///< \f$a_k\f$ or \f$b_k\f$: a non-contractible loop of a handle (a tree-cotree handle generator)
  BOUNDARY_LOOP,  ///< a loop around a boundary component (a tree-cotree boundary generator)
  CONE_LOOP       ///< \f$c_i\f$: a loop around one cone, counterclockwise, enclosing no other cone
};

/// \ingroup PkgSurfaceMeshDirectionFieldsHolonomy
/// One loop of a `Homotopy_basis`.
template <typename TriangleMesh>
struct Homotopy_loop
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;

  Homotopy_loop_kind kind = HANDLE_LOOP;
  /// with `CONE_LOOP`: the cone the loop goes around
  vertex_descriptor cone = boost::graph_traits<TriangleMesh>::null_vertex();
  /// with `HANDLE_LOOP` and `BOUNDARY_LOOP`: the index of the generator in `tree_cotree_generators()`
  std::size_t generator = (std::numeric_limits<std::size_t>::max)();
  /// The loop as a dual cycle: the \f$i\f$-th halfedge `h` means "cross the edge of `h` from
  /// `face(opposite(h))` into `face(h)`" (as `Homology_generator::dual_cycle`). It leaves the
  /// base face with its first crossing and enters it with its last.
  std::vector<halfedge_descriptor> dual_cycle;
};

/// \ingroup PkgSurfaceMeshDirectionFieldsHolonomy
/// A basis of the fundamental group \f$\pi_1(\bar M)\f$ of the punctured surface
/// \f$\bar M\f$, the mesh minus its cones (Lai et al. 2010, Figure 9), see homotopy_basis().
///
/// Representation: every loop is a dual cycle (a sequence of faces joined through edges), which
/// never meets a vertex and so never meets a cone; all of them start and end in `base_face`.
/// Their generalised holonomies (holonomy_group()) are therefore rigid motions in one frame,
/// that of the base face. A cone loop is the counterclockwise loop around the cone's dual cell,
/// joined to the base face by a path of a breadth-first dual tree (out and back, the same path),
/// so it encloses that cone and no other; the handle and boundary loops are the tree-cotree
/// generators joined to the base face in the same way. On a closed surface of genus \f$g\f$
/// with \f$n \ge 1\f$ cones there are \f$2g + n - 1\f$ loops (the loop around the last cone is a
/// product of the others); with \f$b \ge 1\f$ boundary loops, \f$2g + b - 1 + n\f$.
template <typename TriangleMesh>
struct Homotopy_basis
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;

  /// the face every loop starts and ends in
  face_descriptor base_face;
  /// the cones, in the order given (on a closed surface the last one has no loop)
  std::vector<vertex_descriptor> cones;
  /// the handle loops (\f$a_1, b_1, \dots\f$), then the boundary loops, then the cone loops
  std::vector<Homotopy_loop<TriangleMesh>> loops;
};

namespace internal {

// Breadth-first tree of the dual graph (faces, joined through interior edges) from one face.
template <typename TM>
struct Dual_tree
{
  std::vector<int> parent;   // per face: the halfedge crossed to enter it (-1 at the root)
  int root = 0;

  Dual_tree(const Mesh_arrays<TM>& m, int root_face) : parent(m.number_of_faces(), -2), root(root_face)
  {
    std::vector<int> queue(1, root);
    parent[std::size_t(root)] = -1;
    for(std::size_t k = 0; k < queue.size(); ++k) {
      const int f = queue[k];
      int h = m.face_halfedge[std::size_t(f)];
      for(int i = 0; i < 3; ++i, h = m.next[std::size_t(h)]) {
        const int g = m.face[std::size_t(h ^ 1)];
        if(g < 0 || parent[std::size_t(g)] != -2) continue;
        parent[std::size_t(g)] = h ^ 1;   // crossing from f into g
        queue.push_back(g);
      }
    }
  }
  bool reaches(int f) const { return parent[std::size_t(f)] != -2; }
  // crossings from the root to f
  std::vector<int> path_to(const Mesh_arrays<TM>& m, int f) const
  {
    std::vector<int> p;
    while(parent[std::size_t(f)] >= 0) {
      p.push_back(parent[std::size_t(f)]);
      f = m.face[std::size_t(parent[std::size_t(f)] ^ 1)];
    }
    std::reverse(p.begin(), p.end());
    return p;
  }
  // root -> start of the cycle, the cycle, back the same way; crossings that undo the previous
  // one are cancelled (free reduction), which keeps the homotopy class
  std::vector<int> based_cycle(const Mesh_arrays<TM>& m, const std::vector<int>& cycle) const
  {
    const std::vector<int> to = path_to(m, m.face[std::size_t(cycle.front() ^ 1)]);
    std::vector<int> all(to);
    all.insert(all.end(), cycle.begin(), cycle.end());
    for(auto it = to.rbegin(); it != to.rend(); ++it) all.push_back(*it ^ 1);
    std::vector<int> out;
    for(int h : all) {
      if(!out.empty() && out.back() == (h ^ 1)) out.pop_back();
      else out.push_back(h);
    }
    return out;
  }
};

// The counterclockwise dual cycle around interior vertex v (halfedges leaving v).
template <typename TM>
std::vector<int> dual_cycle_around(const Mesh_arrays<TM>& m, int v)
{
  std::vector<int> out;
  const int h0 = m.vertex_out[std::size_t(v)];
  int h = h0;
  do {
    h = m.ccw_out(h);
    out.push_back(h);
  } while(h != h0);
  return out;
}

// Checks the cones (interior vertices of the mesh, each once) and returns their indices.
template <typename TM, typename VertexRange>
std::vector<int> cone_indices(const Mesh_arrays<TM>& m, const VertexRange& cones)
{
  std::vector<int> out;
  std::vector<char> seen(m.number_of_vertices(), 0);
  for(const auto& v : cones) {
    const int vi = m.vertex_index(v);
    if(vi < 0 || std::size_t(vi) >= m.number_of_vertices())
      throw Input_error(Input_error::INVALID_ARGUMENT, "cone " + std::to_string(out.size()) + " is not a vertex of the mesh");
    if(m.is_isolated(vi) || m.is_boundary_vertex(vi))
      throw Input_error(Input_error::INVALID_ARGUMENT,
                        "cone vertex " + std::to_string(vi) + " is not an interior vertex (cones must be interior)");
    if(seen[std::size_t(vi)]++)
      throw Input_error(Input_error::INVALID_ARGUMENT, "cone vertex " + std::to_string(vi) + " is given twice");
    out.push_back(vi);
  }
  return out;
}

} // namespace internal

/// \ingroup PkgSurfaceMeshDirectionFieldsHolonomy
/// Computes a basis of the fundamental group of the mesh minus `cones`, every loop through the
/// first face of `faces(tm)` (see `Homotopy_basis` for the representation and the number of
/// loops). The mesh must have one connected component. Only the connectivity is used.
///
/// Throws `Input_error` for meshes of several components, cones that are not interior vertices
/// of the mesh or that are given twice, and the errors of `Intrinsic_mesh`.
/// \tparam VertexRange a range of `vertex_descriptor`
/// Named parameters: `intrinsic_mesh` and the index maps, as for `Intrinsic_mesh`.
template <typename TriangleMesh, typename VertexRange, typename NamedParameters = parameters::Default_named_parameters>
Homotopy_basis<TriangleMesh> homotopy_basis(const TriangleMesh& tm, const VertexRange& cones,
                                            const NamedParameters& np = parameters::default_values())
{
  const Intrinsic_mesh<TriangleMesh> im = internal::get_intrinsic_mesh(tm, np);
  const internal::Mesh_arrays<TriangleMesh>& m = im.arrays();
  const internal::Topology_arrays& topo = im.topology_arrays();
  if(topo.components.size() != 1)
    throw Input_error(Input_error::INVALID_ARGUMENT, "homotopy_basis() needs a mesh of one connected component, this one has " +
                                                     std::to_string(topo.components.size()));
  const std::vector<int> cone = internal::cone_indices(m, cones);
  const internal::Dual_tree<TriangleMesh> tree(m, 0);
  Homotopy_basis<TriangleMesh> basis;
  basis.base_face = m.faces[0];
  for(int c : cone) basis.cones.push_back(m.vertices[std::size_t(c)]);
  auto add = [&](Homotopy_loop_kind kind, const std::vector<int>& cycle) {
    Homotopy_loop<TriangleMesh> loop;
    loop.kind = kind;
    for(int h : tree.based_cycle(m, cycle)) loop.dual_cycle.push_back(m.halfedge_descriptor_of(h, tm));
    basis.loops.push_back(std::move(loop));
    return &basis.loops.back();
  };
  const std::vector<internal::Generator_arrays>& gens = im.generator_arrays();
  for(std::size_t g = 0; g < gens.size(); ++g)
    if(gens[g].handle) add(HANDLE_LOOP, gens[g].dual)->generator = g;
  for(std::size_t g = 0; g < gens.size(); ++g)
    if(!gens[g].handle) add(BOUNDARY_LOOP, gens[g].dual)->generator = g;
  const std::size_t cone_loops = topo.loops.empty() && !cone.empty() ? cone.size() - 1 : cone.size();
  for(std::size_t i = 0; i < cone_loops; ++i)
    add(CONE_LOOP, internal::dual_cycle_around(m, cone[i]))->cone = basis.cones[i];
  return basis;
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_HOMOTOPY_BASIS_H
