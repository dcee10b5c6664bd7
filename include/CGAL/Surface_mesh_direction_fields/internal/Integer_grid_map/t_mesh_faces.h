// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INTEGER_GRID_MAP_T_MESH_FACES_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INTEGER_GRID_MAP_T_MESH_FACES_H

// The faces of a seamless map's T-mesh (motorcycle_graph.h): each is a rectangle of the map,
// bounded by arcs, with a corner where its boundary turns by a right angle. An integer-grid map
// that keeps the T-mesh keeps every face at least one grid unit wide and high (a face of width 0
// maps a piece of the surface onto a segment): with nonnegative arcs, the condition of Campen,
// Bommes and Kobbelt 2015 on a quantization that a valid map can follow. Its sides' lengths are
// linear forms in the seams' small unknowns.

#include <CGAL/Surface_mesh_direction_fields/internal/Integer_grid_map/motorcycle_graph.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// Walks the faces of the T-mesh `g` (each with the face on its left) and appends the four sides'
// lengths of every rectangular one to `sides`, checked at the seamless map's y (opposite sides
// equal). Faces that do not close into a rectangle (along a boundary loop without corners, at a
// separatrix's end in a singularity, an annulus around a handle) are skipped. Returns the number
// of rectangles.
inline std::size_t t_mesh_face_sides(const Separatrix_arcs& g, const Eigen::VectorXd& y, std::vector<Linear_form>& sides)
{
  struct Half { double angle; int trace, stop; bool forward; };
  const double pi = CGAL_PI;
  std::vector<std::vector<Half>> at(g.period.size());
  std::vector<std::size_t> base(g.stops.size() + 1, 0);
  for(std::size_t t = 0; t < g.stops.size(); ++t) base[t + 1] = base[t] + g.stops[t].size();
  auto normal = [&](int node, double a) {   // into [0, period) where the angles wrap
    const double p = g.period[std::size_t(node)];
    return p > 0 ? a - p * std::floor(a / p) : a;
  };
  for(std::size_t t = 0; t < g.stops.size(); ++t)
    for(std::size_t i = 0; i < g.stops[t].size(); ++i) {
      const Separatrix_arcs::Stop& s = g.stops[t][i];
      if(i + 1 < g.stops[t].size()) at[std::size_t(s.node)].push_back({normal(s.node, s.angle), int(t), int(i), true});
      if(i > 0) at[std::size_t(s.node)].push_back({normal(s.node, s.angle + pi), int(t), int(i), false});
    }
  for(auto& list : at) std::sort(list.begin(), list.end(), [](const Half& a, const Half& b) { return a.angle < b.angle; });
  auto id = [&](const Half& h) { return 2 * (base[std::size_t(h.trace)] + std::size_t(h.stop)) + (h.forward ? 1 : 0); };
  std::vector<char> used(2 * base.back(), 0);
  std::size_t rectangles = 0;
  const double tol = 1e-6;
  for(const auto& list : at)
    for(const Half& first : list) {
      if(used[id(first)]) continue;
      // the walk: each arc with the face's interior angle at its head (pi/2: a corner; pi: straight on)
      std::vector<std::pair<const Linear_form*, bool>> walk;
      Half h = first;
      bool closed = false;
      for(std::size_t step = 0; step <= base.back() * 2 + 4; ++step) {
        used[id(h)] = 1;
        const int j = h.forward ? h.stop + 1 : h.stop - 1;
        const Linear_form& arc = g.arc_of[std::size_t(h.trace)][std::size_t(h.forward ? h.stop : h.stop - 1)];
        const int node = g.stops[std::size_t(h.trace)][std::size_t(j)].node;
        const std::vector<Half>& here = at[std::size_t(node)];
        std::size_t back = here.size();
        for(std::size_t k = 0; k < here.size(); ++k)
          if(here[k].trace == h.trace && here[k].stop == j && here[k].forward != h.forward) back = k;
        if(back == here.size() || here.size() < 2) break;
        // the next half-arc clockwise from the way back: the face's next side
        std::size_t next;
        double inner;
        if(back > 0) { next = back - 1; inner = here[back].angle - here[next].angle; }
        else if(g.period[std::size_t(node)] > 0) { next = here.size() - 1; inner = here[back].angle - here[next].angle + g.period[std::size_t(node)]; }
        else break;   // outside the boundary
        const bool turn = std::abs(inner - pi / 2) < 1e-3;
        if(!turn && !(std::abs(inner - pi) < 1e-3)) break;
        walk.emplace_back(&arc, turn);
        h = here[next];
        if(id(h) == id(first)) { closed = true; break; }
        if(used[id(h)]) break;
      }
      if(!closed) continue;
      std::size_t corners = 0, start = 0;
      for(std::size_t k = 0; k < walk.size(); ++k) if(walk[k].second) { ++corners; start = k + 1; }
      if(corners != 4) continue;
      Linear_form side[4];
      for(std::size_t k = 0, s = 0; k < walk.size(); ++k) {
        const auto& w = walk[(start + k) % walk.size()];
        side[s].add(*w.first, 1);
        if(w.second) ++s;
      }
      const double w0 = side[0](y), h0 = side[1](y), w1 = side[2](y), h1 = side[3](y);
      if(!(std::abs(w0 - w1) <= tol * (1 + std::abs(w0)) && std::abs(h0 - h1) <= tol * (1 + std::abs(h0)))) continue;
      if(side[0].terms.empty() || side[1].terms.empty() || side[2].terms.empty() || side[3].terms.empty()) continue;
      ++rectangles;
      for(const Linear_form& f : side) sides.push_back(f);
    }
  return rectangles;
}

// The nodes of the T-mesh (singularities, corners and the separatrices' ends)
inline std::size_t t_mesh_nodes(const Separatrix_arcs& g)
{
  std::vector<char> seen(g.period.size(), 0);
  for(const auto& stops : g.stops) for(const auto& s : stops) seen[std::size_t(s.node)] = 1;
  return std::size_t(std::count(seen.begin(), seen.end(), 1));
}

// The T-mesh's lengths read back at the integer values y: arcs of negative length and of length 0,
// spans shorter than 1, rectangles (four sides each in `face_sides`) of width or height 0
struct T_mesh_lengths { std::size_t negative_arcs = 0, collapsed_arcs = 0, short_spans = 0, collapsed_faces = 0; };

inline T_mesh_lengths t_mesh_lengths(const Separatrix_arcs& g, const std::vector<Linear_form>& face_sides, const Eigen::VectorXd& y)
{
  T_mesh_lengths r;
  for(const Linear_form& arc : g.forms) {
    const double l = arc(y);
    r.negative_arcs += l < -0.5;
    r.collapsed_arcs += std::abs(l) < 0.5;
  }
  for(const Linear_form& span : g.spans) r.short_spans += span(y) < 0.5;
  for(std::size_t k = 0; k + 1 < face_sides.size(); k += 4) r.collapsed_faces += face_sides[k](y) < 0.5 || face_sides[k + 1](y) < 0.5;
  return r;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INTEGER_GRID_MAP_T_MESH_FACES_H
