// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Meshes generated in code, so tests do something meaningful without ../shared.
#ifndef SMDF_TEST_MESH_GENERATORS_H
#define SMDF_TEST_MESH_GENERATORS_H

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <cmath>
#include <vector>

namespace smdf_test {

struct Soup
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::vector<std::size_t>> faces;
};

// Torus of radii R > r with n x m vertices (wavy, so that metrics are not symmetric).
inline Soup torus_soup(std::size_t n, std::size_t m, double R = 3, double r = 1)
{
  Soup s;
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = 0; j < m; ++j) {
      const double u = 2 * M_PI * i / n, v = 2 * M_PI * j / m;
      const double rr = r * (1 + 0.15 * std::sin(3 * u));
      s.points.push_back({(R + rr * std::cos(v)) * std::cos(u), (R + rr * std::cos(v)) * std::sin(u),
                          rr * std::sin(v)});
    }
  auto id = [&](std::size_t i, std::size_t j) { return (i % n) * m + (j % m); };
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = 0; j < m; ++j) {
      s.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      s.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return s;
}

// Open cylinder (annulus: 2 boundary loops) with n x m vertices.
inline Soup cylinder_soup(std::size_t n, std::size_t m)
{
  Soup s;
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = 0; j < m; ++j) {
      const double u = 2 * M_PI * i / n;
      s.points.push_back({std::cos(u) * (1 + 0.1 * j), std::sin(u), double(j) / (m - 1)});
    }
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = 0; j + 1 < m; ++j) {
      const std::size_t a = i * m + j, b = ((i + 1) % n) * m + j;
      s.faces.push_back({a, b, b + 1});
      s.faces.push_back({a, b + 1, a + 1});
    }
  return s;
}

template <typename Mesh>
void soup_to_mesh(const Soup& s, Mesh& mesh)
{
  typedef typename boost::property_traits<
      typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type Point;
  std::vector<Point> pts;
  for(const auto& p : s.points) pts.push_back(Point(p[0], p[1], p[2]));
  CGAL::clear(mesh);
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(pts, s.faces, mesh);
}

} // namespace smdf_test

#endif
