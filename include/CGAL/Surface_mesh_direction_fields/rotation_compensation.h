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
  /// \f$\omega\f$ to a multiple of \f$2\pi/N\f$: across every edge for the face field, along
  /// every edge between vertices that are no cones for the vertex field
  double max_inconsistency = 0;
  /// largest rotation of the face field across an edge beyond Levi-Civita transport (that of
  /// \f$\omega\f$ between the two faces); below \f$\pi/N\f$, the principal matching (the
  /// nearest rotation by a multiple of \f$2\pi/N\f$) reads back exactly the cones; above, only
  /// the field's own matching (the `matching` output) does
  double max_rotation = 0;
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

// A primal loop without its backtracks h, h^1 (cyclically).
inline std::vector<int> without_backtracks(const std::vector<int>& loop)
{
  std::vector<int> st;
  for(int h : loop) {
    if(!st.empty() && st.back() == (h ^ 1)) st.pop_back(); else st.push_back(h);
  }
  while(st.size() > 1 && st.front() == (st.back() ^ 1)) { st.pop_back(); st.erase(st.begin()); }
  return st;
}

// The paper's jump form for one simple primal loop (halfedges in order, backtracks removed):
// dg of the function g harmonic on the surface cut open along the loop, 1 on the loop's left
// side and 0 on its right, as a value per edge for halfedge 2e. False (and a message) when the
// loop is not simple or the factorisation fails.
template <typename TM>
bool cut_jump_form(const Mesh_arrays<TM>& m, const std::vector<double>& w, std::vector<int> loop,
                   std::vector<double>& dg, std::string& message)
{
  loop = without_backtracks(loop);   // a tree-cotree loop then becomes simple
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


// The dual cycle that runs along the left side of a primal loop (halfedges in order, no
// backtracks), as the halfedges it crosses, each into its own face: at every vertex of the loop,
// through the faces between the incoming and the outgoing halfedge, clockwise. It passes no
// vertex, so its Levi-Civita holonomy is that of the loop passing every cone on its left, and
// the loop's cones and adjacent cones need no detour.
template <typename TM>
std::vector<int> left_push_off(const Mesh_arrays<TM>& m, const std::vector<int>& loop)
{
  std::vector<int> crossed;
  for(std::size_t i = 0; i < loop.size(); ++i) {
    const int in = loop[i], out = loop[(i + 1) % loop.size()];
    for(int g = m.next[std::size_t(in)]; g != out; g = m.next[std::size_t(g ^ 1)]) crossed.push_back(g ^ 1);
  }
  return crossed;
}

// Per halfedge h, the potential of the closed 1-form om in face(h) at source(h): om integrated
// along the face's sides from its first corner, minus its mean over the three corners (the
// field at the face's centre). Across the edge of h, from face(h^1) into face(h), the face field
// turns by transport plus rho(h) = potential[next(h^1)] - potential[h] (the two faces'
// potentials at source(h)); any constant per face would do, as the rho around a vertex telescope
// to 0, but anchoring each face's potential at a corner shared with its neighbours gave 1.4 to 3
// times larger rotations across edges than the mean (cheese, genus-3, fertility, rocker arm).
template <typename TM>
std::vector<double> face_potentials(const Mesh_arrays<TM>& m, const std::vector<double>& om)
{
  auto form_at = [&](int h) { return (h & 1) ? -om[std::size_t(h >> 1)] : om[std::size_t(h >> 1)]; };
  std::vector<double> pot(m.number_of_halfedges(), 0.);
  for(std::size_t f = 0; f < m.number_of_faces(); ++f) {
    const int h0 = m.face_halfedge[f], h1 = m.next[std::size_t(h0)], h2 = m.next[std::size_t(h1)];
    const double p1 = form_at(h0), p2 = p1 + form_at(h1), mean = (p1 + p2) / 3;
    pot[std::size_t(h0)] = -mean;
    pot[std::size_t(h1)] = p1 - mean;
    pot[std::size_t(h2)] = p2 - mean;
  }
  return pot;
}

} // namespace internal

/// \ingroup PkgSurfaceMeshDirectionFieldsFieldDesign
/// Rotation compensation (Lai et al. 2010, section 4.1.3.1) on a closed surface: builds the
/// harmonic 1-forms \f$\omega_k\f$ dual to the handle loops \f$\gamma_k\f$ (a closed 1-form that
/// jumps by 1 across \f$\gamma_k\f$, made harmonic by \f$\Delta(\tau_k + dh_k) = 0\f$ with the cotan
/// Laplacian of the metric: the unique harmonic representative, which is the paper's
/// \f$dg_k + dh_k\f$), solves the small system \f$\sum_k w_k \int_{\gamma_j}\omega_k = p_j\f$ for
/// the periods \f$p_j\f$ that make the holonomy of every handle loop a multiple of \f$2\pi/N\f$
/// (the loop's holonomy taken along its left side, which passes every cone on the loop on its
/// left), and propagates a direction from the first face breadth-first over the faces: carried
/// across each edge by Levi-Civita transport and rotated counterclockwise by \f$\omega\f$ (its
/// integral between the two faces' potentials of \f$\omega\f$, which is closed on each face).
/// The propagation passes no vertex, so any configuration of cones, adjacent or walling off a
/// handle, is served alike.
///
/// `face_angles` receives that field in the face frames, for read-back with
/// field_singularities() and the same `edge_length_map`: its singularities are exactly the
/// cones, of index \f$K/2\pi\f$. `vertex_angles` receives the paper's vertex field: one angle
/// per vertex, counterclockwise from a reference outgoing halfedge (that of the first edge at the
/// vertex, in `edges(tm)` order: `halfedge(e)` or its opposite, whichever leaves the vertex) in
/// the metric, scaled so that the directions around a vertex span \f$2\pi\f$; along every edge
/// between vertices that are no cones it is the transport plus \f$\omega\f$ up to a multiple of
/// \f$2\pi/N\f$.
///
/// Named parameters: `edge_length_map` (a flat cone metric: angle defect 0 except at the
/// cones) or `intrinsic_mesh`, the index maps, and `generator_turning_numbers` (a
/// `std::vector<double>`, one multiple of \f$1/N\f$ per handle loop: the field's total rotation
/// along it over \f$2\pi\f$; default: the multiple nearest to the loop's holonomy, the least
/// compensation), `harmonic_form_construction` (default `HARMONIC_PROJECTION`; see
/// `Harmonic_form_construction`), and `matching` (an edge property map of `int`: receives the
/// field's own matching, for `halfedge(e)` in the convention of field_singularities()'s
/// `matching`: the period jump that makes the rotation across the edge the 1-form's, even where
/// that is \f$\pi/N\f$ or more). Throws `Input_error` for meshes with boundary or several
/// components, \f$N < 1\f$, and the errors of `Intrinsic_mesh`; numerical failure is in the
/// status, and so is a field that turns by \f$\pi/N\f$ or more across an edge when no
/// `matching` is asked for (the principal matching would read other singularities).
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
  std::vector<std::vector<int>> primal(k);   // the handle loops, without backtracks
  for(std::size_t j = 0; j < k; ++j) primal[j] = internal::without_backtracks(loops[j]->primal);
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
  // the period matrix and the targets
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(Eigen::Index(k), Eigen::Index(k));
  Eigen::VectorXd target = Eigen::VectorXd::Zero(Eigen::Index(k));
  for(std::size_t i = 0; i < k; ++i) {
    // the holonomy along the loop's left side (cones passed on their left, as the turning number
    // counts them); the period of a closed form is the same on the loop itself
    double hol = 0;
    const std::vector<int>& p = primal[i];
    for(int h : internal::left_push_off(m, p)) hol += internal::transport_increment(m, h);
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
  // breadth-first propagation over the faces, from face 0: Levi-Civita transport across each
  // edge plus the rotation rho of omega there (face_potentials()). It never meets a vertex, so
  // cones, adjacent cones and the vertices they enclose need no special route: around a vertex
  // the rho telescope to 0 and the transport turns by its curvature, a multiple of 2 pi / N.
  const std::vector<double> pot = internal::face_potentials(m, om);
  auto rho = [&](int h) { return pot[std::size_t(m.next[std::size_t(h ^ 1)])] - pot[std::size_t(h)]; };
  const std::size_t nf = m.number_of_faces();
  std::vector<double> theta(nf, 0.);
  std::vector<char> reached(nf, 0);
  for(std::size_t r = 0; r < nf; ++r) {   // (one component: the first root reaches every face)
    if(reached[r]) continue;
    reached[r] = 1;
    std::vector<int> queue(1, int(r));
    for(std::size_t q = 0; q < queue.size(); ++q) {
      const int g = queue[q], h0 = m.face_halfedge[std::size_t(g)];
      int h = h0;
      for(int i = 0; i < 3; ++i, h = m.next[std::size_t(h)]) {
        const int x = h ^ 1, f = m.face[std::size_t(x)];   // crossing x: from g = face(h) into f = face(x)
        if(f < 0 || reached[std::size_t(f)]) continue;
        reached[std::size_t(f)] = 1;
        theta[std::size_t(f)] = theta[std::size_t(g)] + internal::transport_increment(m, x) + rho(x);
        queue.push_back(f);
      }
    }
  }
  int widest = -1;   // the edge of the largest rotation
  for(std::size_t e = 0; e < ne; ++e) {
    const int x = int(2 * e), f = m.face[std::size_t(x)], g = m.face[std::size_t(x ^ 1)];
    if(f < 0 || g < 0) continue;
    const double r = theta[std::size_t(f)] - theta[std::size_t(g)] - internal::transport_increment(m, x) - rho(x);
    st.max_inconsistency = (std::max)(st.max_inconsistency, std::abs(std::remainder(r, period)));
    if(std::abs(rho(x)) > st.max_rotation) { st.max_rotation = std::abs(rho(x)); widest = int(e); }
  }
  // the vertex field: a direction of face angle b in face(h), h leaving v, makes angle
  // b - halfedge_direction(h) with h; the vertex frame puts h at direction(h); plus the potential
  std::vector<double> alpha(nv, 0.);
  for(std::size_t v = 0; v < nv; ++v) {
    if(m.is_isolated(int(v))) continue;
    const int h = m.vertex_out[v];
    alpha[v] = theta[std::size_t(m.face[std::size_t(h)])] - internal::halfedge_direction(m, h) + frames.direction[std::size_t(h)] +
               pot[std::size_t(h)];
  }
  for(std::size_t e = 0; e < ne; ++e) {   // between vertices that are no cones (their frames are scaled)
    const int h = int(2 * e), a = m.source(h), b = m.target[std::size_t(h)];
    if(cone[std::size_t(a)] || cone[std::size_t(b)]) continue;
    const double r = alpha[std::size_t(b)] - alpha[std::size_t(a)] - frames.transport(h) - form_at(om, h);
    st.max_inconsistency = (std::max)(st.max_inconsistency, std::abs(std::remainder(r, period)));
  }
  for(std::size_t f = 0; f < nf; ++f)
    put(face_angles, m.faces[f], theta[f] - 2 * CGAL_PI * std::floor(theta[f] / (2 * CGAL_PI)));
  for(std::size_t v = 0; v < nv; ++v) {
    const double a = alpha[v] - 2 * CGAL_PI * std::floor(alpha[v] / (2 * CGAL_PI));
    put(vertex_angles, m.vertices[v], a);
  }
  constexpr bool with_matching = !parameters::is_default_parameter<NamedParameters, internal_np::matching_t>::value;
  if constexpr(with_matching) {
    // k such that the rotation across the edge, w(raw) + k period as field_singularities() reads
    // it, is rho (raw is rho up to a multiple of the period); raw from the very angles written
    // (where raw is near a half turn, w(raw) depends on its last bit)
    auto matching = get_parameter(np, internal_np::matching);
    auto written = [&](int f) { return double(get(face_angles, m.faces[std::size_t(f)])); };
    for(std::size_t e = 0; e < ne; ++e) {
      const int x = int(2 * e), f = m.face[std::size_t(x)], g = m.face[std::size_t(x ^ 1)];
      int k = 0;
      if(f >= 0 && g >= 0) {
        const double raw = written(f) - written(g) - internal::transport_increment(m, x);
        k = int(std::lround((rho(x) - internal::wrap_angle(raw)) / period));
      }
      put(matching, m.edges[e], k);
    }
  }
  st.success = st.max_inconsistency <= 1e-6 && (with_matching || st.max_rotation < period / 2);
  if(!st.success) {
    std::ostringstream os;
    os.precision(3);
    if(st.max_inconsistency > 1e-6)
      os << "the compensated field is not an N-RoSy field: inconsistency " << st.max_inconsistency
         << " rad (are the cone curvatures multiples of 2 pi / " << N << "?)";
    else
      os << "the compensated field turns by " << st.max_rotation << " rad across the edge " << m.source(2 * widest) << "-"
         << m.target[std::size_t(2 * widest)] << ", pi / " << N << " or more: the triangulation is too coarse for the "
         << "compensating 1-form there, and the field's matching would read back other singularities than the cones";
    st.message = os.str();
  }
  return st;
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_ROTATION_COMPENSATION_H
