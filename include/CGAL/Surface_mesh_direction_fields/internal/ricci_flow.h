// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_RICCI_FLOW_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_RICCI_FLOW_H

#include <CGAL/Surface_mesh_direction_fields/intrinsic_triangle.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh_arrays.h>
#include <CGAL/Surface_mesh_direction_fields/internal/topology.h>
#include <CGAL/Surface_mesh_direction_fields/internal/sparse_solvers.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

struct Vertex_scaling_result
{
  bool converged = false;
  int iterations = 0;
  double max_error = 0;
  std::string message;
};

// Discrete conformal vertex scaling on a fixed triangulation,
// l_e(u) = l0_e exp((u_a + u_b) / 2), solved for K(u) = target by Newton's method.
// dK/du is the cotan Laplacian L (L_ab = -(cot alpha + cot beta) / 2, rows summing to 0), which
// is positive semi-definite for every valid metric with the constants of each component as
// kernel; one vertex per component is fixed (u = 0) and the reduced matrix is positive definite.
template <typename TM>
class Vertex_scaling_flow
{
public:
  Vertex_scaling_flow(const Mesh_arrays<TM>& m, const Topology_arrays& topo)
    : m_(m), topo_(topo)
  {
    const int nv = int(m.number_of_vertices());
    col_.assign(nv, -1);
    std::vector<char> comp_fixed(topo.components.size(), 0);
    n_ = 0;
    for(int v = 0; v < nv; ++v) {
      const int c = topo.vertex_component[v];
      if(c < 0) continue;                       // isolated
      if(!comp_fixed[c]) { comp_fixed[c] = 1; continue; }   // gauge: first vertex of each component
      col_[v] = n_++;
    }
    build_pattern();
  }

  // Strictly valid triangles whose relative area is above the threshold that Mesh_arrays
  // rejects as degenerate; writes the corner angles (as Mesh_arrays::angle).
  bool angles(const std::vector<double>& len, std::vector<double>& ang, int* bad_face = nullptr) const
  {
    ang.assign(m_.number_of_halfedges(), 0.);
    for(std::size_t f = 0; f < m_.number_of_faces(); ++f) {
      const int h0 = m_.face_halfedge[f], h1 = m_.next[h0], h2 = m_.next[h1];
      const double l0 = len[h0 >> 1], l1 = len[h1 >> 1], l2 = len[h2 >> 1];
      const double lmax = (std::max)(l0, (std::max)(l1, l2));
      if(!is_valid_triangle(l0, l1, l2) || !(triangle_area(l0, l1, l2) > 1e-14 * lmax * lmax)) {
        if(bad_face) *bad_face = int(f);
        return false;
      }
      ang[h0] = corner_angle(l1, l0, l2);
      ang[h1] = corner_angle(l2, l1, l0);
      ang[h2] = corner_angle(l0, l2, l1);
    }
    return true;
  }

  void curvatures(const std::vector<double>& ang, std::vector<double>& k) const
  {
    const std::size_t nv = m_.number_of_vertices();
    k.assign(nv, 0.);
    for(std::size_t h = 0; h < m_.number_of_halfedges(); ++h)
      if(m_.face[h] >= 0) k[m_.source(int(h))] += ang[h];
    for(std::size_t v = 0; v < nv; ++v)
      if(!m_.is_isolated(int(v)))
        k[v] = (m_.is_boundary_vertex(int(v)) ? CGAL_PI : 2 * CGAL_PI) - k[v];
  }

  void lengths(const std::vector<double>& u, std::vector<double>& len) const
  {
    len.resize(m_.number_of_edges());
    for(std::size_t e = 0; e < m_.number_of_edges(); ++e)
      len[e] = m_.length[e] * std::exp(0.5 * (u[m_.target[2 * e]] + u[m_.target[2 * e + 1]]));
  }

  double max_error(const std::vector<double>& k, const std::vector<double>& target) const
  {
    double err = 0;
    for(std::size_t v = 0; v < k.size(); ++v)
      if(!m_.is_isolated(int(v))) err = (std::max)(err, std::abs(k[v] - target[v]));
    return err;
  }

  // u: in/out conformal factors (start value on input); len: output lengths.
  template <typename Callback>
  Vertex_scaling_result run(const std::vector<double>& target, std::vector<double>& u,
                            std::vector<double>& len, int max_iterations, double tol,
                            Callback& callback)
  {
    Vertex_scaling_result res;
    std::vector<double> ang, k, u_try, len_try, ang_try, k_try;
    lengths(u, len);
    int bad = -1;
    if(!angles(len, ang, &bad)) {
      res.message = "the initial conformal factors give a degenerate triangle (face " +
                    std::to_string(bad) + ")";
      return res;
    }
    curvatures(ang, k);
    double err = max_error(k, target);
    double norm2 = residual_norm2(k, target);
    callback(0, err);
    bool analysed = false;
    int it = 0;
    // Stagnation against the boundary of the valid metrics: steps cut short by degenerating
    // triangles while the error hardly decreases.
    std::vector<double> err_history(1, err);
    int cut_streak = 0, cut_face = -1;
    while(err > tol && it < max_iterations) {
      fill_values(ang);
      std::string msg;
      const bool ok = analysed ? chol_.refactor(L_, msg) : chol_.factor(L_, msg);
      analysed = true;
      if(!ok) {
        res.message = "iteration " + std::to_string(it + 1) + ": " + msg;
        break;
      }
      Eigen::VectorXd rhs(n_);
      for(std::size_t v = 0; v < col_.size(); ++v)
        if(col_[v] >= 0) rhs[col_[v]] = target[v] - k[v];
      const Eigen::VectorXd du = n_ > 0 ? chol_.solve(rhs) : Eigen::VectorXd();
      if(!du.allFinite()) {
        res.message = "iteration " + std::to_string(it + 1) + ": the Newton step is not finite";
        break;
      }
      // Backtracking (Armijo on |K - target|^2, for which the Newton step is a descent
      // direction) that only accepts metrics with valid triangles.
      double t = 1;
      bool accepted = false, last_invalid = false, any_invalid = false;
      int last_bad = -1;
      for(int ls = 0; ls < 60; ++ls, t *= 0.5) {
        u_try = u;
        for(std::size_t v = 0; v < col_.size(); ++v)
          if(col_[v] >= 0) u_try[v] += t * du[col_[v]];
        lengths(u_try, len_try);
        if(!angles(len_try, ang_try, &last_bad)) {
          last_invalid = any_invalid = true;
          cut_face = last_bad;
          continue;
        }
        last_invalid = false;
        curvatures(ang_try, k_try);
        const double n2 = residual_norm2(k_try, target);
        if(n2 <= (1 - 2e-4 * t) * norm2) { accepted = true; break; }
      }
      if(!accepted) {
        std::ostringstream os;
        os.precision(3);
        if(last_invalid)
          os << "iteration " << it + 1 << ": the line search cannot keep the triangles valid (face "
             << last_bad << " degenerates); the fixed triangulation cannot carry the target metric"
             << " (intrinsic edge flips or better-placed cones would be needed)";
        else
          os << "iteration " << it + 1 << ": the line search found no decrease of the curvature"
             << " error (stagnation at " << err << ", rounding level of this metric)";
        res.message = os.str();
        break;
      }
      u.swap(u_try); len.swap(len_try); ang.swap(ang_try); k.swap(k_try);
      norm2 = residual_norm2(k, target);
      err = max_error(k, target);
      ++it;
      callback(it, err);
      err_history.push_back(err);
      cut_streak = any_invalid ? cut_streak + 1 : 0;
      const int window = 10;
      if(err > tol && cut_streak >= window && err > 0.9 * err_history[err_history.size() - 1 - window]) {
        std::ostringstream os;
        os.precision(3);
        os << "stopped after iteration " << it << ": for " << window << " iterations every Newton "
           << "step had to be shortened to keep the triangles valid (face " << cut_face
           << " degenerates) and the curvature error only went from "
           << err_history[err_history.size() - 1 - window] << " to " << err
           << "; the fixed triangulation cannot carry the target metric"
           << " (intrinsic edge flips or better-placed cones would be needed)";
        res.message = os.str();
        break;
      }
    }
    res.iterations = it;
    res.max_error = err;
    res.converged = err <= tol;
    if(!res.converged && res.message.empty()) {
      std::ostringstream os;
      os << "no convergence after " << it << " iterations (maximum curvature error " << err << ")";
      res.message = os.str();
    }
    return res;
  }

private:
  const Mesh_arrays<TM>& m_;
  const Topology_arrays& topo_;
  std::vector<int> col_;   // per vertex: column of the reduced system, -1 if fixed or isolated
  int n_ = 0;
  Sparse_matrix_int L_;    // lower triangle of the reduced Hessian
  std::vector<int> edge_pos_, diag_pos_;
  std::vector<double> w_;
  Cholmod_factor chol_;

  double residual_norm2(const std::vector<double>& k, const std::vector<double>& target) const
  {
    double s = 0;
    for(std::size_t v = 0; v < k.size(); ++v)
      if(!m_.is_isolated(int(v))) s += (k[v] - target[v]) * (k[v] - target[v]);
    return s;
  }

  int position(int row, int col) const
  {
    const int* inner = L_.innerIndexPtr();
    const int b = L_.outerIndexPtr()[col], e = L_.outerIndexPtr()[col + 1];
    const int* p = std::lower_bound(inner + b, inner + e, row);
    CGAL_assertion(p != inner + e && *p == row);
    return int(p - inner);
  }

  void build_pattern()
  {
    std::vector<Eigen::Triplet<double, int>> trip;
    for(int c = 0; c < n_; ++c) trip.emplace_back(c, c, 1.);
    for(std::size_t e = 0; e < m_.number_of_edges(); ++e) {
      const int a = col_[m_.target[2 * e]], b = col_[m_.target[2 * e + 1]];
      if(a >= 0 && b >= 0) trip.emplace_back((std::max)(a, b), (std::min)(a, b), 1.);
    }
    L_.resize(n_, n_);
    L_.setFromTriplets(trip.begin(), trip.end());
    L_.makeCompressed();
    diag_pos_.resize(n_);
    for(int c = 0; c < n_; ++c) diag_pos_[c] = position(c, c);
    edge_pos_.assign(m_.number_of_edges(), -1);
    for(std::size_t e = 0; e < m_.number_of_edges(); ++e) {
      const int a = col_[m_.target[2 * e]], b = col_[m_.target[2 * e + 1]];
      if(a >= 0 && b >= 0) edge_pos_[e] = position((std::max)(a, b), (std::min)(a, b));
    }
  }

  // Cotan Laplacian of the metric with corner angles `ang`, restricted to the free vertices.
  void fill_values(const std::vector<double>& ang)
  {
    w_.assign(m_.number_of_edges(), 0.);
    for(std::size_t h = 0; h < m_.number_of_halfedges(); ++h) {
      if(m_.face[h] < 0) continue;
      const double opp = ang[m_.prev(int(h))];   // corner opposite to the edge of h
      w_[h >> 1] += 0.5 * std::cos(opp) / std::sin(opp);
    }
    double* val = L_.valuePtr();
    std::fill(val, val + L_.nonZeros(), 0.);
    for(std::size_t e = 0; e < m_.number_of_edges(); ++e) {
      const int a = col_[m_.target[2 * e]], b = col_[m_.target[2 * e + 1]];
      if(a >= 0) val[diag_pos_[a]] += w_[e];
      if(b >= 0) val[diag_pos_[b]] += w_[e];
      if(edge_pos_[e] >= 0) val[edge_pos_[e]] -= w_[e];
    }
  }
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_RICCI_FLOW_H
