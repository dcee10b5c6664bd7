// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_TRIVIAL_CONNECTION_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_TRIVIAL_CONNECTION_H

// (One concern, over 600 lines: the class and its solve, two thirds of it documentation; the
// rotation limiting and the smoothest-turning search are steps of that solve on the same
// factored system; the system, the guide solver, the field propagation and the lattice search
// are in internal/.)

#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/parameters.h>
#include <CGAL/Surface_mesh_direction_fields/homology_generators.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh_arrays.h>
#include <CGAL/Surface_mesh_direction_fields/internal/development.h>
#include <CGAL/Surface_mesh_direction_fields/internal/topology.h>
#include <CGAL/Surface_mesh_direction_fields/internal/tree_cotree.h>
#include <CGAL/Surface_mesh_direction_fields/Intrinsic_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/Cholmod_cholesky.h>
#include <CGAL/Surface_mesh_direction_fields/internal/cholesky_solver_traits.h>
#include <CGAL/Surface_mesh_direction_fields/internal/connection_system.h>
#include <CGAL/Surface_mesh_direction_fields/internal/field_propagation.h>
#include <CGAL/Surface_mesh_direction_fields/internal/guide_solver.h>
#include <CGAL/Surface_mesh_direction_fields/internal/lattice_minimum.h>
#include <CGAL/Surface_mesh_direction_fields/internal/rotation_minimax.h>
#include <CGAL/Surface_mesh_direction_fields/internal/sparse_solvers.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Kernel_traits.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <future>
#include <map>
#include <numeric>
#include <sstream>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsTrivialConnections
/// Weights of the objective \f$\|D x\|^2 = \sum_e x_e^2 / w_e\f$ of the trivial-connection solve.
enum Connection_weights {
  /// \f$w_e = \frac{1}{2}(\cot\alpha_e + \cot\beta_e)\f$ (Crane et al., section 2.5), computed from
  /// the edge lengths; weights below `cotangent_clamp` times the mean positive weight are
  /// raised to that floor.
  COTAN_WEIGHTS,
  /// \f$w_e = 1\f$ (\f$D = I\f$): the default. Over the shared test meshes it kept the largest
  /// rotation per edge lowest and most often below \f$\pi/N\f$, so that principal matching reads
  /// the prescribed singularities (79.5% of the solves against 52.7% with cotan weights).
  UNIT_WEIGHTS,
  /// cotan weights with each cotangent clamped at 0 before the sum (Crane et al., section 4.2),
  /// then raised to `cotangent_clamp` times their mean where smaller.
  NONNEGATIVE_COTAN_WEIGHTS,
  /// cotan weights kept between `cotangent_clamp` and `cotangent_cap` times their mean positive
  /// value: large weights (edges whose dual is long, around needles and caps) no longer let the
  /// minimum-norm solution put large rotations on them.
  BOUNDED_COTAN_WEIGHTS
};

/// \ingroup PkgSurfaceMeshDirectionFieldsTrivialConnections
/// Linear solver of the trivial-connection problem.
enum Connection_solver {
  /// Production path: CHOLMOD Cholesky factorisation of \f$A W A^\top\f$, kept for edits.
  CHOLMOD_NORMAL_EQUATIONS,
  /// Reference path: SuiteSparseQR minimum-norm solution of \f$(A W^{1/2})\,y = -b\f$ at every
  /// solve (slow; for validation).
  SPQR_MINIMUM_NORM
};

/// \ingroup PkgSurfaceMeshDirectionFieldsTrivialConnections
/// Outcome of `Trivial_connection::solve()`.
struct Trivial_connection_status
{
  /// `true` if the factorisation and the solve succeeded, `scaled_residual` is at most
  /// \f$10^{-9}\f$ and `max_holonomy_error` at most \f$10^{-9}\f$: the holonomy around every
  /// dual cell and generator is then its target, so the field of the connection read with its
  /// own matching (`field_matching()`) has exactly the prescribed singularities. Otherwise
  /// `false`, with the reason in `message`.
  bool success = false;
  std::string message;           ///< empty on success
  double energy = 0;             ///< \f$\|Dx\|^2 = \sum_e x_e^2/w_e\f$
  double residual = 0;           ///< \f$\max_i |(Ax + b)_i|\f$ over all constraint rows
  double scaled_residual = 0;    ///< `residual` \f$/ \max(1, \|b\|_\infty)\f$
  double guide_energy = 0;       ///< \f$\lambda\sum_i (c_i^\top x - \bar c_i)^2\f$ of the guide directions (0 without guides)
  double max_holonomy_error = 0; ///< max over all interior-vertex cycles and generators of the distance between the connection's holonomy and \f$2\pi\f$ times the prescribed index / turning number
  double factor_seconds = 0;     ///< time spent building and factoring the system in this call (0 when reused)
  double solve_seconds = 0;      ///< time of the solve in this call
  /// the largest rotation of the connection against Levi-Civita across one edge,
  /// \f$\max_e |x_e|\f$. Below \f$\pi/N\f$ a reader that matches the field by principal
  /// matching (the rotation in \f$(-\pi/N, \pi/N]\f$) finds the prescribed singularities too;
  /// beyond \f$\pi\f$ the field spins by more than half a turn across one edge.
  double max_rotation = 0;
  std::size_t edges_beyond_half_period = 0; ///< number of edges with \f$|x_e| > \pi/N\f$
  std::size_t edges_beyond_pi = 0;          ///< number of edges with \f$|x_e| > \pi\f$
  /// an estimate of the condition number of \f$A W A^\top\f$ (ratio of its extreme eigenvalues,
  /// by a few power and inverse iterations, computed once per factorisation), reported when
  /// `max_holonomy_error` exceeds \f$10^{-12}\f$; 0 otherwise
  double condition_estimate = 0;
  /// rounds of rotation limiting in this solve (see the `rotation_limit` parameter): 0 when the
  /// minimum-norm connection was within the limit
  int rotation_limit_rounds = 0;
  /// when the reweighting rounds of rotation limiting leave an edge beyond \f$\pi\f$: a lower
  /// bound, proven by a dual cycle whose mean rotation it is, on \f$\max_e |x_e|\f$ over every
  /// connection with these indices and turning numbers (0 when not computed or no cycle was
  /// needed to decide)
  double rotation_lower_bound = 0;
  /// with smoothest turning numbers, when no connection with them stays below \f$\pi\f$ and
  /// the search over turning numbers meets a dual cycle that winds around no generator: its mean
  /// rotation, more than \f$\pi\f$, a lower bound on \f$\max_e |x_e|\f$ over every
  /// connection with these indices, whatever the turning numbers (0 otherwise)
  double rotation_bound_any_turning = 0;
  /// with smoothest turning numbers: the number of generators whose turning number the search
  /// for a connection below \f$\pi\f$ moved away from the smoothest ones (0 when not needed
  /// or not successful)
  std::size_t generators_turned_for_rotation = 0;
  /// the weight \f$\lambda\f$ with which the connection of lowest largest rotation was blended
  /// into the reweighted one, \f$(1 - \lambda) x + \lambda x_\infty\f$, to bring every edge
  /// within the limit, or below \f$\pi\f$, or when no connection can, within
  /// `rotation_lower_bound` (up to the bisection's relative width \f$10^{-3}\f$); 0 when not used
  double minimax_blend = 0;
};

/// \ingroup PkgSurfaceMeshDirectionFieldsTrivialConnections
/// Outcome of `Trivial_connection::choose_smoothest_generator_turning_numbers()`.
struct Smoothest_turning_numbers
{
  std::vector<double> turning_numbers;   ///< the chosen turning number of every generator
  double energy = 0;                     ///< \f$\|Dx\|^2\f$ with them (from the quadratic form)
  double energy_with_zero_turning = 0;   ///< \f$\|Dx\|^2\f$ with all turning numbers 0
  std::size_t generators = 0;            ///< number of generators \f$2g + b - 1\f$
  bool exact = false;                    ///< `true`: the global minimum over the lattice
};

/// \ingroup PkgSurfaceMeshDirectionFieldsTrivialConnections
/// Trivial connections with prescribed singularities (Crane, Desbrun, Schröder 2010), with a
/// factorisation kept for real-time editing.
///
/// The unknown is one adjustment angle \f$x_e\f$ per interior edge. Carrying a direction across
/// the edge of halfedge `h`, from `face(opposite(h))` into `face(h)`, changes its angle in the
/// face frames by the Levi-Civita increment plus \f$\sigma_h x_e\f$, where \f$\sigma_h = +1\f$
/// if `h == halfedge(edge(h))` and \f$-1\f$ otherwise (see `Intrinsic_holonomy` for the frames).
/// The holonomy of the connection around a dual cycle \f$c\f$ is therefore
/// \f$\mathrm{hol}_{LC}(c) + (Ax)_c\f$. The constraints \f$Ax = -b\f$ make it equal to
/// \f$2\pi k_v\f$ around the dual cell of every interior vertex \f$v\f$, where
/// \f$\mathrm{hol}_{LC}\f$ is the angle defect \f$K_v\f$ and \f$k_v\f$ the prescribed index, and
/// \f$2\pi t_g\f$ around every generator \f$g\f$ of `tree_cotree_generators()`, where
/// \f$\mathrm{hol}_{LC}\f$ is taken in \f$(-\pi, \pi]\f$ and \f$t_g\f$ is the prescribed turning
/// number (default 0). Among all solutions the one closest to Levi-Civita,
/// \f$\min \|Dx\|^2\f$, is returned: \f$x = W A^\top y\f$ with \f$(A W A^\top)\,y = -b\f$;
/// by default, when that solution turns some edge by more than \f$0.8\pi\f$, rotation limiting
/// reweights it until no edge does (the `rotation_limit` parameter; 0 gives the minimum norm).
///
/// Indices and turning numbers must be multiples of \f$1/N\f$ for the symmetry order \f$N\f$
/// (N-RoSy fields). On every closed component the indices must sum to the Euler
/// characteristic. On a component with boundary no such condition applies: the dual cells of
/// boundary vertices are left free and the boundary takes the remaining curvature (the "free
/// boundary" of Crane et al., section 2.6 and Figure 8); the turning numbers of all boundary
/// loops but one are generator turning numbers.
///
/// Only \f$b\f$ depends on indices, turning numbers and constraint angles, so after the first
/// solve, changing them costs two triangular solves. Changing the set of constrained faces
/// rebuilds and refactors the system at the next solve.
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
/// \tparam SparseCholeskySolver a model of `SparseCholeskySolver` that factors
///         \f$A W A^\top\f$ (default: `Cholmod_cholesky`; also `Eigen_sparse_cholesky`, or CGAL's
///         `Eigen_solver_traits` wrapped by the `sparse_linear_solver` parameter of
///         compute_trivial_connection())
///
/// \warning Numbers are `double` internally whatever the kernel (see `Intrinsic_mesh`).
template <typename TriangleMesh, typename SparseCholeskySolver = Cholmod_cholesky>
class Trivial_connection
{
  typedef SparseCholeskySolver Solver;

public:
  // the descriptors of the mesh (those of its Intrinsic_mesh)
  typedef typename Intrinsic_mesh<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename Intrinsic_mesh<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename Intrinsic_mesh<TriangleMesh>::face_descriptor face_descriptor;

  /// Precomputes the metric, topology, generators and their Levi-Civita holonomy.
  /// Throws `Input_error` for invalid meshes or parameters.
  /// Named parameters: `edge_length_map`, `vertex_point_map` (also the embedding of
  /// angles_to_vectors()) and the index maps as in the constructor of `Intrinsic_mesh`, and
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{symmetry_order}
  ///     \cgalParamDescription{\f$N\f$: directions are identified up to rotations by \f$2\pi/N\f$}
  ///     \cgalParamType{`int`, at least 1}
  ///     \cgalParamDefault{1 (vector / direction fields); 2 line fields, 4 cross fields}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{connection_weights}
  ///     \cgalParamDescription{the weights \f$w_e\f$ of the objective}
  ///     \cgalParamType{`Connection_weights`}
  ///     \cgalParamDefault{`UNIT_WEIGHTS` (chosen on the shared test meshes: see the manual's section on the choice of weights)}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{cotangent_clamp}
  ///     \cgalParamDescription{cotan weights below this fraction of the mean positive weight are raised to it (non-positive cotangent sums occur on non-Delaunay edges)}
  ///     \cgalParamType{`double` in (0, 1]}
  ///     \cgalParamDefault{`1e-3`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{cotangent_cap}
  ///     \cgalParamDescription{with `BOUNDED_COTAN_WEIGHTS`: weights above this multiple of the mean positive weight are lowered to it}
  ///     \cgalParamType{`double`, at least 1}
  ///     \cgalParamDefault{`10`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{rotation_limit}
  ///     \cgalParamDescription{when the minimum-norm connection turns some edge by more than this
  ///       (radians), rotation limiting: the weight of every edge beyond it is multiplied by
  ///       \f$(\text{limit}/|x_e|)^2\f$ and the system refactored, for up to 8 rounds, until every
  ///       \f$|x_e|\f$ is within 5% of the limit; with smoothest turning numbers
  ///       (choose_smoothest_generator_turning_numbers()) they are chosen again on every round.
  ///       The result is then no longer the minimum-norm connection but one whose rotations stay
  ///       bounded (the status reports the rounds); the kept factorisation is that of the
  ///       plain weights, so a solve within the limit still costs one solve. If an edge is still
  ///       beyond \f$\pi\f$ after the rounds (and there are no directional constraints), the
  ///       connection of lowest largest rotation with the same holonomies is computed (a
  ///       largest-mean-cycle problem on the dual graph, by bisection and Bellman-Ford) and blended
  ///       in with the smallest weight that brings every edge within the limit (and below
  ///       \f$\pi\f$, also for a limit above it), or below \f$\pi\f$ if the limit cannot be
  ///       reached; when no connection can stay below \f$\pi\f$, a dual cycle proves it
  ///       (`rotation_lower_bound`) and the result turns no edge by more than that bound. With
  ///       smoothest turning numbers, those are first searched for ones that let every edge stay
  ///       below \f$\pi\f$ (`generators_turned_for_rotation`), or a proof that none can
  ///       (`rotation_bound_any_turning`). 0 turns it off (the
  ///       paper's minimum-norm solution). Not with guide directions or `SPQR_MINIMUM_NORM`}
  ///     \cgalParamType{`double`, non-negative}
  ///     \cgalParamDefault{\f$0.8\pi\f$ (chosen on the shared test meshes: see the manual's section on the choice of weights)}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{solver}
  ///     \cgalParamDescription{the linear solver: normal equations factored by `SparseCholeskySolver`, or the SPQR reference}
  ///     \cgalParamType{`Connection_solver`}
  ///     \cgalParamDefault{`CHOLMOD_NORMAL_EQUATIONS` (with any `SparseCholeskySolver`, despite its name)}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{sparse_linear_solver}
  ///     \cgalParamDescription{the solver that factors \f$A W A^\top\f$ (copied; its settings are used, not a factorisation it holds)}
  ///     \cgalParamType{`SparseCholeskySolver`, or CGAL's `Eigen_solver_traits` of a direct symmetric solver}
  ///     \cgalParamDefault{a default-constructed `SparseCholeskySolver`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{intrinsic_mesh}
  ///     \cgalParamDescription{the connectivity, metric and generators to use, built before on `tm`; replaces `edge_length_map`, `vertex_point_map` (except for angles_to_vectors()) and the index maps}
  ///     \cgalParamType{`Intrinsic_mesh<TriangleMesh>`}
  ///     \cgalParamDefault{one built from `tm` and the other parameters}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  template <typename NamedParameters = parameters::Default_named_parameters>
  explicit Trivial_connection(const TriangleMesh& tm,
                              const NamedParameters& np = parameters::default_values())
    : tm_(tm), im_(internal::get_intrinsic_mesh(tm, np)), m_(im_.arrays()), topo_(im_.topology_arrays()),
      gens_(im_.generator_arrays()), K_(im_.curvatures()), chol_(internal::make_cholesky_solver<Solver>(np))
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    N_ = choose_parameter(get_parameter(np, internal_np::symmetry_order), 1);
    if(N_ < 1)
      throw Input_error(Input_error::INVALID_ARGUMENT,
                        "symmetry order N must be at least 1, got " + std::to_string(N_));
    weights_ = choose_parameter(get_parameter(np, internal_np::connection_weights), UNIT_WEIGHTS);
    clamp_ = choose_parameter(get_parameter(np, internal_np::cotangent_clamp), 1e-3);
    if(!(clamp_ > 0 && clamp_ <= 1))
      throw Input_error(Input_error::INVALID_ARGUMENT, "cotangent_clamp must be in (0, 1], got " + std::to_string(clamp_));
    cap_ = choose_parameter(get_parameter(np, internal_np::cotangent_cap), 10.);
    rotation_limit_ = choose_parameter(get_parameter(np, internal_np::rotation_limit), 0.8 * CGAL_PI);
    if(!(rotation_limit_ >= 0) || !std::isfinite(rotation_limit_))
      throw Input_error(Input_error::INVALID_ARGUMENT, "rotation_limit must be a non-negative number, got " + std::to_string(rotation_limit_));
    if(!(cap_ >= 1) || !std::isfinite(cap_))
      throw Input_error(Input_error::INVALID_ARGUMENT, "cotangent_cap must be a number of at least 1, got " + std::to_string(cap_));
    solver_kind_ = choose_parameter(get_parameter(np, internal_np::solver), CHOLMOD_NORMAL_EQUATIONS);

    // The fill-reducing ordering of the vertex rows needs only the connectivity: computed on a
    // second thread while the rest of the setup runs (AMD on the vertex graph took 0.1 s at 400k
    // and 0.45 s at 1M faces, as part of CHOLMOD's 0.17 s / 0.8 s analysis). Only solvers that
    // accept Cholesky_hints can use it.
    if(solver_kind_ == CHOLMOD_NORMAL_EQUATIONS && internal::Accepts_cholesky_hints<Solver>::value)
      sys_.start_vertex_ordering(m_);

    typedef typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
    VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                               get_const_property_map(CGAL::vertex_point, tm));
    internal::face_maps(m_, vpm, frames_);

    for(const auto& g : gens_) z_.push_back(internal::wrap_angle(internal::transport_along(m_, g.dual)));
    increment_.resize(m_.number_of_halfedges());
    for(std::size_t h = 0; h < increment_.size(); ++h)
      increment_[h] = m_.face[h] >= 0 && m_.face[h ^ 1] >= 0 ? internal::transport_increment(m_, int(h)) : 0.;
    index_.assign(m_.number_of_vertices(), 0.);
    turning_.assign(gens_.size(), 0.);
    x_.assign(m_.number_of_edges(), 0.);
    internal::Connection_system::Weight_rule rule;
    rule.unit = weights_ == UNIT_WEIGHTS;
    rule.nonnegative_cotangents = weights_ == NONNEGATIVE_COTAN_WEIGHTS;
    rule.floor = clamp_;
    rule.cap = weights_ == BOUNDED_COTAN_WEIGHTS ? cap_ : 0.;
    sys_.compute_weights(m_, rule);
  }

  /// The intrinsic mesh (connectivity, metric, topology, generators) this connection was
  /// built on; pass it to field_singularities() and the other algorithms through the
  /// `intrinsic_mesh` named parameter so that they do not build another.
  const Intrinsic_mesh<TriangleMesh>& intrinsic_mesh() const { return im_; }

  /// The symmetry order \f$N\f$.
  int symmetry_order() const { return N_; }

  /// The homology generators whose turning numbers can be prescribed, in the order of
  /// `tree_cotree_generators()`.
  const std::vector<Homology_generator<TriangleMesh>>& generators() const { return im_.generators(); }

  /// The Levi-Civita holonomy in \f$(-\pi,\pi]\f$ of generator `i`.
  double generator_levi_civita_holonomy(std::size_t i) const { return z_.at(i); }

  /// Prescribes the index of the interior vertex `v` (0 removes a singularity). Throws
  /// `Input_error` if `v` is on the boundary or isolated, or if `index` is not a finite
  /// multiple of \f$1/N\f$.
  void set_singularity(vertex_descriptor v, double index)
  {
    const int vi = m_.vertex_index(v);
    if(m_.is_isolated(vi) || m_.is_boundary_vertex(vi)) {
      std::ostringstream os;
      os << "vertex " << vi << " is " << (m_.is_isolated(vi) ? "isolated" : "on the boundary")
         << "; singularities must be placed at interior vertices";
      throw Input_error(Input_error::INVALID_ARGUMENT, os.str());
    }
    index_[vi] = check_fraction(index, "index of vertex " + std::to_string(vi));
  }

  /// Sets every vertex index to 0.
  void clear_singularities() { std::fill(index_.begin(), index_.end(), 0.); }

  /// The prescribed index of `v`.
  double singularity_index(vertex_descriptor v) const { return index_[m_.vertex_index(v)]; }

  /// Prescribes the turning number of generator `i` (a multiple of \f$1/N\f$; default 0).
  void set_generator_turning_number(std::size_t i, double t)
  {
    if(i >= gens_.size())
      throw Input_error(Input_error::INVALID_ARGUMENT,
                        "generator " + std::to_string(i) + " does not exist (there are " +
                        std::to_string(gens_.size()) + ")");
    turning_[i] = check_fraction(t, "turning number of generator " + std::to_string(i));
    smoothest_ = false;
  }

  /// The prescribed turning number of generator `i`.
  double generator_turning_number(std::size_t i) const { return turning_.at(i); }

  /// Sets the generator turning numbers (multiples of \f$1/N\f$) that minimise the energy
  /// \f$\|Dx\|^2\f$ for the current singularities and directional constraints, and returns
  /// what was found. The energy is a quadratic form in the \f$k = 2g + b - 1\f$ turning numbers
  /// (through the \f$k \times k\f$ Schur complement of the factored system, \f$k + 1\f$ pairs of
  /// triangular solves), minimised over the lattice \f$(1/N)\mathbb{Z}^k\f$: exactly by
  /// enumeration (Schnorr-Euchner) when \f$k \le 12\f$ (`exact`); for larger \f$k\f$ by rounding
  /// the continuous minimiser and descending by single steps of \f$\pm 1/N\f$, which gives a
  /// local minimum that is never worse than all turning numbers 0 (`exact` is then `false`).
  /// Factors the system if needed. Throws `Input_error` with guide directions (their energy
  /// is not this quadratic form) or with the `SPQR_MINIMUM_NORM` solver.
  /// With rotation limiting (the default), solve() chooses them again on every reweighting
  /// round and, where no connection with them keeps every edge below \f$\pi\f$, moves the
  /// fewest it can until one does (Trivial_connection_status::generators_turned_for_rotation);
  /// generator_turning_number() returns the ones the last solve used.
  Smoothest_turning_numbers choose_smoothest_generator_turning_numbers()
  {
    if(!guide_faces_.empty() || solver_kind_ != CHOLMOD_NORMAL_EQUATIONS)
      throw Input_error(Input_error::INVALID_ARGUMENT,
                        "smoothest generator turning numbers need the normal-equation solver and no guide directions");
    check_index_sums();
    Smoothest_turning_numbers r;
    r.generators = gens_.size();
    if(!factored_) {
      Trivial_connection_status st;
      if(!build_and_factor(st)) throw Input_error(Input_error::INVALID_ARGUMENT, "cannot factor the system: " + st.message);
      factored_ = true;
    }
    smoothest_turning(chol_, r);
    smoothest_ = true;
    smoothest_turning_ = turning_;
    r.turning_numbers = turning_;
    return r;
  }

  /// Fixes the field direction in the given faces: pairs (face, angle in the face frame, in
  /// radians, measured counterclockwise from `halfedge(f)`), satisfied exactly modulo
  /// \f$2\pi/N\f$ (Crane et al., section 2.8). An empty range removes all constraints. If the
  /// set of faces differs from the current one, the next solve() refactors the system.
  template <typename FaceAngleRange>
  void set_directional_constraints(const FaceAngleRange& constraints)
  {
    std::vector<int> faces;
    std::vector<double> angles;
    std::vector<char> seen(m_.number_of_faces(), 0);
    for(const auto& c : constraints) {
      const int f = m_.face_index(c.first);
      const double a = double(c.second);
      if(!std::isfinite(a))
        throw Input_error(Input_error::INVALID_ARGUMENT,
                          "constraint angle of face " + std::to_string(f) + " is not finite");
      if(seen[f]++)
        throw Input_error(Input_error::INVALID_ARGUMENT,
                          "face " + std::to_string(f) + " is constrained twice");
      faces.push_back(f);
      angles.push_back(a);
    }
    if(faces != constrained_faces_) { constrained_faces_ = faces; factored_ = false; }
    constraint_angles_ = angles;
  }

  /// Soft alignment to guide directions: pairs (face, angle in the face frame). Instead of being
  /// met exactly, the rotation of the field along the tree path from each guide face to the
  /// nearest guide or constrained face above it is pulled towards the rotation that the two
  /// prescribed angles ask for (the smallest one modulo \f$2\pi/N\f$), by adding
  /// \f$\lambda\sum_i (c_i^\top x - \bar c_i)^2\f$ to the objective, \f$\lambda\f$ = `weight`
  /// (relative to the unit smoothness energy; \f$\lambda \to \infty\f$ gives hard constraints,
  /// \f$\lambda \to 0\f$ the unguided field; useful values are about \f$10^{-3}\f$ to
  /// \f$10^{4}\f$). The prescribed singularities are kept exactly.
  /// In a component without hard constraints the field is then rotated as a whole to fit the
  /// guides best (circular mean modulo \f$2\pi/N\f$), so no guide is favoured.
  /// The solve stays one factorisation: the guide terms are a rank-\f$k\f$ correction
  /// (Sherman-Morrison-Woodbury, \f$k\f$ = number of guides, \f$O(k\,|V|)\f$ memory and
  /// \f$k\f$ extra triangular solves at factorisation), and
  /// changing only the angles costs no refactorisation. Not available with `SPQR_MINIMUM_NORM`.
  template <typename FaceAngleRange>
  void set_guide_directions(const FaceAngleRange& guides, double weight)
  {
    if(!(weight > 0) || !std::isfinite(weight))
      throw Input_error(Input_error::INVALID_ARGUMENT, "guide weight must be positive and finite");
    std::vector<int> faces;
    std::vector<double> angles;
    std::vector<char> seen(m_.number_of_faces(), 0);
    for(int f : constrained_faces_) seen[f] = 2;
    for(const auto& g : guides) {
      const int f = m_.face_index(g.first);
      const double a = double(g.second);
      if(!std::isfinite(a))
        throw Input_error(Input_error::INVALID_ARGUMENT, "guide angle of face " + std::to_string(f) + " is not finite");
      if(seen[f])
        throw Input_error(Input_error::INVALID_ARGUMENT, "face " + std::to_string(f) +
                          (seen[f] == 2 ? " has a directional constraint and a guide" : " has two guides"));
      seen[f] = 1;
      faces.push_back(f);
      angles.push_back(a);
    }
    if(!faces.empty() && solver_kind_ != CHOLMOD_NORMAL_EQUATIONS)
      throw Input_error(Input_error::INVALID_ARGUMENT, "guide directions are not available with the SPQR_MINIMUM_NORM solver");
    if(faces != guide_faces_ || weight != guide_weight_) { guide_faces_ = faces; guide_weight_ = weight; factored_ = false; }
    guide_angles_ = angles;
  }

  /// Solves for the trivial connection closest to Levi-Civita. Throws `Input_error` with kind
  /// `INCONSISTENT_INDICES` if the indices of a closed component do not sum to its Euler
  /// characteristic; numerical failure is reported in the status.
  Trivial_connection_status solve()
  {
    check_index_sums();
    Trivial_connection_status st;
    const auto t0 = std::chrono::steady_clock::now();
    if(!factored_) {
      if(!build_and_factor(st)) return st;
      factored_ = true;
      st.factor_seconds = seconds_since(t0);
    }
    const auto t1 = std::chrono::steady_clock::now();
    if(smoothest_) turning_ = smoothest_turning_;
    Eigen::VectorXd b = sys_.rhs(m_, K_, index_, z_, turning_, constraint_angles_, N_);
    Eigen::VectorXd xc;
    if(!solve_columns(b, xc, st)) return st;
    limit_rotations(b, xc, st);
    std::fill(x_.begin(), x_.end(), 0.);
    for(std::size_t c = 0; c < sys_.edge_of_col_.size(); ++c) x_[sys_.edge_of_col_[c]] = xc[Eigen::Index(c)];
    st.solve_seconds = seconds_since(t1);
    st.energy = xc.cwiseProduct(xc).cwiseQuotient(sys_.W_).sum();
    const Eigen::VectorXd r = sys_.A_ * xc + b;
    st.residual = sys_.rows_ ? r.cwiseAbs().maxCoeff() : 0.;
    // The vertex and generator rows of A x + b are exactly the holonomy errors of those cycles;
    // only the dropped vertex of each closed component needs its own check.
    st.max_holonomy_error = (std::max)(sys_.first_constraint_row_ ? r.head(sys_.first_constraint_row_).cwiseAbs().maxCoeff() : 0.,
                                       sys_.dropped_vertices_holonomy_error(m_, K_, index_, x_));
    st.scaled_residual = st.residual / (std::max)(1., sys_.rows_ ? b.cwiseAbs().maxCoeff() : 0.);
    measure_rotations(xc, st);
    if(!(st.max_holonomy_error <= 1e-12) && solver_kind_ == CHOLMOD_NORMAL_EQUATIONS && sys_.rows_ > 0) {
      if(condition_ == 0) condition_ = sys_.condition_estimate(chol_);
      st.condition_estimate = condition_;
    }
    st.success = false;
    std::ostringstream os;
    os.precision(3);
    if(!std::isfinite(st.energy) || !std::isfinite(st.residual)) os << "the solve produced non-finite values";
    else if(!(st.scaled_residual <= 1e-9)) os << "scaled residual " << st.scaled_residual << " > 1e-9";
    else if(!(st.max_holonomy_error <= 1e-9)) os << "holonomy error " << st.max_holonomy_error << " > 1e-9";
    else st.success = true;
    if(!st.success && st.condition_estimate > 0) os << " (condition number about " << st.condition_estimate << ")";
    st.message = os.str();
    solved_ = std::isfinite(st.energy) && std::isfinite(st.residual);   // a failed field can still be inspected
    return st;
  }

  /// The adjustment angle \f$\sigma_h x_e\f$ added when crossing the edge of `h` from
  /// `face(opposite(h))` into `face(h)` (0 on boundary edges).
  double adjustment_angle(halfedge_descriptor h) const
  {
    const int hi = m_.halfedge_index(h, tm_);
    return (hi & 1) ? -x_[hi >> 1] : x_[hi >> 1];
  }

  /// The angle of the connection across the edge of `h`: the total rotation, in the face frames,
  /// of a direction carried from `face(opposite(h))` into `face(h)` (Levi-Civita increment plus
  /// adjustment angle).
  double connection_angle(halfedge_descriptor h) const
  {
    const int hi = m_.halfedge_index(h, tm_);
    return connection_angle_index(hi);
  }

  /// Holonomy of the computed connection around a dual cycle: its Levi-Civita holonomy taken in
  /// \f$(-\pi, \pi]\f$ plus the sum of the adjustment angles (not wrapped). Around a generator it
  /// is \f$2\pi\f$ times the prescribed turning number, and around the dual cell of an interior
  /// vertex with \f$|K_v| < \pi\f$ it is \f$2\pi\f$ times the prescribed index.
  template <typename HalfedgeRange>
  double holonomy(const HalfedgeRange& dual_cycle) const
  {
    std::vector<int> c;
    for(auto h : dual_cycle) c.push_back(m_.halfedge_index(h, tm_));
    internal::check_dual_path(m_, c, true);
    double s = internal::wrap_angle(internal::transport_along(m_, c));
    for(int h : c) s += (h & 1) ? -x_[h >> 1] : x_[h >> 1];
    return s;
  }

  /// Writes the face-based N-RoSy field that is parallel for the connection: one angle per face
  /// in the face's frame (counterclockwise from `halfedge(f)`, in radians; the N directions are
  /// this angle plus multiples of \f$2\pi/N\f$). Each component starts at its first constrained
  /// face with the constraint angle, or at its first face with `start_angle`, and the field is
  /// propagated along a breadth-first spanning tree of the faces by
  /// \f$\beta_j = \beta_i + \text{increment} + \sigma_h x_e\f$ (Eq. 3); because the connection
  /// is trivial the result does not depend on the tree. Components with guide directions but no
  /// hard constraint are rotated to fit their guides (see set_guide_directions()), so
  /// `start_angle` does not matter there. Linear time.
  /// \pre solve() succeeded.
  template <typename FaceAngleMap>
  void field_angles(FaceAngleMap angles, double start_angle = 0) const
  {
    std::vector<double> beta;
    propagate(beta, start_angle, -1);
    for(std::size_t f = 0; f < beta.size(); ++f) put(angles, m_.faces[f], beta[f]);
  }

  /// As field_angles(), but the field of the component of `start` is propagated from `start`
  /// with angle `start_angle` along a breadth-first tree rooted there (for other components as
  /// in field_angles()). Directional constraints are ignored for that component.
  template <typename FaceAngleMap>
  void field_angles_from(face_descriptor start, double start_angle, FaceAngleMap angles) const
  {
    std::vector<double> beta;
    propagate(beta, start_angle, m_.face_index(start));
    for(std::size_t f = 0; f < beta.size(); ++f) put(angles, m_.faces[f], beta[f]);
  }

  /// The matching of a face field of this connection (e.g. the output of field_angles()): for
  /// every interior edge \f$e\f$ with \f$h\f$ = `halfedge(e)`, the period jump \f$k_e\f$ such
  /// that carrying the direction of the right face `face(opposite(h))` into the left face
  /// `face(h)` with the connection gives the left face's direction rotated by
  /// \f$2\pi k_e/N\f$ (modulo \f$2\pi\f$). Precisely, the connection's rotation relative to
  /// Levi-Civita across \f$h\f$, adjustment_angle(h), is
  /// \f$w(\beta_l - \beta_r - \text{increment}_h) + 2\pi k_e/N\f$ with \f$w\f$ wrapping to
  /// \f$(-\pi, \pi]\f$, so adding multiples of \f$2\pi\f$ to field angles does not change
  /// it. Written to `matching` (0 on boundary edges). Read back with this matching (the
  /// `matching` parameter of field_singularities()), the field has exactly the singularities
  /// and turning numbers of the connection, also across edges where the connection turns by
  /// more than \f$\pi/N\f$, which principal matching misreads.
  /// Returns the largest distance of the computed \f$k_e\f$ to its integer: about
  /// \f$10^{-12}\f$ for a field of this connection, large for any other field.
  /// \tparam EdgeMatchingMap a writable property map, `edge_descriptor` keys, `int` values
  /// \pre solve() succeeded.
  template <typename FaceAngleMap, typename EdgeMatchingMap>
  double field_matching(const FaceAngleMap& angles, EdgeMatchingMap matching) const
  {
    CGAL_precondition(solved_);
    const double scale = N_ / (2 * CGAL_PI);
    double worst = 0;
    for(std::size_t e = 0; e < m_.number_of_edges(); ++e) {
      const int h = int(2 * e);
      int k = 0;
      if(!m_.is_border_edge(int(e))) {
        const double d = double(get(angles, m_.faces[m_.face[h]])) - double(get(angles, m_.faces[m_.face[h ^ 1]])) -
                         increment_[h];
        const double t = (x_[e] - internal::wrap_angle(d)) * scale;
        const double rk = std::round(t);
        worst = (std::max)(worst, std::abs(t - rk));
        k = int(rk);
      }
      put(matching, m_.edges[e], k);
    }
    return worst;
  }

  /// Converts face angles (in the face frames) to unit 3D vectors in the plane of each face of the
  /// embedding given by `vertex_point_map`. When the metric is the embedding's, this is
  /// \f$\cos\beta\,e_1 + \sin\beta\,e_2\f$ with \f$e_1\f$ along `halfedge(f)` and
  /// \f$e_2 = n \times e_1\f$. For any other metric (e.g. a flat cone metric), the direction
  /// is mapped by the linear map of the face that takes the metric's triangle (laid out with
  /// `source(halfedge(f))` at the origin and `halfedge(f)` on the x axis) to the embedded
  /// triangle, and normalised: directions keep their barycentric meaning, not their angles.
  /// \tparam FaceVectorMap writable, `face_descriptor` keys, values constructible from three doubles
  template <typename FaceAngleMap, typename FaceVectorMap>
  void angles_to_vectors(const FaceAngleMap& angles, FaceVectorMap vectors) const
  {
    typedef typename boost::property_traits<FaceVectorMap>::value_type Vector;
    for(std::size_t f = 0; f < m_.number_of_faces(); ++f) {
      const std::array<double, 3> v = internal::embedded_direction(frames_[f], double(get(angles, m_.faces[f])));
      put(vectors, m_.faces[f], Vector(v[0], v[1], v[2]));
    }
  }

private:
  typedef internal::Sparse_matrix_int Sparse_matrix_int;

  static double seconds_since(std::chrono::steady_clock::time_point t)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  }

  double check_fraction(double k, const std::string& what) const
  {
    const double kn = k * N_;
    if(!std::isfinite(k) || std::abs(kn - std::round(kn)) > 1e-9 * std::max(1., std::abs(kn))) {
      std::ostringstream os;
      os.precision(17);
      os << what << " is " << k << ", not a multiple of 1/N = 1/" << N_;
      throw Input_error(Input_error::INVALID_ARGUMENT, os.str());
    }
    return std::round(kn) / N_;
  }

  void check_index_sums() const
  {
    std::vector<double> sum(topo_.components.size(), 0.);
    for(std::size_t v = 0; v < index_.size(); ++v)
      if(topo_.vertex_component[v] >= 0) sum[topo_.vertex_component[v]] += index_[v];
    for(std::size_t c = 0; c < sum.size(); ++c) {
      if(topo_.components[c].boundary_loops != 0) continue;
      const double chi = double(topo_.components[c].euler_characteristic());
      if(std::abs(sum[c] - chi) > 1e-9 * std::max(1., std::abs(chi))) {
        std::ostringstream os;
        os.precision(15);
        os << "singularity indices sum to " << sum[c] << " but the Euler characteristic of component "
           << c << " is " << chi;
        throw Input_error(Input_error::INCONSISTENT_INDICES, os.str());
      }
    }
  }

  double connection_angle_index(int h) const
  {
    return increment_[h] + ((h & 1) ? -x_[h >> 1] : x_[h >> 1]);
  }

  // Builds the system and factors A W A^T (CHOLMOD path) or only builds it (SPQR path).
  bool build_and_factor(Trivial_connection_status& st)
  {
    condition_ = 0;
    tree_.build(m_, constrained_faces_, guide_faces_);
    sys_.build(m_, topo_, gens_, constrained_faces_, tree_);
    // no constraint row (e.g. separate triangles, or disks without interior vertices): x = 0
    if(solver_kind_ != CHOLMOD_NORMAL_EQUATIONS || (sys_.rows_ == 0 && guide_faces_.empty())) return true;
    if(sys_.rows_ == 0) {
      st.message = "guide directions need at least one interior vertex, generator or directional constraint";
      return false;
    }
    const Sparse_matrix_int L = sys_.normal_matrix();
    // Rows in vertex_split_.order with the few generator and constraint rows last are as good as
    // CHOLMOD's AMD on the whole matrix (400k faces: 1.29e9 vs 1.24e9 flops); many
    // constraint rows would fill in as a dense block there, so the solver orders those systems.
    // The same holds for the two-domain split (the vertex graph's domains, then its
    // separator and the extra rows), factored on two threads.
    if(!internal::factor_with_hints(chol_, L, factor_hints(), st.message)) return false;
    guides_.prepare(m_, tree_, sys_, chol_, guide_faces_, constrained_faces_, guide_weight_);
    return true;
  }

  // The lattice search of choose_smoothest_generator_turning_numbers() with the factorisation
  // `chol` of the current weights; sets turning_.
  template <typename Chol>
  void smoothest_turning(const Chol& chol, Smoothest_turning_numbers& r)
  {
    std::vector<double> t(gens_.size(), 0.);
    turning_.swap(t);   // b0: all turning numbers 0
    const Eigen::VectorXd b0 = sys_.rhs(m_, K_, index_, z_, turning_, constraint_angles_, N_);
    turning_.swap(t);
    const Eigen::Index k = Eigen::Index(gens_.size());
    if(sys_.rows_ == 0 || k == 0) { r.exact = true; return; }
    // E(t) = b(t)^T M^-1 b(t), b(t) = b0 - 2 pi P t, P the generator rows: with Z = M^-1 P,
    // E = b0^T M^-1 b0 - 4 pi (Z^T b0) . t + 4 pi^2 t^T (P^T Z) t
    Eigen::MatrixXd G(k, k);
    Eigen::VectorXd h(k);
    for(Eigen::Index g = 0; g < k; ++g) {
      Eigen::VectorXd e = Eigen::VectorXd::Zero(sys_.rows_);
      e[sys_.first_generator_row_ + g] = 1;
      const Eigen::VectorXd z = chol.solve(e);
      h[g] = z.dot(b0);
      for(Eigen::Index j = 0; j < k; ++j) G(j, g) = z[sys_.first_generator_row_ + j];
    }
    G = 0.5 * (G + G.transpose());
    const double c0 = b0.dot(chol.solve(b0));
    auto energy = [&](const Eigen::VectorXd& tt) {
      return c0 - 4 * CGAL_PI * h.dot(tt) + 4 * CGAL_PI * CGAL_PI * tt.dot(G * tt);
    };
    // in s = N t: minimise (s - c)^T G (s - c) with c = N G^-1 h / (2 pi)
    Eigen::LDLT<Eigen::MatrixXd> ldlt(G);
    const Eigen::VectorXd c = ldlt.solve(h) * (N_ / (2 * CGAL_PI));
    const internal::Lattice_minimum lm = internal::lattice_minimum(G, c);
    Eigen::VectorXd best = lm.s / double(N_);
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(k);
    r.energy_with_zero_turning = energy(zero);
    if(!lm.positive_definite || energy(best) > r.energy_with_zero_turning) best = zero;
    r.energy = energy(best);
    r.exact = lm.exact && lm.positive_definite;
    for(Eigen::Index g = 0; g < k; ++g) turning_[std::size_t(g)] = std::round(best[g] * N_) / N_;
  }

  // Rotation limiting (the rotation_limit parameter) on the solution xc for b: edges beyond the
  // limit are penalised and the system refactored; the base weights are restored at the end,
  // so chol_ stays valid. With smoothest turning numbers b changes with them, and where no
  // connection with them stays below pi, the turning numbers are searched for ones that let it.
  void limit_rotations(Eigen::VectorXd& b, Eigen::VectorXd& xc, Trivial_connection_status& st)
  {
    if(!(rotation_limit_ > 0) || solver_kind_ != CHOLMOD_NORMAL_EQUATIONS || !guides_.empty() || sys_.rows_ == 0) return;
    reweight(b, xc, st, smoothest_);
    if(!(xc.cwiseAbs().maxCoeff() > M_PI) || sys_.first_constraint_row_ != sys_.rows_) return;
    const internal::Rotation_constraint_graph g = rotation_graph();
    if(smoothest_ && !gens_.empty() && search_turning_numbers(g, st)) {
      b = sys_.rhs(m_, K_, index_, z_, turning_, constraint_angles_, N_);
      xc = sys_.W_.asDiagonal() * (sys_.A_.transpose() * Eigen::VectorXd(chol_.solve(-b)));
      reweight(b, xc, st, false);
    }
    if(xc.cwiseAbs().maxCoeff() > M_PI) bound_rotations(g, b, xc, st);
  }

  // The reweighting rounds of rotation limiting (choosing the smoothest turning numbers again on
  // every round if `choose_turning`).
  void reweight(Eigen::VectorXd& b, Eigen::VectorXd& xc, Trivial_connection_status& st, bool choose_turning)
  {
    const Eigen::VectorXd W0 = sys_.W_;
    Solver chol;
    for(int round = 1; round <= 8 && xc.cwiseAbs().maxCoeff() > 1.05 * rotation_limit_; ++round) {
      for(Eigen::Index c = 0; c < xc.size(); ++c) {
        const double a = std::abs(xc[c]);
        if(a > rotation_limit_)   // floor: 1e-4 of the base weight keeps the system well conditioned
          sys_.W_[c] = (std::max)(sys_.W_[c] * (rotation_limit_ / a) * (rotation_limit_ / a), 1e-4 * W0[c]);
      }
      std::string message;
      if(!internal::factor_with_hints(chol, sys_.normal_matrix(), factor_hints(), message)) break;   // keep the last solution
      if(choose_turning) {
        Smoothest_turning_numbers r;
        smoothest_turning(chol, r);
        b = sys_.rhs(m_, K_, index_, z_, turning_, constraint_angles_, N_);
      }
      xc = sys_.W_.asDiagonal() * (sys_.A_.transpose() * Eigen::VectorXd(chol.solve(-b)));
      // iterative refinement: the reweighted system is less well conditioned than the base one
      const double scale = (std::max)(1., b.cwiseAbs().maxCoeff());
      for(int k = 0; k < 3; ++k) {
        const Eigen::VectorXd r = sys_.A_ * xc + b;
        if(r.cwiseAbs().maxCoeff() <= 1e-13 * scale) break;
        xc -= sys_.W_.asDiagonal() * (sys_.A_.transpose() * Eigen::VectorXd(chol.solve(r)));
      }
      st.rotation_limit_rounds += 1;
    }
    sys_.W_ = W0;
  }

  // The dual graph of the unknowns for rotation_minimax.h: x_e changes by
  // p[face(h)] - p[face(opposite(h))], h = halfedge(e).
  internal::Rotation_constraint_graph rotation_graph() const
  {
    std::vector<std::array<int, 2>> ends(sys_.edge_of_col_.size());
    for(std::size_t c = 0; c < ends.size(); ++c)
      ends[c] = {{m_.face[std::size_t(2 * sys_.edge_of_col_[c])], m_.face[std::size_t(2 * sys_.edge_of_col_[c] + 1)]}};
    return internal::Rotation_constraint_graph(int(m_.number_of_faces()), ends);
  }

  // Turning numbers of the smoothest mode that let some connection stay below pi, by cutting
  // planes: a dual cycle C that turns by more than pi per edge on average (Bellman-Ford at
  // T = pi) is a combination mu of the rows of A, found by one solve (A W A^T mu = A W s_C for
  // its signed indicator s_C = A^T mu); its turn changes by 2 pi mu_g / N per step of generator
  // g. The turning numbers are then moved, by the fewest steps a greedy search finds, until every
  // cycle met so far is within pi, and the test repeats. A cycle winding around no generator,
  // or cycles around one generator that no number of steps brings all within pi, prove that no
  // turning numbers can help (rotation_bound_any_turning). Returns whether it changed the turning
  // numbers and every edge can now stay below pi.
  bool search_turning_numbers(const internal::Rotation_constraint_graph& g, Trivial_connection_status& st)
  {
    const double goal = M_PI * (1 - 1e-6);
    const std::vector<double> start = turning_;
    std::vector<long> d(gens_.size(), 0);
    std::vector<internal::Turning_cycle> cycles;
    std::vector<double> p;
    std::vector<int> arcs;
    for(int iteration = 0; iteration < 50; ++iteration) {   // each round adds one cycle; the shared meshes and the tests need 1 to 3
      for(std::size_t k = 0; k < d.size(); ++k) turning_[k] = start[k] + double(d[k]) / N_;
      const Eigen::VectorXd b = sys_.rhs(m_, K_, index_, z_, turning_, constraint_angles_, N_);
      const Eigen::VectorXd x = sys_.W_.asDiagonal() * (sys_.A_.transpose() * Eigen::VectorXd(chol_.solve(-b)));
      double mean = 0;
      int length = 0;
      const internal::Rotation_bound_outcome r = internal::rotations_within(g, x, goal, p, mean, length, g.budget(), &arcs);
      if(r == internal::Rotation_bound_outcome::WITHIN) {
        st.generators_turned_for_rotation = std::size_t(std::count_if(d.begin(), d.end(), [](long v) { return v != 0; }));
        return iteration > 0;
      }
      if(r == internal::Rotation_bound_outcome::UNDECIDED) break;
      internal::Turning_cycle cycle;
      if(!internal::turning_cycle(g, arcs, x, sys_.A_, sys_.W_, chol_, sys_.first_generator_row_, gens_.size(), cycle)) break;
      if(cycle.winding.empty()) {   // winds around no generator: no turning numbers change its turn
        st.rotation_bound_any_turning = std::abs(cycle.turn) / cycle.length;
        break;
      }
      // its turn as if measured where the search began
      for(const auto& gm : cycle.winding) cycle.turn -= (2 * M_PI / N_) * double(gm.second) * double(d[std::size_t(gm.first)]);
      cycles.push_back(cycle);
      if(!internal::fit_turning_steps(cycles, N_, goal, d)) {
        // no turning numbers keep these cycles within pi: a proof when they wind around one generator
        st.rotation_bound_any_turning = (std::max)(0., internal::one_generator_bound(cycles, N_, d));
        break;
      }
    }
    turning_ = start;
    return false;
  }

  // The last resort of rotation limiting: the connection of lowest largest rotation with the
  // holonomies of xc (rotation_minimax.h), blended into xc with the smallest weight that brings
  // every edge within the limit, or below pi, or else within that lowest largest rotation.
  void bound_rotations(const internal::Rotation_constraint_graph& g, const Eigen::VectorXd& b, Eigen::VectorXd& xc,
                       Trivial_connection_status& st)
  {
    double lo = 0, hi = 0;
    std::vector<double> p;
    internal::lowest_largest_rotation(g, xc, 16, g.budget(), lo, hi, p);
    st.rotation_lower_bound = lo;
    const double below_pi = M_PI * (1 - 1e-6), first_goal = (std::min)(rotation_limit_, below_pi);
    const double goal = hi < first_goal ? first_goal : hi < below_pi ? below_pi : hi;
    if(!(hi < xc.cwiseAbs().maxCoeff())) return;
    Eigen::VectorXd xinf = xc;
    for(std::size_t c = 0; c < g.ends.size(); ++c) xinf[Eigen::Index(c)] += p[std::size_t(g.ends[c][0])] - p[std::size_t(g.ends[c][1])];
    const double lambda = internal::blend_weight(xc, xinf, goal);
    xc = (1 - lambda) * xc + lambda * xinf;
    // the potentials' rounding in the holonomies: one correction step on the kept factorisation
    const Eigen::VectorXd r = sys_.A_ * xc + b;
    xc -= sys_.W_.asDiagonal() * (sys_.A_.transpose() * Eigen::VectorXd(chol_.solve(r)));
    st.minimax_blend = lambda;
  }

  Cholesky_hints factor_hints() const
  {
    Cholesky_hints hints;
    hints.many_solves = true;
    hints.preordered = sys_.vertex_order_is_amd_ && sys_.rows_ - sys_.first_generator_row_ <= 32;
    if(hints.preordered && sys_.vertex_split_.is_split()) {
      hints.domain_rows[0] = sys_.domain_rows_[0];
      hints.domain_rows[1] = sys_.domain_rows_[1];
    }
    return hints;
  }

  void measure_rotations(const Eigen::VectorXd& xc, Trivial_connection_status& st) const
  {
    const double half_period = M_PI / N_;
    for(Eigen::Index c = 0; c < xc.size(); ++c) {
      const double r = std::abs(xc[c]);
      st.max_rotation = (std::max)(st.max_rotation, r);
      st.edges_beyond_half_period += r > half_period;
      st.edges_beyond_pi += r > M_PI;
    }
  }

  // The adjustment angles for the right-hand side b, one per column of A.
  bool solve_columns(const Eigen::VectorXd& b, Eigen::VectorXd& xc, Trivial_connection_status& st) const
  {
    if(sys_.rows_ == 0) {   // build_and_factor() allowed it only without guides
      xc.setZero(sys_.W_.size());
    } else if(solver_kind_ == CHOLMOD_NORMAL_EQUATIONS && guides_.empty()) {
      const Eigen::VectorXd y = chol_.solve(-b);
      xc = sys_.W_.asDiagonal() * (sys_.A_.transpose() * y);
    } else if(solver_kind_ == CHOLMOD_NORMAL_EQUATIONS) {
      st.guide_energy = guides_.solve(sys_, chol_, b, guides_.rhs(m_, guide_angles_, constraint_angles_, N_), xc);
    } else {
      const Eigen::VectorXd sw = sys_.W_.cwiseSqrt();
      internal::Sparse_matrix M = (sys_.A_ * sw.asDiagonal()).template cast<double>();
      Eigen::VectorXd y;
      if(!internal::spqr_minimum_norm(M, -b, y, st.message)) return false;
      xc = sw.asDiagonal() * y;
    }
    return true;
  }

  // The field of the connection; see field_angles() and field_angles_from().
  void propagate(std::vector<double>& beta, double start_angle, int special_root) const
  {
    CGAL_precondition(solved_);
    internal::propagate_field(m_, tree_, [this](int h) { return connection_angle_index(h); },
                              constrained_faces_, constraint_angles_, start_angle, special_root, beta);
    // a component propagated from special_root is not rotated to the guides
    if(special_root < 0)
      internal::fit_rotation_to_guides(topo_, N_, constrained_faces_, guide_faces_, guide_angles_, beta);
    internal::wrap_field(beta);
  }

  const TriangleMesh& tm_;
  Intrinsic_mesh<TriangleMesh> im_;
  const internal::Mesh_arrays<TriangleMesh>& m_;           // im_'s arrays
  const internal::Topology_arrays& topo_;
  const std::vector<internal::Generator_arrays>& gens_;
  const std::vector<double>& K_;                            // angle defects
  std::vector<double> z_, index_, turning_, x_;
  std::vector<double> increment_;   // Levi-Civita transport increment per halfedge
  std::vector<internal::Face_map> frames_;   // per face: metric triangle -> embedded triangle
  int N_ = 1;
  Connection_weights weights_ = UNIT_WEIGHTS;
  double clamp_ = 1e-3, cap_ = 10, rotation_limit_ = 0.8 * CGAL_PI;
  bool smoothest_ = false;                    // the turning numbers are those of choose_smoothest_generator_turning_numbers()
  std::vector<double> smoothest_turning_;     // ... as it chose them (restored before every solve)
  double condition_ = 0;   // sys_.condition_estimate() of the current factorisation (0: not yet)
  Connection_solver solver_kind_ = CHOLMOD_NORMAL_EQUATIONS;

  internal::Connection_system sys_;
  internal::Face_tree tree_;
  Solver chol_;
  internal::Guide_solver<Solver> guides_;
  bool factored_ = false, solved_ = false;

  std::vector<int> guide_faces_;
  std::vector<double> guide_angles_;
  double guide_weight_ = 1;
  std::vector<int> constrained_faces_;
  std::vector<double> constraint_angles_;
};

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_TRIVIAL_CONNECTION_H
