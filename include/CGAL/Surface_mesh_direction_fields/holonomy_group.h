// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_HOLONOMY_GROUP_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_HOLONOMY_GROUP_H

// The holonomy group of a flat cone metric (Lai et al. 2010, section 3.2) and its
// compatibility tests: parallel N-RoSy fields (Theorem 3.2, Eq. 1) and planar tessellations
// (Theorem 3.5).

#include <CGAL/Surface_mesh_direction_fields/holonomy.h>
#include <CGAL/Surface_mesh_direction_fields/homotopy_basis.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsHolonomy
/// The generalised holonomy of every loop of a `Homotopy_basis` under one metric, see
/// holonomy_group().
struct Holonomy_group
{
  /// per loop of the basis: its generalised holonomy, a rigid motion of the base face's
  /// development frame (the canonical layout of `base_face`: `halfedge(base_face)` from the
  /// origin along the x axis)
  std::vector<Rigid_motion_2> motions;
  /// per loop: its rotational holonomy in \f$[0, 2\pi)\f$ (the rotation of `motions`)
  std::vector<double> rotations;
  /// per cone of the basis: its position developed into the base face's frame along the dual
  /// tree of the basis (the fixed point of its cone loop's motion)
  std::vector<Point_2> cone_positions;
};

/// \ingroup PkgSurfaceMeshDirectionFieldsHolonomy
/// Outcome of the parallel N-RoSy test, see parallel_rosy_compatibility().
struct Rosy_compatibility
{
  int N = 1;
  /// every rotational holonomy is a multiple of \f$2\pi/N\f$ up to the tolerance (Theorem 3.2:
  /// a parallel N-RoSy field exists)
  bool compatible = false;
  /// the largest distance of a rotation to the nearest multiple of \f$2\pi/N\f$ (radians)
  double max_deviation = 0;
  /// the loops (indices in the basis) whose rotation is farther than the tolerance
  std::vector<std::size_t> failing_loops;
};

/// \ingroup PkgSurfaceMeshDirectionFieldsHolonomy
/// The planar tessellations of Theorem 3.5 of Lai et al.
enum Planar_tessellation {
  SQUARE_GRID,     ///< symmetries: rotations by multiples of \f$\pi/2\f$, translations in \f$\mathbb{Z}^2\f$
  TRIANGULAR_GRID  ///< symmetries: rotations by multiples of \f$\pi/3\f$, translations in the triangular lattice
};

/// \ingroup PkgSurfaceMeshDirectionFieldsHolonomy
/// Outcome of the tessellation test, see tessellation_compatibility().
struct Tessellation_compatibility
{
  Planar_tessellation grid = SQUARE_GRID;
  /// every generalised holonomy is a symmetry of the grid placed by `spacing`, `orientation`
  /// and `origin` (Theorem 3.5: the grid can be defined on the surface)
  bool compatible = false;
  /// the grid's edge length: the largest that works (the coarsest common lattice); 0 if every
  /// translation vanishes, when any spacing works; with tessellation_compatibility_at(), the
  /// spacing tested
  double spacing = 0;
  /// angle of a grid edge in the base face's frame
  double orientation = 0;
  /// a grid vertex, in the base face's frame: the first cone's position, or the origin
  Point_2 origin = Point_2(0, 0);
  /// the largest distance of a rotation to the grid's rotations (radians)
  double max_rotation_deviation = 0;
  /// the largest distance of a loop's translation (relative to `origin`) to the lattice, in
  /// units of `spacing`, for the best lattice found
  double max_translation_deviation = 0;
  /// the loops (indices in the basis) that fail either test
  std::vector<std::size_t> failing_loops;
  /// per failing loop (as in `failing_loops`): how far its rotation is from the grid's rotations
  /// (radians) and its translation from the lattice (in units of `spacing`)
  std::vector<double> failing_rotation_deviations, failing_translation_deviations;
};

/// \ingroup PkgSurfaceMeshDirectionFieldsHolonomy
/// The generalised holonomy (rotation and translation, Lai et al. section 3.2) of every loop of
/// `basis` under the metric of the named parameters, in the frame of the base face; on a flat
/// cone metric (compute_cone_metric()) these motions generate the holonomy group of the
/// punctured surface. Also develops the cones into that frame.
///
/// Named parameters: `edge_length_map` (the metric, default: Euclidean lengths), or
/// `intrinsic_mesh`, and the index maps, as for `Intrinsic_holonomy`. Throws `Input_error` as
/// `Intrinsic_holonomy` does.
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
Holonomy_group holonomy_group(const TriangleMesh& tm, const Homotopy_basis<TriangleMesh>& basis,
                              const NamedParameters& np = parameters::default_values())
{
  const Intrinsic_holonomy<TriangleMesh> hol(tm, np);
  const internal::Mesh_arrays<TriangleMesh>& m = hol.intrinsic_mesh().arrays();
  Holonomy_group g;
  for(const auto& loop : basis.loops) {
    const Rigid_motion_2 r = hol.generalized_holonomy(loop.dual_cycle);
    g.motions.push_back(r);
    g.rotations.push_back(r.rotation < 0 ? r.rotation + 2 * CGAL_PI : r.rotation);
  }
  const int base = m.face_index(basis.base_face);
  const internal::Dual_tree<TriangleMesh> tree(m, base);
  for(const auto& v : basis.cones) {
    const int vi = m.vertex_index(v);
    const int h = m.vertex_out[std::size_t(vi)];   // interior cone: face(h) exists
    const int f = m.face[std::size_t(h)];
    const std::vector<int> path = tree.path_to(m, f);
    std::array<Point_2, 3> pos = internal::canonical_layout(m, base);
    int face = base;
    if(!path.empty())   // develop() starts in the base face, the one the first crossing leaves
      internal::develop(m, path, [&](int ff, const std::array<Point_2, 3>& p) { face = ff; pos = p; });
    int k = 0;   // the cone's place in the face's canonical order
    for(int e = m.face_halfedge[std::size_t(face)]; m.source(e) != vi; e = m.next[std::size_t(e)]) ++k;
    g.cone_positions.push_back(pos[std::size_t(k)]);
  }
  return g;
}

namespace internal {

// distance of angle a to the nearest multiple of step
inline double angle_lattice_distance(double a, double step)
{
  const double r = std::remainder(a, step);
  return std::abs(r);
}

} // namespace internal

/// \ingroup PkgSurfaceMeshDirectionFieldsHolonomy
/// Theorem 3.2 of Lai et al.: a parallel N-RoSy field exists on a flat cone metric if and only if
/// every rotational holonomy is a multiple of \f$2\pi/N\f$. Tests that on the loops of `group`
/// with the tolerance `tolerance` (radians).
inline Rosy_compatibility parallel_rosy_compatibility(const Holonomy_group& group, int N, double tolerance = 1e-6)
{
  if(N < 1) throw Input_error(Input_error::INVALID_ARGUMENT, "symmetry order N must be at least 1, got " + std::to_string(N));
  Rosy_compatibility r;
  r.N = N;
  for(std::size_t i = 0; i < group.rotations.size(); ++i) {
    const double d = internal::angle_lattice_distance(group.rotations[i], 2 * CGAL_PI / N);
    r.max_deviation = (std::max)(r.max_deviation, d);
    if(!(d <= tolerance)) r.failing_loops.push_back(i);
  }
  r.compatible = r.failing_loops.empty();
  return r;
}

/// \ingroup PkgSurfaceMeshDirectionFieldsHolonomy
/// The smallest \f$N \le\f$ `max_order` for which parallel_rosy_compatibility() holds (every
/// multiple of it works too), or 0 if there is none.
inline int smallest_parallel_rosy_order(const Holonomy_group& group, int max_order = 24, double tolerance = 1e-6)
{
  for(int N = 1; N <= max_order; ++N)
    if(parallel_rosy_compatibility(group, N, tolerance).compatible) return N;
  return 0;
}

namespace internal {

// The part of the tessellation test that does not depend on the lattice: the rotations, the
// origin and the translations t_i' = tau_i(o) - o as complex numbers; the index of the shortest
// nonzero translation (t.size() if all vanish).
struct Tessellation_translations
{
  std::vector<std::complex<double>> t;
  std::vector<char> fails;   // per loop: its rotation is not a symmetry
  std::vector<double> rotation_deviation;   // per loop: its distance to the grid's rotations
  std::size_t shortest = 0;
  std::complex<double> w;    // the lattice's second basis vector (the first is 1)
};

inline Tessellation_translations tessellation_translations(const Holonomy_group& group, Tessellation_compatibility& r,
                                                           double tolerance)
{
  typedef std::complex<double> C;
  Tessellation_translations tt;
  const double step = r.grid == SQUARE_GRID ? CGAL_PI / 2 : CGAL_PI / 3;
  tt.w = r.grid == SQUARE_GRID ? C(0, 1) : C(0.5, std::sqrt(3.) / 2);
  if(!group.cone_positions.empty()) r.origin = group.cone_positions.front();
  tt.fails.assign(group.motions.size(), 0);
  tt.t.resize(group.motions.size());
  for(std::size_t i = 0; i < group.motions.size(); ++i) {
    const double d = angle_lattice_distance(group.rotations[i], step);
    tt.rotation_deviation.push_back(d);
    r.max_rotation_deviation = (std::max)(r.max_rotation_deviation, d);
    if(!(d <= tolerance)) tt.fails[i] = 1;
    const Point_2 image = group.motions[i](r.origin);
    tt.t[i] = C(image.x() - r.origin.x(), image.y() - r.origin.y());
  }
  double scale_norm = 0;   // the largest |t'| (to make "zero" relative)
  for(const C& z : tt.t) scale_norm = (std::max)(scale_norm, std::abs(z));
  tt.shortest = tt.t.size();
  for(std::size_t i = 0; i < tt.t.size(); ++i)
    if(std::abs(tt.t[i]) > 1e-9 * (1 + scale_norm) && (tt.shortest == tt.t.size() || std::abs(tt.t[i]) < std::abs(tt.t[tt.shortest])))
      tt.shortest = i;
  return tt;
}

// distance of z to the lattice Z + Z w, in lattice units
inline double lattice_distance(std::complex<double> z, std::complex<double> w)
{
  const double b = z.imag() / w.imag();
  const double a = z.real() - b * w.real();
  double best = std::numeric_limits<double>::infinity();
  for(double da : {std::floor(a), std::ceil(a)})
    for(double db : {std::floor(b), std::ceil(b)}) best = (std::min)(best, std::abs(z - (da + db * w)));
  return best;
}

// The largest lattice distance of u t_i over the loops, or a value >= bound as soon as it
// cannot stay below bound (most candidate lattices fail on their first few loops).
inline double lattice_deviation(const Tessellation_translations& tt, std::complex<double> u, double bound)
{
  double dev = 0;
  for(const std::complex<double>& z : tt.t) {
    dev = (std::max)(dev, lattice_distance(u * z, tt.w));
    if(!(dev < bound)) break;
  }
  return dev;
}

inline void finish_tessellation_test(const Tessellation_translations& tt, std::complex<double> u, double tolerance,
                                     Tessellation_compatibility& r)
{
  std::vector<char> fails = tt.fails;
  for(std::size_t i = 0; i < tt.t.size(); ++i)
    if(!(lattice_distance(u * tt.t[i], tt.w) <= tolerance)) fails[i] = 1;
  for(std::size_t i = 0; i < fails.size(); ++i)
    if(fails[i]) {
      r.failing_loops.push_back(i);
      r.failing_rotation_deviations.push_back(tt.rotation_deviation[i]);
      r.failing_translation_deviations.push_back(lattice_distance(u * tt.t[i], tt.w));
    }
  r.compatible = r.failing_loops.empty();
}

} // namespace internal

/// \ingroup PkgSurfaceMeshDirectionFieldsHolonomy
/// Theorem 3.5 of Lai et al.: the grid can be defined on the surface if every generalised
/// holonomy is a symmetry of the grid. The rotations must be multiples of \f$\pi/2\f$
/// (\f$\pi/3\f$); the grid is then placed with a vertex at `origin` (the first cone, or the
/// origin of the base frame without cones), and the translations
/// \f$t_i' = \tau_i(o) - o\f$ of the loops must lie in one lattice of the grid's shape after the
/// best rotation and uniform scaling. The coarsest such lattice is searched among those that
/// contain the shortest \f$t_i'\f$ as a lattice vector of norm at most `max_lattice_norm` (in
/// edge lengths); a translation counts as in the lattice when it is within `tolerance` edge
/// lengths of a lattice point. For a grid of known edge length, tessellation_compatibility_at()
/// has no such bound.
inline Tessellation_compatibility tessellation_compatibility(const Holonomy_group& group, Planar_tessellation grid,
                                                             double tolerance = 1e-6, int max_lattice_norm = 8)
{
  typedef std::complex<double> C;
  Tessellation_compatibility r;
  r.grid = grid;
  const internal::Tessellation_translations tt = internal::tessellation_translations(group, r, tolerance);
  C best_u(0, 0);
  if(tt.shortest < tt.t.size()) {
    // candidate lattice vectors g for t'_shortest, by increasing norm: the first that fits is the coarsest lattice
    std::vector<C> candidates;
    for(int a = -max_lattice_norm; a <= max_lattice_norm; ++a)
      for(int b = -max_lattice_norm; b <= max_lattice_norm; ++b) {
        const C g = double(a) + double(b) * tt.w;
        if(std::abs(g) > 0.5 && std::abs(g) <= max_lattice_norm + 1e-9) candidates.push_back(g);
      }
    std::stable_sort(candidates.begin(), candidates.end(), [](const C& x, const C& y) { return std::abs(x) < std::abs(y) - 1e-12; });
    double best_deviation = std::numeric_limits<double>::infinity();
    for(const C& g : candidates) {
      const C u = g / tt.t[tt.shortest];   // maps the surface's translations to lattice coordinates
      const double dev = internal::lattice_deviation(tt, u, best_deviation - 1e-15);
      if(dev < best_deviation - 1e-15) { best_deviation = dev; best_u = u; }
      if(dev <= tolerance) break;
    }
    r.max_translation_deviation = best_deviation;
    r.spacing = 1 / std::abs(best_u);
    r.orientation = -std::arg(best_u);
  }
  internal::finish_tessellation_test(tt, best_u, tolerance, r);
  return r;
}

/// \ingroup PkgSurfaceMeshDirectionFieldsHolonomy
/// The test of tessellation_compatibility() for the grid of edge length `spacing`: whether,
/// after the best rotation, every translation \f$t_i'\f$ lies within `tolerance` edge lengths
/// of that grid's lattice. Only the orientation is searched: the lattice vectors whose norm is
/// that of the shortest \f$t_i'\f$ (O(\f$|t|\f$/`spacing`) of them, so grids of any size are
/// tested exactly). Among the orientations that fit, the one whose lattice vector is the largest
/// multiple of a primitive one is chosen, so that the grid's lines follow the metric's own
/// lattice (a cube's edges) instead of crossing it at an angle. `spacing` in the result is the
/// given one.
inline Tessellation_compatibility tessellation_compatibility_at(const Holonomy_group& group, Planar_tessellation grid,
                                                                double spacing, double tolerance = 1e-6)
{
  typedef std::complex<double> C;
  if(!(spacing > 0) || !std::isfinite(spacing))
    throw Input_error(Input_error::INVALID_ARGUMENT, "the grid spacing must be positive, got " + std::to_string(spacing));
  Tessellation_compatibility r;
  r.grid = grid;
  r.spacing = spacing;
  const internal::Tessellation_translations tt = internal::tessellation_translations(group, r, tolerance);
  C best_u(1 / spacing, 0);
  if(tt.shortest < tt.t.size()) {
    const C ts = tt.t[tt.shortest];
    const double n = std::abs(ts) / spacing;   // the norm of its lattice vector
    const bool square = grid == SQUARE_GRID;
    auto gcd = [](long x, long y) { while(y) { const long t = x % y; x = y; y = t; } return x; };
    double best_deviation = std::numeric_limits<double>::infinity();
    long best_gcd = 0;
    // lattice vectors g = a + b w with a > 0, b >= 0: one per orientation up to the grid's rotations
    for(long a = 1; a <= long(std::ceil(n + tolerance)); ++a) {
      const double da = double(a);
      const double disc = square ? n * n - da * da : 4 * n * n - 3 * da * da;
      if(disc < -4 * n * tolerance - 1e-9) continue;
      const double bb = square ? std::sqrt((std::max)(0., disc)) : (-da + std::sqrt((std::max)(0., disc))) / 2;
      const long b = std::lround(bb);
      if(b < 0) continue;
      const C g = da + double(b) * tt.w;
      if(!(std::abs(std::abs(g) - n) <= 2 * tolerance + 1e-12 * n)) continue;
      const C u = g / ts;
      const double dev = internal::lattice_deviation(tt, u, (std::max)(best_deviation, tolerance) + 1e-15);
      const long k = gcd(a, b);
      if(dev <= tolerance ? (best_deviation > tolerance || k > best_gcd) : dev < best_deviation) {
        best_deviation = dev; best_u = u; best_gcd = k;
      }
    }
    r.max_translation_deviation = best_deviation;
  }
  r.orientation = -std::arg(best_u);
  internal::finish_tessellation_test(tt, best_u, tolerance, r);
  return r;
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_HOLONOMY_GROUP_H
