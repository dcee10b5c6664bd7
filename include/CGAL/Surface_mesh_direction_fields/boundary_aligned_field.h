// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_BOUNDARY_ALIGNED_FIELD_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_BOUNDARY_ALIGNED_FIELD_H

// N-RoSy fields parallel or orthogonal to the boundary of an open mesh (Lai et al. 2010,
// section 4.3): the double cover's construction (the mesh glued to its mirror image along the
// boundary) restricted to one half, on the mesh's own flat metric with a geodesic boundary.

#include <CGAL/Surface_mesh_direction_fields/Intrinsic_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/cone_metric.h>
#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/internal/development.h>
#include <CGAL/Surface_mesh_direction_fields/internal/cotan_weights.h>
#include <CGAL/Surface_mesh_direction_fields/Cholmod_cholesky.h>
#include <CGAL/Surface_mesh_direction_fields/parallel_rosy_field.h>
#include <CGAL/Surface_mesh_direction_fields/internal/tree_cotree.h>

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsFieldDesign
/// Outcome of boundary_aligned_rosy_field() and boundary_aligned_field_of_metric().
struct Boundary_aligned_field_status
{
  /// a flat cone metric with a geodesic boundary was found (boundary_aligned_rosy_field()), the
  /// field on it is an N-RoSy field, and along every boundary edge one of its directions is
  /// parallel (orthogonal) to the edge
  bool success = false;
  std::string message;                  ///< empty on success
  int N = 1;
  bool orthogonal = false;              ///< the field was asked orthogonal to the boundary
  Cone_metric_status metric;            ///< the Ricci flow (boundary_aligned_rosy_field() only)
  bool rotation_compensation = false;   ///< the mesh has handles, whose holonomy was compensated
  /// over the faces with a border edge: the distance of the field's angle with the edge (minus
  /// \f$\pi/2\f$ when orthogonal) to the nearest multiple of \f$2\pi/N\f$ (\f$\pi/N\f$ for odd
  /// \f$N\f$: a direction along the edge in either orientation), see max_boundary_deviation()
  double max_boundary_deviation = 0;
};

namespace internal {

// The field that follows every boundary loop on a flat metric of an open mesh of any genus: the
// parallel transport plus a rotation rho_e across each interior edge e (added when crossing it
// from face(2e + 1) into face(2e)), the smoothest one, min sum rho_e^2 / w_e (w: cotan weights,
// rho the Hodge dual of a primal 1-form of least Dirichlet energy), subject to
// - around every vertex, interior or on the boundary, sum rho = 0: no index changes, and along
//   each boundary loop the field keeps its angle with the geodesic boundary;
// - around the dual cycle of each handle generator, sum rho = minus the parallel holonomy's
//   distance to the nearest multiple of 2 pi / N (rotation compensation);
// - along a dual path from the first followed loop to each other followed loop, sum rho = minus
//   the angle the parallel field arrives with (modulo the line's period): it reaches that loop
//   aligned. Loops marked in free_loop are not followed (e.g. the holes punched at cones of
//   index >= 1): their vertex sums still keep the field's holonomy around them.
// Lagrange: rho = W C^T lambda, (C W C^T) lambda = c; the vertex block is the cotan Laplacian of
// the interior edges (one vertex held), factored once, the others by a Schur complement of size
// 2g + b - 1. beta receives the face angles, rho the rotations; false (and a message) on
// numerical failure.
template <typename TM>
bool compensated_boundary_field(const Mesh_arrays<TM>& m, const Topology_arrays& topo, const std::vector<Generator_arrays>& generators,
                                const std::vector<char>& free_loop, int N, bool orthogonal, std::vector<double>& beta,
                                std::vector<double>& rho, double& max_inconsistency, std::string& message)
{
  std::size_t first = 0;   // the loop the field starts along
  while(first < topo.loops.size() && free_loop[first]) ++first;
  if(first == topo.loops.size()) {
    message = "every boundary loop is left free: no loop for the field to follow";
    return false;
  }
  const std::size_t nv = m.number_of_vertices(), nf = m.number_of_faces(), ne = m.number_of_edges();
  const double period = 2 * CGAL_PI / N, line_period = N % 2 == 0 ? period : CGAL_PI / N;
  const double across = orthogonal ? CGAL_PI / 2 : 0.;
  auto interior = [&](std::size_t e) { return m.face[2 * e] >= 0 && m.face[2 * e + 1] >= 0; };
  auto sign = [](int x) { return (x & 1) ? -1. : 1.; };   // a crossing x: from face(x ^ 1) into face(x)
  const std::vector<double> w = floored_cotan_edge_weights(m);
  // the extra constraints: crossings and right-hand sides
  std::vector<std::vector<int>> paths;
  std::vector<double> rhs;
  for(const auto& g : generators) {
    if(!g.handle) continue;
    double holonomy = 0;
    for(int x : g.dual) holonomy += transport_increment(m, x);
    paths.push_back(g.dual);
    rhs.push_back(-std::remainder(holonomy, period));
  }
  // a border face of each followed loop, entered across its border edge; dual paths from the first's
  const int h0 = topo.loops[first][0] ^ 1;   // the interior halfedge of a border edge of that loop
  const int start = m.face[std::size_t(h0)];
  std::vector<int> parent(nf, -1);   // the crossing that reached the face
  std::vector<char> seen(nf, 0);
  std::vector<int> queue(1, start);
  seen[std::size_t(start)] = 1;
  for(std::size_t q = 0; q < queue.size(); ++q) {
    const int f = queue[std::size_t(q)];
    int h = m.face_halfedge[std::size_t(f)];
    for(int i = 0; i < 3; ++i, h = m.next[std::size_t(h)]) {
      const int g = m.face[std::size_t(h ^ 1)];
      if(g < 0 || seen[std::size_t(g)]) continue;
      seen[std::size_t(g)] = 1;
      parent[std::size_t(g)] = h ^ 1;   // from face(h) = f into face(h ^ 1) = g
      queue.push_back(g);
    }
  }
  const double beta0 = halfedge_direction(m, h0) + across;
  for(std::size_t j = first + 1; j < topo.loops.size(); ++j) {
    if(free_loop[j]) continue;
    const int hb = topo.loops[j][0] ^ 1;
    std::vector<int> path;
    for(int f = m.face[std::size_t(hb)]; f != start; f = m.face[std::size_t(parent[std::size_t(f)] ^ 1)]) path.push_back(parent[std::size_t(f)]);
    std::reverse(path.begin(), path.end());
    double a = beta0;
    for(int x : path) a += transport_increment(m, x);
    paths.push_back(path);
    rhs.push_back(-std::remainder(a - halfedge_direction(m, hb) - across, line_period));
  }
  // the vertex block: the weighted Laplacian of the interior edges, the first vertex that has
  // one held at 0 (vertices with no interior edge have no constraint)
  std::vector<int> col(nv, -1);
  int held = -1, n = 0;
  for(std::size_t e = 0; e < ne; ++e)
    if(interior(e))
      for(int v : {m.source(int(2 * e)), m.target[2 * e]}) {
        if(held < 0) held = v;
        if(v != held && col[std::size_t(v)] < 0) col[std::size_t(v)] = n++;
      }
  std::vector<Eigen::Triplet<double>> t;
  for(std::size_t e = 0; e < ne; ++e) {
    if(!interior(e)) continue;
    const int ca = col[std::size_t(m.source(int(2 * e)))], cb = col[std::size_t(m.target[2 * e])];
    if(ca >= 0) t.emplace_back(ca, ca, w[e]);
    if(cb >= 0) t.emplace_back(cb, cb, w[e]);
    if(ca >= 0 && cb >= 0) t.emplace_back((std::max)(ca, cb), (std::min)(ca, cb), -w[e]);
  }
  Cholmod_cholesky chol;
  if(n > 0) {
    Cholmod_cholesky::Matrix L(n, n);
    L.setFromTriplets(t.begin(), t.end());
    L.makeCompressed();
    if(!chol.factor(L, message)) return false;
  }
  // per extra constraint k: the edge vector C_k, B_k = C_V W C_k^T (per vertex: + at the
  // source of halfedge 2e, - at its target) and X_k = A^-1 B_k
  const std::size_t k = paths.size();
  std::vector<std::vector<double>> C(k, std::vector<double>(ne, 0.));
  std::vector<Eigen::VectorXd> B(k), X(k);
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(Eigen::Index(k), Eigen::Index(k));
  for(std::size_t i = 0; i < k; ++i) {
    for(int x : paths[i]) C[i][std::size_t(x >> 1)] += sign(x);
    B[i] = Eigen::VectorXd::Zero(n);
    for(std::size_t e = 0; e < ne; ++e) {
      if(C[i][e] == 0) continue;
      const int ca = col[std::size_t(m.source(int(2 * e)))], cb = col[std::size_t(m.target[2 * e])];
      if(ca >= 0) B[i][ca] += w[e] * C[i][e];
      if(cb >= 0) B[i][cb] -= w[e] * C[i][e];
    }
    X[i] = n > 0 ? Eigen::VectorXd(chol.solve(B[i])) : Eigen::VectorXd();
    for(std::size_t j = 0; j <= i; ++j) {   // S = C_X W C_X^T - B^T A^-1 B
      double d = n > 0 ? -B[j].dot(X[i]) : 0.;
      for(std::size_t e = 0; e < ne; ++e) d += C[i][e] * w[e] * C[j][e];
      S(Eigen::Index(i), Eigen::Index(j)) = S(Eigen::Index(j), Eigen::Index(i)) = d;
    }
  }
  Eigen::VectorXd lx = Eigen::VectorXd::Zero(Eigen::Index(k));
  if(k > 0) {
    Eigen::VectorXd c = Eigen::VectorXd::Zero(Eigen::Index(k));
    for(std::size_t i = 0; i < k; ++i) c[Eigen::Index(i)] = rhs[i];
    lx = S.fullPivLu().solve(c);
    if(!lx.allFinite() || (S * lx - c).norm() > 1e-9 * (1 + c.norm())) {
      message = "the handle and boundary-loop constraints of the compensation are not independent";
      return false;
    }
  }
  Eigen::VectorXd lv = Eigen::VectorXd::Zero(n);
  for(std::size_t i = 0; i < k; ++i) lv -= lx[Eigen::Index(i)] * X[i];
  auto lambda = [&](int v) { return col[std::size_t(v)] >= 0 ? lv[col[std::size_t(v)]] : 0.; };
  rho.assign(ne, 0.);
  for(std::size_t e = 0; e < ne; ++e) {
    if(!interior(e)) continue;
    double r = lambda(m.source(int(2 * e))) - lambda(m.target[2 * e]);
    for(std::size_t i = 0; i < k; ++i) r += C[i][e] * lx[Eigen::Index(i)];
    rho[e] = w[e] * r;
  }
  // the field, breadth-first from the first loop's border face, and its consistency
  beta.assign(nf, 0.);
  beta[std::size_t(start)] = beta0;
  for(std::size_t q = 1; q < queue.size(); ++q) {
    const int f = queue[q], x = parent[std::size_t(f)];
    beta[std::size_t(f)] = beta[std::size_t(m.face[std::size_t(x ^ 1)])] + transport_increment(m, x) + sign(x) * rho[std::size_t(x >> 1)];
  }
  max_inconsistency = 0;
  for(std::size_t e = 0; e < ne; ++e) {
    if(!interior(e)) continue;
    const int x = int(2 * e);   // from face(2e + 1) into face(2e)
    const double r = beta[std::size_t(m.face[std::size_t(x)])] - beta[std::size_t(m.face[std::size_t(x ^ 1)])] - transport_increment(m, x) - rho[e];
    max_inconsistency = (std::max)(max_inconsistency, std::abs(std::remainder(r, period)));
  }
  for(double& a : beta) a -= 2 * CGAL_PI * std::floor(a / (2 * CGAL_PI));
  return true;
}

// Over the faces with a border edge: the distance of the field's angle with the edge (minus
// pi/2 when orthogonal) to the nearest direction of the field's line (a multiple of 2 pi / N,
// of pi / N for odd N); a face with two border edges (a corner face) counts the nearer one, as
// no constant field in a face follows two sides that meet at an angle off that lattice.
template <typename TM>
double boundary_deviation(const Mesh_arrays<TM>& mf, const Topology_arrays& topo, int N, bool orthogonal,
                          const std::vector<double>& beta, const std::vector<char>& free_loop = std::vector<char>())
{
  const double line_period = N % 2 == 0 ? 2 * CGAL_PI / N : CGAL_PI / N;
  std::vector<double> per_face(mf.number_of_faces(), -1.);
  for(std::size_t j = 0; j < topo.loops.size(); ++j) {
    if(!free_loop.empty() && free_loop[j]) continue;
    for(int b : topo.loops[j]) {
      const int h = b ^ 1;
      const std::size_t f = std::size_t(mf.face[std::size_t(h)]);
      const double d = std::abs(std::remainder(beta[f] - halfedge_direction(mf, h) - (orthogonal ? CGAL_PI / 2 : 0.), line_period));
      per_face[f] = per_face[f] < 0 ? d : (std::min)(per_face[f], d);
    }
  }
  double worst = 0;
  for(double d : per_face) worst = (std::max)(worst, d);
  return worst;
}

inline std::string boundary_deviation_message(double deviation)
{
  return "the field does not follow the boundary everywhere (deviation " + std::to_string(deviation) +
         " rad): do the boundary corners turn by multiples of 2 pi / N?";
}

} // namespace internal

/// \ingroup PkgSurfaceMeshDirectionFieldsFieldDesign
/// The largest deviation of a face field from the boundary of an open mesh: over the faces with
/// a border edge, the distance of the angle between the field in the face and the edge (minus
/// \f$\pi/2\f$ with `orthogonal_to_boundary(true)`) to the nearest multiple of \f$2\pi/N\f$
/// (\f$\pi/N\f$ for odd \f$N\f$: a direction along the edge in either orientation); a face with
/// two border edges (a corner face) counts the nearer one, as no constant field in a face
/// follows two sides that meet at an angle off that lattice. `face_angles`
/// are in the face frames of the metric given by `edge_length_map` (default: Euclidean lengths)
/// or `intrinsic_mesh`. 0 for a closed mesh.
template <typename TriangleMesh, typename FaceAngleMap, typename NamedParameters = parameters::Default_named_parameters>
double max_boundary_deviation(const TriangleMesh& tm, int N, const FaceAngleMap& face_angles,
                              const NamedParameters& np = parameters::default_values())
{
  if(N < 1) throw Input_error(Input_error::INVALID_ARGUMENT, "symmetry order N must be at least 1, got " + std::to_string(N));
  const Intrinsic_mesh<TriangleMesh> im = internal::get_intrinsic_mesh(tm, np);
  const internal::Mesh_arrays<TriangleMesh>& m = im.arrays();
  std::vector<double> beta(m.number_of_faces());
  for(std::size_t f = 0; f < beta.size(); ++f) beta[f] = double(get(face_angles, m.faces[f]));
  return internal::boundary_deviation(m, im.topology_arrays(), N,
                                      parameters::choose_parameter(parameters::get_parameter(np, internal_np::orthogonal_to_boundary), false),
                                      beta);
}

/// \ingroup PkgSurfaceMeshDirectionFieldsFieldDesign
/// The N-RoSy field parallel (or, with `orthogonal_to_boundary(true)`, orthogonal) to the
/// boundary of an open mesh of any genus and any number of boundary loops, on a flat cone
/// metric whose boundary loops are geodesics with corners that turn by multiples of
/// \f$2\pi/N\f$ and whose cones are multiples of \f$2\pi/N\f$ (e.g. the metric of
/// compute_cone_metric() with boundary targets rounded so, on the input or on its intrinsic
/// triangulation). It is the parallel transport of the metric from a boundary edge, plus the
/// smoothest rotation across the interior edges (a harmonic 1-form, the Hodge dual of the
/// primal 1-form of least Dirichlet energy) that
/// - sums to 0 around every vertex, interior or on the boundary: the cones keep their indices,
///   and along each boundary loop the field keeps its angle with the geodesic boundary;
/// - around each handle of the mesh cancels the holonomy up to a multiple of \f$2\pi/N\f$
///   (Lai et al.'s rotation compensation, section 4.1.3.1);
/// - along a path from the first boundary loop to each other loop turns the field onto it.
///
/// This is Lai et al.'s double cover construction (section 4.3) restricted to one half: the
/// double cover's flat metric is unique, hence mirror-symmetric, and is the mirror double of
/// this one; its compensation that is odd under the mirror is this rotation.
///
/// `face_angles` receives the field in the face frames of the metric, like
/// parallel_rosy_field(), and `matching` its period jumps per edge (the convention of
/// field_singularities(); 0 on border edges): the ones that make its rotation across every
/// interior edge the rotation above. Read back with them, its only singularities are the
/// interior cones (the principal matching may differ where the rotation exceeds
/// \f$\pi/N\f$ across an edge, e.g. between small holes). Named parameters:
/// `orthogonal_to_boundary` (`bool`, default `false`), `free_boundary_vertex_map` (a readable
/// vertex property map to `bool`, default none: the boundary loops whose vertices it marks are
/// left free, neither followed nor measured, e.g. holes punched at cones of index 1 or more; the
/// field keeps its holonomy around them), `edge_length_map` (the flat metric) or
/// `intrinsic_mesh`, and the index maps. The status (its `metric` left empty;
/// `rotation_compensation` says whether the mesh has handles) fails with a message when the
/// field is not consistent across some edge within \f$10^{-6}\f$ rad (a cone or a boundary
/// corner that is no multiple of \f$2\pi/N\f$) or when its deviation from the boundary
/// (max_boundary_deviation()) exceeds \f$10^{-6}\f$. Throws `Input_error` for closed meshes,
/// several components and \f$N < 1\f$.
template <typename TriangleMesh, typename FaceAngleMap, typename EdgeMatchingMap,
          typename NamedParameters = parameters::Default_named_parameters>
Boundary_aligned_field_status boundary_aligned_field_of_metric(const TriangleMesh& tm, int N, FaceAngleMap face_angles,
                                                               EdgeMatchingMap matching,
                                                               const NamedParameters& np = parameters::default_values())
{
  if(N < 1) throw Input_error(Input_error::INVALID_ARGUMENT, "symmetry order N must be at least 1, got " + std::to_string(N));
  Boundary_aligned_field_status st;
  st.N = N;
  st.orthogonal = parameters::choose_parameter(parameters::get_parameter(np, internal_np::orthogonal_to_boundary), false);
  const Intrinsic_mesh<TriangleMesh> im = internal::get_intrinsic_mesh(tm, np);
  const internal::Mesh_arrays<TriangleMesh>& m = im.arrays();
  const internal::Topology_arrays& topo = im.topology_arrays();
  if(topo.components.size() != 1 || topo.loops.empty())
    throw Input_error(Input_error::INVALID_ARGUMENT, "boundary_aligned_field_of_metric() needs a mesh of one component with a boundary");
  st.rotation_compensation = topo.components[0].genus() > 0;
  std::vector<char> free_loop(topo.loops.size(), 0);
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::free_boundary_vertex_t>::value) {
    const auto is_free = parameters::get_parameter(np, internal_np::free_boundary_vertex);
    for(std::size_t j = 0; j < topo.loops.size(); ++j)
      free_loop[j] = get(is_free, m.vertices[std::size_t(m.target[std::size_t(topo.loops[j][0])])]) ? 1 : 0;
  }
  std::vector<double> beta, rho;
  double inconsistency = 0;
  if(!internal::compensated_boundary_field(m, topo, im.generator_arrays(), free_loop, N, st.orthogonal, beta, rho, inconsistency,
                                           st.message))
    return st;
  for(std::size_t f = 0; f < beta.size(); ++f) put(face_angles, m.faces[f], beta[f]);
  const double period = 2 * CGAL_PI / N;
  for(std::size_t e = 0; e < m.number_of_edges(); ++e) {   // rotation wrap(raw) + k period = rho_e
    const int h = int(2 * e);
    if(m.face[std::size_t(h)] < 0 || m.face[std::size_t(h ^ 1)] < 0) { put(matching, m.edges[e], 0); continue; }
    const double raw = beta[std::size_t(m.face[std::size_t(h)])] - beta[std::size_t(m.face[std::size_t(h ^ 1)])] -
                       internal::transport_increment(m, h);
    put(matching, m.edges[e], int(std::lround((rho[e] - internal::wrap_angle(raw)) / period)));
  }
  if(!(inconsistency <= 1e-6)) {
    std::ostringstream os;
    os.precision(3);
    os << "no " << N << "-RoSy field follows the boundary on this metric: across some edge the field differs by " << inconsistency
       << " rad from a multiple of 2 pi / " << N << " (is every cone and every boundary corner a multiple of 2 pi / " << N << "?)";
    st.message = os.str();
    return st;
  }
  st.max_boundary_deviation = internal::boundary_deviation(m, topo, N, st.orthogonal, beta, free_loop);
  st.success = st.max_boundary_deviation <= 1e-6;
  if(!st.success) st.message = internal::boundary_deviation_message(st.max_boundary_deviation);
  return st;
}

/// \ingroup PkgSurfaceMeshDirectionFieldsFieldDesign
/// An N-RoSy field on an open mesh that is parallel to its boundary, or orthogonal to it with
/// the named parameter `orthogonal_to_boundary(true)` (Lai et al. 2010, section 4.3), on the
/// mesh's own triangulation: the flat cone metric of compute_cone_metric() with curvature
/// `target_curvature(v)` at the interior vertices and geodesic curvature `target_curvature(v)`
/// (the boundary's turning angle at v, \f$\pi - \sum\theta\f$) at the boundary vertices, which
/// makes the boundary a geodesic between its corners, then boundary_aligned_field_of_metric()
/// on it. The field follows the boundary when every corner turns by a multiple of
/// \f$2\pi/N\f$ (e.g. four corners of \f$\pi/2\f$ for a cross field on a disk). The targets
/// must satisfy Gauss-Bonnet on the mesh (\f$\sum K + \sum\kappa = 2\pi\chi\f$).
///
/// Outputs: `output_lengths` (per edge of `tm`: the flat metric) and `face_angles` (per face, in
/// the face frames of that metric). The metric is computed without edge flips (it must live on
/// `tm`'s edges); for metrics that need flips, compose compute_cone_metric(),
/// copy_intrinsic_triangulation(), boundary_aligned_field_of_metric() and
/// transfer_face_field_to_input() as `smdf rosy` does. Named parameters: `orthogonal_to_boundary`
/// (`bool`, default `false`), `edge_length_map` (the input metric, default Euclidean) and the
/// index maps. Throws `Input_error` for closed meshes, several components, \f$N < 1\f$ and the
/// errors of compute_cone_metric().
template <typename TriangleMesh, typename VertexCurvatureMap, typename OutputEdgeLengthMap, typename FaceAngleMap,
          typename NamedParameters = parameters::Default_named_parameters>
Boundary_aligned_field_status boundary_aligned_rosy_field(const TriangleMesh& tm, int N, const VertexCurvatureMap& target_curvature,
                                                          OutputEdgeLengthMap output_lengths, FaceAngleMap face_angles,
                                                          const NamedParameters& np = parameters::default_values())
{
  const bool orthogonal = parameters::choose_parameter(parameters::get_parameter(np, internal_np::orthogonal_to_boundary), false);
  const Intrinsic_mesh<TriangleMesh> im = internal::get_intrinsic_mesh(tm, np);
  const internal::Mesh_arrays<TriangleMesh>& m = im.arrays();
  if(im.topology_arrays().components.size() != 1 || im.topology_arrays().loops.empty() || N < 1)
    throw Input_error(Input_error::INVALID_ARGUMENT, "boundary_aligned_rosy_field() needs a mesh of one component with a boundary "
                                                     "and N >= 1 (N = " + std::to_string(N) + ")");
  auto input_length = get(CGAL::dynamic_edge_property_t<double>(), tm);   // the input metric, as given
  for(std::size_t e = 0; e < m.number_of_edges(); ++e) put(input_length, m.edges[e], m.length[e]);
  const Cone_metric_status metric = compute_cone_metric(tm, target_curvature, output_lengths,
                                                        parameters::edge_length_map(input_length).intrinsic_edge_flips(false));
  Boundary_aligned_field_status st;
  if(metric.converged) {
    auto matching = get(CGAL::dynamic_edge_property_t<int>(), tm);
    st = boundary_aligned_field_of_metric(tm, N, face_angles, matching,
                                          parameters::edge_length_map(output_lengths).orthogonal_to_boundary(orthogonal));
  } else {
    st.N = N;
    st.orthogonal = orthogonal;
    st.message = "no flat cone metric with a geodesic boundary on the mesh's triangulation: " + metric.message;
  }
  st.metric = metric;
  return st;
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_BOUNDARY_ALIGNED_FIELD_H
