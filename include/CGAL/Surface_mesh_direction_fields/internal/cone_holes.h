// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_CONE_HOLES_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_CONE_HOLES_H

// Phase 2 of compute_cone_metric() (cone_metric.h): cones of index >= 1 (Lai et al. 2010,
// section 4.1.1).

#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh_arrays.h>
#include <CGAL/Surface_mesh_direction_fields/internal/cone_metric_phases.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <map>
#include <sstream>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// Cones of index >= 1 (Lai et al. 2010, section 4.1.1): punch a hole at each, i.e.
// remove its faces; the ring of the hole becomes boundary with geodesic curvature
// kappa_w = K_w + (K_v - 2 pi) / d on each of its d vertices (Gauss-Bonnet: the hole's
// boundary turns by 2 pi - K_v less than the cone would need), then solve on the rest.
//
// The holed surface: the same vertices (punched ones isolated), the other faces, the input
// lengths; compute_cone_metric() solves it with the maps below (input_length as its
// edge_length_map, output_length, target, u as its conformal_factor_map), and map_back()
// writes the result on the input mesh.
class Holed_surface
{
public:
  typedef CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3> Holed;
  typedef Holed::Vertex_index Vertex;
  typedef Holed::Edge_index Edge;

  Holed mesh;
  Holed::Property_map<Edge, double> input_length, output_length;
  Holed::Property_map<Vertex, double> target, u;

  // Throws Input_error if a hole cannot be punched (see hole_targets()).
  template <typename TM>
  Holed_surface(const Mesh_arrays<TM>& m, const std::vector<double>& input_target,
                const std::vector<int>& punched)
  {
    const std::size_t nv = m.number_of_vertices();
    std::vector<char> removed(m.number_of_faces(), 0);
    is_punched_.assign(nv, 0);
    for(int v : punched) is_punched_[v] = 1;
    const std::vector<double> hole_target = hole_targets(m, input_target, punched, removed);
    build(m, removed, hole_target);
  }

  Holed_surface(const Holed_surface&) = delete;   // the property maps refer to `mesh`
  Holed_surface& operator=(const Holed_surface&) = delete;

  // Writes the solution on the input mesh: lengths of its edges, conformal factors (NaN at the
  // punched vertices).
  template <typename TM, typename EdgeLengthMap, typename NamedParameters>
  void map_back(const Mesh_arrays<TM>& m, EdgeLengthMap output_lengths, const NamedParameters& np) const
  {
    // back to the input: spokes of the holes and flipped-away edges have no length
    std::map<std::pair<int, int>, double> result;
    for(Edge e : edges(mesh))
      result[std::minmax(int(CGAL::source(e, mesh)), int(CGAL::target(e, mesh)))] = output_length[e];
    for(std::size_t e = 0; e < m.number_of_edges(); ++e) {
      auto it = result.find(std::minmax(m.target[2 * e], m.target[2 * e + 1]));
      put(output_lengths, m.edges[e], it == result.end() ? std::numeric_limits<double>::quiet_NaN() : it->second);
    }
    put_conformal_factors(m, np, [this](std::size_t v) {
      return is_punched_[v] ? std::numeric_limits<double>::quiet_NaN() : u[Vertex(v)];
    });
  }

private:
  std::vector<char> is_punched_;

  // The targets of the holed surface: the input's, with the geodesic curvature of the rings and
  // 0 at the punched vertices; marks the faces around the punched vertices in `removed`. Throws
  // Input_error if a ring touches the boundary or another hole, or needs kappa_w >= pi.
  template <typename TM>
  std::vector<double> hole_targets(const Mesh_arrays<TM>& m, const std::vector<double>& target,
                                   const std::vector<int>& punched, std::vector<char>& removed) const
  {
    const std::vector<char>& is_punched = is_punched_;
    std::vector<char> is_ring(m.number_of_vertices(), 0);
    std::vector<double> hole_target = target;
    for(int v : punched) {
      std::vector<int> ring;
      int h = m.vertex_out[v];
      do { ring.push_back(m.target[h]); removed[m.face[h]] = 1; h = m.ccw_out(h); } while(h != m.vertex_out[v]);
      for(int w : ring) {
        std::ostringstream os;
        os.precision(17);
        if(is_punched[w] || is_ring[w] || m.is_boundary_vertex(w)) {
          os << "cannot punch a hole at vertex " << v << " (target curvature " << target[v]
             << " >= 2*pi, a cone of index >= 1): its neighbour " << w << " is "
             << (is_punched[w] ? "another such cone" : m.is_boundary_vertex(w) ? "on the boundary"
                                                                                : "next to another such cone")
             << "; cones of index >= 1 need disjoint interior one-rings";
          throw Input_error(Input_error::INVALID_ARGUMENT, os.str());
        }
        is_ring[w] = 1;
        hole_target[w] = target[w] + (target[v] - 2 * CGAL_PI) / double(ring.size());
        if(hole_target[w] >= CGAL_PI) {
          os << "cannot punch a hole at vertex " << v << " (target curvature " << target[v]
             << "): its " << ring.size() << " neighbours would need a geodesic curvature of "
             << hole_target[w] << " >= pi each; refine the mesh around it";
          throw Input_error(Input_error::INVALID_ARGUMENT, os.str());
        }
      }
      hole_target[v] = 0;
    }
    return hole_target;
  }

  // The mesh without the removed faces, its input lengths and targets.
  template <typename TM>
  void build(const Mesh_arrays<TM>& m, const std::vector<char>& removed, const std::vector<double>& hole_target)
  {
    const std::size_t nv = m.number_of_vertices();
    for(std::size_t v = 0; v < nv; ++v) mesh.add_vertex();
    for(std::size_t f = 0; f < m.number_of_faces(); ++f) {
      if(removed[f]) continue;
      const int h0 = m.face_halfedge[f], h1 = m.next[h0];
      mesh.add_face(Vertex(m.source(h0)), Vertex(m.target[h0]), Vertex(m.target[h1]));
    }
    std::map<std::pair<int, int>, double> length;
    for(std::size_t e = 0; e < m.number_of_edges(); ++e)
      length[std::minmax(m.target[2 * e], m.target[2 * e + 1])] = m.length[e];
    input_length = mesh.add_property_map<Edge, double>("e:input_length", 0.).first;
    output_length = mesh.add_property_map<Edge, double>("e:output_length", 0.).first;
    target = mesh.add_property_map<Vertex, double>("v:target", 0.).first;
    u = mesh.add_property_map<Vertex, double>("v:u", 0.).first;
    for(Edge e : edges(mesh)) {
      const int a = int(CGAL::source(e, mesh)), b = int(CGAL::target(e, mesh));
      input_length[e] = length.at(std::minmax(a, b));
    }
    for(std::size_t v = 0; v < nv; ++v) target[Vertex(v)] = hole_target[v];
  }
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_CONE_HOLES_H
