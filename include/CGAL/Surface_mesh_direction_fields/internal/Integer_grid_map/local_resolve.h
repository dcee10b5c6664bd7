// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INTEGER_GRID_MAP_LOCAL_RESOLVE_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INTEGER_GRID_MAP_LOCAL_RESOLVE_H

// The integer-grid map's vertex unknowns re-solved on a region only, the others held: the local
// stiffening of Bommes et al. changes the weights of a few faces, and its effect on the map is
// local, so the system restricted to the unknowns near them (the rest as boundary values) gives
// the new map there without factoring the whole system again.

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <cstddef>
#include <functional>
#include <queue>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// Solves H_FF z_F = g_F - H_FC z_C for the unknowns F with free[c] != 0 among the first `nb`
// (H: the leading nb x nb block of `lower`, whose lower triangle holds the symmetric system),
// writing z_F into z; the others keep their values. False (z unchanged) if H_FF cannot be
// factored, with `message` saying so.
template <typename SparseMatrix>
bool resolve_on_region(const SparseMatrix& lower, int nb, const Eigen::VectorXd& g, const std::vector<char>& free, Eigen::VectorXd& z,
                       std::string& message)
{
  std::vector<int> local(std::size_t(nb), -1);
  int n = 0;
  for(int c = 0; c < nb; ++c) if(free[std::size_t(c)]) local[std::size_t(c)] = n++;
  if(n == 0) return true;
  Eigen::VectorXd r(n);
  for(int c = 0; c < nb; ++c) if(local[std::size_t(c)] >= 0) r[local[std::size_t(c)]] = g[c];
  std::vector<Eigen::Triplet<double>> t;
  // one pass over the whole lower triangle (a few ms per million entries) instead of a
  // factorisation of the whole system (seconds)
  for(int c = 0; c < nb; ++c)
    for(typename SparseMatrix::InnerIterator it(lower, c); it; ++it) {
      const int row = int(it.row());
      if(row >= nb) continue;
      const int a = local[std::size_t(row)], b = local[std::size_t(c)];
      if(a >= 0 && b >= 0) t.emplace_back((std::max)(a, b), (std::min)(a, b), it.value());
      else if(a >= 0) r[a] -= it.value() * z[c];
      else if(b >= 0) r[b] -= it.value() * z[row];
    }
  Eigen::SparseMatrix<double> H(n, n);
  H.setFromTriplets(t.begin(), t.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> ldlt(H);
  if(ldlt.info() != Eigen::Success) { message = "the map's system on the stiffened region could not be factored"; return false; }
  const Eigen::VectorXd x = ldlt.solve(r);
  if(!x.allFinite()) { message = "the map's system on the stiffened region has no finite solution"; return false; }
  for(int c = 0; c < nb; ++c) if(local[std::size_t(c)] >= 0) z[c] = x[local[std::size_t(c)]];
  return true;
}

// Marks in `mark` the vertices within `radius` of the corners of `faces` along the edges of `m`
// (its lengths), and those within `min_rings` rings of them. `reach` (+infinity) and `hops` (0)
// are work arrays of one entry per vertex, kept from call to call: a vertex reached by an
// earlier call is expanded again only from closer.
template <typename MeshArrays>
void mark_vertices_near_faces(const MeshArrays& m, const std::vector<std::size_t>& faces, double radius, int min_rings,
                              std::vector<double>& reach, std::vector<int>& hops, std::vector<char>& mark)
{
  typedef std::pair<double, std::size_t> Item;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for(std::size_t f : faces) {
    int x = m.face_halfedge[f];
    for(int i = 0; i < 3; ++i, x = m.next[std::size_t(x)]) {
      const std::size_t v = std::size_t(m.source(x));
      if(reach[v] > 0) { reach[v] = 0; hops[v] = 0; queue.emplace(0., v); }
    }
  }
  while(!queue.empty()) {
    const Item it = queue.top();
    queue.pop();
    const std::size_t v = it.second;
    if(it.first > reach[v]) continue;
    mark[v] = 1;
    for(int g = m.vertex_out[v], g0 = g;;) {
      const std::size_t w = std::size_t(m.target[std::size_t(g)]);
      const double dw = it.first + m.length[std::size_t(g >> 1)];
      if((dw <= radius || hops[v] < min_rings) && dw < reach[w]) { reach[w] = dw; hops[w] = hops[v] + 1; queue.emplace(dw, w); }
      if(m.face[std::size_t(g)] < 0) break;   // a boundary vertex's fan ends at the border
      g = m.ccw_out(g);
      if(g == g0) break;
    }
  }
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INTEGER_GRID_MAP_LOCAL_RESOLVE_H
