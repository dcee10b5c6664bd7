// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_HOLONOMY_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_HOLONOMY_H

#include <CGAL/Surface_mesh_direction_fields/intrinsic_triangle.h>
#include <CGAL/Surface_mesh_direction_fields/Intrinsic_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh_arrays.h>
#include <CGAL/Surface_mesh_direction_fields/internal/development.h>
#include <CGAL/Surface_mesh_direction_fields/internal/tree_cotree.h>
#include <CGAL/Surface_mesh_direction_fields/homology_generators.h>

#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsHolonomy
/// An orientation-preserving rigid motion of the plane, an element of \f$E(2)\f$:
/// \f$p \mapsto R(\rho)\,p + t\f$ with \f$R(\rho)\f$ the counterclockwise rotation by `rotation`.
struct Rigid_motion_2
{
  double rotation = 0;            ///< \f$\rho \in (-\pi, \pi]\f$
  Vector_2 translation = Vector_2(0, 0);   ///< \f$t\f$

  /// Applies the motion to a point.
  Point_2 operator()(const Point_2& p) const
  {
    const double c = std::cos(rotation), s = std::sin(rotation);
    return Point_2(c * p.x() - s * p.y() + translation.x(), s * p.x() + c * p.y() + translation.y());
  }
  /// Applies the rotational part to a vector.
  Vector_2 operator()(const Vector_2& v) const
  {
    const double c = std::cos(rotation), s = std::sin(rotation);
    return Vector_2(c * v.x() - s * v.y(), s * v.x() + c * v.y());
  }
  /// Composition: `(a * b)(p) == a(b(p))`.
  friend Rigid_motion_2 operator*(const Rigid_motion_2& a, const Rigid_motion_2& b)
  {
    Rigid_motion_2 r;
    r.rotation = internal::wrap_angle(a.rotation + b.rotation);
    r.translation = a(b.translation) + a.translation;
    return r;
  }
  /// The inverse motion.
  Rigid_motion_2 inverse() const
  {
    Rigid_motion_2 r;
    r.rotation = internal::wrap_angle(-rotation);
    r.translation = -r(translation);
    return r;
  }
};

/// \ingroup PkgSurfaceMeshDirectionFieldsHolonomy
/// Holonomy of the Levi-Civita connection of an intrinsic metric along dual cycles.
///
/// Tangent vectors live on faces. The frame of face \f$f\f$ has its x axis along
/// `halfedge(f, tm)` and is counterclockwise with respect to the face's orientation. Carrying a
/// direction of angle \f$\alpha_i\f$ across an edge into the next face keeps its angle with that
/// edge (Crane et al., Eq. 1):
/// \f$\alpha_j = \alpha_i - \theta_i + \theta_j\f$, where \f$\theta_i, \theta_j\f$ are the
/// directions of the shared edge (same orientation) in the two frames. The holonomy of a dual
/// cycle is the total rotation \f$\alpha_n - \alpha_0\f$ after going around, wrapped to
/// \f$(-\pi, \pi]\f$; around the dual cell of an interior vertex, traversed counterclockwise,
/// it is the angle defect mod \f$2\pi\f$.
///
/// The object precomputes all corner angles once (linear time and memory), so each holonomy
/// costs time proportional to the length of the cycle.
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
template <typename TriangleMesh>
class Intrinsic_holonomy
{
public:
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;

  /// Precomputes the metric. Named parameters as in corner_angle(): `edge_length_map`
  /// (default: Euclidean lengths from `vertex_point_map`), or `intrinsic_mesh` (an
  /// `Intrinsic_mesh` of `tm` to share instead of building one), and the index maps of
  /// `Intrinsic_mesh`.
  /// Throws `Input_error` for non-triangle faces, non-manifold vertices, and faces whose
  /// lengths are degenerate.
  template <typename NamedParameters = parameters::Default_named_parameters>
  explicit Intrinsic_holonomy(const TriangleMesh& tm,
                              const NamedParameters& np = parameters::default_values())
    : tm_(tm), im_(internal::get_intrinsic_mesh(tm, np)), m_(im_.arrays())
  {}

  /// Levi-Civita holonomy of a dual cycle (see `Homology_generator::dual_cycle` for the
  /// encoding), in \f$(-\pi, \pi]\f$. Throws `Input_error` if the sequence is not a closed
  /// dual cycle or crosses a boundary edge.
  template <typename HalfedgeRange>
  double levi_civita_holonomy(const HalfedgeRange& dual_cycle) const
  {
    const std::vector<int> c = indices(dual_cycle);
    internal::check_dual_path(m_, c, true);
    return internal::wrap_angle(internal::transport_along(m_, c));
  }

  /// Generalised holonomy of a dual cycle (Lai et al. 2010, section 3.2): the faces of the
  /// cycle are developed in the plane (unfold_triangle_strip()), which lays out the first face
  /// twice; the result is the rigid motion that maps the second copy onto the first.
  /// Its rotation equals levi_civita_holonomy() up to rounding; its translation is the
  /// translational holonomy (zero for every loop only on a translation surface).
  template <typename HalfedgeRange>
  Rigid_motion_2 generalized_holonomy(const HalfedgeRange& dual_cycle) const
  {
    const std::vector<int> c = indices(dual_cycle);
    internal::check_dual_path(m_, c, true);
    std::array<Point_2, 3> first, last;
    bool started = false;
    internal::develop(m_, c, [&](int, const std::array<Point_2, 3>& p) {
      if(!started) { first = p; started = true; }
      last = p;
    });
    const Point_2 c0 = CGAL::centroid(first[0], first[1], first[2]);
    const Point_2 c1 = CGAL::centroid(last[0], last[1], last[2]);
    double sin_sum = 0, cos_sum = 0;
    for(int i = 0; i < 3; ++i) {
      const Vector_2 a = last[i] - c1, b = first[i] - c0;
      sin_sum += a.x() * b.y() - a.y() * b.x();
      cos_sum += a.x() * b.x() + a.y() * b.y();
    }
    Rigid_motion_2 g;
    g.rotation = internal::wrap_angle(std::atan2(sin_sum, cos_sum));
    g.translation = c0 - g(c1);
    return g;
  }

  /// The dual cycle around the interior vertex `v`, counterclockwise: the halfedges leaving `v`,
  /// each crossed from its right face into its left face. Throws `Input_error` for boundary
  /// and isolated vertices.
  std::vector<halfedge_descriptor> dual_cycle_around_vertex(vertex_descriptor v) const
  {
    const int vi = m_.vertex_index(v);
    if(m_.is_isolated(vi) || m_.is_boundary_vertex(vi))
      throw Input_error(Input_error::INVALID_ARGUMENT,
                        "dual_cycle_around_vertex(): vertex " + std::to_string(vi) +
                        " is not an interior vertex");
    std::vector<halfedge_descriptor> out;
    const int h0 = m_.vertex_out[vi];
    int h = h0;
    do {
      h = m_.ccw_out(h);
      out.push_back(m_.halfedge_descriptor_of(h, tm_));
    } while(h != h0);
    return out;
  }

  /// The dual cycle that runs beside a primal edge loop on its left side (the faces around each
  /// loop vertex that lie to the left of the loop), homotopic to the loop. If the left side
  /// meets the boundary, the right side is used and the result reversed, so the orientation
  /// always follows the loop. Throws `Input_error` if `loop` is not a closed edge loop or both
  /// sides meet the boundary.
  template <typename HalfedgeRange>
  std::vector<halfedge_descriptor> dual_cycle_along_primal_loop(const HalfedgeRange& loop) const
  {
    const std::vector<int> l = indices(loop);
    if(l.empty())
      throw Input_error(Input_error::INVALID_CYCLE, "empty primal loop");
    for(std::size_t i = 0; i < l.size(); ++i)
      if(m_.target[l[i]] != m_.source(l[(i + 1) % l.size()]))
        throw Input_error(Input_error::INVALID_CYCLE,
                          "primal loop is not closed: halfedge " + std::to_string(i) +
                          " does not end where the next one starts");
    std::vector<int> d;
    if(!internal::dual_cycle_left_of(m_, l, d)) {
      std::vector<int> r;
      for(auto it = l.rbegin(); it != l.rend(); ++it) r.push_back(*it ^ 1);
      if(!internal::dual_cycle_left_of(m_, r, d))
        throw Input_error(Input_error::INVALID_CYCLE,
                          "primal loop touches the boundary on both sides");
      d = internal::reversed_dual_cycle(d);
    }
    std::vector<halfedge_descriptor> out;
    for(int h : d) out.push_back(m_.halfedge_descriptor_of(h, tm_));
    return out;
  }

  /// The homology generators of the mesh, as tree_cotree_generators() computes them, from the
  /// connectivity already stored in this object (no second pass over the mesh).
  std::vector<Homology_generator<TriangleMesh>> tree_cotree_generators() const { return im_.generators(); }

  /// The intrinsic mesh this object reads holonomies on.
  const Intrinsic_mesh<TriangleMesh>& intrinsic_mesh() const { return im_; }

  /// Generalised holonomy of a primal edge loop: that of dual_cycle_along_primal_loop().
  template <typename HalfedgeRange>
  Rigid_motion_2 generalized_holonomy_of_primal_loop(const HalfedgeRange& loop) const
  {
    return generalized_holonomy(dual_cycle_along_primal_loop(loop));
  }

private:
  template <typename HalfedgeRange>
  std::vector<int> indices(const HalfedgeRange& r) const
  {
    std::vector<int> c;
    for(auto h : r) c.push_back(m_.halfedge_index(h, tm_));
    return c;
  }

  const TriangleMesh& tm_;
  Intrinsic_mesh<TriangleMesh> im_;
  const internal::Mesh_arrays<TriangleMesh>& m_;   // im_'s arrays
};

/// \ingroup PkgSurfaceMeshDirectionFieldsHolonomy
/// Levi-Civita holonomy of one dual cycle, in \f$(-\pi, \pi]\f$; see `Intrinsic_holonomy`, which
/// should be used for many cycles on the same mesh (this function precomputes the whole metric).
/// Named parameters: `edge_length_map`, `vertex_point_map` as in corner_angle().
template <typename TriangleMesh, typename HalfedgeRange,
          typename NamedParameters = parameters::Default_named_parameters>
double levi_civita_holonomy(const TriangleMesh& tm, const HalfedgeRange& dual_cycle,
                            const NamedParameters& np = parameters::default_values())
{
  return Intrinsic_holonomy<TriangleMesh>(tm, np).levi_civita_holonomy(dual_cycle);
}

/// \ingroup PkgSurfaceMeshDirectionFieldsHolonomy
/// Generalised holonomy (an element of \f$E(2)\f$) of one dual cycle; see
/// `Intrinsic_holonomy::generalized_holonomy()`.
template <typename TriangleMesh, typename HalfedgeRange,
          typename NamedParameters = parameters::Default_named_parameters>
Rigid_motion_2 generalized_holonomy(const TriangleMesh& tm, const HalfedgeRange& dual_cycle,
                                    const NamedParameters& np = parameters::default_values())
{
  return Intrinsic_holonomy<TriangleMesh>(tm, np).generalized_holonomy(dual_cycle);
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_HOLONOMY_H
