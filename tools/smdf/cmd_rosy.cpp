// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// smdf rosy: metric-driven N-RoSy field design (Lai et al. 2010): flat cone metric, holonomy
// group and its compatibility tests, the field (rotation compensation, parallel transport or
// the trivial connection of the metric), open meshes, editing, and its read-back.

#include "commands.h"
#include "common.h"
#include "rosy_inputs.h"

#include <CGAL/Surface_mesh_direction_fields/Intrinsic_triangulation.h>
#include <CGAL/Surface_mesh_direction_fields/Trivial_connection.h>
#include <CGAL/Surface_mesh_direction_fields/boundary_aligned_field.h>
#include <CGAL/Surface_mesh_direction_fields/vertex_field_from_faces.h>
#include <CGAL/Surface_mesh_direction_fields/cone_metric.h>
#include <CGAL/Surface_mesh_direction_fields/curvature_aligned_field.h>
#include <CGAL/Surface_mesh_direction_fields/field_editing.h>
#include <CGAL/Surface_mesh_direction_fields/field_singularities.h>
#include <CGAL/Surface_mesh_direction_fields/field_transfer.h>
#include <CGAL/Surface_mesh_direction_fields/holonomy_group.h>
#include <CGAL/Surface_mesh_direction_fields/homotopy_basis.h>
#include <CGAL/Surface_mesh_direction_fields/parallel_rosy_field.h>
#include <CGAL/Surface_mesh_direction_fields/parameters.h>
#include <CGAL/Surface_mesh_direction_fields/rotation_compensation.h>
#include <CGAL/Surface_mesh_direction_fields/topology.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <map>
#include <string>
#include <vector>

namespace smdf_cli {

namespace {

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

bool has_handles(const Mesh& mesh)
{
  for(const auto& c : SMDF::mesh_topology(mesh).components) if(c.genus > 0) return true;
  return false;
}

bool multiple_of(double K, int N) { const double k = K / (2 * CGAL_PI) * N; return std::abs(k - std::round(k)) < 1e-6; }

} // namespace

Json write_hatching_svg(const Args& args, const std::string& file, const Mesh& mesh, const Face_vector_property& vectors, int N,
                        const SMDF::Svg_options& svg)
{
  SMDF::Svg_options view = svg;
  if(!args.has("view")) view.up_axis = default_up_axis(mesh);
  view.edge_stroke_width = 0;
  view.face_color = "#f4f4f4";
  view.glyph_stroke_width = 0.7;
  const auto lines = on_file(file, [&] { return SMDF::trace_streamlines(mesh, vectors, N); });
  std::ostringstream os;
  SMDF::write_streamlines_svg(os, mesh, lines, view);
  write_lines_file(args.value("hatching-svg"), os.str());
  double total = 0;
  for(const auto& l : lines) total += l.length;
  Json hj = Json::object();
  hj["strokes"] = lines.size();
  hj["total_length"] = total;
  return hj;
}

Json run_rosy(const Args& args)
{
  const std::string& file = args.positional[0];
  const Rosy_options opt = rosy_options(args);
  const SMDF::Svg_options svg = svg_options(args);
  Mesh mesh;
  load_mesh(file, mesh);
  // --cones auto: the singularities of a smooth curvature-aligned field (N given, else 4)
  const bool automatic = args.has("cones") && args.value("cones") == "auto";
  if(automatic && args.has("cone-indices")) throw Usage_error("--cones auto takes no --cone-indices");
  if((args.has("alignment-weight") || args.has("smoothing-steps")) && !automatic)
    throw Usage_error("--alignment-weight and --smoothing-steps need --cones auto");
  Json automatic_json;
  const std::vector<std::pair<vertex_descriptor, double>> cones =
      automatic ? automatic_cones(args, file, mesh, opt.N ? int(opt.N) : 4, opt.boundary, automatic_json) : cone_option(args, mesh, true);
  const bool open = !SMDF::mesh_topology(mesh).is_closed();
  if(opt.boundary_given && !open) throw Usage_error("--boundary: " + file + " has no boundary");
  const bool editing = args.has("edit") || args.has("length");
  Json out = Json::object();
  Json timings = Json::object();
  Stopwatch clock;

  // 0. N: given, else the smallest for which every cone curvature is a multiple of 2 pi / N
  int N = int(opt.N);
  if(N == 0) {
    for(int n = 1; n <= 24 && N == 0; ++n) {
      bool all = true;
      for(const auto& c : cones) all = all && multiple_of(c.second, n);
      if(all) N = n;
    }
    if(N == 0) throw Error("no N <= 24 makes every cone curvature a multiple of 2 pi / N; give --N");
  }
  if(automatic && !opt.N) N = 4;
  out["N"] = N;
  out["N_from"] = opt.N ? "option" : automatic ? "automatic cones" : "cones";
  if(automatic) out["automatic_cones"] = std::move(automatic_json);

  // 1. the method
  Rosy_method method = opt.method;
  if(open && opt.boundary != FREE_BOUNDARY) method = BOUNDARY_ALIGNED;
  // (open meshes with handles: no parallel field in general, and rotation compensation is for
  // closed meshes: the trivial connection of the metric)
  else if(method == AUTOMATIC) method = !open ? ROTATION_COMPENSATION : has_handles(mesh) ? TRIVIAL_CONNECTION : PARALLEL;
  if(method == ROTATION_COMPENSATION && open)
    throw Usage_error("--method rotation-compensation needs a closed mesh; on " + file +
                      " use --method parallel or trivial-connection (free boundary) or --boundary parallel|orthogonal");
  if(editing && method != ROTATION_COMPENSATION)
    throw Usage_error(std::string("--edit and --length edit the vertex field of rotation compensation (closed meshes), not a ") +
                      method_name(method) + " field");
  out["method"] = method_name(method);
  if(open) out["boundary"] = opt.boundary == FREE_BOUNDARY ? "free" : opt.boundary == PARALLEL_BOUNDARY ? "parallel" : "orthogonal";

  // 2. the targets and the flat cone metric
  auto targets = mesh.add_property_map<vertex_descriptor, double>("v:smdf_rosy_target", 0.).first;
  for(const auto& c : cones) targets[c.first] = c.second;
  const Boundary_geometry bgeo = open ? boundary_geometry(mesh) : Boundary_geometry();
  if(open) {
    try {
      open_mesh_targets(mesh, bgeo, N, opt.boundary, cones, targets);
    } catch(const Error& e) {
      throw Error(file + ": " + e.what());   // the same "<file>: " prefix as every other input error
    }
  }
  // cones of index 1 or more: punched holes (Lai et al. 4.1.1), see rosy_punched.cpp
  bool punch = false;
  for(const auto& c : cones) punch = punch || (!is_border(c.first, mesh) && !(c.second < 2 * CGAL_PI));
  if(punch) {
    for(const char* o : {"edit", "length", "turning"})
      if(args.has(o)) throw Usage_error(std::string("--") + o + " is not available with cones of index 1 or more (punched holes)");
    std::string holed_failure;
    Json punched = run_rosy_punched(args, file, mesh, N, cones, targets, opt.method, opt.boundary, svg, &holed_failure);
    if(holed_failure.empty()) return punched;
    out["holed_metric"] = holed_failure;
    out["spread_to_neighbours"] = spread_to_neighbours(mesh, cones, targets);
    method = TRIVIAL_CONNECTION;
    out["method"] = std::string(method_name(method)) + " (cones of index 1 or more spread to their neighbours)";
  }
  Edge_length_property lengths = mesh.add_property_map<edge_descriptor, double>("e:smdf_rosy_length", 0.).first;
  Face_angle_property input_angles = mesh.add_property_map<face_descriptor, double>("f:smdf_rosy_angle", 0.).first;
  // the flat cone metric (flips allowed); fields along the boundary take its geodesic boundary
  // (Lai et al. 4.3: the double cover's metric restricted to the mesh)
  SMDF::Cone_metric_status cm = on_file(file, [&] { return SMDF::compute_cone_metric(mesh, targets, lengths); });
  // open meshes: where a cone next to the boundary stalls the flow, the border edge it faces is
  // split (on the input surface) and the flow run again; everything below then runs on that
  // refinement, and the outputs are brought back to the input's faces at the end
  Boundary_refinement br;
  if(open && !cm.converged && refine_boundary_until_converged(file, mesh, targets, lengths, cm, br))
    input_angles = mesh.add_property_map<face_descriptor, double>("f:smdf_rosy_angle", 0.).first;
  Mesh& original = br.original;
  const SMDF::Delaunay_refinement_status& refinement = br.status;
  const bool refined_input = br.rounds > 0;
  timings["metric_s"] = clock.lap();
  out["metric"] = metric_json(cm, nullptr);
  if(refined_input) {
    Json r = Json::object();
    r["rounds"] = br.rounds;
    r["inserted_vertices"] = refinement.inserted.size();
    r["faces"] = refinement.faces;
    out["boundary_refinement"] = std::move(r);
  }
  if(open) {
    Json bt = Json::array();
    for(const auto& loop : bgeo.loops) {
      double total = 0;
      for(vertex_descriptor v : loop) total += targets[v];
      bt.push_back(total / CGAL_PI);
    }
    out["boundary_turning_over_pi"] = std::move(bt);
  }
  if(!cm.converged) {
    out["success"] = false;
    out["timings"] = std::move(timings);
    throw Failed_result{out, file + ": flat cone metric not converged: " + cm.message, 3};
  }

  // 3. the mesh carrying it (the input, or its intrinsic triangulation: same vertices)
  Mesh flat_mesh;
  Edge_length_property flat = lengths;
  Mesh* carrier = &mesh;
  if(cm.triangulation_changed) {
    flat = flat_mesh.add_property_map<edge_descriptor, double>("e:smdf_rosy_length", 0.).first;
    SMDF::copy_intrinsic_triangulation(cm.intrinsic_triangulation, mesh, flat_mesh, flat);
    carrier = &flat_mesh;
  }
  const bool on_input = carrier == &mesh;
  // with flips, everything reaches the input through the common subdivision
  if(!on_input && !cm.intrinsic_triangulation.has_common_subdivision()) {
    out["success"] = false;
    throw Failed_result{out, file + ": the metric lives on an intrinsic triangulation without its correspondence to the input: " +
                                 cm.correspondence_message, 3};
  }
  if(!on_input) {
    Json c = Json::object();
    c["intrinsic_edges"] = cm.intrinsic_triangulation.number_of_new_edges();
    c["crossings"] = cm.intrinsic_triangulation.number_of_crossings();
    c["pieces"] = cm.intrinsic_triangulation.common_subdivision().size();
    out["correspondence"] = std::move(c);
  }
  // vertex angles: the intrinsic frames' rotation from the input's
  const std::vector<double> frame_delta =
      on_input ? std::vector<double>() : SMDF::input_vertex_frame_angles(mesh, cm.intrinsic_triangulation);
  auto carrier_vertex = [&](vertex_descriptor v) { return vertex_descriptor(std::uint32_t(v.idx())); };   // same indices
  std::vector<vertex_descriptor> cone_vertices;
  for(const auto& c : cones) if(!is_border(c.first, mesh)) cone_vertices.push_back(c.first);

  // 4. the holonomy group and its tests
  // the carrier's own lengths: an intrinsic triangulation may join a vertex to itself (zero from the points)
  const auto basis = on_file(file, [&] { return SMDF::homotopy_basis(*carrier, cone_vertices, SMDF::parameters::edge_length_map(flat)); });
  const SMDF::Holonomy_group group = SMDF::holonomy_group(*carrier, basis, SMDF::parameters::edge_length_map(flat));
  const SMDF::Rosy_compatibility rc = SMDF::parallel_rosy_compatibility(group, N);
  if(args.has("holonomy")) out["holonomy"] = holonomy_loops_json(basis, group, rc);
  Json compatible_N = Json::array();
  for(int n = 1; n <= 24; ++n) if(SMDF::parallel_rosy_compatibility(group, n).compatible) compatible_N.push_back(n);
  out["compatible_N"] = std::move(compatible_N);
  out["smallest_parallel_order"] = SMDF::smallest_parallel_rosy_order(group);
  out["square_grid"] = tessellation_json(SMDF::tessellation_compatibility(group, SMDF::SQUARE_GRID));
  out["triangular_grid"] = tessellation_json(SMDF::tessellation_compatibility(group, SMDF::TRIANGULAR_GRID));
  Json compat = Json::object();
  compat["compatible"] = rc.compatible;
  compat["max_deviation"] = rc.max_deviation;
  compat["failing_loops"] = index_list(rc.failing_loops);
  out["parallel_rosy"] = std::move(compat);
  clock.lap();

  // 5. the field, in the face frames of the metric (and per vertex for rotation compensation)
  std::string failure;
  std::vector<std::string> off_lattice;   // cones whose curvature is no multiple of 2 pi / N
  for(const auto& c : cones)
    if(!is_border(c.first, mesh) && !multiple_of(c.second, N)) off_lattice.push_back(std::to_string(index(c.first)));
  if(!off_lattice.empty()) {
    std::string list;
    for(std::size_t i = 0; i < off_lattice.size() && i < 5; ++i) list += (i ? ", " : "") + off_lattice[i];
    failure = "no " + std::to_string(N) + "-RoSy field has these cones: the curvature of " + std::to_string(off_lattice.size()) +
              " cone(s) (vertex " + list + (off_lattice.size() > 5 ? ", ..." : "") + ") is no multiple of 2 pi / " +
              std::to_string(N) + " (" + std::to_string(rc.failing_loops.size()) + " loops of the holonomy group fail the " +
              std::to_string(N) + "-RoSy test)";
  }
  const Face_angle_property angles =
      on_input ? input_angles : carrier->add_property_map<face_descriptor, double>("f:smdf_rosy_angle", 0.).first;
  const auto vertex_angles = carrier->add_property_map<vertex_descriptor, double>("v:smdf_rosy_angle", 0.).first;
  const auto vertex_lengths = carrier->add_property_map<vertex_descriptor, double>("v:smdf_rosy_length", 1.).first;
  Edge_matching_property matching = carrier->add_property_map<edge_descriptor, int>("e:smdf_rosy_matching", 0).first;
  bool have_matching = false;
  std::vector<double> prescribed_turning;   // trivial connection: per generator
  if(failure.empty()) {
    const auto np = SMDF::parameters::edge_length_map(flat);
    auto trivial_connection = [&](bool least_compensation) {
      SMDF::Trivial_connection<Mesh> tc = on_file(file, [&] {
        return SMDF::Trivial_connection<Mesh>(*carrier, SMDF::parameters::symmetry_order(N).edge_length_map(flat));
      });
      for(const auto& c : cones)
        if(!is_border(c.first, mesh)) tc.set_singularity(c.first, std::round(c.second / (2 * CGAL_PI) * N) / N);
      for(const auto& g : opt.turning) on_file(file, [&] { tc.set_generator_turning_number(g.first, g.second); return 0; });
      if(least_compensation) turn_generators_least(tc, N);
      const SMDF::Trivial_connection_status ts = tc.solve();
      out["trivial_connection"] = trivial_connection_json(ts);
      if(!ts.success) failure = "trivial connection solve failed: " + ts.message;
      else {
        tc.field_angles(angles);
        tc.field_matching(angles, matching);
        have_matching = true;
        for(std::size_t g = 0; g < tc.generators().size(); ++g) prescribed_turning.push_back(tc.generator_turning_number(g));
      }
      timings["compensation_s"] = clock.lap();
    };
    if(method == ROTATION_COMPENSATION) {
      auto compensate = [&](const std::vector<double>& turning) {
        return on_file(file, [&] {
          return SMDF::rotation_compensated_field(*carrier, N, vertex_angles, angles, np.generator_turning_numbers(turning).matching(matching));
        });
      };
      SMDF::Rotation_compensation_status cs = compensate({});
      if(!opt.turning.empty() && cs.success) {
        // the given turning numbers; the others as chosen by default (the least compensation)
        std::vector<double> t;
        for(std::size_t i = 0; i < cs.periods.size(); ++i) t.push_back((cs.periods[i] + cs.holonomy[i]) / (2 * CGAL_PI));
        for(const auto& g : opt.turning) {
          if(g.first >= t.size())
            throw Error("--turning: handle loop " + std::to_string(g.first) + " does not exist (there are " + std::to_string(t.size()) + ")");
          if(!multiple_of(2 * CGAL_PI * g.second, N))
            throw Error("--turning: the turning number of handle loop " + std::to_string(g.first) + " must be a multiple of 1/" + std::to_string(N));
          t[g.first] = g.second;
        }
        for(double& x : t) x = std::round(x * N) / N;
        cs = compensate(t);
      }
      Json c = Json::object();
      Json periods = Json::array(), turning = Json::array();
      for(std::size_t i = 0; i < cs.periods.size(); ++i) {
        periods.push_back(cs.periods[i]);
        turning.push_back(std::round((cs.periods[i] + cs.holonomy[i]) / (2 * CGAL_PI) * N) / N);
      }
      c["periods"] = std::move(periods);
      c["handle_turning_numbers"] = std::move(turning);
      c["max_harmonic_residual"] = cs.max_harmonic_residual;
      c["max_inconsistency"] = cs.max_inconsistency;
      c["max_rotation"] = cs.max_rotation;
      out["rotation_compensation"] = std::move(c);
      if(!cs.success) failure = cs.message;
      // its own matching: the 1-form may turn the field by pi / N or more across long intrinsic edges
      have_matching = cs.success && !editing;
      if(have_matching) out["max_rotation_over_pi_over_N"] = cs.max_rotation / (CGAL_PI / N);
      timings["compensation_s"] = clock.lap();
      if(!cs.success && opt.turning.empty() && !editing) {
        // a numerical failure: the trivial connection with the same least compensation gives the
        // field rotation compensation was asked for
        out["rotation_compensation_failure"] = cs.message;
        failure.clear();
        method = TRIVIAL_CONNECTION;
        out["method"] = std::string(method_name(method)) + " (rotation compensation failed: each handle loop turns by the multiple "
                                                           "of 2 pi / N nearest its holonomy, as rotation compensation would)";
        trivial_connection(true);
      }
    } else if(method == TRIVIAL_CONNECTION) {
      trivial_connection(false);
    } else if(method == PARALLEL) {
      const SMDF::Parallel_rosy_status ps = SMDF::parallel_rosy_field(*carrier, N, angles, np);
      if(!rc.compatible)
        failure = "no parallel " + std::to_string(N) + "-RoSy field: " + std::to_string(rc.failing_loops.size()) +
                  " loops of the holonomy group turn by angles that are no multiple of 2 pi / " + std::to_string(N) +
                  (open ? "" : " (try --method rotation-compensation)");
      else if(!ps.success) failure = ps.message;
      timings["compensation_s"] = clock.lap();
    } else {
      const SMDF::Boundary_aligned_field_status aligned = on_file(file, [&] {
        return SMDF::boundary_aligned_field_of_metric(*carrier, N, angles, matching,
                                                      np.orthogonal_to_boundary(opt.boundary == ORTHOGONAL_BOUNDARY));
      });
      have_matching = aligned.success;
      Json a = Json::object();
      a["max_boundary_deviation"] = aligned.max_boundary_deviation;
      a["rotation_compensation"] = aligned.rotation_compensation;
      out["boundary_aligned"] = std::move(a);
      if(!aligned.success) failure = aligned.message;
      timings["compensation_s"] = clock.lap();
    }
  }

  // 6. editing (Lai et al. 4.2): direction and length constraints at vertices
  if(failure.empty() && editing) {
    SMDF::Rosy_vertex_field_editor<Mesh> editor(*carrier, N, vertex_angles, SMDF::parameters::edge_length_map(flat));
    Json e = Json::object();
    if(args.has("edit")) {
      const Constraint_lines c = read_constraint_file(args.value("edit"), mesh, false);
      auto vectors = mesh.add_property_map<vertex_descriptor, K::Vector_3>("v:smdf_rosy_edit", K::Vector_3(0, 0, 0)).first;
      for(const auto& d : c.directions) vectors[d.first] = d.second;
      auto constraint_angles = mesh.add_property_map<vertex_descriptor, double>("v:smdf_rosy_edit_angle", 0.).first;
      if(on_input) SMDF::vertex_vectors_to_angles(mesh, vectors, constraint_angles, SMDF::parameters::edge_length_map(flat));
      else SMDF::vertex_vectors_to_angles(mesh, vectors, constraint_angles);
      std::vector<std::pair<vertex_descriptor, double>> pairs;
      for(const auto& d : c.directions)
        pairs.emplace_back(carrier_vertex(d.first), constraint_angles[d.first] + (on_input ? 0. : frame_delta[d.first.idx()]));
      on_file(args.value("edit"), [&] { editor.set_direction_constraints(pairs, c.weights); return 0; });
      e["directions"] = pairs.size();
      e["hard_directions"] = c.hard();
    }
    if(args.has("length")) {
      const Constraint_lines c = read_constraint_file(args.value("length"), mesh, true);
      std::vector<std::pair<vertex_descriptor, double>> lengths;
      for(const auto& l : c.lengths) lengths.emplace_back(carrier_vertex(l.first), l.second);
      on_file(args.value("length"), [&] { editor.set_length_constraints(lengths, c.weights); return 0; });
      e["lengths"] = c.lengths.size();
      e["hard_lengths"] = c.hard();
    }
    clock.lap();
    const SMDF::Field_edit_status es = editor.edit();
    editor.vertex_angles(vertex_angles);
    editor.face_angles(angles);
    editor.vertex_lengths(vertex_lengths);
    timings["edit_s"] = clock.lap();
    e["max_direction_error"] = es.max_direction_error;
    e["max_length_error"] = es.max_length_error;
    double lo = 1e300, hi = -1e300;
    for(vertex_descriptor v : vertices(*carrier)) { lo = (std::min)(lo, vertex_lengths[v]); hi = (std::max)(hi, vertex_lengths[v]); }
    e["length_range"] = Json::pair(lo, hi);
    out["edit"] = std::move(e);
    if(!es.success) failure = "editing failed: " + es.message;
  }

  // 7. the read-back with the field's matching: the trivial connection's, else the principal one
  // on the metric (these fields turn by less than pi / N per edge relative to Levi-Civita)
  const SMDF::Field_topology<Mesh> found = [&] {
    if(!failure.empty()) return SMDF::Field_topology<Mesh>();
    const auto np = SMDF::parameters::symmetry_order(N).edge_length_map(flat);
    if(!have_matching) {
      const double widest = SMDF::principal_matching(*carrier, angles, matching, np);
      out["max_rotation_over_pi_over_N"] = widest / (CGAL_PI / N);
    }
    return SMDF::field_singularities(*carrier, angles, np.matching(matching));
  }();
  out["prescribed"] = [&] {
    Json a = Json::array();
    std::vector<std::pair<std::size_t, double>> p;
    for(const auto& c : cones)
      if(!is_border(c.first, mesh)) p.emplace_back(index(c.first), std::round(c.second / (2 * CGAL_PI) * N) / N);
    std::sort(p.begin(), p.end());
    for(const auto& x : p) {
      if(x.second == 0) continue;
      Json o = Json::object();
      o["vertex"] = x.first;
      o["index"] = x.second;
      a.push_back(std::move(o));
    }
    return a;
  }();
  out["found"] = found_list(found);
  out["generator_turning_numbers"] = turning_numbers(found);
  if(failure.empty()) {
    const std::map<vertex_descriptor, double> got(found.singularities.begin(), found.singularities.end());
    if(got != prescribed_indices(mesh, cones, N)) failure = "the field read back with its matching has other singularities than the cones";
    else if(!prescribed_turning.empty() && found.generator_turning_numbers != prescribed_turning)
      failure = "the field read back with its matching has other generator turning numbers than the prescribed ones";
  }
  // 7'. the face field and its matching on the input mesh, read back there: with flips carried
  // through the common subdivision, without them mapped face by face to the embedding
  Edge_matching_property input_matching = matching;
  Face_angle_property embedded_angles = input_angles;   // the field in the embedded face frames
  if(failure.empty()) {
    input_matching = mesh.add_property_map<edge_descriptor, int>("e:smdf_rosy_input_matching", 0).first;
    const Face_angle_property on_mesh_angles =
        on_input ? mesh.add_property_map<face_descriptor, double>("f:smdf_rosy_embedded_angle", 0.).first : input_angles;
    embedded_angles = on_mesh_angles;
    SMDF::Field_transfer_status ts;
    Json t = Json::object();
    if(on_input) {
      SMDF::face_field_in_embedding(mesh, N, angles, matching, flat, on_mesh_angles, input_matching);
      ts.success = true;
    } else {
      std::vector<double> a(num_faces(*carrier));
      std::vector<int> k(num_edges(*carrier));
      for(face_descriptor f : faces(*carrier)) a[f.idx()] = angles[f];
      for(edge_descriptor e : edges(*carrier)) k[e.idx()] = matching[e];
      ts = SMDF::transfer_face_field_to_input(mesh, cm.intrinsic_triangulation, N, a, k, on_mesh_angles, input_matching);
      t["max_distortion"] = ts.max_distortion;
      t["mean_distortion"] = ts.mean_distortion;
    }
    const SMDF::Field_topology<Mesh> on_mesh =
        ts.success ? SMDF::field_singularities(mesh, on_mesh_angles, SMDF::parameters::symmetry_order(N).matching(input_matching))
                   : SMDF::Field_topology<Mesh>();
    t["found"] = found_list(on_mesh);
    // the boundary alignment, measured again on the input faces
    const double deviation = method == BOUNDARY_ALIGNED && ts.success
        ? SMDF::max_boundary_deviation(mesh, N, on_mesh_angles, SMDF::parameters::orthogonal_to_boundary(opt.boundary == ORTHOGONAL_BOUNDARY))
        : 0.;
    if(method == BOUNDARY_ALIGNED) t["max_boundary_deviation"] = deviation;
    out["input_read_back"] = std::move(t);
    const std::map<vertex_descriptor, double> got(on_mesh.singularities.begin(), on_mesh.singularities.end());
    if(!ts.success) failure = "the field could not be carried to the input faces: " + ts.message;
    else if(got != prescribed_indices(mesh, cones, N))
      failure = "the field on the input faces reads back, with its matching, other singularities than the cones";
    else if(!(deviation <= 1e-6))
      failure = "the field on the input faces does not follow the boundary (deviation " + std::to_string(deviation) + " rad)";
  }
  // 7''. after a boundary refinement: the face field and its matching on the input's own faces
  Face_field output{&mesh, embedded_angles, input_matching};
  if(failure.empty() && refined_input)
    failure = bring_back_to_input({{&original, &refinement}}, output, N, cones, method == BOUNDARY_ALIGNED,
                                  opt.boundary == ORTHOGONAL_BOUNDARY, "the boundary refinement", out["boundary_refinement"]);
  out["success"] = failure.empty();
  out["timings"] = std::move(timings);
  if(!failure.empty()) throw Failed_result{out, file + ": " + failure, 3};

  // 8. the files, on the input mesh: vertex and face fields in 3D, the matching, the pictures
  // (after a boundary refinement: the input's vertices come first in it; its faces through 7'')
  Mesh& input = *output.mesh;
  const Face_angle_property input_face_angles = output.angles;
  const Edge_matching_property output_matching = output.matching;
  if(args.has("field-out") && method != ROTATION_COMPENSATION) {
    // the face field's vertex version: zero at the singularities, exact along a followed boundary
    auto vv = input.add_property_map<vertex_descriptor, K::Vector_3>("v:smdf_rosy_vector").first;
    SMDF::vertex_field_from_face_field(input, N, input_face_angles, output_matching, vv);
    std::vector<K::Vector_3> v;
    for(vertex_descriptor x : vertices(input)) v.push_back(vv[x]);
    write_vectors(args.value("field-out"), v);
  } else if(args.has("field-out")) {
    auto vv = mesh.add_property_map<vertex_descriptor, K::Vector_3>("v:smdf_rosy_vector").first;
    if(on_input) SMDF::vertex_field_to_vectors(mesh, vertex_angles, vv, SMDF::parameters::edge_length_map(flat));
    else {
      auto in_angles = mesh.add_property_map<vertex_descriptor, double>("v:smdf_rosy_input_angle", 0.).first;
      for(vertex_descriptor x : vertices(mesh)) in_angles[x] = vertex_angles[carrier_vertex(x)] - frame_delta[x.idx()];
      SMDF::vertex_field_to_vectors(mesh, in_angles, vv);
    }
    std::vector<K::Vector_3> v;
    for(vertex_descriptor x : vertices(input)) v.push_back(vv[x] * vertex_lengths[carrier_vertex(x)]);
    write_vectors(args.value("field-out"), v);
  }
  if(args.has("face-field-out") || args.has("svg") || args.has("hatching-svg")) {
    const Face_vector_property vectors = input.add_property_map<face_descriptor, K::Vector_3>("f:smdf_rosy_vector").first;
    if(refined_input) SMDF::field_angles_to_vectors(input, output.angles, vectors);
    else if(on_input) SMDF::field_angles_to_vectors(mesh, angles, vectors, SMDF::parameters::edge_length_map(flat));
    else SMDF::field_angles_to_vectors(mesh, input_angles, vectors);
    if(args.has("face-field-out")) {
      std::vector<K::Vector_3> v;
      for(face_descriptor f : faces(input)) v.push_back(vectors[f]);
      write_vectors(args.value("face-field-out"), v);
    }
    if(args.has("svg")) write_field_svg_file(args, input, vectors, N, found, svg);
    if(args.has("hatching-svg")) out["hatching"] = write_hatching_svg(args, file, input, vectors, N, svg);
  }
  if(args.has("matching-out")) write_matching(args.value("matching-out"), input, output_matching);
  return out;
}

Command rosy_command()
{
  return {"rosy", {"MESH"},
          {{"cones", "LIST", "cone curvatures 'v:K,...', K in radians (pi/2, -pi, 2*pi/3, ...); at boundary vertices the boundary's turning angle; "
                             "or 'auto': the singularities of a smooth curvature-aligned N-RoSy field"},
           {"alignment-weight", "W", "--cones auto: weight of the alignment with the curvature against smoothness (default 0.01; larger: more singularities)"},
           {"smoothing-steps", "S", "--cones auto: further diffusion steps of the field towards the smoothest one (default 4)"},
           {"cone-indices", "LIST", "the same as indices 'v:k,...', K = 2 pi k (k below 1)"},
           {"N", "n", "symmetry order (default: the smallest N for which every cone curvature is a multiple of 2 pi / N)"},
           {"method", "M", "rotation-compensation (default on closed meshes), parallel (default on open ones) or trivial-connection"},
           {"turning", "LIST", "turning numbers 'g:t,...' (multiples of 1/N): of the handle loops (rotation-compensation) or generators (trivial-connection)"},
           {"boundary", "B", "open meshes: free (default), parallel or orthogonal (the field follows the boundary)"},
           {"edit", "FILE", "direction constraints, lines 'vertex x y z [weight]' (no weight: hard; hard and soft may be mixed)"},
           {"length", "FILE", "length constraints, lines 'vertex length [weight]'"},
           {"field-out", "FILE", "write one 'x y z' per vertex: rotation compensation's vertex field (scaled by the edited lengths), "
                                 "else the face field's vertex version (0 at singularities; along the boundary at boundary vertices when it follows it)"},
           {"face-field-out", "FILE", "write one unit direction 'x y z' per face"},
           {"matching-out", "FILE", "write 'i j k' per interior edge (period jump of the field)"},
           {"holonomy", "", "print the basis-loop table: kind, cone, rotation, translation, compatible"},
           {"svg", "FILE", "write an SVG picture of the field and its singularities"},
           {"hatching-svg", "FILE", "write a pen-and-ink SVG: streamlines of the field traced on the surface"},
           {"view", "A,E[,UP]", "view of the pictures: azimuth,elevation in degrees, up axis x|y|z"},
           {"width", "PX", "width of the pictures in pixels (default 800)"}},
          "metric-driven N-RoSy field design: cone metric, holonomy group, field, editing",
          "Lai et al. 2010: computes the flat cone metric with the given cone curvatures (Ricci flow,\n"
          "as cone-metric; with the boundary's turning angles they must sum to 2 pi chi), a basis of\n"
          "the fundamental group of the mesh minus its cones (handle loops, boundary loops, a loop\n"
          "around every cone but one, all through one base face), the generalised holonomy of every\n"
          "loop and the compatibility tests (Theorem 3.2: the N for which a parallel N-RoSy field\n"
          "exists; Theorem 3.5: square and triangular grids), then the field:\n"
          "  rotation-compensation  closed meshes (default): a harmonic 1-form cancels the holonomy of\n"
          "                         the handle loops (4.1.3.1), a direction per vertex propagated from\n"
          "                         one vertex; --turning sets the handle loops' turning numbers\n"
          "  parallel               parallel transport by the metric; needs a compatible group (open\n"
          "                         meshes: the default)\n"
          "  trivial-connection     Crane et al. on the same metric, with index K / 2 pi at the cones\n"
          "Cones of index 1 or more (K >= 2 pi) punch a hole (4.1.1): the field of the holed\n"
          "surface's flat metric (parallel, or with the other methods its trivial connection with\n"
          "the handles' holonomy compensated), the hole filled with the cone's index. A cone whose\n"
          "ring touches the boundary or another such cone first gets room: its edges are split\n"
          "close to it; where the holed surface's flow stalls next to a border edge (of the mesh\n"
          "or of a hole), that edge is split as below (JSON hole_refinement: {refinements,\n"
          "inserted_vertices, faces}); the outputs are on the input's faces (input_read_back);\n"
          "--holonomy lists the holed surface's loops (the holes are boundary loops).\n"
          "Open meshes: --boundary free gives the boundary vertices not named in --cones the input's\n"
          "turning angle, changed so that each boundary loop turns by a multiple of 2 pi / N and\n"
          "Gauss-Bonnet holds; --boundary parallel|orthogonal rounds each boundary vertex's turning\n"
          "angle to a multiple of 2 pi / N (pi / N for odd N) and builds the field parallel or\n"
          "orthogonal to every boundary edge (4.3) from the mesh's own flat metric with a geodesic\n"
          "boundary (flips allowed; the double cover's, restricted), with rotation compensation of\n"
          "the handles. Where a cone next to the boundary stalls that metric (its triangle on a\n"
          "border edge opens to pi; the double cover would flip the edge), the border edges seen\n"
          "under more than 0.8 pi are split on the input surface and the flow runs again (up to 6\n"
          "rounds, while each halves the curvature error); the field is then brought back to the\n"
          "input's faces and edges and read back\n"
          "there: boundary_refinement: {rounds, inserted_vertices, faces, found, max_distortion,\n"
          "max_boundary_deviation}.\n"
          "--edit and --length edit the vertex field (4.2): harmonic interpolation of the rotation\n"
          "and the log-length with the cotan Laplacian; a line without weight is a hard constraint,\n"
          "one with weight lambda a soft one. Directions are projected on the vertex tangent plane.\n"
          "Prints {N, N_from, method, boundary, metric: {converged, iterations, max_curvature_error,\n"
          "triangulation_changed}, boundary_turning_over_pi (per loop), holonomy (with --holonomy):\n"
          "[{kind, cone, rotation_over_pi, translation, compatible}], compatible_N,\n"
          "smallest_parallel_order, square_grid and triangular_grid: {compatible, spacing,\n"
          "orientation, max_rotation_deviation, max_translation_deviation, failing_loops},\n"
          "parallel_rosy: {compatible, max_deviation, failing_loops}, rotation_compensation:\n"
          "{periods, handle_turning_numbers, max_harmonic_residual, max_inconsistency, max_rotation} or\n"
          "trivial_connection: {energy, max_rotation, ...} (with rotation_compensation_failure when\n"
          "it took over from a rotation compensation that failed) or boundary_aligned, edit: {directions,\n"
          "hard_directions, lengths, hard_lengths, max_direction_error, max_length_error,\n"
          "length_range}, prescribed and found:\n"
          "[{vertex, index}] (found: read back from the face field with its matching),\n"
          "generator_turning_numbers, max_rotation_over_pi_over_N, success, timings: {metric_s,\n"
          "compensation_s, edit_s}, hatching: {strokes, total_length}}.\n"
          "The matching (--matching-out, 'i j k' per interior edge as for connection) is the\n"
          "trivial connection's, else the principal one on the metric: these fields turn by less\n"
          "than pi / N per edge relative to the metric's transport. Exit code 3 (JSON printed)\n"
          "when the metric does not converge, the cones are no multiples of 2 pi / N, no parallel\n"
          "field exists, an edit fails, or the read-back differs from the cones. Face vectors are\n"
          "mapped to 3D by the linear map from each metric triangle to the embedded one. When the\n"
          "metric needed edge flips, the field lives on its intrinsic triangulation and reaches the\n"
          "input faces through their common subdivision: correspondence: {intrinsic_edges,\n"
          "crossings, pieces}, input_read_back: {found, max_distortion, mean_distortion} (the face\n"
          "field carried to the input faces, read back there with its carried matching; the\n"
          "files, pictures and edits are on the input mesh).\n",
          run_rosy};
}

} // namespace smdf_cli
