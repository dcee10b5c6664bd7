// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_MESH_ARRAYS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_MESH_ARRAYS_H

#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/parameters.h>
#include <CGAL/Surface_mesh_direction_fields/intrinsic_triangle.h>
#include <CGAL/Surface_mesh_direction_fields/Euclidean_edge_length_map.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <array>
#include <cmath>
#include <sstream>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

template <typename TM> struct Is_surface_mesh : std::false_type {};
template <typename P> struct Is_surface_mesh<CGAL::Surface_mesh<P>> : std::true_type {};

// Flat, index-based copy of a triangle mesh's connectivity and intrinsic metric.
// Every algorithm of the package runs on these arrays: graph traversals through the
// BGL interface cost a property-map lookup per step, which dominates at 1M faces.
// Halfedge h = 2e + s: s = 0 is halfedge(e, tm), s = 1 its opposite.
template <typename TriangleMesh>
class Mesh_arrays
{
public:
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;
  typedef typename GT::face_descriptor face_descriptor;

  std::vector<vertex_descriptor> vertices;
  std::vector<edge_descriptor> edges;
  std::vector<face_descriptor> faces;

  std::vector<int> next;        // per halfedge (border halfedges too)
  std::vector<int> target;      // per halfedge: vertex index
  std::vector<int> face;        // per halfedge: face index, -1 on the border
  std::vector<int> face_halfedge;  // per face: index of halfedge(f, tm) (the reference direction)
  std::vector<int> vertex_out;  // per vertex: outgoing halfedge; for boundary vertices the one
                                // whose opposite is a border halfedge; -1 for isolated vertices
  std::vector<double> length;   // per edge
  std::vector<double> angle;    // per halfedge: corner angle of face(h) at source(h) (0 on border)

  std::size_t number_of_vertices() const { return vertices.size(); }
  std::size_t number_of_edges() const { return edges.size(); }
  std::size_t number_of_faces() const { return faces.size(); }
  std::size_t number_of_halfedges() const { return 2 * edges.size(); }

  static int opposite(int h) { return h ^ 1; }
  static int edge(int h) { return h >> 1; }
  int prev(int h) const { return next[next[h]]; }   // triangles only
  int source(int h) const { return target[h ^ 1]; }
  bool is_border(int h) const { return face[h] < 0; }
  bool is_border_edge(int e) const { return face[2 * e] < 0 || face[2 * e + 1] < 0; }
  bool is_isolated(int v) const { return vertex_out[v] < 0; }
  bool is_boundary_vertex(int v) const { return vertex_out[v] >= 0 && face[vertex_out[v] ^ 1] < 0; }
  // Per vertex, its index among the vertices with an edge but the first one (-1 for that one and
  // for isolated vertices: systems in which a conformal factor is defined up to a constant, or a
  // curvature fixed by Gauss-Bonnet); n receives their number.
  std::vector<int> indices_but_first_vertex(int& n) const
  {
    std::vector<int> index(vertex_out.size(), -1);
    n = 0;
    bool first = true;
    for(std::size_t v = 0; v < vertex_out.size(); ++v) {
      if(vertex_out[v] < 0) continue;
      if(first) { first = false; continue; }
      index[v] = n++;
    }
    return index;
  }
  // Next outgoing halfedge counterclockwise around source(h); h must not be a border halfedge.
  int ccw_out(int h) const { return opposite(prev(h)); }
  double edge_length(int h) const { return length[h >> 1]; }

  halfedge_descriptor halfedge_descriptor_of(int h, const TriangleMesh& tm) const
  {
    halfedge_descriptor hd = halfedge(edges[h >> 1], tm);
    return (h & 1) ? CGAL::opposite(hd, tm) : hd;
  }

  // Builds connectivity only (no metric).
  explicit Mesh_arrays(const TriangleMesh& tm) { build_connectivity(tm, parameters::default_values()); }

  // Builds connectivity and the metric given by `np` (edge_length_map or vertex_point_map).
  // Simplices are numbered as the index maps of `np` say (vertex_index_map, face_index_map,
  // edge_index_map), else in iteration order.
  template <typename NamedParameters>
  Mesh_arrays(const TriangleMesh& tm, const NamedParameters& np)
  {
    build_connectivity(tm, np);
    set_lengths(tm, np);
  }

  struct Connectivity_only {};
  // Connectivity only, numbered as the index maps of `np` say.
  template <typename NamedParameters>
  Mesh_arrays(const TriangleMesh& tm, const NamedParameters& np, Connectivity_only) { build_connectivity(tm, np); }

  template <typename NamedParameters>
  void set_lengths(const TriangleMesh& tm, const NamedParameters& np)
  {
    length.resize(edges.size());
    fill_edge_lengths(tm, edges, length, np);
    compute_angles();
  }

  // Replaces the metric with explicit per-edge lengths (indexed like `edges`).
  void set_lengths(const std::vector<double>& l)
  {
    length = l;
    compute_angles();
  }

  int vertex_index(vertex_descriptor v) const
  {
    if constexpr(Is_surface_mesh<TriangleMesh>::value) { if(direct_vertices_) return int(v.idx()); }
    return get(vim_, v);
  }
  int face_index(face_descriptor f) const
  {
    if constexpr(Is_surface_mesh<TriangleMesh>::value) { if(direct_faces_) return int(f.idx()); }
    return get(fim_, f);
  }
  int halfedge_index(halfedge_descriptor h, const TriangleMesh&) const
  {
    if constexpr(Is_surface_mesh<TriangleMesh>::value) { if(direct_halfedges_) return int(h.idx()); }
    return get(him_, h);
  }
  int edge_index(edge_descriptor e, const TriangleMesh& tm) const { return halfedge_index(halfedge(e, tm), tm) >> 1; }

private:
  typedef typename boost::property_map<TriangleMesh, CGAL::dynamic_vertex_property_t<int>>::const_type VIM;
  typedef typename boost::property_map<TriangleMesh, CGAL::dynamic_face_property_t<int>>::const_type FIM;
  // Our own halfedge numbering 2e + s. (CGAL 5.5's edge index map of a Polyhedron_3 without
  // ids does not compile, so edge indices are not taken from CGAL's internal maps.)
  typedef typename boost::property_map<TriangleMesh, CGAL::dynamic_halfedge_property_t<int>>::const_type HIM;
  VIM vim_;
  FIM fim_;
  HIM him_;
  // Surface_mesh without removed elements and without user index maps: descriptors' idx()
  // already is our numbering (halfedges 2e and 2e + 1 of edge e), so no property is allocated.
  bool direct_vertices_ = false, direct_faces_ = false, direct_halfedges_ = false;

  // Lists `range` in the order of the user's index map `Tag` of `np` when given (it must number
  // the elements 0 .. n-1, each once), else in iteration order.
  template <typename Tag, typename Range, typename Descriptor, typename NamedParameters>
  static void number_elements(const Range& range, std::vector<Descriptor>& out, const NamedParameters& np,
                              Tag tag, const char* what)
  {
    out.assign(range.begin(), range.end());
    if constexpr(!parameters::is_default_parameter<NamedParameters, Tag>::value) {
      const auto index = parameters::get_parameter(np, tag);
      std::vector<Descriptor> ordered(out.size());
      std::vector<char> used(out.size(), 0);
      for(const Descriptor& d : out) {
        const auto i = get(index, d);
        if(!(i >= 0 && std::size_t(i) < out.size()) || used[std::size_t(i)]++) {
          std::ostringstream os;
          os << "the " << what << " index map gives " << i << ", which is not a distinct index in [0, "
             << out.size() << ")";
          throw Input_error(Input_error::INVALID_ARGUMENT, os.str());
        }
        ordered[std::size_t(i)] = d;
      }
      out.swap(ordered);
    }
  }

  template <typename NamedParameters>
  void build_connectivity(const TriangleMesh& tm, const NamedParameters& np)
  {
    using parameters::is_default_parameter;
    number_elements(CGAL::vertices(tm), vertices, np, CGAL::internal_np::vertex_index, "vertex");
    number_elements(CGAL::edges(tm), edges, np, CGAL::internal_np::edge_index, "edge");
    number_elements(CGAL::faces(tm), faces, np, CGAL::internal_np::face_index, "face");
    if constexpr(Is_surface_mesh<TriangleMesh>::value) {
      const bool clean = !tm.has_garbage();
      direct_vertices_ = clean && is_default_parameter<NamedParameters, CGAL::internal_np::vertex_index_t>::value;
      direct_faces_ = clean && is_default_parameter<NamedParameters, CGAL::internal_np::face_index_t>::value;
      direct_halfedges_ = clean && is_default_parameter<NamedParameters, CGAL::internal_np::edge_index_t>::value;
    }
    if(!direct_vertices_) {
      vim_ = get(CGAL::dynamic_vertex_property_t<int>(), tm);
      for(std::size_t v = 0; v < vertices.size(); ++v) put(vim_, vertices[v], int(v));
    }
    if(!direct_faces_) {
      fim_ = get(CGAL::dynamic_face_property_t<int>(), tm);
      for(std::size_t f = 0; f < faces.size(); ++f) put(fim_, faces[f], int(f));
    }
    const std::size_t nh = 2 * edges.size();
    if(!direct_halfedges_) {
      him_ = get(CGAL::dynamic_halfedge_property_t<int>(), tm);
      for(std::size_t e = 0; e < edges.size(); ++e) {
        const halfedge_descriptor h0 = halfedge(edges[e], tm);
        put(him_, h0, int(2 * e));
        put(him_, CGAL::opposite(h0, tm), int(2 * e + 1));
      }
    }
    next.assign(nh, -1);
    target.assign(nh, -1);
    face.assign(nh, -1);
    face_halfedge.assign(faces.size(), -1);
    vertex_out.assign(vertices.size(), -1);

    for(std::size_t e = 0; e < edges.size(); ++e) {
      halfedge_descriptor h0 = halfedge(edges[e], tm);
      halfedge_descriptor hs[2] = { h0, CGAL::opposite(h0, tm) };
      for(int s = 0; s < 2; ++s) {
        const int h = static_cast<int>(2 * e + s);
        target[h] = vertex_index(CGAL::target(hs[s], tm));
        next[h] = halfedge_index(CGAL::next(hs[s], tm), tm);
        face_descriptor f = CGAL::face(hs[s], tm);
        face[h] = (f == GT::null_face()) ? -1 : face_index(f);
      }
    }
    for(std::size_t f = 0; f < faces.size(); ++f) {
      const int h = halfedge_index(halfedge(faces[f], tm), tm);
      face_halfedge[f] = h;
      if(next[next[next[h]]] != h || next[h] == h || next[next[h]] == h) {
        std::size_t degree = 1;
        for(int g = next[h]; g != h && degree <= nh; g = next[g]) ++degree;
        std::ostringstream os;
        os << "face " << f << " has " << degree << " vertices; only triangle meshes are supported";
        throw Input_error(Input_error::NOT_TRIANGLE_MESH, os.str());
      }
    }
    check_vertex_fans();
  }

  // Every vertex must be a single fan (disk or half-disk); also fixes vertex_out.
  void check_vertex_fans()
  {
    std::vector<int> degree(vertices.size(), 0), border_out(vertices.size(), 0);
    const int nh = static_cast<int>(next.size());
    for(int h = 0; h < nh; ++h) {
      const int v = source(h);
      ++degree[v];
      if(vertex_out[v] < 0) vertex_out[v] = h;
      if(face[h ^ 1] < 0) {
        // outgoing halfedge whose opposite is border: start of the fan
        if(face[h] < 0) {
          std::ostringstream os;
          os << "edge " << (h >> 1) << " has no incident face";
          throw Input_error(Input_error::NON_MANIFOLD_EDGE, os.str());
        }
        ++border_out[v];
        vertex_out[v] = h;
      }
    }
    for(std::size_t v = 0; v < vertices.size(); ++v) {
      if(vertex_out[v] < 0) continue;
      if(border_out[v] > 1) {
        std::ostringstream os;
        os << "vertex " << v << " is non-manifold: " << border_out[v]
           << " boundary fans meet there (pinched vertex)";
        throw Input_error(Input_error::NON_MANIFOLD_VERTEX, os.str());
      }
      int count = 0;
      int h = vertex_out[v];
      do {
        ++count;
        if(face[h] < 0) break;          // reached the border: end of the fan
        h = ccw_out(h);
      } while(h != vertex_out[v] && count <= degree[v]);
      if(count != degree[v]) {
        std::ostringstream os;
        os << "vertex " << v << " is non-manifold: its " << degree[v]
           << " incident edges do not form a single fan";
        throw Input_error(Input_error::NON_MANIFOLD_VERTEX, os.str());
      }
    }
  }

  void compute_angles()
  {
    const int nh = static_cast<int>(next.size());
    angle.assign(nh, 0.);
    for(std::size_t f = 0; f < faces.size(); ++f) {
      const int h0 = face_halfedge[f], h1 = next[h0], h2 = next[h1];
      const double l0 = length[h0 >> 1], l1 = length[h1 >> 1], l2 = length[h2 >> 1];
      const double lmax = (std::max)(l0, (std::max)(l1, l2));
      // Relative area below 1e-14 is zero area up to the rounding of the lengths themselves.
      if(!is_valid_triangle(l0, l1, l2) || triangle_area(l0, l1, l2) <= 1e-14 * lmax * lmax) {
        std::ostringstream os;
        os.precision(17);
        os << "face " << f << " is degenerate (zero area or a zero-length edge): edge lengths "
           << l0 << ", " << l1 << ", " << l2;
        throw Input_error(Input_error::DEGENERATE_FACE, os.str());
      }
      // angle at source(h) is opposite to next(h)
      const std::array<double, 3> a = triangle_angles(l0, l1, l2);
      angle[h0] = a[1];
      angle[h1] = a[2];
      angle[h2] = a[0];
    }
  }
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_MESH_ARRAYS_H
