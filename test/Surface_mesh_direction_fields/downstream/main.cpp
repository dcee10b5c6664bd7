// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Downstream consumer: compiled against an installed Surface_mesh_direction_fields found
// with find_package().  Gauss-Bonnet on a regular tetrahedron: total angle defect = 4*pi.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/Surface_mesh_direction_fields/intrinsic_geometry.h>

#include <cmath>
#include <cstdlib>
#include <iostream>

namespace SMDF = CGAL::Surface_mesh_direction_fields;

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_3 = K::Point_3;
using Mesh = CGAL::Surface_mesh<Point_3>;

int main()
{
  Mesh mesh;
  CGAL::make_tetrahedron(Point_3(1, 1, 1), Point_3(1, -1, -1),
                         Point_3(-1, 1, -1), Point_3(-1, -1, 1), mesh);

  const double pi = std::acos(-1.0);
  const double defect = SMDF::total_angle_defect(mesh);
  const double error = std::abs(defect - 4 * pi);
  std::cout.precision(17);
  std::cout << "total angle defect " << defect << ", 4*pi " << 4 * pi
            << ", error " << error << std::endl;
  if (!(error <= 1e-9)) {
    std::cerr << "FAILED: total angle defect of a tetrahedron is not 4*pi" << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "downstream OK" << std::endl;
  return EXIT_SUCCESS;
}
