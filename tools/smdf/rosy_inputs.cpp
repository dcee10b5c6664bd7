// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// smdf rosy's inputs: see rosy_inputs.h.

#include "rosy_inputs.h"

#include <CGAL/Surface_mesh_direction_fields/curvature_aligned_field.h>
#include <CGAL/Surface_mesh_direction_fields/boundary_aligned_field.h>
#include <CGAL/Surface_mesh_direction_fields/field_singularities.h>
#include <CGAL/Surface_mesh_direction_fields/refinement_field_transfer.h>

#include <CGAL/Surface_mesh_direction_fields/topology.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace smdf_cli {

Boundary_geometry boundary_geometry(const Mesh& mesh)
{
  Boundary_geometry b;
  b.kappa.assign(num_vertices(mesh), 0.);
  b.dual_length.assign(num_vertices(mesh), 0.);
  std::vector<char> done(num_halfedges(mesh), 0);
  for(halfedge_descriptor h : halfedges(mesh)) {
    if(!is_border(h, mesh) || done[std::size_t(h)]) continue;
    std::vector<vertex_descriptor> loop;
    for(halfedge_descriptor g = h; !done[std::size_t(g)]; g = next(g, mesh)) {
      done[std::size_t(g)] = 1;
      loop.push_back(target(g, mesh));
      const double l = std::sqrt(CGAL::squared_distance(mesh.point(source(g, mesh)), mesh.point(target(g, mesh))));
      b.dual_length[index(source(g, mesh))] += l / 2;
      b.dual_length[index(target(g, mesh))] += l / 2;
    }
    b.loops.push_back(std::move(loop));
  }
  for(vertex_descriptor v : vertices(mesh)) {
    if(!is_border(v, mesh)) continue;
    double sum = 0;
    for(halfedge_descriptor h : halfedges_around_target(halfedge(v, mesh), mesh)) {
      if(is_border(h, mesh)) continue;
      const K::Vector_3 a = mesh.point(source(h, mesh)) - mesh.point(v);
      const K::Vector_3 c = mesh.point(target(next(h, mesh), mesh)) - mesh.point(v);
      sum += std::atan2(std::sqrt(CGAL::cross_product(a, c).squared_length()), a * c);
    }
    b.kappa[index(v)] = CGAL_PI - sum;
  }
  return b;
}

void open_mesh_targets(const Mesh& mesh, const Boundary_geometry& b, int N, Boundary_mode mode,
                       const std::vector<std::pair<vertex_descriptor, double>>& cones, Vertex_double_property targets)
{
  std::vector<char> fixed(num_vertices(mesh), 0);
  double fixed_total = 0;
  for(const auto& c : cones) { fixed[index(c.first)] = 1; fixed_total += c.second; targets[c.first] = c.second; }
  const double chi = double(SMDF::mesh_topology(mesh).euler_characteristic());
  const double required = 2 * CGAL_PI * chi - fixed_total;   // over the free boundary vertices
  const double step = mode == FREE_BOUNDARY ? 2 * CGAL_PI / N : (N % 2 ? CGAL_PI / N : 2 * CGAL_PI / N);
  std::vector<vertex_descriptor> free_vertices;
  for(const auto& loop : b.loops) for(vertex_descriptor v : loop) if(!fixed[index(v)]) free_vertices.push_back(v);
  if(free_vertices.empty()) {
    if(std::abs(required) > 1e-9)
      throw Error("the cones sum to " + format_real(fixed_total) + " with every boundary vertex given; Gauss-Bonnet needs 2 pi chi = " +
                  format_real(2 * CGAL_PI * chi) + " [inconsistent_indices]");
    return;
  }
  if(mode == FREE_BOUNDARY) {
    // per loop: the input total over its free vertices, rounded to a multiple of the step with
    // the loop's fixed part; the rounding error of the sum goes to the longest loop
    std::vector<double> have(b.loops.size(), 0.), fixed_part(b.loops.size(), 0.), want(b.loops.size(), 0.), length(b.loops.size(), 0.);
    std::size_t longest = 0;
    for(std::size_t l = 0; l < b.loops.size(); ++l) {
      for(vertex_descriptor v : b.loops[l]) {
        (fixed[index(v)] ? fixed_part[l] : have[l]) += fixed[index(v)] ? targets[v] : b.kappa[index(v)];
        if(!fixed[index(v)]) length[l] += b.dual_length[index(v)];
      }
      want[l] = step * std::round((have[l] + fixed_part[l]) / step) - fixed_part[l];
      if(length[l] > length[longest]) longest = l;
    }
    double sum = 0;
    for(double w : want) sum += w;
    want[longest] += required - sum;
    for(std::size_t l = 0; l < b.loops.size(); ++l) {
      if(length[l] <= 0) continue;
      for(vertex_descriptor v : b.loops[l])
        if(!fixed[index(v)]) targets[v] = b.kappa[index(v)] + (want[l] - have[l]) * b.dual_length[index(v)] / length[l];
    }
  } else {
    double sum = 0;
    // the nearest multiple of the step inside (-pi, pi): a turning that rounds to +-pi takes the
    // multiple on its side of it, and Gauss-Bonnet is then restored by the moves below
    for(vertex_descriptor v : free_vertices) {
      double t = step * std::round(b.kappa[index(v)] / step);
      while(t > CGAL_PI - 1e-9) t -= step;
      while(t < -CGAL_PI + 1e-9) t += step;
      targets[v] = t;
      sum += t;
    }
    long moves = std::lround((required - sum) / step);
    while(moves != 0) {
      const double dir = moves > 0 ? 1. : -1.;
      vertex_descriptor best = free_vertices.front();
      double best_cut = -1e300;
      for(vertex_descriptor v : free_vertices) {
        const double next = targets[v] + dir * step;
        if(!(next < CGAL_PI - 1e-9 && next > -CGAL_PI + 1e-9)) continue;
        const double cut = dir * (b.kappa[index(v)] - targets[v]);
        if(cut > best_cut) { best_cut = cut; best = v; }
      }
      if(best_cut == -1e300)
      {
        double largest = 0;   // the largest multiple of the step strictly below pi
        while(largest + step < CGAL_PI - 1e-9) largest += step;
        throw Error("no boundary turning angles that are multiples of " + format_real(step) + " strictly between -pi and pi satisfy "
                    "Gauss-Bonnet: the " + std::to_string(free_vertices.size()) + " free boundary vertices must turn by " +
                    format_real(required) + " in all (2 pi chi = " + format_real(2 * CGAL_PI * chi) + " minus the cones' " +
                    format_real(fixed_total) + "), at most " + format_real(largest * double(free_vertices.size())) +
                    " in absolute value; give the corners with --cones, or interior cones whose indices sum to chi minus the "
                    "boundary's turning over 2 pi");
      }
      targets[best] += dir * step;
      moves -= long(dir);
    }
    // odd N (steps of pi / N): a loop that turns by an odd multiple of pi / N would carry the
    // field to its opposite, no N-RoSy field; such loops come in pairs (the total is a multiple
    // of 2 pi / N) and each pair trades one step, where the rounding cut least
    if(N % 2 == 1) {
      std::vector<std::size_t> odd;
      for(std::size_t l = 0; l < b.loops.size(); ++l) {
        double total = 0;
        for(vertex_descriptor v : b.loops[l]) total += targets[v];
        if(std::lround(total / step) % 2 != 0) odd.push_back(l);
      }
      for(std::size_t i = 0; i + 1 < odd.size(); i += 2) {
        for(int k = 0; k < 2; ++k) {
          const double dir = k == 0 ? 1. : -1.;
          vertex_descriptor best = vertex_descriptor();
          double best_cut = -1e300;
          for(vertex_descriptor v : b.loops[odd[i + std::size_t(k)]]) {
            if(fixed[index(v)]) continue;
            const double next = targets[v] + dir * step;
            if(!(next < CGAL_PI - 1e-9 && next > -CGAL_PI + 1e-9)) continue;
            const double cut = dir * (b.kappa[index(v)] - targets[v]);
            if(cut > best_cut) { best_cut = cut; best = v; }
          }
          if(best_cut == -1e300)
            throw Error("boundary loop " + std::to_string(odd[i + std::size_t(k)]) + " turns by an odd multiple of pi / " + std::to_string(N) +
                        " and none of its vertices can turn by one step more: give its corners with --cones");
          targets[best] += dir * step;
        }
      }
      if(odd.size() % 2)
        throw Error("one boundary loop turns by an odd multiple of pi / " + std::to_string(N) + ": give the corners with --cones");
    }
  }
  for(vertex_descriptor v : free_vertices)
    if(!(targets[v] < CGAL_PI && targets[v] > -CGAL_PI))
      throw Error("boundary vertex " + std::to_string(index(v)) + " would have to turn by " + format_real(targets[v]) +
                  " (not in (-pi, pi)); give the boundary's turning angles with --cones");
}

std::vector<std::pair<std::size_t, double>> border_points_to_insert(const Mesh& original, const Mesh& mesh,
                                                                    const SMDF::Delaunay_refinement_status* refinement,
                                                                    const SMDF::Cone_metric_status& cm, const Edge_length_property& lengths)
{
  // border edges (as vertex pairs of `mesh`) whose apex angle exceeds 0.8 pi: the degenerating triangles
  std::vector<std::pair<std::size_t, std::size_t>> wide;
  auto apex_wide = [](double c, double a, double b) { return (a * a + b * b - c * c) / (2 * a * b) < std::cos(0.8 * CGAL_PI); };
  if(cm.triangulation_changed) {
    const SMDF::Intrinsic_triangulation& t = cm.intrinsic_triangulation;
    for(std::size_t f = 0; f < t.number_of_faces(); ++f)
      for(int k = 0, h = t.halfedge(int(f)); k < 3; ++k, h = t.next(h)) {
        if(t.face(h ^ 1) >= 0) continue;
        if(apex_wide(t.length(h >> 1), t.length(t.next(h) >> 1), t.length(t.next(t.next(h)) >> 1)))
          wide.emplace_back(std::size_t(t.source(h)), std::size_t(t.target(h)));
      }
  } else {
    for(halfedge_descriptor h : halfedges(mesh)) {
      if(is_border(h, mesh) || !is_border(opposite(h, mesh), mesh)) continue;
      if(apex_wide(lengths[edge(h, mesh)], lengths[edge(next(h, mesh), mesh)], lengths[edge(prev(h, mesh), mesh)]))
        wide.emplace_back(index(source(h, mesh)), index(target(h, mesh)));
    }
  }
  // on the edges of the original mesh: a new vertex knows its edge and parameter
  const std::size_t nv = num_vertices(original);
  std::vector<std::pair<std::size_t, double>> points;
  for(const auto& w : wide) {
    std::size_t e = 0;
    if(w.first >= nv) e = refinement->inserted[w.first - nv].first;
    else if(w.second >= nv) e = refinement->inserted[w.second - nv].first;
    else {
      const auto h = halfedge(vertex_descriptor(std::uint32_t(w.first)), vertex_descriptor(std::uint32_t(w.second)), original);
      if(!h.second) continue;
      e = edge(h.first, original).idx();
    }
    const halfedge_descriptor h = halfedge(edge_descriptor(std::uint32_t(e)), original);
    auto param = [&](std::size_t v) {
      return v >= nv ? refinement->inserted[v - nv].second : index(source(h, original)) == v ? 0. : 1.;
    };
    points.emplace_back(e, 0.5 * (param(w.first) + param(w.second)));
  }
  return points;
}

bool refine_boundary_until_converged(const std::string& file, Mesh& mesh, Vertex_double_property& targets, Edge_length_property& lengths,
                                     SMDF::Cone_metric_status& cm, Boundary_refinement& r)
{
  std::vector<std::pair<std::size_t, double>> points;
  double error = HUGE_VAL;   // each round must halve the stalled flow's error
  for(int round = 0; !cm.converged && round < 6 && cm.max_curvature_error < 0.5 * error; ++round) {
    error = cm.max_curvature_error;
    const auto more = border_points_to_insert(r.rounds ? r.original : mesh, mesh, r.rounds ? &r.status : nullptr, cm, lengths);
    if(more.empty()) break;
    if(r.rounds == 0) r.original = mesh;
    points.insert(points.end(), more.begin(), more.end());
    Mesh refined;
    r.status = on_file(file, [&] { return SMDF::refine_at_edge_points(r.original, points, refined); });
    if(!r.status.success) throw Error(file + ": the boundary refinement failed: " + r.status.message);
    ++r.rounds;
    const Vertex_double_property original_targets = r.original.property_map<vertex_descriptor, double>("v:smdf_rosy_target").first;
    mesh = std::move(refined);
    targets = mesh.add_property_map<vertex_descriptor, double>("v:smdf_rosy_target", 0.).first;   // new vertices: straight
    for(vertex_descriptor v : vertices(r.original)) targets[v] = original_targets[v];
    lengths = mesh.add_property_map<edge_descriptor, double>("e:smdf_rosy_length", 0.).first;
    cm = on_file(file, [&] { return SMDF::compute_cone_metric(mesh, targets, lengths); });
  }
  return r.rounds > 0;
}

Json holonomy_loops_json(const SMDF::Homotopy_basis<Mesh>& basis, const SMDF::Holonomy_group& group, const SMDF::Rosy_compatibility& rc)
{
  std::vector<char> failing(basis.loops.size(), 0);
  for(std::size_t i : rc.failing_loops) failing[i] = 1;
  Json loops = Json::array();
  for(std::size_t i = 0; i < basis.loops.size(); ++i) {
    const SMDF::Homotopy_loop_kind k = basis.loops[i].kind;
    Json l = Json::object();
    l["kind"] = k == SMDF::HANDLE_LOOP ? "handle" : k == SMDF::BOUNDARY_LOOP ? "boundary" : "cone";
    if(k == SMDF::CONE_LOOP) l["cone"] = index(basis.loops[i].cone);
    l["rotation_over_pi"] = group.rotations[i] / CGAL_PI;
    l["translation"] = Json::pair(group.motions[i].translation.x(), group.motions[i].translation.y());
    l["compatible"] = !failing[i];
    loops.push_back(std::move(l));
  }
  return loops;
}

std::string bring_back_to_input(const Refinement_chain& chain, Face_field& field, int N,
                                const std::vector<std::pair<vertex_descriptor, double>>& cones, bool aligned, bool orthogonal,
                                const std::string& what, Json& json)
{
  double distortion = 0;
  for(auto step = chain.rbegin(); step != chain.rend(); ++step) {
    Mesh& coarse = *step->first;
    const Face_field on_coarse{&coarse, coarse.add_property_map<face_descriptor, double>("f:smdf_coarse_angle", 0.).first,
                               coarse.add_property_map<edge_descriptor, int>("e:smdf_coarse_matching", 0).first};
    const SMDF::Field_transfer_status ts = SMDF::transfer_face_field_from_refinement(
        *field.mesh, coarse, *step->second, N, field.angles, field.matching, on_coarse.angles, on_coarse.matching);
    if(!ts.success) return "the field could not be brought back from " + what + " to the input faces: " + ts.message;
    distortion = (std::max)(distortion, ts.max_distortion);
    field = on_coarse;
  }
  const SMDF::Field_topology<Mesh> back =
      SMDF::field_singularities(*field.mesh, field.angles, SMDF::parameters::symmetry_order(N).matching(field.matching));
  json["found"] = found_list(back);
  json["max_distortion"] = distortion;
  if(std::map<vertex_descriptor, double>(back.singularities.begin(), back.singularities.end()) != prescribed_indices(*field.mesh, cones, N))
    return "the field on the input faces (brought back from " + what + ") reads back other singularities than the cones";
  if(aligned) {
    const double worst = SMDF::max_boundary_deviation(*field.mesh, N, field.angles, SMDF::parameters::orthogonal_to_boundary(orthogonal));
    json["max_boundary_deviation"] = worst;
    if(!(worst <= 1e-6))
      return "the field on the input faces (brought back from " + what + ") does not follow the boundary (deviation " +
             format_real(worst) + " rad)";
  }
  return std::string();
}

std::vector<std::pair<vertex_descriptor, double>> automatic_cones(const Args& args, const std::string& file, const Mesh& mesh,
                                                                  int N, Boundary_mode mode, Json& json)
{
  double weight = 0.01;
  if(args.has("alignment-weight")) {
    char* end = nullptr;
    const std::string w = args.value("alignment-weight");
    weight = std::strtod(w.c_str(), &end);
    if(*end != '\0' || !(weight > 0) || !std::isfinite(weight))
      throw Usage_error("option --alignment-weight expects a positive number, got '" + shorten(w) + "'");
  }
  long steps = 4;
  if(args.has("smoothing-steps")) {
    char* end = nullptr;
    const std::string w = args.value("smoothing-steps");
    steps = std::strtol(w.c_str(), &end, 10);
    if(*end != '\0' || w.empty() || steps < 0 || steps > 1000)
      throw Usage_error("option --smoothing-steps expects an integer from 0 to 1000, got '" + shorten(w) + "'");
  }
  const auto st = on_file(file, [&] {
    return SMDF::automatic_singularities(mesh, N, SMDF::parameters::alignment_weight(weight).smoothing_steps(int(steps))
                                                      .follow_boundary(mode != FREE_BOUNDARY)
                                                      .orthogonal_to_boundary(mode == ORTHOGONAL_BOUNDARY));
  });
  if(!st.success) throw Error(file + ": the curvature-aligned field failed: " + st.message);
  json = Json::object();
  json["N"] = N;
  json["alignment_weight"] = weight;
  json["smoothing_steps"] = steps;
  json["singularities"] = st.singularities.size();
  json["max_rotation_over_pi_over_N"] = st.max_rotation_over_pi_over_N;
  std::vector<std::pair<vertex_descriptor, double>> c;
  for(const auto& x : st.singularities) c.emplace_back(x.first, 2 * CGAL_PI * x.second);
  return c;
}

std::map<vertex_descriptor, double> prescribed_indices(const Mesh& mesh, const std::vector<std::pair<vertex_descriptor, double>>& cones,
                                                       int N)
{
  std::map<vertex_descriptor, double> want;
  for(const auto& c : cones) {
    const double k = std::round(c.second / (2 * CGAL_PI) * N) / N;
    if(!is_border(c.first, mesh) && k != 0) want[c.first] = k;
  }
  return want;
}

const char* method_name(Rosy_method m)
{
  switch(m) {
    case ROTATION_COMPENSATION: return "rotation-compensation";
    case TRIVIAL_CONNECTION: return "trivial-connection";
    case PARALLEL: return "parallel";
    case BOUNDARY_ALIGNED: return "boundary-aligned";
    default: return "automatic";
  }
}

Rosy_options rosy_options(const Args& args)
{
  Rosy_options o;
  if(args.has("N")) o.N = symmetry_order_option(args);
  if(args.has("method")) {
    const std::string m = args.value("method");
    if(m == "rotation-compensation") o.method = ROTATION_COMPENSATION;
    else if(m == "trivial-connection") o.method = TRIVIAL_CONNECTION;
    else if(m == "parallel") o.method = PARALLEL;
    else throw Usage_error("option --method expects rotation-compensation, trivial-connection or parallel, got '" + shorten(m) + "'");
  }
  if(args.has("boundary")) {
    o.boundary_given = true;
    const std::string b = args.value("boundary");
    if(b == "free") o.boundary = FREE_BOUNDARY;
    else if(b == "parallel") o.boundary = PARALLEL_BOUNDARY;
    else if(b == "orthogonal") o.boundary = ORTHOGONAL_BOUNDARY;
    else throw Usage_error("option --boundary expects free, parallel or orthogonal, got '" + shorten(b) + "'");
  }
  o.turning = index_list_option(args, "turning");
  if(o.boundary != FREE_BOUNDARY && (o.method == ROTATION_COMPENSATION || o.method == TRIVIAL_CONNECTION))
    throw Usage_error(std::string("--boundary ") + args.value("boundary") + " builds the field that follows the boundary; it takes no --method " +
                      method_name(o.method));
  if(o.method == PARALLEL && !o.turning.empty())
    throw Usage_error("--turning needs --method rotation-compensation or trivial-connection (a parallel field has no choice)");
  return o;
}

void turn_generators_least(SMDF::Trivial_connection<Mesh>& tc, int N)
{
  for(std::size_t g = 0; g < tc.generators().size(); ++g)
    tc.set_generator_turning_number(g, std::round(tc.generator_levi_civita_holonomy(g) / (2 * CGAL_PI) * N) / N);
}

Json trivial_connection_json(const SMDF::Trivial_connection_status& ts)
{
  Json t = Json::object();
  t["energy"] = ts.energy;
  t["max_rotation"] = ts.max_rotation;
  t["max_holonomy_error"] = ts.max_holonomy_error;
  t["scaled_residual"] = ts.scaled_residual;
  return t;
}

Json metric_json(const SMDF::Cone_metric_status& cm, const char* on)
{
  Json metric = Json::object();
  metric["converged"] = cm.converged;
  metric["iterations"] = cm.iterations;
  metric["max_curvature_error"] = cm.max_curvature_error;
  metric["triangulation_changed"] = cm.triangulation_changed;
  if(on) metric["on"] = on;
  return metric;
}

Constraint_lines read_constraint_file(const std::string& file, const Mesh& mesh, bool lengths)
{
  Constraint_lines c;
  const std::size_t values = lengths ? 1 : 3;
  std::vector<char> seen(num_vertices(mesh), 0);
  for_each_data_line(file, [&](std::size_t line, const std::vector<std::string>& f) {
    if(f.size() != 1 + values && f.size() != 2 + values)
      throw line_error(file, line, lengths ? "expected 'vertex length [weight]'" : "expected 'vertex x y z [weight]'");
    const std::size_t v = vertex_field(file, line, f[0], num_vertices(mesh));
    if(seen[v]++) throw line_error(file, line, "vertex " + std::to_string(v) + " is constrained twice");
    double x[3] = {0, 0, 0};
    for(std::size_t i = 0; i < values; ++i) x[i] = finite_field(file, line, f[1 + i]);
    const double w = f.size() == 2 + values ? finite_field(file, line, f[1 + values]) : 0.;
    if(f.size() == 2 + values && !(w > 0)) throw line_error(file, line, "the weight must be positive (no weight: a hard constraint)");
    c.weights.push_back(w);
    const vertex_descriptor vd(static_cast<Mesh::size_type>(v));
    if(lengths) {
      if(!(x[0] > 0)) throw line_error(file, line, "the length must be positive");
      c.lengths.emplace_back(vd, x[0]);
    } else {
      if(x[0] == 0 && x[1] == 0 && x[2] == 0) throw line_error(file, line, "the direction is the zero vector");
      c.directions.emplace_back(vd, K::Vector_3(x[0], x[1], x[2]));
    }
  });
  return c;
}

} // namespace smdf_cli
