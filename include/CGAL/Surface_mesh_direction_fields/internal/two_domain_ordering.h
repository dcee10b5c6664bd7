// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_TWO_DOMAIN_ORDERING_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_TWO_DOMAIN_ORDERING_H

// Fill-reducing orderings of sparse symmetric patterns: AMD through CHOLMOD, and one level of
// nested dissection into two domains and a separator (the ordering of Two_domain_cholesky, also
// computed ahead of the system's assembly by the connection and Cholmod_cholesky).

#include <CGAL/Surface_mesh_direction_fields/internal/cholmod_errors.h>
#include <CGAL/Surface_mesh_direction_fields/internal/two_threads.h>

#include <cholmod.h>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// CHOLMOD's view (no copy) of the lower triangle of a symmetric n x n matrix in compressed
// columns with sorted rows; values == nullptr: the pattern only.
inline cholmod_sparse lower_triangle_view(int n, int* col_begin, int* rows, std::size_t nonzeros, double* values)
{
  cholmod_sparse A;
  A.nrow = A.ncol = std::size_t(n);
  A.nzmax = nonzeros;
  A.p = col_begin;
  A.i = rows;
  A.nz = nullptr;
  A.x = values;
  A.z = nullptr;
  A.stype = -1;
  A.itype = CHOLMOD_INT;
  A.xtype = values ? CHOLMOD_REAL : CHOLMOD_PATTERN;
  A.dtype = CHOLMOD_DOUBLE;
  A.sorted = 1;
  A.packed = 1;
  return A;
}

// AMD fill-reducing ordering of the symmetric pattern with n nodes whose strictly lower
// triangle is given in compressed columns (col_begin of size n + 1, sorted rows without
// duplicates): order[k] is the node eliminated k-th. Empty if CHOLMOD fails. Used to order the
// vertex rows of a mesh Laplacian before the rest of the system exists (it only needs the
// connectivity), so that the ordering can run concurrently with the assembly.
inline std::vector<int> amd_ordering(int n, std::vector<int>& col_begin, std::vector<int>& rows)
{
  std::vector<int> order(std::size_t(n), 0);
  if(n == 0) return order;
  cholmod_common cc;
  cholmod_start(&cc);
  make_cholmod_quiet(cc);   // failures are the return value, nothing is printed
  cholmod_sparse A = lower_triangle_view(n, col_begin.data(), rows.data(), rows.size(), nullptr);
  const bool ok = cholmod_amd(&A, nullptr, 0, order.data(), &cc) && cc.status == CHOLMOD_OK;
  cholmod_finish(&cc);
  if(!ok) order.clear();
  return order;
}

// The split: order[k] is the unknown eliminated k-th, the n1 unknowns of D1 first, then the n2
// of D2, then the separator. n1 = n2 = 0 when no useful split was found (order is then a plain
// fill-reducing order of the whole graph).
struct Two_domain_ordering
{
  std::vector<int> order;
  int n1 = 0, n2 = 0;
  bool is_split() const { return n1 > 0 && n2 > 0; }
};

// Splits the graph of a symmetric matrix (adjacency in compressed rows, both directions, no self
// loops) by a level set of a breadth-first search from a pseudo-peripheral node, chosen as the
// smallest level that leaves at least 35% of the nodes on each side, then thinned (a separator
// node with no neighbour on one side moves to the other). Nodes of degree above dense_degree
// (generator rows, constraint rows) join the separator; components other than the largest go
// to the smaller domain. Each domain is then ordered by AMD, the two concurrently. No split
// (AMD on the whole graph) when the largest component is too small or no level qualifies.
//
// max_separator: larger separators count as no split. order_if_no_split: without a split,
// return an AMD order of the whole graph (otherwise an empty order, saving that work).
inline Two_domain_ordering two_domain_ordering(int n, const std::vector<int>& adj_begin,
                                               const std::vector<int>& adj, int dense_degree,
                                               int max_separator, bool order_if_no_split)
{
  enum { D1 = 0, D2 = 1, SEP = 2, NONE = 3 };
  Two_domain_ordering result;
  std::vector<char> part(static_cast<std::size_t>(n), static_cast<char>(NONE));
  auto degree = [&](int v) { return adj_begin[v + 1] - adj_begin[v]; };
  for(int v = 0; v < n; ++v) if(degree(v) > dense_degree) part[v] = SEP;

  // breadth-first levels from `root` over non-dense nodes; returns the nodes in visiting order
  std::vector<int> level(std::size_t(n), -1);
  auto bfs = [&](int root, std::vector<int>& visited) {
    visited.clear();
    level[root] = 0;
    visited.push_back(root);
    for(std::size_t q = 0; q < visited.size(); ++q) {
      const int v = visited[q];
      for(int p = adj_begin[v]; p < adj_begin[v + 1]; ++p) {
        const int w = adj[p];
        if(part[w] == SEP || level[w] >= 0) continue;
        level[w] = level[v] + 1;
        visited.push_back(w);
      }
    }
  };
  // components: find the largest
  std::vector<int> component(std::size_t(n), -1), comp_size, visited;
  int largest = -1;
  int n_free = 0;
  for(int v = 0; v < n; ++v) {
    // degree-0 nodes (rows without neighbours) go anywhere: left out of the balance
    if(part[v] == SEP || level[v] >= 0 || degree(v) == 0) continue;
    bfs(v, visited);
    n_free += int(visited.size());
    const int c = int(comp_size.size());
    for(int w : visited) component[w] = c;
    comp_size.push_back(int(visited.size()));
    if(largest < 0 || comp_size[c] > comp_size[largest]) largest = c;
  }
  bool split = largest >= 0 && n_free >= 4;
  if(split && comp_size[largest] * 2 <= n_free) {
    // several components of similar size: they are independent, so no separator is needed
    std::vector<int> by_size(comp_size.size());
    for(std::size_t c = 0; c < by_size.size(); ++c) by_size[c] = int(c);
    std::sort(by_size.begin(), by_size.end(), [&](int a, int b) { return comp_size[a] > comp_size[b]; });
    std::vector<char> side(comp_size.size(), 0);
    long long size[2] = {0, 0};
    for(int c : by_size) { const int s = size[0] <= size[1] ? 0 : 1; side[c] = char(s); size[s] += comp_size[c]; }
    for(int v = 0; v < n; ++v) if(part[v] != SEP && component[v] >= 0) part[v] = side[component[v]] ? D2 : D1;
  } else if(split) {
    // pseudo-peripheral root: the last node of a search from any node of the component
    int root = 0;
    while(component[root] != largest) ++root;
    for(int v = 0; v < n; ++v) if(component[v] == largest) level[v] = -1;
    bfs(root, visited);
    root = visited.back();
    for(int v : visited) level[v] = -1;
    bfs(root, visited);
    const int depth = level[visited.back()] + 1;
    std::vector<long long> count(std::size_t(depth), 0);
    for(int v : visited) ++count[std::size_t(level[v])];
    const long long m = (long long)visited.size();
    long long before = 0, best_count = -1;
    int k = -1;
    for(int l = 0; l < depth; ++l) {
      const long long after = m - before - count[l];
      if(10 * (std::min)(before, after) >= 35 * m / 10 && (best_count < 0 || count[l] < best_count)) {
        best_count = count[l];
        k = l;
      }
      before += count[l];
    }
    if(k < 0) {
      split = false;
    } else {
      for(int v : visited) part[v] = level[v] < k ? D1 : level[v] > k ? D2 : SEP;
      // thinning: a separator node none of whose neighbours lies in D2 can join D1, and the
      // converse; decided against the current assignment, so D1 and D2 never touch
      for(int v : visited) {
        if(level[v] != k) continue;
        bool touches[2] = {false, false};
        for(int p = adj_begin[v]; p < adj_begin[v + 1]; ++p) {
          const int q = part[adj[p]];
          if(q == D1 || q == D2) touches[q] = true;
        }
        if(!touches[D2]) part[v] = D1;
        else if(!touches[D1]) part[v] = D2;
      }
      long long size[2] = {0, 0};
      for(int v : visited) if(part[v] == D1 || part[v] == D2) ++size[int(part[v])];
      // the other components, each whole, to the smaller side
      std::vector<char> side(comp_size.size(), char(NONE));
      for(int v = 0; v < n; ++v) {
        if(part[v] != NONE || component[v] < 0) continue;
        char& s = side[std::size_t(component[v])];
        if(s == NONE) { s = char(size[0] <= size[1] ? D1 : D2); size[int(s)] += comp_size[std::size_t(component[v])]; }
        part[v] = s;
      }
    }
  }
  for(int v = 0; v < n; ++v) if(part[v] == NONE) part[v] = D1;   // isolated nodes
  if(split) {
    int separator = 0;
    for(int v = 0; v < n; ++v) separator += part[v] == SEP;
    if(separator > max_separator) split = false;
  }

  // AMD within each domain (the whole graph when there is no split), concurrently
  auto order_part = [&](int which) {
    std::vector<int> local(std::size_t(n), -1), nodes;
    for(int v = 0; v < n; ++v) if(!split || part[v] == which) { local[v] = int(nodes.size()); nodes.push_back(v); }
    const int m = int(nodes.size());
    std::vector<int> col_begin(std::size_t(m) + 1, 0), rows;
    for(int j = 0; j < m; ++j) {
      const int v = nodes[j];
      for(int p = adj_begin[v]; p < adj_begin[v + 1]; ++p) {
        const int i = local[adj[p]];
        if(i > j) rows.push_back(i);
      }
      std::sort(rows.begin() + col_begin[j], rows.end());
      rows.erase(std::unique(rows.begin() + col_begin[j], rows.end()), rows.end());
      col_begin[j + 1] = int(rows.size());
    }
    std::vector<int> o = amd_ordering(m, col_begin, rows);
    if(int(o.size()) != m) { o.resize(std::size_t(m)); for(int i = 0; i < m; ++i) o[i] = i; }
    for(int& i : o) i = nodes[i];
    return o;
  };
  if(!split) {
    if(order_if_no_split) result.order = order_part(D1);
    return result;
  }
  std::vector<int> first, other;
  run_on_two_threads([&](int i) { (i == 0 ? first : other) = order_part(i == 0 ? D1 : D2); });
  result.n1 = int(first.size());
  result.n2 = int(other.size());
  result.order = std::move(first);
  result.order.insert(result.order.end(), other.begin(), other.end());
  for(int v = 0; v < n; ++v) if(part[v] == SEP) result.order.push_back(v);
  return result;
}

// Symmetric adjacency (both directions, no diagonal) of a lower-triangular pattern in
// compressed columns (the diagonal, if present, is skipped).
inline void symmetric_adjacency(int n, const int* col_begin, const int* rows,
                                std::vector<int>& adj_begin, std::vector<int>& adj)
{
  adj_begin.assign(std::size_t(n) + 1, 0);
  for(int j = 0; j < n; ++j)
    for(int p = col_begin[j]; p < col_begin[j + 1]; ++p)
      if(rows[p] != j) { ++adj_begin[std::size_t(rows[p]) + 1]; ++adj_begin[std::size_t(j) + 1]; }
  for(int v = 0; v < n; ++v) adj_begin[v + 1] += adj_begin[v];
  adj.resize(std::size_t(adj_begin[n]));
  std::vector<int> fill(adj_begin.begin(), adj_begin.end() - 1);
  for(int j = 0; j < n; ++j)
    for(int p = col_begin[j]; p < col_begin[j + 1]; ++p)
      if(rows[p] != j) { adj[fill[rows[p]]++] = j; adj[fill[j]++] = rows[p]; }
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_TWO_DOMAIN_ORDERING_H
