// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_CURVATURE_ALIGNED_FIELD_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_CURVATURE_ALIGNED_FIELD_H

#include <CGAL/Surface_mesh_direction_fields/Cholmod_cholesky.h>
#include <CGAL/Surface_mesh_direction_fields/Intrinsic_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/field_singularities.h>
#include <CGAL/Surface_mesh_direction_fields/parameters.h>
#include <CGAL/Surface_mesh_direction_fields/internal/development.h>

#include <Eigen/Sparse>

#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsFieldDesign
/// Outcome of curvature_aligned_rosy_field() and automatic_singularities().
template <typename TriangleMesh>
struct Curvature_aligned_field_status
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  bool success = false;      ///< the field was computed
  std::string message;       ///< why not
  double alignment_weight = 0; ///< the weight \f$\lambda\f$ used
  int smoothing_steps = 0;     ///< the number of smoothing steps used
  /// largest rotation of the field across an interior edge relative to Levi-Civita, over
  /// \f$\pi/N\f$ (below 1: the principal matching is the field's)
  double max_rotation_over_pi_over_N = 0;
  /// the field's singularities read back with principal matching: interior vertices and their
  /// indices (multiples of \f$1/N\f$, summing to \f$\chi\f$ on closed meshes)
  std::vector<std::pair<vertex_descriptor, double>> singularities;
};

namespace internal {

// Per face: the anisotropic part of the shape operator of the normal cycle (Cohen-Steiner,
// Morvan 2003) restricted to the face, S = sum over its edges of beta_e |e| e e^T / 2A (beta_e
// the signed dihedral angle), as the complex number (S_11 - S_22) + 2i S_12 in the face frame
// (e1 along halfedge(f)): its argument is twice the angle of the direction of largest
// curvature, its modulus the anisotropy.
template <typename TM, typename VPM>
std::vector<std::array<double, 2>> face_shape_anisotropy(const Mesh_arrays<TM>& m, const VPM& vpm)
{
  typedef std::array<double, 3> V3;
  auto point = [&](int v) {
    const auto& p = get(vpm, m.vertices[std::size_t(v)]);
    return V3{{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
  };
  auto sub = [](const V3& a, const V3& b) { return V3{{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; };
  auto cross = [](const V3& a, const V3& b) { return V3{{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}}; };
  auto dot = [](const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  const std::size_t nf = m.number_of_faces(), ne = m.number_of_edges();
  std::vector<V3> normal(nf);
  for(std::size_t f = 0; f < nf; ++f) {
    const int h = m.face_halfedge[f];
    const V3 a = point(m.source(h)), b = point(m.target[std::size_t(h)]), c = point(m.target[std::size_t(m.next[std::size_t(h)])]);
    V3 n = cross(sub(b, a), sub(c, a));
    const double l = std::sqrt(dot(n, n));
    for(double& x : n) x /= (l > 0 ? l : 1);
    normal[f] = n;
  }
  std::vector<double> beta(ne, 0.);
  for(std::size_t e = 0; e < ne; ++e) {
    const int h = int(2 * e);
    if(m.face[std::size_t(h)] < 0 || m.face[std::size_t(h ^ 1)] < 0) continue;
    V3 d = sub(point(m.target[std::size_t(h)]), point(m.source(h)));
    const double l = std::sqrt(dot(d, d));
    for(double& x : d) x /= l;
    const V3& nl = normal[std::size_t(m.face[std::size_t(h)])];
    const V3& nr = normal[std::size_t(m.face[std::size_t(h ^ 1)])];
    beta[e] = std::atan2(dot(cross(nl, nr), d), dot(nl, nr));
  }
  std::vector<std::array<double, 2>> w(nf);
  for(std::size_t f = 0; f < nf; ++f) {
    const int h0 = m.face_halfedge[f];
    const double area = triangle_area(m.length[std::size_t(h0 >> 1)], m.length[std::size_t(m.next[std::size_t(h0)] >> 1)],
                                      m.length[std::size_t(m.next[std::size_t(m.next[std::size_t(h0)])] >> 1)]);
    double s11 = 0, s22 = 0, s12 = 0;
    for(int h = h0, i = 0; i < 3; h = m.next[std::size_t(h)], ++i) {
      const double a = halfedge_direction(m, h), len = m.length[std::size_t(h >> 1)];
      const double c = std::cos(a), s = std::sin(a), k = beta[std::size_t(h >> 1)] * len / (2 * area);
      s11 += k * c * c; s22 += k * s * s; s12 += k * c * s;
    }
    w[f] = {{s11 - s22, 2 * s12}};
  }
  return w;
}

} // namespace internal

/// \ingroup PkgSurfaceMeshDirectionFieldsFieldDesign
/// A smooth N-RoSy face field aligned with the principal curvature directions: the field
/// \f$z_f\f$ (in the \f$N\f$-th power representation, one complex number per face) minimising
/// \f[ \sum_{e} w_e\,|z_{l} - \rho_e z_{r}|^2 + \lambda \sum_f \frac{A_f}{\bar A}\,|z_f - q_f|^2, \f]
/// where \f$\rho_e = e^{iN\delta_e}\f$ carries \f$z_r\f$ across edge \f$e\f$ by Levi-Civita
/// transport, \f$w_e = \ell_e^2/(A_l + A_r)\f$, \f$\bar A\f$ the mean face area, and \f$q_f\f$
/// the direction of largest curvature of the face's normal-cycle shape operator, to the power
/// \f$N/2\f$ of its double-angle form, with the anisotropy as modulus (normalised to a mean
/// square of 1). The first term is the smoothness of Knöppel et al. 2013 (face-based), the second
/// the alignment of Hertzmann and Zorin 2000 as a soft constraint; one sparse Cholesky
/// factorisation. Then `smoothing_steps` times, the field is diffused again by the same
/// operator, \f$z \leftarrow (L + \lambda M)^{-1} M z\f$ normalised (inverse power iteration:
/// each step moves it towards the smoothest field of the surface, with fewer singularities; the
/// manual tabulates the counts).
/// Its singularities, read back with principal matching, are an automatic prescription for
/// Lai et al.'s pipeline (see automatic_singularities()).
///
/// On an open mesh, `follow_boundary(true)` adds \f$\beta \sum_{f \ni b} \frac{A_f}{\bar A}|z_f - t_f|^2\f$
/// over the faces with a border edge \f$b\f$, \f$t_f\f$ the edge's direction (turned by \f$\pi/2\f$ with
/// `orthogonal_to_boundary(true)`) to the power \f$N\f$, with \f$\beta = 10^3\f$, kept in every
/// smoothing step: the field then follows the boundary, and its interior singularities are those
/// of a field parallel (orthogonal) to it (for \f$N = 1\f$ they sum to \f$\chi\f$).
///
/// \param tm the mesh (its embedding: curvature needs the vertex points)
/// \param N the symmetry order
/// \param angles receives the field's angle per face, counterclockwise from `halfedge(f)`
/// \param np `alignment_weight` (\f$\lambda\f$, default 0.01: smaller is smoother, with fewer
///   singularities), `smoothing_steps` (default 4), `follow_boundary` (`bool`, default `false`),
///   `orthogonal_to_boundary` (`bool`, default `false`), `vertex_point_map` and the index maps
template <typename TriangleMesh, typename FaceAngleMap, typename NamedParameters = parameters::Default_named_parameters>
Curvature_aligned_field_status<TriangleMesh>
curvature_aligned_rosy_field(const TriangleMesh& tm, int N, FaceAngleMap angles,
                             const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Curvature_aligned_field_status<TriangleMesh> st;
  if(N < 1) throw Input_error(Input_error::INVALID_ARGUMENT, "symmetry order N must be at least 1, got " + std::to_string(N));
  const double lambda = choose_parameter(get_parameter(np, internal_np::alignment_weight), 0.01);
  if(!(lambda > 0) || !std::isfinite(lambda))
    throw Input_error(Input_error::INVALID_ARGUMENT, "alignment_weight must be positive and finite");
  const int steps = choose_parameter(get_parameter(np, internal_np::smoothing_steps), 4);
  const bool follow = choose_parameter(get_parameter(np, internal_np::follow_boundary), false);
  const double across = choose_parameter(get_parameter(np, internal_np::orthogonal_to_boundary), false) ? CGAL_PI / 2 : 0.;
  if(steps < 0) throw Input_error(Input_error::INVALID_ARGUMENT, "smoothing_steps must be non-negative");
  st.smoothing_steps = steps;
  st.alignment_weight = lambda;
  const Intrinsic_mesh<TriangleMesh> im = internal::get_intrinsic_mesh(tm, np);
  const internal::Mesh_arrays<TriangleMesh>& m = im.arrays();
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  const std::size_t nf = m.number_of_faces(), ne = m.number_of_edges();
  if(nf == 0) { st.success = true; return st; }
  const std::vector<std::array<double, 2>> w2 = internal::face_shape_anisotropy(m, vpm);
  std::vector<double> area(nf);
  double mean_area = 0, mean_sq = 0;
  for(std::size_t f = 0; f < nf; ++f) {
    const int h0 = m.face_halfedge[f];
    area[f] = triangle_area(m.length[std::size_t(h0 >> 1)], m.length[std::size_t(m.next[std::size_t(h0)] >> 1)],
                            m.length[std::size_t(m.next[std::size_t(m.next[std::size_t(h0)])] >> 1)]);
    mean_area += area[f] / double(nf);
    mean_sq += (w2[f][0] * w2[f][0] + w2[f][1] * w2[f][1]) / double(nf);
  }
  const double qscale = mean_sq > 0 ? 1 / std::sqrt(mean_sq) : 1.;
  // the normal equations as a real symmetric system of size 2F (lower triangle)
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(2 * nf + 8 * ne);
  std::vector<double> diag(2 * nf, 0.);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(Eigen::Index(2 * nf));
  for(std::size_t f = 0; f < nf; ++f) {
    const double a = lambda * area[f] / mean_area;
    diag[2 * f] += a;
    diag[2 * f + 1] += a;
    const double r = std::hypot(w2[f][0], w2[f][1]);
    if(r > 0) {
      const double phi = 0.5 * N * std::atan2(w2[f][1], w2[f][0]);
      rhs[Eigen::Index(2 * f)] = a * r * qscale * std::cos(phi);
      rhs[Eigen::Index(2 * f + 1)] = a * r * qscale * std::sin(phi);
    }
  }
  // the boundary term: the border edges' directions (N-th power) in their faces
  const double beta = 1e3;
  Eigen::VectorXd boundary_rhs = Eigen::VectorXd::Zero(Eigen::Index(2 * nf));
  if(follow)
    for(std::size_t e = 0; e < ne; ++e)
      for(int h : {int(2 * e), int(2 * e + 1)}) {
        if(m.face[std::size_t(h)] < 0 || m.face[std::size_t(h ^ 1)] >= 0) continue;
        const std::size_t f = std::size_t(m.face[std::size_t(h)]);
        const double b = beta * area[f] / mean_area, phi = N * (internal::halfedge_direction(m, h) + across);
        diag[2 * f] += b;
        diag[2 * f + 1] += b;
        boundary_rhs[Eigen::Index(2 * f)] += b * std::cos(phi);
        boundary_rhs[Eigen::Index(2 * f + 1)] += b * std::sin(phi);
      }
  rhs += boundary_rhs;
  for(std::size_t e = 0; e < ne; ++e) {
    const int h = int(2 * e);
    const int l = m.face[std::size_t(h)], r = m.face[std::size_t(h ^ 1)];
    if(l < 0 || r < 0 || l == r) continue;
    const double we = m.length[e] * m.length[e] / (area[std::size_t(l)] + area[std::size_t(r)]);
    const double rho = N * internal::transport_increment(m, h), c = std::cos(rho), s = std::sin(rho);
    diag[2 * std::size_t(l)] += we; diag[2 * std::size_t(l) + 1] += we;
    diag[2 * std::size_t(r)] += we; diag[2 * std::size_t(r) + 1] += we;
    // -w v_l^T R v_r, R = [[c, -s], [s, c]]: entries (l_i, r_j) = -w R_ij
    const int L = 2 * l, Rr = 2 * r;
    const double R[2][2] = {{c, -s}, {s, c}};
    for(int i = 0; i < 2; ++i)
      for(int j = 0; j < 2; ++j) {
        const int row = L + i, col = Rr + j;
        t.emplace_back((std::max)(row, col), (std::min)(row, col), -we * R[i][j]);
      }
  }
  for(std::size_t i = 0; i < 2 * nf; ++i) t.emplace_back(int(i), int(i), diag[i]);
  Cholmod_cholesky::Matrix A(Eigen::Index(2 * nf), Eigen::Index(2 * nf));
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  Cholmod_cholesky chol;
  if(!chol.factor(A, st.message)) return st;
  // smoothing: the same implicit diffusion applied again to the field, normalised (inverse
  // power iteration: towards the smoothest field of the metric); the boundary term stays, on a
  // field scaled to a mean square of 1 per face like its targets
  Eigen::VectorXd z = chol.solve(rhs), mz(z.size());
  for(int k = 0; k < steps && z.allFinite(); ++k) {
    const double n = z.norm();
    const double scale = follow && n > 0 ? lambda * std::sqrt(double(nf)) / n : 1.;
    for(std::size_t f = 0; f < nf; ++f)
      for(int i = 0; i < 2; ++i)
        mz[Eigen::Index(2 * f + std::size_t(i))] = scale * z[Eigen::Index(2 * f + std::size_t(i))] * area[f] / mean_area;
    z = chol.solve(follow ? Eigen::VectorXd(mz + boundary_rhs) : mz);
    const double n2 = z.norm();
    if(n2 > 0) z /= n2;
  }
  if(!z.allFinite()) { st.message = "the field's solve produced non-finite values"; return st; }
  for(std::size_t f = 0; f < nf; ++f) {
    double a = std::atan2(z[Eigen::Index(2 * f + 1)], z[Eigen::Index(2 * f)]) / N;
    if(a < 0) a += 2 * CGAL_PI / N;
    put(angles, m.faces[f], a);
  }
  // the read-back with principal matching
  auto matching = get(CGAL::dynamic_edge_property_t<int>(), tm);
  const auto rnp = parameters::symmetry_order(N).intrinsic_mesh(im);
  st.max_rotation_over_pi_over_N = principal_matching(tm, angles, matching, rnp) / (CGAL_PI / N);
  st.singularities = field_singularities(tm, angles, rnp.matching(matching)).singularities;
  st.success = true;
  return st;
}

/// \ingroup PkgSurfaceMeshDirectionFieldsFieldDesign
/// Automatic singularities for Lai et al.'s pipeline ("the inputs of singularities can be
/// obtained from other fields directly, such as the principal direction fields"): the
/// singularities of curvature_aligned_rosy_field(), read back with its principal matching, as
/// interior vertices with their indices (multiples of \f$1/N\f$; on a closed component they sum
/// to its Euler characteristic, the read-back's own invariant). Named parameters as
/// curvature_aligned_rosy_field(). The status holds the list in `singularities`.
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
Curvature_aligned_field_status<TriangleMesh>
automatic_singularities(const TriangleMesh& tm, int N, const NamedParameters& np = parameters::default_values())
{
  auto angles = get(CGAL::dynamic_face_property_t<double>(), tm);
  return curvature_aligned_rosy_field(tm, N, angles, np);
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_CURVATURE_ALIGNED_FIELD_H
