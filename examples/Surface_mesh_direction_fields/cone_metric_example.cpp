// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Flat cone metrics by discrete Ricci flow (conformal vertex scaling): a cone pair of index
// +1/4 and -1/4 that the input triangulation can carry, then a cone of index -3/2 balanced by two
// of +3/4, which needs intrinsic edge flips. Each result is checked by recomputing the curvature
// of the output metric, and the second is used through a copy of its intrinsic triangulation.
//
// Usage: cone_metric_example [mesh.off]   (default: data/torus.off; the targets assume genus 1)

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_mesh_direction_fields/cone_metric.h>
#include <CGAL/Surface_mesh_direction_fields/intrinsic_geometry.h>
#include <CGAL/Surface_mesh_direction_fields/Intrinsic_triangulation.h>
#include <CGAL/Surface_mesh_direction_fields/IO/read_triangle_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/topology.h>

#include <algorithm>
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

// Largest |K_v - target_v| of the metric `lengths` on `tm` (vertex i of tm <-> target[i]).
template <typename LengthMap>
double curvature_error(const Mesh& tm, LengthMap lengths, const std::vector<double>& target)
{
  Mesh::Property_map<Vertex, double> k = const_cast<Mesh&>(tm).add_property_map<Vertex, double>("v:k", 0.).first;
  SMDF::compute_vertex_curvatures(tm, k, SMDF::parameters::edge_length_map(lengths));
  double err = 0;
  for(Vertex v : vertices(tm)) err = (std::max)(err, std::abs(k[v] - target[v.idx()]));
  const_cast<Mesh&>(tm).remove_property_map(k);
  return err;
}

int main(int argc, char* argv[])
{
  const std::string filename = argc > 1 ? argv[1] : SMDF_DATA_DIR "/torus.off";
  try {
    Mesh tm;
    SMDF::read_triangle_mesh(filename, tm);
    if(SMDF::mesh_topology(tm).euler_characteristic() != 0 || num_vertices(tm) < 3) {
      std::cerr << "this example prescribes cones summing to 0: it needs a closed genus-1 mesh\n";
      return EXIT_FAILURE;
    }
    const Vertex a(0), b(Mesh::size_type(num_vertices(tm) / 2)), c(Mesh::size_type(num_vertices(tm) / 4));
    bool ok = true;

    //! [cone_metric]
    Mesh::Property_map<Vertex, double> target = tm.add_property_map<Vertex, double>("v:target", 0.).first;
    Mesh::Property_map<Edge, double> lengths = tm.add_property_map<Edge, double>("e:flat", 0.).first;
    Mesh::Property_map<Vertex, double> u = tm.add_property_map<Vertex, double>("v:u", 0.).first;

    // A cone pair of index +1/4 and -1/4 (curvature +-pi/2): the torus becomes flat elsewhere.
    target[a] = CGAL_PI / 2;
    target[b] = -CGAL_PI / 2;
    SMDF::Cone_metric_status st =
      SMDF::compute_cone_metric(tm, target, lengths, SMDF::parameters::conformal_factor_map(u));
    std::cout << "cones +-pi/2: converged " << st.converged << " in " << st.iterations
              << " iterations, max curvature error " << st.max_curvature_error
              << (st.triangulation_changed ? ", on an intrinsic triangulation\n" : ", on the input mesh\n");
    //! [cone_metric]
    std::vector<double> expected(num_vertices(tm));
    for(Vertex v : vertices(tm)) expected[v.idx()] = target[v];
    if(!st.converged) ok = false;
    else if(!st.triangulation_changed) {
      const double err = curvature_error(tm, lengths, expected);
      std::cout << "  recomputed curvature error " << err << "\n";
      ok = ok && err < 1e-9;
    }

    //! [intrinsic_flips]
    // A cone of -3pi (index -3/2) next to two of +3pi/2: vertex scaling on the input
    // triangulation would degenerate triangles, so the flow continues on an intrinsic Delaunay
    // triangulation.
    target[a] = -3 * CGAL_PI;
    target[b] = 1.5 * CGAL_PI;
    target[c] = 1.5 * CGAL_PI;
    st = SMDF::compute_cone_metric(tm, target, lengths);
    std::cout << "cones -3pi, 3pi/2, 3pi/2: converged " << st.converged << " in " << st.iterations
              << " iterations, " << st.edge_flips << " edge flips";
    if(st.triangulation_changed) {
      const SMDF::Intrinsic_triangulation& it = st.intrinsic_triangulation;
      std::cout << ", " << it.number_of_new_edges() << " of " << it.number_of_edges()
                << " edges are not input edges\n";
      // A mesh with the intrinsic connectivity and the flat lengths: every function of the
      // package takes it, e.g. the curvature check below, holonomy or trivial connections.
      Mesh flat;
      Mesh::Property_map<Edge, double> flat_lengths = flat.add_property_map<Edge, double>("e:length", 0.).first;
      SMDF::copy_intrinsic_triangulation(it, tm, flat, flat_lengths);
      // The correspondence with the input: the centroid of intrinsic face 0 on the input mesh
      // (an input face and barycentric coordinates), and back.
      SMDF::Surface_point p;
      p.face = 0;
      p.barycentric = {{1. / 3, 1. / 3, 1. / 3}};
      const SMDF::Surface_point q = it.locate_on_input(p);
      const SMDF::Surface_point back = it.locate_on_intrinsic(q);
      std::cout << "  common subdivision: " << it.common_subdivision().size() << " pieces; the centroid of intrinsic face 0 "
                << "lies in input face " << q.face << ", and maps back to face " << back.face << "\n";
      //! [intrinsic_flips]
      ok = ok && it.has_common_subdivision() && back.face == 0 && std::abs(back.barycentric[0] - 1. / 3) < 1e-10;
      for(Vertex v : vertices(tm)) expected[v.idx()] = target[v];
      const double err = curvature_error(flat, flat_lengths, expected);
      std::cout << "  recomputed curvature error on the intrinsic triangulation " << err << "\n";
      ok = ok && st.converged && err < 1e-9;
    } else {
      std::cout << "\n";
      for(Vertex v : vertices(tm)) expected[v.idx()] = target[v];
      ok = ok && st.converged && curvature_error(tm, lengths, expected) < 1e-9;
    }
    std::cout << (ok ? "all checks passed" : "CHECK FAILED") << std::endl;
    return ok ? EXIT_SUCCESS : EXIT_FAILURE;
  } catch(const SMDF::Input_error& e) {
    std::cerr << "error (" << SMDF::Input_error::kind_name(e.kind()) << "): " << e.what() << "\n";
    return EXIT_FAILURE;
  }
}
