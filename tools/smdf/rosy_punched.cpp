// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// smdf rosy with cones of index >= 1 (Lai et al. 2010, section 4.1.1): a hole is punched at
// each, the field is designed on the rest and carried back, and the hole is filled.

#include "rosy_inputs.h"

#include <CGAL/Surface_mesh_direction_fields/Trivial_connection.h>
#include <CGAL/Surface_mesh_direction_fields/boundary_aligned_field.h>
#include <CGAL/Surface_mesh_direction_fields/cone_metric.h>
#include <CGAL/Surface_mesh_direction_fields/field_singularities.h>
#include <CGAL/Surface_mesh_direction_fields/field_transfer.h>
#include <CGAL/Surface_mesh_direction_fields/parallel_rosy_field.h>
#include <CGAL/Surface_mesh_direction_fields/topology.h>
#include <CGAL/Surface_mesh_direction_fields/vertex_field_from_faces.h>

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace smdf_cli {

namespace {

// 3D helpers for the fill: unit vectors, the face normal, a direction's angle in a face frame.
K::Vector_3 unit_vector(const K::Vector_3& v) { return v / std::sqrt(v.squared_length()); }

K::Vector_3 face_normal(const Mesh& mesh, face_descriptor f)
{
  const halfedge_descriptor h = halfedge(f, mesh);
  const K::Point_3 &a = mesh.point(source(h, mesh)), &b = mesh.point(target(h, mesh)), &c = mesh.point(target(next(h, mesh), mesh));
  return unit_vector(CGAL::cross_product(b - a, c - a));
}

} // namespace

namespace {

// A cone of index >= 1 whose ring touches the boundary, or another such cone within two edges,
// has no room for its hole: points at one distance eps from it on all its edges make that room.
// Each face around it then keeps the ear (cone, p, q) in its Delaunay re-triangulation (eps
// below half of h cos(theta / 2): h the cone's height over the opposite side, theta its angle,
// the ear's circumcircle stays off the other points), so its new ring lies inside the surface;
// eps is at most a third of every edge, so two such cones end three edges apart. As (edge index,
// parameter).
std::vector<std::pair<std::size_t, double>> hole_room_points(const Mesh& mesh, const std::vector<std::pair<vertex_descriptor, double>>& cones)
{
  std::vector<char> big(num_vertices(mesh), 0);
  for(const auto& c : cones)
    if(!is_border(c.first, mesh) && !(c.second < 2 * CGAL_PI - 1e-9)) big[c.first.idx()] = 1;
  std::vector<std::pair<std::size_t, double>> points;
  for(const auto& c : cones) {
    const vertex_descriptor v = c.first;
    if(!big[v.idx()]) continue;
    bool cramped = false;
    for(halfedge_descriptor h : halfedges_around_target(halfedge(v, mesh), mesh)) {
      const vertex_descriptor w = source(h, mesh);
      cramped = cramped || is_border(w, mesh) || big[w.idx()];
      for(halfedge_descriptor g : halfedges_around_target(halfedge(w, mesh), mesh))
        cramped = cramped || (source(g, mesh) != v && big[source(g, mesh).idx()]);
    }
    if(!cramped) continue;
    double eps = HUGE_VAL;
    for(halfedge_descriptor h : halfedges_around_target(halfedge(v, mesh), mesh)) {
      const double L = std::sqrt(CGAL::squared_distance(mesh.point(source(h, mesh)), mesh.point(v)));
      eps = (std::min)(eps, L / 3);
      if(is_border(h, mesh)) continue;
      const K::Point_3 &a = mesh.point(source(h, mesh)), &b = mesh.point(target(next(h, mesh), mesh)), &o = mesh.point(v);
      const K::Vector_3 u = a - o, w = b - o;
      const double theta = std::atan2(std::sqrt(CGAL::cross_product(u, w).squared_length()), u * w);
      const double height = std::sqrt(CGAL::cross_product(u, w).squared_length() / (b - a).squared_length());
      eps = (std::min)(eps, 0.5 * height * std::cos(theta / 2));
    }
    for(halfedge_descriptor h : halfedges_around_target(halfedge(v, mesh), mesh)) {
      const edge_descriptor e = edge(h, mesh);
      const double t = eps / std::sqrt(CGAL::squared_distance(mesh.point(source(h, mesh)), mesh.point(v)));
      points.emplace_back(e.idx(), source(halfedge(e, mesh), mesh) == v ? t : 1 - t);
    }
  }
  return points;
}

// run_rosy_punched() on `mesh`, the last refinement of `chain` (the input when it is empty): the
// outputs are brought back through it to the input's faces. When the holed surface's flow
// stalls on border edges (border_points_to_insert()) and `stall_points` is given, returns an
// empty JSON with these points on `mesh`'s edges there, for another refinement, unless the
// flow's curvature error is not below half of `*stall_error` (the last round's, updated).
Json punched_on(const Args& args, const std::string& file, Mesh& mesh, int N,
                const std::vector<std::pair<vertex_descriptor, double>>& cones, Vertex_double_property targets,
                Rosy_method method, Boundary_mode mode, const SMDF::Svg_options& svg, std::string* holed_failure,
                const Refinement_chain& chain, std::vector<std::pair<std::size_t, double>>* stall_points, double* stall_error);

} // namespace

Json run_rosy_punched(const Args& args, const std::string& file, Mesh& mesh, int N,
                      const std::vector<std::pair<vertex_descriptor, double>>& cones, Vertex_double_property targets,
                      Rosy_method method, Boundary_mode mode, const SMDF::Svg_options& svg, std::string* holed_failure)
{
  // refinements, each of the mesh before: room for the holes, then border edges where the
  // holed surface's flow stalls (a cone next to the boundary or to a hole), up to 6 rounds
  std::vector<std::unique_ptr<Mesh>> meshes;
  std::vector<std::unique_ptr<SMDF::Delaunay_refinement_status>> statuses;
  Refinement_chain chain;
  Mesh* current = &mesh;
  Vertex_double_property current_targets = targets;
  std::vector<std::pair<std::size_t, double>> points = hole_room_points(mesh, cones), stall;
  double stall_error = HUGE_VAL;   // a refinement must halve the stalled flow's error, or the fallback is taken
  for(int round = 0;; ++round) {
    if(!points.empty()) {
      meshes.push_back(std::make_unique<Mesh>());
      Mesh& refined = *meshes.back();
      statuses.push_back(std::make_unique<SMDF::Delaunay_refinement_status>(
          on_file(file, [&] { return SMDF::refine_at_edge_points(*current, points, refined); })));
      if(!statuses.back()->success) throw Error(file + ": the refinement for the holes failed: " + statuses.back()->message);
      const Vertex_double_property t = refined.add_property_map<vertex_descriptor, double>("v:smdf_rosy_target", 0.).first;
      for(vertex_descriptor v : vertices(*current)) t[v] = current_targets[v];   // the coarser mesh's vertices come first
      chain.emplace_back(current, statuses.back().get());
      current = &refined;
      current_targets = t;
    }
    stall.clear();
    Json out = punched_on(args, file, *current, N, cones, current_targets, method, mode, svg, holed_failure, chain, round < 6 ? &stall : nullptr,
                          &stall_error);
    if(stall.empty()) {
      if(!chain.empty() && (!holed_failure || holed_failure->empty())) {
        Json r = Json::object();
        r["refinements"] = chain.size();
        r["inserted_vertices"] = num_vertices(*current) - num_vertices(mesh);
        r["faces"] = num_faces(*current);
        out["hole_refinement"] = std::move(r);
      }
      return out;
    }
    points = stall;
  }
}

namespace {

Json punched_on(const Args& args, const std::string& file, Mesh& mesh, int N,
                const std::vector<std::pair<vertex_descriptor, double>>& cones, Vertex_double_property targets,
                Rosy_method method, Boundary_mode mode, const SMDF::Svg_options& svg, std::string* holed_failure,
                const Refinement_chain& chain, std::vector<std::pair<std::size_t, double>>* stall_points, double* stall_error)
{
  Json out = Json::object();
  Json timings = Json::object();
  Stopwatch clock;
  const std::size_t nv = num_vertices(mesh);
  const SMDF::Mesh_topology topology = SMDF::mesh_topology(mesh);
  const bool open = !topology.is_closed();
  // The field on the holed surface: the paper's parallel field (--method parallel, and fields
  // along the boundary), else the trivial connection of the holed metric with the hole loops'
  // holonomy kept and the handles' compensated by the least rotation (what rotation compensation
  // does; on a sphere it is the parallel field itself). Open meshes without handles take the
  // parallel field by default, as without holes.
  bool handles = false;
  for(const auto& c : topology.components) handles = handles || c.genus > 0;
  const bool aligned = open && mode != FREE_BOUNDARY;
  const bool parallel = !aligned && (method == PARALLEL || (method == AUTOMATIC && open && !handles));
  const Rosy_method named = aligned ? BOUNDARY_ALIGNED : parallel ? PARALLEL
                          : method == AUTOMATIC ? (open ? TRIVIAL_CONNECTION : ROTATION_COMPENSATION) : method;
  out["N"] = N;
  out["method"] = std::string(method_name(named)) + " (punched holes)";
  if(!open) {   // Gauss-Bonnet on the input, before the holes change its Euler characteristic
    double sum = 0;
    for(vertex_descriptor v : vertices(mesh)) sum += targets[v];
    const long chi = topology.euler_characteristic();
    if(std::abs(sum - 2 * CGAL_PI * double(chi)) > 1e-6)
      throw Error(file + ": Gauss-Bonnet: the cones' indices sum to " + format_real(sum / (2 * CGAL_PI)) +
                  " but the Euler characteristic of the mesh is " + std::to_string(chi));
  }
  if(open) out["boundary"] = mode == FREE_BOUNDARY ? "free" : mode == PARALLEL_BOUNDARY ? "parallel" : "orthogonal";

  // 1. the holes: the faces around every interior cone of index >= 1; its ring becomes boundary
  //    turning by kappa_w = K_w + (K_v - 2 pi) / d (Gauss-Bonnet: the hole turns 2 pi - K_v less)
  std::vector<char> in_fan(num_faces(mesh), 0);
  std::vector<int> owner(nv, -1);   // the punched vertex whose hole a vertex belongs to
  std::map<vertex_descriptor, double> holed_target;
  for(vertex_descriptor v : vertices(mesh)) holed_target[v] = targets[v];
  Json punched = Json::array();
  // (holes that cannot be punched: the caller's route without holes where it applies)
  const bool fallback = holed_failure && !aligned && method != PARALLEL;
  try {
    for(const auto& c : cones) {
      const vertex_descriptor v = c.first;
      if(is_border(v, mesh) || c.second < 2 * CGAL_PI - 1e-9) continue;
      std::vector<vertex_descriptor> ring;
      for(halfedge_descriptor h : halfedges_around_target(halfedge(v, mesh), mesh)) ring.push_back(source(h, mesh));
      auto clash = [&](vertex_descriptor w) { return owner[w.idx()] >= 0 && owner[w.idx()] != int(v.idx()); };
      if(clash(v)) throw Error(file + ": the cones of index 1 or more at vertices " + std::to_string(v.idx()) + " and " +
                               std::to_string(owner[v.idx()]) + " are too close to punch two holes (they need three edges between them)");
      owner[v.idx()] = int(v.idx());
      for(vertex_descriptor w : ring) {
        if(is_border(w, mesh))
          throw Error(file + ": the cone of index 1 or more at vertex " + std::to_string(v.idx()) + " touches the boundary (vertex " +
                      std::to_string(w.idx()) + "): its hole needs a ring of interior vertices");
        if(clash(w)) throw Error(file + ": the cones of index 1 or more at vertices " + std::to_string(v.idx()) + " and " +
                                 std::to_string(owner[w.idx()]) + " are too close to punch two holes (they need three edges between them)");
        owner[w.idx()] = int(v.idx());
        holed_target[w] += (c.second - 2 * CGAL_PI) / double(ring.size());
        if(!(holed_target[w] < CGAL_PI))
          throw Error(file + ": the hole of the cone at vertex " + std::to_string(v.idx()) + " would turn by " + format_real(holed_target[w]) +
                      " at ring vertex " + std::to_string(w.idx()) + " (at least pi): its index is too large for its " +
                      std::to_string(ring.size()) + " neighbours");
      }
      for(face_descriptor f : faces_around_target(halfedge(v, mesh), mesh)) in_fan[f.idx()] = 1;
      holed_target.erase(v);
      Json p = Json::object();
      p["vertex"] = v.idx();
      p["index"] = c.second / (2 * CGAL_PI);
      p["ring"] = ring.size();
      punched.push_back(std::move(p));
    }
  } catch(const Error& e) {
    if(!fallback) throw;
    *holed_failure = e.what();
    return Json();
  }
  out["punched"] = std::move(punched);

  // 2. the holed mesh: the same vertices (the punched ones isolated), the other faces, each with
  //    the input's halfedge(f) (a polygon (b, c, a) gives halfedge a -> b), so that face frames agree
  std::vector<K::Point_3> points;
  for(vertex_descriptor v : vertices(mesh)) points.push_back(mesh.point(v));
  std::vector<std::array<std::size_t, 3>> polygons;
  std::vector<face_descriptor> input_face;
  for(face_descriptor f : faces(mesh)) {
    if(in_fan[f.idx()]) continue;
    const halfedge_descriptor h = halfedge(f, mesh);
    polygons.push_back({{target(h, mesh).idx(), target(next(h, mesh), mesh).idx(), source(h, mesh).idx()}});
    input_face.push_back(f);
  }
  Mesh holed;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, holed);
  bool same = num_vertices(holed) == nv && num_faces(holed) == polygons.size();
  for(std::size_t i = 0; same && i < polygons.size(); ++i) {
    const halfedge_descriptor h = halfedge(face_descriptor(Mesh::size_type(i)), holed);
    same = source(h, holed).idx() == polygons[i][2] && target(h, holed).idx() == polygons[i][0];
  }
  if(!same) throw Error(file + ": the mesh with its holes punched could not be built (internal)");

  // 3. the metric of the holed surface
  auto htarget = holed.add_property_map<vertex_descriptor, double>("v:smdf_target", 0.).first;
  for(const auto& t : holed_target) htarget[t.first] = t.second;
  const Edge_length_property hlen = holed.add_property_map<edge_descriptor, double>("e:smdf_length", 0.).first;
  auto hu = holed.add_property_map<vertex_descriptor, double>("v:smdf_u", 0.).first;
  const SMDF::Cone_metric_status cm = on_file(file, [&] {
    return SMDF::compute_cone_metric(holed, htarget, hlen, SMDF::parameters::conformal_factor_map(hu));
  });
  timings["metric_s"] = clock.lap();
  out["metric"] = metric_json(cm, "the mesh with its holes punched");
  auto fail = [&](const std::string& why) {
    out["success"] = false;
    out["timings"] = timings;
    return Failed_result{out, file + ": " + why, 3};
  };
  if(!cm.converged && stall_points && cm.max_curvature_error < 0.5 * *stall_error) {
    *stall_error = cm.max_curvature_error;
    // border edges of the holed surface are edges of `mesh` (the same vertices)
    for(const auto& p : border_points_to_insert(holed, holed, nullptr, cm, hlen)) {
      const halfedge_descriptor hh = halfedge(edge_descriptor(Mesh::size_type(p.first)), holed);
      const auto ih = halfedge(vertex_descriptor(source(hh, holed).idx()), vertex_descriptor(target(hh, holed).idx()), mesh);
      if(!ih.second) continue;
      const edge_descriptor ie = edge(ih.first, mesh);
      stall_points->emplace_back(ie.idx(), halfedge(ie, mesh) == ih.first ? p.second : 1 - p.second);
    }
    if(!stall_points->empty()) return Json();
  }
  if(!cm.converged) {
    if(fallback) {
      *holed_failure = "flat cone metric of the holed surface not converged: " + cm.message;
      return Json();
    }
    throw fail("flat cone metric of the holed surface not converged: " + cm.message);
  }

  // 4. its parallel field, on the holed mesh or its intrinsic triangulation
  Mesh flat_mesh;
  Mesh* carrier = &holed;
  Edge_length_property flat = hlen;
  if(cm.triangulation_changed) {
    if(!cm.intrinsic_triangulation.has_common_subdivision()) throw fail("no correspondence with the input: " + cm.correspondence_message);
    flat = flat_mesh.add_property_map<edge_descriptor, double>("e:smdf_length", 0.).first;
    SMDF::copy_intrinsic_triangulation(cm.intrinsic_triangulation, holed, flat_mesh, flat);
    carrier = &flat_mesh;
  }
  if(args.has("holonomy")) {
    // the holed surface's: its hole loops are boundary loops, the other cones keep their loops
    std::vector<vertex_descriptor> inner_cones;
    for(const auto& c : cones) {
      const vertex_descriptor v(c.first.idx());
      if(c.second < 2 * CGAL_PI - 1e-9 && carrier->halfedge(v) != Mesh::null_halfedge() && !is_border(v, *carrier))
        inner_cones.push_back(v);
    }
    const auto basis = on_file(file, [&] { return SMDF::homotopy_basis(*carrier, inner_cones, SMDF::parameters::edge_length_map(flat)); });
    const SMDF::Holonomy_group group = SMDF::holonomy_group(*carrier, basis, SMDF::parameters::edge_length_map(flat));
    out["holonomy"] = holonomy_loops_json(basis, group, SMDF::parallel_rosy_compatibility(group, N));
  }
  const Face_angle_property angles = carrier->add_property_map<face_descriptor, double>("f:smdf_angle", 0.).first;
  const Edge_matching_property cmatch = carrier->add_property_map<edge_descriptor, int>("e:smdf_matching", 0).first;
  if(aligned) {
    // every loop of the input followed (handles compensated, Lai et al. 4.3), the holes left free
    auto hole = carrier->add_property_map<vertex_descriptor, bool>("v:smdf_hole", false).first;
    for(vertex_descriptor v : vertices(*carrier)) hole[v] = owner[v.idx()] >= 0;
    const SMDF::Boundary_aligned_field_status bs = SMDF::boundary_aligned_field_of_metric(
        *carrier, N, angles, cmatch,
        SMDF::parameters::edge_length_map(flat).orthogonal_to_boundary(mode == ORTHOGONAL_BOUNDARY).free_boundary_vertex_map(hole));
    if(!bs.success) throw fail("no field along the boundary of the holed surface: " + bs.message);
  } else if(parallel) {
    const SMDF::Parallel_rosy_status ps = SMDF::parallel_rosy_field(*carrier, N, angles, SMDF::parameters::edge_length_map(flat));
    if(!ps.success)
      throw fail("no parallel " + std::to_string(N) + "-RoSy field on the holed surface (on a surface with handles its "
                 "holonomy need not allow one; the default method compensates it): " + ps.message);
    SMDF::principal_matching(*carrier, angles, cmatch, SMDF::parameters::symmetry_order(N).edge_length_map(flat));
  } else {
    // interior vertices keep their indices (0, or a cone's); every generator (handle or boundary
    // loop, the holes' among them) turns by the multiple of 2 pi / N nearest its holonomy
    SMDF::Trivial_connection<Mesh> tc = on_file(file, [&] {
      return SMDF::Trivial_connection<Mesh>(*carrier, SMDF::parameters::symmetry_order(N).edge_length_map(flat));
    });
    for(const auto& c : cones) {
      const vertex_descriptor v(c.first.idx());
      if(c.second < 2 * CGAL_PI - 1e-9 && !is_border(v, *carrier) && carrier->halfedge(v) != Mesh::null_halfedge())
        tc.set_singularity(v, std::round(c.second / (2 * CGAL_PI) * N) / N);
    }
    turn_generators_least(tc, N);
    const SMDF::Trivial_connection_status ts = tc.solve();
    out["trivial_connection"] = trivial_connection_json(ts);
    if(!ts.success) throw fail("trivial connection of the holed surface failed: " + ts.message);
    tc.field_angles(angles);
    tc.field_matching(angles, cmatch);
  }
  timings["compensation_s"] = clock.lap();

  // 5. carried to the holed mesh's faces (the input's frames), then to the input's
  const Face_angle_property hangles = holed.add_property_map<face_descriptor, double>("f:smdf_input_angle", 0.).first;
  const Edge_matching_property hmatch = holed.add_property_map<edge_descriptor, int>("e:smdf_input_matching", 0).first;
  if(!cm.triangulation_changed) {   // the same triangles: each face's linear map, as the route without holes
    SMDF::face_field_in_embedding(holed, N, angles, cmatch, hlen, hangles, hmatch);
  } else {
    std::vector<double> a(num_faces(*carrier));
    std::vector<int> k(num_edges(*carrier));
    for(face_descriptor f : faces(*carrier)) a[f.idx()] = angles[f];
    for(edge_descriptor e : edges(*carrier)) k[e.idx()] = cmatch[e];
    const SMDF::Field_transfer_status ts = SMDF::transfer_face_field_to_input(holed, cm.intrinsic_triangulation, N, a, k, hangles, hmatch);
    Json t = Json::object();
    t["max_distortion"] = ts.max_distortion;
    t["mean_distortion"] = ts.mean_distortion;
    out["input_read_back"] = std::move(t);
    if(!ts.success) throw fail("the field could not be carried to the input faces: " + ts.message);
  }
  const Face_angle_property in_angles = mesh.add_property_map<face_descriptor, double>("f:smdf_punched_angle", 0.).first;
  const Face_vector_property vectors = mesh.add_property_map<face_descriptor, K::Vector_3>("f:smdf_punched_vector").first;
  const Edge_matching_property in_match = mesh.add_property_map<edge_descriptor, int>("e:smdf_punched_matching", 0).first;
  for(std::size_t i = 0; i < input_face.size(); ++i) in_angles[input_face[i]] = hangles[face_descriptor(Mesh::size_type(i))];
  for(edge_descriptor e : edges(holed)) {
    if(is_border(e, holed)) continue;
    const halfedge_descriptor hh = halfedge(e, holed);
    const auto ih = halfedge(vertex_descriptor(source(hh, holed).idx()), vertex_descriptor(target(hh, holed).idx()), mesh);
    const edge_descriptor ie = edge(ih.first, mesh);
    in_match[ie] = halfedge(ie, mesh) == ih.first ? hmatch[e] : -hmatch[e];
  }
  // 6. the fill: each face of a hole takes the field of the face across its ring edge, unfolded
  //    (so the ring edges turn it by nothing); the spokes take what the ring vertices' indices
  //    need (0, or their own cone's), which leaves the punched vertex its index (Gauss-Bonnet)
  SMDF::field_angles_to_vectors(mesh, in_angles, vectors);
  for(face_descriptor t : faces(mesh)) {
    if(!in_fan[t.idx()]) continue;
    for(halfedge_descriptor h : halfedges_around_face(halfedge(t, mesh), mesh)) {
      const face_descriptor o = face(opposite(h, mesh), mesh);
      if(o == boost::graph_traits<Mesh>::null_face() || in_fan[o.idx()]) continue;
      const K::Vector_3 ev = unit_vector(mesh.point(target(h, mesh)) - mesh.point(source(h, mesh)));
      const K::Vector_3 no = face_normal(mesh, o), nt = face_normal(mesh, t), v = vectors[o];
      vectors[t] = (v * ev) * ev + (v * CGAL::cross_product(no, ev)) * CGAL::cross_product(nt, ev);
    }
  }
  {
    auto fan_vectors = get(CGAL::dynamic_face_property_t<K::Vector_3>(), mesh);
    auto fan_angles = get(CGAL::dynamic_face_property_t<double>(), mesh);
    for(face_descriptor f : faces(mesh)) put(fan_vectors, f, vectors[f]);
    SMDF::vectors_to_face_angles(mesh, fan_vectors, fan_angles);
    for(face_descriptor f : faces(mesh)) if(in_fan[f.idx()]) in_angles[f] = get(fan_angles, f);
  }
  const auto rnp = SMDF::parameters::symmetry_order(N);
  const std::map<vertex_descriptor, double> want = prescribed_indices(mesh, cones, N);
  SMDF::Field_topology<Mesh> found = SMDF::field_singularities(mesh, in_angles, rnp.matching(in_match));
  {
    std::map<vertex_descriptor, double> idx(found.singularities.begin(), found.singularities.end());
    for(edge_descriptor e : edges(mesh)) {
      const halfedge_descriptor h = halfedge(e, mesh);
      const vertex_descriptor a = source(h, mesh), b = target(h, mesh);
      const bool spoke = owner[a.idx()] >= 0 && owner[b.idx()] >= 0 && (int(a.idx()) == owner[a.idx()] || int(b.idx()) == owner[b.idx()]);
      if(!spoke) continue;
      const vertex_descriptor w = int(a.idx()) == owner[a.idx()] ? b : a;   // the ring vertex
      const double have = idx.count(w) ? idx[w] : 0., need = want.count(w) ? want.at(w) : 0.;
      const int steps = int(std::lround((need - have) * N));
      in_match[e] += w == a ? steps : -steps;   // +1 on halfedge(e) adds 1/N at its source
    }
  }
  found = SMDF::field_singularities(mesh, in_angles, rnp.matching(in_match));
  timings["fill_s"] = clock.lap();

  // 7. the read-back on the input
  const std::map<vertex_descriptor, double> got(found.singularities.begin(), found.singularities.end());
  Json prescribed = Json::array();
  for(const auto& w : want) {
    Json o = Json::object();
    o["vertex"] = w.first.idx();
    o["index"] = w.second;
    prescribed.push_back(std::move(o));
  }
  out["prescribed"] = std::move(prescribed);
  out["found"] = found_list(found);
  if(open && mode != FREE_BOUNDARY) {
    // the boundary faces along their edges (mod 2 pi / N; pi / N for odd N)
    const double worst =
        SMDF::max_boundary_deviation(mesh, N, in_angles, SMDF::parameters::orthogonal_to_boundary(mode == ORTHOGONAL_BOUNDARY));
    Json b = Json::object();
    b["max_boundary_deviation"] = worst;
    out["boundary_aligned"] = std::move(b);
    if(!(worst < 1e-6)) throw fail("the field does not follow the boundary everywhere (deviation " + format_real(worst) + " rad)");
  }
  if(got != want) throw fail("the field read back with its matching has other singularities than the cones");
  out["success"] = true;
  out["timings"] = std::move(timings);

  // 8. the files, on the input's faces (after a refinement: brought back to them and read back there)
  Face_field output{&mesh, in_angles, in_match};
  if(!chain.empty()) {
    Json r = Json::object();
    const std::string why = bring_back_to_input(chain, output, N, cones, open && mode != FREE_BOUNDARY, mode == ORTHOGONAL_BOUNDARY,
                                                "the refinement for the holes", r);
    out["input_read_back"] = std::move(r);
    if(!why.empty()) throw fail(why);
  }
  Mesh* const input = output.mesh;
  const Face_angle_property input_angles = output.angles;
  const Edge_matching_property input_match = output.matching;
  const Face_vector_property input_vectors = input->add_property_map<face_descriptor, K::Vector_3>("f:smdf_punched_output_vector").first;
  SMDF::field_angles_to_vectors(*input, input_angles, input_vectors);
  if(args.has("face-field-out")) {
    std::vector<K::Vector_3> v;
    for(face_descriptor f : faces(*input)) v.push_back(input_vectors[f]);
    write_vectors(args.value("face-field-out"), v);
  }
  if(args.has("matching-out")) write_matching(args.value("matching-out"), *input, input_match);
  if(args.has("field-out")) {   // the vertex version: 0 at the singularities
    auto vv = input->add_property_map<vertex_descriptor, K::Vector_3>("v:smdf_punched_vector").first;
    SMDF::vertex_field_from_face_field(*input, N, input_angles, input_match, vv);
    std::vector<K::Vector_3> v;
    for(vertex_descriptor x : vertices(*input)) v.push_back(vv[x]);
    write_vectors(args.value("field-out"), v);
  }
  if(args.has("svg")) write_field_svg_file(args, *input, input_vectors, N, found, svg);
  if(args.has("hatching-svg")) out["hatching"] = write_hatching_svg(args, file, *input, input_vectors, N, svg);
  return out;
}

} // namespace

Json spread_to_neighbours(const Mesh& mesh, const std::vector<std::pair<vertex_descriptor, double>>& cones, Vertex_double_property targets)
{
  // The holed surface's Ricci flow failed (its boundary edges cannot flip), or the holes could
  // not be punched. Without a hole: a cone of index k >= 1 keeps the curvature 2 pi (k - floor k)
  // and its d neighbours take 2 pi floor(k) / d each, a closed flat cone metric (flips always
  // reach it), on which the trivial connection gives k at the cone and their own indices to the
  // neighbours.
  Json spread = Json::array();
  for(const auto& c : cones) {
    if(is_border(c.first, mesh) || c.second < 2 * CGAL_PI) continue;
    const double whole = std::floor(c.second / (2 * CGAL_PI) + 1e-9);
    std::vector<vertex_descriptor> ring;
    for(halfedge_descriptor h : halfedges_around_target(halfedge(c.first, mesh), mesh)) ring.push_back(source(h, mesh));
    targets[c.first] -= 2 * CGAL_PI * whole;
    for(vertex_descriptor w : ring) targets[w] += 2 * CGAL_PI * whole / double(ring.size());
    Json o = Json::object();
    o["vertex"] = c.first.idx();
    o["index"] = c.second / (2 * CGAL_PI);
    o["ring"] = ring.size();
    spread.push_back(std::move(o));
  }
  return spread;
}

} // namespace smdf_cli
