// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// smdf remesh: its options and help text (the command itself: cmd_remesh.cpp).

#include "commands.h"

namespace smdf_cli {

Command remesh_command()
{
  return {"remesh", {"MESH"},
          {{"grid", "G", "quad (default), triangle, or mixed (with a polyhedron of squares and triangles)"},
           {"edge-length", "H", "the grid's edge length on the surface"},
           {"faces", "N", "about N faces instead (the admissible edge length nearest to area / N)"},
           {"polycube", "P", "metric compensation with a polyhedron: 'box' (corners: the 8 vertices extreme in the diagonal directions from the centroid), 'octahedron' (the 6 extreme along the axes; triangles), 'obelisk' (Lai et al. Fig. 1c, y up: mixed), or a file: one face per line, its 3 or 4 vertex ids counterclockwise from outside (squares or triangles; six quadrilaterals glued as a cube's make a box, scaled along its axes as the preset)"},
           {"lengths", "FILE", "the flat cone metric: one line 'i j length' per edge (e.g. cone-metric --no-flips --lengths-out)"},
           {"cones", "LIST", "cone curvatures 'v:K,...' (K radians: pi/2, 2pi/3, ...): the flat cone metric to tessellate, or the corners of --polycube"},
           {"cone-indices", "LIST", "the same as indices 'v:k,...', K = 2 pi k"},
           {"out", "FILE", "write the remesh (.off or .obj)"},
           {"svg", "FILE", "write an SVG picture of the remesh (on the input surface), its cones marked"},
           {"view", "A,E[,UP]", "view of --svg: azimuth,elevation in degrees, up axis x|y|z"},
           {"width", "PX", "width of the --svg picture in pixels (default 800)"},
           {"knot-svg", "FILE", "write a woven Celtic knot along the quad remesh's medial graph (Lai et al. Fig. 13)"},
           {"segments", "relaxed|ricci", "with --polycube: how the pieces between the polyhedron's edges are mapped onto its faces: relaxed (default: stretch-minimising Tutte embedding relaxed as rigidly as possible, grid cells of even size) or ricci (Lai et al.: each piece flattened by Ricci flow to its polygon, conformal; the two pieces beside an edge path disagree on its vertices, whose mean is taken: max_side_parameter_gap)"},
           {"relaxation", "K", "with --polycube: one round of stretch-minimising reweighting, then at most K steps of as-rigid-as-possible relaxation of the polyhedron's charts (fewer once a triangle about to fold throttles a step below 1 %) and 3K sweeps across its edges near the paths (default 10; 0: the plain Tutte embedding)"},
           {"no-untangle", "", "keep the grid's faces that come out inverted on the surface (default: their vertices are moved along the input until none is, the cones held, or slid along the surface where holding them leaves faces inverted, then quads folded at a corner unfolded as far as such moves can; reported as untangle)"},
           {"place-cones", "", "automatic cones (the default for quads without --cones, --lengths or --polycube, unless every curvature of the input is a multiple of pi/2): meshes of any genus, closed or open; place the cones (cone-metric --place-cones; on an open mesh also the boundary's corners, turning by multiples of pi/2), compute their flat cone metric on the input's edges, the cross field of the trivial connection on it (on an open mesh: parallel to the boundary, straight between the corners) and an integer-grid map whose boundary runs along grid lines, and tessellate that (see the manual)"},
           {"distortion-bound", "B", "automatic cones: the cone metric's log scale within B (default 2, then 1 and 0.5 while every attempt fails; given, only B)"},
           {"max-cones", "n", "automatic cones: at most n cones (default 500)"},
           {"uv-out", "FILE", "automatic cones: write the integer-grid map as OBJ, one vt per face corner (a seamless parametrization in grid units; the triangulation is the Delaunay refinement's when the metric needed it); when every remesh fails its read-back after some attempt's map was valid, that map is still written (exit 3, JSON uv_out_attempt: its index in placement_attempts)"},
           {"cone-spacing", "S", "automatic cones: at least S grid edges apart (along the input's edges) where the placement can; default: 4, then 2, 0 (only never adjacent) and 6 while the map or the remesh fails"},
           {"progress", "", "report each stage on stderr with the elapsed time"}},
          "regular quad or triangle remesh from a flat cone metric",
          "Lai et al. 2010, section 5: develops a flat cone metric of the mesh (its own edge lengths,\n"
          "--lengths, the metric with --cones computed without flips on the input triangulation or,\n"
          "where that cannot carry it, on its conforming Delaunay refinement (vertices added on the\n"
          "input's edges only, so the remesh still lies on the input), or the metric of a\n"
          "polyhedron: --polycube box | octahedron | obelisk | FILE, genus 0 only; with --cones the box's\n"
          "or octahedron's corners are the given cones, by direction from the centroid, and a FILE's\n"
          "corners must carry exactly the given curvatures; P's edges become shortest paths under\n"
          "the flat cone metric with P's cones, computed with intrinsic flips to a curvature error of\n"
          "1e-6, of which they need only the conformal factors; Euclidean paths if it does not\n"
          "converge) and carries the square (quad)\n"
          "or triangular grid onto the surface. The cut graph's motions must be symmetries of the\n"
          "grid (Theorem 3.5) and the cones grid points; otherwise the failing edges are reported.\n"
          "Output vertices lie on the input triangles (barycentric placement); every interior\n"
          "vertex has valence 4 (6) except at a cone of curvature K: 4 - K/(pi/2) (6 - K/(pi/3)).\n"
          "Prints {grid, metric: {source, converged, iterations, max_curvature_error,\n"
          "delaunay_refinement: {input_triangulation_message, success, faces, inserted_vertices} (when\n"
          "used), flat_cone_metric_converged, flat_cone_metric_edge_flips, corners,\n"
          "dimensions or side_length, max_path_stretch, relaxation_steps, seam_relaxed_vertices, segments,\n"
          "max_side_parameter_gap with --segments ricci},\n"
          "edge_length, cut_edges, cones, grid_spacing_of_metric, failing_cut_edges (first 20),\n"
          "failing_cut_edge_deviations (theirs: {rotation (radians from the grid's rotations),\n"
          "translation (grid edges from the lattice)}),\n"
          "failing_cut_edge_count (edge indices of the triangulation carrying the metric: the\n"
          "refinement's when delaunay_refinement is present), vertices, faces_by_size, valences\n"
          "(interior vertices),\n"
          "irregular_vertices: [{vertex, cone, valence}], inverted_faces (after untangling),\n"
          "flipped_faces (faces whose normal opposes the input's at the input point nearest their\n"
          "centroid; exit 3 if any),\n"
          "untangle (when the grid had inverted faces, faces flipped nearest their centroid, nonconvex\n"
          "quads or faces folded on the input: {grid_inverted_faces, inverted_before, inverted_after (by the normals of the input faces\n"
          "nearest the corners, and of those nearest the face's centroid), moved_vertices,\n"
          "cones_moved (0 unless holding the cones left faces inverted: then a second pass lets them\n"
          "slide along the surface, valences kept), folded_before, folded_after (quads folded at a\n"
          "corner, against their own area vector, the input's normals under their corners or at the\n"
          "input point nearest their centroid, inverted ones included;\n"
          "unfolded once none is inverted, best effort; untangle also runs when the grid has\n"
          "nonconvex quads and nothing inverted, and cannot fail then; automatic cones still fail on\n"
          "quads left folded),\n"
          "max_displacement_over_edge_length,\n"
          "straddling_faces (left across a thin part or tip), faces_at_held_vertices (left next to a\n"
          "cone held), rounds}; a failed\n"
          "untangling moves no vertex), quality:\n"
          "{min_corner_angle_deg, max_corner_angle_deg, min_scaled_jacobian, mean_scaled_jacobian,\n"
          "nonconvex_quads (a scaled Jacobian of at most 0 at some corner), min_scaled_jacobian_on_input,\n"
          "mean_scaled_jacobian_on_input (each face's worst corner along the normal of the input face\n"
          "nearest its centroid, the measure of benchmark/compare_quadriflow.py),\n"
          "faces_folded_on_input (a corner at most 0 by it; reported, not failed)},\n"
          "distance_over_edge_length: {remesh_to_input (largest distance of the remesh's vertices,\n"
          "edge midpoints and face-fan centroids to the input), input_to_remesh (of the input's\n"
          "vertices to the remesh), vertices_to_input (of the remesh's vertices alone: 0 up to\n"
          "rounding, they are placed on the input)}: the two-sided Hausdorff distance, sampled, over\n"
          "the edge length, area_ratio (remesh over\n"
          "input), timings: {metric_s,\n"
          "compensation_s, tessellation_s, untangle_s when untangling}, success}. With a mixed grid\n"
          "(obelisk, or a FILE of squares\n"
          "and triangles) each face of P gets its own grid: subdivisions, unexpected_valences, and\n"
          "irregular_vertices: [{vertex, cone, valence, curvature}] (vertices whose faces do not fill\n"
          "2 pi in the grid's angles, cone: P's corner there or null); compensation_s is null (in\n"
          "tessellation_s); polyhedron_compatibility (also with the octahedron and files of one\n"
          "kind of face): {compatible, max_angle_deviation (radians),\n"
          "max_side_deviation (grid edges), curved_vertices, failing_faces: [{face, angle_deviation,\n"
          "side_deviation}]}: the mixed grid's Theorem 3.5 test on the metric built, every face of P\n"
          "developed again from the edge lengths must be a square or triangle of whole grid edges\n"
          "and every other vertex flat. --grid must agree with a FILE's faces (quad, triangle or mixed).\n"
          "An input with faces of more than 3 vertices (quads, polygons) is triangulated first\n"
          "(triangulated_polygons: how many); vertex indices stay those of the file.\n"
          "Exit code 3 (JSON printed) when the metric is\n"
          "incompatible with the grid, the edge length does not fit its lattice, or the read-back\n"
          "fails (valences, inverted faces, the polyhedron test); the remesh is still written when its\n"
          "faces exist.\n"
          "Automatic cones (--place-cones; the default for --grid quad without --cones, --lengths or\n"
          "--polycube unless every curvature of the input is a multiple of pi/2, as on a cube, whose\n"
          "own metric is then tessellated; meshes of any genus, closed or open): the cones (and on an\n"
          "open mesh the boundary's corners, where the input's boundary turns by about pi/2) are placed as by\n"
          "cone-metric --place-cones, their flat cone metric is computed on the input's edges or,\n"
          "where they cannot carry it, on the conforming Delaunay refinement (as with --cones) or,\n"
          "where neither can, with intrinsic flips (metric: intrinsic_edge_flips, and\n"
          "intrinsic_triangulation: true when the remesh was made on that triangulation and placed on\n"
          "the input through its common subdivision; --uv-out is then refused), made seamless on genus\n"
          ">= 1 or with several boundary loops by seamless_cone_metric() on that triangulation\n"
          "(metric.seamless: {success, message, loops, iterations, initial_holonomy_error,\n"
          "holonomy_error, max_log_length_change}) or, where it fails, by\n"
          "seamless_intrinsic_cone_metric() with intrinsic flips (metric.seamless.with_flips:\n"
          "{cone_metric_converged, success, message, iterations, initial_holonomy_error,\n"
          "holonomy_error, curvature_error, cone_metric_flips, edge_flips, min_angle,\n"
          "correspondence}; the remesh is then made on its triangulation and placed on the input\n"
          "through its common subdivision), the\n"
          "trivial connection's cross field with those singularities (smoothest turning around the\n"
          "handles; on an open mesh the field parallel to the boundary) is integrated into an\n"
          "integer-grid map (seams: rotations by multiples of pi/2 and integer translations;\n"
          "singularities and corners on grid points, the boundary on grid lines; exit 3 if a triangle\n"
          "folds, or if a quad stays folded at a corner after untangling), whose edge lengths are the metric tessellated with edge length\n"
          "1 (edge_length 1 in grid units). The JSON adds placed_cones: [{vertex, curvature}],\n"
          "placement: {success, message, distortion_bound, scale_spread, negative_cone_quanta (2 on a\n"
          "genus whose 4|chi| cones of -pi/2 alone exceed half of --max-cones: cones of -pi, valence 6)},\n"
          "placement_attempts:\n"
          "[{distortion_bound, cone_spacing, cones_moved, cones, message, stage_timings, and where\n"
          "measured holonomy_error_before_moves, cone_moves, seamless_holonomy_error,\n"
          "seamless_with_flips: {success, holonomy_error, edge_flips, message},\n"
          "seamless_folded_triangles, folded_triangles, min_area_ratio}] (the cones are placed 4 grid\n"
          "edges apart first; a map that folds or a remesh that fails its read-back is tried again\n"
          "with them 2, 0, then 6 apart, unless --cone-spacing is given, then, unless\n"
          "--distortion-bound is given, with the bound halved and quartered at spacings 4, 2 and 6;\n"
          "an attempt that places the same cones as an earlier one is skipped; interior cones nearer\n"
          "each other than 1.5 grid edges under their metric are separated, opposite pairs cancelled\n"
          "(metric.cone_separation: {close_cones_before, close_cones_after, cancelled_pairs,\n"
          "moved_cones}); on meshes of genus > 0 or with several boundary\n"
          "loops each spacing first moves interior cones a few rings so that the metric's holonomies\n"
          "start near multiples of pi/2 (metric.cone_moves: {moves, initial_holonomy_error,\n"
          "holonomy_error}) and, if that remesh fails, tries the cones as placed), stage_timings (the last\n"
          "attempt's: placement_s, cone_metric_s, cross_field_s, integer_grid_map_s) and integer_grid_map:\n"
          "{success, message, singularities, seams, boundary_corners, boundary_lines, rounded_values, t_mesh_arcs (arcs of the\n"
          "seamless map's T-mesh, kept nonnegative by the rounding; t_mesh_failure: why none were traced), rounded_apart,\n"
          "held_arcs, collapsed_arcs, negative_arcs, t_mesh_spans (boundary runs between corners, separatrices from a cone\n"
          "or corner to the boundary or a cone: kept at least 1 long), short_spans, t_mesh_faces (its rectangles; a\n"
          "collapsed one, width or height 0, is routed otherwise or folds: collapsed_faces), arcs_kept (the map is the second\n"
          "rounding's, which kept the arcs:\n"
          "the first, greedy, folded), folded_triangles,\n"
          "winding_faults (vertices the map wraps around wrongly), stiffening_rounds, seamless_energy, seamless_folded_triangles (before rounding), integer_energy,\n"
          "min_area_ratio}. An attempt whose placement takes --max-cones cones or more fails at once\n"
          "(the map's time grows as their cube).\n",
          run_remesh};
}


} // namespace smdf_cli
