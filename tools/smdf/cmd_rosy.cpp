// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// smdf rosy: metric-driven N-RoSy field design (Lai et al. 2010): flat cone metric, holonomy
// group and its compatibility tests, and the parallel field when there is one.

#include "commands.h"
#include "common.h"

#include <CGAL/Surface_mesh_direction_fields/Intrinsic_triangulation.h>
#include <CGAL/Surface_mesh_direction_fields/cone_metric.h>
#include <CGAL/Surface_mesh_direction_fields/field_singularities.h>
#include <CGAL/Surface_mesh_direction_fields/holonomy_group.h>
#include <CGAL/Surface_mesh_direction_fields/homotopy_basis.h>
#include <CGAL/Surface_mesh_direction_fields/parallel_rosy_field.h>
#include <CGAL/Surface_mesh_direction_fields/rotation_compensation.h>
#include <CGAL/Surface_mesh_direction_fields/topology.h>
#include <CGAL/Surface_mesh_direction_fields/parameters.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace smdf_cli {

namespace {

const char* loop_kind_name(SMDF::Homotopy_loop_kind k)
{
  return k == SMDF::HANDLE_LOOP ? "handle" : k == SMDF::BOUNDARY_LOOP ? "boundary" : "cone";
}

Json index_list(const std::vector<std::size_t>& v)
{
  Json a = Json::array();
  for(std::size_t i : v) a.push_back(i);
  return a;
}

Json tessellation_json(const SMDF::Tessellation_compatibility& t)
{
  Json o = Json::object();
  o["compatible"] = t.compatible;
  o["spacing"] = t.spacing;
  o["orientation"] = t.orientation;
  o["max_rotation_deviation"] = t.max_rotation_deviation;
  o["max_translation_deviation"] = t.max_translation_deviation;
  o["failing_loops"] = index_list(t.failing_loops);
  return o;
}

// The cones of the options: interior vertices with K < 2 pi (index below 1), each once.
std::vector<std::pair<vertex_descriptor, double>> rosy_cones(const Args& args, const Mesh& mesh)
{
  const Indexed_values cones = pairs_option(args, "cones", parse_angle, "'v:K,v:K,...' (K radians: decimal, p/q, pi/2, -4pi, ...)");
  const Indexed_values indices = pairs_option(args, "cone-indices", parse_number, "'v:k,...' (index k, K = 2 pi k)");
  std::vector<std::pair<vertex_descriptor, double>> out;
  std::vector<char> given(num_vertices(mesh), 0);
  auto add = [&](const char* option, std::size_t v, double K) {
    if(v >= num_vertices(mesh))
      throw Error(std::string("--") + option + ": vertex " + std::to_string(v) + " does not exist (the mesh has " +
                  std::to_string(num_vertices(mesh)) + " vertices)");
    const vertex_descriptor vd(static_cast<Mesh::size_type>(v));
    if(given[v]++) throw Error(std::string("--") + option + ": vertex " + std::to_string(v) + " is given twice");
    if(halfedge(vd, mesh) == boost::graph_traits<Mesh>::null_halfedge() || CGAL::is_border(vd, mesh))
      throw Error(std::string("--") + option + ": vertex " + std::to_string(v) + " is not an interior vertex");
    if(!(K < 2 * CGAL_PI))
      throw Error(std::string("--") + option + ": vertex " + std::to_string(v) +
                  ": cones of index 1 or more (punched holes) are not supported by rosy");
    out.emplace_back(vd, K);
  };
  for(const auto& c : cones) add("cones", c.first, c.second);
  for(const auto& c : indices) add("cone-indices", c.first, 2 * CGAL_PI * c.second);
  return out;
}

} // namespace

Json run_rosy(const Args& args)
{
  const std::string& file = args.positional[0];
  const long requested_N = args.has("N") ? symmetry_order_option(args) : 0;
  const SMDF::Svg_options svg = svg_options(args);
  Mesh mesh;
  load_mesh(file, mesh);
  const std::vector<std::pair<vertex_descriptor, double>> cones = rosy_cones(args, mesh);

  // 1. the flat cone metric
  auto targets = mesh.add_property_map<vertex_descriptor, double>("v:smdf_rosy_target", 0.).first;
  for(const auto& c : cones) targets[c.first] = c.second;
  const Edge_length_property lengths = mesh.add_property_map<edge_descriptor, double>("e:smdf_rosy_length", 0.).first;
  const SMDF::Cone_metric_status cm = on_file(file, [&] { return SMDF::compute_cone_metric(mesh, targets, lengths); });
  Json out = Json::object();
  Json metric = Json::object();
  metric["converged"] = cm.converged;
  metric["iterations"] = cm.iterations;
  metric["max_curvature_error"] = cm.max_curvature_error;
  metric["triangulation_changed"] = cm.triangulation_changed;
  out["metric"] = std::move(metric);
  if(!cm.converged) throw Failed_result{out, file + ": flat cone metric not converged: " + cm.message, 3};

  // 2. the mesh carrying it (the input, or its intrinsic triangulation: same vertices)
  Mesh flat_mesh;
  Edge_length_property flat = lengths;
  Mesh* carrier = &mesh;
  if(cm.triangulation_changed) {
    flat = flat_mesh.add_property_map<edge_descriptor, double>("e:smdf_rosy_length", 0.).first;
    SMDF::copy_intrinsic_triangulation(cm.intrinsic_triangulation, mesh, flat_mesh, flat);
    carrier = &flat_mesh;
  }
  std::vector<vertex_descriptor> cone_vertices;
  for(const auto& c : cones) cone_vertices.push_back(c.first);

  // 3. the holonomy group and its tests
  const auto basis = on_file(file, [&] { return SMDF::homotopy_basis(*carrier, cone_vertices); });
  const SMDF::Holonomy_group group = SMDF::holonomy_group(*carrier, basis, SMDF::parameters::edge_length_map(flat));
  Json loops = Json::array();
  for(std::size_t i = 0; i < basis.loops.size(); ++i) {
    Json l = Json::object();
    l["kind"] = loop_kind_name(basis.loops[i].kind);
    if(basis.loops[i].kind == SMDF::CONE_LOOP) l["cone"] = index(basis.loops[i].cone);
    l["rotation_over_pi"] = group.rotations[i] / CGAL_PI;
    l["translation"] = Json::pair(group.motions[i].translation.x(), group.motions[i].translation.y());
    loops.push_back(std::move(l));
  }
  out["holonomy"] = std::move(loops);
  const int smallest = SMDF::smallest_parallel_rosy_order(group);
  out["smallest_parallel_order"] = smallest;
  out["square_grid"] = tessellation_json(SMDF::tessellation_compatibility(group, SMDF::SQUARE_GRID));
  out["triangular_grid"] = tessellation_json(SMDF::tessellation_compatibility(group, SMDF::TRIANGULAR_GRID));
  // without --N: the smallest order of the group (a parallel field), else the smallest order
  // the cone curvatures allow (rotation compensation, closed surfaces)
  auto cones_allow = [&](int n) {
    for(const auto& c : cones) {
      const double k = c.second / (2 * CGAL_PI) * n;
      if(std::abs(k - std::round(k)) > 1e-6) return false;
    }
    return true;
  };
  int N = requested_N > 0 ? int(requested_N) : smallest;
  if(N == 0)
    for(int n = 1; n <= 24 && N == 0; ++n) if(cones_allow(n)) N = n;
  out["N"] = N;
  if(N == 0)
    throw Failed_result{out, file + ": no N <= 24 for which the cone curvatures are multiples of 2 pi / N", 3};
  const SMDF::Rosy_compatibility rc = SMDF::parallel_rosy_compatibility(group, N);
  Json compat = Json::object();
  compat["compatible"] = rc.compatible;
  compat["max_deviation"] = rc.max_deviation;
  compat["failing_loops"] = index_list(rc.failing_loops);
  out["parallel_rosy"] = std::move(compat);

  // 4. the parallel field, or the rotation-compensated one, read back on the metric
  const auto angles = carrier->add_property_map<face_descriptor, double>("f:smdf_rosy_angle", 0.).first;
  std::string field_failure;
  const bool compensate = !rc.compatible && cones_allow(N) && SMDF::mesh_topology(*carrier).is_closed();
  out["method"] = compensate ? "rotation compensation" : "parallel";
  if(compensate) {
    const auto va = carrier->add_property_map<vertex_descriptor, double>("v:smdf_rosy_angle", 0.).first;
    const SMDF::Rotation_compensation_status cs =
        on_file(file, [&] { return SMDF::rotation_compensated_field(*carrier, N, va, angles, SMDF::parameters::edge_length_map(flat)); });
    Json c = Json::object();
    Json periods = Json::array();
    for(double p : cs.periods) periods.push_back(p);
    c["periods"] = std::move(periods);
    c["max_harmonic_residual"] = cs.max_harmonic_residual;
    c["max_inconsistency"] = cs.max_inconsistency;
    out["rotation_compensation"] = std::move(c);
    if(!cs.success) field_failure = cs.message;
  } else {
    const SMDF::Parallel_rosy_status ps = SMDF::parallel_rosy_field(*carrier, N, angles, SMDF::parameters::edge_length_map(flat));
    if(!rc.compatible)
      field_failure = "no parallel " + std::to_string(N) + "-RoSy field: " + std::to_string(rc.failing_loops.size()) +
                      " loops of the holonomy group turn by angles that are no multiple of 2 pi / " + std::to_string(N) +
                      (cones_allow(N) ? "" : " (nor are the cone curvatures multiples of 2 pi / " + std::to_string(N) + ")");
    else if(!ps.success) field_failure = ps.message;
  }
  const SMDF::Field_topology<Mesh> found =
      SMDF::field_singularities(*carrier, angles, SMDF::parameters::symmetry_order(N).edge_length_map(flat));
  out["found"] = found_list(found);
  std::map<vertex_descriptor, double> want, got(found.singularities.begin(), found.singularities.end());
  bool cones_on_lattice = true;
  for(const auto& c : cones) {
    const double k = c.second / (2 * CGAL_PI) * N;
    cones_on_lattice = cones_on_lattice && std::abs(k - std::round(k)) < 1e-6;
    if(std::round(k) != 0) want[c.first] = std::round(k) / N;
  }
  std::string failure = field_failure;
  if(failure.empty() && (!cones_on_lattice || got != want))
    failure = "the field read back on the metric has other singularities than the cones";
  out["success"] = failure.empty();
  if(!failure.empty()) throw Failed_result{out, file + ": " + failure, 3};

  // 5. the field in 3D (on the input faces only)
  if(args.has("field-out") || args.has("svg")) {
    if(cm.triangulation_changed)
      throw Failed_result{out, file + ": the metric lives on an intrinsic triangulation (edge flips): --field-out and --svg "
                                      "need it on the input faces", 3};
    const Face_vector_property vectors = mesh.add_property_map<face_descriptor, K::Vector_3>("f:smdf_rosy_vector").first;
    SMDF::field_angles_to_vectors(mesh, angles, vectors, SMDF::parameters::edge_length_map(flat));
    write_field_files(args, mesh, vectors, N, found, svg);
  }
  return out;
}

Command rosy_command()
{
  return {"rosy", {"MESH"},
          {{"cones", "LIST", "cone curvatures 'v:K,...' of interior vertices, K in radians (pi/2, -pi, 2*pi/3, ...)"},
           {"cone-indices", "LIST", "the same as indices 'v:k,...', K = 2 pi k (k below 1)"},
           {"N", "n", "symmetry order of the field (default: the smallest the holonomy group allows, up to 24)"},
           {"field-out", "FILE", "write one unit direction 'x y z' per face (input triangulation only)"},
           {"svg", "FILE", "write an SVG picture of the field and its singularities"},
           {"view", "A,E[,UP]", "view of --svg: azimuth,elevation in degrees, up axis x|y|z"},
           {"width", "PX", "width of the --svg picture in pixels (default 800)"}},
          "metric-driven N-RoSy field design: cone metric, holonomy group, parallel field",
          "Lai et al. 2010: computes the flat cone metric with the given cone curvatures (Ricci flow,\n"
          "as cone-metric; they must sum to 2 pi chi), a basis of the fundamental group of the mesh\n"
          "minus its cones (handle loops, boundary loops, a loop around every cone but one, all\n"
          "through one base face), the generalised holonomy of every loop, and the compatibility\n"
          "tests: the smallest N for which a parallel N-RoSy field exists (Theorem 3.2; on a sphere\n"
          "the cone curvatures must be multiples of 2 pi / N), and whether a square or triangular\n"
          "grid fits (Theorem 3.5). Then it builds the parallel N-RoSy field and reads it back on the\n"
          "metric: its singularities must be exactly the cones, with index K / 2 pi. When the group\n"
          "allows no parallel field but the cone curvatures are multiples of 2 pi / N (closed\n"
          "surfaces of any genus), the field is made by rotation compensation (Lai et al. 4.1.3.1:\n"
          "a harmonic 1-form cancels the holonomy of the handle loops); without --N, N is the\n"
          "smallest order of the group, else the smallest the cone curvatures allow.\n"
          "Prints {metric: {converged, iterations, max_curvature_error, triangulation_changed},\n"
          "holonomy: [{kind, cone, rotation_over_pi, translation}], smallest_parallel_order (0: none\n"
          "up to 24), square_grid and triangular_grid: {compatible, spacing, orientation,\n"
          "max_rotation_deviation, max_translation_deviation, failing_loops}, N, parallel_rosy:\n"
          "{compatible, max_deviation, failing_loops}, method (parallel | rotation compensation),\n"
          "rotation_compensation: {periods, max_harmonic_residual, max_inconsistency},\n"
          "found: [{vertex, index}], success}.\n"
          "Exit code 3 (JSON printed) when the metric does not converge, no parallel field exists for\n"
          "N, or the read-back differs from the cones. Field vectors are mapped to 3D by the linear\n"
          "map from each metric triangle to the embedded one.\n",
          run_rosy};
}

} // namespace smdf_cli
