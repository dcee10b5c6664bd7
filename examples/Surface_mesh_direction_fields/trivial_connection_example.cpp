// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Trivial connections (Crane, Desbrun, Schroeder 2010): a direction field with chosen
// singularities (Figure 1), generator turning numbers on a torus (Figure 6), a cross field
// (N = 4) with directional constraints, soft guide directions, and an index +20 singularity
// (Figure 20).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_mesh_direction_fields/IO/read_triangle_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/topology.h>
#include <CGAL/Surface_mesh_direction_fields/Trivial_connection.h>
#include <CGAL/Surface_mesh_direction_fields/field_singularities.h>

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace SMDF = CGAL::Surface_mesh_direction_fields;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;

int main(int argc, char** argv)
{
  const std::string file = argc > 1 ? argv[1] : std::string(SMDF_DATA_DIR) + "/torus.off";
  Mesh mesh;
  try { SMDF::read_triangle_mesh(file, mesh); }
  catch(const SMDF::Input_error& e) { std::cerr << e.what() << std::endl; return EXIT_FAILURE; }
  const auto topo = SMDF::mesh_topology(mesh);
  if(topo.components.size() != 1 || !topo.is_closed()) {
    std::cerr << "this example expects a closed connected mesh" << std::endl;
    return EXIT_FAILURE;
  }
  const long chi = topo.euler_characteristic();
  std::vector<Vertex> vs(mesh.vertices().begin(), mesh.vertices().end());

  // 1. Chosen singularities: index chi at one vertex plus a +1 / -1 pair (sum = chi).
  //! [chosen_singularities]
  SMDF::Trivial_connection<Mesh> tc(mesh);   // cotan weights, N = 1
  tc.set_singularity(vs[0], double(chi));
  tc.set_singularity(vs[vs.size() / 3], 1);
  tc.set_singularity(vs[2 * vs.size() / 3], -1);
  SMDF::Trivial_connection_status st = tc.solve();
  if(!st.success) { std::cerr << st.message << std::endl; return EXIT_FAILURE; }
  auto angle = get(CGAL::dynamic_face_property_t<double>(), mesh);
  tc.field_angles(angle);
  // the read-back reuses the connection's intrinsic mesh instead of building its own
  const auto found = SMDF::field_singularities(mesh, angle, SMDF::parameters::intrinsic_mesh(tc.intrinsic_mesh()));
  std::cout << "vector field: energy " << st.energy << ", holonomy error " << st.max_holonomy_error
            << ", singularities found:";
  for(const auto& s : found.singularities) std::cout << " v" << std::size_t(s.first) << ":" << s.second;
  std::cout << std::endl;
  //! [chosen_singularities]

  // 2. Turning numbers around the generators (Figure 6): only the right-hand side changes, so
  //    each solve reuses the factorisation.
  //! [generator_turning]
  for(int t = 0; t < 4 && !tc.generators().empty(); ++t) {
    tc.set_generator_turning_number(0, t);
    st = tc.solve();
    tc.field_angles(angle);
    std::cout << "turning number " << t << " around generator 0: read back "
              << SMDF::field_singularities(mesh, angle, SMDF::parameters::intrinsic_mesh(tc.intrinsic_mesh())).generator_turning_numbers[0]
              << " (solve " << st.solve_seconds << " s, no refactorisation: " << (st.factor_seconds == 0) << ")"
              << std::endl;
  }
  //! [generator_turning]

  // 3. A cross field (N = 4) with indices +-1/4 and two directional constraints.
  //! [cross_field]
  SMDF::Trivial_connection<Mesh> cross(mesh, SMDF::parameters::symmetry_order(4)
                                               .connection_weights(SMDF::COTAN_WEIGHTS));
  cross.set_singularity(vs[0], double(chi));
  cross.set_singularity(vs[vs.size() / 4], 0.25);
  cross.set_singularity(vs[vs.size() / 2], -0.25);
  std::vector<std::pair<Mesh::Face_index, double>> constraints = {
    {Mesh::Face_index(0), 0.0}, {Mesh::Face_index(mesh.number_of_faces() / 2), 0.5}};
  cross.set_directional_constraints(constraints);
  st = cross.solve();
  cross.field_angles(angle);
  std::cout << "cross field: residual " << st.residual << ", angle in face 0 = " << get(angle, Mesh::Face_index(0))
            << " (constrained to 0 mod pi/2), singularities found: "
            << SMDF::field_singularities(mesh, angle, SMDF::parameters::symmetry_order(4)).singularities.size()
            << std::endl;
  //! [cross_field]

  // 4. Soft alignment: pull the cross field towards guide directions in a few faces.
  std::vector<std::pair<Mesh::Face_index, double>> guides = {
    {Mesh::Face_index(10), 0.3}, {Mesh::Face_index(mesh.number_of_faces() / 3), 1.0},
    {Mesh::Face_index(2 * mesh.number_of_faces() / 3), 0.6}};
  cross.set_directional_constraints(std::vector<std::pair<Mesh::Face_index, double>>());
  cross.set_guide_directions(guides, 10.0);
  st = cross.solve();
  std::cout << "guided cross field: smoothness energy " << st.energy << ", guide energy " << st.guide_energy
            << std::endl;

  // 5. A singularity of index +20 (Figure 20), balanced by twenty of index -1: the connection
  //    turns by 40 pi around the vertex even on a coarse mesh.
  //! [index_20]
  SMDF::Trivial_connection<Mesh> big(mesh);
  big.set_singularity(vs[0], 20 + double(chi));
  for(std::size_t i = 1; i <= 20; ++i) big.set_singularity(vs[i * vs.size() / 21], -1);
  const SMDF::Trivial_connection_status sb = big.solve();
  std::cout << "index +20: holonomy error " << sb.max_holonomy_error << std::endl;
  //! [index_20]
  if(!sb.success) return EXIT_FAILURE;
  return st.success ? EXIT_SUCCESS : EXIT_FAILURE;
}
