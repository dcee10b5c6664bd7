// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// smdf remesh: the polyhedra of --polycube (see remesh_polyhedra.h).

#include "remesh_polyhedra.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace smdf_cli {

std::vector<vertex_descriptor> extreme_vertices(const Mesh& mesh, const std::vector<K::Vector_3>& directions)
{
  K::Vector_3 c(0, 0, 0);
  for(vertex_descriptor v : vertices(mesh)) c = c + (mesh.point(v) - CGAL::ORIGIN) / double(num_vertices(mesh));
  double scale = 0;
  for(vertex_descriptor v : vertices(mesh)) scale = (std::max)(scale, std::sqrt((mesh.point(v) - (CGAL::ORIGIN + c)).squared_length()));
  std::vector<vertex_descriptor> out;
  std::vector<char> taken(num_vertices(mesh), 0);
  for(const K::Vector_3& d0 : directions) {
    const K::Vector_3 d = d0 / std::sqrt(d0.squared_length());
    double best = -1e300;
    vertex_descriptor pick = *vertices(mesh).begin();
    for(vertex_descriptor v : vertices(mesh)) {
      if(taken[std::size_t(v)]) continue;
      const K::Vector_3 x = mesh.point(v) - (CGAL::ORIGIN + c);
      const double along = x * d, off = std::sqrt((std::max)(0., x.squared_length() - along * along));
      const double score = along - 1e-9 * off;
      if(score > best + 1e-12 * scale) { best = score; pick = v; }
    }
    taken[std::size_t(pick)] = 1;
    out.push_back(pick);
  }
  return out;
}

std::array<vertex_descriptor, 8> box_corners(const Mesh& mesh)
{
  std::vector<K::Vector_3> d;
  for(int i = 0; i < 8; ++i) d.push_back(K::Vector_3((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1));
  const std::vector<vertex_descriptor> v = extreme_vertices(mesh, d);
  std::array<vertex_descriptor, 8> out;
  std::copy(v.begin(), v.end(), out.begin());
  return out;
}

std::vector<vertex_descriptor> axis_corners(const Mesh& mesh)
{
  return extreme_vertices(mesh, {K::Vector_3(1, 0, 0), K::Vector_3(-1, 0, 0), K::Vector_3(0, 1, 0), K::Vector_3(0, -1, 0),
                                 K::Vector_3(0, 0, 1), K::Vector_3(0, 0, -1)});
}

void check_polyhedron_cones(const std::string& polycube, const std::vector<vertex_descriptor>& corners,
                            const std::vector<double>& curvature, const std::vector<std::pair<vertex_descriptor, double>>& cones)
{
  std::map<vertex_descriptor, double> given(cones.begin(), cones.end());
  for(std::size_t i = 0; i < corners.size(); ++i) {
    auto it = given.find(corners[i]);
    if(it == given.end() || std::abs(it->second - curvature[i]) > 1e-9)
      throw Error(polycube + ": the polyhedron does not match the cones: its corner " + std::to_string(index(corners[i])) +
                  " has curvature " + format_real(curvature[i]) + " (2 pi minus its face angles), --cones gives " +
                  (it == given.end() ? std::string("none") : format_real(it->second)));
    given.erase(it);
  }
  if(!given.empty())
    throw Error(polycube + ": the polyhedron does not match the cones: vertex " + std::to_string(index(given.begin()->first)) +
                " of --cones is no corner of the polyhedron");
}

void read_polyhedron(const std::string& file, const Mesh& mesh, std::vector<vertex_descriptor>& corners, std::vector<std::vector<int>>& faces)
{
  std::map<std::size_t, int> corner_of;
  for_each_data_line(file, [&](std::size_t line_no, const std::vector<std::string>& fields) {
    if(fields.size() != 3 && fields.size() != 4)
      throw line_error(file, line_no, "a face has 3 or 4 vertex ids, got " + std::to_string(fields.size()));
    std::vector<int> f;
    for(const std::string& x : fields) {
      const std::size_t v = vertex_field(file, line_no, x, num_vertices(mesh));
      auto it = corner_of.find(v);
      if(it == corner_of.end()) { it = corner_of.emplace(v, int(corners.size())).first; corners.push_back(vertex_descriptor(Mesh::size_type(v))); }
      f.push_back(it->second);
    }
    faces.push_back(f);
  });
  if(faces.empty()) throw file_error(file, "no face in the polyhedron file", "malformed_file");
  std::map<std::pair<int, int>, int> directed;
  for(const auto& f : faces)
    for(std::size_t i = 0; i < f.size(); ++i) ++directed[std::make_pair(f[i], f[(i + 1) % f.size()])];
  for(const auto& d : directed)
    if(d.second != 1 || directed.count(std::make_pair(d.first.second, d.first.first)) == 0)
      throw file_error(file, "the polyhedron is not a closed oriented surface: its edge between vertices " +
                                 std::to_string(std::size_t(corners[std::size_t(d.first.first)])) + " and " +
                                 std::to_string(std::size_t(corners[std::size_t(d.first.second)])) + " is not in exactly two faces of opposite directions",
                       "malformed_file");
  const long chi = long(corners.size()) - long(directed.size() / 2) + long(faces.size());
  if(chi != 2) throw file_error(file, "the polyhedron is not a sphere (Euler characteristic " + std::to_string(chi) + ")", "malformed_file");
}

std::vector<vertex_descriptor> assign_cones(const std::string& preset, const Mesh& mesh, const std::vector<std::pair<vertex_descriptor, double>>& cones,
                                            const std::vector<K::Vector_3>& directions, double K, const char* K_name)
{
  if(cones.size() != directions.size())
    throw Error("--polycube " + preset + " has " + std::to_string(directions.size()) + " corners of curvature " + K_name + "; --cones gives " +
                std::to_string(cones.size()) + " cones");
  for(const auto& c : cones)
    if(std::abs(c.second - K) > 1e-9)
      throw Error("--polycube " + preset + ": its corners have curvature " + K_name + "; --cones gives " + format_real(c.second) + " at vertex " +
                  std::to_string(index(c.first)));
  K::Vector_3 centre(0, 0, 0);
  for(vertex_descriptor v : vertices(mesh)) centre = centre + (mesh.point(v) - CGAL::ORIGIN) / double(num_vertices(mesh));
  std::vector<vertex_descriptor> out;
  std::vector<char> used(cones.size(), 0);
  for(const K::Vector_3& d : directions) {
    std::size_t best = cones.size();
    double best_dot = -1e300;
    for(std::size_t i = 0; i < cones.size(); ++i) {
      const double x = (mesh.point(cones[i].first) - (CGAL::ORIGIN + centre)) * d;
      if(!used[i] && x > best_dot) { best_dot = x; best = i; }
    }
    if(!(best_dot > 0))
      throw Error("--polycube " + preset + ": no cone lies towards corner direction (" + format_real(d.x()) + ", " + format_real(d.y()) + ", " +
                  format_real(d.z()) + ") from the centroid; place one cone near each corner, or give the polyhedron as a file");
    used[best] = 1;
    out.push_back(cones[best].first);
  }
  return out;
}

} // namespace smdf_cli
