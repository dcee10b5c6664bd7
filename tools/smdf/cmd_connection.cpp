// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// smdf connection: trivial connection with prescribed singularities and its N-RoSy field.

#include "commands.h"
#include "common.h"

#include <CGAL/Surface_mesh_direction_fields/cone_metric.h>
#include <CGAL/Surface_mesh_direction_fields/field_transfer.h>
#include <CGAL/Surface_mesh_direction_fields/parallel_rosy_field.h>

#include <CGAL/Surface_mesh_direction_fields/field_singularities.h>
#include <CGAL/Surface_mesh_direction_fields/parameters.h>
#include <CGAL/Surface_mesh_direction_fields/Trivial_connection.h>

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <utility>
#include <vector>

namespace smdf_cli {

namespace {

// The options of `connection` that do not need the mesh, checked before it is read.
struct Connection_options
{
  long N;
  std::string weights_name;
  SMDF::Connection_weights weights;
  long edits;
  SMDF::Svg_options svg;
  Indexed_values singularities, turning;
  bool smoothest = false;   // --generator-turning smoothest
  double rotation_limit = 0.8 * M_PI;
};

Connection_options connection_options(const Args& args)
{
  Connection_options o;
  o.N = symmetry_order_option(args);
  o.weights_name = args.value("weights", "unit");
  if(o.weights_name == "cotan") o.weights = SMDF::COTAN_WEIGHTS;
  else if(o.weights_name == "unit") o.weights = SMDF::UNIT_WEIGHTS;
  else if(o.weights_name == "nonnegative-cotan") o.weights = SMDF::NONNEGATIVE_COTAN_WEIGHTS;
  else if(o.weights_name == "bounded-cotan") o.weights = SMDF::BOUNDED_COTAN_WEIGHTS;
  else
    throw Usage_error("option --weights expects 'unit', 'cotan', 'nonnegative-cotan' or 'bounded-cotan', got '" +
                      shorten(o.weights_name) + "'");
  if(args.has("rotation-limit")) {
    const std::string v = args.value("rotation-limit");
    if(v == "off") o.rotation_limit = 0;
    else if(!parse_angle(v, o.rotation_limit) || !(o.rotation_limit > 0))
      throw Usage_error("option --rotation-limit expects a positive angle (radians, or e.g. 0.8pi) or 'off', got '" + shorten(v) + "'");
  }
  o.edits = args.integer("edit-benchmark", 0);
  if(o.edits < 0) throw Usage_error("option --edit-benchmark expects a non-negative integer");
  o.svg = svg_options(args);
  o.singularities = index_list_option(args, "singularities");
  o.smoothest = args.has("generator-turning") && args.value("generator-turning") == "smoothest";
  if(!o.smoothest) o.turning = index_list_option(args, "generator-turning");
  return o;
}

// Angle of the projection of (x, y, z) on the plane of f, in the frame of vectors_to_face_angles().
bool direction_angle(const Mesh& mesh, face_descriptor f, const double v[3], double& angle)
{
  const halfedge_descriptor h = halfedge(f, mesh);
  const K::Point_3& p0 = mesh.point(source(h, mesh));
  const K::Point_3& p1 = mesh.point(target(h, mesh));
  const K::Point_3& p2 = mesh.point(target(next(h, mesh), mesh));
  const double e1[3] = {p1.x() - p0.x(), p1.y() - p0.y(), p1.z() - p0.z()};
  const double e2[3] = {p2.x() - p0.x(), p2.y() - p0.y(), p2.z() - p0.z()};
  const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
  const double b[3] = {n[1] * e1[2] - n[2] * e1[1], n[2] * e1[0] - n[0] * e1[2], n[0] * e1[1] - n[1] * e1[0]};
  const double le = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
  const double lb = std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
  if(!(le > 0) || !(lb > 0)) return false;
  const double x = (v[0] * e1[0] + v[1] * e1[1] + v[2] * e1[2]) / le;
  const double y = (v[0] * b[0] + v[1] * b[1] + v[2] * b[2]) / lb;
  const double norm = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if(!(std::hypot(x, y) > 1e-12 * norm)) return false;   // normal to the face
  angle = std::atan2(y, x);
  if(angle < 0) angle += 2 * CGAL_PI;
  return true;
}

// --factors FILE: one conformal factor per vertex (a line 'u', or 'v u'), as cone-metric
// --factors-out writes them.
std::vector<double> read_factors(const std::string& file, const Mesh& mesh)
{
  const std::size_t nv = num_vertices(mesh);
  std::vector<double> u(nv, 0.);
  std::vector<std::size_t> given(nv, 0);
  std::size_t next = 0;
  for_each_data_line(file, [&](std::size_t line_no, const std::vector<std::string>& tok) {
    if(tok.size() != 1 && tok.size() != 2)
      throw line_error(file, line_no, "expected 'u' or 'vertex u', got " + std::to_string(tok.size()) + " fields");
    std::size_t v = next;
    if(tok.size() == 2) v = vertex_field(file, line_no, tok[0], nv);
    else if(v >= nv) throw line_error(file, line_no, "more factors than the mesh's " + std::to_string(nv) + " vertices");
    if(given[v]) throw line_error(file, line_no, "vertex " + std::to_string(v) + " was already given on line " + std::to_string(given[v]));
    given[v] = line_no;
    u[v] = finite_field(file, line_no, tok.back());
    next = v + 1;
  });
  const std::size_t missing = std::size_t(std::count(given.begin(), given.end(), std::size_t(0)));
  if(missing > 0)
    throw file_error(file, std::to_string(missing) + " of " + std::to_string(nv) + " vertices have no conformal factor", "file_error");
  return u;
}

// --lengths FILE whose lines name pairs of vertices that no input edge joins: the intrinsic
// triangulation of a discrete conformal metric (cone-metric --lengths-out after flips). Its
// conformal factors follow from the edges it shares with the input, l = exp((u_i + u_j) / 2) L
// (least squares over them); the triangulation is rebuilt from the factors with its common
// subdivision, and every line of the file is checked against it (relative 1e-8). Returns an
// empty triangulation when every line is an input edge (the plain --lengths route).
SMDF::Intrinsic_triangulation intrinsic_lengths(const std::string& file, Mesh& mesh)
{
  struct Line { std::size_t i, j, line_no; double l; };
  std::vector<Line> lines;
  const std::size_t nv = num_vertices(mesh);
  bool all_input = true;
  for_each_data_line(file, [&](std::size_t line_no, const std::vector<std::string>& tok) {
    if(tok.size() != 3) throw line_error(file, line_no, "expected 'i j length', got " + std::to_string(tok.size()) + " fields");
    Line x{vertex_field(file, line_no, tok[0], nv), vertex_field(file, line_no, tok[1], nv), line_no, finite_field(file, line_no, tok[2])};
    if(!(x.l > 0)) throw line_error(file, line_no, "the length must be positive, got " + tok[2]);
    if(x.i == x.j) throw line_error(file, line_no, "an edge from vertex " + tok[0] + " to itself");
    all_input = all_input && halfedge(vertex_descriptor(Mesh::size_type(x.i)), vertex_descriptor(Mesh::size_type(x.j)), mesh).second;
    lines.push_back(x);
  });
  if(all_input) return SMDF::Intrinsic_triangulation();
  // the factors: least squares over the lines on input edges (normal equations, the signless
  // Laplacian of those edges; a vertex on none of them has no factor)
  std::vector<Eigen::Triplet<double>> t;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(Eigen::Index(nv));
  std::vector<char> covered(nv, 0);
  for(const Line& x : lines) {
    const auto h = halfedge(vertex_descriptor(Mesh::size_type(x.i)), vertex_descriptor(Mesh::size_type(x.j)), mesh);
    if(!h.second) continue;
    const double L = std::sqrt(CGAL::squared_distance(mesh.point(source(h.first, mesh)), mesh.point(target(h.first, mesh))));
    const double b = 2 * std::log(x.l / L);
    for(std::size_t a : {x.i, x.j}) { t.emplace_back(Eigen::Index(a), Eigen::Index(a), 1.); rhs[Eigen::Index(a)] += b; covered[a] = 1; }
    t.emplace_back(Eigen::Index(x.i), Eigen::Index(x.j), 1.);
    t.emplace_back(Eigen::Index(x.j), Eigen::Index(x.i), 1.);
  }
  for(vertex_descriptor v : vertices(mesh))
    if(!covered[v.idx()] && !mesh.is_isolated(v))
      throw file_error(file, "vertex " + std::to_string(v.idx()) + " is on no input edge of the file: its conformal factor is unknown "
                             "(use --factors)", "file_error");
  for(std::size_t v = 0; v < nv; ++v) if(!covered[v]) t.emplace_back(Eigen::Index(v), Eigen::Index(v), 1.);
  Eigen::SparseMatrix<double> A{Eigen::Index(nv), Eigen::Index(nv)};
  A.setFromTriplets(t.begin(), t.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(A);
  const Eigen::VectorXd u = ldlt.solve(rhs);
  if(ldlt.info() != Eigen::Success || !u.allFinite())
    throw file_error(file, "the lengths of the input edges in the file determine no conformal factors", "file_error");
  auto factors = mesh.add_property_map<vertex_descriptor, double>("v:smdf_factor", 0.).first;
  for(vertex_descriptor v : vertices(mesh)) factors[v] = u[Eigen::Index(v.idx())];
  SMDF::Intrinsic_triangulation itri = on_file(file, [&] { return SMDF::conformal_intrinsic_triangulation(mesh, factors); });
  // every line an edge of the rebuilt triangulation with its length, and every edge a line
  std::map<std::pair<std::size_t, std::size_t>, std::vector<double>> rebuilt;
  for(std::size_t e = 0; e < itri.number_of_edges(); ++e) {
    const std::size_t a = std::size_t(itri.source(int(2 * e))), b = std::size_t(itri.target(int(2 * e)));
    rebuilt[{(std::min)(a, b), (std::max)(a, b)}].push_back(itri.length(int(e)));
  }
  for(const Line& x : lines) {
    auto it = rebuilt.find({(std::min)(x.i, x.j), (std::max)(x.i, x.j)});
    std::size_t best = 0;
    double err = 1e300;
    if(it != rebuilt.end())
      for(std::size_t k = 0; k < it->second.size(); ++k) {
        const double d = std::abs(it->second[k] - x.l) / x.l;
        if(d < err) { err = d; best = k; }
      }
    if(!(err <= 1e-8))
      throw line_error(file, x.line_no, it == rebuilt.end()
          ? "edge (" + std::to_string(x.i) + ", " + std::to_string(x.j) + ") is not in the intrinsic Delaunay triangulation of the "
            "conformal metric these lengths define (are they a discrete conformal metric of the mesh, e.g. cone-metric --lengths-out?)"
          : "edge (" + std::to_string(x.i) + ", " + std::to_string(x.j) + ") has length " + std::to_string(x.l) +
            " but the conformal metric of the input edges gives it " + std::to_string(it->second[best]) + " (relative error " +
            std::to_string(err) + ")");
    it->second.erase(it->second.begin() + long(best));
  }
  if(lines.size() != itri.number_of_edges())
    throw file_error(file, std::to_string(lines.size()) + " lengths for a triangulation of " + std::to_string(itri.number_of_edges()) +
                           " edges", "file_error");
  return itri;
}

// --constraints FILE: lines 'face angle' (radians in the face frame) or 'face x y z' (a 3D
// direction, projected on the face plane).
std::vector<std::pair<face_descriptor, double>> read_constraints(const std::string& cf, const Mesh& mesh)
{
  std::vector<std::pair<face_descriptor, double>> constraints;
  const std::size_t nf = num_faces(mesh);
  std::vector<std::size_t> seen(nf, 0);
  for_each_data_line(cf, [&](std::size_t line_no, const std::vector<std::string>& tok) {
    if(tok.size() != 2 && tok.size() != 4)
      throw line_error(cf, line_no, "expected 'face angle' or 'face x y z', got " + std::to_string(tok.size()) + " fields");
    const std::size_t fi = face_field(cf, line_no, tok[0], nf);
    if(seen[fi]) throw line_error(cf, line_no, "face " + tok[0] + " was already constrained on line " + std::to_string(seen[fi]));
    seen[fi] = line_no;
    double v[3];
    for(std::size_t k = 1; k < tok.size(); ++k) v[k - 1] = finite_field(cf, line_no, tok[k]);
    const face_descriptor f = face_descriptor(Mesh::size_type(fi));
    double angle = v[0];
    if(tok.size() == 4 && !direction_angle(mesh, f, v, angle))
      throw line_error(cf, line_no, "the direction of face " + tok[0] + " has no component in the face plane");
    constraints.push_back(std::make_pair(f, angle));
  });
  return constraints;
}

// --connection-out FILE: 'i j angle' per interior edge, i j the vertices of halfedge(e).
void write_connection(const std::string& file, const Mesh& mesh, const SMDF::Trivial_connection<Mesh>& tc)
{
  std::ostringstream os = number_stream();
  for(edge_descriptor e : edges(mesh)) {
    if(is_border(e, mesh)) continue;
    const halfedge_descriptor h = halfedge(e, mesh);
    os << index(source(h, mesh)) << ' ' << index(target(h, mesh)) << ' ' << tc.adjustment_angle(h) << '\n';
  }
  write_lines_file(file, os.str());
}

// --edit-benchmark K: moves a random singularity of `sing` (in the order given) to a random
// free interior vertex K times, re-solving each time; the median time of solve + field, or
// null if no move was made.
Json edit_benchmark(const std::string& file, const Mesh& mesh, SMDF::Trivial_connection<Mesh>& tc,
                    const Indexed_values& sing, long edits, Face_angle_property angles)
{
  std::vector<vertex_descriptor> interior;
  for(vertex_descriptor v : vertices(mesh))
    if(!is_border(v, mesh) && halfedge(v, mesh) != boost::graph_traits<Mesh>::null_halfedge())
      interior.push_back(v);
  std::vector<std::pair<vertex_descriptor, double>> current;
  for(const auto& s : sing)
    if(s.second != 0) current.push_back(std::make_pair(vertex_descriptor(Mesh::size_type(s.first)), s.second));
  std::mt19937 rng(12345);
  std::vector<double> times;
  for(long k = 0; k < edits && !current.empty(); ++k) {
    auto& s = current[std::uniform_int_distribution<std::size_t>(0, current.size() - 1)(rng)];
    vertex_descriptor to = s.first;
    for(int tries = 0; tries < 100 && tc.singularity_index(to) != 0; ++tries)
      to = interior[std::uniform_int_distribution<std::size_t>(0, interior.size() - 1)(rng)];
    if(tc.singularity_index(to) != 0) continue;
    tc.set_singularity(s.first, 0);
    tc.set_singularity(to, s.second);
    s.first = to;
    Stopwatch edit_clock;
    const SMDF::Trivial_connection_status est = tc.solve();
    if(!est.success) throw Error(file + ": trivial connection solve failed during --edit-benchmark: " + est.message);
    tc.field_angles(angles);
    times.push_back(edit_clock.total());
  }
  Json median;
  if(!times.empty()) {
    std::sort(times.begin(), times.end());
    const std::size_t m = times.size() / 2;
    median = times.size() % 2 ? times[m] : 0.5 * (times[m - 1] + times[m]);
  }
  return median;
}

// The prescribed singularities by vertex, rounded to multiples of 1/N as the library stores
// them, without the zeros.
Json prescribed_list(Indexed_values sing, long N)
{
  std::sort(sing.begin(), sing.end());
  Indexed_values prescribed;
  for(const auto& s : sing)
    if(s.second != 0) prescribed.push_back(std::make_pair(s.first, std::round(s.second * double(N)) / double(N)));
  return singularity_list(prescribed);
}

// --generator-turning smoothest: chooses and sets the turning numbers of least energy.
Json smoothest_turning(const std::string& file, SMDF::Trivial_connection<Mesh>& tc)
{
  const SMDF::Smoothest_turning_numbers s = on_file(file, [&] { return tc.choose_smoothest_generator_turning_numbers(); });
  Json r = Json::object();
  Json t = Json::array();
  for(double x : s.turning_numbers) t.push_back(x);
  r["turning_numbers"] = std::move(t);
  r["energy"] = s.energy;
  r["energy_with_zero_turning"] = s.energy_with_zero_turning;
  r["exact"] = s.exact;
  return r;
}

// The singularities of `topo` are exactly the nonzero ones of `sing` (rounded to 1/N).
bool same_singularities(const SMDF::Field_topology<Mesh>& topo, const Indexed_values& sing, long N)
{
  std::map<std::size_t, double> wanted, seen;
  for(const auto& s : sing)
    if(s.second != 0) wanted[s.first] = std::round(s.second * double(N)) / double(N);
  for(const auto& p : topo.singularities) seen[index(p.first)] = p.second;
  return wanted == seen;
}

// What a reader of the face field without its matching sees (principal matching: the smallest
// rotation per edge): its singularities and turning numbers, the vertices it gets wrong, and
// the interior edges across which the connection turns by pi/N or more.
Json principal_matching_report(const Mesh& mesh, const SMDF::Trivial_connection<Mesh>& tc,
                               const SMDF::Field_topology<Mesh>& principal, const Indexed_values& sing, long N)
{
  std::map<std::size_t, double> wanted, seen;
  for(const auto& s : sing)
    if(s.second != 0) wanted[s.first] = std::round(s.second * double(N)) / double(N);
  for(const auto& p : principal.singularities) seen[index(p.first)] = p.second;
  Json extra = Json::array(), missing = Json::array();
  for(const auto& p : seen) {
    auto it = wanted.find(p.first);
    if(it == wanted.end() || it->second != p.second) extra.push_back(p.first);
  }
  for(const auto& p : wanted) {
    auto it = seen.find(p.first);
    if(it == seen.end() || it->second != p.second) missing.push_back(p.first);
  }
  std::size_t wide = 0;
  const double limit = CGAL_PI / double(N);
  for(edge_descriptor e : edges(mesh))
    if(!is_border(e, mesh) && std::abs(tc.adjustment_angle(halfedge(e, mesh))) >= limit) ++wide;
  Json r = Json::object();
  r["found"] = found_list(principal);
  r["generator_turning_numbers"] = turning_numbers(principal);
  r["extra"] = std::move(extra);
  r["missing"] = std::move(missing);
  r["edges_turning_at_least_pi_over_N"] = wide;
  return r;
}

} // namespace

Json run_connection(const Args& args)
{
  const std::string& file = args.positional[0];
  const Connection_options opt = connection_options(args);
  const long N = opt.N;

  Mesh mesh;
  load_mesh(file, mesh);
  const Indexed_values sing = prescribed_singularities(args, opt.singularities, num_vertices(mesh));
  std::vector<std::pair<face_descriptor, double>> constraints;
  if(args.has("constraints")) constraints = read_constraints(args.value("constraints"), mesh);

  Stopwatch clock;
  // --lengths: the connection of another metric (e.g. a flat cone metric from cone-metric
  // --lengths-out); the field is drawn on the embedding through each face's linear map.
  // --factors: the discrete conformal metric of these factors (cone-metric --factors-out), on its
  // intrinsic Delaunay triangulation when it needs flips: the connection is solved there and the
  // field carried to the input faces through the common subdivision.
  if(args.has("lengths") && args.has("factors")) throw Usage_error("give --lengths or --factors, not both");
  const bool own_metric = args.has("lengths") || args.has("factors");
  const std::string metric_file = args.has("lengths") ? args.value("lengths") : args.has("factors") ? args.value("factors") : file;
  SMDF::Intrinsic_triangulation itri;
  Mesh flat_mesh;
  Mesh* carrier = &mesh;
  Edge_length_property metric_lengths;
  if(args.has("lengths")) itri = intrinsic_lengths(metric_file, mesh);   // empty: every line an input edge
  if(args.has("factors") || !itri.empty()) {
    if(args.has("factors")) {
      const std::vector<double> u = read_factors(metric_file, mesh);
      auto factors = mesh.add_property_map<vertex_descriptor, double>("v:smdf_factor", 0.).first;
      for(vertex_descriptor v : vertices(mesh)) factors[v] = u[v.idx()];
      itri = on_file(metric_file, [&] { return SMDF::conformal_intrinsic_triangulation(mesh, factors); });
    }
    if(itri.number_of_new_edges() > 0) {
      if(!constraints.empty() || opt.edits > 0 || args.has("connection-out"))
        throw Usage_error("--constraints, --edit-benchmark and --connection-out need the metric on the input's edges; "
                          "these factors need edge flips");
      metric_lengths = flat_mesh.add_property_map<edge_descriptor, double>("e:smdf_length", 0.).first;
      SMDF::copy_intrinsic_triangulation(itri, mesh, flat_mesh, metric_lengths);
      carrier = &flat_mesh;
    } else {
      metric_lengths = mesh.add_property_map<edge_descriptor, double>("e:smdf_length", 0.).first;
      for(std::size_t e = 0; e < itri.number_of_edges(); ++e)
        metric_lengths[edge_descriptor(Mesh::size_type(itri.input_edge(int(e))))] = itri.length(int(e));
    }
  } else if(args.has("lengths")) {
    metric_lengths = read_edge_lengths(metric_file, mesh);
  }
  const bool on_input = carrier == &mesh;
  const auto np = SMDF::parameters::symmetry_order(int(N)).connection_weights(opt.weights).rotation_limit(opt.rotation_limit);
  auto connect = [&](const auto& params) {
    return on_file(metric_file, [&] { return SMDF::Trivial_connection<Mesh>(*carrier, params); });
  };
  SMDF::Trivial_connection<Mesh> tc = own_metric ? connect(np.edge_length_map(metric_lengths)) : connect(np);
  const double construct_s = clock.lap();
  for(const auto& s : sing) tc.set_singularity(vertex_descriptor(Mesh::size_type(s.first)), s.second);
  for(const auto& t : opt.turning) tc.set_generator_turning_number(t.first, t.second);
  if(!constraints.empty()) tc.set_directional_constraints(constraints);
  Json smoothest;
  if(opt.smoothest) smoothest = smoothest_turning(file, tc);   // factors the system
  const double prepare_s = clock.lap();
  const SMDF::Trivial_connection_status st = tc.solve();
  clock.lap();

  Face_angle_property angles = carrier->add_property_map<face_descriptor, double>("f:smdf_angle", 0.).first;
  tc.field_angles(angles);
  Edge_matching_property matching = carrier->add_property_map<edge_descriptor, int>("e:smdf_matching", 0).first;
  const double off_lattice = tc.field_matching(angles, matching);
  const double field_s = clock.lap();
  // read back with the field's own matching (the result) and with principal matching (what a
  // reader without the matching sees), both on the connection's intrinsic mesh
  const auto read = [&](bool with_matching) {
    return on_file(file, [&] {
      const auto np = SMDF::parameters::symmetry_order(int(N)).intrinsic_mesh(tc.intrinsic_mesh());
      return with_matching ? SMDF::field_singularities(*carrier, angles, np.matching(matching))
                           : SMDF::field_singularities(*carrier, angles, np);
    });
  };
  const SMDF::Field_topology<Mesh> topo = read(true);
  const SMDF::Field_topology<Mesh> principal = read(false);
  // with flips: the field and its matching carried to the input faces, read back there
  Face_angle_property out_angles = angles;
  Edge_matching_property out_matching = matching;
  SMDF::Field_topology<Mesh> input_topo;
  SMDF::Field_transfer_status transfer;
  if(on_input && own_metric) {
    // another metric on the input's edges: the field and its matching in the embedding
    out_angles = mesh.add_property_map<face_descriptor, double>("f:smdf_input_angle", 0.).first;
    out_matching = mesh.add_property_map<edge_descriptor, int>("e:smdf_input_matching", 0).first;
    SMDF::face_field_in_embedding(mesh, int(N), angles, matching, metric_lengths, out_angles, out_matching);
    input_topo = SMDF::field_singularities(mesh, out_angles, SMDF::parameters::symmetry_order(int(N)).matching(out_matching));
    transfer.success = true;
  }
  if(!on_input) {
    out_angles = mesh.add_property_map<face_descriptor, double>("f:smdf_input_angle", 0.).first;
    out_matching = mesh.add_property_map<edge_descriptor, int>("e:smdf_input_matching", 0).first;
    std::vector<double> a(num_faces(*carrier));
    std::vector<int> k(num_edges(*carrier));
    for(face_descriptor f : faces(*carrier)) a[f.idx()] = angles[f];
    for(edge_descriptor e : edges(*carrier)) k[e.idx()] = matching[e];
    transfer = SMDF::transfer_face_field_to_input(mesh, itri, int(N), a, k, out_angles, out_matching);
    if(transfer.success)
      input_topo = SMDF::field_singularities(mesh, out_angles, SMDF::parameters::symmetry_order(int(N)).matching(out_matching));
  }
  if(args.has("field-out") || args.has("svg")) {
    Face_vector_property vectors =
      mesh.add_property_map<face_descriptor, K::Vector_3>("f:smdf_vector", K::Vector_3(0, 0, 0)).first;
    if(on_input && !own_metric) tc.angles_to_vectors(angles, vectors);
    else SMDF::field_angles_to_vectors(mesh, out_angles, vectors);
    write_field_files(args, mesh, vectors, N, on_input && !own_metric ? topo : input_topo, opt.svg);
  }
  if(args.has("connection-out")) write_connection(args.value("connection-out"), mesh, tc);
  if(args.has("matching-out")) write_matching(args.value("matching-out"), mesh, out_matching);

  const Json edit_median = st.success && opt.edits > 0 && !sing.empty()
                               ? edit_benchmark(file, mesh, tc, sing, opt.edits, angles) : Json();

  Json timings = Json::object();
  timings["setup_s"] = construct_s + prepare_s + st.factor_seconds;
  timings["solve_s"] = st.solve_seconds;
  timings["field_s"] = field_s;
  timings["edit_median_s"] = edit_median;

  Json out = Json::object();
  out["N"] = N;
  out["weights"] = opt.weights_name;
  out["metric"] = args.has("factors") ? "factors" : own_metric ? "lengths" : "embedding";
  if(on_input && own_metric) {
    Json t = Json::object();
    t["found"] = found_list(input_topo);
    out["input_read_back"] = std::move(t);
  }
  if(!on_input) {
    Json c = Json::object();
    c["intrinsic_edges"] = itri.number_of_new_edges();
    c["crossings"] = itri.number_of_crossings();
    c["pieces"] = itri.common_subdivision().size();
    out["correspondence"] = std::move(c);
    Json t = Json::object();
    t["found"] = found_list(input_topo);
    t["max_distortion"] = transfer.max_distortion;
    t["mean_distortion"] = transfer.mean_distortion;
    out["input_read_back"] = std::move(t);
  }
  out["prescribed"] = prescribed_list(sing, N);   // as set before the edits
  out["found"] = found_list(topo);
  out["generator_turning_numbers"] = turning_numbers(topo);
  out["principal_matching"] = principal_matching_report(*carrier, tc, principal, sing, N);
  if(opt.smoothest) out["smoothest_generator_turning"] = std::move(smoothest);
  out["energy"] = st.energy;
  out["residual"] = st.residual;
  out["scaled_residual"] = st.scaled_residual;
  out["max_holonomy_error"] = st.max_holonomy_error;
  out["max_rotation"] = st.max_rotation;
  out["edges_beyond_half_period"] = st.edges_beyond_half_period;
  out["edges_beyond_pi"] = st.edges_beyond_pi;
  out["rotation_limit"] = opt.rotation_limit;
  out["rotation_limit_rounds"] = st.rotation_limit_rounds;
  out["rotation_lower_bound"] = st.rotation_lower_bound;
  out["rotation_bound_any_turning"] = st.rotation_bound_any_turning;
  out["generators_turned_for_rotation"] = st.generators_turned_for_rotation;
  out["minimax_blend"] = st.minimax_blend;
  if(st.condition_estimate > 0) out["condition_estimate"] = st.condition_estimate;
  out["max_matching_rounding"] = off_lattice;

  // The result is what its read-back says: the field with its matching must have exactly the
  // prescribed singularities and turning numbers.
  std::string failure = st.success ? "" : "trivial connection solve failed: " + st.message;
  if(failure.empty() && !same_singularities(topo, sing, N))
    failure = "the field read back with its matching has other singularities than the prescribed ones";
  std::vector<double> prescribed_turning;
  for(std::size_t g = 0; g < tc.generators().size(); ++g) prescribed_turning.push_back(tc.generator_turning_number(g));
  if(failure.empty() && topo.generator_turning_numbers != prescribed_turning)
    failure = "the field read back with its matching has other generator turning numbers than the prescribed ones";
  if(failure.empty() && own_metric && !transfer.success)
    failure = "the field could not be carried to the input faces: " + transfer.message;
  if(failure.empty() && own_metric && !same_singularities(input_topo, sing, N))
    failure = "the field on the input faces reads back, with its matching, other singularities than the prescribed ones";
  out["success"] = failure.empty();
  out["timings"] = std::move(timings);
  if(!failure.empty()) throw Failed_result{out, file + ": " + failure, 3};
  return out;
}

Command connection_command()
{
  return {"connection", {"MESH"},
          {{"singularities", "LIST", "prescribed indices 'v:k,v:k,...' (k integer, p/q or decimal)"},
           {"singularities-file", "FILE", "prescribed indices, one line 'v k' per vertex"},
           {"N", "n", "symmetry order (1 vectors, 2 lines, 4 crosses; default 1)"},
           {"weights", "W", "unit (default), cotan, nonnegative-cotan or bounded-cotan (manual: choice of weights)"},
           {"rotation-limit", "A", "bound on |x_e| enforced by reweighting when the minimum-norm solution exceeds it (default 0.8pi; 'off': the minimum-norm connection)"},
           {"generator-turning", "LIST", "turning numbers 'g:t,...' of the generators (default 0), or 'smoothest'"},
           {"constraints", "FILE", "directional constraints: lines 'face angle' or 'face x y z'"},
           {"field-out", "FILE", "write one unit direction 'x y z' per face"},
           {"connection-out", "FILE", "write 'i j angle' per interior edge (adjustment angle)"},
           {"matching-out", "FILE", "write 'i j k' per interior edge (period jump of the field)"},
           {"lengths", "FILE", "intrinsic metric: one line 'i j length' per edge (as holonomy --lengths); with edges not in the input "
                              "(cone-metric --lengths-out after flips) the conformal metric is rebuilt from the shared edges, checked "
                              "line by line, and the field carried to the input faces"},
           {"factors", "FILE", "the discrete conformal metric of these factors, one 'u' per vertex (cone-metric --factors-out); with edge flips the field is carried to the input faces"},
           {"edit-benchmark", "K", "time K random singularity moves (re-solve + field)"},
           {"svg", "FILE", "write an SVG picture of the field and its found singularities"},
           {"view", "A,E[,UP]", "view of --svg: azimuth,elevation in degrees, up axis x|y|z (default 30,20 and an up axis chosen from the bounding box, named in the picture)"},
           {"width", "PX", "width of the --svg picture in pixels (default 800)"}},
          "trivial connection with prescribed singularities and its N-RoSy field",
          "Computes the trivial connection closest to Levi-Civita with the prescribed singularity\n"
          "indices (multiples of 1/N at interior vertices; on a closed component they must sum to\n"
          "its Euler characteristic) and generator turning numbers, and the face field it transports.\n"
          "Prints {N, weights, prescribed: [{vertex, index}], found: [{vertex, index}] (read back\n"
          "from the computed field with its matching), generator_turning_numbers (read back),\n"
          "principal_matching: {found, generator_turning_numbers, extra, missing,\n"
          "edges_turning_at_least_pi_over_N} (what a reader without the matching sees), energy,\n"
          "residual, scaled_residual, max_holonomy_error, max_rotation (largest |x_e|),\n"
          "edges_beyond_half_period (|x_e| > pi/N), edges_beyond_pi, rotation_limit,\n"
          "rotation_limit_rounds (refactorisations spent bounding |x_e|), rotation_lower_bound (when an\n"
          "edge stays beyond pi: every connection with these indices and turning numbers turns some\n"
          "edge by at least this, proven by a dual cycle), rotation_bound_any_turning (the same\n"
          "whatever the turning numbers, when a cycle around no handle proves it),\n"
          "generators_turned_for_rotation (turning numbers moved from the smoothest ones to get every\n"
          "edge below pi), minimax_blend (weight of the connection of lowest largest rotation\n"
          "blended in), condition_estimate (only when\n"
          "the holonomy error exceeds 1e-12), max_matching_rounding, success, timings:\n"
          "{setup_s, solve_s, field_s, edit_median_s}}; with --generator-turning smoothest also\n"
          "smoothest_generator_turning: {turning_numbers, energy, energy_with_zero_turning, exact}\n"
          "(the turning numbers of least energy; exact: global minimum over multiples of 1/N,\n"
          "searched exhaustively up to 12 generators). Exit code 3 (JSON printed) when the solve\n"
          "fails or found differs from prescribed.\n"
          "Constraint angles are in radians in the face frame, counterclockwise from halfedge(f);\n"
          "3D directions are projected on the face plane. Files may hold blank lines and '#'\n"
          "comments. --connection-out writes, per interior edge, the vertices i j of halfedge(e) and\n"
          "the adjustment angle for crossing it from its right face into its left face;\n"
          "--matching-out the period jump k: carrying the right face's direction into the left\n"
          "face gives the left face's direction rotated by 2 pi k / N.\n"
          "--lengths runs on another metric than the embedding's (e.g. cone-metric --lengths-out\n"
          "without flips); --field-out and --svg then map each face's directions to 3D by the\n"
          "linear map from the metric's triangle to the embedded one. --factors FILE (one 'u' per\n"
          "vertex, cone-metric --factors-out) runs on the discrete conformal metric of those\n"
          "factors, for every metric: when it needs edge flips the connection is solved on its\n"
          "intrinsic Delaunay triangulation and the field and its matching are carried to the\n"
          "input faces (correspondence: {intrinsic_edges, crossings, pieces}, input_read_back:\n"
          "{found, max_distortion, mean_distortion}, which must equal the prescribed ones).\n"
          "--edit-benchmark K moves a random singularity K times (pseudo-random, fixed seed) and\n"
          "reports the median time of solve + field (null without singularities).\n"
          "--svg draws the mesh (orthographic view, back faces culled), the field (one\n"
          "glyph per visible face, thinned out on large meshes) and the found singularities (red\n"
          "positive, blue negative).\n",
          run_connection};
}

} // namespace smdf_cli
