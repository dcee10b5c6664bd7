// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Metric-driven N-RoSy field design (Lai et al. 2010) on a closed mesh: a flat cone metric with
// two cones, its holonomy group and the parallel-field test, the rotation-compensated cross field,
// an edit by a direction constraint, and hatching strokes along the result. Every field is read
// back with its matching: its singularities must be the cones.
//
// Usage: field_design_example [mesh.off [hatching.svg]]   (default: data/torus.off; the cones
// +pi/2 and -pi/2 assume a closed mesh of genus 1)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_mesh_direction_fields.h>
#include <CGAL/Surface_mesh_direction_fields/IO.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index Vertex;
typedef Mesh::Face_index Face;
typedef Mesh::Edge_index Edge;
namespace SMDF = CGAL::Surface_mesh_direction_fields;

// The singularities of a face field read back with its principal matching on the metric.
template <typename NP>
std::map<Vertex, double> read_back(const Mesh& tm, Mesh::Property_map<Face, double> angles, const NP& np)
{
  Mesh::Property_map<Edge, int> k = const_cast<Mesh&>(tm).add_property_map<Edge, int>("e:matching", 0).first;
  SMDF::principal_matching(tm, angles, k, np);
  const SMDF::Field_topology<Mesh> topo = SMDF::field_singularities(tm, angles, np.matching(k));
  const_cast<Mesh&>(tm).remove_property_map(k);
  return std::map<Vertex, double>(topo.singularities.begin(), topo.singularities.end());
}

int main(int argc, char* argv[])
{
  const std::string filename = argc > 1 ? argv[1] : SMDF_DATA_DIR "/torus.off";
  try {
    Mesh tm;
    SMDF::read_triangle_mesh(filename, tm);
    if(SMDF::mesh_topology(tm).euler_characteristic() != 0 || !SMDF::mesh_topology(tm).is_closed()) {
      std::cerr << "this example prescribes cones summing to 0: it needs a closed genus-1 mesh\n";
      return EXIT_FAILURE;
    }
    const int N = 4;
    const Vertex a(10), b(Mesh::size_type(num_vertices(tm) / 3));

    //! [metric]
    Mesh::Property_map<Vertex, double> target = tm.add_property_map<Vertex, double>("v:target", 0.).first;
    Mesh::Property_map<Edge, double> flat = tm.add_property_map<Edge, double>("e:flat", 0.).first;
    target[a] = CGAL_PI / 2;    // index +1/4
    target[b] = -CGAL_PI / 2;   // index -1/4
    const SMDF::Cone_metric_status cm =
        SMDF::compute_cone_metric(tm, target, flat, SMDF::parameters::intrinsic_edge_flips(false));
    if(!cm.converged) { std::cerr << "no flat cone metric: " << cm.message << "\n"; return EXIT_FAILURE; }
    //! [metric]

    //! [holonomy_group]
    const SMDF::Homotopy_basis<Mesh> basis = SMDF::homotopy_basis(tm, std::vector<Vertex>{a, b});
    const SMDF::Holonomy_group group = SMDF::holonomy_group(tm, basis, SMDF::parameters::edge_length_map(flat));
    const SMDF::Rosy_compatibility parallel = SMDF::parallel_rosy_compatibility(group, N);
    std::cout << basis.loops.size() << " basis loops; a parallel cross field "
              << (parallel.compatible ? "exists" : "does not exist") << " (" << parallel.failing_loops.size()
              << " loops fail)\n";
    //! [holonomy_group]

    //! [rotation_compensation]
    // one intrinsic mesh of the metric, shared by the compensation, the editor and the read-back
    const SMDF::Intrinsic_mesh<Mesh> im(tm, SMDF::parameters::edge_length_map(flat));
    Mesh::Property_map<Vertex, double> vertex_angle = tm.add_property_map<Vertex, double>("v:angle", 0.).first;
    Mesh::Property_map<Face, double> face_angle = tm.add_property_map<Face, double>("f:angle", 0.).first;
    const SMDF::Rotation_compensation_status rc =
        SMDF::rotation_compensated_field(tm, N, vertex_angle, face_angle, SMDF::parameters::intrinsic_mesh(im));
    const auto np = SMDF::parameters::symmetry_order(N).intrinsic_mesh(im);
    const std::map<Vertex, double> want = {{a, 0.25}, {b, -0.25}};
    bool ok = rc.success && read_back(tm, face_angle, np) == want;
    std::cout << "rotation compensation: " << rc.periods.size() << " handle loops, inconsistency "
              << rc.max_inconsistency << ", read back: " << (ok ? "the two cones" : "other singularities") << "\n";
    //! [rotation_compensation]

    //! [editing]
    // turn the field by 30 degrees at the vertex halfway between the cones (not a cone)
    SMDF::Rosy_vertex_field_editor<Mesh> editor(tm, N, vertex_angle, SMDF::parameters::intrinsic_mesh(im));
    const Vertex c(Mesh::size_type(num_vertices(tm) / 6));
    editor.set_direction_constraints(std::vector<std::pair<Vertex, double>>{{c, vertex_angle[c] + CGAL_PI / 6}});
    const SMDF::Field_edit_status es = editor.edit();
    editor.face_angles(face_angle);
    const bool edited_ok = es.success && es.max_direction_error < 1e-12 && read_back(tm, face_angle, np) == want;
    std::cout << "edit: constraint met to " << es.max_direction_error << ", read back: "
              << (edited_ok ? "the same two cones" : "other singularities") << "\n";
    ok = ok && edited_ok;
    //! [editing]

    //! [hatching]
    Mesh::Property_map<Face, K::Vector_3> vectors = tm.add_property_map<Face, K::Vector_3>("f:vector").first;
    SMDF::field_angles_to_vectors(tm, face_angle, vectors, SMDF::parameters::intrinsic_mesh(im));
    const std::vector<SMDF::Streamline<Mesh>> lines = SMDF::trace_streamlines(tm, vectors, N);
    std::cout << lines.size() << " hatching strokes\n";
    if(argc > 2) {
      std::ofstream out(argv[2]);
      SMDF::Svg_options view;
      view.edge_stroke_width = 0;
      view.face_color = "#f4f4f4";
      SMDF::write_streamlines_svg(out, tm, lines, view);
    }
    //! [hatching]
    return ok && !lines.empty() ? EXIT_SUCCESS : EXIT_FAILURE;
  } catch(const SMDF::Input_error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return EXIT_FAILURE;
  }
}
