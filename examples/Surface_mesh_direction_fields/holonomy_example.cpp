// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Levi-Civita holonomy and generalised holonomy (a rigid motion of the plane) of the homology
// generators of a triangle mesh, and a check of the discrete identity "holonomy around the
// dual cell of an interior vertex = angle defect (mod 2*pi)".
//
// Usage: holonomy_example [mesh.off]   (default: data/torus.off)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_mesh_direction_fields/holonomy.h>
#include <CGAL/Surface_mesh_direction_fields/homology_generators.h>
#include <CGAL/Surface_mesh_direction_fields/intrinsic_geometry.h>
#include <CGAL/Surface_mesh_direction_fields/IO/read_triangle_mesh.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace SMDF = CGAL::Surface_mesh_direction_fields;

// Distance between two angles on the circle.
double angle_distance(double a, double b) { return std::abs(std::remainder(a - b, 2 * CGAL_PI)); }

int main(int argc, char* argv[])
{
  const std::string filename = argc > 1 ? argv[1] : SMDF_DATA_DIR "/torus.off";
  try {
    Mesh tm;
    SMDF::read_triangle_mesh(filename, tm);   // validates the mesh, throws SMDF::Input_error
    bool ok = true;

    //! [holonomy_of_generators]
    // Precompute the corner angles of the metric once; every query is then linear in the
    // length of its cycle.
    const SMDF::Intrinsic_holonomy<Mesh> holonomy(
      tm, SMDF::parameters::vertex_point_map(get(CGAL::vertex_point, tm)));

    for(const SMDF::Homology_generator<Mesh>& g : SMDF::tree_cotree_generators(tm)) {
      const double rotation = holonomy.levi_civita_holonomy(g.dual_cycle);
      const SMDF::Rigid_motion_2 motion = holonomy.generalized_holonomy(g.dual_cycle);
      std::cout << (g.kind == SMDF::HANDLE_GENERATOR ? "handle  " : "boundary")
                << " generator (" << g.dual_cycle.size() << " faces): rotation " << rotation
                << ", E(2) holonomy: rotation " << motion.rotation << ", translation ("
                << motion.translation.x() << ", " << motion.translation.y() << ")\n";
      // The rotational part of the development is the Levi-Civita holonomy.
      if(angle_distance(motion.rotation, rotation) > 1e-8) ok = false;
    }
    //! [holonomy_of_generators]

    //! [holonomy_around_vertices]
    double max_error = 0;
    std::size_t interior = 0;
    for(Mesh::Vertex_index v : vertices(tm)) {
      if(tm.is_isolated(v) || is_border(v, tm)) continue;
      const double around = holonomy.levi_civita_holonomy(holonomy.dual_cycle_around_vertex(v));
      max_error = (std::max)(max_error, angle_distance(around, SMDF::angle_defect(v, tm)));
      ++interior;
    }
    std::cout << interior << " interior vertices: max |holonomy - angle defect| (mod 2 pi) = "
              << max_error << "\n";
    //! [holonomy_around_vertices]
    if(max_error > 1e-8) ok = false;

    if(!ok) {
      std::cerr << "error: inconsistent holonomies\n";
      return EXIT_FAILURE;
    }
  } catch(const SMDF::Input_error& e) {   // unreadable file, invalid mesh or degenerate metric
    std::cerr << "error (" << SMDF::Input_error::kind_name(e.kind()) << "): " << e.what() << "\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
