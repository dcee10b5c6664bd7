// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Discrete curvature of a triangle mesh, first for the metric of its embedding and then for a
// modified intrinsic metric given as an edge-length map: the curvature changes from vertex to
// vertex, but its total stays 2*pi*chi (discrete Gauss-Bonnet).
//
// Usage: intrinsic_geometry_example [mesh.off]   (default: data/torus.off)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_mesh_direction_fields/intrinsic_geometry.h>
#include <CGAL/Surface_mesh_direction_fields/IO/read_triangle_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/topology.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index vertex_descriptor;
typedef Mesh::Edge_index edge_descriptor;
namespace SMDF = CGAL::Surface_mesh_direction_fields;

// Prints the range of the vertex curvatures and compares their sum with 2*pi*chi.
bool report(const char* title, const Mesh& tm, Mesh::Property_map<vertex_descriptor, double> k,
            double total, long chi)
{
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for(vertex_descriptor v : vertices(tm)) { lo = (std::min)(lo, k[v]); hi = (std::max)(hi, k[v]); }
  const double error = std::abs(total - 2 * CGAL_PI * double(chi));
  std::cout << title << ": curvature in [" << lo << ", " << hi << "], total " << total
            << ", 2*pi*chi " << 2 * CGAL_PI * double(chi) << ", |difference| " << error << "\n";
  return error < 1e-8 * (1. + double(num_vertices(tm)));
}

int main(int argc, char* argv[])
{
  const std::string filename = argc > 1 ? argv[1] : SMDF_DATA_DIR "/torus.off";
  try {
    //! [read]
    Mesh tm;
    SMDF::read_triangle_mesh(filename, tm);   // validates the mesh, throws SMDF::Input_error
    //! [read]
    const long chi = SMDF::mesh_topology(tm).euler_characteristic();
    std::cout << filename << ": " << num_vertices(tm) << " vertices, " << num_faces(tm)
              << " faces, Euler characteristic " << chi << "\n";

    Mesh::Property_map<vertex_descriptor, double> curvature =
      tm.add_property_map<vertex_descriptor, double>("v:curvature", 0.).first;

    //! [embedding_metric]
    // Default metric: Euclidean edge lengths of the vertex positions.
    double total = SMDF::compute_vertex_curvatures(tm, curvature,
                     SMDF::parameters::vertex_point_map(get(CGAL::vertex_point, tm)));
    //! [embedding_metric]
    bool ok = report("embedding metric", tm, curvature, total, chi);

    //! [scaled_metric]
    // Another metric on the same mesh: each edge pq is rescaled by exp((u_p + u_q) / 2) for a
    // smooth conformal factor u (a "vertex scaling"). No vertex moves; only lengths change.
    Mesh::Property_map<edge_descriptor, double> length =
      tm.add_property_map<edge_descriptor, double>("e:length", 0.).first;
    for(edge_descriptor e : edges(tm)) {
      const K::Point_3& p = tm.point(source(halfedge(e, tm), tm));
      const K::Point_3& q = tm.point(target(halfedge(e, tm), tm));
      const double u_p = 0.2 * std::sin(p.x()), u_q = 0.2 * std::sin(q.x());
      length[e] = std::exp(0.5 * (u_p + u_q)) * std::sqrt(CGAL::squared_distance(p, q));
    }
    total = SMDF::compute_vertex_curvatures(tm, curvature,
                                            SMDF::parameters::edge_length_map(length));
    //! [scaled_metric]
    ok = report("scaled metric   ", tm, curvature, total, chi) && ok;

    // Queries on single elements take the same named parameters.
    const edge_descriptor e0 = *edges(tm).begin();
    std::cout << "edge 0: cotangent weight " << SMDF::cotangent_weight(e0, tm) << " (embedding), "
              << SMDF::cotangent_weight(e0, tm, SMDF::parameters::edge_length_map(length))
              << " (scaled metric)\n";

    if(!ok) {
      std::cerr << "error: the total curvature differs from 2*pi*chi\n";
      return EXIT_FAILURE;
    }
  } catch(const SMDF::Input_error& e) {   // unreadable file, invalid mesh or degenerate metric
    std::cerr << "error (" << SMDF::Input_error::kind_name(e.kind()) << "): " << e.what() << "\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
