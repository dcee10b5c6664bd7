// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_HOLONOMY_LOOPS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_HOLONOMY_LOOPS_H

// The loops whose holonomy a seamless metric fixes (seamless_metric.h, seamless_cone_moves.h):
// the handle generators' dual cycles and, on open meshes with several boundary loops, a path of
// faces from the first loop to each other one; each as the turns it makes inside the faces it
// crosses. A loop's holonomy is a sum of corner angles, with an exact derivative in the log
// edge lengths.

#include <CGAL/Surface_mesh_direction_fields/Intrinsic_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh_arrays.h>
#include <CGAL/Surface_mesh_direction_fields/internal/topology.h>
#include <CGAL/Surface_mesh_direction_fields/internal/tree_cotree.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// Entered by halfedge a, left by halfedge b, both of face `face`.
struct Loop_turn { int a, b, face; };

// The loops of a triangulation given as arrays, with its topology and tree-cotree generators:
// first the handles' dual cycles (closed), then the boundary paths (open: the first turn enters
// by an edge of the first boundary loop, the last leaves by one of another loop).
template <typename TM>
std::vector<std::vector<Loop_turn>> holonomy_loops(const Mesh_arrays<TM>& m, const Topology_arrays& topology,
                                                   const std::vector<Generator_arrays>& generators)
{
  typedef Loop_turn Turn;
  const std::size_t nf = m.number_of_faces();
  std::vector<std::vector<Turn>> loops;
  for(const auto& g : generators) {
    if(!g.handle || g.dual.empty()) continue;
    std::vector<Turn> t;
    const std::size_t n = g.dual.size();
    for(std::size_t k = 0; k < n; ++k) t.push_back({g.dual[k], g.dual[(k + 1) % n] ^ 1, m.face[std::size_t(g.dual[k])]});
    loops.push_back(std::move(t));
  }
  // Open meshes with several boundary loops: a path of faces from an edge of the first loop to an
  // edge of each other one, entered by the first and left by the second. A parallel field along
  // the first loop's edges then lies along the other's only if the path turns by a multiple of
  // 2 pi / N from one edge to the other; the same sum of turns as a loop's holonomy measures it.
  {
    const std::vector<std::vector<int>>& bloops = topology.loops;   // border halfedges
    if(bloops.size() >= 2) {
      std::vector<int> parent(nf, -2);   // per face: the halfedge it was entered by (-1: a start face)
      std::vector<int> queue;
      for(int hb : bloops[0]) {
        const int f = m.face[std::size_t(hb ^ 1)];
        if(parent[std::size_t(f)] == -2) { parent[std::size_t(f)] = -1; queue.push_back(f); }
      }
      for(std::size_t q = 0; q < queue.size(); ++q) {
        int x = m.face_halfedge[std::size_t(queue[q])];
        for(int i = 0; i < 3; ++i, x = m.next[std::size_t(x)]) {
          const int g = m.face[std::size_t(x ^ 1)];
          if(g < 0 || parent[std::size_t(g)] != -2) continue;
          parent[std::size_t(g)] = x ^ 1;
          queue.push_back(g);
        }
      }
      std::vector<std::size_t> order(nf, queue.size());   // per face: its place in the search
      for(std::size_t q = 0; q < queue.size(); ++q) order[std::size_t(queue[q])] = q;
      auto entry_edge = [&](int f) {   // a start face's halfedge on the first loop
        int x = m.face_halfedge[std::size_t(f)];
        for(int i = 0; i < 3; ++i, x = m.next[std::size_t(x)])
          for(int hb : bloops[0]) if((hb ^ 1) == x) return x;
        return -1;
      };
      for(std::size_t j = 1; j < bloops.size(); ++j) {
        int end = -1, exit = -1;   // the face reached first among those on loop j, and its edge there
        std::size_t best = queue.size();
        for(int hb : bloops[j]) {
          const int f = m.face[std::size_t(hb ^ 1)];
          if(order[std::size_t(f)] < best) { best = order[std::size_t(f)]; end = f; exit = hb ^ 1; }
        }
        if(end < 0) continue;
        std::vector<Turn> t;
        for(int f = end, b = exit;;) {
          const int a = parent[std::size_t(f)] >= 0 ? parent[std::size_t(f)] : entry_edge(f);
          t.push_back({a, b, f});
          if(parent[std::size_t(f)] < 0) break;
          b = parent[std::size_t(f)] ^ 1;
          f = m.face[std::size_t(b)];
        }
        std::reverse(t.begin(), t.end());
        loops.push_back(std::move(t));
      }
    }
  }
  return loops;
}

template <typename TM>
std::vector<std::vector<Loop_turn>> holonomy_loops(const Intrinsic_mesh<TM>& im)
{
  return holonomy_loops(im.arrays(), im.topology_arrays(), im.generator_arrays());
}

// A loop's holonomy under the corner angles `angle` (per halfedge, at its source): pi per
// crossing plus, per face, the turn from its entry to its exit edge. `m` has the triangulation's
// `next` (Mesh_arrays or Flippable_triangulation).
template <typename Arrays>
double loop_holonomy(const Arrays& m, const std::vector<double>& angle, const std::vector<Loop_turn>& t)
{
  double hsum = CGAL_PI * double(t.size());
  for(const Loop_turn& x : t) {
    if(x.b == m.next[std::size_t(x.a)]) hsum += angle[std::size_t(x.b)] - CGAL_PI;
    else hsum += angle[std::size_t(m.next[std::size_t(x.a)])] + angle[std::size_t(x.b)] - 2 * CGAL_PI;
  }
  return hsum;
}

// Calls add(edge, d) with s times the derivative of the angle at source(c) in face(c) by the log
// length of each side of that face (d theta_A / d lambda_BC = cot B + cot C, by AB: -cot B).
template <typename Arrays, typename Add>
void corner_angle_derivative(const Arrays& m, const std::vector<double>& angle, int c, double s, const Add& add)
{
  const int n = m.next[std::size_t(c)], p = m.next[std::size_t(n)];
  const double cn = 1 / std::tan(angle[std::size_t(n)]), cp = 1 / std::tan(angle[std::size_t(p)]);
  add(n >> 1, s * (cn + cp));
  add(c >> 1, -s * cn);
  add(p >> 1, -s * cp);
}

// The same for a loop's holonomy (loop_holonomy()).
template <typename Arrays, typename Add>
void loop_holonomy_derivative(const Arrays& m, const std::vector<double>& angle, const std::vector<Loop_turn>& t, const Add& add)
{
  for(const Loop_turn& x : t) {
    corner_angle_derivative(m, angle, x.b, 1., add);
    if(x.b != m.next[std::size_t(x.a)]) corner_angle_derivative(m, angle, m.next[std::size_t(x.a)], 1., add);
  }
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_HOLONOMY_LOOPS_H
