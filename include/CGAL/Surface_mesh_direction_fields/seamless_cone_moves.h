// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_SEAMLESS_CONE_MOVES_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_SEAMLESS_CONE_MOVES_H

// Cones moved so that a flat cone metric's holonomies start near multiples of 2 pi / N, where
// seamless_cone_metric() can reach them without flips.

#include <CGAL/Surface_mesh_direction_fields/Intrinsic_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/parameters.h>
#include <CGAL/Surface_mesh_direction_fields/internal/holonomy_loops.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// Outcome of move_cones_toward_seamless().
struct Cone_moves_status
{
  std::size_t loops = 0;                ///< handle loops and boundary paths (as seamless_cone_metric())
  int moves = 0;                        ///< cones moved by one step each (a cone may move several times)
  double initial_holonomy_error = 0;    ///< the largest distance of a loop's holonomy to a multiple of \f$2\pi/N\f$
  double predicted_holonomy_error = 0;  ///< the same after the moves, to first order
};

/// \ingroup PkgSurfaceMeshDirectionFieldsRemeshing
/// Moves interior cones so that the holonomies that seamless_cone_metric() must fix start nearer
/// multiples of \f$2\pi/N\f$ (the idea of MovingCones, Li et al. 2023, to first order): where
/// they start more than about 0.3 rad away, the fixed triangulation cannot reach them.
///
/// The flat cone metric of the cones is the conformal one with those curvatures; a loop's
/// holonomy \f$H\f$ is a sum of corner angles, so to first order a curvature target change
/// \f$\delta\hat K\f$ changes it by \f$\varphi^T \delta\hat K\f$, \f$\varphi\f$ the solution of
/// the flow's Jacobian system \f$(\partial K/\partial u)^T \varphi = (\partial H/\partial u)^T\f$
/// (one sparse factorisation, one solve per loop). A cone of curvature \f$k\f$ moved from \f$c\f$ to
/// \f$w\f$ changes it by \f$k(\varphi_w - \varphi_c)\f$. Greedily, the move (within `rings` rings
/// of a cone, to an interior vertex that is neither a cone nor next to one) that lowers the largest
/// error most is made, until the largest error is below `target` or no move lowers it. The caller
/// computes the cones' metric again (the prediction is linear) and may call again.
///
/// \param tm a triangle mesh of one component
/// \param lengths the flat cone metric of `cones` on `tm`
/// \param cones in and out: (vertex, curvature) pairs; boundary cones (corners) stay
/// \param N the symmetry order (4 for quads)
/// \param target stop when every predicted error is below it (radians)
/// \param rings how far a cone may move per step
/// \param max_moves the most moves made
///
/// Throws `Input_error` as `Intrinsic_mesh` does.
template <typename TriangleMesh, typename LengthMap>
Cone_moves_status move_cones_toward_seamless(const TriangleMesh& tm, const LengthMap& lengths,
                                             std::vector<std::pair<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, double>>& cones,
                                             int N = 4, double target = 0.05, int rings = 2, int max_moves = 60)
{
  Cone_moves_status st;
  const Intrinsic_mesh<TriangleMesh> im(tm, parameters::edge_length_map(lengths));
  const internal::Mesh_arrays<TriangleMesh>& m = im.arrays();
  const std::vector<std::vector<internal::Loop_turn>> loops = internal::holonomy_loops(im);
  st.loops = loops.size();
  if(loops.empty()) return st;
  const std::size_t nv = m.number_of_vertices(), nl = loops.size();
  const double period = 2 * CGAL_PI / N;
  auto wrap = [&](double x) { return x - period * std::round(x / period); };
  const std::vector<double>& angle = m.angle;
  std::vector<double> error(nl);
  for(std::size_t i = 0; i < nl; ++i) {
    error[i] = wrap(internal::loop_holonomy(m, angle, loops[i]));
    st.initial_holonomy_error = (std::max)(st.initial_holonomy_error, std::abs(error[i]));
  }
  st.predicted_holonomy_error = st.initial_holonomy_error;
  if(st.initial_holonomy_error <= target) return st;

  // columns: every vertex with an edge but the first (u is defined up to a constant; Gauss-Bonnet
  // fixes the first curvature); lambda_e = lambda0_e + (u_a + u_b) / 2
  int n = 0;
  const std::vector<int> col = m.indices_but_first_vertex(n);
  std::vector<Eigen::Triplet<double>> tj;
  for(std::size_t f = 0; f < m.number_of_faces(); ++f) {
    int c = m.face_halfedge[f];
    for(int i = 0; i < 3; ++i, c = m.next[std::size_t(c)]) {
      const int r = col[std::size_t(m.source(c))];   // K at source(c) loses this corner's angle
      if(r < 0) continue;
      internal::corner_angle_derivative(m, angle, c, -1., [&](int e, double d) {
        for(int b : {m.source(2 * e), m.target[std::size_t(2 * e)]}) if(col[std::size_t(b)] >= 0) tj.emplace_back(r, col[std::size_t(b)], d / 2);
      });
    }
  }
  Eigen::SparseMatrix<double> J(n, n);
  J.setFromTriplets(tj.begin(), tj.end());
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(n, Eigen::Index(nl));   // (dH/du)^T, one column per loop
  for(std::size_t i = 0; i < nl; ++i)
    internal::loop_holonomy_derivative(m, angle, loops[i], [&](int e, double d) {
      for(int b : {m.source(2 * e), m.target[std::size_t(2 * e)]}) if(col[std::size_t(b)] >= 0) G(col[std::size_t(b)], Eigen::Index(i)) += d / 2;
    });
  // dK/du is the cotan Laplacian up to sign: symmetric, definite once the first vertex is fixed
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(Eigen::SparseMatrix<double>(J.transpose()));
  if(ldlt.info() != Eigen::Success) return st;
  const Eigen::MatrixXd phi = ldlt.solve(G);
  if(!phi.allFinite()) return st;
  auto phi_at = [&](std::size_t v, std::size_t i) { return col[v] >= 0 ? phi(col[v], Eigen::Index(i)) : 0.; };

  std::vector<int> cone_at(nv, -1);
  for(std::size_t c = 0; c < cones.size(); ++c) cone_at[std::size_t(m.vertex_index(cones[c].first))] = int(c);
  auto free_for = [&](std::size_t w, std::size_t c) {   // w may take cone c: interior, no other cone at or next to it
    if(m.is_isolated(int(w)) || m.is_boundary_vertex(int(w)) || (cone_at[w] >= 0 && cone_at[w] != int(c))) return false;
    for(int h = m.vertex_out[w], h0 = h;;) {
      const int o = cone_at[std::size_t(m.target[std::size_t(h)])];
      if(o >= 0 && o != int(c)) return false;
      h = m.ccw_out(h);
      if(h == h0) break;
    }
    return true;
  };
  auto worst = [](const std::vector<double>& e) { double x = 0; for(double v : e) x = (std::max)(x, std::abs(v)); return x; };
  std::vector<int> seen(nv, -1);
  for(; st.moves < max_moves && st.predicted_holonomy_error > target; ++st.moves) {
    double best = st.predicted_holonomy_error - 1e-3;
    std::size_t best_cone = cones.size(), best_to = nv;
    std::vector<double> trial(nl);
    for(std::size_t c = 0; c < cones.size(); ++c) {
      const std::size_t v = std::size_t(m.vertex_index(cones[c].first));
      if(m.is_boundary_vertex(int(v))) continue;
      std::vector<std::size_t> ring{v};   // breadth-first within `rings` rings
      seen[v] = int(st.moves * int(cones.size()) + int(c));
      for(int r = 0, begin = 0; r < rings; ++r) {
        const int end = int(ring.size());
        for(int q = begin; q < end; ++q)
          for(int h = m.vertex_out[ring[std::size_t(q)]], h0 = h;;) {
            const std::size_t w = std::size_t(m.target[std::size_t(h)]);
            if(seen[w] != seen[v]) { seen[w] = seen[v]; ring.push_back(w); }
            if(m.face[std::size_t(h)] < 0) break;
            h = m.ccw_out(h);
            if(h == h0) break;
          }
        begin = end;
      }
      for(std::size_t w : ring) {
        if(w == v || !free_for(w, c)) continue;
        for(std::size_t i = 0; i < nl; ++i) trial[i] = wrap(error[i] + cones[c].second * (phi_at(w, i) - phi_at(v, i)));
        const double x = worst(trial);
        if(x < best) { best = x; best_cone = c; best_to = w; }
      }
    }
    if(best_cone == cones.size()) break;
    const std::size_t v = std::size_t(m.vertex_index(cones[best_cone].first));
    for(std::size_t i = 0; i < nl; ++i) error[i] = wrap(error[i] + cones[best_cone].second * (phi_at(best_to, i) - phi_at(v, i)));
    cone_at[v] = -1;
    cone_at[best_to] = int(best_cone);
    cones[best_cone].first = m.vertices[best_to];
    st.predicted_holonomy_error = worst(error);
  }
  std::sort(cones.begin(), cones.end());
  return st;
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_SEAMLESS_CONE_MOVES_H
