// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_POLYHEDRON_PATHS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_POLYHEDRON_PATHS_H

// The cut of a polyhedron metric (Lai et al. 2010, section 4.1.3.2): P's edges as disjoint
// shortest edge paths between the mesh vertices of its corners.

#include <CGAL/Surface_mesh_direction_fields/internal/Mesh_arrays.h>
#include <CGAL/Surface_mesh_direction_fields/internal/two_threads.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// Shortens an edge path (vertices `p`, halfedges `hs` from p[i] to p[i + 1]) wherever an edge
// joins two of its vertices that are not consecutive. Under lengths that break the triangle
// inequality (conformal scalings of the input's edges after intrinsic flips) a shortest path may
// walk around a triangle; all three corners would then lie on one straight side of the chart.
template <typename TM>
void shortcut_chords(const Mesh_arrays<TM>& m, std::vector<int>& p, std::vector<int>& hs)
{
  std::map<int, std::size_t> position;
  for(std::size_t i = 0; i < p.size(); ++i) position[p[i]] = i;
  std::vector<int> q(1, p[0]), qh;
  for(std::size_t i = 0; i + 1 < p.size();) {
    std::size_t j = i + 1;
    int via = hs[i];
    const int h0 = m.vertex_out[std::size_t(p[i])];
    int h = h0;
    do {
      const auto it = position.find(m.target[std::size_t(h)]);
      if(it != position.end() && it->second > j) { j = it->second; via = h; }
      h = m.ccw_out(h);
    } while(h != h0);
    q.push_back(p[j]);
    qh.push_back(via);
    i = j;
  }
  p.swap(q);
  hs.swap(qh);
}

// P's edges (pedges[k]: two corner indices into corner_vertex; corner_of: per mesh vertex its
// corner or -1) as shortest edge paths under `length(h)` (a length per halfedge), each avoiding
// the earlier ones (their inner vertices and edges) and the other corners, tried in three orders
// (shortest first, longest first, P's order) until every one exists. Fills `paths` (vertices
// from pedges[k][0] to pedges[k][1]), `path_halfedges` (from paths[k][i] to paths[k][i + 1])
// and `path_of_edge` (per mesh edge its path, or -1); returns the number of path edges, or 0
// and `message`.
template <typename TM, typename Length>
std::size_t polyhedron_edge_paths(const Mesh_arrays<TM>& m, const std::vector<int>& corner_vertex, const std::vector<int>& corner_of,
                                  const std::vector<std::array<int, 2>>& pedges, const Length& length,
                                  std::vector<std::vector<int>>& paths, std::vector<std::vector<int>>& path_halfedges,
                                  std::vector<int>& path_of_edge, std::string& message)
{
  const std::size_t nv = m.number_of_vertices(), ne = m.number_of_edges(), np = pedges.size();
  std::vector<char> used;
  std::size_t path_edges = 0;
  paths.assign(np, {});
  path_halfedges.assign(np, {});
  // Dijkstra from vertex s to t on the metric's lengths, returning the distance; `from[v]` is
  // the halfedge into v. With `avoid`, not through earlier paths (their inner vertices and
  // edges) nor through other corners.
  auto shortest = [&](int s, int t, bool avoid, std::vector<int>& from) {
    std::vector<double> d(nv, std::numeric_limits<double>::infinity());
    from.assign(nv, -1);
    typedef std::pair<double, int> Item;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    d[std::size_t(s)] = 0;
    queue.push({0., s});
    while(!queue.empty()) {
      const Item it = queue.top();
      queue.pop();
      if(it.first > d[std::size_t(it.second)]) continue;
      if(it.second == t) break;
      const int h0 = m.vertex_out[std::size_t(it.second)];
      int h = h0;
      do {
        const int u = m.target[std::size_t(h)];
        const bool blocked = avoid && (used[std::size_t(u)] || (corner_of[std::size_t(u)] >= 0 && u != t) || path_of_edge[std::size_t(h >> 1)] >= 0);
        const double du = it.first + length(h);
        if(!blocked && du < d[std::size_t(u)]) { d[std::size_t(u)] = du; from[std::size_t(u)] = h; queue.push({du, u}); }
        h = m.ccw_out(h);
      } while(h != h0);
    }
    return d[std::size_t(t)];
  };
  // the path from s to t that `from` holds: its vertices and halfedges, from s
  auto trace = [&](int s, int t, const std::vector<int>& from, std::vector<int>& p, std::vector<int>& hs) {
    p.assign(1, t);
    hs.clear();
    for(int v = t; v != s;) {
      const int h = from[std::size_t(v)];
      hs.push_back(h);
      v = m.source(h);
      p.push_back(v);
    }
    std::reverse(p.begin(), p.end());
    std::reverse(hs.begin(), hs.end());
  };
  // every edge of P without obstacles: its distance (for the orders) and a shortest path, taken
  // as it is below whenever it avoids the earlier paths (a box on Spot: 12 of the 12, on the
  // armadillo at 433k faces 11; paths 0.59 -> 0.25 s there)
  std::vector<double> reach(np, 0.);
  std::vector<std::vector<int>> free_path(np), free_halfedges(np);
  run_on_two_threads([&](int t) {   // (without obstacles the searches only read shared data)
    std::vector<int> from;
    for(std::size_t k = std::size_t(t); k < np; k += 2) {
      const int s = corner_vertex[std::size_t(pedges[k][0])], e = corner_vertex[std::size_t(pedges[k][1])];
      reach[k] = shortest(s, e, false, from);
      if(from[std::size_t(e)] >= 0) trace(s, e, from, free_path[k], free_halfedges[k]);
    }
  }, nv >= 10000);
  // whether a path crosses no earlier path (inner vertex or edge) and no corner but its ends
  auto avoids = [&](const std::vector<int>& p, const std::vector<int>& hs) {
    for(std::size_t i = 1; i + 1 < p.size(); ++i)
      if(used[std::size_t(p[i])] || corner_of[std::size_t(p[i])] >= 0) return false;
    for(int h : hs) if(path_of_edge[std::size_t(h >> 1)] >= 0) return false;
    return true;
  };
  std::vector<std::size_t> order(np);
  for(int attempt = 0; attempt < 3; ++attempt) {   // shortest first, longest first, P's order
    for(std::size_t k = 0; k < np; ++k) order[k] = k;
    if(attempt < 2)
      std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return attempt == 0 ? reach[x] < reach[y] : reach[x] > reach[y]; });
    used.assign(nv, 0);
    path_of_edge.assign(ne, -1);
    path_edges = 0;
    message.clear();
    for(std::size_t kk = 0; kk < np && message.empty(); ++kk) {
      const std::size_t k = order[kk];
      const int s = corner_vertex[std::size_t(pedges[k][0])], t = corner_vertex[std::size_t(pedges[k][1])];
      std::vector<int> p, hs;
      if(!free_halfedges[k].empty() && avoids(free_path[k], free_halfedges[k])) {
        p = free_path[k];   // a shortest path without obstacles that avoids them is one with them
        hs = free_halfedges[k];
      } else {
        std::vector<int> from;
        shortest(s, t, true, from);
        if(from[std::size_t(t)] >= 0) trace(s, t, from, p, hs);
      }
      if(hs.empty()) {
        std::ostringstream os;
        os << "no path from corner " << pedges[k][0] << " (vertex " << s << ") to corner " << pedges[k][1] << " (vertex " << t
           << ") avoids the earlier paths (place the corners farther apart, or refine the mesh)";
        message = os.str();
        break;
      }
      shortcut_chords(m, p, hs);
      for(int h : hs) path_of_edge[std::size_t(h >> 1)] = int(k);
      path_edges += hs.size();
      for(std::size_t i = 1; i + 1 < p.size(); ++i) used[std::size_t(p[i])] = 1;
      paths[k] = p;
      path_halfedges[k] = hs;
    }
    if(message.empty()) break;
  }
  return message.empty() ? path_edges : 0;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_POLYHEDRON_PATHS_H
