// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_CIRCLE_PACKING_FLOW_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_CIRCLE_PACKING_FLOW_H

// The discrete Ricci flow of Lai et al. 2010 (after Jin, Kim, Luo and Gu 2008): inversive
// distance circle packing metrics. Every vertex carries a circle of radius r_v = r0_v e^{u_v};
// edge ab has length l_ab^2 = r_a^2 + r_b^2 + 2 r_a r_b I_ab with a fixed inversive distance
// I_ab, chosen so that u = 0 reproduces the input lengths exactly (r0_v is a third of the
// shortest edge at v, so I_ab > 1: disjoint circles). Newton's method on K(u) = target on the
// fixed input triangulation, with the same solver, stopping rule and status as vertex scaling.

#include <CGAL/Surface_mesh_direction_fields/intrinsic_triangle.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh_arrays.h>
#include <CGAL/Surface_mesh_direction_fields/internal/ricci_flow.h>
#include <CGAL/Surface_mesh_direction_fields/internal/topology.h>

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

template <typename TM, typename Solver>
class Circle_packing_flow
{
public:
  Circle_packing_flow(const Mesh_arrays<TM>& m, const Topology_arrays& topo, const Solver& solver)
    : m_(m), chol_(solver), r0_(m.number_of_vertices(), std::numeric_limits<double>::infinity()), I_(m.number_of_edges())
  {
    for(std::size_t e = 0; e < m.number_of_edges(); ++e)
      for(int v : {m.target[2 * e], m.target[2 * e + 1]}) r0_[std::size_t(v)] = (std::min)(r0_[std::size_t(v)], m.length[e] / 3);
    for(std::size_t e = 0; e < m.number_of_edges(); ++e) {
      const double a = r0_[std::size_t(m.target[2 * e + 1])], b = r0_[std::size_t(m.target[2 * e])], l = m.length[e];
      I_[e] = (l * l - a * a - b * b) / (2 * a * b);
    }
    // one vertex per component is held (scaling all radii of a component keeps its angles)
    column_.assign(m.number_of_vertices(), -1);
    std::vector<char> held(topo.components.size(), 0);
    n_ = 0;
    for(std::size_t v = 0; v < m.number_of_vertices(); ++v) {
      if(m.is_isolated(int(v))) continue;
      const int c = topo.vertex_component[v];
      if(!held[std::size_t(c)]) { held[std::size_t(c)] = 1; continue; }
      column_[v] = n_++;
    }
  }

  const std::vector<double>& inversive_distances() const { return I_; }

  // Lengths for u; false if a face is not a valid triangle (its index in bad_face).
  bool lengths(const std::vector<double>& u, std::vector<double>& len, int* bad_face = nullptr) const
  {
    len.resize(m_.number_of_edges());
    for(std::size_t e = 0; e < len.size(); ++e) {
      const int a = m_.target[2 * e + 1], b = m_.target[2 * e];
      const double ra = r0_[std::size_t(a)] * std::exp(u[std::size_t(a)]), rb = r0_[std::size_t(b)] * std::exp(u[std::size_t(b)]);
      const double q = ra * ra + rb * rb + 2 * ra * rb * I_[e];
      len[e] = q > 0 ? std::sqrt(q) : 0.;
    }
    for(std::size_t f = 0; f < m_.number_of_faces(); ++f) {
      const int h0 = m_.face_halfedge[f], h1 = m_.next[std::size_t(h0)], h2 = m_.next[std::size_t(h1)];
      if(!is_valid_triangle(len[std::size_t(h0 >> 1)], len[std::size_t(h1 >> 1)], len[std::size_t(h2 >> 1)])) {
        if(bad_face) *bad_face = int(f);
        return false;
      }
    }
    return true;
  }

  // Curvatures: 2 pi - sum of angles (interior), pi - sum (boundary).
  void curvatures(const std::vector<double>& len, std::vector<double>& K) const
  {
    const std::size_t nv = m_.number_of_vertices();
    K.assign(nv, 0.);
    std::vector<char> boundary(nv, 0);
    for(std::size_t h = 0; h < m_.number_of_halfedges(); ++h) {
      if(m_.face[h] < 0) { boundary[std::size_t(m_.source(int(h)))] = 1; continue; }
      // the corner of face(h) at source(h): opposite the edge of next(h)
      const int n = m_.next[h], p = m_.next[std::size_t(n)];
      K[std::size_t(m_.source(int(h)))] += corner_angle(len[std::size_t(n >> 1)], len[h >> 1], len[std::size_t(p >> 1)]);
    }
    for(std::size_t v = 0; v < nv; ++v)
      if(!m_.is_isolated(int(v))) K[v] = (boundary[v] ? CGAL_PI : 2 * CGAL_PI) - K[v];
  }

  // dK/du by the chain rule: d theta_i / d l_i = l_i / 2A, d theta_i / d l_j = -l_i cos theta_k / 2A
  // (l_i opposite theta_i), and d l_ab / d u_a = (r_a^2 + r_a r_b I_ab) / l_ab. Symmetric for
  // inversive distance circle packings (Guo 2011); the lower triangle of the reduced matrix.
  void jacobian(const std::vector<double>& u, const std::vector<double>& len, Eigen::SparseMatrix<double, Eigen::ColMajor, int>& J) const
  {
    std::vector<Eigen::Triplet<double>> t;
    for(std::size_t f = 0; f < m_.number_of_faces(); ++f) {
      const int h[3] = {m_.face_halfedge[f], m_.next[std::size_t(m_.face_halfedge[f])], m_.next[std::size_t(m_.next[std::size_t(m_.face_halfedge[f])])]};
      // corner c sits at source(h[c]) and is opposite the edge of h[(c + 1) % 3]
      double l[3], theta[3];
      int vert[3];
      for(int c = 0; c < 3; ++c) { vert[c] = m_.source(h[c]); l[c] = len[std::size_t(h[(c + 1) % 3] >> 1)]; }
      for(int c = 0; c < 3; ++c) theta[c] = corner_angle(l[c], l[(c + 1) % 3], l[(c + 2) % 3]);
      const double A2 = 2 * triangle_area(l[0], l[1], l[2]);
      // edge opposite corner c joins the other two corners, vert[(c+1)%3] and vert[(c+2)%3]
      for(int c = 0; c < 3; ++c) {           // the angle theta_c
        for(int e = 0; e < 3; ++e) {         // the length l_e (opposite corner e)
          const double dtheta = e == c ? l[c] / A2 : -l[c] * std::cos(theta[3 - c - e]) / A2;
          const int a = vert[(e + 1) % 3], b = vert[(e + 2) % 3];
          const double ra = r0_[std::size_t(a)] * std::exp(u[std::size_t(a)]), rb = r0_[std::size_t(b)] * std::exp(u[std::size_t(b)]);
          const double Iab = I_[std::size_t(h[(e + 1) % 3] >> 1)];
          const double dla = (ra * ra + ra * rb * Iab) / l[e], dlb = (rb * rb + ra * rb * Iab) / l[e];
          // dK_{vert[c]} = -dtheta
          const int row = column_[std::size_t(vert[c])];
          if(row < 0) continue;
          for(const auto& w : {std::make_pair(a, dla), std::make_pair(b, dlb)}) {
            const int col = column_[std::size_t(w.first)];
            if(col >= 0 && col <= row) t.emplace_back(row, col, -dtheta * w.second * (col == row ? 1. : 0.5));
            if(col >= 0 && col > row) t.emplace_back(col, row, -dtheta * w.second * 0.5);
          }
        }
      }
    }
    J.resize(n_, n_);
    J.setFromTriplets(t.begin(), t.end());
    J.makeCompressed();
  }

  template <typename Visitor>
  Vertex_scaling_result run(const std::vector<double>& target, std::vector<double>& u, std::vector<double>& len,
                            int max_iterations, double tol, Visitor& visitor)
  {
    Vertex_scaling_result r;
    std::vector<double> K;
    int bad = -1;
    if(!lengths(u, len, &bad)) { r.message = "the initial radii give a degenerate triangle (face " + std::to_string(bad) + ")"; return r; }
    curvatures(len, K);
    auto error = [&](const std::vector<double>& k) {
      double e = 0;
      for(std::size_t v = 0; v < k.size(); ++v) if(!m_.is_isolated(int(v))) e = (std::max)(e, std::abs(k[v] - target[v]));
      return e;
    };
    auto norm2 = [&](const std::vector<double>& k) {
      double s = 0;
      for(std::size_t v = 0; v < k.size(); ++v) if(column_[v] >= 0) s += (k[v] - target[v]) * (k[v] - target[v]);
      return s;
    };
    r.max_error = error(K);
    visitor(0, r.max_error);
    Eigen::SparseMatrix<double, Eigen::ColMajor, int> J;
    for(int it = 1; it <= max_iterations && r.max_error > tol; ++it) {
      jacobian(u, len, J);
      std::string msg;
      // the pattern never changes: the symbolic analysis of the first iteration is reused
      if(n_ > 0 && !(it == 1 ? chol_.factor(J, msg) : chol_.refactor(J, msg))) {
        r.message = "the circle packing Jacobian could not be factored: " + msg;
        return r;
      }
      Eigen::VectorXd rhs(n_);
      for(std::size_t v = 0; v < u.size(); ++v) if(column_[v] >= 0) rhs[column_[v]] = target[v] - K[v];
      const Eigen::VectorXd du = n_ > 0 ? Eigen::VectorXd(chol_.solve(rhs)) : Eigen::VectorXd();
      // halve the step until every triangle is valid and the residual decreases
      const double before = norm2(K);
      double t = 1;
      std::vector<double> u2(u), len2, K2;
      bool accepted = false;
      for(int halvings = 0; halvings < 40 && !accepted; ++halvings, t /= 2) {
        for(std::size_t v = 0; v < u.size(); ++v) u2[v] = column_[v] >= 0 ? u[v] + t * du[column_[v]] : u[v];
        if(!lengths(u2, len2)) continue;
        curvatures(len2, K2);
        accepted = norm2(K2) < before;
      }
      r.iterations = it;
      if(!accepted) { r.message = "Newton steps of the circle packing flow no longer reduce the curvature error (the fixed triangulation may not carry the target)"; return r; }
      u.swap(u2);
      len.swap(len2);
      K.swap(K2);
      r.max_error = error(K);
      visitor(it, r.max_error);
    }
    r.converged = r.max_error <= tol;
    r.scaled_error = r.max_error;
    if(!r.converged && r.message.empty()) r.message = "no convergence after " + std::to_string(max_iterations) + " iterations";
    return r;
  }

private:
  const Mesh_arrays<TM>& m_;
  Solver chol_;
  std::vector<double> r0_, I_;
  std::vector<int> column_;
  int n_ = 0;
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_CIRCLE_PACKING_FLOW_H
