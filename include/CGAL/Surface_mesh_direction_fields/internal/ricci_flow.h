// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_RICCI_FLOW_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_RICCI_FLOW_H

// The Newton flow of discrete conformal vertex scaling (Springborn, Schroeder, Pinkall 2008)
// with intrinsic Delaunay flips, one class whose steps are short member functions. Over 600
// lines because the flip phase and the Newton phase share the triangulation state; splitting
// them would pass that state between headers.

#include <CGAL/Surface_mesh_direction_fields/intrinsic_triangle.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh_arrays.h>
#include <CGAL/Surface_mesh_direction_fields/internal/topology.h>
#include <CGAL/Surface_mesh_direction_fields/Cholmod_cholesky.h>

#include <algorithm>
#include <array>
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
  double max_error = 0;      // max |K - target|
  double scaled_error = 0;   // the convergence measure, see scaled_error()
  double rounding_level = 0; // max_v of the rounding level, see curvatures()
  std::size_t flips = 0;
  std::string message;
};

// Triangle connectivity that intrinsic edge flips may change, with the halfedge numbering of
// Mesh_arrays (h = 2e + s); a flip keeps the edge's index and its two faces' indices.
struct Flippable_triangulation
{
  std::vector<int> next, target, face, face_halfedge;

  int prev(int h) const { return next[next[h]]; }
  int source(int h) const { return target[h ^ 1]; }
  bool is_flippable(int e) const
  {
    return face[2 * e] >= 0 && face[2 * e + 1] >= 0 && face[2 * e] != face[2 * e + 1];
  }

  // Whether interior edge e is not Delaunay for the lengths len: the cosines of the two corners
  // opposite e, by the law of cosines, sum below 0 (defined, and the right test, Gillespie et
  // al. 2021, even when a triangle violates the triangle inequality).
  bool needs_delaunay_flip(int e, const std::vector<double>& len) const
  {
    const int h = 2 * e, o = h + 1;
    const int h1 = next[h], h2 = next[h1], o1 = next[o], o2 = next[o1];
    const double le = len[e], a1 = len[h1 >> 1], a2 = len[h2 >> 1], b1 = len[o1 >> 1], b2 = len[o2 >> 1];
    const double cos_sum = (a1 * a1 + a2 * a2 - le * le) / (2 * a1 * a2) + (b1 * b1 + b2 * b2 - le * le) / (2 * b1 * b2);
    return cos_sum < -1e-12;
  }
  // The Penner coordinate of the diagonal that a flip of e creates (Ptolemy).
  double ptolemy(int e, const std::vector<double>& l0) const
  {
    const int h = 2 * e, o = h + 1;
    const int h1 = next[h], h2 = next[h1], o1 = next[o], o2 = next[o1];
    return (l0[h1 >> 1] * l0[o1 >> 1] + l0[h2 >> 1] * l0[o2 >> 1]) / l0[e];
  }

  // Edge ab between faces abc (halfedge h = a->b) and bad becomes cd, between dca and cdb.
  void flip(int e)
  {
    const int h = 2 * e, o = h + 1;
    const int h1 = next[h], h2 = next[h1], o1 = next[o], o2 = next[o1];
    const int f0 = face[h], f1 = face[o];
    const int c = target[h1], d = target[o1];
    target[h] = c; target[o] = d;
    next[h] = h2; next[h2] = o1; next[o1] = h;
    next[o] = o2; next[o2] = h1; next[h1] = o;
    face[o1] = f0; face[h1] = f1;
    face_halfedge[f0] = h; face_halfedge[f1] = o;
  }
};

// Discrete conformal vertex scaling, l_e(u) = l0_e exp((u_a + u_b) / 2), solved for
// K(u) = target by Newton's method. dK/du is the cotan Laplacian L (L_ab = -(cot alpha +
// cot beta) / 2, rows summing to 0), positive semi-definite for every valid metric with the
// constants of each component as kernel; one vertex per component is fixed (u = 0) and the
// reduced matrix is positive definite.
//
// Two modes. On the fixed input triangulation, a step is accepted only if every triangle stays
// valid; some targets have no solution there. With intrinsic flips (Gillespie, Springborn,
// Crane 2021), l0 are Penner coordinates: before every evaluation the triangulation is made
// Delaunay for the current metric by Ptolemy flips (l_cd l_ab = l_ad l_bc + l_db l_ca, which
// commutes with vertex scaling), every Delaunay triangulation satisfies the triangle
// inequalities, and a solution exists for every target satisfying Gauss-Bonnet.
// Solver: the SparseCholeskySolver of the Newton systems (reduced Hessians).
template <typename TM, typename Solver = Cholmod_cholesky>
class Vertex_scaling_flow
{
public:
  Vertex_scaling_flow(const Mesh_arrays<TM>& m, const Topology_arrays& topo, const Solver& solver = Solver())
    : m_(m), l0_(m.length), chol_(solver)
  {
    tri_.next = m.next;
    tri_.target = m.target;
    tri_.face = m.face;
    tri_.face_halfedge = m.face_halfedge;
    const int nv = int(m.number_of_vertices());
    col_.assign(nv, -1);
    std::vector<char> comp_fixed(topo.components.size(), 0);
    n_ = 0;
    component_ = topo.vertex_component;
    component_size_.assign(topo.components.size(), 0);
    for(int v = 0; v < nv; ++v) {
      const int c = topo.vertex_component[v];
      if(c < 0) continue;                       // isolated
      ++component_size_[c];
      if(!comp_fixed[c]) { comp_fixed[c] = 1; continue; }   // gauge: first vertex of each component
      col_[v] = n_++;
      column_component_.push_back(c);
    }
  }

  const Flippable_triangulation& triangulation() const { return tri_; }
  const std::vector<double>& base_lengths() const { return l0_; }
  bool triangulation_changed() const { return tri_.next != m_.next; }
  // The flips that lead from the input triangulation to triangulation(), in order (those of
  // rejected trial points undone): replayed with the same Ptolemy updates they give the same
  // triangulation and Penner coordinates, bit for bit (Tracked_delaunay_flips::replay()).
  const std::vector<int>& flip_log() const { return flip_log_; }

  // Strictly valid triangles whose relative area is above the threshold that Mesh_arrays
  // rejects as degenerate; writes the corner angles (as Mesh_arrays::angle) and, per corner,
  // how much the angle can move by the rounding of the lengths, in units of 2^-53:
  // |d theta_m| <= l_m (|d l_m| + |d l_p| + |d l_q|) / 2A (from 2A d theta_m = l_m (d l_m -
  // cos theta_q d l_p - cos theta_p d l_q)), i.e. l_m P / 2A for a perimeter P and relative
  // length errors of one unit, times the units of rounding of a length: 4 (its evaluation and
  // its rounding to double) plus max |u| of the triangle (u is a double, and e^{u / 2} moves
  // by |u| 2^-54 when u moves by one unit in the last place).
  bool angles(const std::vector<double>& len, const std::vector<double>& u, std::vector<double>& ang,
              std::vector<double>& sensitivity, int* bad_face = nullptr) const
  {
    ang.assign(m_.number_of_halfedges(), 0.);
    sensitivity.assign(m_.number_of_halfedges(), 0.);
    const std::size_t nf = m_.number_of_faces();
    int bad[2] = {-1, -1};   // first invalid face of each half of the face range
    in_two_parts(nf, [&](std::size_t begin, std::size_t end, int i) {
      for(std::size_t f = begin; f < end; ++f) {
        const int h0 = tri_.face_halfedge[f], h1 = tri_.next[h0], h2 = tri_.next[h1];
        const double l0 = len[h0 >> 1], l1 = len[h1 >> 1], l2 = len[h2 >> 1];
        const double lmax = (std::max)(l0, (std::max)(l1, l2));
        const double area = is_valid_triangle(l0, l1, l2) ? triangle_area(l0, l1, l2) : 0.;
        if(!(area > 1e-14 * lmax * lmax)) {
          bad[i] = int(f);
          return;
        }
        const std::array<double, 3> a = triangle_angles(l0, l1, l2);
        ang[h0] = a[1];
        ang[h1] = a[2];
        ang[h2] = a[0];
        const double units = 4 + (std::max)({std::abs(u[tri_.target[h0]]), std::abs(u[tri_.target[h1]]),
                                             std::abs(u[tri_.target[h2]])});
        const double c = units * (l0 + l1 + l2) / (2 * area);
        sensitivity[h0] = c * l1;
        sensitivity[h1] = c * l2;
        sensitivity[h2] = c * l0;
      }
    });
    const int first_bad = bad[0] >= 0 ? bad[0] : bad[1];
    if(first_bad >= 0 && bad_face) *bad_face = first_bad;
    return first_bad < 0;
  }

  // Angle defects k and their rounding levels: rounding[v] bounds, to first order, the change
  // of the angle sum of v by the rounding of the lengths of its triangles (see angles()). It is
  // 1e-14 on ordinary meshes; near a needle triangle, whose angles at the short side depend on
  // the difference of its two long sides, it is that needle's aspect ratio times larger
  // (cheese_cgal.off with one -528 pi cone: sides 3.8e-5 and 4.5e-11 and |u| = 17 make it 1e-8):
  // no metric in double edge lengths and conformal factors can be more accurate there.
  void curvatures(const std::vector<double>& ang, const std::vector<double>& sensitivity,
                  std::vector<double>& k, std::vector<double>& rounding) const
  {
    const std::size_t nv = m_.number_of_vertices();
    k.assign(nv, 0.);
    rounding.assign(nv, 0.);
    for(std::size_t h = 0; h < m_.number_of_halfedges(); ++h)
      if(tri_.face[h] >= 0) {
        k[tri_.source(int(h))] += ang[h];
        rounding[tri_.source(int(h))] += sensitivity[h];
      }
    const double unit = std::ldexp(1., -53);
    for(std::size_t v = 0; v < nv; ++v) {
      if(!m_.is_isolated(int(v)))
        k[v] = (m_.is_boundary_vertex(int(v)) ? CGAL_PI : 2 * CGAL_PI) - k[v];
      rounding[v] *= unit;
    }
  }

  // l_e = l0_e e^{u_a / 2} e^{u_b / 2}: three roundings, where exp((u_a + u_b) / 2) also rounds
  // the sum (relative error |u| 2^-53, 20 units at |u| = 17), and a third of the exponentials
  void lengths(const std::vector<double>& u, std::vector<double>& len)
  {
    const std::size_t ne = m_.number_of_edges(), nv = u.size();
    half_exp_.resize(nv);
    in_two_parts(nv, [&](std::size_t begin, std::size_t end, int) {
      for(std::size_t v = begin; v < end; ++v) half_exp_[v] = std::exp(0.5 * u[v]);
    });
    len.resize(ne);
    in_two_parts(ne, [&](std::size_t begin, std::size_t end, int) {
      for(std::size_t e = begin; e < end; ++e)
        len[e] = l0_[e] * half_exp_[tri_.target[2 * e]] * half_exp_[tri_.target[2 * e + 1]];
    });
  }

  // part(begin, end, i) on the halves i = 0, 1 of [0, size), concurrently for large meshes (the
  // per-face and per-edge loops of an evaluation are independent; 433k faces: 2 x 0.03 s per
  // evaluation)
  template <typename Part>
  static void in_two_parts(std::size_t size, const Part& part)
  {
    auto half = [&](int i) { part(i == 0 ? 0 : size / 2, i == 0 ? size / 2 : size, i); };
    if(size >= 100000) {
      run_on_two_threads(half);
    } else {
      half(0);
      half(1);
    }
  }

  // max_v (|K_v - target_v| - rounding_v) / max(1, target angle sum / 2 pi), at least 0: the
  // error beyond the rounding level of the metric (see curvatures()), relative to the cone angle
  // where it exceeds 2 pi (the rounding error of an angle sum grows with the number of angles).
  double scaled_error(const std::vector<double>& k, const std::vector<double>& rounding,
                      const std::vector<double>& target) const
  {
    double err = 0;
    for(std::size_t v = 0; v < k.size(); ++v) {
      if(m_.is_isolated(int(v))) continue;
      const double sum = (m_.is_boundary_vertex(int(v)) ? CGAL_PI : 2 * CGAL_PI) - target[v];
      err = (std::max)(err, (std::abs(k[v] - target[v]) - rounding[v]) / (std::max)(1., sum / (2 * CGAL_PI)));
    }
    return err;
  }

  double max_error(const std::vector<double>& k, const std::vector<double>& target) const
  {
    double err = 0;
    for(std::size_t v = 0; v < k.size(); ++v)
      if(!m_.is_isolated(int(v))) err = (std::max)(err, std::abs(k[v] - target[v]));
    return err;
  }

  // Flips edges until the triangulation is Delaunay for the lengths `len` computed by lengths()
  // (updated, as are the Penner coordinates l0 of the flipped edges). Returns false if flipping
  // does not terminate (a safeguard: on exact arithmetic it always does).
  bool make_delaunay(std::vector<double>& len)
  {
    const int ne = int(m_.number_of_edges());
    std::vector<int>& queue = queue_;
    queue.clear();
    in_queue_.assign(ne, 1);
    for(int e = ne - 1; e >= 0; --e) queue.push_back(e);
    const std::size_t budget = 100 * std::size_t(ne) + 1000;
    std::size_t flips = 0;
    while(!queue.empty()) {
      const int e = queue.back();
      queue.pop_back();
      in_queue_[e] = 0;
      if(!tri_.is_flippable(e)) continue;
      const int h = 2 * e, o = h + 1;
      const int h1 = tri_.next[h], h2 = tri_.next[h1], o1 = tri_.next[o], o2 = tri_.next[o1];
      if(!tri_.needs_delaunay_flip(e, len)) continue;
      if(++flips > budget) return false;
      // Ptolemy on the Penner coordinates themselves (it commutes with vertex scaling), not
      // through the current lengths and exp(-(u_c + u_d) / 2), which moved the coordinates by
      // the rounding of exp at every flip.
      const double p_new = tri_.ptolemy(e, l0_);
      if(!std::isfinite(p_new) || !(p_new > 0)) return false;
      tri_.flip(e);
      flip_log_.push_back(e);
      l0_[e] = p_new;
      len[e] = p_new * half_exp_[tri_.target[h]] * half_exp_[tri_.target[o]];
      if(!std::isfinite(len[e]) || !(len[e] > 0)) return false;
      for(int g : {h1, h2, o1, o2})
        if(!in_queue_[g >> 1]) { in_queue_[g >> 1] = 1; queue.push_back(g >> 1); }
    }
    flips_ += flips;
    return true;
  }

  enum Mode {
    FIXED,               // input triangulation; give up after 10 consecutive Newton steps shortened
                         // to keep triangles valid without a 10% decrease of the error
    FIXED_BEFORE_FLIPS,  // the same, but after 3 such steps, or as soon as two consecutive steps
                         // were cut to t <= 1/4 or one to t <= 1/8 (flips will take over); a
                         // first step that would be cut that far is not taken
    FLIPS                // intrinsic Delaunay triangulation
  };

  // u: in/out conformal factors (start value on input); len: output lengths; first_iteration:
  // iterations done by an earlier run (numbering of the callback and messages); follows: whether
  // this run continues an earlier one (which reported iteration 0).
  template <typename Callback>
  Vertex_scaling_result run(const std::vector<double>& target, std::vector<double>& u,
                            std::vector<double>& len, int max_iterations, double tol,
                            Callback& callback, Mode mode, int first_iteration = 0,
                            bool follows = false)
  {
    Newton_state s(target, tol, mode, first_iteration);
    s.cur.len.swap(len);   // the current iterate's lengths are the caller's
    if(start(s, u)) {
      if(!follows) callback(0, max_error(s.cur.k, target));
      while(s.err > tol && s.it < max_iterations) {
        // rejected trial points of the last line search may have flipped edges
        if(s.flip) restore();
        assemble_hessian(s);
        Eigen::VectorXd du;
        if(!newton_direction(s, newton_rhs(s), du)) break;
        const Line_search ls = line_search(s, u, du);
        if(!step_taken(s, ls)) break;
        accept_step(s, u, ls);
        callback(first_iteration + s.it, max_error(s.cur.k, target));
        if(stalls_at_rounding_level(s, ls) || triangulation_cannot_carry_target(s, ls)) break;
      }
      finish(s);
    }
    len.swap(s.cur.len);
    return s.res;
  }

private:
  // The steps of run().

  // The metric at one point u of the flow: lengths (after the Delaunay flips in flip mode), corner
  // angles and their rounding sensitivities (angles()), curvatures and their rounding levels
  // (curvatures()).
  struct Evaluation
  {
    std::vector<double> len, ang, sens, k, rho;

    void swap(Evaluation& other)
    {
      len.swap(other.len); ang.swap(other.ang); sens.swap(other.sens); k.swap(other.k); rho.swap(other.rho);
    }
  };

  // State of one run(): the current iterate and the trial point of the line search, the progress
  // that the stopping tests watch, what of the Hessian's pattern and factorisation the next
  // iteration can reuse, and the result.
  struct Newton_state
  {
    Newton_state(const std::vector<double>& t, double tl, Mode md, int first)
      : target(t), tol(tl), mode(md), flip(md == FLIPS), first_iteration(first) {}

    const std::vector<double>& target;
    const double tol;
    const Mode mode;
    const bool flip;
    const int first_iteration;
    Evaluation cur, trial;
    std::vector<double> u_try;
    double err = 0, norm2 = 0, best = 0;
    int best_iteration = 0;
    int it = 0;
    std::vector<double> err_history;
    int cut_streak = 0, small_cut_streak = 0, cut_face = -1;
    std::size_t version_at_analysis = 0, pattern_version = 0;
    bool analysed = false, has_pattern = false, last_full_step = false;
    Vertex_scaling_result res;
  };

  // Outcome of the line search of one Newton iteration
  struct Line_search
  {
    double t = 1;
    bool accepted = false, last_invalid = false, any_invalid = false;
    int last_bad = -1;
  };

  // lengths, Delaunay flips (flip mode), angles and curvatures at u
  bool evaluate(bool flip, const std::vector<double>& u, Evaluation& e, int* bad_face)
  {
    lengths(u, e.len);
    // conformal factors beyond the range of double (exp overflow): not a metric, and flipping
    // on such lengths would corrupt the Penner coordinates
    for(double x : e.len) if(!(x > 0) || !std::isfinite(x)) return false;
    if(flip && !make_delaunay(e.len)) return false;
    if(!angles(e.len, u, e.ang, e.sens, bad_face)) return false;
    curvatures(e.ang, e.sens, e.k, e.rho);
    return true;
  }

  // Evaluates the start value u; false (and a message) if it is not a valid metric.
  bool start(Newton_state& s, const std::vector<double>& u)
  {
    int bad = -1;
    if(!evaluate(s.flip, u, s.cur, &bad)) {
      s.res.message = s.flip ? std::string("intrinsic edge flips did not produce a valid triangulation")
                             : "the initial conformal factors give a degenerate triangle (face " +
                                   std::to_string(bad) + ")";
      return false;
    }
    if(s.flip) snapshot();
    s.err = scaled_error(s.cur.k, s.cur.rho, s.target);
    s.norm2 = residual_norm2(s.cur.k, s.target);
    s.best = s.err;
    s.err_history.assign(1, s.err);
    return true;
  }

  // The Hessian at the current iterate, on the pattern of the last iteration when the
  // triangulation has not changed since.
  void assemble_hessian(Newton_state& s)
  {
    fill_values(s.cur.len, s.has_pattern && s.pattern_version == version_);
    s.has_pattern = true;
    s.pattern_version = version_;
  }

  // The residuals of a component sum to zero up to rounding (Gauss-Bonnet holds for every
  // metric), and with the reduced system the gauge vertex would collect that rounding of all
  // the others (1M faces: 1.2e-10 there, 1e-13 elsewhere); removing the mean spreads it.
  Eigen::VectorXd newton_rhs(const Newton_state& s) const
  {
    const std::vector<double>& target = s.target;
    const std::vector<double>& k = s.cur.k;
    std::vector<double> mean(component_size_.size(), 0.);
    for(std::size_t v = 0; v < col_.size(); ++v)
      if(component_[v] >= 0) mean[component_[v]] += target[v] - k[v];
    for(std::size_t c = 0; c < mean.size(); ++c) if(component_size_[c] > 0) mean[c] /= component_size_[c];
    Eigen::VectorXd rhs(n_);
    for(std::size_t v = 0; v < col_.size(); ++v)
      if(col_[v] >= 0) rhs[col_[v]] = target[v] - k[v] - mean[component_[v]];
    return rhs;
  }

  // The Newton step du of the reduced system; false (and a message) if the factorisation fails
  // or the step is not finite.
  bool newton_direction(Newton_state& s, const Eigen::VectorXd& rhs, Eigen::VectorXd& du)
  {
    // Inexact Newton: close to the solution (full steps, small error) the Hessian changes
    // little between iterations, and conjugate gradients preconditioned by the previous
    // factorisation reach the forcing tolerance in a few triangular solves, much cheaper than a
    // new factorisation (433k faces: 0.57 s refactorisation, 1.2 s with a new analysis).
    bool solved = false;
    if(s.analysed && s.last_full_step && n_ > 0)
      solved = preconditioned_cg(rhs, du, (std::min)(1e-2, s.err), 0.1 * s.tol, 8);
    if(!solved) {
      std::string msg;
      const bool same_pattern = s.analysed && s.version_at_analysis == version_;
      const bool ok = same_pattern ? chol_.refactor(L_, msg) : chol_.factor(L_, msg);
      s.analysed = true;
      s.version_at_analysis = version_;
      if(!ok) {
        s.res.message = "iteration " + std::to_string(s.first_iteration + s.it + 1) + ": " + msg;
        return false;
      }
      if(n_ > 0) du = chol_.solve(rhs);
    }
    if(!du.allFinite()) {
      s.res.message = "iteration " + std::to_string(s.first_iteration + s.it + 1) + ": the Newton step is not finite";
      return false;
    }
    return true;
  }

  // Backtracking that only accepts metrics with valid triangles, and a step t if either
  // |K - target|^2 decreases enough (Armijo; the Newton step is a descent direction for it),
  // or t is at most the minimiser of the convex energy E (grad E = K - target, Hessian L)
  // along the step: phi'(t) = du . (K(t) - target) <= 0. Halving from 1 stops in
  // [t*/2, t*], which by convexity gains at least half of the best decrease of E along the
  // line: global convergence without evaluating E (far from the solution, where the residual
  // may not decrease along any step).
  // The last trial point is left in s.u_try and s.trial.
  Line_search line_search(Newton_state& s, const std::vector<double>& u, const Eigen::VectorXd& du)
  {
    Line_search ls;
    for(int i = 0; i < 60; ++i, ls.t *= 0.5) {
      s.u_try = u;
      for(std::size_t v = 0; v < col_.size(); ++v)
        if(col_[v] >= 0) s.u_try[v] += ls.t * du[col_[v]];
      if(!evaluate(s.flip, s.u_try, s.trial, &ls.last_bad)) {
        ls.last_invalid = ls.any_invalid = true;
        s.cut_face = ls.last_bad;
        if(s.mode == FIXED_BEFORE_FLIPS && s.it == 0 && ls.t <= 0.125) break;   // abandoned below
        continue;
      }
      ls.last_invalid = false;
      const double n2 = residual_norm2(s.trial.k, s.target);
      if(n2 <= (1 - 2e-4 * ls.t) * s.norm2) { ls.accepted = true; break; }
      double dphi = 0;
      for(std::size_t v = 0; v < col_.size(); ++v)
        if(col_[v] >= 0) dphi += du[col_[v]] * (s.trial.k[v] - s.target[v]);
      if(dphi <= 0) { ls.accepted = true; break; }
    }
    return ls;
  }

  // Whether the step of the line search is taken; if not, the run ends here (with a message).
  bool step_taken(Newton_state& s, const Line_search& ls)
  {
    // The first step already degenerates triangles: leave the input triangulation before
    // moving (the flip phase then starts from the input metric; 433k faces: one iteration less)
    if(s.mode == FIXED_BEFORE_FLIPS && s.it == 0 && ls.any_invalid && (!ls.accepted || ls.t <= 0.125)) {
      std::ostringstream os;
      os << "iteration " << s.first_iteration + 1 << ": the Newton step had to be cut below 1/8"
         << " to keep the triangles valid (face " << s.cut_face << " degenerates)";
      s.res.message = os.str();
      return false;
    }
    if(!ls.accepted) {
      std::ostringstream os;
      os.precision(3);
      if(ls.last_invalid && !s.flip)
        os << "iteration " << s.first_iteration + s.it + 1 << ": the line search cannot keep the triangles valid (face "
           << ls.last_bad << " degenerates); the fixed triangulation cannot carry the target metric";
      else
        os << "iteration " << s.first_iteration + s.it + 1 << ": the line search found no decrease of the curvature"
           << " error (stagnation at " << s.err << ", rounding level of this metric)";
      s.res.message = os.str();
      return false;
    }
    return true;
  }

  // The accepted trial point becomes the current iterate.
  void accept_step(Newton_state& s, std::vector<double>& u, const Line_search& ls)
  {
    s.last_full_step = (ls.t == 1);
    u.swap(s.u_try);
    s.cur.swap(s.trial);
    if(s.flip) snapshot();
    s.norm2 = residual_norm2(s.cur.k, s.target);
    s.err = scaled_error(s.cur.k, s.cur.rho, s.target);
    ++s.it;
  }

  // Stop when the error no longer halves (with a message): rounding, not a lack of iterations.
  bool stalls_at_rounding_level(Newton_state& s, const Line_search& ls) const
  {
    if(s.err < 0.5 * s.best) { s.best = s.err; s.best_iteration = s.it; }
    // Below 1e-6 Newton converges quadratically; 6 iterations without halving the error is
    // rounding (1M-face decimated armadillo: 1.2e-10, then 20 idle iterations, 40 s), and 3
    // full steps are enough below 1e-8 (shortened steps may still be making slow progress).
    const int idle = s.best < 1e-8 && ls.t == 1 ? 3 : 6;
    if(s.err > s.tol && s.best < 1e-6 && s.it - s.best_iteration >= idle) {
      std::ostringstream os;
      os.precision(3);
      os << "stopped after iteration " << s.first_iteration + s.it << ": the curvature error has not halved"
         << " in " << idle << " iterations (" << s.best << " at best): rounding level of this metric";
      s.res.message = os.str();
      return true;
    }
    return false;
  }

  // On the fixed triangulation (see Mode), stop when the steps keep being shortened to keep the
  // triangles valid without enough progress (with a message). With flips, only a triangle on a
  // border edge (which cannot flip) can stop a step: 20 such steps without 10 % progress end the
  // flow too (a cone next to the boundary; it used to run its 200 iterations, 4 s on 8k faces).
  bool triangulation_cannot_carry_target(Newton_state& s, const Line_search& ls) const
  {
    s.err_history.push_back(s.err);
    s.cut_streak = ls.any_invalid ? s.cut_streak + 1 : 0;
    s.small_cut_streak = (ls.any_invalid && ls.t <= 0.25) ? s.small_cut_streak + 1 : 0;
    const int w = s.flip ? 20 : s.mode == FIXED ? 10 : 3;
    const bool stalled = s.cut_streak >= w && s.err > 0.9 * s.err_history[s.err_history.size() - 1 - w];
    const bool collapsing = s.mode == FIXED_BEFORE_FLIPS && (s.small_cut_streak >= 2 || (ls.any_invalid && ls.t <= 0.125));
    if(s.flip && s.err > s.tol && stalled) {
      std::ostringstream os;
      os.precision(3);
      os << "stopped after iteration " << s.first_iteration + s.it << ": " << s.cut_streak
         << " consecutive Newton steps had to be shortened to keep the triangles valid (face " << s.cut_face
         << " degenerates, last step " << ls.t << ") and the curvature error only went from "
         << s.err_history[s.err_history.size() - 1 - w] << " to " << s.err
         << "; a triangle on a border edge, which cannot flip, degenerates (a cone next to the boundary?)";
      s.res.message = os.str();
      return true;
    }
    if(!s.flip && s.err > s.tol && (stalled || collapsing)) {
      std::ostringstream os;
      os.precision(3);
      os << "stopped after iteration " << s.first_iteration + s.it << ": " << s.cut_streak
         << " consecutive Newton steps had to be shortened to keep the triangles valid (face "
         << s.cut_face << " degenerates, last step " << ls.t << ") and the curvature error (relative to the"
         << " cone angle where it exceeds 2 pi) only went from "
         << s.err_history[s.err_history.size() - 1 - (std::min)(s.cut_streak, s.it)] << " to " << s.err
         << "; the fixed triangulation cannot carry the target metric";
      s.res.message = os.str();
      return true;
    }
    return false;
  }

  // The result of the iterations done.
  void finish(Newton_state& s)
  {
    if(s.flip) restore();   // the triangulation of the returned metric
    Vertex_scaling_result& res = s.res;
    res.iterations = s.it;
    res.max_error = max_error(s.cur.k, s.target);
    res.scaled_error = s.err;
    res.rounding_level = s.cur.rho.empty() ? 0. : *std::max_element(s.cur.rho.begin(), s.cur.rho.end());
    res.converged = s.err <= s.tol;
    res.flips = flips_;
    if(!res.converged && res.message.empty()) {
      std::ostringstream os;
      os << "no convergence after " << s.first_iteration + s.it << " iterations (maximum curvature error "
         << res.max_error << ")";
      res.message = os.str();
    }
  }

  const Mesh_arrays<TM>& m_;
  Flippable_triangulation tri_;
  std::vector<double> l0_;          // per edge: length at u = 0 (Penner coordinate once flipped)
  std::vector<int> queue_;
  std::vector<char> in_queue_;
  std::size_t flips_ = 0;
  // Triangulation and Penner coordinates of the last accepted iterate (trial points of the line
  // search flip edges too); version_ counts its changes (the Hessian's pattern follows it).
  Flippable_triangulation saved_tri_;
  std::vector<double> saved_l0_;
  std::size_t flips_at_snapshot_ = 0, version_ = 0;
  std::vector<int> flip_log_;
  std::size_t log_at_snapshot_ = 0;

  void snapshot()
  {
    log_at_snapshot_ = flip_log_.size();
    if(flips_ == flips_at_snapshot_ && !saved_l0_.empty()) return;
    saved_tri_ = tri_;
    saved_l0_ = l0_;
    flips_at_snapshot_ = flips_;
    ++version_;
  }
  void restore()
  {
    if(flips_ == flips_at_snapshot_) return;
    flip_log_.resize(log_at_snapshot_);
    tri_ = saved_tri_;
    l0_ = saved_l0_;
    flips_at_snapshot_ = flips_;
  }
  std::vector<int> col_;   // per vertex: column of the reduced system, -1 if fixed or isolated
  std::vector<int> component_, component_size_;   // per vertex / per component
  std::vector<int> column_component_;             // per column of the reduced system
  int n_ = 0;
  Sparse_matrix_int L_;    // lower triangle of the reduced Hessian
  std::vector<int> edge_pos_, diag_pos_;
  std::vector<double> w_, half_cot_;
  std::vector<double> half_exp_;   // per vertex: e^{u / 2} of the last lengths()
  Solver chol_;

  double residual_norm2(const std::vector<double>& k, const std::vector<double>& target) const
  {
    double s = 0;
    for(std::size_t v = 0; v < k.size(); ++v)
      if(!m_.is_isolated(int(v))) s += (k[v] - target[v]) * (k[v] - target[v]);
    return s;
  }

  // Conjugate gradients on L_ du = rhs, preconditioned by the kept factorisation (of an earlier
  // Hessian); true if |rhs - L_ du| <= eta |rhs| within max_iterations.
  // The linearised residual of the gauge vertex of a component is minus the sum over the
  // others (the Hessian's rows sum to zero): both must be below `stop`.
  bool small_residual(const Eigen::VectorXd& r, double stop) const
  {
    if(!(r.template lpNorm<Eigen::Infinity>() <= stop)) return false;
    std::vector<double> sum(component_size_.size(), 0.);
    for(Eigen::Index c = 0; c < r.size(); ++c) sum[column_component_[std::size_t(c)]] += r[c];
    for(double x : sum) if(!(std::abs(x) <= stop)) return false;
    return true;
  }

  // Stops when the largest linearised curvature residual is below eta times the current one (the
  // forcing term of inexact Newton) or below `floor`, a fraction of the tolerance: the
  // quadratic convergence then leaves no reason to solve the last step more accurately.
  bool preconditioned_cg(const Eigen::VectorXd& rhs, Eigen::VectorXd& x, double eta, double floor,
                         int max_iterations) const
  {
    const auto A = L_.template selfadjointView<Eigen::Lower>();
    x = Eigen::VectorXd::Zero(rhs.size());
    Eigen::VectorXd r = rhs, z = chol_.solve(r), p = z, Ap(rhs.size());
    double rz = r.dot(z);
    const double stop = (std::max)(eta * rhs.template lpNorm<Eigen::Infinity>(), floor);
    for(int i = 0; i < max_iterations; ++i) {
      Ap.noalias() = A * p;
      const double pAp = p.dot(Ap);
      if(!(pAp > 0)) return false;
      const double alpha = rz / pAp;
      x += alpha * p;
      r -= alpha * Ap;
      if(small_residual(r, stop)) return x.allFinite();
      z = chol_.solve(r);
      const double rz_new = r.dot(z);
      p = z + (rz_new / rz) * p;
      rz = rz_new;
    }
    return false;
  }

  int position(int row, int col) const
  {
    const int* inner = L_.innerIndexPtr();
    const int b = L_.outerIndexPtr()[col], e = L_.outerIndexPtr()[col + 1];
    const int* p = std::lower_bound(inner + b, inner + e, row);
    CGAL_assertion(p != inner + e && *p == row);
    return int(p - inner);
  }

  // Sparsity pattern of the reduced Hessian on the current triangulation (several edges may
  // join the same two vertices after flips; an edge from a vertex to itself adds nothing).
  void build_pattern()
  {
    std::vector<Eigen::Triplet<double, int>> trip;
    trip.reserve(n_ + m_.number_of_edges());
    for(int c = 0; c < n_; ++c) trip.emplace_back(c, c, 1.);
    for(std::size_t e = 0; e < m_.number_of_edges(); ++e) {
      const int a = col_[tri_.target[2 * e]], b = col_[tri_.target[2 * e + 1]];
      if(a >= 0 && b >= 0 && a != b) trip.emplace_back((std::max)(a, b), (std::min)(a, b), 1.);
    }
    L_.resize(n_, n_);
    L_.setFromTriplets(trip.begin(), trip.end());
    L_.makeCompressed();
    diag_pos_.resize(n_);
    for(int c = 0; c < n_; ++c) diag_pos_[c] = position(c, c);
    edge_pos_.assign(m_.number_of_edges(), -1);
    for(std::size_t e = 0; e < m_.number_of_edges(); ++e) {
      const int a = col_[tri_.target[2 * e]], b = col_[tri_.target[2 * e + 1]];
      if(a >= 0 && b >= 0 && a != b) edge_pos_[e] = position((std::max)(a, b), (std::min)(a, b));
    }
  }

  // Cotan Laplacian of the metric with edge lengths `len` (valid triangles), restricted to the
  // free vertices. The cotangents come from the lengths face by face, cot = (a^2 + b^2 - c^2) /
  // 4A: a third of the time of cos/sin of the corner angles looked up per halfedge.
  void fill_values(const std::vector<double>& len, bool same_pattern)
  {
    if(!same_pattern) build_pattern();
    // half cotangent of the corner opposite each halfedge (0 on the border), then w_e per edge
    const std::size_t nf = m_.number_of_faces(), ne = m_.number_of_edges();
    half_cot_.assign(m_.number_of_halfedges(), 0.);
    in_two_parts(nf, [&](std::size_t begin, std::size_t end, int) {
      for(std::size_t f = begin; f < end; ++f) {
        const int h0 = tri_.face_halfedge[f], h1 = tri_.next[h0], h2 = tri_.next[h1];
        const double l0 = len[h0 >> 1], l1 = len[h1 >> 1], l2 = len[h2 >> 1];
        const double q0 = l0 * l0, q1 = l1 * l1, q2 = l2 * l2;
        const double inv8A = 1. / (8. * triangle_area(l0, l1, l2));
        half_cot_[h0] = (q1 + q2 - q0) * inv8A;
        half_cot_[h1] = (q2 + q0 - q1) * inv8A;
        half_cot_[h2] = (q0 + q1 - q2) * inv8A;
      }
    });
    w_.resize(ne);
    for(std::size_t e = 0; e < ne; ++e) w_[e] = half_cot_[2 * e] + half_cot_[2 * e + 1];
    double* val = L_.valuePtr();
    std::fill(val, val + L_.nonZeros(), 0.);
    for(std::size_t e = 0; e < m_.number_of_edges(); ++e) {
      const int a = col_[tri_.target[2 * e]], b = col_[tri_.target[2 * e + 1]];
      if(a == b && a >= 0) continue;
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
