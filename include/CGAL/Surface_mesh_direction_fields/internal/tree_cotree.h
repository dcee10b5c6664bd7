// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_TREE_COTREE_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_TREE_COTREE_H

#include <CGAL/Surface_mesh_direction_fields/internal/Mesh_arrays.h>
#include <CGAL/Surface_mesh_direction_fields/internal/topology.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

struct Generator_arrays
{
  bool handle;              // false: a boundary loop
  int component;
  int edge;                 // the leftover edge closing the cycles (-1 for boundary loops)
  std::vector<int> dual;    // crossings: from face(h ^ 1) into face(h)
  std::vector<int> primal;  // halfedges, head to tail
};

// The dual cycle running beside a primal loop on its left: the faces around each vertex of the
// loop on the left side, in order. Returns false if the left side meets the boundary.
template <typename TM>
bool dual_cycle_left_of(const Mesh_arrays<TM>& m, const std::vector<int>& loop, std::vector<int>& out)
{
  out.clear();
  const std::size_t n = loop.size();
  if(m.face[loop[0]] < 0) return false;
  for(std::size_t i = 0; i < n; ++i) {
    const int hn = loop[(i + 1) % n];
    const std::size_t guard = out.size() + m.number_of_halfedges();
    for(int g = m.next[loop[i]]; g != hn; g = m.next[g ^ 1]) {
      if(m.face[g ^ 1] < 0 || out.size() > guard) return false;
      out.push_back(g ^ 1);
    }
  }
  return true;
}

// Reverses the orientation of a dual cycle.
inline std::vector<int> reversed_dual_cycle(const std::vector<int>& c)
{
  std::vector<int> r;
  r.reserve(c.size());
  for(auto it = c.rbegin(); it != c.rend(); ++it) r.push_back(*it ^ 1);
  if(r.size() > 1) std::rotate(r.begin(), r.end() - 1, r.end());   // start in the same face
  return r;
}

// Tree-cotree decomposition (Eppstein 2003) with boundary loops capped by virtual faces:
// per component, 2g handle generators from leftover edges plus b - 1 boundary loops.
template <typename TM>
std::vector<Generator_arrays> tree_cotree(const Mesh_arrays<TM>& m, const Topology_arrays& t)
{
  const int nv = int(m.number_of_vertices()), nf = int(m.number_of_faces());
  const int ne = int(m.number_of_edges());
  std::vector<char> in_tree(ne, 0), in_cotree(ne, 0);

  // --- primal spanning tree with parent pointers (root: first vertex of each component)
  std::vector<int> parent_h(nv, -1), depth_v(nv, -1);
  auto for_each_out = [&](int v, auto&& fn) {
    const int start = m.vertex_out[v];
    int h = start;
    do {
      fn(h);
      if(m.face[h] < 0) break;
      h = m.ccw_out(h);
    } while(h != start);
  };
  std::vector<int> queue;
  queue.reserve(nv);
  if(t.loops.empty()) {
    // closed: the breadth-first tree itself
    for(int r = 0; r < nv; ++r) {
      if(depth_v[r] >= 0 || m.is_isolated(r)) continue;
      depth_v[r] = 0;
      std::size_t head = queue.size();
      queue.push_back(r);
      while(head < queue.size()) {
        const int v = queue[head++];
        for_each_out(v, [&](int h) {
          const int w = m.target[h];
          if(depth_v[w] >= 0) return;
          depth_v[w] = depth_v[v] + 1;
          parent_h[w] = h;
          in_tree[h >> 1] = 1;
          queue.push_back(w);
        });
      }
    }
  } else {
    // every boundary loop minus one edge first (union-find), then edges in breadth-first order
    std::vector<int> uf(nv);
    std::iota(uf.begin(), uf.end(), 0);
    auto find = [&](int x) { while(uf[x] != x) { uf[x] = uf[uf[x]]; x = uf[x]; } return x; };
    auto unite = [&](int e) {
      const int a = find(m.target[2 * e]), b = find(m.target[2 * e + 1]);
      if(a == b) return;
      uf[a] = b;
      in_tree[e] = 1;
    };
    for(const auto& loop : t.loops)
      for(std::size_t k = 1; k < loop.size(); ++k) unite(loop[k] >> 1);
    std::vector<char> visited(nv, 0);
    std::vector<int> order;
    order.reserve(nv);
    for(int r = 0; r < nv; ++r) {
      if(visited[r] || m.is_isolated(r)) continue;
      std::size_t head = order.size();
      order.push_back(r);
      visited[r] = 1;
      while(head < order.size()) {
        const int v = order[head++];
        for_each_out(v, [&](int h) {
          const int w = m.target[h];
          unite(h >> 1);
          if(!visited[w]) { visited[w] = 1; order.push_back(w); }
        });
      }
    }
    for(int r : order) {
      if(depth_v[r] >= 0) continue;
      depth_v[r] = 0;
      queue.clear();
      queue.push_back(r);
      for(std::size_t head = 0; head < queue.size(); ++head) {
        const int v = queue[head];
        for_each_out(v, [&](int h) {
          const int w = m.target[h];
          if(in_tree[h >> 1] && depth_v[w] < 0) {
            depth_v[w] = depth_v[v] + 1;
            parent_h[w] = h;
            queue.push_back(w);
          }
        });
      }
    }
  }

  // --- dual spanning tree over real faces through edges not in the primal tree; each boundary
  // loop's virtual face hangs as a leaf on its one edge left out of the primal tree.
  std::vector<int> parent_cross(nf, -1), depth_f(nf, -1);
  {
    queue.clear();
    queue.reserve(nf);
    for(int r = 0; r < nf; ++r) {
      if(depth_f[r] >= 0) continue;
      depth_f[r] = 0;
      queue.clear();
      queue.push_back(r);
      for(std::size_t head = 0; head < queue.size(); ++head) {
        const int f = queue[head];
        int h = m.face_halfedge[f];
        for(int k = 0; k < 3; ++k, h = m.next[h]) {
          const int g = m.face[h ^ 1];
          if(g < 0 || in_tree[h >> 1] || depth_f[g] >= 0) continue;
          depth_f[g] = depth_f[f] + 1;
          parent_cross[g] = h ^ 1;
          in_cotree[h >> 1] = 1;
          queue.push_back(g);
        }
      }
    }
    for(const auto& loop : t.loops) in_cotree[loop[0] >> 1] = 1;
  }

  std::vector<Generator_arrays> gens;
  for(int e = 0; e < ne; ++e) {
    if(in_tree[e] || in_cotree[e]) continue;
    CGAL_assertion(!m.is_border_edge(e));
    Generator_arrays g;
    g.handle = true;
    g.edge = e;
    g.component = t.face_component[m.face[2 * e]];

    // dual cycle: cross e into b, climb from b to the common ancestor, descend to a
    const int h = 2 * e;
    int x = m.face[h], y = m.face[h ^ 1];
    std::vector<int> up_x, up_y;
    while(x != y) {
      if(depth_f[x] >= depth_f[y]) { up_x.push_back(parent_cross[x] ^ 1); x = m.face[parent_cross[x] ^ 1]; }
      else { up_y.push_back(parent_cross[y]); y = m.face[parent_cross[y] ^ 1]; }
    }
    g.dual.push_back(h);
    g.dual.insert(g.dual.end(), up_x.begin(), up_x.end());
    g.dual.insert(g.dual.end(), up_y.rbegin(), up_y.rend());

    // primal loop: e from u to w, climb from w to the common ancestor, descend to u
    int a = m.target[h], b = m.target[h ^ 1];
    std::vector<int> up_a, up_b;
    while(a != b) {
      if(depth_v[a] >= depth_v[b]) { up_a.push_back(parent_h[a] ^ 1); a = m.source(parent_h[a]); }
      else { up_b.push_back(parent_h[b]); b = m.source(parent_h[b]); }
    }
    g.primal.push_back(h);
    g.primal.insert(g.primal.end(), up_a.begin(), up_a.end());
    g.primal.insert(g.primal.end(), up_b.rbegin(), up_b.rend());
    gens.push_back(std::move(g));
  }

  // boundary loops: all but the last one of each component
  std::vector<int> last_loop(t.components.size(), -1);
  for(std::size_t i = 0; i < t.loops.size(); ++i) last_loop[t.loop_component[i]] = int(i);
  for(std::size_t i = 0; i < t.loops.size(); ++i) {
    if(last_loop[t.loop_component[i]] == int(i)) continue;
    Generator_arrays g;
    g.handle = false;
    g.edge = -1;
    g.component = t.loop_component[i];
    for(auto it = t.loops[i].rbegin(); it != t.loops[i].rend(); ++it) g.primal.push_back(*it ^ 1);
    const bool ok = dual_cycle_left_of(m, g.primal, g.dual);
    CGAL_assertion(ok);
    CGAL_USE(ok);
    gens.push_back(std::move(g));
  }
  return gens;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_TREE_COTREE_H
