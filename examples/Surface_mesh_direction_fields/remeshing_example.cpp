// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Regular quad remeshing (Lai et al. 2010, section 5) of a genus-0 mesh through the box
// polycube metric: eight cones of pi/2 at the vertices extreme in the diagonal directions, the
// box's edges as shortest paths under their flat cone metric, the box metric, its development
// and the square grid carried onto the surface. Then the same cones on the mesh's conforming
// Delaunay refinement, where a flat cone metric the input triangulation cannot carry usually
// exists without intrinsic flips; and a triangle remesh through the octahedron (six cones of
// 2 pi/3), whose inverted triangles, if any, are unfolded along the surface. Every result is read
// back (valences, inverted faces, convergence).
//
// Usage: remeshing_example [mesh.off] [quads]   (default: data/spot.off, about 2000 quads)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <CGAL/Surface_mesh_direction_fields/cone_metric.h>
#include <CGAL/Surface_mesh_direction_fields/delaunay_refinement.h>
#include <CGAL/Surface_mesh_direction_fields/flat_development.h>
#include <CGAL/Surface_mesh_direction_fields/grid_tessellation.h>
#include <CGAL/Surface_mesh_direction_fields/polycube_metric.h>
#include <CGAL/Surface_mesh_direction_fields/remesh_untangling.h>
#include <CGAL/Surface_mesh_direction_fields/IO/read_triangle_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;
typedef Mesh::Edge_index Edge;
namespace SMDF = CGAL::Surface_mesh_direction_fields;

int main(int argc, char* argv[])
{
  const std::string filename = argc > 1 ? argv[1] : SMDF_DATA_DIR "/spot.off";
  const double quads = argc > 2 ? std::atof(argv[2]) : 2000;
  try {
    Mesh mesh;
    SMDF::read_triangle_mesh(filename, mesh);

    // the box's corners: the vertices extreme in the eight diagonal directions from the centroid
    K::Vector_3 c(0, 0, 0);
    for(Vertex v : vertices(mesh)) c = c + (mesh.point(v) - CGAL::ORIGIN) / double(num_vertices(mesh));
    std::array<Vertex, 8> corners;
    for(int i = 0; i < 8; ++i) {
      const K::Vector_3 d((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1);
      double best = -HUGE_VAL;
      for(Vertex v : vertices(mesh))
        if((mesh.point(v) - CGAL::ORIGIN - c) * d > best) { best = (mesh.point(v) - CGAL::ORIGIN - c) * d; corners[i] = v; }
    }

    //! [box_remesh]
    // 1. the conformal factors of the flat cone metric with the box's cones (for the paths)
    auto target = mesh.add_property_map<Vertex, double>("v:target", 0.).first;
    for(Vertex v : corners) target[v] = CGAL_PI / 2;
    auto flat = mesh.add_property_map<Edge, double>("e:flat", 0.).first;
    auto u = mesh.add_property_map<Vertex, double>("v:u", 0.).first;
    SMDF::compute_cone_metric(mesh, target, flat, SMDF::parameters::conformal_factor_map(u).curvature_tolerance(1e-6));

    // 2. the box metric: edge lengths whose development tiles with squares of side h
    const double h = std::sqrt(CGAL::Polygon_mesh_processing::area(mesh) / quads);
    auto box = mesh.add_property_map<Edge, double>("e:box", 0.).first;
    const SMDF::Polycube_metric_status ps =
      SMDF::box_polycube_metric(mesh, corners, h, box, SMDF::parameters::conformal_factor_map(u));
    if(!ps.success) { std::cerr << "box metric: " << ps.message << "\n"; return EXIT_FAILURE; }

    // 3. develop it and carry the square grid onto the surface
    const auto dev = SMDF::develop_flat_metric(mesh, SMDF::parameters::edge_length_map(box));
    Mesh remesh;
    const SMDF::Grid_tessellation_status st = SMDF::tessellate_flat_metric(mesh, dev, SMDF::SQUARE_GRID, h, remesh);
    std::cout << "box " << ps.dimensions[0] << " x " << ps.dimensions[1] << " x " << ps.dimensions[2] << ": " << st.faces
              << " quads, " << st.irregular_vertices.size() << " irregular vertices (the cones), " << st.inverted_faces
              << " inverted; read-back " << (st.success ? "ok" : st.message) << "\n";
    //! [box_remesh]
    if(!st.success) return EXIT_FAILURE;
    //! [octahedron_remesh]
    // Triangles: the octahedron on the six vertices extreme along the axes (cones of 2 pi/3),
    // its faces equilateral triangles of a side that is a multiple of h, unrelaxed (the plain
    // Tutte embedding of every face), then the triangular grid.
    std::vector<Vertex> axis(6);
    for(int k = 0; k < 6; ++k) {
      K::Vector_3 d(0, 0, 0);
      d = (k / 2 == 0 ? K::Vector_3(1, 0, 0) : k / 2 == 1 ? K::Vector_3(0, 1, 0) : K::Vector_3(0, 0, 1)) * (k % 2 ? -1. : 1.);
      double best = -HUGE_VAL;
      for(Vertex v : vertices(mesh))
        if((mesh.point(v) - CGAL::ORIGIN - c) * d > best) { best = (mesh.point(v) - CGAL::ORIGIN - c) * d; axis[std::size_t(k)] = v; }
    }
    std::vector<std::vector<int>> octahedron;   // counterclockwise seen from outside
    for(int sx : {1, -1})
      for(int sy : {1, -1})
        for(int sz : {1, -1}) {
          const int X = sx > 0 ? 0 : 1, Y = sy > 0 ? 2 : 3, Z = sz > 0 ? 4 : 5;
          octahedron.push_back(sx * sy * sz > 0 ? std::vector<int>{X, Y, Z} : std::vector<int>{X, Z, Y});
        }
    for(Vertex v : vertices(mesh)) target[v] = 0;
    for(Vertex v : axis) target[v] = 2 * CGAL_PI / 3;
    SMDF::compute_cone_metric(mesh, target, flat, SMDF::parameters::conformal_factor_map(u).curvature_tolerance(1e-6));
    // the octahedron's side for the surface's area, cut into k segments: 8 k^2 triangles, about
    // 1.5 times the number of quads
    const double side = std::sqrt(CGAL::Polygon_mesh_processing::area(mesh) / (2 * std::sqrt(3.)));
    const double k = std::max(1., std::round(std::sqrt(1.5 * quads / 8))), ht = side / k;
    auto octa = mesh.add_property_map<Edge, double>("e:octahedron", 0.).first;
    const SMDF::Polycube_metric_status os = SMDF::polyhedron_metric(
      mesh, axis, octahedron, side, octa, SMDF::parameters::conformal_factor_map(u).number_of_iterations(0));
    if(!os.success) { std::cerr << "octahedron metric: " << os.message << "\n"; return EXIT_FAILURE; }
    const auto odev = SMDF::develop_flat_metric(mesh, SMDF::parameters::edge_length_map(octa));
    Mesh triangles;
    const SMDF::Grid_tessellation_status ts = SMDF::tessellate_flat_metric(mesh, odev, SMDF::TRIANGULAR_GRID, ht, triangles);
    std::cout << "octahedron of side " << side << ": " << ts.faces << " triangles, " << ts.irregular_vertices.size()
              << " irregular vertices (the cones, valence 4), " << ts.inverted_faces << " inverted; read-back "
              << (ts.success ? "ok" : ts.message) << "\n";
    bool valid = ts.success;
    if(!ts.success && ts.inverted_faces > 0) {
      // every other check passed (inverted faces are counted last): move the vertices near them
      // along the surface, the cones held; faces and valences stay the grid's
      auto held = triangles.add_property_map<Vertex, bool>("v:held", false).first;
      for(const auto& iv : ts.irregular_vertices) held[Vertex(Mesh::size_type(iv.first))] = true;
      const SMDF::Untangle_status us = SMDF::untangle_remesh(mesh, triangles, SMDF::parameters::vertex_is_constrained_map(held));
      std::cout << "untangled: " << us.inverted_before << " inverted triangles, " << us.moved_vertices << " vertices moved; "
                << (us.success ? "none inverted now" : us.message) << "\n";
      valid = us.success;
    }
    //! [octahedron_remesh]
    if(!valid) return EXIT_FAILURE;

    //! [refinement]
    // The same cones without flips on the conforming Delaunay refinement: vertices added on the
    // input's edges only, the input's vertices first with their indices, every edge Delaunay.
    Mesh refined;
    const SMDF::Delaunay_refinement_status rs = SMDF::conforming_delaunay_refinement(mesh, refined);
    if(!rs.success) { std::cerr << "refinement: " << rs.message << "\n"; return EXIT_FAILURE; }
    auto rtarget = refined.add_property_map<Vertex, double>("v:target", 0.).first;
    for(Vertex v : corners) rtarget[v] = CGAL_PI / 2;
    auto rflat = refined.add_property_map<Edge, double>("e:flat", 0.).first;
    const SMDF::Cone_metric_status cm =
      SMDF::compute_cone_metric(refined, rtarget, rflat, SMDF::parameters::intrinsic_edge_flips(false));
    std::cout << "Delaunay refinement: " << num_faces(mesh) << " -> " << rs.faces << " faces; flat cone metric on it "
              << (cm.converged ? "converged" : "not converged") << " in " << cm.iterations << " iterations, no flips\n";
    //! [refinement]
    return cm.converged ? EXIT_SUCCESS : EXIT_FAILURE;
  } catch(const std::exception& e) {
    std::cerr << filename << ": " << e.what() << "\n";
    return EXIT_FAILURE;
  }
}
