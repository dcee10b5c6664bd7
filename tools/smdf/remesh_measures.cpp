// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// smdf remesh's measures of the remesh: see remesh_measures.h.

#include "remesh_measures.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>

#include <cmath>
#include <exception>
#include <thread>
#include <vector>

namespace smdf_cli {

namespace {

// Calls corner(angle_deg, scaled_jacobian, quad) for every corner of every face of `out` (the
// scaled Jacobian against the face's own area vector; 0 where that vanishes), then face_done(quad)
// after the corners of each face; a corner with a zero-length edge counts as angle 0, scaled
// Jacobian -1 (a degenerate face).
template <typename Corner, typename Face>
void for_each_corner(const Mesh& out, const Corner& corner, const Face& face_done)
{
  for(face_descriptor f : faces(out)) {
    std::vector<K::Point_3> p;
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, out), out)) p.push_back(out.point(target(h, out)));
    K::Vector_3 n(0, 0, 0);
    for(std::size_t i = 0; i < p.size(); ++i) n = n + CGAL::cross_product(p[i] - CGAL::ORIGIN, p[(i + 1) % p.size()] - CGAL::ORIGIN);
    const double nl = std::sqrt(n.squared_length());
    for(std::size_t i = 0; i < p.size(); ++i) {
      const K::Vector_3 a = p[(i + 1) % p.size()] - p[i], b = p[(i + p.size() - 1) % p.size()] - p[i];
      const double la = std::sqrt(a.squared_length()), lb = std::sqrt(b.squared_length());
      if(!(la > 0) || !(lb > 0)) { corner(0., -1., p.size() == 4); continue; }
      const double ang = std::atan2(std::sqrt(CGAL::cross_product(a, b).squared_length()), a * b) * 180 / CGAL_PI;
      corner(ang, nl > 0 ? (CGAL::cross_product(a, b) * n) / (la * lb * nl) : 0., p.size() == 4);
    }
    face_done(p.size() == 4);
  }
}

} // namespace

Json remesh_quality(const Mesh& out)
{
  double amin = 360, amax = 0, jmin = 1, jsum = 0;
  std::size_t jn = 0, nonconvex = 0;
  bool folded = false;
  for_each_corner(out, [&](double ang, double j, bool quad) {
    amin = (std::min)(amin, ang);
    amax = (std::max)(amax, ang);
    if(!quad) return;
    jmin = (std::min)(jmin, j);
    jsum += j;
    ++jn;
    folded = folded || j <= 0;
  }, [&](bool) { nonconvex += folded; folded = false; });
  Json q = Json::object();
  q["min_corner_angle_deg"] = amin;
  q["max_corner_angle_deg"] = amax;
  if(jn) { q["min_scaled_jacobian"] = jmin; q["mean_scaled_jacobian"] = jsum / double(jn); q["nonconvex_quads"] = nonconvex; }
  return q;
}

std::size_t nonconvex_quads(const Mesh& out)
{
  std::size_t nonconvex = 0;
  bool folded = false;
  for_each_corner(out, [&](double, double j, bool quad) { folded = folded || (quad && j <= 0); },
                  [&](bool) { nonconvex += folded; folded = false; });
  return nonconvex;
}

namespace {
typedef CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_face_graph_triangle_primitive<Mesh>>> Face_tree;
}

struct Input_faces_tree::Tree
{
  explicit Tree(const Mesh& m) : tree(faces(m).first, faces(m).second, m) { tree.accelerate_distance_queries(); }
  Face_tree tree;
};

Input_faces_tree::Input_faces_tree(const Mesh& input) : input_(input) {}
Input_faces_tree::~Input_faces_tree() = default;

const Input_faces_tree::Tree& Input_faces_tree::tree() const
{
  if(!tree_) tree_.reset(new Tree(input_));
  return *tree_;
}

face_descriptor Input_faces_tree::closest_face(const K::Point_3& p) const { return tree().tree.closest_point_and_primitive(p).second; }

double Input_faces_tree::squared_distance(const K::Point_3& p) const { return tree().tree.squared_distance(p); }

On_input_measures measures_on_input(const Input_faces_tree& tree, const Mesh& out)
{
  On_input_measures r;
  const Mesh& input = tree.mesh();
  if(num_faces(input) == 0 || num_faces(out) == 0) return r;
  std::vector<K::Point_3> corners;
  double sum = 0;
  r.min_scaled_jacobian = 1;
  for(face_descriptor f : faces(out)) {
    corners.clear();
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, out), out)) corners.push_back(out.point(target(h, out)));
    double c[3] = {0, 0, 0};
    for(const K::Point_3& p : corners) { c[0] += p.x(); c[1] += p.y(); c[2] += p.z(); }
    const std::size_t k = corners.size();
    const K::Point_3 centroid(c[0] / double(k), c[1] / double(k), c[2] / double(k));
    K::Vector_3 area(0, 0, 0);   // the polygon's area vector (fan from its first corner)
    for(std::size_t i = 1; i + 1 < k; ++i) area = area + CGAL::cross_product(corners[i] - corners[0], corners[i + 1] - corners[0]);
    const face_descriptor near = tree.closest_face(centroid);
    const halfedge_descriptor g = halfedge(near, input);
    K::Vector_3 n = CGAL::cross_product(input.point(target(g, input)) - input.point(source(g, input)),
                                        input.point(target(next(g, input), input)) - input.point(source(g, input)));
    r.flipped_faces += area * n < 0;
    const double ln = std::sqrt(n.squared_length());
    double worst = 1;
    for(std::size_t i = 0; i < k; ++i) {
      const K::Vector_3 a = corners[(i + 1) % k] - corners[i], b = corners[(i + k - 1) % k] - corners[i];
      const double l = std::sqrt(a.squared_length() * b.squared_length()) * ln;
      worst = (std::min)(worst, l > 0 ? (CGAL::cross_product(a, b) * n) / l : -1.);
    }
    r.min_scaled_jacobian = (std::min)(r.min_scaled_jacobian, worst);
    sum += worst;
    r.folded_faces += worst <= 0;
  }
  r.mean_scaled_jacobian = sum / double(num_faces(out));
  return r;
}

// Two-sided distance between input and remesh, over the edge length: output vertices to the
// input surface, input vertices to the remesh (its faces fanned into triangles).
Json remesh_distances(const Input_faces_tree& input_tree, const Mesh& out, double h)
{
  const Mesh& input = input_tree.mesh();
  Mesh fan;
  for(vertex_descriptor v : vertices(out)) fan.add_vertex(out.point(v));
  std::vector<vertex_descriptor> vs;
  for(face_descriptor f : faces(out)) {
    vs.clear();
    for(halfedge_descriptor hh : CGAL::halfedges_around_face(halfedge(f, out), out)) vs.push_back(target(hh, out));
    for(std::size_t i = 1; i + 1 < vs.size(); ++i) fan.add_face(vs[0], vs[i], vs[i + 1]);
  }
  // largest distance from `points` to a surface (and in `first`, from the first `split` of them)
  auto farthest = [](const std::vector<K::Point_3>& points, const auto& squared_distance, std::size_t split, double& first) {
    first = 0;
    double d = 0;
    for(std::size_t i = 0; i < points.size(); ++i) {
      d = (std::max)(d, squared_distance(points[i]));
      if(i + 1 == split) first = std::sqrt(d);
    }
    return std::sqrt(d);
  };
  // The remesh's vertices lie on the input by construction, so its distance is that of its
  // faces: sampled at the vertices, the midpoints of its edges and the centroids of its faces'
  // fan triangles. The input is sampled at its vertices (finer than the remesh in practice).
  std::vector<K::Point_3> remesh_points, input_points;
  for(vertex_descriptor v : vertices(out)) remesh_points.push_back(out.point(v));
  for(edge_descriptor e : edges(out)) remesh_points.push_back(CGAL::midpoint(out.point(source(halfedge(e, out), out)), out.point(target(halfedge(e, out), out))));
  for(face_descriptor f : faces(fan)) {
    const halfedge_descriptor g = halfedge(f, fan);
    remesh_points.push_back(CGAL::centroid(fan.point(source(g, fan)), fan.point(target(g, fan)), fan.point(target(next(g, fan), fan))));
  }
  for(vertex_descriptor v : vertices(input)) input_points.push_back(input.point(v));
  // the two directions on two threads: at 433k faces several seconds, the largest part of a run
  double d1 = 0, d2 = 0, d1_vertices = 0, unused = 0;
  std::exception_ptr failure;
  std::thread other([&] {
    try {
      if(num_faces(fan) == 0) return;
      const Face_tree fan_tree(faces(fan).first, faces(fan).second, fan);
      d2 = farthest(input_points, [&](const K::Point_3& p) { return fan_tree.squared_distance(p); }, 0, unused);
    } catch(...) { failure = std::current_exception(); }
  });
  try {
    if(num_faces(input) > 0) d1 = farthest(remesh_points, [&](const K::Point_3& p) { return input_tree.squared_distance(p); }, num_vertices(out), d1_vertices);
  } catch(...) { other.join(); throw; }
  other.join();
  if(failure) std::rethrow_exception(failure);
  Json d = Json::object();
  d["remesh_to_input"] = d1 / h;
  d["vertices_to_input"] = d1_vertices / h;
  d["input_to_remesh"] = d2 / h;
  return d;
}

// Area of the remesh (its faces fanned into triangles) over that of the input.
double remesh_area_ratio(const Mesh& input, const Mesh& out)
{
  double a = 0, b = 0;
  for(face_descriptor f : faces(input)) {
    const halfedge_descriptor h = halfedge(f, input);
    a += std::sqrt(CGAL::squared_area(input.point(source(h, input)), input.point(target(h, input)), input.point(target(next(h, input), input))));
  }
  for(face_descriptor f : faces(out)) {
    std::vector<K::Point_3> p;
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, out), out)) p.push_back(out.point(target(h, out)));
    for(std::size_t i = 1; i + 1 < p.size(); ++i) b += std::sqrt(CGAL::squared_area(p[0], p[i], p[i + 1]));
  }
  return a > 0 ? b / a : 0;
}

std::vector<double> grid_curvatures(const Mesh& remesh)
{
  std::vector<double> K(num_vertices(remesh), 2 * CGAL_PI);
  for(face_descriptor f : faces(remesh)) {
    const std::size_t n = CGAL::halfedges_around_face(halfedge(f, remesh), remesh).size();
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, remesh), remesh))
      K[index(target(h, remesh))] -= n == 4 ? CGAL_PI / 2 : n == 3 ? CGAL_PI / 3 : 0.;
  }
  return K;
}

double metric_area(const Mesh& mesh, const Edge_length_property& l)
{
  double a = 0;
  for(face_descriptor f : faces(mesh)) {
    const halfedge_descriptor h = halfedge(f, mesh);
    const double x = l[edge(h, mesh)], y = l[edge(next(h, mesh), mesh)], z = l[edge(prev(h, mesh), mesh)];
    const double s = 0.5 * (x + y + z);
    a += std::sqrt((std::max)(0., s * (s - x) * (s - y) * (s - z)));
  }
  return a;
}

} // namespace smdf_cli
