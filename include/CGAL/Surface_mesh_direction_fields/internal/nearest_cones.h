// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_NEAREST_CONES_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_NEAREST_CONES_H

// Edge-path distances from every vertex to its two nearest sources (cones), within a radius.

#include <array>
#include <cstddef>
#include <functional>
#include <limits>
#include <queue>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// For every vertex, its edge-path distances (under the arrays' lengths) to the two nearest of
// `sources` (vertex indices), distinct, with their positions in `sources`; within `radius` only
// (farther: infinity, source -1).
struct Two_nearest_sources
{
  std::vector<std::array<double, 2>> distance;
  std::vector<std::array<int, 2>> source;

  // The distance from vertex v to the nearest source other than `not_this` (infinity if none
  // within the radius), and that source (-1 if none).
  double other_than(std::size_t v, int not_this, int* which = nullptr) const
  {
    for(std::size_t k = 0; k < 2; ++k)
      if(source[v][k] >= 0 && source[v][k] != not_this) {
        if(which) *which = source[v][k];
        return distance[v][k];
      }
    if(which) *which = -1;
    return std::numeric_limits<double>::infinity();
  }
};

// Dijkstra with two labels per vertex, over the balls of `radius` around the sources only.
template <typename Arrays>
Two_nearest_sources two_nearest_sources(const Arrays& m, const std::vector<std::size_t>& sources, double radius)
{
  const std::size_t nv = m.number_of_vertices();
  const double inf = std::numeric_limits<double>::infinity();
  Two_nearest_sources r;
  r.distance.assign(nv, {inf, inf});
  r.source.assign(nv, {-1, -1});
  typedef std::tuple<double, std::size_t, int> Item;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for(std::size_t i = 0; i < sources.size(); ++i) queue.emplace(0., sources[i], int(i));
  while(!queue.empty()) {
    const Item it = queue.top();
    queue.pop();
    const double d = std::get<0>(it);
    const std::size_t v = std::get<1>(it);
    const int s = std::get<2>(it);
    std::array<int, 2>& sv = r.source[v];
    if(sv[0] == s || sv[1] == s || sv[1] >= 0) continue;
    const std::size_t k = sv[0] < 0 ? 0 : 1;
    sv[k] = s;
    r.distance[v][k] = d;
    if(m.is_isolated(int(v))) continue;
    for(int h = m.vertex_out[v], h0 = h;;) {
      const std::size_t w = std::size_t(m.target[std::size_t(h)]);
      const double dw = d + m.edge_length(h);
      if(dw <= radius && r.source[w][1] < 0 && r.source[w][0] != s) queue.emplace(dw, w, s);
      if(m.face[std::size_t(h)] < 0) break;
      h = m.ccw_out(h);
      if(h == h0) break;
    }
  }
  return r;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_NEAREST_CONES_H
