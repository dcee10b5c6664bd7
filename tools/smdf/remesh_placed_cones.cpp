// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "remesh_placed_cones.h"
#include "remesh_measures.h"

#include <CGAL/Surface_mesh_direction_fields/boundary_aligned_field.h>
#include <CGAL/Surface_mesh_direction_fields/compute_trivial_connection.h>
#include <CGAL/Surface_mesh_direction_fields/cone_metric.h>
#include <CGAL/Surface_mesh_direction_fields/integer_grid_map.h>
#include <CGAL/Surface_mesh_direction_fields/intrinsic_geometry.h>
#include <CGAL/Surface_mesh_direction_fields/remeshing_cone_separation.h>
#include <CGAL/Surface_mesh_direction_fields/remeshing_cones.h>
#include <CGAL/Surface_mesh_direction_fields/seamless_cone_moves.h>
#include <CGAL/Surface_mesh_direction_fields/seamless_intrinsic_metric.h>
#include <CGAL/Surface_mesh_direction_fields/seamless_metric.h>
#include <CGAL/Surface_mesh_direction_fields/topology.h>

#include <CGAL/Polygon_mesh_processing/measure.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

namespace smdf_cli {

// The JSON of a conforming Delaunay refinement made because the input's edges could not carry
// a metric (`message`: why not).
Json refinement_json(const std::string& message, const SMDF::Delaunay_refinement_status& rs)
{
  Json r = Json::object();
  r["input_triangulation_message"] = message;
  r["success"] = rs.success;
  r["faces"] = rs.faces;
  r["inserted_vertices"] = rs.inserted.size();
  return r;
}

bool embedding_fits_quads(const Mesh& mesh)
{
  auto k = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
  SMDF::compute_vertex_curvatures(mesh, k);
  for(vertex_descriptor v : vertices(mesh)) {
    const double q = get(k, v) / (CGAL_PI / 2);
    if(std::abs(q - std::round(q)) > 1e-6) return false;
  }
  return true;
}

namespace {

// Makes `surface` and `lengths` the copy of the intrinsic triangulation `it` (of `base`, its
// common subdivision built), kept in `intrinsic` for placing the remesh back on `base`.
void use_intrinsic_triangulation(SMDF::Intrinsic_triangulation&& it, Mesh& base, Intrinsic_surface& intrinsic, Mesh*& surface,
                                 Edge_length_property& lengths, Json& metric)
{
  intrinsic.triangulation = std::move(it);
  CGAL::clear(intrinsic.mesh);
  lengths = intrinsic.mesh.add_property_map<edge_descriptor, double>("e:smdf_remesh_length", 0.).first;
  SMDF::copy_intrinsic_triangulation(intrinsic.triangulation, base, intrinsic.mesh, lengths);
  intrinsic.of = &base;
  surface = &intrinsic.mesh;
  metric["intrinsic_triangulation"] = true;
}

} // namespace

SMDF::Cone_metric_status intrinsic_cone_metric(const std::string& file, Mesh& base, const std::vector<std::pair<vertex_descriptor, double>>& curvatures,
                                               const std::string& without_flips, Intrinsic_surface& intrinsic, Mesh*& surface,
                                               Edge_length_property& lengths, Json& metric)
{
  metric["without_flips_message"] = without_flips;
  metric["intrinsic_triangulation"] = false;
  auto targets = base.add_property_map<vertex_descriptor, double>("v:smdf_remesh_target", 0.).first;
  for(vertex_descriptor v : vertices(base)) targets[v] = 0;
  for(const auto& c : curvatures) targets[c.first] = c.second;
  Edge_length_property flipped = base.add_property_map<edge_descriptor, double>("e:smdf_remesh_flipped_length", 0.).first;
  SMDF::Cone_metric_status cm = on_file(file, [&] { return SMDF::compute_cone_metric(base, targets, flipped); });
  metric["intrinsic_edge_flips"] = cm.edge_flips;
  if(!cm.converged) return cm;
  if(!cm.triangulation_changed) {
    surface = &base;
    lengths = flipped;
    return cm;
  }
  if(!cm.intrinsic_triangulation.has_common_subdivision()) {
    cm.converged = false;
    cm.message = "the metric needed intrinsic flips and its correspondence with the surface failed: " + cm.correspondence_message;
    return cm;
  }
  use_intrinsic_triangulation(std::move(cm.intrinsic_triangulation), base, intrinsic, surface, lengths, metric);
  return cm;
}

namespace {

Edge_length_property cross_field_and_map(const std::string& file, Mesh& on, const std::vector<std::pair<vertex_descriptor, double>>& indices,
                                         double requested_h, long requested_faces, Edge_length_property lengths, Json& out, Json& metric,
                                         const std::function<void(const char*)>& stage, const std::function<void(const char*)>& timed);

// The flat cone metric of the cones `current` (vertices of `base` or of its intrinsic copy, in the
// same order; curvatures in radians) computed on `base` with intrinsic flips, then made seamless
// with flips (seamless_intrinsic_cone_metric()). On success `intrinsic`, `surface` and `lengths`
// become that triangulation and its metric. Returns the JSON of the step.
Json seamless_with_flips(const std::string& file, Mesh& base, const std::vector<std::pair<vertex_descriptor, double>>& current,
                         Intrinsic_surface& intrinsic, Mesh*& surface, Edge_length_property& lengths, Json& metric)
{
  Json j = Json::object();
  auto targets = base.add_property_map<vertex_descriptor, double>("v:smdf_seamless_target", 0.).first;
  auto u = base.add_property_map<vertex_descriptor, double>("v:smdf_seamless_factor", 0.).first;
  auto flow = base.add_property_map<edge_descriptor, double>("e:smdf_seamless_flow", 0.).first;
  for(vertex_descriptor v : vertices(base)) targets[v] = 0;
  for(const auto& c : current) targets[vertex_descriptor(c.first.idx())] = c.second;
  const SMDF::Cone_metric_status cm = on_file(file, [&] {
    return SMDF::compute_cone_metric(base, targets, flow, SMDF::parameters::conformal_factor_map(u).common_subdivision(false));
  });
  j["cone_metric_converged"] = cm.converged;
  if(!cm.converged) {
    j["success"] = false;
    j["message"] = "the flat cone metric with flips: " + cm.message;
  } else {
    SMDF::Seamless_intrinsic_metric_status ss = on_file(file, [&] {
      return SMDF::seamless_intrinsic_cone_metric(base, u, SMDF::parameters::intrinsic_edge_flips(cm.triangulation_changed));
    });
    j["success"] = ss.success;
    j["message"] = ss.message;
    j["iterations"] = ss.iterations;
    j["initial_holonomy_error"] = ss.initial_holonomy_error;
    j["holonomy_error"] = ss.holonomy_error;
    j["curvature_error"] = ss.curvature_error;
    j["cone_metric_flips"] = ss.cone_metric_flips;
    j["edge_flips"] = ss.edge_flips;
    j["min_angle"] = ss.min_angle;
    j["correspondence"] = ss.correspondence_message.empty() ? std::string("common subdivision") : ss.correspondence_message;
    if(ss.success && ss.intrinsic_triangulation.has_common_subdivision())
      use_intrinsic_triangulation(std::move(ss.intrinsic_triangulation), base, intrinsic, surface, lengths, metric);
    else if(ss.success) j["success"] = false;
  }
  base.remove_property_map(flow);
  base.remove_property_map(u);
  base.remove_property_map(targets);
  return j;
}

// One attempt with cones `cone_spacing` grid edges apart where the placement can.
Edge_length_property placed_cones_attempt(const std::string& file, Mesh& mesh, Mesh& refined, Intrinsic_surface& intrinsic, Mesh*& surface, double requested_h,
                                          long requested_faces, double distortion_bound, long max_cones, double cone_spacing, Json& out,
                                          Json& metric, const std::function<void(const char*)>& stage, std::size_t& cones,
                                          std::vector<std::string>& placements, bool& repeated, bool keep_input_faces, bool move_cones,
                                          bool& moved)
{
  Edge_length_property lengths;
  // cones placed for low distortion, their flat cone metric on the input's edges, the cross
  // field of the trivial connection on it, and the integer-grid map (grid units) whose edge
  // lengths are the metric to tessellate
  stage("cone placement");
  // each stage's time, in out["stage_timings"] as soon as it ends (failures keep them too)
  Stopwatch stage_clock;
  out["stage_timings"] = Json::object();
  auto timed = [&](const char* name) { out["stage_timings"][name] = stage_clock.lap(); };
  Edge_length_property placed = mesh.add_property_map<edge_descriptor, double>("e:smdf_placed_length", 0.).first;
  // the grid's edge length on the input, roughly (the metric scales it by e^u, u within the bound)
  const double h_input = requested_h > 0 ? requested_h : std::sqrt(CGAL::Polygon_mesh_processing::area(mesh) / double(requested_faces));
  // interior cones at least one grid edge from the boundary where the placement can (closer, the
  // rounding puts their grid point on the boundary's line or across it and the map folds)
  const double boundary_spacing = (std::max)(cone_spacing, 1.);
  auto ps = on_file(file, [&] {
    return SMDF::place_remeshing_cones(mesh, placed, SMDF::parameters::symmetry_order(4).distortion_bound(distortion_bound)
                                                         .maximum_number_of_cones(int(max_cones))
                                                         .minimum_cone_distance(cone_spacing * h_input)
                                                         .minimum_boundary_distance(boundary_spacing * h_input));
  });
  Json pl = Json::object(), pc = Json::array();
  for(const auto& c : ps.cones) {
    Json o = Json::object();
    o["vertex"] = index(c.first);
    o["curvature"] = c.second;
    pc.push_back(std::move(o));
  }
  // the same cones as a failed attempt's (a mesh with no cone, cones far apart at every spacing)
  // would fail the same way
  std::ostringstream key;
  pc.write(key);
  key << (move_cones ? " moved" : "");
  repeated = std::find(placements.begin(), placements.end(), key.str()) != placements.end();
  placements.push_back(key.str());
  out["placed_cones"] = std::move(pc);
  timed("placement_s");
  cones = ps.cones.size();
  if(repeated) throw Failed_result{out, "the same cones as an earlier attempt", 3};
  pl["success"] = ps.success;
  pl["message"] = ps.message;
  pl["distortion_bound"] = ps.distortion_bound;
  pl["scale_spread"] = ps.scale_spread;
  pl["negative_cone_quanta"] = ps.negative_cone_quanta;
  out["placement"] = std::move(pl);
  metric["source"] = "placed cones";
  if(long(ps.cones.size()) >= max_cones) {
    // the map's dense system has two unknowns per cone and per seam and costs their cube: a
    // genus-133 mesh's 1,208 cones ran over 4 minutes; stop here and say what to change
    const long chi = long(num_vertices(mesh)) - long(num_edges(mesh)) + long(num_faces(mesh));
    out["metric"] = metric;
    out["success"] = false;
    throw Failed_result{out, file + ": the placement took " + std::to_string(ps.cones.size()) + " cones, the maximum (--max-cones " +
                                 std::to_string(max_cones) + ")" + (chi < 0 ? "; this genus needs at least " + std::string(ps.negative_cone_quanta > 1 ? "4|chi|/" + std::to_string(ps.negative_cone_quanta) : "4|chi|") +
                                                        " = " + std::to_string((-4 * chi + ps.negative_cone_quanta - 1) / ps.negative_cone_quanta) : std::string()) +
                                 "; raise --max-cones or --distortion-bound (the integer-grid map's time grows as the cube of its cones and seams)", 3};
  }
  if(!ps.metric.converged) {
    out["metric"] = metric;
    out["success"] = false;
    throw Failed_result{out, file + ": --place-cones: " + ps.message, 3};
  }
  stage("flat cone metric on the input's edges");
  std::vector<std::pair<vertex_descriptor, double>> indices;
  for(const auto& c : ps.cones) indices.emplace_back(c.first, c.second / (2 * CGAL_PI));
  // the metric without flips on a triangulation `on` of the surface (the input, or its
  // conforming Delaunay refinement, which keeps the input's vertex indices)
  auto metric_on = [&](Mesh& on) {
    auto targets = on.add_property_map<vertex_descriptor, double>("v:smdf_remesh_target", 0.).first;
    for(vertex_descriptor v : vertices(on)) targets[v] = 0;   // a second attempt finds the first one's map
    for(const auto& c : indices) targets[c.first] = c.second * 2 * CGAL_PI;
    lengths = on.add_property_map<edge_descriptor, double>("e:smdf_remesh_length", 0.).first;
    return on_file(file, [&] { return SMDF::compute_cone_metric(on, targets, lengths, SMDF::parameters::intrinsic_edge_flips(false)); });
  };
  // the placement's read-back already is this metric when it needed no flip (half a second at
  // 114k faces)
  SMDF::Cone_metric_status cm;
  if(ps.metric.converged && !ps.metric.triangulation_changed) {
    lengths = mesh.add_property_map<edge_descriptor, double>("e:smdf_remesh_length", 0.).first;
    for(edge_descriptor e : edges(mesh)) lengths[e] = placed[e];
    cm = ps.metric;
  } else if(ps.metric.converged && !keep_input_faces && ps.metric.intrinsic_triangulation.has_common_subdivision()) {
    // it needed flips: the map and the grid are made on its intrinsic triangulation and brought
    // back through the common subdivision it already has (a second flow on the Delaunay
    // refinement was 12 s of a 1M-face run)
    use_intrinsic_triangulation(std::move(ps.metric.intrinsic_triangulation), mesh, intrinsic, surface, lengths, metric);
    cm = ps.metric;
    metric["intrinsic_edge_flips"] = cm.edge_flips;
  } else if(ps.metric.converged) {
    // it needed flips: the flow without them stalled on the input's edges, as it would again
    cm.message = "the flat cone metric of the placed cones needs intrinsic flips on the input's edges";
  } else {
    cm = metric_on(mesh);
  }
  if(!cm.converged) {
    stage("flat cone metric on the Delaunay refinement");
    const SMDF::Delaunay_refinement_status rs = on_file(file, [&] { return SMDF::conforming_delaunay_refinement(mesh, refined); });
    metric["delaunay_refinement"] = refinement_json(cm.message, rs);
    if(rs.success) {
      cm = metric_on(refined);
      surface = &refined;
    }
    if(!cm.converged) {
      // with intrinsic flips: the map and the grid are made on that triangulation and brought
      // back through its common subdivision with the surface
      stage("flat cone metric with intrinsic flips");
      std::vector<std::pair<vertex_descriptor, double>> curvatures;
      for(const auto& c : ps.cones) curvatures.emplace_back(c.first, c.second);
      cm = intrinsic_cone_metric(file, rs.success ? refined : mesh, curvatures, cm.message, intrinsic, surface, lengths, metric);
    }
  }
  Mesh& on = *surface;
  timed("cone_metric_s");
  metric["converged"] = cm.converged;
  metric["max_curvature_error"] = cm.max_curvature_error;
  if(!cm.converged) {
    out["metric"] = metric;
    out["success"] = false;
    throw Failed_result{out, file + ": the flat cone metric of the placed cones converges neither on the input's edges, nor on its Delaunay "
                                 "refinement, nor with intrinsic flips: " + cm.message, 3};
  }
  // the cones as they stand (curvatures in radians), their metric computed again on the same
  // triangulation from the current one when they change; not on the Delaunay refinement, where
  // a cone could move to a vertex the input lacks
  std::vector<std::pair<vertex_descriptor, double>> current;
  for(const auto& c : indices) current.emplace_back(c.first, c.second * 2 * CGAL_PI);
  const bool input_vertices = num_vertices(on) == num_vertices(mesh);
  auto metric_again = [&](const std::vector<std::pair<vertex_descriptor, double>>& trial) {
    auto targets = on.add_property_map<vertex_descriptor, double>("v:smdf_moved_target", 0.).first;
    for(vertex_descriptor v : vertices(on)) targets[v] = 0;
    for(const auto& c : trial) targets[c.first] = c.second;
    auto ml = on.add_property_map<edge_descriptor, double>("e:smdf_moved_length", 0.).first;
    const SMDF::Cone_metric_status mc = on_file(file, [&] {
      return SMDF::compute_cone_metric(on, targets, ml, SMDF::parameters::edge_length_map(lengths).intrinsic_edge_flips(false));
    });
    if(mc.converged) {
      current = trial;
      for(edge_descriptor e : edges(on)) lengths[e] = ml[e];
    }
    on.remove_property_map(ml);
    on.remove_property_map(targets);
    return mc.converged;
  };
  bool changed = false;
  // cones at least a grid edge and a half apart under their own metric (the placement keeps them
  // apart on the input, where a region the metric shrinks can hold several within one grid
  // edge: the map then rounds them together and folds); up to 2 rounds, distances measured again
  // under each new metric. Measured on the 28 valid shared meshes of one component, 112 runs at
  // 1,000 to 12,000 quads: 92 valid against 88 without (the feline at 12,000 quads for the first
  // time, the armadillo at 1,000 and 12,000, the casting at 2,500), none lost; at 2.5 grid edges
  // the moved cones crowd others and most maps still fold.
  if(input_vertices) {
    stage("cones separated");
    const double grid_edge = requested_h > 0 ? requested_h : std::sqrt(metric_area(on, lengths) / double(requested_faces));
    Json sj = Json::object();
    int cancelled = 0, separated = 0;
    for(int round = 0; round < 3; ++round) {   // the third only measures
      std::vector<std::pair<vertex_descriptor, double>> trial = current;
      const SMDF::Cone_separation_status ss = SMDF::separate_remeshing_cones(on, lengths, trial, 1.5 * grid_edge);
      if(round == 0) sj["close_cones_before"] = ss.close_cones_before;
      sj["close_cones_after"] = ss.close_cones_before;
      if(round == 2 || ss.cancelled_pairs + ss.moved_cones == 0 || !metric_again(trial)) break;
      cancelled += ss.cancelled_pairs;
      separated += ss.moved_cones;
      changed = true;
    }
    sj["cancelled_pairs"] = cancelled;
    sj["moved_cones"] = separated;
    metric["cone_separation"] = std::move(sj);
    timed("cone_separation_s");
  }
  // metric compensation, rotational part: the handles' holonomies, and the turning between
  // boundary loops, made multiples of pi/2, so that the parallel cross field closes and follows
  // every boundary, and the map can follow the metric exactly
  const SMDF::Mesh_topology<Mesh> on_topology = SMDF::mesh_topology(on);
  moved = false;
  const bool compensate = on_topology.components[0].genus > 0 || on_topology.boundary_loops.size() >= 2;
  if(compensate) {
    // first the interior cones moved a few rings, to first order, so that the holonomies start
    // within the fixed triangulation's reach (up to 3 rounds)
    stage("cones moved toward a seamless metric");
    Json mj = Json::object();
    int total_moves = 0;
    for(int round = 0; round < 3 && move_cones && input_vertices; ++round) {
      std::vector<std::pair<vertex_descriptor, double>> trial = current;
      const SMDF::Cone_moves_status ms = SMDF::move_cones_toward_seamless(on, lengths, trial);
      if(round == 0) mj["initial_holonomy_error"] = ms.initial_holonomy_error;
      mj["holonomy_error"] = ms.initial_holonomy_error;
      if(ms.moves == 0 || !metric_again(trial)) break;
      total_moves += ms.moves;
    }
    mj["moves"] = total_moves;
    metric["cone_moves"] = std::move(mj);
    moved = total_moves > 0;
    changed = changed || moved;
  }
  if(changed) {
    indices.clear();
    Json pc = Json::array();
    for(const auto& c : current) {
      indices.emplace_back(c.first, c.second / (2 * CGAL_PI));
      Json o = Json::object();
      o["vertex"] = index(c.first);
      o["curvature"] = c.second;
      pc.push_back(std::move(o));
    }
    out["placed_cones"] = std::move(pc);
  }
  if(compensate) {
    timed("cone_moves_s");
    stage("seamless metric");
    auto seamless = on.add_property_map<edge_descriptor, double>("e:smdf_remesh_seamless", 0.).first;
    const SMDF::Seamless_metric_status ss = on_file(file, [&] { return SMDF::seamless_cone_metric(on, lengths, seamless); });
    Json sj = Json::object();
    sj["success"] = ss.success;
    sj["message"] = ss.message;
    sj["loops"] = ss.loops;
    sj["iterations"] = ss.iterations;
    sj["initial_holonomy_error"] = ss.initial_holonomy_error;
    sj["holonomy_error"] = ss.holonomy_error;
    sj["max_log_length_change"] = ss.max_log_length_change;
    if(ss.success) for(edge_descriptor e : edges(on)) lengths[e] = seamless[e];
    on.remove_property_map(seamless);
    if(!ss.success) {
      // the fixed triangulation cannot move the holonomies that far: the metric of the current
      // cones on the surface the triangulation was made from, then seamless with intrinsic flips
      stage("seamless metric with intrinsic flips");
      sj["with_flips"] = seamless_with_flips(file, surface == &intrinsic.mesh ? *intrinsic.of : on, current, intrinsic, surface, lengths, metric);
    }
    metric["seamless"] = std::move(sj);
    timed("seamless_metric_s");
  }
  return cross_field_and_map(file, *surface, indices, requested_h, requested_faces, lengths, out, metric, stage, timed);
}

// The cross field of the cones `indices` on `on` under `lengths` (seamless where the topology asks)
// and its integer-grid map; returns the map's edge lengths in grid units.
Edge_length_property cross_field_and_map(const std::string& file, Mesh& on, const std::vector<std::pair<vertex_descriptor, double>>& indices,
                                         double requested_h, long requested_faces, Edge_length_property lengths, Json& out, Json& metric,
                                         const std::function<void(const char*)>& stage, const std::function<void(const char*)>& timed)
{
  stage("cross field and integer-grid map");
  auto adjustment = on.add_property_map<edge_descriptor, double>("e:smdf_remesh_adjustment", 0.).first;
  auto field = on.add_property_map<face_descriptor, double>("f:smdf_remesh_field", 0.).first;
  // closed: the trivial connection with the interior cones as singularities, its turning around
  // the handles the smoothest; open: the field parallel to the boundary (straight between the
  // corners under the metric), compensated around the handles the same way
  bool field_ok = false;
  std::string field_message;
  if(CGAL::is_closed(on)) {
    const SMDF::Trivial_connection_status ts = on_file(file, [&] {
      return SMDF::compute_trivial_connection(on, indices, adjustment, SMDF::parameters::edge_length_map(lengths).symmetry_order(4)
                                                                           .smoothest_generator_turning_numbers(true).face_angle_map(field));
    });
    field_ok = ts.success;
    field_message = ts.message;
  } else {
    auto matching = on.add_property_map<edge_descriptor, int>("e:smdf_remesh_matching", 0).first;
    const SMDF::Boundary_aligned_field_status bs = on_file(file, [&] {
      return SMDF::boundary_aligned_field_of_metric(on, 4, field, matching, SMDF::parameters::edge_length_map(lengths));
    });
    field_ok = bs.success;
    field_message = bs.message;
  }
  if(!field_ok) {
    out["metric"] = metric;
    out["success"] = false;
    throw Failed_result{out, file + ": the cross field of the placed cones failed: " + field_message, 3};
  }
  timed("cross_field_s");
  const double hm = requested_h > 0 ? requested_h : std::sqrt(metric_area(on, lengths) / double(requested_faces));
  auto uv = on.add_property_map<halfedge_descriptor, std::array<double, 2>>("h:smdf_remesh_uv").first;
  const SMDF::Integer_grid_map_status gs = on_file(file, [&] {
    return SMDF::integer_grid_map(on, field, hm, uv, SMDF::parameters::edge_length_map(lengths));
  });
  timed("integer_grid_map_s");
  Json ig = Json::object();
  ig["success"] = gs.success;
  ig["message"] = gs.message;
  ig["singularities"] = gs.singularities.size();
  ig["seams"] = gs.arcs;
  ig["boundary_corners"] = gs.boundary_corners.size();
  ig["boundary_lines"] = gs.boundary_lines;
  ig["rounded_values"] = gs.rounded;
  ig["t_mesh_arcs"] = gs.t_mesh_arcs;
  if(!gs.t_mesh_failure.empty()) ig["t_mesh_failure"] = gs.t_mesh_failure;
  ig["rounded_apart"] = gs.rounded_apart;
  ig["held_arcs"] = gs.held_arcs;
  ig["collapsed_arcs"] = gs.collapsed_arcs;
  ig["negative_arcs"] = gs.negative_arcs;
  ig["t_mesh_spans"] = gs.t_mesh_spans;
  ig["short_spans"] = gs.short_spans;
  ig["t_mesh_faces"] = gs.t_mesh_faces;
  ig["collapsed_faces"] = gs.collapsed_faces;
  ig["arcs_kept"] = gs.arcs_kept;
  ig["folded_triangles"] = gs.folded_triangles;
  ig["winding_faults"] = gs.winding_faults;
  ig["stiffening_rounds"] = gs.stiffening_rounds;
  ig["seamless_energy"] = gs.seamless_energy;
  ig["seamless_folded_triangles"] = gs.seamless_folded_triangles;   // before rounding
  ig["integer_energy"] = gs.integer_energy;
  ig["min_area_ratio"] = gs.min_area_ratio;
  out["integer_grid_map"] = std::move(ig);
  if(!gs.success) {
    out["metric"] = metric;
    out["success"] = false;
    throw Failed_result{out, file + ": integer-grid map: " + gs.message, 3};
  }
  for(edge_descriptor e : edges(on)) {   // the map's lengths, in grid units
    const halfedge_descriptor x = halfedge(e, on);
    const std::array<double, 2> a = uv[prev(x, on)], b = uv[x];
    lengths[e] = std::hypot(b[0] - a[0], b[1] - a[1]);
  }
  return lengths;
}

// The holonomy errors of an attempt's `metric` JSON (radians from the nearest multiple of pi/2, the
// largest over the loops) before and after the cone moves and after the seamless metric, kept in
// its record `a` when it had them (a metric left off its seamless goal folds the map before any
// rounding; one that reached it folds, if at all, in the rounding).
void record_holonomy(const Json& metric, Json& a)
{
  if(const Json* moves = metric.find("cone_moves"))
    if(const Json* e = moves->find("initial_holonomy_error")) {
      a["holonomy_error_before_moves"] = *e;
      a["cone_moves"] = *moves->find("moves");
    }
  if(const Json* s = metric.find("seamless")) {
    a["seamless_holonomy_error"] = *s->find("holonomy_error");
    if(const Json* w = s->find("with_flips")) {   // the fixed triangulation failed; the flips' outcome
      Json r = Json::object();
      for(const char* k : {"success", "holonomy_error", "edge_flips", "message"})
        if(const Json* x = w->find(k)) r[k] = *x;
      a["seamless_with_flips"] = std::move(r);
    }
  }
}

} // namespace

Edge_length_property placed_cones_metric(const std::string& file, Mesh& mesh, Mesh& refined, Intrinsic_surface& intrinsic, Mesh*& surface, double requested_h,
                                         long requested_faces, double distortion_bound, long max_cones, double cone_spacing, Json& out, Json& metric,
                                         const std::function<void(const char*)>& stage,
                                         const std::function<void(Edge_length_property)>& finish, bool keep_input_faces, bool tighten_bound)
{
  const SMDF::Mesh_topology<Mesh> topo = SMDF::mesh_topology(mesh);
  if(topo.components.size() != 1)
    throw Error(file + ": automatic cones need a mesh of one component; this one has " + std::to_string(topo.components.size()) +
                " [invalid_input]");
  // Automatic spacing: cones 4 grid edges apart first, then 2, 0 (only kept apart) and 6, while
  // the map folds or the remesh fails its read-back. Measured on the 28 valid shared meshes of
  // one component at 4,000 and 12,000 quads, one spacing alone: 28 of 56 valid at 0, 33 at 2,
  // 34 at 3, 37 at 4, with 5,330, 4,144, 3,800 and 3,654 cones in all (the armadillo 244 at 0
  // against 50 at 4, the cheburashka 108 against 28): near a cone its metric's log scale is
  // singular, and a spread measured only one input ring away grows with the input's resolution
  // (the bunny at 20,000 quads: 26 cones from 28k faces, 78 from the same shape at 114k; 18 and 18
  // at 4). Trying 2 and 0 next recovers 3 more (the bunny and the camelhead at 4,000 quads valid
  // at 0 or 2 only); 6 unfolded the armadillo at 20,000 quads. Only failing runs pay for retries.
  const std::vector<double> spacings = cone_spacing >= 0 ? std::vector<double>{cone_spacing} : std::vector<double>{4., 2., 0., 6.};
  // then, unless the bound was given, the bound halved and quartered: more cones, the metric
  // stretching less (spacings 4, 2 and 6; 0 packs hundreds of cones). Measured on the 28 failing
  // runs of the 112 (the 28 valid shared meshes of one component at 1,000 to 12,000 quads): 7
  // valid at bound 1 (botijo, bunny, spot and stanford bunny at 1,000, rotor at 4,000, ...), the
  // homer at 2,500 only at 0.5. Each retry is a placement and a map: only failing runs pay.
  struct Attempt { double bound, spacing; bool move; };
  std::vector<Attempt> schedule;
  for(double sp : spacings) for(bool mv : {true, false}) schedule.push_back({distortion_bound, sp, mv});
  if(tighten_bound)
    for(double b : {distortion_bound / 2, distortion_bound / 4})
      for(double sp : cone_spacing >= 0 ? std::vector<double>{cone_spacing} : std::vector<double>{4., 2., 6.}) schedule.push_back({b, sp, true});
  Json attempts = Json::array();
  const Json out_before = out, metric_before = metric;
  std::vector<std::string> placements;
  Failed_result failure{Json(), "", 3};   // the last attempt that ran
  // at each spacing the cones first moved toward a seamless metric (genus > 0 or several boundary
  // loops), then, if that remesh fails, as placed (the stanford bunny at 12,000 quads remeshes
  // only so)
  bool moved = false;
  for(std::size_t k = 0; k < schedule.size(); ++k) {
    const Attempt& at = schedule[k];
    const bool move_cones = at.move;
    if(!move_cones && !moved) continue;   // nothing was moved: the same attempt again
    Json a = Json::object();
    a["distortion_bound"] = at.bound;
    a["cone_spacing"] = at.spacing;
    a["cones_moved"] = move_cones;
    std::size_t cones = 0;
    bool repeated = false;
    moved = false;
    try {
      if(k > 0) { out = out_before; metric = metric_before; }   // nothing of a failed attempt stays but its record
      surface = &mesh;
      CGAL::clear(refined);   // the refinement of a previous attempt, made for other cones
      intrinsic.of = nullptr;
      Edge_length_property l = placed_cones_attempt(file, mesh, refined, intrinsic, surface, requested_h, requested_faces, at.bound, max_cones,
                                                    at.spacing, out, metric, stage, cones, placements, repeated, keep_input_faces, move_cones, moved);
      a["cones"] = cones;
      a["message"] = "";
      a["stage_timings"] = out["stage_timings"];
      record_holonomy(metric, a);
      Json recorded = attempts;
      recorded.push_back(a);
      out["placement_attempts"] = std::move(recorded);   // as it will stand if this attempt's remesh passes
      finish(l);
      return l;
    } catch(Failed_result& f) {
      a["cones"] = cones;
      a["message"] = f.message;
      a["stage_timings"] = f.json["stage_timings"];
      const Json* failed_metric = f.json.find("metric");
      record_holonomy(failed_metric ? *failed_metric : metric, a);
      if(const Json* ig = f.json.find("integer_grid_map")) {   // folds before and after rounding
        a["seamless_folded_triangles"] = *ig->find("seamless_folded_triangles");
        a["folded_triangles"] = *ig->find("folded_triangles");
        a["negative_arcs"] = *ig->find("negative_arcs");
        a["min_area_ratio"] = *ig->find("min_area_ratio");
      }
      attempts.push_back(std::move(a));
      if(!repeated) failure = f;
      stage("the remesh failed: cones placed again");
    }
  }
  failure.json["placement_attempts"] = std::move(attempts);
  throw failure;
}

std::string uv_obj_text(const Mesh& on)
{
  const auto found = on.property_map<halfedge_descriptor, std::array<double, 2>>("h:smdf_remesh_uv");
  if(!found.second) throw Error("no integer-grid map was made [internal]");
  const auto& uv = found.first;
  std::ostringstream os = number_stream();
  os << "# integer-grid map (smdf remesh): a seamless parametrization, grid units; across every seam the two\n"
        "# sides differ by a rotation by a multiple of 90 degrees and an integer translation\n";
  std::vector<std::size_t> index(num_vertices(on), 0);
  std::size_t n = 0;
  for(vertex_descriptor v : vertices(on)) {
    index[std::size_t(v)] = ++n;
    const auto& p = on.point(v);
    os << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  }
  for(face_descriptor f : faces(on))
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, on), on)) os << "vt " << uv[h][0] << ' ' << uv[h][1] << '\n';
  std::size_t t = 0;
  for(face_descriptor f : faces(on)) {
    os << 'f';
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, on), on)) os << ' ' << index[std::size_t(target(h, on))] << '/' << ++t;
    os << '\n';
  }
  return os.str();
}

} // namespace smdf_cli
