// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Regular remeshing from flat cone metrics (Lai et al. 2010, section 5): cut and develop, and
// the square and triangular grids carried onto the surface. Checked on every result, from the
// output mesh alone: face sizes, valences (4 or 6 except at the cones, where a cone of
// curvature K has 4 - K/(pi/2) or 6 - K/(pi/3)), Euler characteristic, face count against the
// area, every output vertex on the input surface (AABB distance), no face flipped against the
// input's normal; and the failures (incompatible metric, edge length that does not divide).

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <CGAL/Surface_mesh_direction_fields/flat_development.h>
#include <CGAL/Surface_mesh_direction_fields/grid_tessellation.h>
#include <CGAL/Surface_mesh_direction_fields/tessellation_on_input.h>
#include <CGAL/Surface_mesh_direction_fields/polycube_metric.h>
#include <CGAL/Surface_mesh_direction_fields/polyhedron_compatibility.h>
#include <CGAL/Surface_mesh_direction_fields/polyhedron_remeshing.h>
#include <CGAL/Surface_mesh_direction_fields/remesh_untangling.h>
#include <CGAL/Surface_mesh_direction_fields/remeshing_cones.h>
#include <CGAL/Surface_mesh_direction_fields/remeshing_cone_separation.h>
#include <CGAL/Surface_mesh_direction_fields/integer_grid_map.h>
#include <CGAL/Surface_mesh_direction_fields/seamless_metric.h>
#include <CGAL/Surface_mesh_direction_fields/seamless_cone_moves.h>
#include <CGAL/Surface_mesh_direction_fields/seamless_intrinsic_metric.h>
#include <CGAL/Surface_mesh_direction_fields/holonomy_group.h>
#include <CGAL/Surface_mesh_direction_fields/compute_trivial_connection.h>
#include <CGAL/Surface_mesh_direction_fields/boundary_aligned_field.h>
#include <CGAL/Surface_mesh_direction_fields/Intrinsic_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/cone_metric.h>
#include <CGAL/Surface_mesh_direction_fields/intrinsic_geometry.h>
#include <CGAL/Surface_mesh_direction_fields/delaunay_refinement.h>
#include <CGAL/Surface_mesh_direction_fields/topology.h>
#include <CGAL/Surface_mesh_direction_fields/homotopy_basis.h>
#include <CGAL/Surface_mesh_direction_fields/IO/read_triangle_mesh.h>

#include <CGAL/boost/graph/IO/OFF.h>
#include <CGAL/boost/graph/IO/OBJ.h>

#include <cmath>
#include <sstream>
#include <iostream>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <set>
#include <algorithm>
#include <complex>
#include <random>
#include <string>
#include <vector>

#include "shared_meshes.h"
#include "test_util.h"
#include "mesh_generators.h"

namespace SMDF = CGAL::Surface_mesh_direction_fields;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Surface_mesh;
typedef CGAL::Polyhedron_3<K> Polyhedron;

namespace {

// The surface of the unit cube, each side cut into n x n squares of two triangles; the vertices
// inside a side moved within it at random (the metric stays the cube's: flat, eight cones of
// pi/2 at the corners).
smdf_test::Soup cube_soup(int n, unsigned seed)
{
  smdf_test::Soup s;
  std::map<std::array<long, 3>, std::size_t> index;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.3 / n, 0.3 / n);
  auto vertex = [&](std::array<long, 3> g) {
    auto it = index.find(g);
    if(it != index.end()) return it->second;
    std::array<double, 3> p;
    int inside = 0;
    for(int k = 0; k < 3; ++k) { p[std::size_t(k)] = double(g[std::size_t(k)]) / n; inside += g[std::size_t(k)] > 0 && g[std::size_t(k)] < n; }
    if(inside == 2)   // inside a side: move it within the side's plane
      for(int k = 0; k < 3; ++k) if(g[std::size_t(k)] > 0 && g[std::size_t(k)] < n) p[std::size_t(k)] += jitter(rng);
    s.points.push_back(p);
    return index[g] = s.points.size() - 1;
  };
  for(int axis = 0; axis < 3; ++axis)
    for(int side = 0; side < 2; ++side) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      for(int i = 0; i < n; ++i)
        for(int j = 0; j < n; ++j) {
          std::array<long, 3> c[4];
          const int di[4] = {0, 1, 1, 0}, dj[4] = {0, 0, 1, 1};
          for(int k = 0; k < 4; ++k) {
            c[k][std::size_t(axis)] = side * n;
            c[k][std::size_t(u)] = i + di[k];
            c[k][std::size_t(v)] = j + dj[k];
          }
          std::size_t q[4];
          for(int k = 0; k < 4; ++k) q[k] = vertex(c[k]);
          if(side == 1) { s.faces.push_back({q[0], q[1], q[2]}); s.faces.push_back({q[0], q[2], q[3]}); }   // outward normals
          else { s.faces.push_back({q[0], q[2], q[1]}); s.faces.push_back({q[0], q[3], q[2]}); }
        }
    }
  return s;
}

// The regular octahedron with vertices +-e_i, each face cut into n^2 triangles: six cones of
// 2 pi / 3.
smdf_test::Soup octahedron_soup(int n)
{
  smdf_test::Soup s;
  std::map<std::array<long, 3>, std::size_t> index;
  auto vertex = [&](std::array<long, 3> g) {   // barycentric integer coordinates times n, signed
    auto it = index.find(g);
    if(it != index.end()) return it->second;
    s.points.push_back({{double(g[0]) / n, double(g[1]) / n, double(g[2]) / n}});
    return index[g] = s.points.size() - 1;
  };
  for(int sx : {-1, 1})
    for(int sy : {-1, 1})
      for(int sz : {-1, 1}) {
        auto P = [&](long a, long b) { return vertex({{sx * a, sy * b, sz * (n - a - b)}}); };
        const bool flip = sx * sy * sz < 0;
        for(long a = 0; a < n; ++a)
          for(long b = 0; a + b < n; ++b) {
            std::vector<std::size_t> t1 = {P(a, b), P(a + 1, b), P(a, b + 1)};
            if(flip) std::swap(t1[1], t1[2]);
            s.faces.push_back(t1);
            if(a + b + 1 < n) {
              std::vector<std::size_t> t2 = {P(a + 1, b), P(a + 1, b + 1), P(a, b + 1)};
              if(flip) std::swap(t2[1], t2[2]);
              s.faces.push_back(t2);
            }
          }
      }
  return s;
}

// Area of a polygon mesh, its faces fanned into triangles.
double polygon_area(const Surface_mesh& m)
{
  double a = 0;
  for(auto f : faces(m)) {
    std::vector<K::Point_3> p;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, m), m)) p.push_back(m.point(target(h, m)));
    for(std::size_t i = 1; i + 1 < p.size(); ++i) a += std::sqrt(CGAL::squared_area(p[0], p[i], p[i + 1]));
  }
  return a;
}

double surface_area(const Surface_mesh& m)
{
  double a = 0;
  for(auto f : faces(m)) {
    const auto h = halfedge(f, m);
    a += std::sqrt(CGAL::squared_area(m.point(source(h, m)), m.point(target(h, m)), m.point(target(next(h, m), m))));
  }
  return a;
}

typedef CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_face_graph_triangle_primitive<Surface_mesh>>> Input_tree;

// The faces of `out` flipped against the input surface `in_sm` (`tree` over its faces): a face's
// area vector against the input's normals under its corners, computed here independently of the
// library's test.
std::size_t flipped_faces(const Surface_mesh& in_sm, const Surface_mesh& out, const Input_tree& tree)
{
  std::size_t flipped = 0;
  for(auto f : faces(out)) {   // the face's area vector against the input's normals under its corners
    K::Vector_3 n(0, 0, 0), under(0, 0, 0);
    std::vector<K::Point_3> p;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, out), out)) p.push_back(out.point(target(h, out)));
    for(std::size_t i = 0; i < p.size(); ++i) {
      n = n + CGAL::cross_product(p[i] - CGAL::ORIGIN, p[(i + 1) % p.size()] - CGAL::ORIGIN);
      const auto hit = tree.closest_point_and_primitive(p[i]);
      auto unit_normal = [&](Surface_mesh::Face_index g) {
        const auto h = halfedge(g, in_sm);
        const K::Vector_3 m = CGAL::normal(in_sm.point(source(h, in_sm)), in_sm.point(target(h, in_sm)), in_sm.point(target(next(h, in_sm), in_sm)));
        return m / std::sqrt(m.squared_length());
      };
      // at an input vertex (a cone), the normalised sum of its faces' unit normals; on an input
      // edge, of the two beside it; else the face's
      K::Vector_3 m = unit_normal(hit.second);
      bool at_vertex = false;
      for(auto c : CGAL::vertices_around_face(halfedge(hit.second, in_sm), in_sm))
        if(CGAL::squared_distance(in_sm.point(c), p[i]) < 1e-24) {
          at_vertex = true;
          m = K::Vector_3(0, 0, 0);
          for(auto g : CGAL::faces_around_target(halfedge(c, in_sm), in_sm)) if(g != Surface_mesh::null_face()) m = m + unit_normal(g);
        }
      for(auto h : CGAL::halfedges_around_face(halfedge(hit.second, in_sm), in_sm))
        if(!at_vertex && !CGAL::is_border(opposite(h, in_sm), in_sm) &&
           CGAL::squared_distance(K::Segment_3(in_sm.point(source(h, in_sm)), in_sm.point(target(h, in_sm))), p[i]) < 1e-24)
          m = m + unit_normal(face(opposite(h, in_sm), in_sm));
      under = under + m / std::sqrt(m.squared_length());
    }
    if(n * under <= 0 && std::getenv("SMDF_DEBUG_FLIPS")) {
      std::cerr << "flagged face " << std::size_t(f) << ": valences";
      for(auto h : CGAL::halfedges_around_face(halfedge(f, out), out)) std::cerr << " " << degree(target(h, out), out);
      std::cerr << ", cos " << n * under / std::sqrt(n.squared_length() * under.squared_length()) << ", |n| " << std::sqrt(n.squared_length()) << "\n";
    }
    flipped += n * under <= 0;
  }
  return flipped;
}

// The quads of `q` with a corner turning against the quad's own area vector (a scaled Jacobian
// of at most 0 there): not convex, or inverted.
std::size_t nonconvex_quads(const Surface_mesh& q)
{
  std::size_t count = 0;
  for(auto f : faces(q)) {
    std::vector<K::Point_3> p;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, q), q)) p.push_back(q.point(target(h, q)));
    if(p.size() != 4) continue;
    K::Vector_3 n(0, 0, 0);
    for(std::size_t i = 0; i < 4; ++i) n = n + CGAL::cross_product(p[i] - CGAL::ORIGIN, p[(i + 1) % 4] - CGAL::ORIGIN);
    bool bad = false;
    for(std::size_t i = 0; i < 4; ++i) bad = bad || CGAL::cross_product(p[(i + 1) % 4] - p[i], p[(i + 3) % 4] - p[i]) * n <= 0;
    count += bad;
  }
  return count;
}

// The faces of `out` whose area vector points against the normal of the input face nearest
// their centroid (smdf's read-back: a face bent over a ridge or around a thin part, which the
// normals under its corners miss), computed here independently of the library's test.
std::size_t flipped_at_centroid(const Surface_mesh& in_sm, const Surface_mesh& out, const Input_tree& tree)
{
  std::size_t flipped = 0;
  for(auto f : faces(out)) {
    std::vector<K::Point_3> p;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, out), out)) p.push_back(out.point(target(h, out)));
    K::Vector_3 n(0, 0, 0), c(0, 0, 0);
    for(std::size_t i = 0; i < p.size(); ++i) {
      n = n + CGAL::cross_product(p[i] - CGAL::ORIGIN, p[(i + 1) % p.size()] - CGAL::ORIGIN);
      c = c + (p[i] - CGAL::ORIGIN) / double(p.size());
    }
    const auto g = halfedge(tree.closest_point_and_primitive(CGAL::ORIGIN + c).second, in_sm);
    flipped += n * CGAL::normal(in_sm.point(source(g, in_sm)), in_sm.point(target(g, in_sm)), in_sm.point(target(next(g, in_sm), in_sm))) < 0;
  }
  return flipped;
}

// The faces of `out` with a corner whose scaled Jacobian along the normal of the input face
// nearest their centroid is at most 0 (the measure of benchmark/compare_quadriflow.py: a quad
// bent over a ridge can be convex against its own area vector and still fold by it), computed
// here independently of the library.
std::size_t folded_at_centroid(const Surface_mesh& in_sm, const Surface_mesh& out, const Input_tree& tree)
{
  std::size_t folded = 0;
  for(auto f : faces(out)) {
    std::vector<K::Point_3> p;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, out), out)) p.push_back(out.point(target(h, out)));
    K::Vector_3 c(0, 0, 0);
    for(const auto& q : p) c = c + (q - CGAL::ORIGIN) / double(p.size());
    const auto g = halfedge(tree.closest_point_and_primitive(CGAL::ORIGIN + c).second, in_sm);
    const K::Vector_3 n = CGAL::normal(in_sm.point(source(g, in_sm)), in_sm.point(target(g, in_sm)), in_sm.point(target(next(g, in_sm), in_sm)));
    bool bad = false;
    for(std::size_t i = 0; i < p.size(); ++i)
      bad = bad || CGAL::cross_product(p[(i + 1) % p.size()] - p[i], p[(i + p.size() - 1) % p.size()] - p[i]) * n <= 0;
    folded += bad;
  }
  return folded;
}

// The read-back of a remesh, from the output mesh alone.
template <typename InputMesh>
void check_remesh(const InputMesh& input, const Surface_mesh& in_sm, const Surface_mesh& out, const SMDF::Grid_tessellation_status& st,
                  int sides, const std::map<int, std::size_t>& expected_irregular, double expected_faces, const std::string& what)
{
  (void)input;
  SMDF_CHECK_MSG(st.success, what << ": " << st.message);
  if(!st.success) return;
  std::size_t wrong_size = 0;
  for(auto f : faces(out)) wrong_size += CGAL::halfedges_around_face(halfedge(f, out), out).size() != std::size_t(sides);
  const long chi_in = long(num_vertices(in_sm)) - long(num_edges(in_sm)) + long(num_faces(in_sm));
  const long chi_out = long(num_vertices(out)) - long(num_edges(out)) + long(num_faces(out));
  std::map<int, std::size_t> irregular;
  const int regular = sides == 4 ? 4 : 6;
  for(auto v : vertices(out)) {   // interior vertices (those on an open input's boundary have fewer faces)
    const int d = int(degree(v, out));
    if(d != regular && !CGAL::is_border(v, out)) ++irregular[d];
  }
  SMDF_CHECK_MSG(wrong_size == 0 && CGAL::is_valid_polygon_mesh(out), what << ": all faces have " << sides << " sides (" << wrong_size << " do not)");
  SMDF_CHECK_MSG(chi_out == chi_in, what << ": Euler characteristic " << chi_out << ", input " << chi_in);
  SMDF_CHECK_MSG(irregular == expected_irregular, what << ": the irregular vertices are those of the cones (" << irregular.size() << " valences)");
  SMDF_CHECK_MSG(std::abs(double(num_faces(out)) - expected_faces) < 1e-6 * expected_faces,
                 what << ": " << num_faces(out) << " faces, area / face area = " << expected_faces);
  // every output vertex on the input surface; no face flipped against the input's normal
  Input_tree tree(faces(in_sm).first, faces(in_sm).second, in_sm);
  double far = 0;
  for(auto v : vertices(out)) far = std::max(far, std::sqrt(tree.squared_distance(out.point(v))));
  const std::size_t flipped = flipped_faces(in_sm, out, tree), flipped_middle = flipped_at_centroid(in_sm, out, tree);
  // the output read back by CGAL's own readers (OFF and OBJ, Surface_mesh and Polyhedron_3)
  for(const char* format : {"off", "obj"}) {
    std::stringstream file;
    const bool written = std::string(format) == "off" ? CGAL::IO::write_OFF(file, out, CGAL::parameters::stream_precision(17))
                                                      : CGAL::IO::write_OBJ(file, out, CGAL::parameters::stream_precision(17));
    Surface_mesh back;
    Polyhedron pback;
    std::stringstream copy(file.str());
    const bool read = std::string(format) == "off" ? CGAL::IO::read_OFF(file, back) && CGAL::IO::read_OFF(copy, pback)
                                                   : CGAL::IO::read_OBJ(file, back) && CGAL::IO::read_OBJ(copy, pback);
    double moved = 0;
    if(read && num_vertices(back) == num_vertices(out))
      for(auto v : vertices(out)) moved = std::max(moved, std::sqrt(CGAL::squared_distance(out.point(v), back.point(v))));
    SMDF_CHECK_MSG(written && read && CGAL::is_valid_polygon_mesh(back) && CGAL::is_valid_polygon_mesh(pback) &&
                       num_vertices(back) == num_vertices(out) && num_faces(back) == num_faces(out) && num_edges(back) == num_edges(out) &&
                       num_faces(pback) == num_faces(out) && CGAL::is_closed(back) == CGAL::is_closed(out) && moved == 0,
                   what << ": written as " << format << " and read back by CGAL (Surface_mesh and Polyhedron_3): the same mesh");
  }
  SMDF_CHECK_MSG(far < 1e-12, what << ": every output vertex lies on the input surface (farthest " << far << ")");
  // the tessellation's promise is the test at the corners; the one nearest the centroid (smdf's
  // read-back) is reached by untangle_remesh(), checked where it runs (untangling())
  SMDF_CHECK_MSG(flipped == 0, what << ": no face flipped against the input surface at its corners (" << flipped << " are)");
  std::cout << what << ": " << num_vertices(out) << " vertices, " << num_faces(out) << " faces, spacing of the metric "
            << st.compatibility.spacing << ", edge length " << st.edge_length << ", " << flipped_middle
            << " faces flipped nearest their centroid" << std::endl;
}

void cube()
{
  for(int n : {3, 4}) {
    Surface_mesh mesh;
    smdf_test::soup_to_mesh(cube_soup(n, 7u + unsigned(n)), mesh);
    const auto dev = SMDF::develop_flat_metric(mesh);
    SMDF_CHECK_MSG(dev.cones().size() == 8 && dev.max_flatness_error() < 1e-12 && dev.max_pruned_motion() < 1e-9,
                   "cube: eight cones, flat elsewhere (" << dev.max_flatness_error() << "), pruned motions trivial");
    // 0.1: the metric's lattice is spanned by (1, 1) (spacing sqrt 2), and |10 + 10i| = |2 + 14i|:
    // the grid must follow the cube's edges (area exact), not cross them at an angle
    // 1: each face of the remesh has a cone at all four corners (none to read it from but a cone)
    for(double h : {1., 0.5, 0.25, 0.125, 0.1}) {
      Surface_mesh out;
      const auto st = SMDF::tessellate_flat_metric(mesh, dev, SMDF::SQUARE_GRID, h, out);
      check_remesh(mesh, mesh, out, st, 4, {{3, 8}}, 6 / (h * h), "cube n=" + std::to_string(n) + ", quads of " + std::to_string(h));
      if(h == 0.25) {   // nothing inverted or folded: untangling leaves the remesh as it is
        const Surface_mesh before = out;
        const SMDF::Untangle_status us = SMDF::untangle_remesh(mesh, out);
        bool same = true;
        for(auto v : vertices(out)) same = same && out.point(v) == before.point(v);
        SMDF_CHECK_MSG(us.success && us.inverted_before == 0 && us.folded_before == 0 && us.folded_after == 0 && us.moved_vertices == 0 && same,
                       "cube n=" << n << ": untangling a remesh with no inverted or folded face moves nothing (" << us.moved_vertices << ")");
      }
      const double ratio = polygon_area(out) / surface_area(mesh);
      SMDF_CHECK_MSG(std::abs(ratio - 1) < 1e-9, "cube n=" << n << ", quads of " << h << ": the remesh has the input's area (ratio " << ratio << ")");
    }
    Surface_mesh out;
    const auto bad = SMDF::tessellate_flat_metric(mesh, dev, SMDF::SQUARE_GRID, 0.3, out);
    SMDF_CHECK_MSG(!bad.success && bad.message.find("divide") != std::string::npos, "cube, edge length 0.3: " << bad.message);
    const auto tri = SMDF::tessellate_flat_metric(mesh, dev, SMDF::TRIANGULAR_GRID, 0.25, out);
    SMDF_CHECK_MSG(!tri.success && !tri.failing_edges.empty(), "cube with the triangular grid: incompatible (" << tri.message << ")");
  }
  // the same on a Polyhedron_3
  Polyhedron p;
  smdf_test::soup_to_mesh(cube_soup(3, 3u), p);
  Surface_mesh sm;
  smdf_test::soup_to_mesh(cube_soup(3, 3u), sm);
  const auto dev = SMDF::develop_flat_metric(p);
  Surface_mesh out;
  const auto st = SMDF::tessellate_flat_metric(p, dev, SMDF::SQUARE_GRID, 0.25, out);
  check_remesh(p, sm, out, st, 4, {{3, 8}}, 96, "cube (Polyhedron_3), quads of 0.25");
}

void octahedron()
{
  Surface_mesh mesh;
  smdf_test::soup_to_mesh(octahedron_soup(3), mesh);
  const auto dev = SMDF::develop_flat_metric(mesh);
  SMDF_CHECK_MSG(dev.cones().size() == 6, "octahedron: six cones");
  const double side = std::sqrt(2.);
  for(int k : {1, 2, 4}) {   // 1: the octahedron itself, every corner a cone
    Surface_mesh out;
    const auto st = SMDF::tessellate_flat_metric(mesh, dev, SMDF::TRIANGULAR_GRID, side / k, out);
    check_remesh(mesh, mesh, out, st, 3, {{4, 6}}, 8. * k * k, "octahedron, triangles of side/" + std::to_string(k));
  }
  Surface_mesh out;
  const auto sq = SMDF::tessellate_flat_metric(mesh, dev, SMDF::SQUARE_GRID, side / 2, out);
  SMDF_CHECK_MSG(!sq.success && !sq.failing_edges.empty(), "octahedron with the square grid: incompatible (" << sq.message << ")");
}

// A torus embedded in space whose metric is that of a flat torus: the lengths of a periodic
// planar layout of its n x m grid, cell (a, b), vertices jittered. Rectangular lattice
// (n a, 0), (0, m b); with shear, a lattice the square grid does not fit.
void flat_torus()
{
  const std::size_t n = 20, m = 12;
  Surface_mesh mesh;
  smdf_test::soup_to_mesh(smdf_test::torus_soup(n, m), mesh);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> jitter(-0.06, 0.06);
  for(double shear : {0., 0.37}) {
    std::vector<std::array<double, 2>> plane(n * m);
    for(std::size_t i = 0; i < n; ++i)
      for(std::size_t j = 0; j < m; ++j) plane[i * m + j] = {{0.25 * double(i) + jitter(rng), 0.25 * double(j) + jitter(rng)}};
    auto lengths = mesh.add_property_map<Surface_mesh::Edge_index, double>("e:flat", 0).first;
    const double L[2] = {0.25 * double(n), 0.25 * double(m)};
    for(auto e : edges(mesh)) {   // the shortest periodic difference (cells are small)
      const std::size_t a = std::size_t(source(halfedge(e, mesh), mesh)), b = std::size_t(target(halfedge(e, mesh), mesh));
      double dx = plane[b][0] - plane[a][0], dy = plane[b][1] - plane[a][1];
      const double wy = std::round(dy / L[1]);
      dy -= wy * L[1];
      dx -= wy * shear;   // going once around in v shifts u by the shear
      dx -= std::round(dx / L[0]) * L[0];
      lengths[e] = std::sqrt(dx * dx + dy * dy);
    }
    const auto dev = SMDF::develop_flat_metric(mesh, SMDF::parameters::edge_length_map(lengths));
    Surface_mesh out;
    const auto st = SMDF::tessellate_flat_metric(mesh, dev, SMDF::SQUARE_GRID, 0.5, out);
    if(shear == 0) {
      SMDF_CHECK_MSG(dev.cones().empty() && dev.max_flatness_error() < 1e-9, "flat torus: no cones (" << dev.max_flatness_error() << ")");
      check_remesh(mesh, mesh, out, st, 4, {}, 60, "flat 5 x 3 torus, quads of 0.5");
    } else {
      SMDF_CHECK_MSG(!st.success && !st.failing_edges.empty(), "sheared flat torus: the square grid does not fit (" << st.message << ")");
    }
    mesh.remove_property_map(lengths);
  }
}

// box_corner_order(): the box's own faces under a random relabelling (faces shuffled, cycles
// rotated) are recognised, and the order found maps every box face onto one of them in the same
// direction; the octahedron and a box with a face missing are not boxes.
void box_corner_order()
{
  std::vector<std::vector<int>> box;
  std::vector<std::array<int, 2>> axes;
  SMDF::internal::box_faces(box, axes);
  std::mt19937 rng(11);
  for(int trial = 0; trial < 20; ++trial) {
    std::array<int, 8> label{{0, 1, 2, 3, 4, 5, 6, 7}};
    std::shuffle(label.begin(), label.end(), rng);
    std::vector<std::vector<int>> faces;
    for(const auto& f : box) {
      std::vector<int> g;
      const std::size_t r = rng() % 4;
      for(std::size_t k = 0; k < 4; ++k) g.push_back(label[std::size_t(f[(k + r) % 4])]);
      faces.push_back(g);
    }
    std::shuffle(faces.begin(), faces.end(), rng);
    std::array<int, 8> order;
    bool ok = SMDF::box_corner_order(faces, order);
    for(const auto& f : box) {
      bool found = false;
      for(const auto& g : faces)
        for(std::size_t r = 0; r < 4; ++r) {
          bool same = true;
          for(std::size_t k = 0; k < 4; ++k) same = same && g[(k + r) % 4] == order[std::size_t(f[k])];
          found = found || same;
        }
      ok = ok && found;
    }
    SMDF_CHECK_MSG(ok, "box_corner_order: relabelled box " << trial << " recognised, its faces kept in direction");
  }
  std::array<int, 8> order;
  const std::vector<std::vector<int>> octahedron = {{0, 2, 4}, {0, 4, 3}, {0, 3, 5}, {0, 5, 2}, {1, 4, 2}, {1, 3, 4}, {1, 5, 3}, {1, 2, 5}};
  SMDF_CHECK(!SMDF::box_corner_order(octahedron, order));
  std::vector<std::vector<int>> split = box;
  split.pop_back();
  SMDF_CHECK(!SMDF::box_corner_order(split, order));
}

// Open meshes: a planar unit square under its own flat metric (four boundary corners of pi/2)
// gives 16 quads of 1/4 along its sides, a disk like the input; with a square hole of one grid
// cell whose corners are grid points, 15 quads and an annulus; with a hole whose corners are no
// grid points (at 1/3), the boundary cannot follow the grid and the failing boundary edges are
// named.
void open_square()
{
  const std::size_t n = 24;
  for(int hole = 0; hole < 3; ++hole) {
    const std::size_t lo = hole == 1 ? 6 : 8, hi = hole == 1 ? 12 : 10;   // [1/4, 1/2]^2 or [1/3, 5/12]^2
    smdf_test::Soup soup;
    for(std::size_t i = 0; i <= n; ++i)
      for(std::size_t j = 0; j <= n; ++j) soup.points.push_back({{double(i) / n, double(j) / n, 0.}});
    for(std::size_t i = 0; i < n; ++i)
      for(std::size_t j = 0; j < n; ++j) {
        if(hole && i >= lo && i < hi && j >= lo && j < hi) continue;
        const std::size_t a = i * (n + 1) + j, b = (i + 1) * (n + 1) + j;
        soup.faces.push_back({a, b, b + 1});
        soup.faces.push_back({a, b + 1, a + 1});
      }
    Surface_mesh mesh;
    smdf_test::soup_to_mesh(soup, mesh);
    // unreferenced vertices inside the hole
    std::vector<Surface_mesh::Vertex_index> isolated;
    for(auto v : vertices(mesh)) if(degree(v, mesh) == 0) isolated.push_back(v);
    for(auto v : isolated) mesh.remove_vertex(v);
    mesh.collect_garbage();
    const auto dev = SMDF::develop_flat_metric(mesh);
    Surface_mesh out;
    const auto st = SMDF::tessellate_flat_metric(mesh, dev, SMDF::SQUARE_GRID, 0.25, out);
    if(hole < 2) {
      const std::string what = hole ? "unit square with a hole of one cell, quads of 1/4" : "unit square, quads of 1/4";
      check_remesh(mesh, mesh, out, st, 4, {}, hole ? 15 : 16, what);
      SMDF_CHECK_MSG(st.euler_characteristic == 1 - hole && st.boundary_loops == std::size_t(1 + hole),
                     what << ": the input's topology (" << st.euler_characteristic << ", " << st.boundary_loops << " loops)");
    } else {
      SMDF_CHECK_MSG(!st.success && num_faces(out) == 0 && st.message.find("does not divide") != std::string::npos,
                     "square with a hole whose corners are no grid points: refused, the metric's lattice named (" << st.message << ")");
    }
  }
}

// The eight vertices extreme in the diagonal directions (+-1, +-1, +-1) seen from `center`: corner
// i of the box takes direction ((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1).
std::array<Surface_mesh::Vertex_index, 8> diagonal_corners(const Surface_mesh& mesh, const K::Vector_3& center)
{
  std::array<Surface_mesh::Vertex_index, 8> corners;
  for(int i = 0; i < 8; ++i) {
    const K::Vector_3 d((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1);
    double best = -1e300;
    for(auto v : vertices(mesh)) {
      const double x = (mesh.point(v) - (CGAL::ORIGIN + center)) * d;
      if(x > best) { best = x; corners[std::size_t(i)] = v; }
    }
  }
  return corners;
}

// Metric compensation with a box on real genus-0 meshes: the eight vertices extreme in the
// diagonal directions as corners, the box metric, then the quad remesh, read back as above.
void box_polycube(const std::string& dir)
{
  for(const char* file : {"spot_c3d.obj", "bunny_bff.obj"}) {
    Surface_mesh mesh;
    SMDF::read_triangle_mesh(dir + "/meshes/" + file, mesh);
    K::Vector_3 center(0, 0, 0);
    for(auto v : vertices(mesh)) center = center + (mesh.point(v) - CGAL::ORIGIN) / double(num_vertices(mesh));
    double extent = 0;
    for(auto v : vertices(mesh)) extent = std::max(extent, std::sqrt((mesh.point(v) - (CGAL::ORIGIN + center)).squared_length()));
    const std::array<Surface_mesh::Vertex_index, 8> corners = diagonal_corners(mesh, center);
    const bool spot = std::string(file) == "spot_c3d.obj";
    // the paths under the flat cone metric with the corners as cones of pi/2 (Lai et al.): on Spot
    // through its conformal factors (the flow free to flip edges), on the bunny through its
    // lengths on the input triangulation (the weights' angles then also the flat metric's)
    auto targets = mesh.add_property_map<Surface_mesh::Vertex_index, double>("v:target", 0.).first;
    for(auto v : corners) targets[v] = M_PI / 2;
    auto flat = mesh.add_property_map<Surface_mesh::Edge_index, double>("e:flat", 0).first;
    auto u = mesh.add_property_map<Surface_mesh::Vertex_index, double>("v:u", 0.).first;
    const auto cm = spot ? SMDF::compute_cone_metric(mesh, targets, flat, SMDF::parameters::conformal_factor_map(u))
                         : SMDF::compute_cone_metric(mesh, targets, flat, SMDF::parameters::intrinsic_edge_flips(false));
    SMDF_CHECK_MSG(cm.converged, file << ": flat cone metric " << cm.message);
    if(spot && !cm.triangulation_changed) {   // the factors scale the input's edges to the flat metric's lengths
      const SMDF::internal::Mesh_arrays<Surface_mesh> arrays(mesh, SMDF::parameters::default_values());   // Euclidean lengths
      std::vector<double> scaled;
      SMDF_CHECK(SMDF::internal::conformal_path_metric(arrays, SMDF::parameters::conformal_factor_map(u), scaled));
      double worst = 0;
      for(std::size_t e = 0; e < scaled.size(); ++e) worst = std::max(worst, std::abs(scaled[e] / flat[arrays.edges[e]] - 1));
      SMDF_CHECK_MSG(worst < 1e-12, file << ": l e^((u_i + u_j) / 2) is the flat metric's length (" << worst << ")");
    }
    const double input_area = surface_area(mesh);
    // relaxed (the default) and the plain Tutte embedding; on Spot also a fine grid
    std::map<int, double> ratio;
    for(int relax : {10, 0}) {
      for(double h : spot && relax == 10 ? std::vector<double>{extent / 16, extent / 48} : std::vector<double>{extent / 16}) {
        auto lengths = mesh.add_property_map<Surface_mesh::Edge_index, double>("e:box", 0).first;
        const auto ps = spot ? SMDF::box_polycube_metric(mesh, corners, h, lengths, SMDF::parameters::conformal_factor_map(u).number_of_iterations(relax))
                             : SMDF::box_polycube_metric(mesh, corners, h, lengths, SMDF::parameters::edge_length_map(flat).number_of_iterations(relax));
        SMDF_CHECK_MSG(ps.success, file << ": box metric: " << ps.message);
        if(!ps.success) continue;
        SMDF_CHECK_MSG((ps.relaxation_steps > 0) == (relax > 0), file << ": relaxation steps taken " << ps.relaxation_steps);
        const auto dev = SMDF::develop_flat_metric(mesh, SMDF::parameters::edge_length_map(lengths));
        SMDF_CHECK_MSG(dev.cones().size() == 8 && dev.max_flatness_error() < 1e-9,
                       file << ": the box metric has eight cones and is flat elsewhere (" << dev.cones().size() << ", " << dev.max_flatness_error() << ")");
        Surface_mesh out;
        const auto st = SMDF::tessellate_flat_metric(mesh, dev, SMDF::SQUARE_GRID, h, out);
        const auto& D = ps.dimensions;
        {   // the face-by-face test: six rectangles of D[a] / h grid edges along axis a
          std::vector<std::vector<int>> box;
          std::vector<std::array<int, 2>> axes;
          SMDF::internal::box_faces(box, axes);
          const std::vector<Surface_mesh::Vertex_index> pc(corners.begin(), corners.end());
          const auto fit = SMDF::polyhedron_compatibility(mesh, pc, box, h, SMDF::parameters::edge_length_map(lengths));
          bool sides = fit.edges.size() == 12;
          for(std::size_t k = 0; k < fit.edges.size() && sides; ++k) {
            const int axis = fit.edges[k][0] ^ fit.edges[k][1];   // one bit: the axis the edge runs along
            sides = fit.sides[k] == int(std::lround(D[std::size_t(axis == 1 ? 0 : axis == 2 ? 1 : 2)] / h));
          }
          SMDF_CHECK_MSG(fit.compatible && sides, file << ", relaxation " << relax << ", h " << h << ": the box metric reads back as six rectangles of whole grid edges (angles off by "
                                                       << fit.max_angle_deviation << ", sides by " << fit.max_side_deviation << ", " << fit.failing_faces.size()
                                                       << " faces fail, " << fit.curved_vertices << " curved; box " << D[0] / h << " " << D[1] / h << " " << D[2] / h << ")");
        }
        const double faces = 2 * (D[0] * D[1] + D[1] * D[2] + D[2] * D[0]) / (h * h);
        if(relax > 0)   // the relaxed box has the input's area, up to the rounding of its sides
          SMDF_CHECK_MSG(std::abs(faces * h * h / input_area - 1) < 2 * h * (D[0] + D[1] + D[2]) * 2 / (faces * h * h) + 1e-9,
                         file << ": the relaxed box's area " << faces * h * h << " is the input's " << input_area);
        const std::string what = std::string(file) + ", box polycube, relaxation " + std::to_string(relax) + ", quads of extent/" +
                                 std::to_string(int(std::round(extent / h)));
        std::cout << what << ": box " << D[0] / h << " x " << D[1] / h << " x " << D[2] / h << " edge lengths, path stretch "
                  << ps.max_path_stretch << ", " << ps.relaxation_steps << " relaxation steps" << std::endl;
        if(spot && relax > 0) SMDF_CHECK_MSG(st.inverted_faces == 0, what << ": no inverted face on Spot (" << st.inverted_faces << ")");
        if(st.inverted_faces == 0) check_remesh(mesh, mesh, out, st, 4, {{3, 8}}, faces, what);
        else {   // known on the bunny: one box squeezes the ears; the status must say so
          SMDF_CHECK_MSG(!st.success && st.message.find("inverted") != std::string::npos, what << ": inverted faces reported as failure");
          std::cout << what << ": " << st.inverted_faces << " of " << faces << " faces inverted in space, reported: " << st.message << std::endl;
        }
        if(num_faces(out) > 0) {
          const double r = polygon_area(out) / input_area;
          std::cout << what << ": area ratio " << r << std::endl;
          if(h == extent / 16) ratio[relax] = r;
          if(spot && relax > 0 && h < extent / 16)   // issue 13: the area within 1 % at fine resolution
            SMDF_CHECK_MSG(std::abs(r - 1) < 0.01, what << ": the remesh's area is within 1 % of the input's (" << r << ")");
        }
        mesh.remove_property_map(lengths);
      }
    }
    // the relaxation spreads the grid evenly: on Spot its remesh keeps more of the surface's area,
    // with fewer quads (the bunny's ears stay squeezed by one box either way)
    if(spot && ratio.size() == 2)
      SMDF_CHECK_MSG(std::abs(ratio[10] - 1) < std::abs(ratio[0] - 1),
                     file << ": the relaxed box loses less area (" << ratio[10] << ") than the plain Tutte embedding (" << ratio[0] << ")");
  }
}

// The octahedron as the polyhedron (Lai et al.'s 3-RoSy / triangle remeshing): six corners at
// the vertices extreme along the axes, eight equilateral triangles, the triangular grid.
void octahedron_polyhedron(const std::string& dir)
{
  Surface_mesh mesh;
  SMDF::read_triangle_mesh(dir + "/meshes/spot_c3d.obj", mesh);
  std::vector<Surface_mesh::Vertex_index> corners(6);
  double extent = 0;
  for(int i = 0; i < 6; ++i) {
    K::Vector_3 d(i / 2 == 0 ? 1 : 0, i / 2 == 1 ? 1 : 0, i / 2 == 2 ? 1 : 0);
    if(i % 2) d = -d;
    double best = -1e300;
    for(auto v : vertices(mesh)) {
      const double x = (mesh.point(v) - CGAL::ORIGIN) * d;
      if(x > best) { best = x; corners[std::size_t(i)] = v; }
    }
    extent = std::max(extent, best);
  }
  std::vector<std::vector<int>> faces;
  for(int sx : {1, -1})
    for(int sy : {1, -1})
      for(int sz : {1, -1}) {
        const int X = sx > 0 ? 0 : 1, Y = sy > 0 ? 2 : 3, Z = sz > 0 ? 4 : 5;
        faces.push_back(sx * sy * sz > 0 ? std::vector<int>{X, Y, Z} : std::vector<int>{X, Z, Y});
      }
  auto targets = mesh.add_property_map<Surface_mesh::Vertex_index, double>("v:octa", 0.).first;
  for(auto v : corners) targets[v] = 2 * M_PI / 3;
  auto flat = mesh.add_property_map<Surface_mesh::Edge_index, double>("e:octa_flat", 0).first;
  auto u = mesh.add_property_map<Surface_mesh::Vertex_index, double>("v:octa_u", 0.).first;
  const auto cm = SMDF::compute_cone_metric(mesh, targets, flat, SMDF::parameters::conformal_factor_map(u));
  SMDF_CHECK_MSG(cm.converged, "spot, octahedron cones: " << cm.message);
  const double h = extent / 8, side = 6 * h;
  auto lengths = mesh.add_property_map<Surface_mesh::Edge_index, double>("e:octa", 0).first;
  const auto ps = SMDF::polyhedron_metric(mesh, corners, faces, side, lengths, SMDF::parameters::conformal_factor_map(u));
  SMDF_CHECK_MSG(ps.success, "spot, octahedron metric: " << ps.message);
  if(!ps.success) return;
  const auto dev = SMDF::develop_flat_metric(mesh, SMDF::parameters::edge_length_map(lengths));
  SMDF_CHECK_MSG(dev.cones().size() == 6 && dev.max_flatness_error() < 1e-9, "spot, octahedron metric: six cones, flat elsewhere");
  Surface_mesh out;
  const auto st = SMDF::tessellate_flat_metric(mesh, dev, SMDF::TRIANGULAR_GRID, h, out);
  const std::string what = "spot, octahedron polyhedron, triangles of side/6";
  if(st.inverted_faces == 0) check_remesh(mesh, mesh, out, st, 3, {{4, 6}}, 8 * 36, what);
  else SMDF_CHECK_MSG(!st.success && st.message.find("inverted") != std::string::npos, what << ": inverted faces reported as failure");
  std::cout << what << ": path stretch " << ps.max_path_stretch << ", " << st.inverted_faces << " inverted faces" << std::endl;
  {   // at a fine grid (issue 13: area within 1 %): P of the surface's area, 40 grid edges a side,
      // 12,800 triangles, inverted ones unfolded along the surface, then the full read-back
    const double area = surface_area(mesh), fine_side = std::sqrt(area / (2 * std::sqrt(3.))), fh = fine_side / 40;
    auto fine = mesh.add_property_map<Surface_mesh::Edge_index, double>("e:octa_fine", 0).first;
    const auto fs = SMDF::polyhedron_metric(mesh, corners, faces, fine_side, fine, SMDF::parameters::conformal_factor_map(u));
    SMDF_CHECK_MSG(fs.success, "spot, octahedron metric of the surface's area: " << fs.message);
    const auto fdev = SMDF::develop_flat_metric(mesh, SMDF::parameters::edge_length_map(fine));
    Surface_mesh fout;
    SMDF::Grid_tessellation_status fst = SMDF::tessellate_flat_metric(mesh, fdev, SMDF::TRIANGULAR_GRID, fh, fout);
    const std::string fwhat = "spot, octahedron polyhedron, 40 triangles a side";
    std::size_t grid_inverted = fst.inverted_faces;
    if(!fst.success && fst.inverted_faces > 0) {
      auto held = fout.add_property_map<Surface_mesh::Vertex_index, bool>("v:held", false).first;
      for(const auto& iv : fst.irregular_vertices) held[Surface_mesh::Vertex_index(Surface_mesh::size_type(iv.first))] = true;
      const SMDF::Untangle_status us = SMDF::untangle_remesh(mesh, fout, SMDF::parameters::vertex_is_constrained_map(held));
      fst.success = us.success;
      fst.inverted_faces = us.inverted_after;
      std::cout << fwhat << ": untangling " << us.inverted_before << " -> " << us.inverted_after << " (" << us.straddling_faces
                << " across a thin part or tip, " << us.faces_at_held_vertices << " next to a cone), " << us.moved_vertices << " moved" << std::endl;
      // known: one triangle of the 18, next to a cone, stays inverted (reported, the grid left as it was)
      SMDF_CHECK_MSG(us.success || (us.moved_vertices == 0 && us.inverted_after > 0 && us.inverted_after < us.inverted_before &&
                                    us.message.find("left as the grid made it") != std::string::npos),
                     fwhat << ": untangled, or the failure reported with the grid unmoved: " << us.message);
    }
    if(fst.success) check_remesh(mesh, mesh, fout, fst, 3, {{4, 6}}, 8 * 1600, fwhat);
    const double r = polygon_area(fout) / area;
    SMDF_CHECK_MSG(std::abs(r - 1) < 0.01, fwhat << ": the remesh's area is within 1 % of the input's (" << r << ")");
    std::cout << fwhat << ": " << grid_inverted << " inverted in the grid, area ratio " << r << std::endl;
  }
  // a polyhedron that is not a sphere, and a polygon that is neither a triangle nor a square
  bool threw = false;
  try { SMDF::polyhedron_metric(mesh, corners, std::vector<std::vector<int>>(faces.begin(), faces.begin() + 4), side, lengths); }
  catch(const SMDF::Input_error&) { threw = true; }
  SMDF_CHECK_MSG(threw, "an open polyhedron is refused");
  threw = false;
  try { SMDF::polyhedron_metric(mesh, corners, {{0, 2, 1, 3, 4}}, side, lengths); } catch(const SMDF::Input_error&) { threw = true; }
  SMDF_CHECK_MSG(threw, "a pentagon is refused");
}

// The paper's obelisk (Lai et al., Figure 1c and d): a box of four squares on a square base with
// a pyramid of four equilateral triangles on top; cones of pi/2 at the base, pi/3 at the middle
// ring, 2 pi/3 at the apex. The mixed remesh: quads on the box, triangles on the pyramid,
// valence 5 along the ring, each corner the number of its faces.
void obelisk(const std::string& dir)
{
  Surface_mesh mesh;
  SMDF::read_triangle_mesh(dir + "/meshes/spot_c3d.obj", mesh);
  K::Vector_3 center(0, 0, 0);
  for(auto v : vertices(mesh)) center = center + (mesh.point(v) - CGAL::ORIGIN) / double(num_vertices(mesh));
  std::vector<K::Vector_3> dirs;
  for(double y : {-1., 0.5})
    for(int i = 0; i < 4; ++i) dirs.push_back(K::Vector_3(std::cos(M_PI / 4 + i * M_PI / 2), y, std::sin(M_PI / 4 + i * M_PI / 2)));
  dirs.push_back(K::Vector_3(0, 1, 0));
  std::vector<Surface_mesh::Vertex_index> corners;
  for(const auto& d : dirs) {
    double best = -1e300;
    Surface_mesh::Vertex_index pick;
    for(auto v : vertices(mesh)) {
      const double x = (mesh.point(v) - (CGAL::ORIGIN + center)) * d;
      if(x > best && std::find(corners.begin(), corners.end(), v) == corners.end()) { best = x; pick = v; }
    }
    corners.push_back(pick);
  }
  std::vector<std::vector<int>> pfaces = {{0, 1, 2, 3}};   // the base, then the sides and the pyramid
  for(int i = 0; i < 4; ++i) pfaces.push_back({i, 4 + i, 4 + (i + 1) % 4, (i + 1) % 4});
  for(int i = 0; i < 4; ++i) pfaces.push_back({4 + i, 8, 4 + (i + 1) % 4});
  auto targets = mesh.add_property_map<Surface_mesh::Vertex_index, double>("v:obelisk", 0.).first;
  for(int i = 0; i < 9; ++i) targets[corners[std::size_t(i)]] = i < 4 ? M_PI / 2 : i < 8 ? M_PI / 3 : 2 * M_PI / 3;
  auto flat = mesh.add_property_map<Surface_mesh::Edge_index, double>("e:obelisk_flat", 0).first;
  const auto cm = SMDF::compute_cone_metric(mesh, targets, flat, SMDF::parameters::intrinsic_edge_flips(false));
  SMDF_CHECK_MSG(cm.converged, "spot, obelisk cones: " << cm.message);
  for(int n : {3, 6, 20}) {
    Surface_mesh out;
    const auto st = SMDF::polyhedron_remesh(mesh, corners, pfaces, n, out, SMDF::parameters::edge_length_map(flat));
    const std::string what = "spot, obelisk, " + std::to_string(n) + " grid edges per side";
    SMDF_CHECK_MSG(st.metric.success, what << ": " << st.message);
    if(!st.metric.success) continue;
    std::map<std::size_t, std::size_t> sides, valence;
    for(auto f : faces(out)) ++sides[CGAL::halfedges_around_face(halfedge(f, out), out).size()];
    for(auto v : vertices(out)) ++valence[degree(v, out)];
    const long chi = long(num_vertices(out)) - long(num_edges(out)) + long(num_faces(out));
    // base corners 3, ring and apex 4, ring edges 5 (4 (n - 1) points), pyramid inside 6
    const std::size_t n1 = std::size_t(n - 1);
    const std::size_t tri_inner = n >= 3 ? std::size_t((n - 1) * (n - 2) / 2) : 0;
    SMDF_CHECK_MSG(sides[4] == std::size_t(5 * n * n) && sides[3] == std::size_t(4 * n * n) && sides.size() == 2,
                   what << ": " << sides[4] << " quads on the box, " << sides[3] << " triangles on the pyramid");
    SMDF_CHECK_MSG(chi == 2 && CGAL::is_valid_polygon_mesh(out), what << ": a valid sphere (chi " << chi << ")");
    SMDF_CHECK_MSG(valence[3] == 4 && valence[5] == 4 * n1 && valence[6] == 4 * tri_inner + 4 * n1 && st.unexpected_valences == 0,
                   what << ": valences 3 (base corners), 5 (ring), 6 (pyramid): " << valence[3] << ", " << valence[5] << ", " << valence[6]);
    Input_tree tree(faces(mesh).first, faces(mesh).second, mesh);
    double far = 0;
    for(auto v : vertices(out)) far = std::max(far, std::sqrt(tree.squared_distance(out.point(v))));
    SMDF_CHECK_MSG(far < 1e-12, what << ": every output vertex on the input surface (" << far << ")");
    SMDF_CHECK_MSG(st.success == (st.inverted_faces == 0), what << ": success unless faces are inverted (" << st.inverted_faces << ")");
    SMDF_CHECK_MSG(chi == 2 && num_faces(out) == std::size_t(9 * n * n), what << ": all faces there");
    // the read-back of the metric (the mixed grid's Theorem 3.5 test): every face of P a whole grid polygon of n edges a side
    const auto& pc = st.compatibility;
    SMDF_CHECK_MSG(pc.compatible && pc.failing_faces.empty() && pc.curved_vertices == 0 && pc.max_angle_deviation < 1e-9 &&
                       pc.max_side_deviation < 1e-9 && pc.edges.size() == 16 && std::count(pc.sides.begin(), pc.sides.end(), n) == 16,
                   what << ": the metric read back as P's faces of " << n << " edges a side (angles off by " << pc.max_angle_deviation
                        << ", sides by " << pc.max_side_deviation << ", " << pc.curved_vertices << " vertices not flat)");
    if(n == 20) {   // fine (issue 13: area within 1 %), inverted faces unfolded along the surface
      std::size_t left = st.inverted_faces;
      if(st.inverted_faces > 0) {
        // as smdf remesh: P's corners held first; if faces next to one stay inverted (the apex
        // on Spot's horn tip, which the flat metric shrinks below a face), the corners slide too
        auto held = out.add_property_map<Surface_mesh::Vertex_index, bool>("v:held", false).first;
        std::vector<Surface_mesh::Vertex_index> at_corner;
        for(auto v : vertices(out))
          for(auto c : corners)
            if(out.point(v) == mesh.point(c)) { held[v] = true; at_corner.push_back(v); }
        SMDF_CHECK_MSG(at_corner.size() == 9, what << ": P's nine corners are output vertices (" << at_corner.size() << ")");
        auto degrees = [&out] { std::vector<std::size_t> d; for(auto v : vertices(out)) d.push_back(degree(v, out)); return d; };
        const std::vector<std::size_t> valence_before = degrees();
        SMDF::Untangle_status us = SMDF::untangle_remesh(mesh, out, SMDF::parameters::vertex_is_constrained_map(held));
        std::cout << what << ": untangling, corners held: " << us.inverted_before << " -> " << us.inverted_after << " (" << us.straddling_faces
                  << " across a thin part or tip, " << us.faces_at_held_vertices << " next to a corner)" << std::endl;
        SMDF_CHECK_MSG(us.success || (us.moved_vertices == 0 && us.inverted_after > 0 && us.message.find("left as the grid made it") != std::string::npos),
                       what << ": untangled, or the failure reported with the grid unmoved: " << us.message);
        if(!us.success && us.faces_at_held_vertices > 0) {
          for(auto v : at_corner) held[v] = false;
          us = SMDF::untangle_remesh(mesh, out, SMDF::parameters::vertex_is_constrained_map(held));
          std::cout << what << ": untangling, corners free: " << us.inverted_before << " -> " << us.inverted_after << ", "
                    << us.moved_vertices << " moved, at most " << us.max_displacement << " edge lengths" << std::endl;
        }
        left = us.inverted_after;
        SMDF_CHECK_MSG(us.success && left == 0 && degrees() == valence_before,
                       what << ": untangled, connectivity kept: " << us.message);
        double far2 = 0;
        for(auto v : vertices(out)) far2 = std::max(far2, std::sqrt(tree.squared_distance(out.point(v))));
        SMDF_CHECK_MSG(far2 < 1e-12, what << ": after untangling every output vertex still on the input surface (" << far2 << ")");
        SMDF_CHECK_MSG(flipped_faces(mesh, out, tree) == 0, what << ": the independent check finds no inverted face after untangling");
      }
      const double r = polygon_area(out) / surface_area(mesh);
      SMDF_CHECK_MSG(std::abs(r - 1) < 0.01, what << ": area within 1 % of the input's (" << r << "; " << st.inverted_faces << " inverted in the grid, "
                                                  << left << " after untangling)");
    }
    std::cout << what << ": " << sides[4] << " quads, " << sides[3] << " triangles, " << st.inverted_faces << " inverted, path stretch "
              << st.metric.max_path_stretch << "; read back: angles off by " << pc.max_angle_deviation << ", sides by " << pc.max_side_deviation
              << std::endl;
  }
  // The test itself (polyhedron_compatibility()) on metrics it must refuse and accept:
  // P's metric of side L at the edge length L / 4 (compatible) and L / 4.5 (every side half an
  // edge off, so every face fails); the flow's flat cone metric with P's cones (flat elsewhere,
  // but its pieces are not squares and triangles); the input's own metric (curved everywhere).
  auto pm = mesh.add_property_map<Surface_mesh::Edge_index, double>("e:obelisk_p", 0).first;
  const double L = 0.8;
  const auto ps = SMDF::polyhedron_metric(mesh, corners, pfaces, L, pm, SMDF::parameters::edge_length_map(flat));
  SMDF_CHECK_MSG(ps.success, "spot, obelisk polyhedron metric: " << ps.message);
  const auto fit = SMDF::polyhedron_compatibility(mesh, corners, pfaces, L / 4, SMDF::parameters::edge_length_map(pm));
  SMDF_CHECK_MSG(fit.compatible && std::count(fit.sides.begin(), fit.sides.end(), 4) == 16,
                 "obelisk metric at L / 4: compatible, sides of 4 (" << fit.max_angle_deviation << ", " << fit.max_side_deviation << ")");
  const auto half = SMDF::polyhedron_compatibility(mesh, corners, pfaces, L / 4.5, SMDF::parameters::edge_length_map(pm));
  SMDF_CHECK_MSG(!half.compatible && half.failing_faces.size() == 9 && std::abs(half.max_side_deviation - 0.5) < 1e-6 &&
                     half.max_angle_deviation < 1e-9 && half.failing_face_side_deviations.size() == 9,
                 "obelisk metric at L / 4.5: all 9 faces fail by half an edge (" << half.failing_faces.size() << ", " << half.max_side_deviation << ")");
  const auto flow = SMDF::polyhedron_compatibility(mesh, corners, pfaces, L / 4, SMDF::parameters::edge_length_map(flat));
  SMDF_CHECK_MSG(!flow.compatible && flow.curved_vertices == 0 && flow.max_angle_deviation > 1e-3 && !flow.failing_faces.empty(),
                 "flat cone metric with the obelisk's cones: flat elsewhere (" << flow.max_curvature_elsewhere << ") but not P's faces (angles off by "
                     << flow.max_angle_deviation << ", " << flow.failing_faces.size() << " faces)");
  const auto euclid = SMDF::polyhedron_compatibility(mesh, corners, pfaces, L / 4);
  SMDF_CHECK_MSG(!euclid.compatible && euclid.curved_vertices > num_vertices(mesh) / 2,
                 "the input's metric: curved at " << euclid.curved_vertices << " vertices (" << euclid.message << ")");
  std::cout << "polyhedron_compatibility on spot's obelisk: P's metric at L/4 passes, at L/4.5 " << half.failing_faces.size()
            << " faces fail by " << half.max_side_deviation << " edge; the flow's metric fails " << flow.failing_faces.size()
            << " faces (angles off by up to " << flow.max_angle_deviation << " rad)" << std::endl;
  bool threw = false;
  try { SMDF::polyhedron_compatibility(mesh, corners, pfaces, 0.); } catch(const SMDF::Input_error&) { threw = true; }
  SMDF_CHECK_MSG(threw, "an edge length of 0 is an Input_error");
}

// The flat cone metric with cones of pi/2 at the eight diagonal corners seen from the origin,
// edge flips allowed: the corners, the flow's status and its conformal factors (map "v:u").
struct Box_cone_metric
{
  std::array<Surface_mesh::Vertex_index, 8> corners;
  SMDF::Cone_metric_status status;
  Surface_mesh::Property_map<Surface_mesh::Vertex_index, double> u;
};
Box_cone_metric box_cone_metric(Surface_mesh& mesh)
{
  Box_cone_metric b;
  b.corners = diagonal_corners(mesh, K::Vector_3(0, 0, 0));
  auto targets = mesh.add_property_map<Surface_mesh::Vertex_index, double>("v:target", 0.).first;
  for(auto v : b.corners) targets[v] = M_PI / 2;
  auto flat = mesh.add_property_map<Surface_mesh::Edge_index, double>("e:flat", 0).first;
  b.u = mesh.add_property_map<Surface_mesh::Vertex_index, double>("v:u", 0.).first;
  b.status = SMDF::compute_cone_metric(mesh, targets, flat, SMDF::parameters::conformal_factor_map(b.u));
  return b;
}

// Lai et al.'s segments (segment_flattening(RICCI_FLOW_SEGMENTS)) against the relaxed ones, on
// Spot's box: both metrics read back as six rectangles of whole grid edges; the two segments
// beside a path disagree on where its vertices lie (the gap the mean closes); the Ricci
// segments, conformal maps, spread the areas more (measured on the output lengths alone); the
// remesh of the Ricci metric passes the full read-back.
void ricci_flow_segments(const std::string& dir)
{
  Surface_mesh mesh;
  SMDF::read_triangle_mesh(dir + "/meshes/spot_c3d.obj", mesh);
  const Box_cone_metric box = box_cone_metric(mesh);
  SMDF_CHECK_MSG(box.status.converged, "spot, 8 cones: flat cone metric " << box.status.message);
  const double input_area = surface_area(mesh), h = std::sqrt(input_area / 1500);
  std::map<SMDF::Segment_flattening, double> angle_error, area_spread;
  for(SMDF::Segment_flattening method : {SMDF::RELAXED_SEGMENTS, SMDF::RICCI_FLOW_SEGMENTS}) {
    const bool ricci = method == SMDF::RICCI_FLOW_SEGMENTS;
    const std::string what = std::string("spot, box, ") + (ricci ? "Ricci flow segments" : "relaxed segments");
    auto lengths = mesh.add_property_map<Surface_mesh::Edge_index, double>("e:segments", 0).first;
    const auto ps = SMDF::box_polycube_metric(mesh, box.corners, h, lengths, SMDF::parameters::conformal_factor_map(box.u).segment_flattening(method));
    SMDF_CHECK_MSG(ps.success, what << ": " << ps.message);
    if(!ps.success) continue;
    if(ricci)
      SMDF_CHECK_MSG(ps.relaxation_steps == 0 && ps.max_side_parameter_gap > 1e-3 && ps.max_side_parameter_gap < 0.5,
                     what << ": no relaxation, and the two segments beside a path place its vertices apart (" << ps.max_side_parameter_gap << " of the edge)");
    else
      SMDF_CHECK_MSG(ps.max_side_parameter_gap == 0, what << ": no side gap reported");
    std::vector<std::vector<int>> pfaces;
    std::vector<std::array<int, 2>> axes;
    SMDF::internal::box_faces(pfaces, axes);
    const std::vector<Surface_mesh::Vertex_index> pc(box.corners.begin(), box.corners.end());
    const auto fit = SMDF::polyhedron_compatibility(mesh, pc, pfaces, h, SMDF::parameters::edge_length_map(lengths));
    SMDF_CHECK_MSG(fit.compatible && fit.edges.size() == 12, what << ": reads back as six rectangles of whole grid edges (angles off by "
                                                               << fit.max_angle_deviation << ", sides by " << fit.max_side_deviation << ")");
    // the metric's corner angles against the input's, and the spread of its triangles' areas
    double angle_sum = 0, log_sum = 0, log_sq = 0;
    std::size_t corners_seen = 0;
    for(auto f : faces(mesh)) {
      double l[3], e[3];
      int k = 0;
      for(auto hd : CGAL::halfedges_around_face(halfedge(f, mesh), mesh)) {
        l[k] = lengths[edge(hd, mesh)];
        e[k] = std::sqrt(CGAL::squared_distance(mesh.point(source(hd, mesh)), mesh.point(target(hd, mesh))));
        ++k;
      }
      auto angle = [](const double* x, int i) {   // the angle opposite side i
        const double a = x[i], b = x[(i + 1) % 3], c = x[(i + 2) % 3];
        return std::acos(std::max(-1., std::min(1., (b * b + c * c - a * a) / (2 * b * c))));
      };
      for(int i = 0; i < 3; ++i) { angle_sum += std::abs(angle(l, i) - angle(e, i)); ++corners_seen; }
      auto area = [](const double* x) { const double s = 0.5 * (x[0] + x[1] + x[2]); return std::sqrt(std::max(0., s * (s - x[0]) * (s - x[1]) * (s - x[2]))); };
      const double r = std::log(area(l) / area(e));
      log_sum += r;
      log_sq += r * r;
    }
    const double n = double(num_faces(mesh));
    angle_error[method] = angle_sum / double(corners_seen);
    area_spread[method] = std::sqrt(std::max(0., log_sq / n - (log_sum / n) * (log_sum / n)));
    // the remesh, its inverted quads (if any) unfolded along the surface, then the full read-back
    const auto dev = SMDF::develop_flat_metric(mesh, SMDF::parameters::edge_length_map(lengths));
    Surface_mesh out;
    SMDF::Grid_tessellation_status st = SMDF::tessellate_flat_metric(mesh, dev, SMDF::SQUARE_GRID, h, out);
    if(!st.success && st.inverted_faces > 0) {
      auto held = out.add_property_map<Surface_mesh::Vertex_index, bool>("v:held", false).first;
      for(const auto& iv : st.irregular_vertices) held[Surface_mesh::Vertex_index(Surface_mesh::size_type(iv.first))] = true;
      const SMDF::Untangle_status us = SMDF::untangle_remesh(mesh, out, SMDF::parameters::vertex_is_constrained_map(held));
      std::cout << what << ": untangling " << us.inverted_before << " -> " << us.inverted_after << std::endl;
      st.success = us.success;
      st.inverted_faces = us.inverted_after;
    }
    const auto& D = ps.dimensions;
    check_remesh(mesh, mesh, out, st, 4, {{3, 8}}, 2 * (D[0] * D[1] + D[1] * D[2] + D[2] * D[0]) / (h * h), what);
    std::cout << what << ": mean angle error " << angle_error[method] << " rad, spread of log area ratios " << area_spread[method]
              << ", side gap " << ps.max_side_parameter_gap << ", area ratio " << (num_faces(out) ? polygon_area(out) / input_area : 0.) << std::endl;
    mesh.remove_property_map(lengths);
  }
  if(area_spread.size() == 2)
    SMDF_CHECK_MSG(area_spread[SMDF::RICCI_FLOW_SEGMENTS] > area_spread[SMDF::RELAXED_SEGMENTS],
                   "spot, box: the Ricci flow segments (conformal) spread the areas more (" << area_spread[SMDF::RICCI_FLOW_SEGMENTS] << " against "
                       << area_spread[SMDF::RELAXED_SEGMENTS] << ")");
  // On a cube whose six faces are the segments (flat squares with straight sides), the Ricci
  // flow has nothing to change: the two segments beside an edge agree, and the cube's edges keep
  // their lengths in the metric.
  Surface_mesh cube;
  smdf_test::soup_to_mesh(cube_soup(4, 11u), cube);
  std::array<Surface_mesh::Vertex_index, 8> cc;
  for(auto v : vertices(cube)) {
    const K::Point_3& p = cube.point(v);
    if((p.x() == 0 || p.x() == 1) && (p.y() == 0 || p.y() == 1) && (p.z() == 0 || p.z() == 1))
      cc[std::size_t(int(p.x()) + 2 * int(p.y()) + 4 * int(p.z()))] = v;
  }
  auto cl = cube.add_property_map<Surface_mesh::Edge_index, double>("e:segments", 0).first;
  const auto cs = SMDF::box_polycube_metric(cube, cc, 0.25, cl, SMDF::parameters::segment_flattening(SMDF::RICCI_FLOW_SEGMENTS));
  double worst = 0;
  std::size_t on_edges = 0;
  for(auto e : edges(cube)) {
    const K::Point_3 &p = cube.point(source(halfedge(e, cube), cube)), &q = cube.point(target(halfedge(e, cube), cube));
    int shared = 0;   // coordinates at 0 or 1 in both: two for a piece of a cube edge
    for(int k = 0; k < 3; ++k) shared += p[k] == q[k] && (p[k] == 0 || p[k] == 1);
    if(shared < 2) continue;
    ++on_edges;
    worst = std::max(worst, std::abs(cl[e] - std::sqrt(CGAL::squared_distance(p, q))));
  }
  SMDF_CHECK_MSG(cs.success && cs.max_side_parameter_gap < 1e-9 && on_edges == 48 && worst < 1e-9,
                 "cube, Ricci flow segments: the sides agree (gap " << cs.max_side_parameter_gap << ") and the cube's " << on_edges
                     << " edge pieces keep their lengths (off by " << worst << "): " << cs.message);
}

// The relaxation across the box's edges (named parameter seam_relaxation_rings), at the grid
// where it matters: Spot Loop-subdivided once (23k faces), about as many quads as faces. With and
// without it the metric is the box's (eight cones, flat elsewhere); with it the remesh reads back
// valid, none of its quads is inverted, and it has fewer poor quads (scaled Jacobian below 0.2)
// than with the paths held straight.
void seam_relaxation(const std::string& dir)
{
  Surface_mesh mesh;
  SMDF::read_triangle_mesh(dir + "/meshes/spot_c3d.obj", mesh);
  CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(1));
  const Box_cone_metric box = box_cone_metric(mesh);
  const auto& corners = box.corners;
  const auto& cm = box.status;
  const auto u = box.u;
  SMDF_CHECK_MSG(cm.converged, "spot subdivided, 8 cones: flat cone metric " << cm.message);
  const double h = std::sqrt(surface_area(mesh) / double(num_faces(mesh)));
  std::map<int, std::size_t> poor;
  for(int rings : {0, 8}) {
    const std::string what = "spot subdivided (" + std::to_string(num_faces(mesh)) + " faces), box, seam rings " + std::to_string(rings);
    auto lengths = mesh.add_property_map<Surface_mesh::Edge_index, double>("e:box", 0).first;
    const auto ps = SMDF::box_polycube_metric(mesh, corners, h, lengths, SMDF::parameters::conformal_factor_map(u).seam_relaxation_rings(rings));
    SMDF_CHECK_MSG(ps.success && (ps.seam_relaxed_vertices > 0) == (rings > 0), what << ": " << ps.message << ", " << ps.seam_relaxed_vertices << " vertices relaxed");
    if(!ps.success) continue;
    const auto dev = SMDF::develop_flat_metric(mesh, SMDF::parameters::edge_length_map(lengths));
    SMDF_CHECK_MSG(dev.cones().size() == 8 && dev.max_flatness_error() < 1e-9,
                   what << ": eight cones, flat elsewhere (" << dev.cones().size() << ", " << dev.max_flatness_error() << ")");
    Surface_mesh out;
    const auto st = SMDF::tessellate_flat_metric(mesh, dev, SMDF::SQUARE_GRID, h, out);
    const auto& D = ps.dimensions;
    if(rings > 0) {
      SMDF_CHECK_MSG(st.inverted_faces == 0, what << ": no inverted quad (" << st.inverted_faces << ")");
      check_remesh(mesh, mesh, out, st, 4, {{3, 8}}, 2 * (D[0] * D[1] + D[1] * D[2] + D[2] * D[0]) / (h * h), what);
    }
    std::size_t count = 0;   // quads whose smallest corner scaled Jacobian (about the diagonals' normal) is below 0.2
    for(auto f : faces(out)) {
      std::vector<K::Point_3> p;
      for(auto g : CGAL::halfedges_around_face(halfedge(f, out), out)) p.push_back(out.point(target(g, out)));
      if(p.size() != 4) continue;
      K::Vector_3 n = CGAL::cross_product(p[2] - p[0], p[3] - p[1]);
      n = n / std::sqrt(n.squared_length());
      double worst = 1;
      for(int c = 0; c < 4; ++c) {
        const K::Vector_3 a = p[std::size_t((c + 1) % 4)] - p[std::size_t(c)], b = p[std::size_t((c + 3) % 4)] - p[std::size_t(c)];
        worst = std::min(worst, CGAL::cross_product(a, b) * n / std::sqrt(a.squared_length() * b.squared_length()));
      }
      count += worst < 0.2;
    }
    poor[rings] = count;
    std::cout << what << ": " << ps.seam_relaxed_vertices << " vertices relaxed across the edges, " << st.faces << " quads, "
              << st.inverted_faces << " inverted, " << count << " with a scaled Jacobian below 0.2" << std::endl;
    mesh.remove_property_map(lengths);
  }
  if(poor.size() == 2)
    SMDF_CHECK_MSG(poor[8] < poor[0], "the relaxation across the edges leaves fewer poor quads (" << poor[8] << " against " << poor[0] << ")");
  bool threw = false;
  auto lengths = mesh.add_property_map<Surface_mesh::Edge_index, double>("e:bad", 0).first;
  try { SMDF::box_polycube_metric(mesh, corners, h, lengths, SMDF::parameters::seam_relaxation_rings(-1)); }
  catch(const SMDF::Input_error& e) { threw = std::string(e.what()).find("seam_relaxation_rings") != std::string::npos; }
  SMDF_CHECK_MSG(threw, "seam_relaxation_rings(-1) is rejected by name");
}

// Cones for remeshing (place_remeshing_cones()) on every shared mesh of one component, closed
// and open, N = 4 or 6 and the bound drawn at random. Read back from the result alone: every
// curvature 2pi/N or -2pi/N (-4pi/N allowed where 2 pi chi alone needs more than 250 cones of
// -2pi/N: the cheese, of genus 133), the sum 2 pi chi, no two
// cones adjacent, the metric's curvature recomputed from its lengths (on its own triangulation)
// equal to the cones and zero elsewhere, and its scale spread recomputed from the conformal
// factors (away from the cones' rings and isolated vertices) equal to the reported one, within the bound on success.
template <typename Mesh>
bool check_remeshing_cones(const Mesh& mesh, int N, double bound, const std::string& what, std::size_t& cones_out)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor V;
  auto lengths = get(CGAL::dynamic_edge_property_t<double>(), mesh);
  auto u = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
  const auto st = SMDF::place_remeshing_cones(mesh, lengths, SMDF::parameters::symmetry_order(N).distortion_bound(bound).conformal_factor_map(u));
  SMDF_CHECK_MSG(st.success || !st.message.empty(), what);
  SMDF_CHECK_MSG(st.metric.converged, what << ": " << st.message);
  if(!st.metric.converged) return false;
  const double q = 2 * CGAL_PI / N;
  const SMDF::Mesh_topology<Mesh> topo = SMDF::mesh_topology(mesh);
  const long chi = topo.components[0].euler_characteristic;
  const auto vim = CGAL::get_initialized_vertex_index_map(mesh);
  auto id = [&](V v) { return std::size_t(get(vim, v)); };
  std::map<std::size_t, double> K;
  double sum = 0;
  bool multiples = true, ranged = true;
  for(const auto& c : st.cones) {
    K[id(c.first)] = c.second;
    sum += c.second;
    const double k = c.second / q;
    multiples = multiples && std::abs(k - std::round(k)) < 1e-12;
    ranged = ranged && (std::round(k) == 1 || (std::round(k) <= -1 && std::round(k) >= -st.negative_cone_quanta));
  }
  // the default: two quanta for a negative cone where 2 pi chi alone would fill over half of the
  // 500 cones allowed
  const int quanta = -chi * N > 250 ? 2 : 1;
  SMDF_CHECK_MSG(multiples && ranged && st.negative_cone_quanta == quanta,
                 what << ": curvatures of one quantum, or up to " << quanta << " for negative ones (" << st.negative_cone_quanta << ")");
  SMDF_CHECK_MSG(K.size() == st.cones.size(), what << ": a vertex listed twice");
  SMDF_CHECK_MSG(std::abs(sum - 2 * CGAL_PI * chi) < 1e-9, what << ": cones sum to " << sum << ", 2 pi chi = " << 2 * CGAL_PI * chi);
  bool apart = true;
  for(const auto& c : st.cones)
    for(auto w : CGAL::vertices_around_target(halfedge(c.first, mesh), mesh)) apart = apart && !K.count(id(w));
  SMDF_CHECK_MSG(apart, what << ": two cones are adjacent");
  // the metric's curvature, recomputed on the triangulation that carries it
  double err = 0;
  if(st.metric.triangulation_changed) {
    Surface_mesh tri;
    auto tl = tri.template add_property_map<Surface_mesh::Edge_index, double>("e:l", 0.).first;
    SMDF::copy_intrinsic_triangulation(st.metric.intrinsic_triangulation, mesh, tri, tl);
    const SMDF::Intrinsic_mesh<Surface_mesh> im(tri, SMDF::parameters::edge_length_map(tl));
    for(auto v : vertices(tri)) {
      const auto it = K.find(std::size_t(v.idx()));
      err = std::max(err, std::abs(im.vertex_curvature(v) - (it == K.end() ? 0. : it->second)));
    }
  } else {
    const SMDF::Intrinsic_mesh<Mesh> im(mesh, SMDF::parameters::edge_length_map(lengths));
    for(auto v : vertices(mesh)) {
      const auto it = K.find(id(v));
      err = std::max(err, std::abs(im.vertex_curvature(v) - (it == K.end() ? 0. : it->second)));
    }
  }
  SMDF_CHECK_MSG(err < 1e-8, what << ": curvature error " << err);
  // the spread, away from the cones and their neighbours and from the boundary's straight or
  // smooth stretches (input angle within pi/4 of pi), which take no corner; every corner sits
  // where the input's boundary turns its way (angle below 3 pi/4 convex, above 5 pi/4 concave)
  std::set<std::size_t> near;
  for(const auto& c : st.cones) {
    near.insert(id(c.first));
    for(auto w : CGAL::vertices_around_target(halfedge(c.first, mesh), mesh)) near.insert(id(w));
  }
  const SMDF::Intrinsic_mesh<Mesh> input_metric(mesh);
  bool corners_fit = true;
  for(auto v : vertices(mesh)) {
    if(!is_border(v, mesh)) continue;
    const double angle = CGAL_PI - input_metric.vertex_curvature(v);
    const auto it = K.find(id(v));
    if(it == K.end()) { if(std::abs(angle - CGAL_PI) <= CGAL_PI / 4) near.insert(id(v)); }
    else corners_fit = corners_fit && (it->second > 0 ? angle < 0.75 * CGAL_PI : angle > 1.25 * CGAL_PI);
  }
  SMDF_CHECK_MSG(corners_fit, what << ": a corner where the input's boundary does not turn its way");
  double lo = 1e300, hi = -1e300;
  for(auto v : vertices(mesh)) if(!near.count(id(v)) && halfedge(v, mesh) != boost::graph_traits<Mesh>::null_halfedge()) { lo = std::min(lo, get(u, v)); hi = std::max(hi, get(u, v)); }
  SMDF_CHECK_MSG(std::abs((hi - lo) - st.scale_spread) < 1e-9, what << ": spread " << hi - lo << " reported " << st.scale_spread);
  if(st.success) SMDF_CHECK_MSG(st.scale_spread <= bound, what);
  std::cout << what << ": " << st.cones.size() << " cones, spread " << st.scale_spread << " (bound " << bound << ")"
            << (st.metric.triangulation_changed ? ", flips" : "") << (st.success ? "" : ", not within the bound: " + st.message) << std::endl;
  cones_out = st.cones.size();
  return st.success;
}

struct Cone_separation_counts { std::size_t before = 0, after = 0; };

void remeshing_cones(const std::string& dir)
{
  std::mt19937 rng(20261206);
  std::size_t runs = 0, within = 0, open = 0;
  for(bool open_meshes : {false, true})
    smdf_test::for_each_shared_mesh<Surface_mesh>(dir, open_meshes, [&](const smdf_test::Manifest_entry& e, const Surface_mesh& mesh) {
      const int N = std::uniform_int_distribution<int>(0, 3)(rng) == 0 ? 6 : 4;
      const double bound = std::uniform_real_distribution<double>(1.5, 2.5)(rng);
      std::size_t n = 0;
      ++runs;
      open += open_meshes;
      within += check_remeshing_cones(mesh, N, bound, e.file + " (N = " + std::to_string(N) + ")", n);
    });
  std::cout << "remeshing cones: " << within << " of " << runs << " meshes (" << open << " open) within the bound" << std::endl;
  const bool reduced = std::getenv("SMDF_TEST_MAX_FACES") != nullptr;   // the sanitizer run's meshes of at most 10k faces: 12, 4 open
  SMDF_CHECK(runs >= (reduced ? 12u : 20u) && open >= (reduced ? 4u : 5u));
  SMDF_CHECK(within * 10 >= runs * 8);   // measured: the beetle and the feline miss it at 2
  // Polyhedron_3: the same cones as on the Surface_mesh
  Polyhedron p;
  Surface_mesh sm;
  SMDF::read_triangle_mesh(dir + "/meshes/double-torus_jnd.off", p);
  SMDF::read_triangle_mesh(dir + "/meshes/double-torus_jnd.off", sm);
  std::size_t np = 0, ns = 0;
  check_remeshing_cones(p, 4, 2., "double torus (Polyhedron_3)", np);
  check_remeshing_cones(sm, 4, 2., "double torus (Surface_mesh)", ns);
  SMDF_CHECK(np == ns && np >= 4);
  // minimum_cone_distance, read back by Dijkstra along the edges from every cone: a pair closer
  // than d only if the status counts a crowded cone; more room costs no read-back check
  std::size_t spaced = 0;
  for(const char* name : {"double-torus_jnd.off", "spot_c3d.obj", "bob_small_gc.off", "genus3_vhacd.off"}) {
    Surface_mesh m;
    SMDF::read_triangle_mesh(dir + "/meshes/" + name, m);
    double mean = 0;
    for(auto e : edges(m)) mean += std::sqrt(CGAL::squared_distance(m.point(source(e, m)), m.point(target(e, m))));
    mean /= double(num_edges(m));
    const double d = std::uniform_real_distribution<double>(4, 10)(rng) * mean;
    auto lengths = m.add_property_map<Surface_mesh::Edge_index, double>("e:l", 0.).first;
    const auto st = SMDF::place_remeshing_cones(m, lengths, SMDF::parameters::minimum_cone_distance(d));
    std::vector<double> dist;
    double closest = std::numeric_limits<double>::infinity();
    for(const auto& c : st.cones) {
      dist.assign(num_vertices(m), std::numeric_limits<double>::infinity());
      typedef std::pair<double, Surface_mesh::Vertex_index> Item;
      std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
      dist[c.first] = 0;
      queue.emplace(0., c.first);
      while(!queue.empty()) {
        const Item it = queue.top();
        queue.pop();
        if(it.first > dist[it.second]) continue;
        for(auto h : CGAL::halfedges_around_source(it.second, m)) {
          const auto w = target(h, m);
          const double dw = it.first + std::sqrt(CGAL::squared_distance(m.point(it.second), m.point(w)));
          if(dw < dist[w]) { dist[w] = dw; queue.emplace(dw, w); }
        }
      }
      for(const auto& o : st.cones) if(o.first != c.first) closest = (std::min)(closest, dist[o.first]);
    }
    std::cout << name << ", cones at least " << d << " apart: " << st.cones.size() << " cones, closest pair " << closest << ", "
              << st.crowded_cones << " crowded, spread " << st.scale_spread << (st.success ? "" : " (" + st.message + ")") << std::endl;
    SMDF_CHECK_MSG(st.crowded_cones > 0 || closest >= d * (1 - 1e-12), name << ": cones " << closest << " apart, fewer than " << d);
    spaced += st.crowded_cones == 0 && st.success;
  }
  SMDF_CHECK(spaced >= 3);
  // maximum_negative_cone_quanta(2) on the double torus (chi = -2): fewer cones than with one
  // quantum each, some of curvature -pi (valence 6), the sum 2 pi chi either way
  {
    auto l1 = get(CGAL::dynamic_edge_property_t<double>(), sm), l2 = get(CGAL::dynamic_edge_property_t<double>(), sm);
    const auto one = SMDF::place_remeshing_cones(sm, l1, SMDF::parameters::maximum_negative_cone_quanta(1));
    const auto two = SMDF::place_remeshing_cones(sm, l2, SMDF::parameters::maximum_negative_cone_quanta(2));
    auto tally = [](const auto& st, int& doubled, double& sum) {
      bool ranged = true;
      doubled = 0;
      sum = 0;
      for(const auto& c : st.cones) {
        const long k = std::lround(c.second / (CGAL_PI / 2));
        ranged = ranged && std::abs(c.second - k * CGAL_PI / 2) < 1e-12 && (k == 1 || (k <= -1 && k >= -st.negative_cone_quanta));
        doubled += k == -2;
        sum += c.second;
      }
      return ranged;
    };
    int d1 = 0, d2 = 0;
    double s1 = 0, s2 = 0;
    const bool r1 = tally(one, d1, s1), r2 = tally(two, d2, s2);
    SMDF_CHECK_MSG(r1 && r2 && d1 == 0 && d2 > 0 && two.cones.size() < one.cones.size() && std::abs(s1 + 4 * CGAL_PI) < 1e-9 &&
                       std::abs(s2 + 4 * CGAL_PI) < 1e-9 && one.negative_cone_quanta == 1 && two.negative_cone_quanta == 2,
                   "double torus: " << one.cones.size() << " cones of one quantum, " << two.cones.size() << " with up to two (" << d2
                                    << " of -pi); sums " << s1 << " and " << s2);
  }
  // bad input
  bool threw = false;
  try { SMDF::place_remeshing_cones(sm, get(CGAL::dynamic_edge_property_t<double>(), sm), SMDF::parameters::maximum_negative_cone_quanta(0)); }
  catch(const SMDF::Input_error&) { threw = true; }
  SMDF_CHECK(threw);
  threw = false;
  try { SMDF::place_remeshing_cones(sm, get(CGAL::dynamic_edge_property_t<double>(), sm), SMDF::parameters::distortion_bound(-1.)); }
  catch(const SMDF::Input_error&) { threw = true; }
  SMDF_CHECK(threw);
  threw = false;
  try { SMDF::place_remeshing_cones(sm, get(CGAL::dynamic_edge_property_t<double>(), sm), SMDF::parameters::minimum_cone_distance(-1.)); }
  catch(const SMDF::Input_error&) { threw = true; }
  SMDF_CHECK(threw);
}

// separate_remeshing_cones() on meshes whose placed cones crowd under their own metric at 1,000
// to 2,500 quads (the casting, of genus 9; the beetle with 9 boundary loops and the holes with 7;
// homer): read back by Dijkstra along the edges from every cone, under the same lengths, the
// counts of interior cones nearer another than the distance before and after are the status's;
// fewer after; the total curvature is kept, 2 cones fewer per cancelled pair, the boundary's
// corners in place, no two cones adjacent; the metric of the new cones converges. On both
// Surface_mesh and Polyhedron_3 (the same counts).
// The cones place_remeshing_cones() places on `m` (its defaults): its status, and the cones as a
// curvature per vertex (0 elsewhere).
template <typename Mesh>
auto placed_cone_curvatures(const Mesh& m)
{
  auto placed = get(CGAL::dynamic_edge_property_t<double>(), m);
  const auto ps = SMDF::place_remeshing_cones(m, placed);
  auto curvature = get(CGAL::dynamic_vertex_property_t<double>(), m);
  for(auto v : vertices(m)) put(curvature, v, 0.);
  for(const auto& c : ps.cones) put(curvature, c.first, c.second);
  return std::make_pair(ps, curvature);
}

template <typename Mesh>
std::size_t check_cone_separation(const Mesh& m, double quads, const std::string& what, Cone_separation_counts& counts)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor V;
  const auto placement = placed_cone_curvatures(m);
  const auto& ps = placement.first;
  const auto& curvature = placement.second;
  auto l = get(CGAL::dynamic_edge_property_t<double>(), m);
  const auto cm = SMDF::compute_cone_metric(m, curvature, l, SMDF::parameters::intrinsic_edge_flips(false));
  if(!cm.converged) { std::cout << what << ": the cone metric needs flips (skipped)" << std::endl; return 0; }
  double area = 0;
  for(auto f : faces(m)) {
    const auto h = halfedge(f, m);
    const double a = get(l, edge(h, m)), b = get(l, edge(next(h, m), m)), c = get(l, edge(prev(h, m), m)), p = (a + b + c) / 2;
    area += std::sqrt(std::max(0., p * (p - a) * (p - b) * (p - c)));
  }
  const double d = 1.5 * std::sqrt(area / quads);
  // interior cones with another cone nearer than d, by Dijkstra from each
  auto dist = get(CGAL::dynamic_vertex_property_t<double>(), m);
  auto mark = get(CGAL::dynamic_vertex_property_t<int>(), m);   // 1: a cone
  for(V v : vertices(m)) { put(dist, v, std::numeric_limits<double>::infinity()); put(mark, v, 0); }
  auto close = [&](const std::vector<std::pair<V, double>>& cones) {
    std::size_t n = 0;
    for(const auto& c : cones) put(mark, c.first, 1);
    for(const auto& c : cones) {
      if(is_border(c.first, m)) continue;
      std::vector<V> touched{c.first};
      typedef std::pair<double, V> Item;
      auto later = [](const Item& a, const Item& b) { return a.first > b.first; };
      std::priority_queue<Item, std::vector<Item>, decltype(later)> queue(later);
      put(dist, c.first, 0.);
      queue.emplace(0., c.first);
      bool near = false;
      while(!queue.empty() && !near) {
        const Item it = queue.top();
        queue.pop();
        if(it.first > get(dist, it.second)) continue;
        near = it.second != c.first && get(mark, it.second) == 1;
        for(auto h : CGAL::halfedges_around_source(it.second, m)) {
          const V w = target(h, m);
          const double dw = it.first + get(l, edge(h, m));
          if(dw < d && dw < get(dist, w)) { put(dist, w, dw); touched.push_back(w); queue.emplace(dw, w); }
        }
      }
      for(V w : touched) put(dist, w, std::numeric_limits<double>::infinity());
      n += near;
    }
    for(const auto& c : cones) put(mark, c.first, 0);
    return n;
  };
  std::vector<std::pair<V, double>> cones = ps.cones;
  const SMDF::Cone_separation_status st = SMDF::separate_remeshing_cones(m, l, cones, d);
  double before = 0, after = 0;
  for(const auto& c : ps.cones) before += c.second;
  for(const auto& c : cones) after += c.second;
  std::vector<std::size_t> corners_before, corners_after;   // positions of the border cones in vertices(m)
  auto position = [&](V v) { return std::size_t(std::distance(vertices(m).begin(), std::find(vertices(m).begin(), vertices(m).end(), v))); };
  for(const auto& c : ps.cones) if(is_border(c.first, m)) corners_before.push_back(position(c.first));
  for(const auto& c : cones) { if(is_border(c.first, m)) corners_after.push_back(position(c.first)); put(mark, c.first, 2); }
  std::sort(corners_before.begin(), corners_before.end());
  std::sort(corners_after.begin(), corners_after.end());
  bool adjacent = false;
  std::size_t distinct = 0;
  for(V v : vertices(m)) distinct += get(mark, v) == 2;
  for(const auto& c : cones)
    for(auto h : CGAL::halfedges_around_source(c.first, m)) adjacent = adjacent || get(mark, target(h, m)) == 2;
  for(const auto& c : cones) put(mark, c.first, 0);
  const std::size_t close_before = close(ps.cones), close_after = close(cones);
  std::cout << what << ": " << ps.cones.size() << " cones, " << close_before << " nearer another than " << d << " (1.5 grid edges at "
            << quads << " quads), " << st.cancelled_pairs << " pairs cancelled, " << st.moved_cones << " moved, " << close_after << " near after" << std::endl;
  SMDF_CHECK_MSG(st.close_cones_before == close_before && st.close_cones_after == close_after && close_after <= close_before,
                 what << ": the status counts " << st.close_cones_before << " -> " << st.close_cones_after);
  SMDF_CHECK_MSG(std::abs(before - after) < 1e-9 && cones.size() + 2 * std::size_t(st.cancelled_pairs) == ps.cones.size() &&
                 corners_before == corners_after && !adjacent && distinct == cones.size(),
                 what << ": total " << before << " -> " << after << ", " << cones.size() << " cones, adjacent " << adjacent);
  for(V v : vertices(m)) put(curvature, v, 0.);
  for(const auto& c : cones) put(curvature, c.first, c.second);
  auto l2 = get(CGAL::dynamic_edge_property_t<double>(), m);
  const auto cm2 = SMDF::compute_cone_metric(m, curvature, l2, SMDF::parameters::edge_length_map(l).intrinsic_edge_flips(false));
  SMDF_CHECK_MSG(cm2.converged && cm2.max_curvature_error < 1e-9, what << ": the separated cones' metric: " << cm2.message);
  counts.before += close_before;
  counts.after += close_after;
  return cones.size();
}

void cone_separation(const std::string& dir)
{
  Cone_separation_counts counts;
  for(const char* name : {"casting_vhacd.off", "beetle_euclid.off", "holes_cgal.off", "homer_cgal.off"}) {
    Surface_mesh m;
    SMDF::read_triangle_mesh(dir + "/meshes/" + name, m);
    for(double quads : {1000., 2500.}) check_cone_separation(m, quads, std::string(name) + " at " + std::to_string(int(quads)), counts);
  }
  SMDF_CHECK_MSG(counts.before >= 10 && counts.after * 2 <= counts.before, counts.before << " crowded cones, " << counts.after << " after");
  Polyhedron p;
  Surface_mesh sm;
  SMDF::read_triangle_mesh(dir + "/meshes/casting_vhacd.off", p);
  SMDF::read_triangle_mesh(dir + "/meshes/casting_vhacd.off", sm);
  Cone_separation_counts cp, cs;
  const std::size_t np = check_cone_separation(p, 1000., "casting (Polyhedron_3)", cp), ns = check_cone_separation(sm, 1000., "casting (Surface_mesh)", cs);
  SMDF_CHECK(np == ns && cp.before == cs.before && cp.after == cs.after);
  bool threw = false;
  std::vector<std::pair<Surface_mesh::Vertex_index, double>> none;
  try { SMDF::separate_remeshing_cones(sm, get(CGAL::dynamic_edge_property_t<double>(), sm), none, 0.); }
  catch(const SMDF::Input_error&) { threw = true; }
  SMDF_CHECK(threw);
}

// Integer-grid maps (integer_grid_map()) of every closed shared mesh of at most 40k faces whose
// placed cones have a flat cone metric on its own triangulation, with the cross field of the
// trivial connection on that metric (singularities: the cones). Read back from the map alone:
// across every edge the two faces' images differ by a rotation by a multiple of pi/2 and an
// integer translation; every singularity is an integer point; the angles of the images sum to
// 2 pi at every vertex but the singularities, which are the cones (K = 2 pi - angle sum, a
// multiple of pi/2); no triangle folded (the status and the images agree); on genus 0 the
// seamless map is the metric's own development (relative energy ~0). Then every unfolded map is
// tessellated; each remesh that succeeds is checked (quads, valence 4 except at the singularities,
// on the input surface). The T-mesh of each seamless stage is read back (check_t_mesh()).
// A metric carried by an intrinsic triangulation, placed back: the cube's cone metric computed
// with flips from the start (its jittered sides are not Delaunay; Ptolemy flips keep the
// discrete conformal class, not the cube's lengths, so the metric differs slightly from the
// cube's and fits no grid by itself), its cross field and integer-grid map on the intrinsic
// triangulation's copy, tessellated there and brought to the cube through the common
// subdivision by place_tessellation_on_input(): a quad remesh of the cube with its eight
// corners of valence 3, every vertex on the cube, no face flipped.
void cube_through_intrinsic_triangulation()
{
  typedef Surface_mesh::Vertex_index V;
  typedef Surface_mesh::Halfedge_index H;
  Surface_mesh mesh;
  smdf_test::soup_to_mesh(cube_soup(4, 23u), mesh);
  auto target = mesh.add_property_map<V, double>("v:target", 0.).first;
  SMDF::compute_vertex_curvatures(mesh, target);
  std::vector<std::pair<V, double>> sing;
  for(auto v : vertices(mesh)) if(std::abs(target[v]) > 1e-9) { target[v] = CGAL_PI / 2; sing.emplace_back(v, 0.25); } else target[v] = 0;
  auto l = mesh.add_property_map<Surface_mesh::Edge_index, double>("e:l", 0.).first;
  const SMDF::Cone_metric_status cm = SMDF::compute_cone_metric(mesh, target, l, SMDF::parameters::input_triangulation_first(false));
  SMDF_CHECK_MSG(sing.size() == 8 && cm.converged && cm.triangulation_changed && cm.intrinsic_triangulation.has_common_subdivision(),
                 "cube with flips from the start: converged (" << cm.converged << ") on a flipped triangulation (" << cm.edge_flips << " flips)");
  if(!cm.triangulation_changed || !cm.intrinsic_triangulation.has_common_subdivision()) return;
  Surface_mesh imesh;
  auto il = imesh.add_property_map<Surface_mesh::Edge_index, double>("e:l", 0.).first;
  SMDF::copy_intrinsic_triangulation(cm.intrinsic_triangulation, mesh, imesh, il);
  auto adj = imesh.add_property_map<Surface_mesh::Edge_index, double>("e:adj", 0.).first;
  auto fa = imesh.add_property_map<Surface_mesh::Face_index, double>("f:angle", 0.).first;
  const auto tc = SMDF::compute_trivial_connection(imesh, sing, adj, SMDF::parameters::edge_length_map(il).symmetry_order(4).face_angle_map(fa));
  SMDF_CHECK_MSG(tc.success, "cube on the intrinsic triangulation: the cross field");
  for(double h : {0.5, 0.25}) {
    auto uv = imesh.add_property_map<H, std::array<double, 2>>("h:uv").first;
    const SMDF::Integer_grid_map_status gs = SMDF::integer_grid_map(imesh, fa, h, uv, SMDF::parameters::edge_length_map(il));
    const std::string what = "cube through " + std::to_string(cm.edge_flips) + " flips, quads of about " + std::to_string(h);
    SMDF_CHECK_MSG(gs.success, what << ": the integer-grid map: " << gs.message);
    if(!gs.success) continue;
    auto gl = imesh.add_property_map<Surface_mesh::Edge_index, double>("e:grid", 0.).first;
    for(auto ed : edges(imesh)) {
      const H x = halfedge(ed, imesh);
      gl[ed] = std::hypot(uv[x][0] - uv[prev(x, imesh)][0], uv[x][1] - uv[prev(x, imesh)][1]);
    }
    const auto dev = SMDF::develop_flat_metric(imesh, SMDF::parameters::edge_length_map(gl));
    Surface_mesh out;
    SMDF::Grid_tessellation_status st = SMDF::tessellate_flat_metric(imesh, dev, SMDF::SQUARE_GRID, 1., out);
    SMDF::place_tessellation_on_input(cm.intrinsic_triangulation, mesh, st, out);
    if(st.message.find("inverted") != std::string::npos) { st.success = true; st.message.clear(); }   // judged by chords before the placement
    check_remesh(mesh, mesh, out, st, 4, {{3, 8}}, double(st.faces), what);
    const double ratio = polygon_area(out) / surface_area(mesh);
    SMDF_CHECK_MSG(std::abs(ratio - 1) < 0.05, what << ": the remesh's area is the cube's within 5% (ratio " << ratio << ")");
    imesh.remove_property_map(uv);
    imesh.remove_property_map(gl);
  }
}

// The T-mesh of a map's seamless stage, read back: traced wherever the seamless map folds no
// triangle (or says why not, never an arc whose symbolic length disagrees with the traced one),
// at least one arc per singularity and corner.
void check_t_mesh(const SMDF::Integer_grid_map_status& st, std::size_t nodes, long chi, const std::string& what, std::size_t& traced)
{
  SMDF_CHECK_MSG(st.t_mesh_failure.find("form gives") == std::string::npos, what << ": " << st.t_mesh_failure);
  if(st.seamless_folded_triangles == 0 && st.t_mesh_failure.find("folds back") == std::string::npos)
    SMDF_CHECK_MSG(st.t_mesh_failure.empty(), what << ": the seamless map folds no triangle, but its T-mesh: " << st.t_mesh_failure);
  if(!st.t_mesh_failure.empty()) return;
  ++traced;
  SMDF_CHECK_MSG(st.t_mesh_arcs >= nodes, what << ": " << st.t_mesh_arcs << " T-mesh arcs for " << nodes << " singularities and corners");
  SMDF_CHECK_MSG(st.held_arcs <= st.t_mesh_arcs + st.t_mesh_spans && st.collapsed_arcs + st.negative_arcs <= st.t_mesh_arcs &&
                     st.short_spans <= st.t_mesh_spans,
                 what << ": arcs miscounted");
  // a boundary run between consecutive corners, at least, per corner
  SMDF_CHECK_MSG(st.t_mesh_spans >= st.boundary_corners.size(), what << ": " << st.t_mesh_spans << " spans for " << st.boundary_corners.size() << " corners");
  // Euler: the rectangles are at most the faces the nodes and arcs leave, all of them on a closed
  // sphere (no face winds around a handle or along a boundary loop)
  const long faces = chi - long(st.t_mesh_nodes) + long(st.t_mesh_arcs);
  SMDF_CHECK_MSG(long(st.t_mesh_faces) <= faces && (chi != 2 || st.t_mesh_arcs == 0 || long(st.t_mesh_faces) == faces) &&
                     st.collapsed_faces <= st.t_mesh_faces,
                 what << ": " << st.t_mesh_faces << " rectangles, " << faces << " faces by Euler's formula (" << st.t_mesh_nodes << " nodes, "
                      << st.t_mesh_arcs << " arcs)");
}

std::string t_mesh_summary(const SMDF::Integer_grid_map_status& st)
{
  if(!st.t_mesh_failure.empty()) return "no T-mesh (" + st.t_mesh_failure + ")";
  return std::to_string(st.t_mesh_arcs) + " T-mesh arcs (" + std::to_string(st.held_arcs) + " held, " + std::to_string(st.collapsed_arcs) +
         " collapsed, " + std::to_string(st.negative_arcs) + " negative, " + std::to_string(st.rounded_apart) + " values rounded apart, " +
         std::to_string(st.short_spans) + " of " + std::to_string(st.t_mesh_spans) + " spans short, " + std::to_string(st.collapsed_faces) +
         " of " + std::to_string(st.t_mesh_faces) + " faces collapsed" +
         (st.arcs_kept ? "; kept" : "") + ")";
}

// The T-mesh of a known seamless map: the planar staircase polygon (0,0) (7,0) (7,2) (4,2) (4,5)
// (2,5) (2,7) (0,7) with a constant field. Its two concave corners send two separatrices each;
// the one from (2,5) downwards meets the one from (4,2) leftwards at (2,2) after that one passed
// there (3 units against 2) and stops (the motorcycle rule); the three others end on the
// boundary. 4 separatrices make 5 arcs, and the 8 boundary runs are cut into 11 by 3 ends: 16
// arcs; 11 spans (the 8 runs and the 3 separatrices that end on the boundary). On a grid mesh (each separatrix runs along edges and through vertices) and on the same
// mesh with its interior vertices moved at random.
void staircase_t_mesh()
{
  typedef Surface_mesh::Face_index F;
  typedef Surface_mesh::Halfedge_index H;
  const int n = 2;   // squares per unit
  auto inside = [](double x, double y) { return y < 2 ? x < 7 : y < 5 ? x < 4 : y < 7 && x < 2; };
  for(int jitter = 0; jitter < 2; ++jitter) {
    smdf_test::Soup soup;
    std::map<std::pair<int, int>, std::size_t> index;
    auto vertex = [&](int i, int j) {
      const auto it = index.find({i, j});
      if(it != index.end()) return it->second;
      soup.points.push_back({double(i) / n, double(j) / n, 0.});
      return index[{i, j}] = soup.points.size() - 1;
    };
    for(int i = 0; i < 7 * n; ++i)
      for(int j = 0; j < 7 * n; ++j) {
        if(!inside((i + 0.5) / n, (j + 0.5) / n)) continue;
        const std::size_t a = vertex(i, j), b = vertex(i + 1, j), c = vertex(i + 1, j + 1), d = vertex(i, j + 1);
        if((i + j) % 2 == 0) { soup.faces.push_back({a, b, c}); soup.faces.push_back({a, c, d}); }
        else { soup.faces.push_back({a, b, d}); soup.faces.push_back({b, c, d}); }
      }
    Surface_mesh mesh;
    smdf_test::soup_to_mesh(soup, mesh);
    if(jitter) {
      std::mt19937 rng(11u);
      std::uniform_real_distribution<double> u(-0.3 / n, 0.3 / n);
      for(auto v : vertices(mesh))
        if(!is_border(v, mesh)) mesh.point(v) = K::Point_3(mesh.point(v).x() + u(rng), mesh.point(v).y() + u(rng), 0);
    }
    auto fa = mesh.add_property_map<F, double>("f:angle", 0.).first;
    for(auto f : faces(mesh)) {   // the field along x, from halfedge(f)
      const H h = halfedge(f, mesh);
      const K::Point_3 &p = mesh.point(source(h, mesh)), &q = mesh.point(target(h, mesh));
      fa[f] = -std::atan2(q.y() - p.y(), q.x() - p.x());
    }
    auto uv = mesh.add_property_map<H, std::array<double, 2>>("h:uv").first;
    const SMDF::Integer_grid_map_status st = SMDF::integer_grid_map(mesh, fa, 0.37, uv);
    const std::string what = std::string("staircase, ") + (jitter ? "interior vertices moved" : "grid mesh");
    std::cout << what << ": " << t_mesh_summary(st) << ", " << (st.success ? "unfolded" : st.message) << std::endl;
    SMDF_CHECK_MSG(st.t_mesh_failure.empty() && st.t_mesh_arcs == 16, what << ": " << st.t_mesh_arcs << " T-mesh arcs, 16 expected " << st.t_mesh_failure);
    // spans: the 8 boundary runs, and the 3 separatrices that end on the boundary
    SMDF_CHECK_MSG(st.t_mesh_spans == 11 && st.short_spans == 0, what << ": " << st.t_mesh_spans << " spans, 11 expected, " << st.short_spans << " short");
    // 5 rectangles: 8 corners and 4 ends make 12 nodes, 16 arcs, 1 - 12 + 16 faces
    SMDF_CHECK_MSG(st.t_mesh_faces == 5 && st.t_mesh_nodes == 12 && st.collapsed_faces == 0,
                   what << ": " << st.t_mesh_faces << " rectangles and " << st.t_mesh_nodes << " nodes, 5 and 12 expected");
    SMDF_CHECK_MSG(st.success && st.boundary_corners.size() == 8 && st.negative_arcs == 0, what << ": " << st.message);
  }
}

void integer_grid_maps(const std::string& dir)
{
  typedef Surface_mesh::Vertex_index V;
  typedef Surface_mesh::Halfedge_index H;
  std::size_t runs = 0, runs_on_input = 0, unfolded = 0, unfolded_on_input = 0, skipped = 0, tessellated = 0, intrinsic = 0, intrinsic_tessellated = 0,
              t_meshes = 0;
  smdf_test::for_each_shared_mesh<Surface_mesh>(dir, false, [&](const smdf_test::Manifest_entry& e, const Surface_mesh& input) {
    if(e.F > 40000) return;
    Surface_mesh mesh = input;
    auto placed = mesh.add_property_map<Surface_mesh::Edge_index, double>("e:placed", 0.).first;
    const auto cs = SMDF::place_remeshing_cones(mesh, placed);
    auto cone_target = mesh.add_property_map<V, double>("v:target", 0.).first;
    std::vector<std::pair<V, double>> sing;
    for(const auto& c : cs.cones) { cone_target[c.first] = c.second; sing.emplace_back(c.first, c.second / (2 * CGAL_PI)); }
    auto cl = mesh.add_property_map<Surface_mesh::Edge_index, double>("e:cone", 0.).first;
    const auto cm = SMDF::compute_cone_metric(mesh, cone_target, cl, SMDF::parameters::intrinsic_edge_flips(false));
    // where the input's edges cannot carry the metric: the map and the grid on the intrinsic
    // triangulation the flow flipped to, the remesh brought back through its common subdivision
    SMDF::Intrinsic_triangulation it;
    Surface_mesh imesh;
    Surface_mesh* on = &mesh;
    if(!cm.converged && cs.cones.size() > 120) {   // a dense map of thousands of unknowns: minutes, not for this test
      ++skipped;
      std::cout << e.file << ": the cone metric needs flips, " << cs.cones.size() << " cones (skipped)" << std::endl;
      return;
    }
    if(!cm.converged) {
      auto fl = mesh.add_property_map<Surface_mesh::Edge_index, double>("e:flipped", 0.).first;
      SMDF::Cone_metric_status cf = SMDF::compute_cone_metric(mesh, cone_target, fl);
      if(!cf.converged || !cf.triangulation_changed || !cf.intrinsic_triangulation.has_common_subdivision()) {
        ++skipped;
        std::cout << e.file << ": the cone metric converges neither without nor with flips (skipped): " << cf.message << std::endl;
        return;
      }
      it = std::move(cf.intrinsic_triangulation);
      cl = imesh.add_property_map<Surface_mesh::Edge_index, double>("e:cone", 0.).first;
      SMDF::copy_intrinsic_triangulation(it, mesh, imesh, cl);
      on = &imesh;
      ++intrinsic;
    }
    Surface_mesh& msh = *on;
    auto adj = msh.add_property_map<Surface_mesh::Edge_index, double>("e:adj", 0.).first;
    auto fa = msh.add_property_map<Surface_mesh::Face_index, double>("f:angle", 0.).first;
    const auto tc = SMDF::compute_trivial_connection(msh, sing, adj, SMDF::parameters::edge_length_map(cl).symmetry_order(4)
                                                                      .smoothest_generator_turning_numbers(true).face_angle_map(fa));
    SMDF_CHECK_MSG(tc.success, e.file);
    double area = 0;
    for(auto f : faces(msh)) {
      const H h = halfedge(f, msh);
      const double a = cl[edge(h, msh)], b = cl[edge(next(h, msh), msh)], c = cl[edge(prev(h, msh), msh)], p = (a + b + c) / 2;
      area += std::sqrt(std::max(0., p * (p - a) * (p - b) * (p - c)));
    }
    const double h = std::sqrt(area / 3000);
    auto uv = msh.add_property_map<H, std::array<double, 2>>("h:uv").first;
    const SMDF::Integer_grid_map_status st = SMDF::integer_grid_map(msh, fa, h, uv, SMDF::parameters::edge_length_map(cl));
    ++runs;
    runs_on_input += on == &mesh;
    const std::string what = e.file + " (genus " + e.genus + ", " + std::to_string(cs.cones.size()) + " cones" +
                             (on == &imesh ? ", on the intrinsic triangulation" : "") + ")";
    std::cout << what << ": " << (st.success ? "unfolded" : st.message) << ", " << st.arcs << " seams, " << st.rounded << " values rounded, "
              << t_mesh_summary(st) << ", "
              << st.stiffening_rounds << " stiffening rounds, energy " << st.seamless_energy << " -> " << st.integer_energy
              << ", min area ratio " << st.min_area_ratio << std::endl;
    check_t_mesh(st, st.singularities.size(), 2 - 2 * std::stol(e.genus), what, t_meshes);
    if(st.folded_triangles == 0 && st.winding_faults == 0) SMDF_CHECK_MSG(st.success, what << ": " << st.message);
    if(!st.success && st.folded_triangles == 0 && st.winding_faults == 0) return;
    typedef std::complex<double> C;
    auto at = [&](H x) { return C(uv[x][0], uv[x][1]); };   // target(x) in face(x)
    // seams: rotation by i^k and an integer translation
    double worst_rotation = 0, worst_translation = 0;
    for(auto ed : edges(msh)) {
      const H x = halfedge(ed, msh), o = opposite(x, msh);
      const C aL = at(prev(x, msh)), bL = at(x), bR = at(prev(o, msh)), aR = at(o);
      const C ratio = (bR - aR) / (bL - aL);
      const C rk(std::round(ratio.real()), std::round(ratio.imag()));
      worst_rotation = std::max(worst_rotation, std::abs(ratio - rk) + std::abs(std::abs(rk) - 1));
      const C t = aR - rk * aL;
      worst_translation = std::max(worst_translation, std::abs(t - C(std::round(t.real()), std::round(t.imag()))));
    }
    SMDF_CHECK_MSG(worst_rotation < 1e-6 && worst_translation < 1e-6, what << ": seam motions off the grid's symmetries by " << worst_rotation
                                                                        << " (rotation), " << worst_translation << " (translation)");
    // singularities at integer points, and the images' angle sums
    std::vector<double> angle_sum(num_vertices(msh), 0.);
    std::size_t folded = 0;
    double worst_point = 0;
    std::set<std::size_t> singular;
    for(const auto& sv : st.singularities) singular.insert(sv.first);
    for(auto f : faces(msh)) {
      for(H x : CGAL::halfedges_around_face(halfedge(f, msh), msh)) {
        const C p = at(x), a = at(prev(x, msh)), b = at(next(x, msh));
        angle_sum[target(x, msh)] += std::abs(std::arg((b - p) / (a - p)));
        if(singular.count(std::size_t(target(x, msh))))
          worst_point = std::max(worst_point, std::abs(p - C(std::round(p.real()), std::round(p.imag()))));
      }
      const H x = halfedge(f, msh);
      const C p0 = at(prev(x, msh)), p1 = at(x), p2 = at(next(x, msh));
      folded += !((p1 - p0).real() * (p2 - p0).imag() - (p1 - p0).imag() * (p2 - p0).real() > 0);
    }
    SMDF_CHECK_MSG(worst_point < 1e-6, what << ": a singularity " << worst_point << " away from the lattice");
    SMDF_CHECK_MSG(folded == st.folded_triangles, what << ": " << folded << " folded triangles, the status says " << st.folded_triangles);
    if(folded == 0) {
      ++unfolded;
      unfolded_on_input += on == &mesh;
      std::map<std::size_t, double> K;
      for(const auto& c : cs.cones) K[std::size_t(c.first)] = c.second;
      double worst_k = 0;
      for(auto v : vertices(msh)) {
        const auto it = K.find(std::size_t(v));
        worst_k = std::max(worst_k, std::abs(2 * CGAL_PI - angle_sum[v] - (it == K.end() ? 0. : it->second)));
      }
      // a map that wraps wrongly around a vertex says so, and only then (its angle sums disagree)
      SMDF_CHECK_MSG((worst_k < 1e-6) == (st.winding_faults == 0) && singular.size() == K.size(),
                     what << ": the map's cones differ from the placed ones by " << worst_k << ", " << st.winding_faults << " winding faults");
    }
    if(e.genus == "0") SMDF_CHECK_MSG(st.seamless_energy < 1e-12, what << ": seamless energy " << st.seamless_energy);
    if(st.success) {
      auto gl = msh.add_property_map<Surface_mesh::Edge_index, double>("e:grid", 0.).first;
      for(auto ed : edges(msh)) gl[ed] = std::abs(at(halfedge(ed, msh)) - at(prev(halfedge(ed, msh), msh)));
      // the package's own holonomy-group test (Theorem 3.5) on the map's metric: every loop of a
      // homotopy basis around the cones and the handles moves by a symmetry of the unit grid
      std::vector<Surface_mesh::Vertex_index> cone_vertices;
      for(const auto& c : cs.cones) cone_vertices.push_back(c.first);
      const auto basis = SMDF::homotopy_basis(msh, cone_vertices);
      const SMDF::Holonomy_group group = SMDF::holonomy_group(msh, basis, SMDF::parameters::edge_length_map(gl));
      const SMDF::Tessellation_compatibility tc = SMDF::tessellation_compatibility_at(group, SMDF::SQUARE_GRID, 1., 1e-6);
      SMDF_CHECK_MSG(tc.compatible && group.motions.size() == basis.loops.size(),
                     what << ": the map's metric fails the holonomy-group test: " << tc.failing_loops.size() << " of " << group.motions.size()
                          << " loops, rotation off by " << tc.max_rotation_deviation << ", translation by " << tc.max_translation_deviation);
      const auto dev = SMDF::develop_flat_metric(msh, SMDF::parameters::edge_length_map(gl));
      Surface_mesh out;
      auto ts = SMDF::tessellate_flat_metric(msh, dev, SMDF::SQUARE_GRID, 1., out);
      std::map<int, std::size_t> expected;
      for(const auto& c : cs.cones) expected[4 - int(std::lround(c.second / (CGAL_PI / 2)))]++;
      if(on == &imesh && num_faces(out) > 0) {
        // on the intrinsic copy the tessellation judged inversion by chords: only the surface's counts
        SMDF::place_tessellation_on_input(it, mesh, ts, out);
        if(ts.message.find("inverted") != std::string::npos) { ts.success = true; ts.message.clear(); }
        intrinsic_tessellated += ts.success;
      }
      if(ts.success) check_remesh(mesh, mesh, out, ts, 4, expected, double(ts.faces), what + ", tessellated" + (on == &imesh ? " on the intrinsic triangulation" : ""));
      else std::cout << what << ": not tessellated: " << ts.message << std::endl;
      tessellated += ts.success;
    }
  });
  std::cout << "integer-grid maps: " << unfolded << " of " << runs << " without a fold (" << intrinsic << " on an intrinsic triangulation, "
            << intrinsic_tessellated << " of them tessellated and placed on the input; " << skipped << " skipped), " << tessellated << " tessellated, "
            << t_meshes << " T-meshes traced" << std::endl;
  // measured: 10 of 12 unfolded maps tessellated (the rotor's grid has 7 faces inverted in space at
  // this size, the casting's 1: its arcs kept at least 1 by the rounding stretch it)
  const bool reduced = std::getenv("SMDF_TEST_MAX_FACES") != nullptr;   // the sanitizer run's meshes of at most 10k faces: 7 maps
  // on the input's triangulations; the few on intrinsic ones (homer and cheburashka: 80 and 108
  // cones, the metric flipped) fold at this size
  SMDF_CHECK(runs_on_input >= (reduced ? 6u : 8u) && unfolded_on_input * 10 >= runs_on_input * 8 && tessellated + 2 >= unfolded &&
             t_meshes >= (reduced ? 3u : 9u));
}

} // namespace

// The paths under a flat cone metric that lives on an intrinsic triangulation (the flow flipped
// edges): only its conformal factors reach box_polycube_metric(). Cheburashka's ears make the
// flow leave the input triangulation. The box metric must exist and develop with its eight
// cones, and the remesh's irregular vertices must be those cones, of valence 3. Also
// shortcut_chords(): a path that walks around a triangle (possible under scaled lengths that
// break the triangle inequality) is shortened to the triangle's third edge.
void flipped_flat_metric(const std::string& dir)
{
  Surface_mesh mesh;
  SMDF::read_triangle_mesh(dir + "/meshes/cheburashka_igltut.off", mesh);
  const Box_cone_metric box = box_cone_metric(mesh);
  const auto& corners = box.corners;
  const auto& cm = box.status;
  const auto u = box.u;
  SMDF_CHECK_MSG(cm.converged && cm.triangulation_changed, "cheburashka, 8 cones: the flow converges after " << cm.edge_flips << " flips");
  double extent = 0;
  for(auto v : vertices(mesh)) extent = std::max(extent, std::sqrt((mesh.point(v) - CGAL::ORIGIN).squared_length()));
  const double h = extent / 32;
  auto lengths = mesh.add_property_map<Surface_mesh::Edge_index, double>("e:box", 0).first;
  const auto ps = SMDF::box_polycube_metric(mesh, corners, h, lengths, SMDF::parameters::conformal_factor_map(u));
  SMDF_CHECK_MSG(ps.success, "cheburashka: box metric on the flipped metric's paths: " << ps.message);
  if(ps.success) {
    const auto dev = SMDF::develop_flat_metric(mesh, SMDF::parameters::edge_length_map(lengths));
    SMDF_CHECK_MSG(dev.cones().size() == 8 && dev.max_flatness_error() < 1e-9, "cheburashka: the box metric has eight cones, flat elsewhere");
    Surface_mesh out;
    const auto st = SMDF::tessellate_flat_metric(mesh, dev, SMDF::SQUARE_GRID, h, out);
    std::size_t at_cones = 0, other = 0;
    for(const auto& iv : st.irregular_vertices) (iv.second >= 0 && degree(Surface_mesh::Vertex_index(Surface_mesh::size_type(iv.first)), out) == 3 ? at_cones : other) += 1;
    SMDF_CHECK_MSG(num_faces(out) > 0 && at_cones == 8 && other == 0,
                   "cheburashka: the remesh's irregular vertices are the eight cones, of valence 3 (" << at_cones << ", " << other << " others)");
    std::cout << "cheburashka, box on the flipped flat metric (" << cm.edge_flips << " flips): " << st.faces << " quads, "
              << st.inverted_faces << " inverted" << std::endl;
  }
  // a path around a triangle (a, v, b) becomes (a, b)
  const SMDF::internal::Mesh_arrays<Surface_mesh> m(mesh, SMDF::parameters::default_values());
  const int v = 0, out0 = m.vertex_out[0], a = m.target[std::size_t(out0)], next_out = m.ccw_out(out0), b = m.target[std::size_t(next_out)];
  int ha = -1;   // the halfedge a -> v
  for(int g = m.vertex_out[std::size_t(a)], g0 = g;;) { if(m.target[std::size_t(g)] == v) { ha = g; break; } g = m.ccw_out(g); if(g == g0) break; }
  std::vector<int> path{a, v, b}, hs{ha, next_out};
  SMDF::internal::shortcut_chords(m, path, hs);
  SMDF_CHECK_MSG(path.size() == 2 && path[0] == a && path[1] == b && hs.size() == 1 && m.source(hs[0]) == a && m.target[std::size_t(hs[0])] == b,
                 "a path around a triangle is shortcut to its third edge");
}

// conforming_delaunay_refinement(), read back from its output alone: a valid mesh of the same
// Euler characteristic, boundary and area; the input's vertices first and unmoved; every vertex
// on the input surface and every face inside the input face it names; every interior edge
// Delaunay (opposite angles recomputed from the points); the output lengths the points'
// distances. On Surface_mesh and Polyhedron_3 the same refinement.
template <typename Input>
SMDF::Delaunay_refinement_status check_refinement(const Input& input, const Surface_mesh& in_sm, Surface_mesh& out, const std::string& what)
{
  auto lengths = out.add_property_map<Surface_mesh::Edge_index, double>("e:refined", -1.).first;
  const SMDF::Delaunay_refinement_status st =
      SMDF::conforming_delaunay_refinement(input, out, SMDF::parameters::default_values(), SMDF::parameters::edge_length_map(lengths));
  SMDF_CHECK_MSG(st.success && st.faces == num_faces(out) && st.face_origin.size() == num_faces(out) &&
                     st.inserted.size() + num_vertices(in_sm) == num_vertices(out),
                 what << ": refined (" << st.message << ")");
  if(!st.success) return st;
  const auto tin = SMDF::mesh_topology(in_sm), tout = SMDF::mesh_topology(out);
  SMDF_CHECK_MSG(CGAL::is_valid_polygon_mesh(out) && CGAL::is_triangle_mesh(out) && tout.euler_characteristic() == tin.euler_characteristic() &&
                     tout.boundary_loops.size() == tin.boundary_loops.size(),
                 what << ": a valid triangle mesh of the input's Euler characteristic " << tin.euler_characteristic() << " and "
                      << tin.boundary_loops.size() << " boundary loops");
  double moved = 0, far = 0, outside = 0, non_delaunay = 0, length_error = 0, scale = 0;
  for(auto v : vertices(in_sm)) {
    moved = std::max(moved, std::sqrt(CGAL::squared_distance(in_sm.point(v), out.point(v))));
    scale = std::max(scale, std::sqrt((in_sm.point(v) - CGAL::ORIGIN).squared_length()));
  }
  Input_tree tree(faces(in_sm).first, faces(in_sm).second, in_sm);
  for(auto v : vertices(out)) far = std::max(far, std::sqrt(tree.squared_distance(out.point(v))));
  std::size_t i = 0;
  for(auto f : faces(out)) {
    const auto g = Surface_mesh::Face_index(Surface_mesh::size_type(st.face_origin[i++]));
    std::vector<K::Point_3> t;
    for(auto h : CGAL::halfedges_around_face(halfedge(g, in_sm), in_sm)) t.push_back(in_sm.point(target(h, in_sm)));
    const K::Triangle_3 tri(t[0], t[1], t[2]);
    for(auto h : CGAL::halfedges_around_face(halfedge(f, out), out)) outside = std::max(outside, std::sqrt(CGAL::squared_distance(tri, out.point(target(h, out)))));
  }
  auto angle = [&](Surface_mesh::Halfedge_index h) {   // opposite h, in its face
    const K::Point_3 a = out.point(source(h, out)), b = out.point(target(h, out)), c = out.point(target(next(h, out), out));
    return std::atan2(std::sqrt(CGAL::cross_product(a - c, b - c).squared_length()), (a - c) * (b - c));
  };
  for(auto e : edges(out)) {
    const auto h = halfedge(e, out);
    const double d = std::sqrt(CGAL::squared_distance(out.point(source(h, out)), out.point(target(h, out))));
    length_error = std::max(length_error, std::abs(lengths[e] - d));
    if(!is_border(e, out)) non_delaunay = std::max(non_delaunay, angle(h) + angle(opposite(h, out)) - M_PI);
  }
  SMDF_CHECK_MSG(moved == 0 && far < 1e-12 * scale && outside < 1e-12 * scale,
                 what << ": the input vertices unmoved (" << moved << "), every vertex on the input surface (" << far / scale
                      << ") and every face inside its input face (" << outside / scale << ")");
  SMDF_CHECK_MSG(non_delaunay < 1e-9, what << ": every interior edge Delaunay (opposite angles - pi at most " << non_delaunay << ")");
  SMDF_CHECK_MSG(length_error < 1e-12 * scale, what << ": the output lengths are the points' distances (" << length_error / scale << " of the extent)");
  const double ratio = surface_area(out) / surface_area(in_sm);
  SMDF_CHECK_MSG(std::abs(ratio - 1) < 1e-12, what << ": the input's area (ratio " << ratio << ")");
  std::cout << what << ": " << num_faces(in_sm) << " -> " << num_faces(out) << " faces, " << st.inserted.size() << " vertices added" << std::endl;
  return st;
}

// The curvature of `lengths` on `mesh`, recomputed: the largest error against the targets.
template <typename Targets, typename Lengths>
double curvature_error(const Surface_mesh& mesh, const Targets& targets, const Lengths& lengths)
{
  const SMDF::Intrinsic_mesh<Surface_mesh> im(mesh, SMDF::parameters::edge_length_map(lengths));
  double err = 0;
  for(auto v : vertices(mesh)) err = std::max(err, std::abs(im.vertex_curvature(v) - targets[v]));
  return err;
}

void delaunay_refinement(const std::string& dir)
{
  // shared meshes: closed and open, genus 0 and 3, needle triangles
  for(const char* name : {"cheburashka_igltut.off", "face_bff.obj", "genus3_vhacd.off", "camelhead_igltut.off"}) {
    Surface_mesh mesh, out;
    SMDF::read_triangle_mesh(dir + "/meshes/" + name, mesh);
    check_refinement(mesh, mesh, out, name);
  }
  // caps with angles up to 179.9993 degrees: Delaunay sub-segments along their long sides take
  // about 1 / (smallest angle) splits; the limit per edge stops that with a clear status
  {
    Surface_mesh mesh, out;
    SMDF::read_triangle_mesh(dir + "/meshes/bad-stl-wing_openscad.off", mesh);
    const auto st = SMDF::conforming_delaunay_refinement(mesh, out);
    SMDF_CHECK_MSG(!st.success && st.message.find("too thin") != std::string::npos && num_faces(out) == 0,
                   "bad-stl-wing: the refinement stops at its limit per edge (" << st.message << ")");
    bool thrown = false;
    try { SMDF::conforming_delaunay_refinement(mesh, mesh); } catch(const SMDF::Input_error&) { thrown = true; }
    SMDF_CHECK_MSG(thrown, "a non-empty output mesh is rejected");
  }
  // Polyhedron_3: the same refinement
  {
    Surface_mesh mesh, out, pout;
    Polyhedron p;
    SMDF::read_triangle_mesh(dir + "/meshes/cheburashka_igltut.off", mesh);
    SMDF::read_triangle_mesh(dir + "/meshes/cheburashka_igltut.off", p);
    const auto a = check_refinement(mesh, mesh, out, "cheburashka");
    const auto b = check_refinement(p, mesh, pout, "cheburashka (Polyhedron_3)");
    SMDF_CHECK_MSG(a.inserted == b.inserted && a.face_origin == b.face_origin, "cheburashka: Polyhedron_3 gives the same refinement");
  }
  // Cheburashka with eight cones of pi/2: the flow without flips fails on the input
  // triangulation and converges on the refinement (curvature recomputed from the lengths)
  Surface_mesh mesh, out;
  SMDF::read_triangle_mesh(dir + "/meshes/cheburashka_igltut.off", mesh);
  const auto corners = diagonal_corners(mesh, K::Vector_3(0, 0, 0));
  auto targets = mesh.add_property_map<Surface_mesh::Vertex_index, double>("v:target", 0.).first;
  for(auto v : corners) targets[v] = M_PI / 2;
  auto flat = mesh.add_property_map<Surface_mesh::Edge_index, double>("e:flat", 0).first;
  const auto on_input = SMDF::compute_cone_metric(mesh, targets, flat, SMDF::parameters::intrinsic_edge_flips(false));
  SMDF_CHECK_MSG(!on_input.converged, "cheburashka, 8 cones: no convergence on the input triangulation without flips");
  check_refinement(mesh, mesh, out, "cheburashka refined");
  auto rtargets = out.add_property_map<Surface_mesh::Vertex_index, double>("v:target", 0.).first;
  for(auto v : corners) rtargets[v] = M_PI / 2;   // the input's vertices keep their indices
  auto rflat = out.add_property_map<Surface_mesh::Edge_index, double>("e:flat", 0).first;
  const auto on_refined = SMDF::compute_cone_metric(out, rtargets, rflat, SMDF::parameters::intrinsic_edge_flips(false));
  const double err = curvature_error(out, rtargets, rflat);
  SMDF_CHECK_MSG(on_refined.converged && !on_refined.triangulation_changed && err < 1e-9,
                 "cheburashka refined, 8 cones: converged without flips (curvature error " << err << ", " << on_refined.message << ")");
  // the pull-back through a refinement: a cube whose vertices are pushed onto a sphere, under
  // the cube's own metric (lengths): refined in that metric, the remesh of the refinement lies on
  // the input (the sphere polyhedron) and reads back as the cube's
  Surface_mesh ball, rball;
  smdf_test::soup_to_mesh(cube_soup(3, 5u), ball);
  auto cube_lengths = ball.add_property_map<Surface_mesh::Edge_index, double>("e:cube", 0).first;
  for(auto e : edges(ball)) cube_lengths[e] = std::sqrt(CGAL::squared_distance(ball.point(source(e, ball)), ball.point(target(e, ball))));
  for(auto v : vertices(ball)) {
    const K::Vector_3 d = ball.point(v) - K::Point_3(0.5, 0.5, 0.5);
    ball.point(v) = K::Point_3(0.5, 0.5, 0.5) + d / std::sqrt(d.squared_length());
  }
  auto rlengths = rball.add_property_map<Surface_mesh::Edge_index, double>("e:cube", 0).first;
  const auto rs = SMDF::conforming_delaunay_refinement(ball, rball, SMDF::parameters::edge_length_map(cube_lengths), SMDF::parameters::edge_length_map(rlengths));
  SMDF_CHECK_MSG(rs.success, "sphere-pushed cube refined in the cube's metric: " << rs.message);
  const auto dev = SMDF::develop_flat_metric(rball, SMDF::parameters::edge_length_map(rlengths));
  Surface_mesh remesh;
  const auto ts = SMDF::tessellate_flat_metric(rball, dev, SMDF::SQUARE_GRID, 0.25, remesh);
  check_remesh(ball, ball, remesh, ts, 4, {{3, 8}}, 96, "sphere-pushed cube, refined (" + std::to_string(rs.inserted.size()) + " vertices added), quads of 0.25");
}

// untangle_remesh() on the bunny's box remesh at about 8,000 quads, where one box squeezes the
// ears and 16 quads come out inverted: afterwards none is, the connectivity is the grid's (the
// same valence at every vertex, the eight cones held in place) and the full read-back passes on
// the moved mesh (every vertex on the input, no face flipped by the test's own normals, at its
// corners or nearest its centroid, CGAL's readers). At about 2,000 quads one quad lies across the ear, where smoothing finds no move;
// the pattern search of the third attempt unfolds it (before it, the status reported that face
// and moved nothing).
void untangling(const std::string& dir)
{
  Surface_mesh mesh;
  SMDF::read_triangle_mesh(dir + "/meshes/bunny_bff.obj", mesh);
  K::Vector_3 center(0, 0, 0);
  for(auto v : vertices(mesh)) center = center + (mesh.point(v) - CGAL::ORIGIN) / double(num_vertices(mesh));
  const std::array<Surface_mesh::Vertex_index, 8> corners = diagonal_corners(mesh, center);
  auto targets = mesh.add_property_map<Surface_mesh::Vertex_index, double>("v:target", 0.).first;
  for(auto v : corners) targets[v] = M_PI / 2;
  auto flat = mesh.add_property_map<Surface_mesh::Edge_index, double>("e:flat", 0).first;
  auto u = mesh.add_property_map<Surface_mesh::Vertex_index, double>("v:u", 0.).first;
  const auto cm = SMDF::compute_cone_metric(mesh, targets, flat, SMDF::parameters::conformal_factor_map(u).curvature_tolerance(1e-6));
  SMDF_CHECK_MSG(cm.converged, "bunny, 8 cones: " << cm.message);
  const double area = surface_area(mesh);
  std::map<int, std::size_t> outcome;
  for(int quads : {8000, 2000}) {
    const double h = std::sqrt(area / quads);
    auto lengths = mesh.add_property_map<Surface_mesh::Edge_index, double>("e:box", 0).first;
    const auto ps = SMDF::box_polycube_metric(mesh, corners, h, lengths, SMDF::parameters::conformal_factor_map(u));
    SMDF_CHECK_MSG(ps.success, "bunny box metric: " << ps.message);
    if(!ps.success) continue;
    const auto dev = SMDF::develop_flat_metric(mesh, SMDF::parameters::edge_length_map(lengths));
    Surface_mesh out;
    const auto st = SMDF::tessellate_flat_metric(mesh, dev, SMDF::SQUARE_GRID, h, out);
    mesh.remove_property_map(lengths);
    const std::string what = "bunny, box, about " + std::to_string(quads) + " quads, untangled";
    SMDF_CHECK_MSG(!st.success && st.inverted_faces > 0, what << ": the grid itself has inverted quads (" << st.inverted_faces << ")");
    std::vector<std::size_t> valence;
    std::vector<K::Point_3> before;
    for(auto v : vertices(out)) { valence.push_back(degree(v, out)); before.push_back(out.point(v)); }
    auto held = out.add_property_map<Surface_mesh::Vertex_index, bool>("v:held", false).first;
    for(const auto& iv : st.irregular_vertices) held[Surface_mesh::Vertex_index(Surface_mesh::size_type(iv.first))] = true;
    const SMDF::Untangle_status us = SMDF::untangle_remesh(mesh, out, SMDF::parameters::vertex_is_constrained_map(held));
    std::size_t same_valence = 0, held_still = 0, unmoved = 0;
    for(auto v : vertices(out)) {
      same_valence += degree(v, out) == valence[std::size_t(v)];
      held_still += held[v] && out.point(v) == before[std::size_t(v)];
      unmoved += out.point(v) == before[std::size_t(v)];
    }
    SMDF_CHECK_MSG(same_valence == num_vertices(out) && held_still == 8 && num_vertices(out) - unmoved == us.moved_vertices &&
                       (us.moved_vertices > 0) == us.success,
                   what << ": positions only, all or none (" << same_valence << " of " << num_vertices(out) << " valences kept, " << held_still
                        << " of 8 cones held, " << us.moved_vertices << " vertices moved, " << num_vertices(out) - unmoved << " found moved)");
    SMDF_CHECK_MSG(us.inverted_after == us.straddling_faces && us.success == (us.inverted_after == 0),
                   what << ": every face left inverted lies across a thin part (" << us.inverted_after << ", " << us.straddling_faces << "): " << us.message);
    // then the quads folded at a corner: fewer, and the test's own count (against each quad's
    // area vector) within the untangler's (which also counts corners against the input's normals)
    const std::size_t nonconvex_after = nonconvex_quads(out);
    SMDF_CHECK_MSG(!us.success || (us.folded_after * 4 < us.folded_before && nonconvex_after <= us.folded_after),
                   what << ": quads folded at a corner " << us.folded_before << " -> " << us.folded_after << " (at most a quarter left), "
                        << nonconvex_after << " by the test's count");
    outcome[quads] = us.inverted_after;
    std::cout << what << ": " << us.inverted_before << " inverted, " << us.inverted_after << " left (" << us.straddling_faces
              << " across a thin part), " << us.moved_vertices << " vertices moved by up to " << us.max_displacement << " edge lengths, "
              << us.rounds << " rounds" << std::endl;
    if(us.success) {   // the status of the moved mesh: the tessellation's checks, then no inversion
      SMDF::Grid_tessellation_status after = st;
      after.success = us.success;
      after.inverted_faces = us.inverted_after;
      check_remesh(mesh, mesh, out, after, 4, {{3, 8}}, double(num_faces(out)), what);
      const Input_tree tree(faces(mesh).first, faces(mesh).second, mesh);
      const std::size_t middle = flipped_at_centroid(mesh, out, tree);
      SMDF_CHECK_MSG(middle == 0, what << ": no face flipped against the input's normal nearest its centroid either (" << middle << " are)");
      // the untangler's folded count includes corners against the input's normals nearest the
      // centroid (of every input face there: at least the test's, which takes one)
      const std::size_t folded_middle = folded_at_centroid(mesh, out, tree);
      SMDF_CHECK_MSG(folded_middle <= us.folded_after,
                     what << ": faces folded against the input's normal nearest their centroid, by the test's count (" << folded_middle
                          << "), within the untangler's folded faces left (" << us.folded_after << ")");
    }
    if(quads == 8000) {
      // the same untangling with the input as a Polyhedron_3 (the grid's positions again)
      Polyhedron poly;
      CGAL::copy_face_graph(mesh, poly);
      Surface_mesh again = out;
      for(auto v : vertices(again)) again.point(v) = before[std::size_t(v)];
      auto held_again = again.property_map<Surface_mesh::Vertex_index, bool>("v:held").first;
      const SMDF::Untangle_status up = SMDF::untangle_remesh(poly, again, SMDF::parameters::vertex_is_constrained_map(held_again));
      double gap = 0;
      for(auto v : vertices(again)) gap = std::max(gap, std::sqrt(CGAL::squared_distance(again.point(v), out.point(v))));
      SMDF_CHECK_MSG(up.success && up.inverted_before == us.inverted_before,
                     what << ": the same on a Polyhedron_3 input (" << up.inverted_before << " inverted, " << up.moved_vertices << " moved, "
                          << "largest distance to the Surface_mesh run " << gap << ": closest points tie differently on input edges)");
    }
  }
  SMDF_CHECK_MSG(outcome[8000] == 0 && outcome[2000] == 0, "bunny: untangled at 8000 quads (" << outcome[8000] << " left) and at 2000 ("
                                                                 << outcome[2000] << " left, across the ear)");
}

// The integer solutions of the seams' conditions (internal/Integer_grid_map/seam_lattice.h), on
// random homogeneous integer systems shaped as integer_grid_map() writes them (a few unknowns per
// condition, coefficients +-1 and +-2 as the closings of nodes and of quarter- and half-turn
// cones put them, realified complex coefficients (1 - i^k) included, and on systems of at most 5
// unknowns any coefficient up to 6): B's columns solve every
// condition, the coordinate rows T satisfy T B = I (so every integer solution in B's span is B t
// with t = T y an integer vector), the number of free variables is n minus the conditions' rank,
// and, on small systems, every integer solution in a box found by enumeration is B (T y).
void seam_lattice_core()
{
  typedef SMDF::internal::Seam_lattice Lattice;
  std::mt19937 rng(20261207);
  std::size_t systems = 0, enumerated = 0, combined = 0, rounded_values = 0;
  for(int trial = 0; trial < 400; ++trial) {
    const int n = 1 + int(rng() % (trial < 200 ? 5 : 40));
    const int m = int(rng() % std::size_t(n + 3));
    std::vector<Lattice::Sparse> rows;
    for(int r = 0; r < m; ++r) {
      Lattice::Sparse row;
      if(n >= 4 && rng() % 3 == 0) {   // (1 - i^k) Z - T = 0, realified: Z = (z0, z1), T = (t0, t1)
        const int k = 1 + int(rng() % 3), z = int(rng() % std::size_t(n - 1)), t = (z + 2 + int(rng() % std::size_t(n - 2))) % n;
        const std::complex<double> c = 1. - std::pow(std::complex<double>(0, 1), k);
        const bool imaginary_part = rng() % 2;
        Lattice::Sparse q;
        auto add = [&](int i, long long v) { if(v != 0) q[i] += v; };
        if(!imaginary_part) { add(z, std::lround(c.real())); add((z + 1) % n, -std::lround(c.imag())); }
        else { add(z, std::lround(c.imag())); add((z + 1) % n, std::lround(c.real())); }
        add(t, -1);
        for(const auto& e : q) if(e.second != 0) row[e.first] = e.second;
      } else {
        // small systems: any small coefficients; large ones: a node's closing (+-1), sometimes a 2
        const int entries = 1 + int(rng() % 4);
        for(int j = 0; j < entries; ++j) {
          static const long long small_system[] = {1, -1, 2, -2, 3, -4, 6}, large_system[] = {1, -1, 1, -1, 1, -1, 2, -2};
          row[int(rng() % std::size_t(n))] += n <= 5 ? small_system[rng() % 7] : large_system[rng() % 8];
        }
        for(auto it = row.begin(); it != row.end();) it = it->second == 0 ? row.erase(it) : std::next(it);
      }
      if(!row.empty()) rows.push_back(row);
    }
    Lattice lattice(n, n / 2);
    std::string msg;
    bool added = true;
    for(const auto& row : rows) added = added && lattice.add(row, msg);
    SMDF_CHECK_MSG(added, "seam lattice, system " << trial << ": " << msg);
    if(!added) continue;
    ++systems;
    const std::vector<int> fv = lattice.free_variables();
    Eigen::MatrixXd C = Eigen::MatrixXd::Zero(Eigen::Index(rows.size()), n);
    for(std::size_t r = 0; r < rows.size(); ++r) for(const auto& e : rows[r]) C(Eigen::Index(r), e.first) = double(e.second);
    const Eigen::Index rank = rows.empty() ? 0 : Eigen::FullPivLU<Eigen::MatrixXd>(C).rank();
    SMDF_CHECK_MSG(Eigen::Index(fv.size()) == n - rank, "seam lattice, system " << trial << ": " << fv.size() << " free variables, " << n - rank << " expected");
    std::vector<Lattice::Sparse> columns;
    for(int w : fv) columns.push_back(lattice.column(w));
    for(std::size_t a = 0; a < fv.size(); ++a) {
      for(const auto& row : rows) {   // C b = 0, exactly
        long long dot = 0;
        for(const auto& e : row) { const auto it = columns[a].find(e.first); if(it != columns[a].end()) dot += e.second * it->second; }
        SMDF_CHECK_MSG(dot == 0, "seam lattice, system " << trial << ": a basis vector breaks a condition by " << dot);
      }
      for(std::size_t b = 0; b < fv.size(); ++b) {   // T B = I, exactly
        long long dot = 0;
        for(const auto& e : lattice.coordinate(fv[a])) { const auto it = columns[b].find(e.first); if(it != columns[b].end()) dot += e.second * it->second; }
        SMDF_CHECK_MSG(dot == (a == b ? 1 : 0), "seam lattice, system " << trial << ": T B is not the identity at " << a << ", " << b);
      }
      combined += lattice.coordinate(fv[a]).size() > 1;
    }
    // rounding: values fixed one at a time, each to the nearest admitted integer of a random
    // target; in the end every value is determined, and the integers solve every condition and
    // keep every fixed value. On small systems an admitted value is checked against enumeration:
    // a value that some integer solution in [-3, 3]^n takes (with the earlier fixes) is admitted.
    {
      Lattice rounding(n, n / 2);
      for(const auto& row : rows) rounding.add(row, msg);
      std::vector<std::pair<int, long long>> fixed;
      std::vector<int> order(static_cast<std::size_t>(n));
      for(int k = 0; k < n; ++k) order[std::size_t(k)] = k;
      std::shuffle(order.begin(), order.end(), rng);
      bool sound = true;
      for(int k : order) {
        if(rounding.determined(k)) continue;
        const long long target = static_cast<long long>(rng() % 7) - 3;
        long long v = target;
        for(int step = 1; !rounding.admits(k, v) && step < 64; ++step) v = target + ((step + 1) / 2) * (step % 2 == 1 ? 1 : -1);
        if(n <= 4) {   // every value an enumerated solution takes is admitted
          std::vector<long long> y(std::size_t(n), -3);
          for(;;) {
            bool solves = true;
            for(const auto& row : rows) { long long dot = 0; for(const auto& e : row) dot += e.second * y[std::size_t(e.first)]; solves = solves && dot == 0; }
            for(const auto& f : fixed) solves = solves && y[std::size_t(f.first)] == f.second;
            if(solves) sound = sound && rounding.admits(k, y[std::size_t(k)]);
            int i = 0;
            while(i < n && y[std::size_t(i)] == 3) y[std::size_t(i++)] = -3;
            if(i == n) break;
            ++y[std::size_t(i)];
          }
        }
        Lattice::Sparse fix;
        fix[k] = 1;
        SMDF_CHECK_MSG(rounding.add(fix, msg, v), "seam lattice, system " << trial << ": an admitted value was refused: " << msg);
        fixed.emplace_back(k, v);
      }
      SMDF_CHECK_MSG(sound, "seam lattice, system " << trial << ": a value that an integer solution takes was not admitted");
      bool all = true, solves = true, kept = true;
      for(int k = 0; k < n; ++k) all = all && rounding.determined(k);
      for(const auto& row : rows) { long long dot = 0; for(const auto& e : row) dot += e.second * rounding.offset(e.first); solves = solves && dot == 0; }
      for(const auto& f : fixed) kept = kept && rounding.offset(f.first) == f.second;
      SMDF_CHECK_MSG(all && solves && kept, "seam lattice, system " << trial << ": after the roundings, determined " << all << ", solves " << solves << ", fixed values kept " << kept);
      rounded_values += fixed.size();
    }
    if(n > 4) continue;
    // every integer solution in [-4, 4]^n is B (T y)
    std::vector<long long> y(std::size_t(n), -4);
    for(;;) {
      bool solves = true;
      for(const auto& row : rows) { long long dot = 0; for(const auto& e : row) dot += e.second * y[std::size_t(e.first)]; solves = solves && dot == 0; }
      if(solves) {
        std::vector<long long> back(std::size_t(n), 0);
        for(std::size_t a = 0; a < fv.size(); ++a) {
          long long t = 0;
          for(const auto& e : lattice.coordinate(fv[a])) t += e.second * y[std::size_t(e.first)];
          for(const auto& e : columns[a]) back[std::size_t(e.first)] += e.second * t;
        }
        SMDF_CHECK_MSG(back == y, "seam lattice, system " << trial << ": an integer solution is not B T y");
        ++enumerated;
      }
      int i = 0;
      while(i < n && y[std::size_t(i)] == 4) y[std::size_t(i++)] = -4;
      if(i == n) break;
      ++y[std::size_t(i)];
    }
  }
  {   // a dense system of large coefficients: the changes of variables outgrow 2^30, said so
    Lattice lattice(60, 30);
    std::string msg;
    bool added = true;
    for(int r = 0; r < 60 && added; ++r) {
      Lattice::Sparse row;
      for(int j = 0; j < 60; ++j) row[j] = 2 + (long long)(rng() % 5);
      added = lattice.add(row, msg);
    }
    SMDF_CHECK_MSG(!added && msg.find("2^30") != std::string::npos, "seam lattice: a dense system of coefficients 2 to 6 reduced without overflow, or failed without saying why");
  }
  std::cout << "seam lattice: " << systems << " random systems, " << combined << " coordinates that combine several values, "
            << enumerated << " integer solutions enumerated, each B T y; " << rounded_values << " values rounded to admitted integers" << std::endl;
  SMDF_CHECK_MSG(combined > 0, "seam lattice: no system needed a combined coordinate (the extended-Euclid path untested)");
}

// Quads of a remesh folded at a corner (not convex, none inverted) on a flat input: a 6 x 6 grid
// of quads on the square [0, 3]^2 (the input: 12 x 12 cells, two triangles each), three inner
// vertices pushed into a neighbouring quad. untangle_remesh() counts the folded quads, unfolds
// them along the plane and moves no border vertex; an independent count of corners with a
// scaled Jacobian of at most 0 agrees before and finds none after.
// winding_faults() (internal/Integer_grid_map/winding.h): maps whose triangles are all
// counterclockwise but which wrap twice around an interior vertex, or by 2 pi around a boundary
// vertex whose boundary runs straight, are caught there and nowhere else; the faithful images of
// the same fans are not.
void winding_faults_core()
{
  typedef std::complex<double> C;
  for(int open = 0; open < 2; ++open) {
    const int n = open ? 5 : 8;   // triangles around the centre vertex 0
    Surface_mesh fan;
    std::vector<Surface_mesh::Vertex_index> v{fan.add_vertex(K::Point_3(0, 0, 0))};
    const double span = open ? CGAL_PI : 2 * CGAL_PI;
    const int ring = open ? n + 1 : n;
    for(int i = 0; i < ring; ++i) v.push_back(fan.add_vertex(K::Point_3(std::cos(span * i / n), std::sin(span * i / n), 0)));
    for(int i = 0; i < n; ++i) fan.add_face(v[0], v[std::size_t(1 + i)], v[std::size_t(1 + (i + 1) % ring)]);
    const SMDF::internal::Mesh_arrays<Surface_mesh> m(fan, SMDF::parameters::default_values());
    SMDF::internal::Seam_layout seams;
    seams.turns.assign(m.number_of_vertices(), 0);
    seams.turn_quarters.assign(m.number_of_vertices(), 0);
    const std::vector<double> expected = SMDF::internal::map_angle_sums_expected(m, seams);
    SMDF_CHECK(std::abs(expected[0] - span) < 1e-12);
    for(int wrap = 1; wrap <= 2; ++wrap) {
      // the ring at angles wrap * span * i / n: a triangle spans less than pi either way
      const double image_span = open ? wrap * (span - 0.1) + (wrap == 1 ? 0.1 : 0.) : wrap * span;
      auto image = [&](int x) {
        const int a = m.source(x);
        if(a == 0) return C(0, 0);
        return std::polar(1., image_span * (a - 1) / n);
      };
      for(std::size_t f = 0; f < m.number_of_faces(); ++f) {   // every image triangle counterclockwise
        const int x0 = m.face_halfedge[f], x1 = m.next[std::size_t(x0)], x2 = m.next[std::size_t(x1)];
        const C d1 = image(x1) - image(x0), d2 = image(x2) - image(x0);
        SMDF_CHECK(d1.real() * d2.imag() - d1.imag() * d2.real() > 0);
      }
      const std::vector<int> faults = SMDF::internal::winding_faults(m, expected, image);
      const bool centre = std::find(faults.begin(), faults.end(), 0) != faults.end();
      SMDF_CHECK_MSG(centre == (wrap == 2), (open ? "a boundary vertex" : "an interior vertex") << " wrapped " << wrap
                                                                                                  << " times: fault found " << centre);
    }
  }
}

// A face bent around a thin part: the input is a thin shell (two sheets 0.1 apart, radii 1.05
// and 0.95 about the y axis, each facing away from the other), the remesh lies on its outer
// sheet. One quad spanning 0.7 radians of the arc sags 0.064 below the outer sheet, nearer the
// inner one: its corners face the input (the outer sheet's normals), its middle does not.
// untangle_remesh() counts it inverted (the test's own count at the centroid agrees, the count
// at the corners finds none); its corners are on the remesh's border, so nothing moves and the
// status fails with the grid unmoved. The same region as 2 x 2 quads sags 0.016: none inverted.
void face_bent_around_thin_part()
{
  Surface_mesh shell;
  auto at = [](double r, double a, double y) { return K::Point_3(r * std::sin(a), y, r * std::cos(a)); };
  const int na = 24, ny = 4;
  for(int sheet = 0; sheet < 2; ++sheet) {   // outer (normals away from the axis), inner (towards it)
    const double r = sheet == 0 ? 1.05 : 0.95;
    std::vector<Surface_mesh::Vertex_index> v;
    for(int j = 0; j <= ny; ++j)
      for(int i = 0; i <= na; ++i) v.push_back(shell.add_vertex(at(r, -0.6 + 1.2 * i / na, double(j) / ny)));
    for(int j = 0; j < ny; ++j)
      for(int i = 0; i < na; ++i) {
        const auto a = v[std::size_t(j * (na + 1) + i)], b = v[std::size_t(j * (na + 1) + i + 1)], c = v[std::size_t((j + 1) * (na + 1) + i + 1)],
                   d = v[std::size_t((j + 1) * (na + 1) + i)];
        if(sheet == 0) { shell.add_face(a, b, c); shell.add_face(a, c, d); }
        else { shell.add_face(a, c, b); shell.add_face(a, d, c); }
      }
  }
  const Input_tree tree(faces(shell).first, faces(shell).second, shell);
  for(int cells = 1; cells <= 2; ++cells) {
    Surface_mesh grid;
    std::vector<Surface_mesh::Vertex_index> g;
    for(int j = 0; j <= cells; ++j)
      for(int i = 0; i <= cells; ++i) g.push_back(grid.add_vertex(at(1.05, -0.35 + 0.7 * i / cells, 0.25 + 0.5 * j / cells)));
    for(int j = 0; j < cells; ++j)
      for(int i = 0; i < cells; ++i)
        grid.add_face(g[std::size_t(j * (cells + 1) + i)], g[std::size_t(j * (cells + 1) + i + 1)], g[std::size_t((j + 1) * (cells + 1) + i + 1)],
                      g[std::size_t((j + 1) * (cells + 1) + i)]);
    const Surface_mesh before = grid;
    const std::size_t at_corners = flipped_faces(shell, grid, tree), at_centroid = flipped_at_centroid(shell, grid, tree);
    const SMDF::Untangle_status us = SMDF::untangle_remesh(shell, grid);
    std::size_t moved = 0;
    for(auto v : vertices(grid)) moved += grid.point(v) != before.point(v);
    const std::size_t expected = cells == 1 ? 1 : 0;
    SMDF_CHECK_MSG(at_corners == 0 && at_centroid == expected && us.inverted_before == expected,
                   "thin shell, " << cells << " x " << cells << " quads: " << expected << " inverted by the untangler's count ("
                                  << us.inverted_before << "), as by the test's at the centroid (" << at_centroid << "), none at the corners ("
                                  << at_corners << ")");
    SMDF_CHECK_MSG(us.success == (expected == 0) && us.inverted_after == expected && moved == 0 && (us.success || !us.message.empty()),
                   "thin shell, " << cells << " x " << cells << " quads: " << (expected ? "reported, the border held and nothing moved" : "valid as it is")
                                  << " (" << moved << " moved): " << us.message);
  }
}

void folded_quads()
{
  Surface_mesh plane;
  {
    const int n = 12;
    std::vector<Surface_mesh::Vertex_index> v;
    for(int j = 0; j <= n; ++j)
      for(int i = 0; i <= n; ++i) v.push_back(plane.add_vertex(K::Point_3(3. * i / n, 3. * j / n, 0)));
    for(int j = 0; j < n; ++j)
      for(int i = 0; i < n; ++i) {
        const auto a = v[std::size_t(j * (n + 1) + i)], b = v[std::size_t(j * (n + 1) + i + 1)], c = v[std::size_t((j + 1) * (n + 1) + i + 1)],
                   d = v[std::size_t((j + 1) * (n + 1) + i)];
        plane.add_face(a, b, c);
        plane.add_face(a, c, d);
      }
  }
  Surface_mesh grid;
  const int m = 6;
  std::vector<Surface_mesh::Vertex_index> g;
  for(int j = 0; j <= m; ++j)
    for(int i = 0; i <= m; ++i) g.push_back(grid.add_vertex(K::Point_3(0.5 * i, 0.5 * j, 0)));
  for(int j = 0; j < m; ++j)
    for(int i = 0; i < m; ++i)
      grid.add_face(g[std::size_t(j * (m + 1) + i)], g[std::size_t(j * (m + 1) + i + 1)], g[std::size_t((j + 1) * (m + 1) + i + 1)],
                    g[std::size_t((j + 1) * (m + 1) + i)]);
  // each pushed 0.35 along a diagonal, into the quad beyond it: that quad gets a reflex corner
  for(const std::array<int, 2>& at : {std::array<int, 2>{{1, 1}}, std::array<int, 2>{{4, 2}}, std::array<int, 2>{{2, 4}}})
    grid.point(g[std::size_t(at[1] * (m + 1) + at[0])]) = K::Point_3(0.5 * at[0] + 0.35, 0.5 * at[1] + 0.35, 0);
  const std::size_t folded = nonconvex_quads(grid);
  const Surface_mesh before = grid;
  const SMDF::Untangle_status us = SMDF::untangle_remesh(plane, grid);
  std::size_t border_moved = 0;
  double off_plane = 0;
  for(auto v : vertices(grid)) {
    border_moved += CGAL::is_border(v, grid) && grid.point(v) != before.point(v);
    off_plane = std::max(off_plane, std::abs(grid.point(v).z()));
  }
  SMDF_CHECK_MSG(folded >= 3 && us.inverted_before == 0 && us.folded_before == folded,
                 "folded quads: the untangler counts the folded quads as the test does (" << us.folded_before << ", " << folded << "), none inverted");
  SMDF_CHECK_MSG(us.success && us.folded_after == 0 && nonconvex_quads(grid) == 0 && us.moved_vertices > 0 && border_moved == 0 && off_plane == 0,
                 "folded quads: all unfolded along the plane (" << us.folded_after << " left by its count, " << nonconvex_quads(grid) << " by the test's, "
                                                             << us.moved_vertices << " moved, " << border_moved << " border vertices moved)");
  std::cout << "folded quads on a plane: " << us.folded_before << " -> " << us.folded_after << ", " << us.moved_vertices << " vertices moved"
            << std::endl;
  // one vertex pushed 0.6 along the diagonal, past the far corner of its quad: that quad is
  // inverted (and so also folded); untangled, nothing is left folded either
  Surface_mesh inverted_grid = before;
  inverted_grid.point(g[std::size_t(1 * (m + 1) + 1)]) = K::Point_3(0.5 + 0.6, 0.5 + 0.6, 0);
  inverted_grid.point(g[std::size_t(2 * (m + 1) + 4)]) = K::Point_3(2.0, 1.0, 0);   // the other two back on the grid
  inverted_grid.point(g[std::size_t(4 * (m + 1) + 2)]) = K::Point_3(1.0, 2.0, 0);
  const SMDF::Untangle_status ui = SMDF::untangle_remesh(plane, inverted_grid);
  SMDF_CHECK_MSG(ui.inverted_before >= 1 && ui.folded_before >= ui.inverted_before && ui.success && ui.folded_after == 0 &&
                     nonconvex_quads(inverted_grid) == 0,
                 "folded quads: an inverted quad untangled leaves nothing folded (" << ui.inverted_before << " inverted, folded "
                                                                                 << ui.folded_before << " -> " << ui.folded_after << ", "
                                                                                 << nonconvex_quads(inverted_grid) << " by the test's count)");
}

// A polycube of three unit cubes in an L (Lai et al.: "some cone singularities ... are
// negative, which can be handled by our method consistently"): its 14 unit squares as P, on a
// smoothly deformed mesh of that shape (6 x 6 cells a square). P has corners of 3 squares
// (cones of pi/2), of 4 (flat) and, at the inner corner of the L, of 5 (cones of -pi/2).
// polyhedron_metric() gives the metric, polyhedron_compatibility() reads it back as P's squares,
// and the quad remesh has valence 3 at the convex corners and 5 at the two concave ones.
void l_shaped_polycube()
{
  const std::set<std::array<int, 3>> cubes = {{{0, 0, 0}}, {{1, 0, 0}}, {{0, 1, 0}}};
  const int k = 6;
  Surface_mesh mesh;
  std::map<std::array<int, 3>, Surface_mesh::Vertex_index> at;   // mesh vertices by coordinates times k
  std::map<std::array<int, 3>, int> corner_of;                   // P's corners by lattice coordinates
  std::vector<Surface_mesh::Vertex_index> corners;
  std::vector<std::vector<int>> pfaces;
  auto vertex = [&](std::array<int, 3> g) {
    auto it = at.find(g);
    if(it != at.end()) return it->second;
    const double x = double(g[0]) / k, y = double(g[1]) / k, z = double(g[2]) / k;
    const auto v = mesh.add_vertex(K::Point_3(x + 0.08 * std::sin(1.3 * y + 0.5 * z), y + 0.08 * std::sin(1.1 * z + 0.7 * x),
                                              z + 0.08 * std::sin(0.9 * x + 1.2 * y)));
    at[g] = v;
    return v;
  };
  for(const auto& c : cubes)
    for(int a = 0; a < 3; ++a)
      for(int side = 0; side < 2; ++side) {
        std::array<int, 3> n = c;
        n[std::size_t(a)] += side ? 1 : -1;
        if(cubes.count(n)) continue;   // shared with another cube: inside
        const int u = (a + 1) % 3, w = (a + 2) % 3;
        auto lattice = [&](int i, int j) {   // cell coordinates (i, j) of the square, times k
          std::array<int, 3> g{{c[0] * k, c[1] * k, c[2] * k}};
          g[std::size_t(a)] += side * k;
          g[std::size_t(u)] += i;
          g[std::size_t(w)] += j;
          return g;
        };
        // counterclockwise seen from outside: (u, w) for the + side, (w, u) for the - side
        const std::array<std::array<int, 2>, 4> ccw = side ? std::array<std::array<int, 2>, 4>{{{{0, 0}}, {{1, 0}}, {{1, 1}}, {{0, 1}}}}
                                                           : std::array<std::array<int, 2>, 4>{{{{0, 0}}, {{0, 1}}, {{1, 1}}, {{1, 0}}}};
        std::vector<int> pf;
        for(const auto& q : ccw) {
          std::array<int, 3> g = lattice(q[0] * k, q[1] * k);
          auto it = corner_of.find(g);
          if(it == corner_of.end()) { it = corner_of.emplace(g, int(corners.size())).first; corners.push_back(vertex(g)); }
          pf.push_back(it->second);
        }
        pfaces.push_back(pf);
        for(int i = 0; i < k; ++i)
          for(int j = 0; j < k; ++j) {
            std::array<Surface_mesh::Vertex_index, 4> q;
            for(std::size_t m = 0; m < 4; ++m) q[m] = vertex(lattice(i + ccw[m][0], j + ccw[m][1]));
            mesh.add_face(q[0], q[1], q[2]);
            mesh.add_face(q[0], q[2], q[3]);
          }
      }
  SMDF_CHECK_MSG(CGAL::is_valid_polygon_mesh(mesh) && CGAL::is_closed(mesh) && pfaces.size() == 14 && corners.size() == 16,
                 "L polycube: a closed mesh, 14 squares, 16 corners (" << pfaces.size() << ", " << corners.size() << ")");
  std::map<int, int> squares_at;
  for(const auto& f : pfaces) for(int c : f) ++squares_at[c];
  std::map<int, std::size_t> expected;   // valence -> count, the corners of 3 and 5 squares
  for(const auto& p : squares_at) if(p.second != 4) ++expected[p.second];
  SMDF_CHECK_MSG(expected.size() == 2 && expected[5] == 2, "L polycube: two concave corners of 5 squares (" << expected[5] << ")");
  const double L = std::sqrt(surface_area(mesh) / 14);
  auto lengths = mesh.add_property_map<Surface_mesh::Edge_index, double>("e:l", 0).first;
  const auto ps = SMDF::polyhedron_metric(mesh, corners, pfaces, L, lengths);
  SMDF_CHECK_MSG(ps.success, "L polycube metric: " << ps.message);
  if(!ps.success) return;
  const auto fit = SMDF::polyhedron_compatibility(mesh, corners, pfaces, L / 4, SMDF::parameters::edge_length_map(lengths));
  SMDF_CHECK_MSG(fit.compatible && std::count(fit.sides.begin(), fit.sides.end(), 4) == int(fit.sides.size()),
                 "L polycube metric: P's unit squares, 4 grid edges a side (angles off by " << fit.max_angle_deviation << ", sides by "
                                                                                            << fit.max_side_deviation << ")");
  const auto dev = SMDF::develop_flat_metric(mesh, SMDF::parameters::edge_length_map(lengths));
  const SMDF::internal::Mesh_arrays<Surface_mesh> arrays(mesh, SMDF::parameters::edge_length_map(lengths));
  std::vector<double> curvature;
  SMDF::internal::vertex_curvatures(arrays, curvature);
  double total = 0;
  std::size_t negative = 0, cones = 0;
  for(double c : curvature) {
    total += c;
    negative += std::abs(c + M_PI / 2) < 1e-9;
    cones += std::abs(c) > 1e-9;
  }
  SMDF_CHECK_MSG(negative == 2 && cones == dev.cones().size() && cones == expected[3] + 2 && std::abs(total - 4 * M_PI) < 1e-9,
                 "L polycube metric: cones of pi/2 at the convex corners, two of -pi/2, flat elsewhere, 4 pi in all (" << negative << " of -pi/2, "
                     << cones << " cones, " << total << ")");
  Surface_mesh out;
  const auto st = SMDF::tessellate_flat_metric(mesh, dev, SMDF::SQUARE_GRID, L / 4, out);
  check_remesh(mesh, mesh, out, st, 4, expected, 14 * 16, "L polycube, quads of a quarter side");
}

// Three parts, three CTest entries that run in parallel: "automatic" (cones placed for remeshing,
// integer-grid maps), "polycube" (the polycube and the paper's polyhedra's metrics) and
// "untangling" (refinement, untangling: together they took twice the automatic part under ASan);
// no argument runs all three.
// Integer-grid maps of the open shared meshes of at most 40k faces (#37 item 4), on the input's
// own triangulation where the placed cones' metric converges there: cones and boundary corners
// placed with one quad side of room from the boundary, the field parallel to the boundary
// (boundary_aligned_field_of_metric()), the map at about 2,000 quads. Read back from the map
// alone: across every interior edge a grid symmetry; every border edge on a grid line; every
// singularity and every corner an integer point, the corners the placed ones; no triangle folded
// where the status says none; in an unfolded map the images' angles sum to 2 pi - K at the
// interior vertices and to pi - kappa on the boundary (K, kappa: the placed cones and corners).
// Every unfolded map is tessellated and read back (quads, the input's Euler characteristic,
// interior irregular vertices the interior cones, on the input, none flipped). The T-mesh is read
// back as in the closed maps.
void integer_grid_maps_open(const std::string& dir)
{
  typedef Surface_mesh::Vertex_index V;
  typedef Surface_mesh::Halfedge_index H;
  typedef std::complex<double> C;
  std::size_t runs = 0, unfolded = 0, tessellated = 0, skipped = 0, t_meshes = 0;
  smdf_test::for_each_shared_mesh<Surface_mesh>(dir, true, [&](const smdf_test::Manifest_entry& e, const Surface_mesh& input) {
    if(e.F > 40000) return;
    Surface_mesh mesh = input;
    const double h_in = std::sqrt(surface_area(mesh) / 2000);
    auto placed = mesh.add_property_map<Surface_mesh::Edge_index, double>("e:placed", 0.).first;
    const auto cs = SMDF::place_remeshing_cones(mesh, placed, SMDF::parameters::minimum_boundary_distance(h_in));
    if(!cs.success) { ++skipped; std::cout << e.file << ": placement: " << cs.message << " (skipped)" << std::endl; return; }
    auto cone_target = mesh.add_property_map<V, double>("v:target", 0.).first;
    std::map<std::size_t, double> K;
    for(const auto& c : cs.cones) { cone_target[c.first] = c.second; K[std::size_t(c.first)] = c.second; }
    auto cl = mesh.add_property_map<Surface_mesh::Edge_index, double>("e:cone", 0.).first;
    const auto cm = SMDF::compute_cone_metric(mesh, cone_target, cl, SMDF::parameters::intrinsic_edge_flips(false));
    if(!cm.converged) { ++skipped; std::cout << e.file << ": the cone metric needs a refinement or flips (skipped)" << std::endl; return; }
    auto fa = mesh.add_property_map<Surface_mesh::Face_index, double>("f:angle", 0.).first;
    auto matching = mesh.add_property_map<Surface_mesh::Edge_index, int>("e:matching", 0).first;
    const auto bf = SMDF::boundary_aligned_field_of_metric(mesh, 4, fa, matching, SMDF::parameters::edge_length_map(cl));
    SMDF_CHECK_MSG(bf.success, e.file << ": the boundary-aligned cross field: " << bf.message);
    if(!bf.success) return;
    double area = 0;
    for(auto f : faces(mesh)) {
      const H x = halfedge(f, mesh);
      const double a = cl[edge(x, mesh)], b = cl[edge(next(x, mesh), mesh)], c = cl[edge(prev(x, mesh), mesh)], p = (a + b + c) / 2;
      area += std::sqrt(std::max(0., p * (p - a) * (p - b) * (p - c)));
    }
    auto uv = mesh.add_property_map<H, std::array<double, 2>>("h:uv").first;
    const SMDF::Integer_grid_map_status st = SMDF::integer_grid_map(mesh, fa, std::sqrt(area / 2000), uv, SMDF::parameters::edge_length_map(cl));
    ++runs;
    const std::string what = e.file + " (genus " + e.genus + ", " + std::to_string(e.boundary_loops) + " boundary loops, " +
                             std::to_string(cs.cones.size()) + " cones and corners)";
    std::cout << what << ": " << (st.success ? "unfolded" : st.message) << ", " << st.arcs << " seams, " << t_mesh_summary(st) << ", " << st.boundary_lines
              << " boundary lines, " << st.boundary_corners.size() << " corners, energy " << st.seamless_energy << " -> " << st.integer_energy << std::endl;
    check_t_mesh(st, st.singularities.size() + st.boundary_corners.size(), 2 - 2 * std::stol(e.genus) - long(e.boundary_loops), what, t_meshes);
    if(st.folded_triangles == 0 && st.winding_faults == 0) SMDF_CHECK_MSG(st.success, what << ": " << st.message);
    if(!st.success && st.folded_triangles == 0 && st.winding_faults == 0) return;
    auto at = [&](H x) { return C(uv[x][0], uv[x][1]); };   // target(x) in face(x)
    auto lattice = [](C p) { return std::abs(p - C(std::round(p.real()), std::round(p.imag()))); };
    double worst_seam = 0, worst_line = 0;
    for(auto ed : edges(mesh)) {
      const H x = halfedge(ed, mesh), o = opposite(x, mesh);
      if(is_border(x, mesh) || is_border(o, mesh)) {   // on a grid line: U or V constant and an integer
        const H in = is_border(x, mesh) ? o : x;
        const C a = at(prev(in, mesh)), b = at(in);
        worst_line = std::max(worst_line, std::min(std::max(std::abs(a.real() - b.real()), std::abs(a.real() - std::round(a.real()))),
                                                   std::max(std::abs(a.imag() - b.imag()), std::abs(a.imag() - std::round(a.imag())))));
        continue;
      }
      const C aL = at(prev(x, mesh)), bL = at(x), bR = at(prev(o, mesh)), aR = at(o);
      const C ratio = (bR - aR) / (bL - aL);
      const C rk(std::round(ratio.real()), std::round(ratio.imag()));
      worst_seam = std::max(worst_seam, std::abs(ratio - rk) + std::abs(std::abs(rk) - 1) + lattice(aR - rk * aL));
    }
    SMDF_CHECK_MSG(worst_seam < 1e-6 && worst_line < 1e-6, what << ": seams off the grid's symmetries by " << worst_seam
                                                                << ", border edges off grid lines by " << worst_line);
    std::set<std::size_t> points;
    for(const auto& sv : st.singularities) points.insert(sv.first);
    std::size_t placed_corners = 0, corners_found = 0;
    for(const auto& c : cs.cones) placed_corners += mesh.is_border(c.first);
    for(const auto& cv : st.boundary_corners) { points.insert(cv.first); corners_found += K.count(cv.first) && mesh.is_border(V(Surface_mesh::size_type(cv.first))); }
    SMDF_CHECK_MSG(corners_found == placed_corners && st.boundary_corners.size() == placed_corners,
                   what << ": the map's boundary corners are the " << placed_corners << " placed ones (" << st.boundary_corners.size() << ")");
    std::vector<double> angle_sum(num_vertices(mesh), 0.);
    std::size_t folded = 0;
    double worst_point = 0;
    for(auto f : faces(mesh)) {
      for(H x : CGAL::halfedges_around_face(halfedge(f, mesh), mesh)) {
        const C p = at(x), a = at(prev(x, mesh)), b = at(next(x, mesh));
        angle_sum[target(x, mesh)] += std::abs(std::arg((b - p) / (a - p)));
        if(points.count(std::size_t(target(x, mesh)))) worst_point = std::max(worst_point, lattice(p));
      }
      const H x = halfedge(f, mesh);
      const C p0 = at(prev(x, mesh)), p1 = at(x), p2 = at(next(x, mesh));
      folded += !((p1 - p0).real() * (p2 - p0).imag() - (p1 - p0).imag() * (p2 - p0).real() > 0);
    }
    SMDF_CHECK_MSG(worst_point < 1e-6, what << ": a singularity or corner " << worst_point << " away from the lattice");
    SMDF_CHECK_MSG(folded == st.folded_triangles, what << ": " << folded << " folded triangles, the status says " << st.folded_triangles);
    if(folded != 0) return;
    ++unfolded;
    double worst_k = 0;
    std::map<int, std::size_t> expected;
    for(auto v : vertices(mesh)) {
      if(mesh.is_isolated(v)) continue;
      const auto it = K.find(std::size_t(v));
      const double k = it == K.end() ? 0. : it->second;
      worst_k = std::max(worst_k, std::abs((mesh.is_border(v) ? CGAL_PI : 2 * CGAL_PI) - angle_sum[v] - k));
      if(!mesh.is_border(v) && it != K.end()) expected[4 - int(std::lround(k / (CGAL_PI / 2)))]++;
    }
    SMDF_CHECK_MSG((worst_k < 1e-6) == (st.winding_faults == 0),
                   what << ": the map's cones and corners differ from the placed ones by " << worst_k << ", " << st.winding_faults << " winding faults");
    if(!st.success) return;
    auto gl = mesh.add_property_map<Surface_mesh::Edge_index, double>("e:grid", 0.).first;
    for(auto ed : edges(mesh)) {
      const H x = is_border(halfedge(ed, mesh), mesh) ? opposite(halfedge(ed, mesh), mesh) : halfedge(ed, mesh);
      gl[ed] = std::abs(at(x) - at(prev(x, mesh)));
    }
    const auto dev = SMDF::develop_flat_metric(mesh, SMDF::parameters::edge_length_map(gl));
    Surface_mesh out;
    const auto ts = SMDF::tessellate_flat_metric(mesh, dev, SMDF::SQUARE_GRID, 1., out);
    if(ts.success) check_remesh(mesh, mesh, out, ts, 4, expected, double(ts.faces), what + ", tessellated");
    else std::cout << what << ": not tessellated: " << ts.message << std::endl;
    tessellated += ts.success;
  });
  std::cout << "open integer-grid maps: " << unfolded << " of " << runs << " without a fold, " << tessellated << " tessellated (" << skipped
            << " skipped), " << t_meshes << " T-meshes traced" << std::endl;
  const bool reduced = std::getenv("SMDF_TEST_MAX_FACES") != nullptr;
  SMDF_CHECK(runs >= (reduced ? 1u : 4u) && unfolded * 2 >= runs && tessellated == unfolded && t_meshes >= (reduced ? 1u : 2u));
}

// The spread, modulo pi/2, of the border edges' directions in a development of `mesh` under the
// flat metric `l` (0 when every boundary runs along the grid of one cross field).
double border_direction_spread(const Surface_mesh& mesh, Surface_mesh::Property_map<Surface_mesh::Edge_index, double> l)
{
  const auto dev = SMDF::develop_flat_metric(mesh, SMDF::parameters::edge_length_map(l));
  const double q = CGAL_PI / 2;
  double first = -1, worst = 0;
  for(auto hb : halfedges(mesh)) {
    if(!is_border(hb, mesh)) continue;
    const auto x = opposite(hb, mesh);
    const auto f = face(x, mesh);
    const auto h0 = halfedge(f, mesh);
    const int k = x == h0 ? 0 : x == next(h0, mesh) ? 1 : 2;
    const auto c = dev.corners(f);
    const double a = std::atan2(c[std::size_t((k + 1) % 3)].y() - c[std::size_t(k)].y(), c[std::size_t((k + 1) % 3)].x() - c[std::size_t(k)].x());
    const double r = a - q * std::floor(a / q);
    if(first < 0) first = r;
    const double d = std::abs(r - first);
    worst = std::max(worst, std::min(d, q - d));
  }
  return worst;
}

// Seamless metrics (seamless_cone_metric(), metric compensation's rotational part) of the closed
// shared meshes of genus 1 or more and at most 40k faces, from the flat cone metric of their
// placed cones on the input's edges. Where it succeeds, read back: every vertex's curvature is
// the placed cone's (or 0), and the package's holonomy-group test (Theorem 3.2, N = 4) passes on
// a homotopy basis around the cones and the handles, which the input metric failed; where it
// fails, the output is the input metric unchanged.
void seamless_metrics(const std::string& dir)
{
  typedef Surface_mesh::Vertex_index V;
  std::size_t runs = 0, converged = 0, moved = 0, moved_converged = 0;
  smdf_test::for_each_shared_mesh<Surface_mesh>(dir, false, [&](const smdf_test::Manifest_entry& e, const Surface_mesh& input) {
    if(e.F > 40000 || e.genus == "0") return;
    Surface_mesh mesh = input;
    auto placed = mesh.add_property_map<Surface_mesh::Edge_index, double>("e:placed", 0.).first;
    const auto cs = SMDF::place_remeshing_cones(mesh, placed);
    if(cs.cones.size() > 120) return;   // the cheese: 1,208 cones
    auto cone_target = mesh.add_property_map<V, double>("v:target", 0.).first;
    std::vector<V> cone_vertices;
    for(const auto& c : cs.cones) { cone_target[c.first] = c.second; cone_vertices.push_back(c.first); }
    auto cl = mesh.add_property_map<Surface_mesh::Edge_index, double>("e:cone", 0.).first;
    if(!SMDF::compute_cone_metric(mesh, cone_target, cl, SMDF::parameters::intrinsic_edge_flips(false)).converged) return;
    auto sl = mesh.add_property_map<Surface_mesh::Edge_index, double>("e:seamless", 0.).first;
    const SMDF::Seamless_metric_status st = SMDF::seamless_cone_metric(mesh, cl, sl);
    ++runs;
    const std::string what = e.file + " (genus " + e.genus + ", " + std::to_string(cs.cones.size()) + " cones)";
    std::cout << what << ": seamless metric " << (st.success ? "converged" : st.message) << ", " << st.loops << " loops, holonomy off by "
              << st.initial_holonomy_error << " -> " << st.holonomy_error << ", " << st.iterations << " steps, log length change "
              << st.max_log_length_change << std::endl;
    SMDF_CHECK_MSG(st.loops == 2 * std::size_t(std::stoi(e.genus)), what << ": one loop per generator, " << st.loops);
    if(!st.success) {
      bool same = true;
      for(auto ed : edges(mesh)) same = same && sl[ed] == cl[ed];
      SMDF_CHECK_MSG(same && !st.message.empty(), what << ": a failed seamless metric leaves the input metric and says why");
      // the cones moved toward it (move_cones_toward_seamless()), their metric computed again: its
      // holonomies are as predicted to first order, nearer their goals, and then seamless
      std::vector<std::pair<V, double>> moved(cs.cones.begin(), cs.cones.end());
      const SMDF::Cone_moves_status ms = SMDF::move_cones_toward_seamless(mesh, cl, moved);
      double total = 0, moved_total = 0;
      for(const auto& c : cs.cones) total += c.second;
      bool apart = true;
      for(const auto& c : moved) {
        moved_total += c.second;
        for(auto w : CGAL::vertices_around_target(c.first, mesh))
          for(const auto& d : moved) apart = apart && d.first != w;
      }
      SMDF_CHECK_MSG(ms.moves > 0 && ms.loops == st.loops && std::abs(total - moved_total) < 1e-12 && apart && moved.size() == cs.cones.size(),
                     what << ": " << ms.moves << " moves keep the cones, their total and no two adjacent");
      auto moved_target = mesh.add_property_map<V, double>("v:moved", 0.).first;
      for(const auto& c : moved) moved_target[c.first] = c.second;
      auto ml = mesh.add_property_map<Surface_mesh::Edge_index, double>("e:moved", 0.).first;
      if(!SMDF::compute_cone_metric(mesh, moved_target, ml, SMDF::parameters::edge_length_map(cl).intrinsic_edge_flips(false)).converged) return;
      auto msl = mesh.add_property_map<Surface_mesh::Edge_index, double>("e:moved_seamless", 0.).first;
      const SMDF::Seamless_metric_status mst = SMDF::seamless_cone_metric(mesh, ml, msl);
      std::cout << "  cones moved " << ms.moves << " times: holonomy off by " << ms.initial_holonomy_error << " -> predicted "
                << ms.predicted_holonomy_error << ", read back " << mst.initial_holonomy_error << "; seamless metric "
                << (mst.success ? "converged" : mst.message) << std::endl;
      SMDF_CHECK_MSG(mst.initial_holonomy_error < ms.initial_holonomy_error && std::abs(mst.initial_holonomy_error - ms.predicted_holonomy_error) < 0.1,
                     what << ": the moved cones' holonomy error " << mst.initial_holonomy_error << ", predicted " << ms.predicted_holonomy_error);
      if(!mst.success) return;
      ++moved_converged;
      std::vector<V> moved_vertices;
      for(const auto& c : moved) moved_vertices.push_back(c.first);
      const SMDF::Intrinsic_mesh<Surface_mesh> mim(mesh, SMDF::parameters::edge_length_map(msl));
      double worst_moved_k = 0;
      for(auto v : vertices(mesh)) worst_moved_k = std::max(worst_moved_k, std::abs(mim.vertex_curvature(v) - moved_target[v]));
      const auto mbasis = SMDF::homotopy_basis(mesh, moved_vertices);
      const auto mafter = SMDF::parallel_rosy_compatibility(SMDF::holonomy_group(mesh, mbasis, SMDF::parameters::edge_length_map(msl)), 4, 1e-8);
      SMDF_CHECK_MSG(worst_moved_k < 1e-9 && mafter.compatible, what << ", cones moved: curvatures off by " << worst_moved_k
                                                                      << ", holonomy-group test off by " << mafter.max_deviation);
      return;
    }
    ++converged;
    moved += st.initial_holonomy_error > 1e-6;
    const SMDF::Intrinsic_mesh<Surface_mesh> im(mesh, SMDF::parameters::edge_length_map(sl));
    double worst_k = 0, change = 0;
    for(auto v : vertices(mesh)) worst_k = std::max(worst_k, std::abs(im.vertex_curvature(v) - cone_target[v]));
    for(auto ed : edges(mesh)) change = std::max(change, std::abs(std::log(sl[ed] / cl[ed])));
    SMDF_CHECK_MSG(worst_k < 1e-9 && std::abs(change - st.max_log_length_change) < 1e-12,
                   what << ": the seamless metric's curvatures are the cones' within " << worst_k);
    const auto basis = SMDF::homotopy_basis(mesh, cone_vertices);
    const auto after = SMDF::parallel_rosy_compatibility(SMDF::holonomy_group(mesh, basis, SMDF::parameters::edge_length_map(sl)), 4, 1e-8);
    const auto before = SMDF::parallel_rosy_compatibility(SMDF::holonomy_group(mesh, basis, SMDF::parameters::edge_length_map(cl)), 4, 1e-8);
    SMDF_CHECK_MSG(after.compatible && (before.compatible == (st.initial_holonomy_error < 1e-8)),
                   what << ": the holonomy-group test (N = 4) passes on the seamless metric (off by " << after.max_deviation
                        << "), the input metric's was off by " << before.max_deviation);
  });
  std::cout << "seamless metrics: " << converged << " of " << runs << " converged, " << moved << " of them moved; " << moved_converged
            << " more once their cones moved" << std::endl;
  // measured: bob and the triple torus move (0.27 and 0.03 rad); the tori and the knot have no cone
  const bool reduced = std::getenv("SMDF_TEST_MAX_FACES") != nullptr;
  SMDF_CHECK(moved >= (reduced ? 0u : 2u) && moved_converged >= (reduced ? 0u : 3u));

  // Open meshes with handles or several boundary loops: also a path from the first loop to each
  // other one, whose turning must be a multiple of pi/2. Read back from a development of the
  // seamless metric: every border edge's direction there is the same modulo pi/2 (the field
  // along one boundary runs along all of them), and the curvatures are the placed ones.
  std::size_t open_runs = 0, open_converged = 0;
  smdf_test::for_each_shared_mesh<Surface_mesh>(dir, true, [&](const smdf_test::Manifest_entry& e, const Surface_mesh& input) {
    if(e.F > 40000 || (e.genus == "0" && e.boundary_loops < 2)) return;
    Surface_mesh mesh = input;
    auto placed = mesh.add_property_map<Surface_mesh::Edge_index, double>("e:placed", 0.).first;
    // as smdf's first attempt at 4,000 quads: the cones 4 quad sides apart
    const double h = std::sqrt(CGAL::Polygon_mesh_processing::area(mesh) / 4000);
    const auto cs = SMDF::place_remeshing_cones(mesh, placed, SMDF::parameters::minimum_cone_distance(4 * h));
    auto cone_target = mesh.add_property_map<V, double>("v:target", 0.).first;
    for(const auto& c : cs.cones) cone_target[c.first] = c.second;
    auto cl = mesh.add_property_map<Surface_mesh::Edge_index, double>("e:cone", 0.).first;
    if(!SMDF::compute_cone_metric(mesh, cone_target, cl, SMDF::parameters::intrinsic_edge_flips(false)).converged) return;
    auto sl = mesh.add_property_map<Surface_mesh::Edge_index, double>("e:seamless", 0.).first;
    const SMDF::Seamless_metric_status st = SMDF::seamless_cone_metric(mesh, cl, sl);
    ++open_runs;
    const std::string what = e.file + " (genus " + e.genus + ", " + std::to_string(e.boundary_loops) + " boundary loops, " +
                             std::to_string(cs.cones.size()) + " cones and corners)";
    auto border_spread = [&](Surface_mesh::Property_map<Surface_mesh::Edge_index, double> l) { return border_direction_spread(mesh, l); };
    std::cout << what << ": seamless metric " << (st.success ? "converged" : st.message) << ", " << st.loops << " loops and paths, off by "
              << st.initial_holonomy_error << " -> " << st.holonomy_error << ", border directions spread modulo pi/2 " << border_spread(cl);
    const std::size_t expected_loops = 2 * std::size_t(std::stoi(e.genus)) + std::size_t(e.boundary_loops) - 1;
    SMDF_CHECK_MSG(st.loops == expected_loops, what << ": one loop per handle generator and one path per further boundary loop, " << st.loops);
    if(!st.success) {
      std::cout << std::endl;
      bool same = true;
      for(auto ed : edges(mesh)) same = same && sl[ed] == cl[ed];
      SMDF_CHECK_MSG(same && !st.message.empty(), what << ": a failed seamless metric leaves the input metric and says why");
      return;
    }
    ++open_converged;
    const double after = border_spread(sl);
    std::cout << " -> " << after << std::endl;
    const SMDF::Intrinsic_mesh<Surface_mesh> im(mesh, SMDF::parameters::edge_length_map(sl));
    double worst_k = 0;
    for(auto v : vertices(mesh)) worst_k = std::max(worst_k, std::abs(im.vertex_curvature(v) - cone_target[v]));
    SMDF_CHECK_MSG(worst_k < 1e-9 && after < 1e-7, what << ": curvatures off the placed ones by " << worst_k << ", border directions by " << after);
  });
  std::cout << "open seamless metrics: " << open_converged << " of " << open_runs << " converged" << std::endl;
  // measured: the annulus converges (0.014 rad); the others need flips (0.3-0.8 rad)
  SMDF_CHECK(open_runs >= (reduced ? 0u : 3u) && open_converged >= (reduced ? 0u : 1u));
}

// The seamless metric with flips of `mesh`'s placed cones, for a comparison of mesh types.
template <typename Mesh>
SMDF::Seamless_intrinsic_metric_status seamless_with_flips_of(const Mesh& mesh)
{
  const auto target = placed_cone_curvatures(mesh).second;
  auto lengths = get(CGAL::dynamic_edge_property_t<double>(), mesh);
  auto u = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
  const SMDF::Cone_metric_status cm = SMDF::compute_cone_metric(mesh, target, lengths, SMDF::parameters::conformal_factor_map(u).common_subdivision(false));
  SMDF_CHECK(cm.converged);
  return SMDF::seamless_intrinsic_cone_metric(mesh, u, SMDF::parameters::intrinsic_edge_flips(cm.triangulation_changed));
}

// Seamless metrics with intrinsic flips (seamless_intrinsic_cone_metric()) of the shared meshes
// of at most 40k faces with a handle or several boundary loops, from the flat cone metric of their
// placed cones (with flips where it needs them), including those whose holonomies start too far
// for the fixed triangulation. Read back on a copy of the resulting triangulation: every vertex's
// curvature is the placed one (cones, boundary corners, 0 elsewhere); on closed meshes the
// holonomy-group test (Theorem 3.2, N = 4) passes on a homotopy basis around the cones and the
// handles, on open ones every border edge has the same direction modulo pi/2 in a development; and
// the common subdivision with the input tiles both (its pieces' areas sum to each input face's and
// each intrinsic face's area).
void seamless_intrinsic_metrics(const std::string& dir)
{
  typedef Surface_mesh::Vertex_index V;
  typedef Surface_mesh::Edge_index E;
  std::size_t runs = 0, converged = 0, beyond_reach = 0, flipped = 0, open_runs = 0, open_converged = 0;
  auto check = [&](const smdf_test::Manifest_entry& e, const Surface_mesh& input) {
    const bool open = e.boundary_loops > 0;
    if(e.F > 40000 || (e.genus == "0" && e.boundary_loops < 2)) return;
    Surface_mesh mesh = input;
    auto placed = mesh.add_property_map<E, double>("e:placed", 0.).first;
    // open: as smdf's first attempt at 4,000 quads, the cones 4 quad sides apart
    const double h = std::sqrt(CGAL::Polygon_mesh_processing::area(mesh) / 4000);
    const auto cs = open ? SMDF::place_remeshing_cones(mesh, placed, SMDF::parameters::minimum_cone_distance(4 * h))
                         : SMDF::place_remeshing_cones(mesh, placed);
    if(cs.cones.size() > 120) return;   // the cheese
    auto cone_target = mesh.add_property_map<V, double>("v:target", 0.).first;
    std::vector<V> cone_vertices;
    for(const auto& c : cs.cones) { cone_target[c.first] = c.second; cone_vertices.push_back(c.first); }
    auto cl = mesh.add_property_map<E, double>("e:cone", 0.).first;
    auto u = mesh.add_property_map<V, double>("v:u", 0.).first;
    const SMDF::Cone_metric_status cm = SMDF::compute_cone_metric(mesh, cone_target, cl, SMDF::parameters::conformal_factor_map(u).common_subdivision(false));
    if(!cm.converged) return;
    SMDF::Seamless_intrinsic_metric_status st =
        SMDF::seamless_intrinsic_cone_metric(mesh, u, SMDF::parameters::intrinsic_edge_flips(cm.triangulation_changed));
    ++runs;
    open_runs += open;
    const std::string what = e.file + " (genus " + e.genus + ", " + std::to_string(e.boundary_loops) + " boundary loops, " +
                             std::to_string(cs.cones.size()) + " cones and corners)";
    std::cout << what << ": seamless metric with flips " << (st.success ? "converged" : st.message) << ", " << st.loops
              << " loops and paths, holonomy off by " << st.initial_holonomy_error << " -> " << st.holonomy_error << ", " << st.iterations
              << " steps, " << st.cone_metric_flips << " + " << st.edge_flips << " flips, smallest angle " << st.min_angle
              << (st.correspondence_message.empty() ? std::string() : ", " + st.correspondence_message) << std::endl;
    const std::size_t expected_loops = 2 * std::size_t(std::stoi(e.genus)) + (open ? std::size_t(e.boundary_loops) - 1 : 0);
    SMDF_CHECK_MSG(st.loops == expected_loops, what << ": one loop per handle generator and one path per further boundary loop, " << st.loops);
    if(!st.success) {
      SMDF_CHECK_MSG(!st.message.empty(), what << ": a failure says why");
      return;
    }
    ++converged;
    open_converged += open;
    beyond_reach += st.initial_holonomy_error > 0.3;
    flipped += st.edge_flips > 0;
    SMDF_CHECK_MSG(st.intrinsic_triangulation.has_common_subdivision(), what << ": the correspondence: " << st.correspondence_message);
    Surface_mesh out;
    auto ol = out.add_property_map<E, double>("e:length", 0.).first;
    SMDF::copy_intrinsic_triangulation(st.intrinsic_triangulation, mesh, out, ol);
    const SMDF::Intrinsic_mesh<Surface_mesh> im(out, SMDF::parameters::edge_length_map(ol));
    double worst_k = 0;
    for(auto v : vertices(out)) worst_k = std::max(worst_k, std::abs(im.vertex_curvature(v) - cone_target[V(v.idx())]));
    if(open) {
      const double spread = border_direction_spread(out, ol);
      SMDF_CHECK_MSG(worst_k < 1e-9 && spread < 1e-7, what << ": curvatures off by " << worst_k << ", border directions by " << spread);
    } else {
      const auto basis = SMDF::homotopy_basis(out, cone_vertices);
      const auto after = SMDF::parallel_rosy_compatibility(SMDF::holonomy_group(out, basis, SMDF::parameters::edge_length_map(ol)), 4, 1e-8);
      SMDF_CHECK_MSG(worst_k < 1e-9 && after.compatible, what << ": curvatures off by " << worst_k << ", holonomy-group test off by " << after.max_deviation);
    }
    if(!st.intrinsic_triangulation.has_common_subdivision()) return;
    // the pieces tile both triangulations
    std::vector<double> in_area(num_faces(mesh), 0.), it_area(num_faces(out), 0.);
    for(const auto& p : st.intrinsic_triangulation.common_subdivision()) {
      in_area[std::size_t(p.input_face)] += p.input_area;
      it_area[std::size_t(p.intrinsic_face)] += p.intrinsic_area;
    }
    double worst_in = 0, worst_it = 0;
    for(auto f : faces(mesh)) worst_in = std::max(worst_in, std::abs(in_area[f.idx()] / CGAL::Polygon_mesh_processing::face_area(f, mesh) - 1));
    for(auto f : faces(out)) {
      const auto hf = halfedge(f, out);
      const double a = ol[edge(hf, out)], b = ol[edge(next(hf, out), out)], c = ol[edge(prev(hf, out), out)];
      const double s = 0.5 * (a + b + c);
      worst_it = std::max(worst_it, std::abs(it_area[f.idx()] / std::sqrt(s * (s - a) * (s - b) * (s - c)) - 1));
    }
    SMDF_CHECK_MSG(worst_in < 1e-8 && worst_it < 1e-8, what << ": the common subdivision's pieces cover the input faces within " << worst_in
                                                            << " and the intrinsic faces within " << worst_it << " of their areas");
  };
  smdf_test::for_each_shared_mesh<Surface_mesh>(dir, false, check);
  smdf_test::for_each_shared_mesh<Surface_mesh>(dir, true, check);
  // Polyhedron_3: the same metric as on the Surface_mesh (the double torus, 0.64 rad off)
  Polyhedron p;
  Surface_mesh sm;
  SMDF::read_triangle_mesh(dir + "/meshes/double-torus_jnd.off", p);
  SMDF::read_triangle_mesh(dir + "/meshes/double-torus_jnd.off", sm);
  const SMDF::Seamless_intrinsic_metric_status ps = seamless_with_flips_of(p), ss = seamless_with_flips_of(sm);
  SMDF_CHECK_MSG(ps.success && ss.success && ps.iterations == ss.iterations && ps.edge_flips == ss.edge_flips &&
                     ps.intrinsic_triangulation.has_common_subdivision() && ps.intrinsic_triangulation.number_of_edges() == num_edges(sm),
                 "double torus: Polyhedron_3 " << ps.iterations << " steps, " << ps.edge_flips << " flips; Surface_mesh " << ss.iterations
                                               << ", " << ss.edge_flips);
  std::cout << "seamless metrics with flips: " << converged << " of " << runs << " converged (" << open_runs << " open), " << beyond_reach
            << " beyond the fixed triangulation's reach, " << flipped << " with flips" << std::endl;
  // measured: the 11 closed ones converge, 6 of them from 0.31-0.78 rad off; of the 5 open ones
  // the alex (0.36 rad), the annulus and the punctured torus; the beetle and the holes stall
  // (Newton's progress; triangles at the boundary, whose edges cannot flip, at the smallest angle)
  const bool reduced = std::getenv("SMDF_TEST_MAX_FACES") != nullptr;
  SMDF_CHECK(runs >= (reduced ? 1u : 16u) && converged - open_converged == runs - open_runs && open_converged >= (reduced ? 0u : 3u) &&
             beyond_reach >= (reduced ? 0u : 5u));
}

int main(int argc, char** argv)
{
  const std::string part = argc > 1 ? argv[1] : "all";
  if(part == "seamless") {   // the seamless metrics alone
    const std::string dir = smdf_test::shared_data_dir();
    if(!dir.empty()) { seamless_metrics(dir); seamless_intrinsic_metrics(dir); }
    return smdf_test::finish();
  }
  if(part == "maps") {   // the integer-grid maps alone
    staircase_t_mesh();
    const std::string dir = smdf_test::shared_data_dir();
    if(!dir.empty()) { integer_grid_maps(dir); integer_grid_maps_open(dir); }
    return smdf_test::finish();
  }
  if(part != "all" && part != "automatic" && part != "polycube" && part != "untangling") {
    std::cerr << "usage: test_remeshing [automatic|polycube|untangling|seamless|maps]" << std::endl;
    return 2;
  }
  const std::string dir = smdf_test::shared_data_dir();
  auto runs = [&](const char* p) { return part == "all" || part == p; };
  if(runs("polycube")) {
    cube();
    octahedron();
    flat_torus();
    open_square();
    box_corner_order();
    l_shaped_polycube();
    folded_quads();
    face_bent_around_thin_part();
    winding_faults_core();
    if(!dir.empty()) { box_polycube(dir); ricci_flow_segments(dir); seam_relaxation(dir); flipped_flat_metric(dir); octahedron_polyhedron(dir); obelisk(dir); }
  }
  if(runs("untangling") && !dir.empty()) { delaunay_refinement(dir); untangling(dir); }
  if(runs("automatic")) { seam_lattice_core(); staircase_t_mesh(); cube_through_intrinsic_triangulation(); }
  if(runs("automatic") && !dir.empty()) { remeshing_cones(dir); cone_separation(dir); integer_grid_maps(dir); integer_grid_maps_open(dir); seamless_metrics(dir); seamless_intrinsic_metrics(dir); }
  if(dir.empty()) std::cout << "../shared/data not found: the shared meshes' parts skipped" << std::endl;
  return smdf_test::finish();
}
