// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_ROTATION_COMPENSATION_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_ROTATION_COMPENSATION_H

// Rotation compensation (Lai et al. 2010, section 4.1.3.1): on a flat cone metric of genus
// g > 0 whose cone curvatures are multiples of 2 pi / N, a vertex-based N-RoSy field that is
// parallel up to a harmonic 1-form whose periods cancel the holonomy of the handle loops.

#include <CGAL/Surface_mesh_direction_fields/Cholmod_cholesky.h>
#include <CGAL/Surface_mesh_direction_fields/Intrinsic_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/internal/cotan_weights.h>
#include <CGAL/Surface_mesh_direction_fields/internal/development.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vertex_frames.h>
#include <CGAL/Surface_mesh_direction_fields/vertex_field_embedding.h>

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsFieldDesign
/// Outcome of rotation_compensated_field().
struct Rotation_compensation_status
{
  /// the field is an N-RoSy field across every edge (up to the tolerance), so that its only
  /// singularities are the cones
  bool success = false;
  std::string message;                ///< empty on success
  int N = 1;
  /// per handle loop (the primal loops of the tree-cotree handle generators, in their order):
  /// the Levi-Civita holonomy of the metric along it, in \f$(-\pi, \pi]\f$
  std::vector<double> holonomy;
  /// per handle loop: the period \f$\int_\gamma \omega\f$ of the compensating 1-form,
  /// \f$2\pi t - h(\gamma)\f$ for the loop's turning number \f$t\f$ (the field's total rotation
  /// along the loop over \f$2\pi\f$, a multiple of \f$1/N\f$)
  std::vector<double> periods;
  /// largest residual of the harmonic 1-form: its sum around a face (closedness) or its
  /// cotan-weighted divergence at a vertex (co-closedness)
  double max_harmonic_residual = 0;
  /// largest distance, over all edges, of the field's rotation relative to transport plus
  /// \f$\omega\f$ to a multiple of \f$2\pi/N\f$ (edges of enclosed vertices apart)
  double max_inconsistency = 0;
  /// vertices that no path of vertices reaches around the cones (each one's neighbours are
  /// cones or such vertices): they take the field of one of their faces, carried by Levi-Civita
  /// transport from faces that have it
  std::size_t enclosed_vertices = 0;
  /// the same distance on the edges of enclosed vertices: the rotation of \f$\omega\f$ that the
  /// transport into their faces leaves out (small; the field's singularities are still the cones)
  double max_enclosed_inconsistency = 0;
};


/// \ingroup PkgSurfaceMeshDirectionFieldsFieldDesign
/// How rotation_compensated_field() builds its basis of harmonic 1-forms; both give the same
/// field (the harmonic 1-form with prescribed periods is unique; the tests compare them).
enum Harmonic_form_construction {
  /// the closed 1-form that counts crossings of the handle's dual cycle, made co-closed by one
  /// solve with the Laplacian factored once for all loops: the default
  HARMONIC_PROJECTION,
  /// the paper's construction (after Gu and Yau): cut the surface open along the loop
  /// \f$\gamma_k\f$, solve \f$\Delta g_k = 0\f$ on the cut surface with \f$g_k = 1\f$ on one side of
  /// the cut and 0 on the other (one factorisation per loop), then make \f$dg_k\f$ co-closed on
  /// the whole surface, \f$\Delta(dg_k + dh_k) = 0\f$; needs simple loops
  CUT_AND_DIRICHLET
};

namespace internal {

// The paper's jump form for one simple primal loop (halfedges in order, backtracks removed):
// dg of the function g harmonic on the surface cut open along the loop, 1 on the loop's left
// side and 0 on its right, as a value per edge for halfedge 2e. False (and a message) when the
// loop is not simple or the factorisation fails.
template <typename TM>
bool cut_jump_form(const Mesh_arrays<TM>& m, const std::vector<double>& w, std::vector<int> loop,
                   std::vector<double>& dg, std::string& message)
{
  // remove backtracks h, h^1 (cyclically): a tree-cotree loop then becomes simple
  std::vector<int> st;
  for(int h : loop) {
    if(!st.empty() && st.back() == (h ^ 1)) st.pop_back(); else st.push_back(h);
  }
  while(st.size() > 1 && st.front() == (st.back() ^ 1)) { st.pop_back(); st.erase(st.begin()); }
  loop.swap(st);
  const std::size_t nv = m.number_of_vertices(), ne = m.number_of_edges();
  std::vector<int> in_of(nv, -1);   // per loop vertex, the loop halfedge that arrives there
  for(int h : loop) {
    if(in_of[std::size_t(m.target[std::size_t(h)])] >= 0) { message = "the cut construction of harmonic forms needs simple handle loops"; return false; }
    in_of[std::size_t(m.target[std::size_t(h)])] = h;
  }
  // per halfedge leaving a loop vertex: 1 if it lies on the loop's left (counterclockwise from
  // the outgoing loop halfedge to the incoming one), 0 on its right or along the loop
  std::vector<double> side(m.number_of_halfedges(), 0.);
  for(int out : loop) {
    const int v = m.source(out), in = in_of[std::size_t(v)];
    for(int h = m.ccw_out(out); h != (in ^ 1); h = m.ccw_out(h)) side[std::size_t(h)] = 1.;
  }
  std::vector<int> column(nv, -1);
  int n = 0;
  for(std::size_t v = 0; v < nv; ++v) if(in_of[v] < 0 && !m.is_isolated(int(v))) column[v] = n++;
  std::vector<Eigen::Triplet<double>> t;
  Eigen::VectorXd b = Eigen::VectorXd::Zero(n);
  for(std::size_t e = 0; e < ne; ++e) {
    const int h = int(2 * e), a = m.source(h), c = m.target[std::size_t(h)];
    const int ca = column[std::size_t(a)], cc = column[std::size_t(c)];
    if(ca >= 0) t.emplace_back(ca, ca, w[e]);
    if(cc >= 0) t.emplace_back(cc, cc, w[e]);
    if(ca >= 0 && cc >= 0) t.emplace_back((std::max)(ca, cc), (std::min)(ca, cc), -w[e]);
    if(ca >= 0 && cc < 0) b[ca] += w[e] * side[std::size_t(h ^ 1)];   // the Dirichlet value seen along the edge
    if(cc >= 0 && ca < 0) b[cc] += w[e] * side[std::size_t(h)];
  }
  Eigen::VectorXd g;
  if(n > 0) {
    Cholmod_cholesky::Matrix L(n, n);
    L.setFromTriplets(t.begin(), t.end());
    L.makeCompressed();
    Cholmod_cholesky chol;
    if(!chol.factor(L, message)) return false;
    g = chol.solve(b);
  }
  // the value of g at the end of halfedge h's edge at vertex v (v on the loop: its side's value)
  auto value = [&](int v, int leaving) { return column[std::size_t(v)] >= 0 ? g[column[std::size_t(v)]] : side[std::size_t(leaving)]; };
  dg.assign(ne, 0.);
  for(std::size_t e = 0; e < ne; ++e) {
    const int h = int(2 * e);
    dg[e] = value(m.target[std::size_t(h)], h ^ 1) - value(m.source(h), h);
  }
  return true;
}


// A vertex of the largest set of vertices that paths of vertices other than cones connect (the
// rest are islands the cones enclose), or the number of vertices if every vertex is a cone.
template <typename TM>
std::size_t vertex_off_the_islands(const Mesh_arrays<TM>& m, const std::vector<char>& cone)
{
  const std::size_t nv = m.number_of_vertices();
  std::vector<char> seen(nv, 0);
  std::size_t best = nv, best_size = 0;
  std::vector<int> queue;
  for(std::size_t r = 0; r < nv; ++r) {
    if(seen[r] || cone[r] || m.is_isolated(int(r))) continue;
    queue.assign(1, int(r));
    seen[r] = 1;
    for(std::size_t qi = 0; qi < queue.size(); ++qi) {
      const int h0 = m.vertex_out[std::size_t(queue[qi])];
      int h = h0;
      do {
        const int w = m.target[std::size_t(h)];
        if(!seen[std::size_t(w)] && !cone[std::size_t(w)]) { seen[std::size_t(w)] = 1; queue.push_back(w); }
        h = m.ccw_out(h);
      } while(h != h0);
    }
    if(queue.size() > best_size) { best_size = queue.size(); best = r; }
  }
  return best;
}

// k primal loops of the surface minus the cone vertices whose homology classes are independent
// (their periods against the k closed forms omega, a basis of the harmonic ones, are linearly
// independent): the fundamental cycles of a spanning tree of the vertices that are no cones,
// chosen greedily by the part of their period vector that the chosen ones do not span (a cycle
// around cones only, or bounding, has periods 0). Vertices the cones enclose (islands: every
// path to the root passes a cone) are left out: a loop through one would pass between two
// adjacent cones, which no loop of vertices can; the loops of the rest span the handles unless
// the cones wall one off (then false, as when no vertex is left).
template <typename TM>
bool loops_avoiding_cones(const Mesh_arrays<TM>& m, const std::vector<char>& cone,
                          const std::vector<std::vector<double>>& omega, std::vector<std::vector<int>>& primal,
                          std::string& message)
{
  const std::size_t nv = m.number_of_vertices(), ne = m.number_of_edges(), k = omega.size();
  auto form_at = [&](std::size_t j, int h) { return (h & 1) ? -omega[j][std::size_t(h >> 1)] : omega[j][std::size_t(h >> 1)]; };
  std::vector<int> parent(nv, -2);   // halfedge from the parent, -1 at the root
  std::vector<double> phi(nv * k, 0.);
  const std::size_t root = vertex_off_the_islands(m, cone);
  if(root == nv) { message = "every vertex is a cone"; return false; }
  parent[root] = -1;
  std::vector<int> queue(1, int(root));
  for(std::size_t qi = 0; qi < queue.size(); ++qi) {
    const int v = queue[qi];
    const int h0 = m.vertex_out[std::size_t(v)];
    int h = h0;
    do {
      const int w = m.target[std::size_t(h)];
      if(!cone[std::size_t(w)] && parent[std::size_t(w)] == -2) {
        parent[std::size_t(w)] = h;
        for(std::size_t j = 0; j < k; ++j) phi[std::size_t(w) * k + j] = phi[std::size_t(v) * k + j] + form_at(j, h);
        queue.push_back(w);
      }
      h = m.ccw_out(h);
    } while(h != h0);
  }
  // one pass over the fundamental cycles: a cycle is kept if a tenth of its period vector lies
  // outside the span of those kept (bounding cycles and cycles around cones have periods 0)
  std::vector<std::vector<double>> basis;   // orthonormal
  std::vector<int> chosen;
  std::vector<double> p(k);
  double scale = 0;
  for(std::size_t e = 0; e < ne; ++e)
    for(std::size_t j = 0; j < k; ++j) scale = (std::max)(scale, std::abs(omega[j][e]));
  for(std::size_t e = 0; e < ne && chosen.size() < k; ++e) {
    const int h = int(2 * e), a = m.source(h), b = m.target[std::size_t(h)];
    if(cone[std::size_t(a)] || cone[std::size_t(b)] || parent[std::size_t(a)] == -2 || m.is_border_edge(int(e)) ||
       parent[std::size_t(b)] == h || parent[std::size_t(a)] == (h ^ 1))
      continue;
    double norm0 = 0;
    for(std::size_t j = 0; j < k; ++j) {
      p[j] = phi[std::size_t(a) * k + j] + form_at(j, h) - phi[std::size_t(b) * k + j];
      norm0 += p[j] * p[j];
    }
    norm0 = std::sqrt(norm0);
    if(!(norm0 > 1e-6 * scale)) continue;
    for(const auto& q : basis) {
      double d = 0;
      for(std::size_t j = 0; j < k; ++j) d += q[j] * p[j];
      for(std::size_t j = 0; j < k; ++j) p[j] -= d * q[j];
    }
    double norm = 0;
    for(double x : p) norm += x * x;
    norm = std::sqrt(norm);
    if(!(norm > 0.1 * norm0)) continue;
    for(double& x : p) x /= norm;
    basis.push_back(p);
    chosen.push_back(h);
  }
  if(chosen.size() < k) {
    std::size_t islands = 0;
    for(std::size_t v = 0; v < nv; ++v) islands += !cone[v] && !m.is_isolated(int(v)) && parent[v] == -2;
    message = "no loops around the cones span the handles" +
              (islands ? " (the cones cut " + std::to_string(islands) + " vertices off the rest)" : std::string());
    return false;
  }
  for(std::size_t j = 0; j < k; ++j) {
    const int h = chosen[j];
    std::vector<int> down;   // root -> source(h)
    for(int v = m.source(h); parent[std::size_t(v)] >= 0; v = m.source(parent[std::size_t(v)])) down.push_back(parent[std::size_t(v)]);
    primal[j].assign(down.rbegin(), down.rend());
    primal[j].push_back(h);
    for(int v = m.target[std::size_t(h)]; parent[std::size_t(v)] >= 0; v = m.source(parent[std::size_t(v)]))
      primal[j].push_back(parent[std::size_t(v)] ^ 1);
  }
  return true;
}

} // namespace internal

/// \ingroup PkgSurfaceMeshDirectionFieldsFieldDesign
/// Rotation compensation (Lai et al. 2010, section 4.1.3.1) on a closed surface: builds the
/// harmonic 1-forms \f$\omega_k\f$ dual to the handle loops \f$\gamma_k\f$ (a closed 1-form that
/// jumps by 1 across \f$\gamma_k\f$, made harmonic by \f$\Delta(\tau_k + dh_k) = 0\f$ with the cotan
/// Laplacian of the metric: the unique harmonic representative, which is the paper's
/// \f$dg_k + dh_k\f$), solves the small system \f$\sum_k w_k \int_{\gamma_j}\omega_k = p_j\f$ for
/// the periods \f$p_j\f$ that make the holonomy of every handle loop a multiple of \f$2\pi/N\f$,
/// and propagates a direction from vertex 0 breadth-first: carried along each edge by the
/// metric's transport and rotated counterclockwise by \f$\omega\f$ on it.
///
/// `vertex_angles` receives one angle per vertex, counterclockwise from a reference outgoing
/// halfedge (that of the first edge at the vertex, in `edges(tm)` order: `halfedge(e)` or its
/// opposite, whichever leaves the vertex) in the metric, scaled so that the directions around
/// a vertex span \f$2\pi\f$; `face_angles` the same field in the face frames (each face takes
/// it from a corner that is not a cone), for read-back with field_singularities() and the same
/// `edge_length_map`: its singularities are then exactly the cones, of index \f$K/2\pi\f$.
///
/// Named parameters: `edge_length_map` (a flat cone metric: angle defect 0 except at the
/// cones) or `intrinsic_mesh`, the index maps, and `generator_turning_numbers` (a
/// `std::vector<double>`, one multiple of \f$1/N\f$ per handle loop: the field's total rotation
/// along it over \f$2\pi\f$; default: the multiple nearest to the loop's holonomy, the least
/// compensation), `harmonic_form_construction` (default `HARMONIC_PROJECTION`; see
/// `Harmonic_form_construction`). Throws `Input_error` for meshes with
/// boundary or several components, \f$N < 1\f$, and the errors of `Intrinsic_mesh`; numerical
/// failure is in the status.
template <typename TriangleMesh, typename VertexAngleMap, typename FaceAngleMap,
          typename NamedParameters = parameters::Default_named_parameters>
Rotation_compensation_status rotation_compensated_field(const TriangleMesh& tm, int N, VertexAngleMap vertex_angles,
                                                        FaceAngleMap face_angles,
                                                        const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  if(N < 1) throw Input_error(Input_error::INVALID_ARGUMENT, "symmetry order N must be at least 1, got " + std::to_string(N));
  const std::vector<double> turning =
      choose_parameter(get_parameter(np, internal_np::generator_turning_numbers), std::vector<double>());
  const Harmonic_form_construction construction =
      choose_parameter(get_parameter(np, internal_np::harmonic_form_construction), HARMONIC_PROJECTION);
  for(double t : turning)
    if(!std::isfinite(t) || std::abs(t * N - std::round(t * N)) > 1e-9)
      throw Input_error(Input_error::INVALID_ARGUMENT, "generator turning numbers must be multiples of 1/N, got " + std::to_string(t));
  const Intrinsic_mesh<TriangleMesh> im = internal::get_intrinsic_mesh(tm, np);
  const internal::Mesh_arrays<TriangleMesh>& m = im.arrays();
  const internal::Topology_arrays& topo = im.topology_arrays();
  if(topo.components.size() != 1 || !topo.loops.empty())
    throw Input_error(Input_error::INVALID_ARGUMENT,
                      "rotation_compensated_field() needs a closed mesh of one component (open meshes: not supported yet)");
  const std::size_t nv = m.number_of_vertices(), ne = m.number_of_edges();
  const std::vector<double>& K = im.curvatures();
  Rotation_compensation_status st;
  st.N = N;
  const double period = 2 * CGAL_PI / N;
  const internal::Vertex_frames<TriangleMesh> frames(m);

  // one harmonic form per handle loop; a 1-form is a value per edge for halfedge 2e (-value for 2e + 1)
  std::vector<const internal::Generator_arrays*> loops;
  for(const auto& g : im.generator_arrays()) if(g.handle) loops.push_back(&g);
  const std::size_t k = loops.size();
  // cotan weights of the metric (raised to 1e-3 of their mean) and the Laplacian, factored once;
  // vertex 0 is held at 0 (the Laplacian of a closed surface has the constants as kernel)
  const std::vector<double> w = k > 0 ? internal::floored_cotan_edge_weights(m) : std::vector<double>();
  Cholmod_cholesky chol;
  if(k > 0 && nv > 1) {   // (genus 0: no handle loop, no form: the field is the parallel one, no factorisation)
    std::vector<Eigen::Triplet<double>> t;
    for(std::size_t e = 0; e < ne; ++e) {
      const int a = m.target[2 * e + 1], b = m.target[2 * e];
      for(int v : {a, b}) if(v > 0) t.emplace_back(v - 1, v - 1, w[e]);
      if(a > 0 && b > 0) t.emplace_back((std::max)(a, b) - 1, (std::min)(a, b) - 1, -w[e]);
    }
    Cholmod_cholesky::Matrix L(Eigen::Index(nv - 1), Eigen::Index(nv - 1));
    L.setFromTriplets(t.begin(), t.end());
    L.makeCompressed();
    if(!chol.factor(L, st.message)) return st;
  }
  if(!turning.empty() && turning.size() != k)
    throw Input_error(Input_error::INVALID_ARGUMENT, "generator_turning_numbers: " + std::to_string(turning.size()) +
                                                     " values for " + std::to_string(k) + " handle loops");
  std::vector<std::vector<double>> omega(k);
  auto form_at = [](const std::vector<double>& f, int h) { return (h & 1) ? -f[std::size_t(h >> 1)] : f[std::size_t(h >> 1)]; };
  std::vector<char> cone(nv, 0);
  for(std::size_t v = 0; v < nv; ++v) cone[v] = std::abs(K[v]) > 1e-6;
  // each handle loop as a primal loop of the punctured surface: the tree loop, with every pass
  // through a cone replaced by the path around the cone's left side (through its link); where
  // that meets another cone, loops of the surface minus the cones chosen afresh (below)
  std::vector<std::vector<int>> primal(k);
  bool reroute = false;
  for(std::size_t j = 0; j < k && !reroute; ++j) {
    const std::vector<int>& p = loops[j]->primal;   // prev --in--> u --out--> next
    bool drop_last = false;
    for(std::size_t i = 0; i < p.size() && !reroute; ++i) {
      const int out = p[i], in = p[(i + p.size() - 1) % p.size()];
      if(!cone[std::size_t(m.source(out))]) { primal[j].push_back(out); continue; }
      if(cone[std::size_t(m.source(in))]) { reroute = true; break; }   // two adjacent cones on the loop
      if(i > 0) primal[j].pop_back(); else drop_last = true;   // `in` goes
      std::vector<int> link;   // next -> ... -> prev, counterclockwise around the cone
      for(int h = out; h != (in ^ 1); h = m.ccw_out(h)) link.push_back(m.next[std::size_t(h)]);
      for(auto it = link.rbegin(); it != link.rend(); ++it) primal[j].push_back(*it ^ 1);   // prev -> ... -> next
    }
    if(reroute) break;
    if(drop_last) primal[j].pop_back();
    for(int h : primal[j])
      if(cone[std::size_t(m.source(h))]) { reroute = true; break; }   // the detour meets an adjacent cone
  }
  if(reroute && construction == CUT_AND_DIRICHLET) {
    st.message = "a handle loop passes next to adjacent cones; the cut-and-Dirichlet construction needs them apart "
                 "(the default harmonic projection routes the loops around them)";
    return st;
  }
  if(reroute && !turning.empty()) {
    st.message = "a handle loop of the tree-cotree basis passes next to adjacent cones: its turning number cannot be "
                 "prescribed (without --turning the loops are routed around the cones)";
    return st;
  }
  for(std::size_t j = 0; j < k; ++j) {
    std::vector<double> tau(ne, 0.);
    if(construction == CUT_AND_DIRICHLET) {
      if(!internal::cut_jump_form(m, w, primal[j], tau, st.message)) return st;
    } else {
      // the Poincare dual of the handle's dual cycle, +1 on each edge it crosses (closed: each
      // face it passes through is entered once and left once)
      for(int h : loops[j]->dual) tau[std::size_t(h >> 1)] += (h & 1) ? -1. : 1.;
    }
    // harmonic projection: L hk = -div(tau), omega = tau + d hk
    Eigen::VectorXd div = Eigen::VectorXd::Zero(Eigen::Index(nv - 1));
    for(std::size_t e = 0; e < ne; ++e) {
      const int a = m.target[2 * e + 1], b = m.target[2 * e];   // halfedge 2e: a -> b
      if(a > 0) div[a - 1] += w[e] * tau[e];
      if(b > 0) div[b - 1] -= w[e] * tau[e];
    }
    const Eigen::VectorXd hk = nv > 1 ? Eigen::VectorXd(chol.solve(div)) : Eigen::VectorXd();
    auto hv = [&](int v) { return v > 0 ? hk[v - 1] : 0.; };
    omega[j].resize(ne);
    for(std::size_t e = 0; e < ne; ++e) omega[j][e] = tau[e] + hv(m.target[2 * e]) - hv(m.target[2 * e + 1]);
  }
  if(reroute && !internal::loops_avoiding_cones(m, cone, omega, primal, st.message)) return st;
  // the period matrix and the targets
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(Eigen::Index(k), Eigen::Index(k));
  Eigen::VectorXd target = Eigen::VectorXd::Zero(Eigen::Index(k));
  for(std::size_t i = 0; i < k; ++i) {
    double hol = 0;
    const std::vector<int>& p = primal[i];
    for(int h : p) hol += frames.transport(h);   // each step maps source frame to target frame
    hol = internal::wrap_angle(hol);
    st.holonomy.push_back(hol);
    // the field's total rotation along the loop, 2 pi t: the chosen turning number, else the
    // multiple of 2 pi / N nearest to the holonomy (the least compensation)
    const double turn = i < turning.size() ? 2 * CGAL_PI * turning[i] : period * std::round(hol / period);
    target[Eigen::Index(i)] = turn - hol;
    st.periods.push_back(target[Eigen::Index(i)]);
    for(std::size_t j = 0; j < k; ++j) {
      double s = 0;
      for(int h : p) s += form_at(omega[j], h);
      P(Eigen::Index(i), Eigen::Index(j)) = s;
    }
  }
  const Eigen::VectorXd weights = k ? Eigen::VectorXd(P.fullPivLu().solve(target)) : Eigen::VectorXd();
  std::vector<double> om(ne, 0.);
  for(std::size_t j = 0; j < k; ++j)
    for(std::size_t e = 0; e < ne; ++e) om[e] += weights[Eigen::Index(j)] * omega[j][e];
  // residuals: closed on faces, co-closed at vertices (the zero form when there is no handle)
  for(std::size_t f = 0; k > 0 && f < m.number_of_faces(); ++f) {
    const int h0 = m.face_halfedge[f];
    const double r = form_at(om, h0) + form_at(om, m.next[std::size_t(h0)]) + form_at(om, m.next[std::size_t(m.next[std::size_t(h0)])]);
    st.max_harmonic_residual = (std::max)(st.max_harmonic_residual, std::abs(r));
  }
  if(k > 0) {
    std::vector<double> d(nv, 0.);
    for(std::size_t e = 0; e < ne; ++e) { d[std::size_t(m.target[2 * e + 1])] += w[e] * om[e]; d[std::size_t(m.target[2 * e])] -= w[e] * om[e]; }
    double wmax = 0;
    for(double x : w) wmax = (std::max)(wmax, x);
    for(double x : d) st.max_harmonic_residual = (std::max)(st.max_harmonic_residual, std::abs(x) / (std::max)(wmax, 1e-300));
  }
  // breadth-first propagation over the vertices
  std::vector<double> alpha(nv, 0.);
  std::vector<char> seen(nv, 0);
  int start = int(internal::vertex_off_the_islands(m, cone));
  if(start == int(nv)) start = 0;   // every vertex is a cone
  std::vector<int> queue(1, start);
  seen[std::size_t(start)] = 1;
  for(std::size_t q = 0; q < queue.size(); ++q) {
    const int v = queue[q];
    const int h0 = m.vertex_out[std::size_t(v)];
    int h = h0;
    do {
      const int u = m.target[std::size_t(h)];
      if(!seen[std::size_t(u)]) {   // cones get a value but pass nothing on (the field is singular there)
        seen[std::size_t(u)] = 1;
        alpha[std::size_t(u)] = alpha[std::size_t(v)] + frames.transport(h) + form_at(om, h);
        if(!cone[std::size_t(u)]) queue.push_back(u);
      }
      h = m.ccw_out(h);
    } while(h != h0);
  }
  for(std::size_t e = 0; e < ne; ++e) {
    const int h = int(2 * e);
    if(cone[std::size_t(m.target[std::size_t(h)])] || cone[std::size_t(m.source(h))] || !seen[std::size_t(m.target[std::size_t(h)])] ||
       !seen[std::size_t(m.source(h))])
      continue;
    const double r = alpha[std::size_t(m.target[std::size_t(h)])] - alpha[std::size_t(m.source(h))] - frames.transport(h) - form_at(om, h);
    st.max_inconsistency = (std::max)(st.max_inconsistency, std::abs(std::remainder(r, period)));
  }
  // vertices the cones enclose (no path of vertices reaches them around the cones): their faces
  // take the field by Levi-Civita transport from faces that have it (the conversion's rule for
  // faces of cones only: parallel across an edge up to the 1-form's small rotation), and each
  // such vertex the direction of one of its faces
  std::vector<double> islands_K;
  for(std::size_t v = 0; v < nv; ++v)
    if(!seen[v] && !cone[v] && !m.is_isolated(int(v))) {
      if(islands_K.empty()) islands_K = K;
      islands_K[v] = 1;   // not a corner to take the field from
    }
  internal::vertex_field_to_face_angles(m, frames, islands_K.empty() ? K : islands_K, alpha, face_angles);
  if(!islands_K.empty()) {
    for(std::size_t v = 0; v < nv; ++v) {
      if(seen[v] || cone[v] || m.is_isolated(int(v))) continue;
      const int h = m.vertex_out[v];   // a direction of face angle b makes angle b - halfedge_direction(h) with h
      alpha[v] = double(get(face_angles, m.faces[std::size_t(m.face[std::size_t(h)])])) - internal::halfedge_direction(m, h) +
                 frames.direction[std::size_t(h)];
      ++st.enclosed_vertices;
    }
    for(std::size_t e = 0; e < ne; ++e) {   // their edges too
      const int h = int(2 * e), a = m.source(h), b = m.target[std::size_t(h)];
      if(cone[std::size_t(a)] || cone[std::size_t(b)] || (seen[std::size_t(a)] && seen[std::size_t(b)])) continue;
      const double r = alpha[std::size_t(b)] - alpha[std::size_t(a)] - frames.transport(h) - form_at(om, h);
      st.max_enclosed_inconsistency = (std::max)(st.max_enclosed_inconsistency, std::abs(std::remainder(r, period)));
    }
  }
  for(std::size_t v = 0; v < nv; ++v) {
    const double a = alpha[v] - 2 * CGAL_PI * std::floor(alpha[v] / (2 * CGAL_PI));
    put(vertex_angles, m.vertices[v], a);
  }
  st.success = st.max_inconsistency <= 1e-6;
  if(!st.success) {
    std::ostringstream os;
    os.precision(3);
    os << "the compensated field is not an N-RoSy field: inconsistency " << st.max_inconsistency
       << " rad (are the cone curvatures multiples of 2 pi / " << N << "?)";
    st.message = os.str();
  }
  return st;
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_ROTATION_COMPENSATION_H
