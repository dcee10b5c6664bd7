// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_TRIVIAL_CONNECTION_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_TRIVIAL_CONNECTION_H

#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/parameters.h>
#include <CGAL/Surface_mesh_direction_fields/homology_generators.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh_arrays.h>
#include <CGAL/Surface_mesh_direction_fields/internal/development.h>
#include <CGAL/Surface_mesh_direction_fields/internal/topology.h>
#include <CGAL/Surface_mesh_direction_fields/internal/tree_cotree.h>
#include <CGAL/Surface_mesh_direction_fields/internal/sparse_solvers.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Kernel_traits.h>

#include <algorithm>
#include <chrono>
#include <cmath>
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
  /// \f$w_e = 1\f$ (\f$D = I\f$).
  UNIT_WEIGHTS
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
  bool success = false;          ///< `false` if the factorisation or solve failed (see `message`)
  std::string message;           ///< empty on success
  double energy = 0;             ///< \f$\|Dx\|^2 = \sum_e x_e^2/w_e\f$
  double residual = 0;           ///< \f$\max_i |(Ax + b)_i|\f$ over all constraint rows
  double guide_energy = 0;       ///< \f$\lambda\sum_i (c_i^\top x - \bar c_i)^2\f$ of the guide directions (0 without guides)
  double max_holonomy_error = 0; ///< max over all interior-vertex cycles and generators of the distance between the connection's holonomy and \f$2\pi\f$ times the prescribed index / turning number
  double factor_seconds = 0;     ///< time spent building and factoring the system in this call (0 when reused)
  double solve_seconds = 0;      ///< time of the solve in this call
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
/// \f$\min \|Dx\|^2\f$, is returned: \f$x = W A^\top y\f$ with \f$(A W A^\top)\,y = -b\f$.
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
template <typename TriangleMesh>
class Trivial_connection
{
public:
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;

  /// Precomputes the metric, topology, generators and their Levi-Civita holonomy.
  /// Throws `Input_error` for invalid meshes or parameters.
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{edge_length_map}
  ///     \cgalParamDescription{the intrinsic metric}
  ///     \cgalParamType{a readable property map with `edge_descriptor` keys and `double` values}
  ///     \cgalParamDefault{Euclidean lengths from `vertex_point_map`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{vertex_point_map}
  ///     \cgalParamDescription{vertex positions: the default metric and the embedding of field_vectors()}
  ///     \cgalParamType{a readable property map with `vertex_descriptor` keys and 3D point values}
  ///     \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, tm)`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{symmetry_order}
  ///     \cgalParamDescription{\f$N\f$: directions are identified up to rotations by \f$2\pi/N\f$}
  ///     \cgalParamType{`int`, at least 1}
  ///     \cgalParamDefault{1 (vector / direction fields); 2 line fields, 4 cross fields}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{connection_weights}
  ///     \cgalParamDescription{the weights \f$w_e\f$ of the objective}
  ///     \cgalParamType{`Connection_weights`}
  ///     \cgalParamDefault{`COTAN_WEIGHTS`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{cotangent_clamp}
  ///     \cgalParamDescription{cotan weights below this fraction of the mean positive weight are raised to it (non-positive cotangent sums occur on non-Delaunay edges)}
  ///     \cgalParamType{`double` in (0, 1]}
  ///     \cgalParamDefault{`1e-3`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{solver}
  ///     \cgalParamDescription{the linear solver}
  ///     \cgalParamType{`Connection_solver`}
  ///     \cgalParamDefault{`CHOLMOD_NORMAL_EQUATIONS`}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  template <typename NamedParameters = parameters::Default_named_parameters>
  explicit Trivial_connection(const TriangleMesh& tm,
                              const NamedParameters& np = parameters::default_values())
    : tm_(tm), m_(tm, np), topo_(m_)
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    N_ = choose_parameter(get_parameter(np, internal_np::symmetry_order), 1);
    if(N_ < 1)
      throw Input_error(Input_error::INVALID_ARGUMENT,
                        "symmetry order N must be at least 1, got " + std::to_string(N_));
    weights_ = choose_parameter(get_parameter(np, internal_np::connection_weights), COTAN_WEIGHTS);
    clamp_ = choose_parameter(get_parameter(np, internal_np::cotangent_clamp), 1e-3);
    if(!(clamp_ > 0 && clamp_ <= 1))
      throw Input_error(Input_error::INVALID_ARGUMENT, "cotangent_clamp must be in (0, 1]");
    solver_kind_ = choose_parameter(get_parameter(np, internal_np::solver), CHOLMOD_NORMAL_EQUATIONS);

    // The fill-reducing ordering of the vertex rows needs only the connectivity: computed on a
    // second thread while the rest of the setup runs (AMD on the vertex graph took 0.1 s at 400k
    // and 0.45 s at 1M faces, as part of CHOLMOD's 0.17 s / 0.8 s analysis).
    if(solver_kind_ == CHOLMOD_NORMAL_EQUATIONS) start_vertex_ordering();

    typedef typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
    VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                               get_const_property_map(CGAL::vertex_point, tm));
    store_embedding(vpm);

    gens_ = internal::tree_cotree(m_, topo_);
    public_gens_ = internal::to_homology_generators(m_, gens_, tm);
    for(const auto& g : gens_) z_.push_back(internal::wrap_angle(internal::transport_along(m_, g.dual)));
    internal::vertex_curvatures(m_, K_);
    increment_.resize(m_.number_of_halfedges());
    for(std::size_t h = 0; h < increment_.size(); ++h)
      increment_[h] = m_.face[h] >= 0 && m_.face[h ^ 1] >= 0 ? internal::transport_increment(m_, int(h)) : 0.;
    index_.assign(m_.number_of_vertices(), 0.);
    turning_.assign(gens_.size(), 0.);
    x_.assign(m_.number_of_edges(), 0.);
    compute_weights();
  }

  /// The symmetry order \f$N\f$.
  int symmetry_order() const { return N_; }

  /// The homology generators whose turning numbers can be prescribed, in the order of
  /// `tree_cotree_generators()`.
  const std::vector<Homology_generator<TriangleMesh>>& generators() const { return public_gens_; }

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
  /// changing only the angles costs no refactorisation. Requires the CHOLMOD solver.
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
      throw Input_error(Input_error::INVALID_ARGUMENT, "guide directions require the CHOLMOD solver");
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
      build_system();
      if(solver_kind_ == CHOLMOD_NORMAL_EQUATIONS) {
        Sparse_matrix_int L = normal_matrix();
        // Rows in vertex_split_.order with the few generator and constraint rows last are as good as
        // CHOLMOD's AMD on the whole matrix (400k faces: 1.29e9 vs 1.24e9 flops); many
        // constraint rows would fill in as a dense block there, so CHOLMOD orders those systems.
        // The same holds for the two-domain split (the vertex graph's domains, then its
        // separator and the extra rows), factored on two threads.
        const bool ordered = vertex_order_is_amd_ && rows_ - first_generator_row_ <= 32;
        const bool split = ordered && vertex_split_.is_split();
        if(!chol_.factor(L, st.message, ordered ? internal::Cholmod_factor::PRESERVE_ORDERING
                                                : internal::Cholmod_factor::CHOLMOD_ORDERING,
                         split ? domain_rows_[0] : 0, split ? domain_rows_[1] : 0, true))
          return st;
        prepare_guides();
      }
      factored_ = true;
      st.factor_seconds = seconds_since(t0);
    }
    const auto t1 = std::chrono::steady_clock::now();
    Eigen::VectorXd b = rhs();
    Eigen::VectorXd xc;
    if(solver_kind_ == CHOLMOD_NORMAL_EQUATIONS && guide_paths_.empty()) {
      const Eigen::VectorXd y = chol_.solve(-b);
      xc = W_.asDiagonal() * (A_.transpose() * y);
    } else if(solver_kind_ == CHOLMOD_NORMAL_EQUATIONS) {
      // KKT system M x + A^T y = f, A x = g with M = W^-1 + lambda C^T C, f = lambda C^T cbar,
      // g = -b: x = M^-1 (f - A^T y), (A M^-1 A^T) y = A M^-1 f - g. One step of iterative
      // refinement recovers the digits that the Woodbury correction loses at large weights.
      const Eigen::VectorXd cbar = guide_rhs();
      Eigen::VectorXd f = Eigen::VectorXd::Zero(W_.size());
      for(std::size_t i = 0; i < guide_paths_.size(); ++i)
        for(const auto& ce : guide_columns_[i]) f[ce.first] += guide_weight_ * cbar[Eigen::Index(i)] * ce.second;
      Eigen::VectorXd y;
      kkt_solve(f, -b, xc, y);
      const Eigen::VectorXd r1 = f - apply_M(xc) - A_.transpose() * y;
      const Eigen::VectorXd r2 = -b - A_ * xc;
      Eigen::VectorXd dx, dy;
      kkt_solve(r1, r2, dx, dy);
      xc += dx;
      double misfit = 0;
      for(std::size_t i = 0; i < guide_paths_.size(); ++i) {
        double cx = 0;
        for(const auto& ce : guide_columns_[i]) cx += ce.second * xc[ce.first];
        misfit += guide_weight_ * (cx - cbar[Eigen::Index(i)]) * (cx - cbar[Eigen::Index(i)]);
      }
      st.guide_energy = misfit;
    } else {
      const Eigen::VectorXd sw = W_.cwiseSqrt();
      internal::Sparse_matrix M = (A_ * sw.asDiagonal()).template cast<double>();
      Eigen::VectorXd y;
      if(!internal::spqr_minimum_norm(M, -b, y, st.message)) return st;
      xc = sw.asDiagonal() * y;
    }
    std::fill(x_.begin(), x_.end(), 0.);
    for(std::size_t c = 0; c < edge_of_col_.size(); ++c) x_[edge_of_col_[c]] = xc[Eigen::Index(c)];
    st.solve_seconds = seconds_since(t1);
    st.energy = xc.cwiseProduct(xc).cwiseQuotient(W_).sum();
    const Eigen::VectorXd r = A_ * xc + b;
    st.residual = rows_ ? r.cwiseAbs().maxCoeff() : 0.;
    // The vertex and generator rows of A x + b are exactly the holonomy errors of those cycles;
    // only the dropped vertex of each closed component needs its own check.
    st.max_holonomy_error = (std::max)(first_constraint_row_ ? r.head(first_constraint_row_).cwiseAbs().maxCoeff() : 0.,
                                       dropped_vertices_holonomy_error());
    st.success = std::isfinite(st.energy) && std::isfinite(st.residual);
    if(!st.success) st.message = "the solve produced non-finite values";
    solved_ = st.success;
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

  /// Converts face angles (in the face frames) to unit 3D vectors in the plane of each face of the
  /// embedding given by `vertex_point_map`: \f$\cos\beta\,e_1 + \sin\beta\,e_2\f$ with \f$e_1\f$
  /// along `halfedge(f)` and \f$e_2 = n \times e_1\f$. When the metric is not the embedding's,
  /// angles are mapped as they are.
  /// \tparam FaceVectorMap writable, `face_descriptor` keys, values constructible from three doubles
  template <typename FaceAngleMap, typename FaceVectorMap>
  void angles_to_vectors(const FaceAngleMap& angles, FaceVectorMap vectors) const
  {
    typedef typename boost::property_traits<FaceVectorMap>::value_type Vector;
    for(std::size_t f = 0; f < m_.number_of_faces(); ++f) {
      const double beta = double(get(angles, m_.faces[f]));
      const auto& fr = frames_[f];
      const double c = std::cos(beta), s = std::sin(beta);
      put(vectors, m_.faces[f], Vector(c * fr[0] + s * fr[3], c * fr[1] + s * fr[4], c * fr[2] + s * fr[5]));
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

  template <typename VPM>
  void store_embedding(VPM vpm)
  {
    frames_.resize(m_.number_of_faces());
    for(std::size_t f = 0; f < m_.number_of_faces(); ++f) {
      const int h0 = m_.face_halfedge[f], h1 = m_.next[h0];
      double p[3][3];
      const int vs[3] = {m_.source(h0), m_.target[h0], m_.target[h1]};
      for(int i = 0; i < 3; ++i) {
        const auto& q = get(vpm, m_.vertices[vs[i]]);
        p[i][0] = CGAL::to_double(q.x()); p[i][1] = CGAL::to_double(q.y()); p[i][2] = CGAL::to_double(q.z());
      }
      double e1[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
      double e2[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
      double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
      auto normalize = [](double* v) {
        const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        if(l > 0) { v[0] /= l; v[1] /= l; v[2] /= l; }
      };
      normalize(e1);
      normalize(n);
      const double b[3] = {n[1] * e1[2] - n[2] * e1[1], n[2] * e1[0] - n[0] * e1[2], n[0] * e1[1] - n[1] * e1[0]};
      frames_[f] = {{e1[0], e1[1], e1[2], b[0], b[1], b[2]}};
    }
  }

  // Launches the AMD ordering of the graph of interior vertices (interior edges between them).
  // The task owns its input, so it never touches this object.
  void start_vertex_ordering()
  {
    const int nv = int(m_.number_of_vertices());
    auto interior = [&](int v) { return !m_.is_isolated(v) && !m_.is_boundary_vertex(v); };
    std::vector<int> col_begin(std::size_t(nv) + 1, 0);
    for(std::size_t e = 0; e < m_.number_of_edges(); ++e) {
      const int u = m_.target[2 * e], w = m_.target[2 * e + 1];
      if(u != w && interior(u) && interior(w)) ++col_begin[std::size_t((std::min)(u, w)) + 1];
    }
    for(int v = 0; v < nv; ++v) col_begin[v + 1] += col_begin[v];
    std::vector<int> rows(static_cast<std::size_t>(col_begin[nv]));
    std::vector<int> fill(col_begin.begin(), col_begin.end() - 1);
    for(std::size_t e = 0; e < m_.number_of_edges(); ++e) {
      const int u = m_.target[2 * e], w = m_.target[2 * e + 1];
      if(u != w && interior(u) && interior(w)) rows[fill[(std::min)(u, w)]++] = (std::max)(u, w);
    }
    // sort each column and drop repeated edges
    int k = 0;
    for(int v = 0; v < nv; ++v) {
      const int b = col_begin[v], e = col_begin[v + 1];
      std::sort(rows.begin() + b, rows.begin() + e);
      col_begin[v] = k;
      for(int i = b; i < e; ++i)
        if(i == b || rows[i] != rows[i - 1]) rows[k++] = rows[i];
    }
    col_begin[nv] = k;
    rows.resize(std::size_t(k));
    vertex_order_future_ = std::async(std::launch::async,
        [nv](std::vector<int> cb, std::vector<int> r) {
          internal::Two_domain_ordering o;
          if(nv < internal::Cholmod_factor::two_domain_min_rows) {
            o.order = internal::amd_ordering(nv, cb, r);
            return o;
          }
          std::vector<int> adj_begin, adj;
          internal::symmetric_adjacency(nv, cb.data(), r.data(), adj_begin, adj);
          return internal::two_domain_ordering(nv, adj_begin, adj, (std::numeric_limits<int>::max)(),
                                               internal::Cholmod_factor::max_separator, true);
        },
        std::move(col_begin), std::move(rows));
  }

  void compute_weights()
  {
    col_of_edge_.assign(m_.number_of_edges(), -1);
    edge_of_col_.clear();
    for(std::size_t e = 0; e < m_.number_of_edges(); ++e) {
      if(m_.is_border_edge(int(e))) continue;
      col_of_edge_[e] = int(edge_of_col_.size());
      edge_of_col_.push_back(int(e));
    }
    W_.setOnes(Eigen::Index(edge_of_col_.size()));
    if(weights_ == UNIT_WEIGHTS) return;
    // per face: cot of the corner opposite each halfedge, (a^2 + b^2 - c^2) / 4A, added to w_e / 2
    std::vector<double> w(m_.number_of_edges(), 0.);
    for(std::size_t f = 0; f < m_.number_of_faces(); ++f) {
      const int h0 = m_.face_halfedge[f], h1 = m_.next[h0], h2 = m_.next[h1];
      const double l0 = m_.edge_length(h0), l1 = m_.edge_length(h1), l2 = m_.edge_length(h2);
      const double q0 = l0 * l0, q1 = l1 * l1, q2 = l2 * l2;
      const double inv8A = 1. / (8. * triangle_area(l0, l1, l2));
      w[h0 >> 1] += (q1 + q2 - q0) * inv8A;
      w[h1 >> 1] += (q2 + q0 - q1) * inv8A;
      w[h2 >> 1] += (q0 + q1 - q2) * inv8A;
    }
    double sum = 0;
    std::size_t count = 0;
    for(int e : edge_of_col_) if(w[e] > 0 && std::isfinite(w[e])) { sum += w[e]; ++count; }
    const double floor = clamp_ * (count ? sum / double(count) : 1.);
    for(std::size_t c = 0; c < edge_of_col_.size(); ++c) {
      const double x = w[edge_of_col_[c]];
      W_[Eigen::Index(c)] = x >= floor ? x : floor;
    }
  }

  // Rows: interior vertices (minus one per closed component), generators, constraint paths.
  // A is assembled column by column (one column per interior edge): the vertex rows of an edge
  // come first and in increasing order, then the generator and constraint rows.
  void build_system()
  {
    const int ne = int(m_.number_of_edges());
    row_of_vertex_.assign(m_.number_of_vertices(), -1);
    std::vector<char> dropped(topo_.components.size(), 0), has_row(m_.number_of_vertices(), 0);
    for(std::size_t v = 0; v < m_.number_of_vertices(); ++v) {
      if(m_.is_isolated(int(v)) || m_.is_boundary_vertex(int(v))) continue;
      const int c = topo_.vertex_component[v];
      if(topo_.components[c].boundary_loops == 0 && !dropped[c]) { dropped[c] = 1; continue; }
      has_row[v] = 1;
    }
    // vertex rows numbered in the fill-reducing order when there is one
    if(vertex_order_future_.valid()) {
      vertex_split_ = vertex_order_future_.get();
      vertex_order_is_amd_ = vertex_split_.order.size() == m_.number_of_vertices();
    }
    if(vertex_split_.order.size() != m_.number_of_vertices()) {
      vertex_split_ = internal::Two_domain_ordering();
      vertex_split_.order.resize(m_.number_of_vertices());
      std::iota(vertex_split_.order.begin(), vertex_split_.order.end(), 0);
    }
    // rows of the two domains of the split (the separator rows and all others follow them)
    domain_rows_[0] = domain_rows_[1] = 0;
    int r = 0;
    for(std::size_t k = 0; k < vertex_split_.order.size(); ++k) {
      const int v = vertex_split_.order[k];
      if(has_row[v]) row_of_vertex_[v] = r++;
      if(k + 1 == std::size_t(vertex_split_.n1)) domain_rows_[0] = r;
      if(k + 1 == std::size_t(vertex_split_.n1 + vertex_split_.n2)) domain_rows_[1] = r - domain_rows_[0];
    }
    // sparse rows beyond the vertex rows: (column, row, value)
    struct Entry { int col, row; double value; };
    std::vector<Entry> extra;
    first_generator_row_ = r;
    for(const auto& g : gens_) {
      for(int h : g.dual) extra.push_back(Entry{col_of_edge_[h >> 1], r, (h & 1) ? -1. : 1.});
      ++r;
    }
    first_constraint_row_ = r;
    build_field_tree();
    constraint_paths_.clear();
    constraint_targets_.clear();
    std::vector<int> constrained(m_.number_of_faces(), -1);
    for(std::size_t i = 0; i < constrained_faces_.size(); ++i) constrained[constrained_faces_[i]] = int(i);
    for(std::size_t i = 0; i < constrained_faces_.size(); ++i) {
      int f = constrained_faces_[i];
      if(parent_cross_[f] < 0) continue;   // a root
      std::vector<int> path;
      do {
        const int up = parent_cross_[f] ^ 1;   // enters the parent
        path.push_back(up);
        f = m_.face[up];
      } while(constrained[f] < 0);
      for(int h : path) extra.push_back(Entry{col_of_edge_[h >> 1], r, (h & 1) ? -1. : 1.});
      constraint_paths_.push_back(path);
      constraint_targets_.push_back(std::make_pair(int(i), constrained[f]));
      ++r;
    }
    rows_ = r;
    std::sort(extra.begin(), extra.end(),
              [](const Entry& a, const Entry& b) { return a.col != b.col ? a.col < b.col : a.row < b.row; });

    const int ncols = int(edge_of_col_.size());
    // compressed columns written in place (insert() into reserved columns and makeCompressed()
    // made build_system() 0.30 s instead of 0.17 s at 1M faces)
    A_.resize(r, ncols);
    A_.resizeNonZeros(2 * ncols + int(extra.size()));
    int* outer = A_.outerIndexPtr();
    int* inner = A_.innerIndexPtr();
    double* value = A_.valuePtr();
    int nz = 0;
    auto put_entry = [&](int row, double v) { inner[nz] = row; value[nz++] = v; };
    std::size_t k = 0;
    for(int c = 0; c < ncols; ++c) {
      outer[c] = nz;
      const int e = edge_of_col_[c];
      // vertex u = source(2e) crosses 2e (sign +1), w = target(2e) crosses 2e + 1 (sign -1)
      const int ru = row_of_vertex_[m_.target[2 * e + 1]], rw = row_of_vertex_[m_.target[2 * e]];
      if(ru >= 0 && rw >= 0 && rw < ru) { put_entry(rw, -1.); put_entry(ru, 1.); }
      else { if(ru >= 0) put_entry(ru, 1.); if(rw >= 0) put_entry(rw, -1.); }
      for(; k < extra.size() && extra[k].col == c; ++k) {
        double v = extra[k].value;
        while(k + 1 < extra.size() && extra[k + 1].col == c && extra[k + 1].row == extra[k].row) v += extra[++k].value;
        if(v != 0) put_entry(extra[k].row, v);
      }
    }
    outer[ncols] = nz;
    A_.data().resize(nz);
    CGAL_USE(ne);
  }

  // Guide paths (tree paths from each guide face up to the nearest guide or constrained face),
  // their columns, and the Woodbury data Z = L^-1 U, G = S - U^T Z with U = A W C^T,
  // S = diag(1/lambda + c_i^T W c_i).
  void prepare_guides()
  {
    guide_paths_.clear();
    guide_partner_.clear();
    guide_columns_.clear();
    if(guide_faces_.empty()) return;
    std::vector<int> mark(m_.number_of_faces(), -1);   // >= 0 guide i, <= -2 constraint -(j + 2)
    for(std::size_t i = 0; i < guide_faces_.size(); ++i) mark[guide_faces_[i]] = int(i);
    for(std::size_t j = 0; j < constrained_faces_.size(); ++j) mark[constrained_faces_[j]] = -int(j) - 2;
    for(std::size_t i = 0; i < guide_faces_.size(); ++i) {
      int f = guide_faces_[i];
      std::vector<int> path;
      while(parent_cross_[f] >= 0) {
        const int up = parent_cross_[f] ^ 1;
        path.push_back(up);
        f = m_.face[up];
        if(mark[f] != -1) break;
      }
      if(mark[f] == -1 || path.empty()) continue;   // reached an unconstrained root
      std::map<int, double> cols;
      for(int h : path) cols[col_of_edge_[h >> 1]] += (h & 1) ? -1. : 1.;
      std::vector<std::pair<Eigen::Index, double>> c;
      for(const auto& ce : cols) if(ce.second != 0) c.push_back(std::make_pair(Eigen::Index(ce.first), ce.second));
      guide_paths_.push_back(path);
      guide_partner_.push_back(std::make_pair(int(i), mark[f]));
      guide_columns_.push_back(c);
    }
    // Paths of guides in different subtrees may share the edges above their common ancestor,
    // so C W C^T is a small dense matrix.
    const Eigen::Index k = Eigen::Index(guide_paths_.size());
    Eigen::MatrixXd S = Eigen::MatrixXd::Identity(k, k) / guide_weight_;
    Eigen::MatrixXd U(rows_, k);
    guide_WCt_.resize(W_.size(), k);
    std::vector<Eigen::Triplet<double>> t;
    for(Eigen::Index i = 0; i < k; ++i)
      for(const auto& ce : guide_columns_[std::size_t(i)]) t.emplace_back(ce.first, i, W_[ce.first] * ce.second);
    guide_WCt_.setFromTriplets(t.begin(), t.end());
    for(Eigen::Index i = 0; i < k; ++i) {
      const Eigen::VectorXd wc = guide_WCt_.col(i);
      for(Eigen::Index j = 0; j < k; ++j)
        for(const auto& ce : guide_columns_[std::size_t(j)]) S(j, i) += ce.second * wc[ce.first];
      U.col(i) = A_ * wc;
    }
    guide_S_.compute(S);
    guide_Z_.resize(rows_, k);
    for(Eigen::Index i = 0; i < k; ++i) guide_Z_.col(i) = chol_.solve(U.col(i));
    guide_G_.compute(S - U.transpose() * guide_Z_);
  }

  void kkt_solve(const Eigen::VectorXd& f, const Eigen::VectorXd& g, Eigen::VectorXd& x, Eigen::VectorXd& y) const
  {
    const Eigen::VectorXd r = A_ * apply_M_inverse(f) - g;
    y = chol_.solve(r);
    y += guide_Z_ * guide_G_.solve(guide_Z_.transpose() * r);
    x = apply_M_inverse(f - A_.transpose() * y);
  }

  // M v = W^-1 v + lambda C^T C v
  Eigen::VectorXd apply_M(const Eigen::VectorXd& v) const
  {
    Eigen::VectorXd r = v.cwiseQuotient(W_);
    for(const auto& cols : guide_columns_) {
      double cv = 0;
      for(const auto& ce : cols) cv += ce.second * v[ce.first];
      for(const auto& ce : cols) r[ce.first] += guide_weight_ * ce.second * cv;
    }
    return r;
  }

  // M^-1 v with M = W^-1 + lambda C^T C, by Woodbury: W v - W C^T S^-1 C W v.
  Eigen::VectorXd apply_M_inverse(const Eigen::VectorXd& v) const
  {
    Eigen::VectorXd r = W_.cwiseProduct(v);
    if(guide_columns_.empty()) return r;
    const Eigen::VectorXd cwv = guide_WCt_.transpose() * v;
    return r - guide_WCt_ * guide_S_.solve(cwv);
  }

  // Smallest rotation (mod 2pi/N) asked by each guide path.
  Eigen::VectorXd guide_rhs() const
  {
    Eigen::VectorXd c(Eigen::Index(guide_paths_.size()));
    const double period = 2 * CGAL_PI / N_;
    for(std::size_t i = 0; i < guide_paths_.size(); ++i) {
      const double gm = guide_angles_[guide_partner_[i].first];
      const int p = guide_partner_[i].second;
      const double gn = p >= 0 ? guide_angles_[p] : constraint_angles_[-p - 2];
      c[Eigen::Index(i)] = std::remainder(gn - gm - internal::transport_along(m_, guide_paths_[i]), period);
    }
    return c;
  }

  // Lower triangle of A W A^T, the sum over columns c of w_c a_c a_c^T (a column of A has two
  // vertex entries plus one per generator or constraint path crossing the edge), assembled in
  // compressed form: diagonal first in each column, then the off-diagonal products, sorted and
  // merged column by column. (Triplets and setFromTriplets took 0.52 s and 35k page faults,
  // 140 MB of transient memory, at 1M faces.)
  Sparse_matrix_int normal_matrix() const
  {
    const int n = int(rows_);
    Sparse_matrix_int L(n, n);
    if(n == 0) return L;
    std::vector<int> begin(std::size_t(n) + 1, 0);
    for(Eigen::Index c = 0; c < A_.outerSize(); ++c) {
      const int b = A_.outerIndexPtr()[c], e = A_.outerIndexPtr()[c + 1];
      for(int p = b; p < e; ++p) begin[std::size_t(A_.innerIndexPtr()[p]) + 1] += e - p - 1;
    }
    for(int j = 0; j < n; ++j) begin[j + 1] += begin[j] + 1;   // + 1: the diagonal
    L.resizeNonZeros(begin[n]);
    int* outer = L.outerIndexPtr();
    int* inner = L.innerIndexPtr();
    double* value = L.valuePtr();
    std::vector<int> fill(begin.begin(), begin.end() - 1);
    for(int j = 0; j < n; ++j) { inner[fill[j]] = j; value[fill[j]++] = 0; }
    // rows within a column of A are increasing (build_system), so i < k below
    for(Eigen::Index c = 0; c < A_.outerSize(); ++c) {
      const double w = W_[c];
      const int b = A_.outerIndexPtr()[c], e = A_.outerIndexPtr()[c + 1];
      for(int p = b; p < e; ++p) {
        const int i = A_.innerIndexPtr()[p];
        const double wa = w * A_.valuePtr()[p];
        value[begin[i]] += wa * A_.valuePtr()[p];
        for(int q = p + 1; q < e; ++q) {
          inner[fill[i]] = A_.innerIndexPtr()[q];
          value[fill[i]++] = wa * A_.valuePtr()[q];
        }
      }
    }
    std::vector<std::pair<int, double>> column;
    int k = 0;
    for(int j = 0; j < n; ++j) {
      const int b = begin[j], e = begin[j + 1];
      column.assign(1, std::make_pair(inner[b], value[b]));
      for(int p = b + 1; p < e; ++p) column.emplace_back(inner[p], value[p]);
      std::sort(column.begin() + 1, column.end(),
                [](const std::pair<int, double>& x, const std::pair<int, double>& y) { return x.first < y.first; });
      outer[j] = k;
      for(std::size_t p = 0; p < column.size(); ++p) {
        if(p > 1 && column[p].first == inner[k - 1]) { value[k - 1] += column[p].second; continue; }
        inner[k] = column[p].first;
        value[k++] = column[p].second;
      }
    }
    outer[n] = k;
    L.data().resize(k);
    return L;
  }

  Eigen::VectorXd rhs() const
  {
    Eigen::VectorXd b(rows_);
    for(std::size_t v = 0; v < row_of_vertex_.size(); ++v)
      if(row_of_vertex_[v] >= 0) b[row_of_vertex_[v]] = K_[v] - 2 * CGAL_PI * index_[v];
    for(std::size_t g = 0; g < gens_.size(); ++g)
      b[first_generator_row_ + Eigen::Index(g)] = z_[g] - 2 * CGAL_PI * turning_[g];
    const double period = 2 * CGAL_PI / N_;
    for(std::size_t i = 0; i < constraint_paths_.size(); ++i) {
      const double gm = constraint_angles_[constraint_targets_[i].first];
      const double gn = constraint_angles_[constraint_targets_[i].second];
      const double wanted = gn - gm - internal::transport_along(m_, constraint_paths_[i]);
      const double rot = std::remainder(wanted, period);   // smallest rotation mod 2pi/N
      b[first_constraint_row_ + Eigen::Index(i)] = -rot;
    }
    return b;
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

  double dropped_vertices_holonomy_error() const
  {
    double err = 0;
    for(std::size_t v = 0; v < m_.number_of_vertices(); ++v) {
      if(row_of_vertex_[v] >= 0 || m_.is_isolated(int(v)) || m_.is_boundary_vertex(int(v))) continue;
      double s = K_[v];
      const int h0 = m_.vertex_out[v];
      int h = h0;
      do { s += (h & 1) ? -x_[h >> 1] : x_[h >> 1]; h = m_.ccw_out(h); } while(h != h0);
      err = std::max(err, std::abs(s - 2 * CGAL_PI * index_[v]));
    }
    return err;
  }

  // Breadth-first spanning forest of the faces, rooted at the first constrained face of each
  // component, else its first guide face, else its first face.
  void build_field_tree()
  {
    const int nf = int(m_.number_of_faces());
    parent_cross_.assign(nf, -1);
    parent_face_.assign(nf, -1);
    roots_.clear();
    order_.clear();
    order_.reserve(nf);
    std::vector<char> visited(nf, 0);
    auto grow = [&](int root) {
      std::size_t head = order_.size();
      visited[root] = 1;
      order_.push_back(root);
      roots_.push_back(root);
      while(head < order_.size()) {
        const int f = order_[head++];
        int h = m_.face_halfedge[f];
        for(int k = 0; k < 3; ++k, h = m_.next[h]) {
          const int g = m_.face[h ^ 1];
          if(g < 0 || visited[g]) continue;
          visited[g] = 1;
          parent_cross_[g] = h ^ 1;
          parent_face_[g] = f;
          order_.push_back(g);
        }
      }
    };
    for(int f : constrained_faces_) if(!visited[f]) grow(f);
    for(int f : guide_faces_) if(!visited[f]) grow(f);   // so that every other guide has a partner
    for(int f = 0; f < nf; ++f) if(!visited[f]) grow(f);
  }

  // Rotates each component without hard constraints so that its guides fit best.
  void fit_rotation_to_guides(std::vector<double>& beta) const
  {
    if(guide_faces_.empty()) return;
    const std::size_t nc = topo_.components.size();
    std::vector<char> hard(nc, 0);
    for(int f : constrained_faces_) hard[topo_.face_component[f]] = 1;
    std::vector<double> sx(nc, 0.), sy(nc, 0.);
    for(std::size_t i = 0; i < guide_faces_.size(); ++i) {
      const int c = topo_.face_component[guide_faces_[i]];
      const double d = N_ * (guide_angles_[i] - beta[guide_faces_[i]]);
      sx[c] += std::cos(d);
      sy[c] += std::sin(d);
    }
    std::vector<double> rot(nc, 0.);
    for(std::size_t c = 0; c < nc; ++c)
      if(!hard[c] && (sx[c] != 0 || sy[c] != 0)) rot[c] = std::atan2(sy[c], sx[c]) / N_;
    for(std::size_t f = 0; f < beta.size(); ++f) beta[f] += rot[topo_.face_component[f]];
  }

  void propagate(std::vector<double>& beta, double start_angle, int special_root) const
  {
    CGAL_precondition(solved_);
    const int nf = int(m_.number_of_faces());
    beta.assign(nf, 0.);
    std::vector<int> constraint_of(nf, -1);
    for(std::size_t i = 0; i < constrained_faces_.size(); ++i) constraint_of[constrained_faces_[i]] = int(i);
    if(special_root < 0) {
      // order_ lists parents before children
      for(int f : order_) {
        const int h = parent_cross_[f];
        if(h < 0) beta[f] = constraint_of[f] >= 0 ? constraint_angles_[constraint_of[f]] : start_angle;
        else beta[f] = beta[parent_face_[f]] + connection_angle_index(h);
      }
      fit_rotation_to_guides(beta);
      wrap_field(beta);
      return;
    }
    propagate(beta, start_angle, -1);
    const int comp = topo_.face_component[special_root];
    std::vector<int> queue = {special_root};
    std::vector<char> visited(nf, 0);
    visited[special_root] = 1;
    beta[special_root] = start_angle;
    for(std::size_t head = 0; head < queue.size(); ++head) {
      const int f = queue[head];
      int h = m_.face_halfedge[f];
      for(int k = 0; k < 3; ++k, h = m_.next[h]) {
        const int g = m_.face[h ^ 1];
        if(g < 0 || visited[g]) continue;
        visited[g] = 1;
        beta[g] = beta[f] + connection_angle_index(h ^ 1);
        queue.push_back(g);
      }
    }
    CGAL_USE(comp);
    wrap_field(beta);
  }

  // Angles into [0, 2pi). Subtracting 2pi floor(b / 2pi) rather than std::fmod, which took a
  // quarter of an edit at 400k faces; the rounding is eps |b|, that of the propagation itself.
  static void wrap_field(std::vector<double>& beta)
  {
    const double two_pi = 2 * CGAL_PI;
    for(double& b : beta) {
      if(b >= 0 && b < two_pi) continue;
      b -= two_pi * std::floor(b / two_pi);
      if(b >= two_pi) b -= two_pi;
      if(b < 0) b += two_pi;
      if(b >= two_pi) b = 0;   // b was -0 or a negative value that rounds to 2 pi
    }
  }

  const TriangleMesh& tm_;
  internal::Mesh_arrays<TriangleMesh> m_;
  internal::Topology_arrays topo_;
  std::vector<internal::Generator_arrays> gens_;
  std::vector<Homology_generator<TriangleMesh>> public_gens_;
  std::vector<double> z_, K_, index_, turning_, x_;
  std::vector<double> increment_;   // Levi-Civita transport increment per halfedge
  std::vector<std::array<double, 6>> frames_;
  int N_ = 1;
  Connection_weights weights_ = COTAN_WEIGHTS;
  double clamp_ = 1e-3;
  Connection_solver solver_kind_ = CHOLMOD_NORMAL_EQUATIONS;

  std::vector<int> col_of_edge_, edge_of_col_, row_of_vertex_;
  Eigen::VectorXd W_;
  Sparse_matrix_int A_;
  Eigen::Index rows_ = 0, first_generator_row_ = 0, first_constraint_row_ = 0;
  internal::Cholmod_factor chol_;
  std::future<internal::Two_domain_ordering> vertex_order_future_;
  internal::Two_domain_ordering vertex_split_;   // order of the vertex rows
  int domain_rows_[2] = {0, 0};                  // rows in the two domains of vertex_split_
  bool vertex_order_is_amd_ = false;
  bool factored_ = false, solved_ = false;

  std::vector<int> guide_faces_;
  std::vector<double> guide_angles_;
  double guide_weight_ = 1;
  std::vector<std::vector<int>> guide_paths_;
  std::vector<std::pair<int, int>> guide_partner_;
  std::vector<std::vector<std::pair<Eigen::Index, double>>> guide_columns_;
  Eigen::SparseMatrix<double> guide_WCt_;          // W C^T
  Eigen::LDLT<Eigen::MatrixXd> guide_S_;           // S = I / lambda + C W C^T
  Eigen::MatrixXd guide_Z_;                        // L^-1 A W C^T
  Eigen::PartialPivLU<Eigen::MatrixXd> guide_G_;

  std::vector<int> constrained_faces_;
  std::vector<double> constraint_angles_;
  std::vector<std::vector<int>> constraint_paths_;
  std::vector<std::pair<int, int>> constraint_targets_;
  std::vector<int> parent_cross_, parent_face_, order_, roots_;
};

/// \ingroup PkgSurfaceMeshDirectionFieldsTrivialConnections
/// Computes the trivial connection with the given singularities in one call (see
/// `Trivial_connection`) and writes the adjustment angle of each edge, for crossing in the
/// direction of `halfedge(e)` (0 on boundary edges), to `adjustment`.
/// \tparam SingularityRange a range of `std::pair<vertex_descriptor, double>` (vertex, index);
///         may be empty when `singularity_index_map` is given
/// \tparam EdgeAngleMap a writable property map, `edge_descriptor` keys, `double` values
///
/// Named parameters: those of the `Trivial_connection` constructor, and
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{singularity_index_map}
///     \cgalParamDescription{the index of every vertex (0 for regular vertices), read at interior vertices; pairs of `singularities` override it}
///     \cgalParamType{a readable property map with `vertex_descriptor` keys and `double` values}
///     \cgalParamDefault{all indices 0}
///   \cgalParamNEnd
///   \cgalParamNBegin{generator_turning_numbers}
///     \cgalParamDescription{turning number around each generator of `tree_cotree_generators()`, in that order}
///     \cgalParamType{a range of `double` (multiples of \f$1/N\f$)}
///     \cgalParamDefault{all 0}
///   \cgalParamNEnd
///   \cgalParamNBegin{directional_constraints}
///     \cgalParamDescription{faces with a fixed field angle, see `Trivial_connection::set_directional_constraints()`}
///     \cgalParamType{a range of `std::pair<face_descriptor, double>`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{guide_directions}
///     \cgalParamDescription{soft guide directions, see `Trivial_connection::set_guide_directions()`}
///     \cgalParamType{a range of `std::pair<face_descriptor, double>`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{guide_weight}
///     \cgalParamDescription{the weight \f$\lambda\f$ of the guide directions}
///     \cgalParamType{`double`}
///     \cgalParamDefault{1}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_angle_map}
///     \cgalParamDescription{if given, receives the field angle of every face (`Trivial_connection::field_angles()`)}
///     \cgalParamType{a writable property map with `face_descriptor` keys and `double` values}
///     \cgalParamDefault{not written}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// Throws as `Trivial_connection::set_singularity()` and `Trivial_connection::solve()` do.
template <typename TriangleMesh, typename SingularityRange, typename EdgeAngleMap,
          typename NamedParameters = parameters::Default_named_parameters>
Trivial_connection_status compute_trivial_connection(const TriangleMesh& tm,
                                                     const SingularityRange& singularities,
                                                     EdgeAngleMap adjustment,
                                                     const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  Trivial_connection<TriangleMesh> tc(tm, np);
  if constexpr(!is_default_parameter<NamedParameters, internal_np::singularity_index_t>::value) {
    const auto index = get_parameter(np, internal_np::singularity_index);
    for(auto v : vertices(tm))
      if(!is_border(v, tm) && halfedge(v, tm) != boost::graph_traits<TriangleMesh>::null_halfedge()) {
        const double k = double(get(index, v));
        if(k != 0) tc.set_singularity(v, k);
      }
  }
  for(const auto& s : singularities) tc.set_singularity(s.first, s.second);
  if constexpr(!is_default_parameter<NamedParameters, internal_np::generator_turning_numbers_t>::value) {
    std::size_t i = 0;
    for(double t : get_parameter(np, internal_np::generator_turning_numbers)) tc.set_generator_turning_number(i++, t);
  }
  if constexpr(!is_default_parameter<NamedParameters, internal_np::directional_constraints_t>::value)
    tc.set_directional_constraints(get_parameter(np, internal_np::directional_constraints));
  if constexpr(!is_default_parameter<NamedParameters, internal_np::guide_directions_t>::value)
    tc.set_guide_directions(get_parameter(np, internal_np::guide_directions),
                            choose_parameter(get_parameter(np, internal_np::guide_weight), 1.));
  Trivial_connection_status st = tc.solve();
  if(st.success) {
    for(auto e : edges(tm)) put(adjustment, e, tc.adjustment_angle(halfedge(e, tm)));
    if constexpr(!is_default_parameter<NamedParameters, internal_np::face_angle_t>::value)
      tc.field_angles(get_parameter(np, internal_np::face_angle));
  }
  return st;
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_TRIVIAL_CONNECTION_H
