// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_CONE_METRIC_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_CONE_METRIC_H

#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/parameters.h>
#include <CGAL/Surface_mesh_direction_fields/intrinsic_triangle.h>
#include <CGAL/Surface_mesh_direction_fields/Intrinsic_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/Intrinsic_triangulation.h>
#include <CGAL/Surface_mesh_direction_fields/internal/cholesky_solver_traits.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh_arrays.h>
#include <CGAL/Surface_mesh_direction_fields/internal/development.h>
#include <CGAL/Surface_mesh_direction_fields/internal/topology.h>
#include <CGAL/Surface_mesh_direction_fields/internal/ricci_flow.h>
#include <CGAL/Surface_mesh_direction_fields/internal/cone_metric_phases.h>
#include <CGAL/Surface_mesh_direction_fields/internal/cone_holes.h>
#include <CGAL/Surface_mesh_direction_fields/internal/circle_packing_flow.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <chrono>
#include <cmath>
#include <map>
#include <deque>
#include <sstream>
#include <limits>
#include <string>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsConeMetrics
/// Outcome of compute_cone_metric().
/// \ingroup PkgSurfaceMeshDirectionFieldsConeMetrics
/// The discrete Ricci flows of compute_cone_metric().
enum Ricci_flow_scheme {
  /// discrete conformal vertex scaling \f$l_{ab} = l^0_{ab} e^{(u_a + u_b)/2}\f$ (Springborn,
  /// Schroeder, Pinkall 2008), with intrinsic Delaunay flips when needed: the default
  VERTEX_SCALING,
  /// inversive distance circle packing \f$l_{ab}^2 = r_a^2 + r_b^2 + 2 r_a r_b I_{ab}\f$,
  /// \f$r_v = r^0_v e^{u_v}\f$, the scheme of Lai et al. 2010 (after Jin, Kim, Luo, Gu 2008); the
  /// inversive distances are chosen so that \f$u = 0\f$ reproduces the input metric
  /// (\f$r^0_v\f$ a third of the shortest edge at \f$v\f$); on the input triangulation only
  /// (no flips)
  INVERSIVE_DISTANCE_CIRCLE_PACKING
};

struct Cone_metric_status
{
  bool converged = false;          ///< `true` if the maximum curvature error is at most the tolerance
  int iterations = 0;              ///< Newton iterations performed
  double max_curvature_error = 0;  ///< \f$\max_v |K_v - \bar K_v|\f$ of the output metric (radians)
  /// \f$\max_v \rho_v\f$, the largest rounding level of an angle sum of the output metric (see
  /// `curvature_tolerance` in compute_cone_metric()): about \f$10^{-14}\f$ on ordinary meshes,
  /// larger next to needle triangles
  double rounding_level = 0;
  std::string message;             ///< why it did not converge; empty on success
  double seconds = 0;              ///< wall-clock time of the call
  /// `true` if the metric lives on an intrinsic triangulation that differs from the input's
  /// (see `intrinsic_triangulation`); `false` if it is a metric on the input mesh's edges
  bool triangulation_changed = false;
  std::size_t edge_flips = 0;      ///< number of intrinsic edge flips performed
  /// the triangulation carrying the metric when `triangulation_changed`, empty otherwise
  Intrinsic_triangulation intrinsic_triangulation;
  /// empty, or why `intrinsic_triangulation` has no common subdivision with the input although
  /// edges were flipped (its own consistency checks failed; the metric is sound)
  std::string correspondence_message;
  /// interior vertices with a target curvature \f$\ge 2\pi\f$ (cones of index \f$\ge 1\f$) at which a
  /// hole was punched, in vertex order
  std::vector<std::size_t> punched_vertices;
};

namespace internal {
struct No_cone_metric_visitor { void operator()(int, double) const {} };
} // namespace internal

/// \ingroup PkgSurfaceMeshDirectionFieldsConeMetrics
/// Computes a flat cone metric: edge lengths whose discrete curvature equals the prescribed
/// target at every vertex, conformally equivalent to the input metric.
///
/// <b>Scheme.</b> Discrete conformal vertex scaling, the Yamabe member of the unified discrete
/// Ricci flow family (Luo 2004; Springborn, Schröder, Pinkall 2008; Zhang, Guo, Zeng, Luo,
/// Yau, Gu 2014): \f$\ell_{ij}(u) = \ell^0_{ij}\, e^{(u_i + u_j)/2}\f$ with one conformal factor
/// \f$u_i\f$ per vertex. It reproduces the input metric exactly at \f$u = 0\f$, whereas
/// Thurston's circle packing metric used by Lai et al. (2010, section 4.1.1, after Jin et al.
/// 2008) only approximates it. The curvature \f$K(u)\f$ is the gradient of a convex energy whose
/// Hessian \f$\partial K_i/\partial u_j\f$ is the cotangent Laplacian of the current metric
/// (\f$-\frac12(\cot\alpha_{ij} + \cot\beta_{ij})\f$ off the diagonal, rows summing to zero),
/// positive semi-definite with the constants of each connected component as kernel. The target
/// is reached by Newton's method: one \f$u\f$ per component is fixed, the reduced Hessian is
/// factored by CHOLMOD (symbolic analysis done once, the triangulation is fixed), and a
/// backtracking line search accepts a step only if every triangle stays valid (strict triangle
/// inequalities) and \f$\|K - \bar K\|_2\f$ decreases. At the end \f$u\f$ is shifted on each
/// component so that its total area equals the input's.
///
/// <b>Intrinsic edge flips.</b> Newton's method first runs on the input triangulation (unless
/// `input_triangulation_first` is `false`). Some targets have no solution there (cones far from
/// where the input's curvature is, needle triangles): the line search then keeps shortening
/// steps to keep triangles valid. In that case,
/// unless `intrinsic_edge_flips` is `false`, the flow continues on an intrinsic Delaunay
/// triangulation (Gillespie, Springborn, Crane 2021): the input lengths become Penner
/// coordinates, and before every evaluation edges are flipped with the Ptolemy relation
/// \f$\ell_{cd}\,\ell_{ab} = \ell_{ad}\,\ell_{bc} + \ell_{db}\,\ell_{ca}\f$ until the triangulation is
/// Delaunay for the current metric. Delaunay triangulations always satisfy the triangle
/// inequalities and the flow then has a solution for every target that satisfies Gauss–Bonnet
/// (the Hessian is the cotan Laplacian of the Delaunay triangulation, with non-negative weights).
/// If the final triangulation differs from the input, `triangulation_changed` is set, the
/// status holds the `Intrinsic_triangulation` with its lengths and its correspondence to the
/// input edges, `output_lengths` receives the lengths of the input edges that are still edges
/// and a quiet NaN for the others, and the conformal factors are those of the whole flow.
///
/// If no solution is found (flips disabled, or the tolerance is not reached within the
/// iteration budget), the status says so (`converged == false` and a message), and
/// `output_lengths` holds the last valid iterate, which is a valid metric but not the requested
/// one.
///
/// Targets: the angle defect \f$\bar K_v = 2\pi - \sum\theta\f$ at interior vertices (cones
/// have \f$\bar K_v \neq 0\f$, \f$2\pi\f$ times the index of a field singularity; all others 0)
/// and the geodesic curvature \f$\bar\kappa_v = \pi - \sum\theta\f$ at boundary vertices
/// (\f$\pi/2\f$ at the corners of a rectangle, 0 along straight sides).
///
/// <b>Cones of index \f$\geq 1\f$.</b> An interior target \f$\bar K_v \geq 2\pi\f$ has no positive
/// angle sum at a single vertex. As Lai et al. (2010, section 4.1.1), a hole is punched there:
/// the faces around \f$v\f$ are removed, and each of the \f$d\f$ vertices \f$w\f$ of its ring
/// becomes a boundary vertex with target geodesic curvature
/// \f$\bar\kappa_w = \bar K_w + (\bar K_v - 2\pi)/d\f$, so that the index of the hole is
/// \f$\sum_w \bar\kappa_w / 2\pi + 1 = \bar K_v / 2\pi\f$ (for \f$\bar K_w = 0\f$). The metric
/// is computed on the holed surface; `output_lengths` is a quiet NaN on the edges inside the
/// holes, the conformal factor of \f$v\f$ is NaN, the status lists the punched vertices, and
/// its curvature error is measured on the holed surface (at the ring: geodesic curvature).
///
/// Throws `Input_error` if the mesh is invalid (see `compute_vertex_curvatures()`), if a target
/// is not finite, if a cone of index \f$\geq 1\f$ has a neighbour on the boundary or in the ring
/// of another such cone, or its ring would need \f$\bar\kappa_w \geq \pi\f$, if a boundary target
/// is \f$\geq \pi\f$, or (kind `INCONSISTENT_INDICES`) if on a connected component the targets
/// do not sum to \f$2\pi\chi\f$ (Gauss–Bonnet) within \f$10^{-8}\max(1, 2\pi|\chi|)\f$.
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
/// \tparam VertexCurvatureMap a readable property map, `vertex_descriptor` keys, `double` values
/// \tparam OutputEdgeLengthMap a writable property map, `edge_descriptor` keys, `double` values
///
/// \param tm the mesh
/// \param target_curvature the target \f$\bar K_v\f$ / \f$\bar\kappa_v\f$ of every vertex
/// \param output_lengths receives the length of every edge (also when not converged)
/// \param np optional named parameters:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{edge_length_map}
///     \cgalParamDescription{the input metric \f$\ell^0\f$}
///     \cgalParamType{a readable property map with `edge_descriptor` keys and `double` values}
///     \cgalParamDefault{Euclidean lengths from `vertex_point_map`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{vertex positions, used only when no `edge_length_map` is given}
///     \cgalParamType{a readable property map with `vertex_descriptor` keys and 3D point values}
///     \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{conformal_factor_map}
///     \cgalParamDescription{receives \f$u_v\f$, so that the output length of edge \f$ij\f$ is \f$\ell^0_{ij} e^{(u_i+u_j)/2}\f$}
///     \cgalParamType{a writable property map with `vertex_descriptor` keys and `double` values}
///     \cgalParamDefault{not written}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{maximum number of Newton iterations}
///     \cgalParamType{`int`}
///     \cgalParamDefault{200}
///   \cgalParamNEnd
///   \cgalParamNBegin{curvature_tolerance}
///     \cgalParamDescription{convergence threshold: the flow stops when
///       \f$|K_v - \bar K_v| \le \mathrm{tol}\cdot\max(1, \bar\Theta_v / 2\pi) + \rho_v\f$ at every
///       vertex, where \f$\bar\Theta_v\f$ is the target angle sum (\f$2\pi - \bar K_v\f$ inside,
///       \f$\pi - \bar\kappa_v\f$ on the boundary) and \f$\rho_v\f$ the rounding level of the angle
///       sum: radians, independent of the mesh's scale, relative for cones whose angle exceeds
///       \f$2\pi\f$ (the rounding error of an angle sum grows with it). \f$\rho_v\f$ bounds, to first
///       order, how much the angle sum at \f$v\f$ moves when the lengths of its triangles move
///       by their rounding, \f$2^{-53}(4 + \max|u|)\f$ relative (a length is a double computed from
///       conformal factors that are doubles): \f$\rho_v = 2^{-53}\sum_{t \ni v}(4 + \max_{t}|u|)
///       \,\ell_{\mathrm{opp}}P_t / 2A_t\f$ over the triangles \f$t\f$ at \f$v\f$, with the side
///       \f$\ell_{\mathrm{opp}}\f$ opposite \f$v\f$, perimeter \f$P_t\f$ and area \f$A_t\f$. It is
///       about \f$10^{-14}\f$ on ordinary meshes and matters only next to needle triangles, whose
///       angles at the short side depend on the difference of the two long sides (a cone of
///       \f$-528\pi\f$ on a genus-133 mesh makes triangles with sides \f$3.8\cdot10^{-5}\f$ and
///       \f$4.5\cdot10^{-11}\f$ and \f$\rho_v \approx 10^{-8}\f$): no metric in double precision is
///       more accurate there. The status reports \f$\max_v\rho_v\f$.}
///     \cgalParamType{`double`, positive}
///     \cgalParamDefault{`1e-10`}
///   \cgalParamNEnd
///   \cgalParamNBegin{common_subdivision}
///     \cgalParamDescription{with flips, whether the intrinsic triangulation comes with its
///       common subdivision with the input (`Intrinsic_triangulation::has_common_subdivision()`):
///       the correspondence that fields and pictures need on the input. Callers that use only
///       the conformal factors (e.g. polycube metrics) save its cost (about a third of the flow's
///       time when many edges are flipped)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{intrinsic_edge_flips}
///     \cgalParamDescription{whether the flow may continue on an intrinsic Delaunay triangulation
///       when the input triangulation cannot carry the target metric}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{input_triangulation_first}
///     \cgalParamDescription{whether Newton's method starts on the input triangulation (`true`) or
///       on the intrinsic Delaunay triangulation of the input lengths (`false`). Starting there
///       skips the attempt on the input, which costs a factorisation and a line search when it is
///       abandoned (the decimated armadillo with 8 cones, 433k faces: 1.9 s of 4.9 s); the result
///       then lives on the intrinsic triangulation whenever the input is not Delaunay, even if
///       the input could have carried it, and the conformal factors differ. Where the input
///       carries the metric its factors served the paths of box_polycube_metric() better
///       (`smdf remesh --polycube box` at 1k-8k quads: Homer and the armadillo 5 inverted quads
///       in 8 remeshes against 21, mean scaled Jacobian 0.90 against 0.88 on Homer), so `smdf`
///       keeps the default. Ignored when `intrinsic_edge_flips` is `false` or with
///       `INVERSIVE_DISTANCE_CIRCLE_PACKING`.}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{ricci_flow_scheme}
///     \cgalParamDescription{the discrete Ricci flow; with `INVERSIVE_DISTANCE_CIRCLE_PACKING` the
///       triangulation is never flipped, the conformal factors are \f$u_v = \log(r_v / r^0_v)\f$ and
///       the area is not normalised (see \ref SMDFSecCirclePacking)}
///     \cgalParamType{`Ricci_flow_scheme`}
///     \cgalParamDefault{`VERTEX_SCALING`}
///   \cgalParamNEnd
///   \cgalParamNBegin{sparse_linear_solver}
///     \cgalParamDescription{the solver of the Newton systems (copied)}
///     \cgalParamType{a model of `SparseCholeskySolver`, or CGAL's `Eigen_solver_traits` of a direct symmetric solver}
///     \cgalParamDefault{`Cholmod_cholesky`}
///   \cgalParamNEnd
///   \cgalParamNBegin{intrinsic_mesh}
///     \cgalParamDescription{the input metric as an `Intrinsic_mesh` of `tm` built before, instead of building one; replaces `edge_length_map`, `vertex_point_map` and the index maps}
///     \cgalParamType{`Intrinsic_mesh<TriangleMesh>`}
///     \cgalParamDefault{one built from `tm` and the other parameters}
///   \cgalParamNEnd
///   \cgalParamNBegin{visitor}
///     \cgalParamDescription{progress callback, called as `visitor(iteration, max_error)` once with
///       iteration 0 for the input metric and after every Newton iteration; `max_error` is the
///       current \f$\max_v |K_v - \bar K_v|\f$}
///     \cgalParamType{a model of `ConeMetricVisitor`: a callable with signature `void(int, double)`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename TriangleMesh, typename VertexCurvatureMap, typename OutputEdgeLengthMap,
          typename NamedParameters = parameters::Default_named_parameters>
Cone_metric_status compute_cone_metric(const TriangleMesh& tm,
                                       VertexCurvatureMap target_curvature,
                                       OutputEdgeLengthMap output_lengths,
                                       const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto t0 = std::chrono::steady_clock::now();

  const int max_iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 200);
  const double tol = choose_parameter(get_parameter(np, internal_np::curvature_tolerance), 1e-10);
  if(!(tol > 0) || !std::isfinite(tol))
    throw Input_error(Input_error::INVALID_ARGUMENT, "curvature_tolerance must be positive and finite");
  if(max_iterations < 0)
    throw Input_error(Input_error::INVALID_ARGUMENT, "number_of_iterations must be non-negative");
  auto visitor = choose_parameter(get_parameter(np, CGAL::internal_np::visitor),
                                  internal::No_cone_metric_visitor());
  const bool allow_flips = choose_parameter(get_parameter(np, internal_np::intrinsic_edge_flips), true);
  const bool input_first = choose_parameter(get_parameter(np, internal_np::input_triangulation_first), true);
  const bool with_subdivision = choose_parameter(get_parameter(np, internal_np::common_subdivision), true);
  const Ricci_flow_scheme scheme = choose_parameter(get_parameter(np, internal_np::ricci_flow_scheme), VERTEX_SCALING);

  const Intrinsic_mesh<TriangleMesh> im = internal::get_intrinsic_mesh(tm, np);
  const internal::Mesh_arrays<TriangleMesh>& m = im.arrays();
  const internal::Topology_arrays& topo = im.topology_arrays();
  const std::size_t nv = m.number_of_vertices();
  typedef typename internal::Get_cholesky_solver<NamedParameters>::type Solver;
  const Solver solver = internal::make_cholesky_solver<Solver>(np);

  // --- 1. the targets: finite, boundary ones below pi, Gauss-Bonnet on every component
  std::vector<double> target;
  std::vector<int> punched;   // interior vertices with a target >= 2 pi
  internal::read_target_curvatures(m, target_curvature, target, punched);
  internal::check_gauss_bonnet(m, topo, target);

  // --- 2. cones of index >= 1 (Lai et al. 2010, section 4.1.1): a hole at each, and the
  // holed surface solved by this function (see internal/cone_holes.h)
  if(!punched.empty()) {
    internal::Holed_surface holed(m, target, punched);
    Cone_metric_status st = compute_cone_metric(
        holed.mesh, holed.target, holed.output_length,
        parameters::edge_length_map(holed.input_length).conformal_factor_map(holed.u)
            .number_of_iterations(max_iterations).curvature_tolerance(tol).visitor(visitor)
            .intrinsic_edge_flips(allow_flips).input_triangulation_first(input_first)
            .sparse_linear_solver(solver).ricci_flow_scheme(scheme));
    holed.map_back(m, output_lengths, np);
    st.punched_vertices.assign(punched.begin(), punched.end());
    st.seconds = internal::seconds_since(t0);
    return st;
  }

  // --- 3'. the circle packing flow of Lai et al., on the input triangulation
  if(scheme == INVERSIVE_DISTANCE_CIRCLE_PACKING) {
    internal::Circle_packing_flow<TriangleMesh, Solver> flow(m, topo, solver);
    std::vector<double> u(nv, 0.), len;
    internal::Vertex_scaling_result r = flow.run(target, u, len, max_iterations, tol, visitor);
    Cone_metric_status st;
    internal::put_input_edge_lengths(m, len, output_lengths);
    internal::put_conformal_factors(m, np, [&u](std::size_t v) { return u[v]; });
    internal::put_flow_outcome(r, st);
    st.seconds = internal::seconds_since(t0);
    return st;
  }

  // --- 3. Newton, first on the input triangulation, then (if needed) with intrinsic flips
  typedef internal::Vertex_scaling_flow<TriangleMesh, Solver> Flow;
  Flow flow(m, topo, solver);
  std::vector<double> u(nv, 0.), len;
  internal::Vertex_scaling_result r =
      internal::run_vertex_scaling(flow, target, u, len, max_iterations, tol, visitor, allow_flips, input_first);

  // --- 4. area normalisation per component: shift u so that the total area is preserved
  internal::normalise_areas(m, topo, flow, target, tol, u, len, r);

  // --- 5. output: lengths of the input edges, or the intrinsic triangulation and its
  // correspondence to the input; conformal factors; status
  Cone_metric_status st;
  st.triangulation_changed = flow.triangulation_changed();
  if(!st.triangulation_changed)
    internal::put_input_edge_lengths(m, len, output_lengths);
  else
    internal::output_intrinsic_triangulation(m, flow, u, len, target, tol, output_lengths, st.intrinsic_triangulation,
                                             st.correspondence_message, with_subdivision);
  internal::put_conformal_factors(m, np, [&u](std::size_t v) { return u[v]; });
  internal::put_flow_outcome(r, st);
  st.seconds = internal::seconds_since(t0);
  return st;
}

/// \ingroup PkgSurfaceMeshDirectionFieldsConeMetrics
/// The intrinsic Delaunay triangulation of the discrete conformal metric
/// \f$\ell_{ij} = \ell^0_{ij} e^{(u_i + u_j)/2}\f$ of given conformal factors (e.g. those
/// compute_cone_metric() wrote to its `conformal_factor_map`, saved and read back), made from the
/// input by Ptolemy flips, with its common subdivision with the input: the same triangulation
/// compute_cone_metric() returns for these factors, rebuilt without the flow. When no flip is
/// needed it is the input triangulation (its common subdivision: one piece per face).
///
/// \param tm the input mesh
/// \param conformal_factors a readable vertex property map: \f$u_v\f$ (finite)
/// \param np the input metric (`edge_length_map` or `vertex_point_map`) and the index maps;
///   `intrinsic_edge_flips(false)` keeps the input triangulation (the metric compute_cone_metric()
///   found on it without flips need not be Delaunay)
///
/// Throws `Input_error` for a non-finite factor, a face that violates the triangle inequality
/// without flips, or a triangulation whose correspondence fails its
/// own checks (the message says why).
template <typename TriangleMesh, typename VertexFactorMap, typename NamedParameters = parameters::Default_named_parameters>
Intrinsic_triangulation conformal_intrinsic_triangulation(const TriangleMesh& tm, const VertexFactorMap& conformal_factors,
                                                          const NamedParameters& np = parameters::default_values())
{
  const Intrinsic_mesh<TriangleMesh> im = internal::get_intrinsic_mesh(tm, np);
  const internal::Mesh_arrays<TriangleMesh>& m = im.arrays();
  std::vector<double> u(m.number_of_vertices(), 0.);
  for(std::size_t v = 0; v < u.size(); ++v) {
    u[v] = double(get(conformal_factors, m.vertices[v]));
    if(!std::isfinite(u[v]))
      throw Input_error(Input_error::INVALID_GEOMETRY, "conformal factor of vertex " + std::to_string(v) + " is not finite");
  }
  internal::Tracked_delaunay_flips<TriangleMesh> tf(m);
  std::vector<double> len;
  if(parameters::choose_parameter(parameters::get_parameter(np, internal_np::intrinsic_edge_flips), true)) {
    try {
      len = tf.make_delaunay(u);
    } catch(const std::runtime_error& e) {
      throw Input_error(Input_error::INVALID_ARGUMENT, e.what());
    }
  } else {
    len.resize(m.number_of_edges());
    for(std::size_t e = 0; e < len.size(); ++e) len[e] = m.length[e] * std::exp(0.5 * (u[std::size_t(m.target[2 * e])] + u[std::size_t(m.target[2 * e + 1])]));
    for(std::size_t f = 0; f < m.number_of_faces(); ++f) {
      const int h0 = m.face_halfedge[f], h1 = m.next[std::size_t(h0)], h2 = m.next[std::size_t(h1)];
      const double a = len[std::size_t(h0 >> 1)], b = len[std::size_t(h1 >> 1)], c = len[std::size_t(h2 >> 1)];
      if(!(a < b + c && b < c + a && c < a + b))
        throw Input_error(Input_error::DEGENERATE_FACE, "conformal_intrinsic_triangulation(): face " + std::to_string(f) +
                                                            " violates the triangle inequality under these factors without flips");
    }
  }
  std::vector<long> input_edge(tf.coincident.begin(), tf.coincident.end());
  Intrinsic_triangulation it(m.number_of_vertices(), tf.tri.next, tf.tri.target, tf.tri.face, tf.tri.face_halfedge, len,
                             std::move(input_edge));
  try {
    internal::build_common_subdivision(m, tf, u, len, it);
  } catch(const std::runtime_error& e) {
    throw Input_error(Input_error::INVALID_ARGUMENT, e.what());
  }
  return it;
}

/// \ingroup PkgSurfaceMeshDirectionFieldsConeMetrics
/// Lays out a topological disk with a flat metric in the plane: the faces are unfolded one
/// after the other in breadth-first order from the first face (`unfold_vertex()`), which is
/// placed with `source(halfedge(f))` at the origin and `target(halfedge(f))` on the positive
/// x axis. Every triangle is laid out counterclockwise; the layout may overlap itself globally
/// when the boundary winds (large geodesic curvature). Typical use: the output of
/// compute_cone_metric() with \f$\bar K = 0\f$ inside and the boundary curvature of a polygon.
///
/// Returns `true` if every laid-out triangle has positive signed area (the layout is locally
/// injective), `false` otherwise (rounding on nearly degenerate triangles).
/// Throws `Input_error` if the mesh is not a single connected component with exactly one
/// boundary loop and genus 0, or if the metric is not flat: an interior vertex with
/// \f$|K_v|\f$ above `curvature_tolerance`.
///
/// \tparam VertexUVMap a writable property map with `vertex_descriptor` keys and values
///   constructible from two `double` (e.g. `Point_2`)
/// \param tm the mesh
/// \param lengths readable edge map: the flat metric
/// \param uv receives the planar position of every vertex
/// \param np optional named parameters:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{curvature_tolerance}
///     \cgalParamDescription{maximum \f$|K_v|\f$ at interior vertices accepted as flat}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`1e-8`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename TriangleMesh, typename EdgeLengthMap, typename VertexUVMap,
          typename NamedParameters = parameters::Default_named_parameters>
bool lay_out_disk(const TriangleMesh& tm, EdgeLengthMap lengths, VertexUVMap uv,
                  const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename boost::property_traits<VertexUVMap>::value_type UV;
  const double tol = choose_parameter(get_parameter(np, internal_np::curvature_tolerance), 1e-8);

  internal::Mesh_arrays<TriangleMesh> m(tm, parameters::edge_length_map(lengths));
  internal::Topology_arrays topo(m);
  if(topo.components.size() != 1 || topo.components[0].boundary_loops != 1 ||
     topo.components[0].genus() != 0 || topo.isolated_vertices != 0) {
    std::ostringstream os;
    os << "lay_out_disk() needs one connected disk without isolated vertices; the mesh has "
       << topo.components.size() << " component(s), "
       << (topo.components.empty() ? 0 : topo.components[0].boundary_loops)
       << " boundary loop(s) in the first, genus "
       << (topo.components.empty() ? 0 : topo.components[0].genus());
    throw Input_error(Input_error::INVALID_ARGUMENT, os.str());
  }
  std::vector<double> k;
  internal::vertex_curvatures(m, k);
  for(std::size_t v = 0; v < k.size(); ++v)
    if(!m.is_boundary_vertex(int(v)) && std::abs(k[v]) > tol) {
      std::ostringstream os;
      os << "lay_out_disk(): the metric is not flat: interior vertex " << v
         << " has angle defect " << k[v];
      throw Input_error(Input_error::INVALID_ARGUMENT, os.str());
    }

  const std::size_t nf = m.number_of_faces();
  std::vector<Point_2> pos(m.number_of_vertices());
  std::vector<char> placed(m.number_of_vertices(), 0), done(nf, 0);
  {
    const int h0 = m.face_halfedge[0], h1 = m.next[h0];
    const std::array<Point_2, 3> p = internal::canonical_layout(m, 0);
    const int vs[3] = {m.source(h0), m.target[h0], m.target[h1]};
    for(int i = 0; i < 3; ++i) { pos[vs[i]] = p[i]; placed[vs[i]] = 1; }
  }
  std::deque<int> queue(1, 0);
  done[0] = 1;
  while(!queue.empty()) {
    const int f = queue.front();
    queue.pop_front();
    int h = m.face_halfedge[f];
    for(int i = 0; i < 3; ++i, h = m.next[h]) {
      const int o = h ^ 1, g = m.face[o];
      if(g < 0 || done[g]) continue;
      done[g] = 1;
      queue.push_back(g);
      const int r = m.target[m.next[o]];
      if(placed[r]) continue;
      // o runs from target(h) to source(h); the third vertex lies to the left of o
      const int p = m.source(o), q = m.target[o];
      pos[r] = unfold_vertex(pos[p], pos[q], m.edge_length(o), m.edge_length(m.next[o]),
                             m.edge_length(m.prev(o)));
      placed[r] = 1;
    }
  }
  bool ok = true;
  for(std::size_t f = 0; f < nf; ++f) {
    const int h0 = m.face_halfedge[f], h1 = m.next[h0];
    const Point_2& a = pos[m.source(h0)];
    const Point_2& b = pos[m.target[h0]];
    const Point_2& c = pos[m.target[h1]];
    const double area2 = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
    if(!(area2 > 0)) ok = false;
  }
  for(std::size_t v = 0; v < pos.size(); ++v) put(uv, m.vertices[v], UV(pos[v].x(), pos[v].y()));
  return ok;
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_CONE_METRIC_H
