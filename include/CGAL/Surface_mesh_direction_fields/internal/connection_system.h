// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_CONNECTION_SYSTEM_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_CONNECTION_SYSTEM_H

// The linear system of a trivial connection (Crane et al. 2010, sections 2.4-2.8): one column
// per interior edge (the adjustment angles x), one row per interior vertex (minus one per
// closed component), per generator and per directional-constraint path; A x = -b. The
// minimum-norm solution is x = W A^T y with (A W A^T) y = -b, W the diagonal weights.
#include <CGAL/Surface_mesh_direction_fields/internal/cotan_weights.h>
#include <CGAL/Surface_mesh_direction_fields/Cholmod_cholesky.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh_arrays.h>
#include <CGAL/Surface_mesh_direction_fields/internal/development.h>
#include <CGAL/Surface_mesh_direction_fields/internal/field_propagation.h>
#include <CGAL/Surface_mesh_direction_fields/internal/topology.h>
#include <CGAL/Surface_mesh_direction_fields/internal/tree_cotree.h>
#include <CGAL/Surface_mesh_direction_fields/internal/two_domain_cholesky.h>
#include <CGAL/Surface_mesh_direction_fields/internal/two_domain_ordering.h>

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <future>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

struct Connection_system
{
  std::vector<int> col_of_edge_, edge_of_col_, row_of_vertex_;
  Eigen::VectorXd W_;                            // weights w_e per column
  Sparse_matrix_int A_;
  Eigen::Index rows_ = 0, first_generator_row_ = 0, first_constraint_row_ = 0;
  std::vector<std::vector<int>> constraint_paths_;
  std::vector<std::pair<int, int>> constraint_targets_;
  std::future<Two_domain_ordering> vertex_order_future_;
  Two_domain_ordering vertex_split_;             // order of the vertex rows
  int domain_rows_[2] = {0, 0};                  // rows in the two domains of vertex_split_
  bool vertex_order_is_amd_ = false;

  // Launches the AMD ordering of the graph of interior vertices (interior edges between them).
  // The task owns its input, so it never touches this object.
  template <typename TM>
  void start_vertex_ordering(const Mesh_arrays<TM>& m_)
  {
    const int nv = int(m_.number_of_vertices());
    auto interior = [&](int v) { return !m_.is_isolated(v) && !m_.is_boundary_vertex(v); };
    std::vector<int> col_begin(std::size_t(nv) + 1, 0);
    for(std::size_t e = 0; e < m_.number_of_edges(); ++e) {
      const int u = m_.target[2 * e], w = m_.target[2 * e + 1];
      if(u != w && interior(u) && interior(w)) ++col_begin[std::size_t((std::min)(u, w)) + 1];
    }
    for(int v = 0; v < nv; ++v) col_begin[v + 1] += col_begin[v];
    std::vector<int> rows(static_cast<std::size_t>(col_begin[nv]));
    std::vector<int> fill(col_begin.begin(), col_begin.end() - 1);
    for(std::size_t e = 0; e < m_.number_of_edges(); ++e) {
      const int u = m_.target[2 * e], w = m_.target[2 * e + 1];
      if(u != w && interior(u) && interior(w)) rows[fill[(std::min)(u, w)]++] = (std::max)(u, w);
    }
    // sort each column and drop repeated edges
    int k = 0;
    for(int v = 0; v < nv; ++v) {
      const int b = col_begin[v], e = col_begin[v + 1];
      std::sort(rows.begin() + b, rows.begin() + e);
      col_begin[v] = k;
      for(int i = b; i < e; ++i)
        if(i == b || rows[i] != rows[i - 1]) rows[k++] = rows[i];
    }
    col_begin[nv] = k;
    rows.resize(std::size_t(k));
    vertex_order_future_ = std::async(std::launch::async,
        [nv](std::vector<int> cb, std::vector<int> r) {
          Two_domain_ordering o;
          if(nv < Cholmod_cholesky::two_domain_min_rows) {
            o.order = amd_ordering(nv, cb, r);
            return o;
          }
          std::vector<int> adj_begin, adj;
          symmetric_adjacency(nv, cb.data(), r.data(), adj_begin, adj);
          return two_domain_ordering(nv, adj_begin, adj, (std::numeric_limits<int>::max)(),
                                               Cholmod_cholesky::max_separator, true);
        },
        std::move(col_begin), std::move(rows));
  }


  // How the weights w_e are made (Connection_weights): 1, or the cotan formula with its two
  // cotangents optionally clamped at 0 each, then kept in [floor, cap] times the mean positive
  // weight (cap <= 0: no upper bound).
  struct Weight_rule
  {
    bool unit = false;
    bool nonnegative_cotangents = false;
    double floor = 1e-3, cap = 0;
  };

  template <typename TM>
  void compute_weights(const Mesh_arrays<TM>& m_, const Weight_rule& rule)
  {
    col_of_edge_.assign(m_.number_of_edges(), -1);
    edge_of_col_.clear();
    for(std::size_t e = 0; e < m_.number_of_edges(); ++e) {
      if(m_.is_border_edge(int(e))) continue;
      col_of_edge_[e] = int(edge_of_col_.size());
      edge_of_col_.push_back(int(e));
    }
    W_.setOnes(Eigen::Index(edge_of_col_.size()));
    if(rule.unit) return;
    const std::vector<double> w =
        cotan_edge_weights(m_, rule.nonnegative_cotangents ? 0. : -std::numeric_limits<double>::infinity());
    double sum = 0;
    std::size_t count = 0;
    for(int e : edge_of_col_) if(w[e] > 0 && std::isfinite(w[e])) { sum += w[e]; ++count; }
    const double mean = count ? sum / double(count) : 1.;
    const double lo = rule.floor * mean, hi = rule.cap > 0 ? rule.cap * mean : std::numeric_limits<double>::infinity();
    for(std::size_t c = 0; c < edge_of_col_.size(); ++c) {
      const double x = w[edge_of_col_[c]];
      W_[Eigen::Index(c)] = x >= lo ? (x <= hi ? x : hi) : lo;   // NaN (degenerate face) -> lo
    }
  }


  // lambda_max / lambda_min of A W A^T: 20 power iterations with the matrix, 20 with its
  // factored inverse (each an underestimate of its eigenvalue, so the ratio is a lower bound,
  // usually within a factor of a few). Only for the diagnosis of inaccurate solves.
  template <typename Solver>
  double condition_estimate(const Solver& chol) const
  {
    const Eigen::Index n = Eigen::Index(rows_);
    auto apply = [this](const Eigen::VectorXd& v) -> Eigen::VectorXd {
      return A_ * (W_.asDiagonal() * (A_.transpose() * v));
    };
    auto largest = [n](auto op) {
      Eigen::VectorXd v(n);
      for(Eigen::Index i = 0; i < n; ++i) v[i] = 1. + 0.5 * std::sin(1.7 * double(i));
      double lambda = 0;
      for(int it = 0; it < 20; ++it) {
        v.normalize();
        const Eigen::VectorXd w = op(v);
        lambda = v.dot(w);
        if(!std::isfinite(lambda) || w.norm() == 0) return 0.;
        v = w;
      }
      return lambda;
    };
    const double big = largest(apply);
    const double inverse_small = largest([&chol](const Eigen::VectorXd& v) { return Eigen::VectorXd(chol.solve(v)); });
    return big > 0 && inverse_small > 0 ? big * inverse_small : std::numeric_limits<double>::infinity();
  }

  // Rows: interior vertices (minus one per closed component), generators, constraint paths.
  // A is assembled column by column (one column per interior edge): the vertex rows of an edge
  // come first and in increasing order, then the generator and constraint rows.
  template <typename TM>
  void build(const Mesh_arrays<TM>& m_, const Topology_arrays& topo_, const std::vector<Generator_arrays>& gens_,
             const std::vector<int>& constrained_faces_, const Face_tree& tree)
  {
    const int ne = int(m_.number_of_edges());
    row_of_vertex_.assign(m_.number_of_vertices(), -1);
    std::vector<char> dropped(topo_.components.size(), 0), has_row(m_.number_of_vertices(), 0);
    for(std::size_t v = 0; v < m_.number_of_vertices(); ++v) {
      if(m_.is_isolated(int(v)) || m_.is_boundary_vertex(int(v))) continue;
      const int c = topo_.vertex_component[v];
      if(topo_.components[c].boundary_loops == 0 && !dropped[c]) { dropped[c] = 1; continue; }
      has_row[v] = 1;
    }
    // vertex rows numbered in the fill-reducing order when there is one
    if(vertex_order_future_.valid()) {
      vertex_split_ = vertex_order_future_.get();
      vertex_order_is_amd_ = vertex_split_.order.size() == m_.number_of_vertices();
    }
    if(vertex_split_.order.size() != m_.number_of_vertices()) {
      vertex_split_ = Two_domain_ordering();
      vertex_split_.order.resize(m_.number_of_vertices());
      std::iota(vertex_split_.order.begin(), vertex_split_.order.end(), 0);
    }
    // rows of the two domains of the split (the separator rows and all others follow them)
    domain_rows_[0] = domain_rows_[1] = 0;
    int r = 0;
    for(std::size_t k = 0; k < vertex_split_.order.size(); ++k) {
      const int v = vertex_split_.order[k];
      if(has_row[v]) row_of_vertex_[v] = r++;
      if(k + 1 == std::size_t(vertex_split_.n1)) domain_rows_[0] = r;
      if(k + 1 == std::size_t(vertex_split_.n1 + vertex_split_.n2)) domain_rows_[1] = r - domain_rows_[0];
    }
    // sparse rows beyond the vertex rows: (column, row, value)
    struct Entry { int col, row; double value; };
    std::vector<Entry> extra;
    first_generator_row_ = r;
    for(const auto& g : gens_) {
      for(int h : g.dual) extra.push_back(Entry{col_of_edge_[h >> 1], r, (h & 1) ? -1. : 1.});
      ++r;
    }
    first_constraint_row_ = r;
    constraint_paths_.clear();
    constraint_targets_.clear();
    std::vector<int> constrained(m_.number_of_faces(), -1);
    for(std::size_t i = 0; i < constrained_faces_.size(); ++i) constrained[constrained_faces_[i]] = int(i);
    for(std::size_t i = 0; i < constrained_faces_.size(); ++i) {
      int f = constrained_faces_[i];
      if(tree.parent_cross_[f] < 0) continue;   // a root
      std::vector<int> path;
      do {
        const int up = tree.parent_cross_[f] ^ 1;   // enters the parent
        path.push_back(up);
        f = m_.face[up];
      } while(constrained[f] < 0);
      for(int h : path) extra.push_back(Entry{col_of_edge_[h >> 1], r, (h & 1) ? -1. : 1.});
      constraint_paths_.push_back(path);
      constraint_targets_.push_back(std::make_pair(int(i), constrained[f]));
      ++r;
    }
    rows_ = r;
    std::sort(extra.begin(), extra.end(),
              [](const Entry& a, const Entry& b) { return a.col != b.col ? a.col < b.col : a.row < b.row; });

    const int ncols = int(edge_of_col_.size());
    // compressed columns written in place (insert() into reserved columns and makeCompressed()
    // made build_system() 0.30 s instead of 0.17 s at 1M faces)
    A_.resize(r, ncols);
    A_.resizeNonZeros(2 * ncols + int(extra.size()));
    int* outer = A_.outerIndexPtr();
    int* inner = A_.innerIndexPtr();
    double* value = A_.valuePtr();
    int nz = 0;
    auto put_entry = [&](int row, double v) { inner[nz] = row; value[nz++] = v; };
    std::size_t k = 0;
    for(int c = 0; c < ncols; ++c) {
      outer[c] = nz;
      const int e = edge_of_col_[c];
      // vertex u = source(2e) crosses 2e (sign +1), w = target(2e) crosses 2e + 1 (sign -1)
      const int ru = row_of_vertex_[m_.target[2 * e + 1]], rw = row_of_vertex_[m_.target[2 * e]];
      if(ru >= 0 && ru == rw) {}   // an edge from a vertex to itself (intrinsic triangulations): crossed both ways, 0
      else if(ru >= 0 && rw >= 0 && rw < ru) { put_entry(rw, -1.); put_entry(ru, 1.); }
      else { if(ru >= 0) put_entry(ru, 1.); if(rw >= 0) put_entry(rw, -1.); }
      for(; k < extra.size() && extra[k].col == c; ++k) {
        double v = extra[k].value;
        while(k + 1 < extra.size() && extra[k + 1].col == c && extra[k + 1].row == extra[k].row) v += extra[++k].value;
        if(v != 0) put_entry(extra[k].row, v);
      }
    }
    outer[ncols] = nz;
    A_.data().resize(nz);
    CGAL_USE(ne);
  }


  // Lower triangle of A W A^T, the sum over columns c of w_c a_c a_c^T (a column of A has two
  // vertex entries plus one per generator or constraint path crossing the edge), assembled in
  // compressed form: diagonal first in each column, then the off-diagonal products, sorted and
  // merged column by column. (Triplets and setFromTriplets took 0.52 s and 35k page faults,
  // 140 MB of transient memory, at 1M faces.)
  Sparse_matrix_int normal_matrix() const
  {
    const int n = int(rows_);
    Sparse_matrix_int L(n, n);
    if(n == 0) return L;
    std::vector<int> begin(std::size_t(n) + 1, 0);
    for(Eigen::Index c = 0; c < A_.outerSize(); ++c) {
      const int b = A_.outerIndexPtr()[c], e = A_.outerIndexPtr()[c + 1];
      for(int p = b; p < e; ++p) begin[std::size_t(A_.innerIndexPtr()[p]) + 1] += e - p - 1;
    }
    for(int j = 0; j < n; ++j) begin[j + 1] += begin[j] + 1;   // + 1: the diagonal
    L.resizeNonZeros(begin[n]);
    int* outer = L.outerIndexPtr();
    int* inner = L.innerIndexPtr();
    double* value = L.valuePtr();
    std::vector<int> fill(begin.begin(), begin.end() - 1);
    for(int j = 0; j < n; ++j) { inner[fill[j]] = j; value[fill[j]++] = 0; }
    // rows within a column of A are increasing (build_system), so i < k below
    for(Eigen::Index c = 0; c < A_.outerSize(); ++c) {
      const double w = W_[c];
      const int b = A_.outerIndexPtr()[c], e = A_.outerIndexPtr()[c + 1];
      for(int p = b; p < e; ++p) {
        const int i = A_.innerIndexPtr()[p];
        const double wa = w * A_.valuePtr()[p];
        value[begin[i]] += wa * A_.valuePtr()[p];
        for(int q = p + 1; q < e; ++q) {
          inner[fill[i]] = A_.innerIndexPtr()[q];
          value[fill[i]++] = wa * A_.valuePtr()[q];
        }
      }
    }
    std::vector<std::pair<int, double>> column;
    int k = 0;
    for(int j = 0; j < n; ++j) {
      const int b = begin[j], e = begin[j + 1];
      column.assign(1, std::make_pair(inner[b], value[b]));
      for(int p = b + 1; p < e; ++p) column.emplace_back(inner[p], value[p]);
      std::sort(column.begin() + 1, column.end(),
                [](const std::pair<int, double>& x, const std::pair<int, double>& y) { return x.first < y.first; });
      outer[j] = k;
      for(std::size_t p = 0; p < column.size(); ++p) {
        if(p > 1 && column[p].first == inner[k - 1]) { value[k - 1] += column[p].second; continue; }
        inner[k] = column[p].first;
        value[k++] = column[p].second;
      }
    }
    outer[n] = k;
    L.data().resize(k);
    return L;
  }


  // b: the Levi-Civita holonomy of every row's cycle minus 2 pi times its target
  template <typename TM>
  Eigen::VectorXd rhs(const Mesh_arrays<TM>& m_, const std::vector<double>& K_, const std::vector<double>& index_,
                      const std::vector<double>& z_, const std::vector<double>& turning_,
                      const std::vector<double>& constraint_angles_, int N_) const
  {
    Eigen::VectorXd b(rows_);
    for(std::size_t v = 0; v < row_of_vertex_.size(); ++v)
      if(row_of_vertex_[v] >= 0) b[row_of_vertex_[v]] = K_[v] - 2 * CGAL_PI * index_[v];
    for(std::size_t g = 0; g < z_.size(); ++g)
      b[first_generator_row_ + Eigen::Index(g)] = z_[g] - 2 * CGAL_PI * turning_[g];
    const double period = 2 * CGAL_PI / N_;
    for(std::size_t i = 0; i < constraint_paths_.size(); ++i) {
      const double gm = constraint_angles_[constraint_targets_[i].first];
      const double gn = constraint_angles_[constraint_targets_[i].second];
      const double wanted = gn - gm - transport_along(m_, constraint_paths_[i]);
      const double rot = std::remainder(wanted, period);   // smallest rotation mod 2pi/N
      b[first_constraint_row_ + Eigen::Index(i)] = -rot;
    }
    return b;
  }


  // Holonomy error of the dual cells of the vertices without a row (one per closed component).
  template <typename TM>
  double dropped_vertices_holonomy_error(const Mesh_arrays<TM>& m_, const std::vector<double>& K_,
                                         const std::vector<double>& index_, const std::vector<double>& x_) const
  {
    double err = 0;
    for(std::size_t v = 0; v < m_.number_of_vertices(); ++v) {
      if(row_of_vertex_[v] >= 0 || m_.is_isolated(int(v)) || m_.is_boundary_vertex(int(v))) continue;
      double s = K_[v];
      const int h0 = m_.vertex_out[v];
      int h = h0;
      do { s += (h & 1) ? -x_[h >> 1] : x_[h >> 1]; h = m_.ccw_out(h); } while(h != h0);
      err = std::max(err, std::abs(s - 2 * CGAL_PI * index_[v]));
    }
    return err;
  }

};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_CONNECTION_SYSTEM_H
