// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// smdf remesh: the grid's inverted faces and folded quads unfolded along the input surface
// (untangle_remesh()), the cones held first, then free to slide.

#ifndef SMDF_CLI_REMESH_UNTANGLE_H
#define SMDF_CLI_REMESH_UNTANGLE_H

#include "common.h"

#include <string>

namespace smdf_cli {

// The inverted faces of a remesh unfolded along the input surface (untangle_remesh()), the
// cones (vertices whose faces do not fill 2 pi in the grid's angles) held; where faces next to a
// cone stay inverted (a cone on a sharp tip, which the metric shrinks to less than a face), a
// second pass lets the cones slide along the surface too, keeping their valences. Once none is
// inverted, quads folded at a corner are unfolded as far as moves along the surface can (best
// effort: `ok` does not depend on it). `ok` says whether no inverted face is left (true when
// the grid had none: called for folded quads alone, a failure leaves the grid as it was), `left`
// how many are (on entry: the tessellation's count), `message` why. Returns the JSON of what was
// done.
Json untangle_inverted(const Mesh& input, Mesh& remesh, bool& ok, std::size_t& left, std::string& message);

} // namespace smdf_cli

#endif // SMDF_CLI_REMESH_UNTANGLE_H
