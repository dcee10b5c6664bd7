// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_TOPOLOGY_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_TOPOLOGY_H

#include <CGAL/Surface_mesh_direction_fields/internal/Mesh_arrays.h>

#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

struct Component_counts
{
  std::size_t vertices = 0, edges = 0, faces = 0, boundary_loops = 0;
  long euler_characteristic() const { return long(vertices) - long(edges) + long(faces); }
  long genus() const { return (2 - euler_characteristic() - long(boundary_loops)) / 2; }
  // First Betti number: 2g when closed, 2g + b - 1 otherwise.
  long betti_1() const
  {
    return boundary_loops == 0 ? 2 * genus() : 2 * genus() + long(boundary_loops) - 1;
  }
};

// Connected components (through faces), boundary loops and their components.
struct Topology_arrays
{
  std::vector<int> face_component;       // per face
  std::vector<int> vertex_component;     // per vertex, -1 for isolated vertices
  std::vector<std::vector<int>> loops;   // border halfedges of each boundary loop, in next order
  std::vector<int> loop_component;
  std::vector<Component_counts> components;
  std::size_t isolated_vertices = 0;

  template <typename TM>
  explicit Topology_arrays(const Mesh_arrays<TM>& m)
  {
    const int nf = int(m.number_of_faces());
    face_component.assign(nf, -1);
    std::vector<int> stack;
    int nc = 0;
    for(int f0 = 0; f0 < nf; ++f0) {
      if(face_component[f0] >= 0) continue;
      face_component[f0] = nc;
      stack.push_back(f0);
      while(!stack.empty()) {
        const int f = stack.back();
        stack.pop_back();
        int h = m.face_halfedge[f];
        for(int k = 0; k < 3; ++k, h = m.next[h]) {
          const int g = m.face[h ^ 1];
          if(g >= 0 && face_component[g] < 0) { face_component[g] = nc; stack.push_back(g); }
        }
      }
      ++nc;
    }
    components.assign(nc, Component_counts());
    for(int f = 0; f < nf; ++f) ++components[face_component[f]].faces;
    vertex_component.assign(m.number_of_vertices(), -1);
    for(std::size_t v = 0; v < m.number_of_vertices(); ++v) {
      const int h = m.vertex_out[v];
      if(h < 0) { ++isolated_vertices; continue; }
      const int f = m.face[h] >= 0 ? m.face[h] : m.face[h ^ 1];
      vertex_component[v] = face_component[f];
      ++components[vertex_component[v]].vertices;
    }
    for(std::size_t e = 0; e < m.number_of_edges(); ++e)
      ++components[vertex_component[m.target[2 * e]]].edges;

    std::vector<char> seen(m.number_of_halfedges(), 0);
    for(int h0 = 0; h0 < int(m.number_of_halfedges()); ++h0) {
      if(m.face[h0] >= 0 || seen[h0]) continue;
      std::vector<int> loop;
      for(int h = h0; !seen[h]; h = m.next[h]) { seen[h] = 1; loop.push_back(h); }
      const int c = vertex_component[m.target[h0]];
      loops.push_back(loop);
      loop_component.push_back(c);
      ++components[c].boundary_loops;
    }
  }
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_TOPOLOGY_H
