// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_REMESHING_CONE_SEPARATION_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_REMESHING_CONE_SEPARATION_H

// Cones kept a grid's resolution apart under their own flat cone metric: a pair of opposite
// curvatures closer than that cancelled, any other cone moved out of reach of its neighbour.

#include <CGAL/Surface_mesh_direction_fields/Intrinsic_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/parameters.h>
#include <CGAL/Surface_mesh_direction_fields/internal/nearest_cones.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <queue>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// Outcome of separate_remeshing_cones().
struct Cone_separation_status
{
  std::size_t close_cones_before = 0;  ///< interior cones nearer another cone than the distance, before
  int cancelled_pairs = 0;             ///< pairs of opposite curvatures removed together
  int moved_cones = 0;                 ///< cones moved out of reach of the others
  std::size_t close_cones_after = 0;   ///< the same count after (no vertex far enough within reach)
};

/// Keeps the interior cones of a flat cone metric at least `distance` apart (shortest edge
/// paths under `lengths`), as a regular remesh of edge length about `distance` needs: an
/// integer-grid map rounds cones less than a grid edge apart onto the same or neighbouring grid
/// points and folds there. Closest pair first: two cones of opposite curvature are both removed
/// (their total is 0, and at this resolution the remesh cannot tell them from a regular vertex);
/// otherwise one of them (the one with the shorter way out) moves to the nearest interior vertex,
/// within three times the distance, that is no cone, is next to none, and is at least
/// `distance` from every other cone. Gauss-Bonnet's total is kept; boundary cones (corners) do
/// not move but count as neighbours. The lengths are those of the cones before: the caller
/// computes the metric of the new cones again, under which distances differ, and may call again.
///
/// \param tm a triangle mesh
/// \param lengths the flat cone metric of `cones` on `tm`
/// \param cones in and out: (vertex, curvature) pairs, sorted on return
/// \param distance the shortest edge path to keep between cones (the grid edge, or a few)
///
/// Throws `Input_error` if `distance` is not positive and finite, and as `Intrinsic_mesh` does.
template <typename TriangleMesh, typename LengthMap>
Cone_separation_status separate_remeshing_cones(const TriangleMesh& tm, const LengthMap& lengths,
                                                std::vector<std::pair<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, double>>& cones,
                                                double distance)
{
  if(!(distance > 0) || !std::isfinite(distance))
    throw Input_error(Input_error::INVALID_ARGUMENT, "separate_remeshing_cones(): the distance must be positive and finite, got " + std::to_string(distance));
  Cone_separation_status st;
  const Intrinsic_mesh<TriangleMesh> im(tm, parameters::edge_length_map(lengths));
  const internal::Mesh_arrays<TriangleMesh>& m = im.arrays();
  const std::size_t nv = m.number_of_vertices(), nc = cones.size();
  std::vector<std::size_t> at(nc);
  std::vector<int> cone_at(nv, -1);
  for(std::size_t c = 0; c < nc; ++c) {
    at[c] = std::size_t(m.vertex_index(cones[c].first));
    cone_at[at[c]] = int(c);
  }
  std::vector<char> alive(nc, 1), stuck(nc, 0);
  auto interior = [&](std::size_t c) { return !m.is_boundary_vertex(int(at[c])); };
  // the distances to the two nearest living cones, numbered as in `cones`
  auto nearest = [&] {
    std::vector<std::size_t> sources, number;
    for(std::size_t c = 0; c < nc; ++c) if(alive[c]) { sources.push_back(at[c]); number.push_back(c); }
    internal::Two_nearest_sources r = internal::two_nearest_sources(m, sources, distance);
    for(auto& s : r.source) for(int& x : s) if(x >= 0) x = int(number[std::size_t(x)]);
    return r;
  };
  auto close_count = [&](const internal::Two_nearest_sources& r) {
    std::size_t n = 0;
    for(std::size_t c = 0; c < nc; ++c) n += alive[c] && interior(c) && r.other_than(at[c], int(c)) < distance;
    return n;
  };
  // the nearest vertex to cone c's (within 3 distances) that may take it, and how far: interior,
  // no other cone at it or next to it, every other cone at least `distance` away
  auto way_out = [&](std::size_t c, const internal::Two_nearest_sources& r, double& how_far) {
    typedef std::pair<double, std::size_t> Item;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    std::vector<char> done(nv, 0);
    queue.emplace(0., at[c]);
    while(!queue.empty()) {
      const Item it = queue.top();
      queue.pop();
      const std::size_t w = it.second;
      if(done[w]) continue;
      done[w] = 1;
      bool free = !m.is_isolated(int(w)) && !m.is_boundary_vertex(int(w)) && (cone_at[w] < 0 || cone_at[w] == int(c)) &&
                  r.other_than(w, int(c)) >= distance;
      for(int h = m.vertex_out[w], h0 = h; free;) {
        const int o = cone_at[std::size_t(m.target[std::size_t(h)])];
        if(o >= 0 && o != int(c)) free = false;
        h = m.ccw_out(h);
        if(h == h0) break;
      }
      if(free && w != at[c]) { how_far = it.first; return w; }
      for(int h = m.vertex_out[w], h0 = h;;) {
        const std::size_t x = std::size_t(m.target[std::size_t(h)]);
        const double dx = it.first + m.edge_length(h);
        if(!done[x] && dx <= 3 * distance) queue.emplace(dx, x);
        if(m.face[std::size_t(h)] < 0) break;
        h = m.ccw_out(h);
        if(h == h0) break;
      }
    }
    return nv;
  };
  internal::Two_nearest_sources r = nearest();
  st.close_cones_before = close_count(r);
  for(std::size_t round = 0; round < 2 * nc; ++round) {
    // the closest pair not yet found stuck
    double best = distance;
    std::size_t c = nc;
    int o = -1;
    for(std::size_t x = 0; x < nc; ++x) {
      if(!alive[x] || stuck[x] || !interior(x)) continue;
      int y = -1;
      const double d = r.other_than(at[x], int(x), &y);
      if(d < best) { best = d; c = x; o = y; }
    }
    if(c == nc) break;
    const std::size_t p = std::size_t(o);
    if(interior(p) && cones[c].second == -cones[p].second) {
      alive[c] = alive[p] = 0;
      cone_at[at[c]] = cone_at[at[p]] = -1;
      ++st.cancelled_pairs;
    } else {
      double far_c = std::numeric_limits<double>::infinity(), far_p = far_c;
      const std::size_t to_c = way_out(c, r, far_c), to_p = interior(p) ? way_out(p, r, far_p) : nv;
      if(to_c == nv && to_p == nv) { stuck[c] = 1; continue; }
      const std::size_t mover = far_c <= far_p ? c : p, to = far_c <= far_p ? to_c : to_p;
      cone_at[at[mover]] = -1;
      at[mover] = to;
      cone_at[to] = int(mover);
      cones[mover].first = m.vertices[to];
      ++st.moved_cones;
    }
    r = nearest();
  }
  st.close_cones_after = close_count(r);
  std::vector<std::pair<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, double>> kept;
  for(std::size_t c = 0; c < nc; ++c) if(alive[c]) kept.push_back(cones[c]);
  std::sort(kept.begin(), kept.end());
  cones.swap(kept);
  return st;
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_REMESHING_CONE_SEPARATION_H
