// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Topology of a triangle mesh and a basis of its first homology group by the tree-cotree
// decomposition: the number of generators of each connected component is its first Betti
// number, 2g for a closed component and 2g + b - 1 with b >= 1 boundary loops.
//
// Usage: homology_generators_example [mesh.off]   (default: data/torus.off)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_mesh_direction_fields/Euclidean_edge_length_map.h>
#include <CGAL/Surface_mesh_direction_fields/homology_generators.h>
#include <CGAL/Surface_mesh_direction_fields/IO/read_triangle_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/topology.h>

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace SMDF = CGAL::Surface_mesh_direction_fields;

int main(int argc, char* argv[])
{
  const std::string filename = argc > 1 ? argv[1] : SMDF_DATA_DIR "/torus.off";
  try {
    Mesh tm;
    SMDF::read_triangle_mesh(filename, tm);   // validates the mesh, throws SMDF::Input_error

    //! [topology]
    const SMDF::Mesh_topology<Mesh> topology = SMDF::mesh_topology(tm);
    for(std::size_t c = 0; c < topology.components.size(); ++c) {
      const SMDF::Component_topology& t = topology.components[c];
      std::cout << "component " << c << ": V " << t.vertices << ", E " << t.edges << ", F "
                << t.faces << ", chi " << t.euler_characteristic << ", genus " << t.genus
                << ", boundary loops " << t.boundary_loops << ", b1 " << t.betti_1 << "\n";
    }
    //! [topology]

    //! [generators]
    const std::vector<SMDF::Homology_generator<Mesh>> generators =
      SMDF::tree_cotree_generators(tm);

    // Lengths of the primal loops in the metric given by the named parameters (here the
    // Euclidean lengths of an explicitly passed vertex point map).
    const auto length = SMDF::get_edge_length_map(
      tm, SMDF::parameters::vertex_point_map(get(CGAL::vertex_point, tm)));

    std::vector<long> count(topology.components.size(), 0);
    for(std::size_t i = 0; i < generators.size(); ++i) {
      const SMDF::Homology_generator<Mesh>& g = generators[i];
      double loop_length = 0;
      for(Mesh::Halfedge_index h : g.primal_loop) loop_length += get(length, edge(h, tm));
      std::cout << "generator " << i << " ("
                << (g.kind == SMDF::HANDLE_GENERATOR ? "handle" : "boundary")
                << ", component " << g.component << "): dual cycle of " << g.dual_cycle.size()
                << " faces, primal loop of " << g.primal_loop.size() << " edges, length "
                << loop_length << "\n";
      ++count[g.component];
    }
    //! [generators]

    bool ok = true;
    for(std::size_t c = 0; c < count.size(); ++c)
      if(count[c] != topology.components[c].betti_1) {
        std::cerr << "error: component " << c << " has " << count[c]
                  << " generators but its first Betti number is "
                  << topology.components[c].betti_1 << "\n";
        ok = false;
      }
    std::cout << generators.size() << " generators, first Betti number " << topology.betti_1()
              << "\n";
    if(!ok) return EXIT_FAILURE;
  } catch(const SMDF::Input_error& e) {   // unreadable file or invalid mesh
    std::cerr << "error (" << SMDF::Input_error::kind_name(e.kind()) << "): " << e.what() << "\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
