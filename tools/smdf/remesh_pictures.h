// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// smdf remesh: its pictures, --svg (the remesh and its cones) and --knot-svg (a Celtic knot).

#ifndef SMDF_CLI_REMESH_PICTURES_H
#define SMDF_CLI_REMESH_PICTURES_H

#include "common.h"

namespace smdf_cli {

// --svg: the remesh itself, its faces shaded and painted back to front (back faces culled), its
// edges stroked, its cones marked: the vertices whose faces' corner angles of the grid (pi/2 in a
// quad, pi/3 in a triangle) do not sum to 2 pi, with index K / 2 pi.
void write_remesh_svg(const Args& args, const Mesh& input, const Mesh& remesh, int N);

// --knot-svg: a woven Celtic knot on a quad remesh (Lai et al. Fig. 13): the strands follow the
// medial graph (in each quad, a curve from the midpoint of each edge to that of the next one,
// bent towards their shared corner) and cross at every edge midpoint. Each curve passes over at
// the crossing where it starts (counterclockwise in its quad) and under where it ends, which
// alternates along every strand (the two curves of one strand at a crossing both end there or
// both start there); "under" is drawn as a gap. Drawn on the remesh fanned into triangles.
void write_knot_svg(const Args& args, const Mesh& input, const Mesh& remesh);

} // namespace smdf_cli

#endif // SMDF_CLI_REMESH_PICTURES_H
