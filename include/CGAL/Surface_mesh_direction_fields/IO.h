// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
// The package's input and output: validated mesh reading and SVG pictures. Not included by the
// core headers; the umbrella header includes it when CGAL_SURFACE_MESH_DIRECTION_FIELDS_WITH_IO
// is defined.

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_H

#include <CGAL/Surface_mesh_direction_fields/IO/read_triangle_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/IO/svg_writer.h>

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_H
