// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_POLYHEDRON_PATHS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_POLYHEDRON_PATHS_H

// The cut of a polyhedron metric (Lai et al. 2010, section 4.1.3.2): P's edges as disjoint
// shortest edge paths between the mesh vertices of its corners, and the pieces they cut.

#include <CGAL/Surface_mesh_direction_fields/errors.h>
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

// A polyhedron P cut into a mesh: its corners, edges, the paths of its edges and the pieces
// they cut the mesh into, each matched to its face of P.
struct Polyhedron_cut
{
  std::vector<int> corner_of;                      // per mesh vertex: its corner of P, or -1
  std::map<std::pair<int, int>, int> edge_id;      // P's edge of two corners (the smaller first)
  std::vector<std::array<int, 2>> pedges;          // P's edges, in the direction of their first face
  std::vector<std::vector<int>> paths;             // per P edge: mesh vertices from pedges[k][0] to pedges[k][1]
  std::vector<std::vector<int>> path_halfedges;    // ... and their halfedges
  std::vector<int> path_of_edge;                   // per mesh edge: its path, or -1
  std::size_t path_edges = 0;
  std::vector<int> region;                         // per mesh face: its piece
  std::vector<int> face_of_region, region_of_face; // piece <-> face of P

  int edge_of(int a, int b) const { return edge_id.at(std::make_pair((std::min)(a, b), (std::max)(a, b))); }
};

// Cuts the mesh along shortest edge paths (under `length(h)`) of the edges of P, whose corners
// are the mesh vertices `corner_vertex` and whose faces `pfaces` are cycles of corner indices
// (counterclockwise seen from outside), and matches the pieces to P's faces by their corners.
// Throws Input_error for a P that is not a closed oriented sphere or corners that are not
// distinct vertices; returns false with `message` when the paths or the pieces fail.
template <typename TM, typename Length>
bool cut_along_polyhedron(const Mesh_arrays<TM>& m, const std::vector<int>& corner_vertex, const std::vector<std::vector<int>>& pfaces,
                          const Length& length, Polyhedron_cut& cut, std::string& message)
{
  const std::size_t nv = m.number_of_vertices(), nf = m.number_of_faces(), nc = corner_vertex.size();
  cut.corner_of.assign(nv, -1);
  for(std::size_t i = 0; i < nc; ++i) {
    const int v = corner_vertex[i];
    if(v < 0 || std::size_t(v) >= nv || m.is_isolated(v) || cut.corner_of[std::size_t(v)] >= 0)
      throw Input_error(Input_error::INVALID_ARGUMENT, "the polyhedron's corners must be distinct vertices of the mesh");
    cut.corner_of[std::size_t(v)] = int(i);
  }
  // P's edges, each in two faces in opposite directions
  std::vector<int> uses;
  for(const auto& f : pfaces) {
    if(f.size() < 3) throw Input_error(Input_error::INVALID_ARGUMENT, "a face of the polyhedron has fewer than three corners");
    for(std::size_t i = 0; i < f.size(); ++i) {
      const int a = f[i], b = f[(i + 1) % f.size()];
      if(a < 0 || b < 0 || std::size_t(a) >= nc || std::size_t(b) >= nc || a == b)
        throw Input_error(Input_error::INVALID_ARGUMENT, "a face of the polyhedron names a corner that does not exist");
      const auto key = std::make_pair((std::min)(a, b), (std::max)(a, b));
      auto it = cut.edge_id.find(key);
      if(it == cut.edge_id.end()) { cut.edge_id[key] = int(cut.pedges.size()); cut.pedges.push_back({{a, b}}); uses.push_back(1); }
      else if(cut.pedges[std::size_t(it->second)][0] != b || ++uses[std::size_t(it->second)] > 2)
        throw Input_error(Input_error::INVALID_ARGUMENT, "the polyhedron is not a closed oriented surface (edge of corners " +
                                                             std::to_string(a) + " and " + std::to_string(b) + ")");
    }
  }
  for(int u : uses) if(u != 2) throw Input_error(Input_error::INVALID_ARGUMENT, "the polyhedron has an edge in only one face");
  const long chi = long(nc) - long(cut.pedges.size()) + long(pfaces.size());
  if(chi != 2) throw Input_error(Input_error::INVALID_ARGUMENT, "the polyhedron is not a sphere (Euler characteristic " + std::to_string(chi) + ")");
  // the paths
  cut.path_edges = polyhedron_edge_paths(m, corner_vertex, cut.corner_of, cut.pedges, length, cut.paths, cut.path_halfedges,
                                         cut.path_of_edge, message);
  if(!message.empty()) return false;
  // the pieces: faces connected without crossing a path, matched to P's faces by their corners
  cut.region.assign(nf, -1);
  int regions = 0;
  for(std::size_t f0 = 0; f0 < nf; ++f0) {
    if(cut.region[f0] >= 0) continue;
    std::vector<int> stack(1, int(f0));
    cut.region[f0] = regions;
    while(!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      int h = m.face_halfedge[std::size_t(f)];
      for(int i = 0; i < 3; ++i, h = m.next[std::size_t(h)]) {
        const int g = m.face[std::size_t(h ^ 1)];
        if(g >= 0 && cut.region[std::size_t(g)] < 0 && cut.path_of_edge[std::size_t(h >> 1)] < 0) { cut.region[std::size_t(g)] = regions; stack.push_back(g); }
      }
    }
    ++regions;
  }
  if(std::size_t(regions) != pfaces.size()) {
    message = "the paths cut the mesh into " + std::to_string(regions) + " pieces, not the " + std::to_string(pfaces.size()) +
              " faces of the polyhedron";
    return false;
  }
  std::vector<std::vector<int>> region_corners((std::size_t(regions)));
  for(std::size_t h = 0; h < m.number_of_halfedges(); ++h) {
    const int f = m.face[h], v = m.source(int(h));
    if(f >= 0 && cut.corner_of[std::size_t(v)] >= 0) region_corners[std::size_t(cut.region[std::size_t(f)])].push_back(cut.corner_of[std::size_t(v)]);
  }
  cut.face_of_region.assign(std::size_t(regions), -1);
  cut.region_of_face.assign(pfaces.size(), -1);
  for(int r = 0; r < regions; ++r) {
    std::vector<int>& rc = region_corners[std::size_t(r)];
    std::sort(rc.begin(), rc.end());
    rc.erase(std::unique(rc.begin(), rc.end()), rc.end());
    for(std::size_t j = 0; j < pfaces.size(); ++j) {
      std::vector<int> fc = pfaces[j];
      std::sort(fc.begin(), fc.end());
      if(fc == rc && cut.region_of_face[j] < 0) { cut.face_of_region[std::size_t(r)] = int(j); cut.region_of_face[j] = r; break; }
    }
    if(cut.face_of_region[std::size_t(r)] < 0) {
      message = "a piece cut by the paths does not have the corners of a face of the polyhedron (are the corners placed like P's?)";
      return false;
    }
  }
  return true;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_POLYHEDRON_PATHS_H
