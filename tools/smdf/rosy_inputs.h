// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// smdf rosy: its inputs beyond the option lists: the boundary of an open mesh and the target
// turning angles the field needs there, and the constraint files of --edit and --length.

#ifndef SMDF_CLI_ROSY_INPUTS_H
#define SMDF_CLI_ROSY_INPUTS_H

#include "common.h"

#include <CGAL/Surface_mesh_direction_fields/Trivial_connection.h>
#include <CGAL/Surface_mesh_direction_fields/cone_metric.h>
#include <CGAL/Surface_mesh_direction_fields/delaunay_refinement.h>
#include <CGAL/Surface_mesh_direction_fields/holonomy_group.h>
#include <CGAL/Surface_mesh_direction_fields/homotopy_basis.h>

#include <algorithm>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace smdf_cli {

typedef Mesh::Property_map<vertex_descriptor, double> Vertex_double_property;

enum Boundary_mode { FREE_BOUNDARY, PARALLEL_BOUNDARY, ORTHOGONAL_BOUNDARY };

enum Rosy_method { AUTOMATIC, ROTATION_COMPENSATION, TRIVIAL_CONNECTION, PARALLEL, BOUNDARY_ALIGNED };

// The name of a method in the JSON and the messages.
const char* method_name(Rosy_method m);

// The options of smdf rosy that choose the field: --method, --boundary, --N, --turning (usage
// errors for the combinations that make no sense).
struct Rosy_options
{
  Rosy_method method = AUTOMATIC;
  Boundary_mode boundary = FREE_BOUNDARY;
  bool boundary_given = false;
  long N = 0;   // 0: from the cones
  Indexed_values turning;
};

Rosy_options rosy_options(const Args& args);

// The input's turning angle pi - sum(theta) at every boundary vertex, and the boundary loops.
struct Boundary_geometry
{
  std::vector<double> kappa;                            // per vertex (0 inside)
  std::vector<std::vector<vertex_descriptor>> loops;    // per boundary loop, in order
  std::vector<double> dual_length;                      // per vertex: half its two boundary edges
};

Boundary_geometry boundary_geometry(const Mesh& mesh);

// The target curvatures of an open mesh: the cones inside and at the given boundary vertices;
// at the other boundary vertices the input's turning angle, changed so that Gauss-Bonnet holds
// and the field can exist:
//  - free boundary: every boundary loop turns in total by a multiple of 2 pi / N (so that the
//    loop's holonomy allows a parallel field), the change spread in proportion to boundary length;
//  - boundary-aligned fields: every boundary vertex turns by a multiple of the field's step
//    (2 pi / N; pi / N for odd N, whose directions are lines along the boundary): the input's
//    turning rounded, then moved by a step where the rounding cut most until Gauss-Bonnet holds.
void open_mesh_targets(const Mesh& mesh, const Boundary_geometry& b, int N, Boundary_mode mode,
                       const std::vector<std::pair<vertex_descriptor, double>>& cones, Vertex_double_property targets);

// Open meshes whose flat cone metric with a geodesic boundary stalled: the points where the
// boundary needs a vertex. A cone next to the boundary wants the triangle between it and a
// border edge to open to pi (in the double cover that edge would flip); the middle of every
// border edge of the stalled triangulation seen from its apex under more than 0.8 pi, as
// (edge of `original`, parameter from the source of its halfedge). `mesh` is `original`
// (refinement null) or refine_at_edge_points() of it; `lengths` the stalled lengths on `mesh`'s
// edges when the flow made no flips.
std::vector<std::pair<std::size_t, double>> border_points_to_insert(const Mesh& original, const Mesh& mesh,
                                                                    const SMDF::Delaunay_refinement_status* refinement,
                                                                    const SMDF::Cone_metric_status& cm, const Edge_length_property& lengths);

// An open mesh whose flat cone metric `cm` stalled: the border edges border_points_to_insert()
// finds are split on the input surface and the flow runs again on the refinement, up to 6
// rounds or until it converges. `mesh` then becomes the refinement (the input's vertices first;
// its maps "v:smdf_rosy_target", the new vertices straight, and "e:smdf_rosy_length" made again
// in `targets` and `lengths`) and `r` holds the input and the refinement's status. Returns
// whether the mesh was refined.
struct Boundary_refinement
{
  Mesh original;
  SMDF::Delaunay_refinement_status status;
  int rounds = 0;   // refinements made (0: `mesh` is the input)
};

bool refine_boundary_until_converged(const std::string& file, Mesh& mesh, Vertex_double_property& targets, Edge_length_property& lengths,
                                     SMDF::Cone_metric_status& cm, Boundary_refinement& r);

// Refinements of the input (refine_at_edge_points()), each of the mesh before: per step the
// coarser mesh and the status of its refinement into the next one (stable addresses).
typedef std::vector<std::pair<Mesh*, const SMDF::Delaunay_refinement_status*>> Refinement_chain;

// A face field (angles in the embedded face frames) with its matching, on one mesh.
struct Face_field
{
  Mesh* mesh;
  Face_angle_property angles;
  Edge_matching_property matching;
};

// `field`, on the last refinement of `chain`, brought back through every step to the input's
// faces (transfer_face_field_from_refinement()) and read back there: its singularities must be
// the cones' (indices as prescribed_indices()), and with `aligned` it must follow the boundary
// (orthogonal or parallel). `field` then describes the field on the input; `json` receives
// {found, max_distortion, max_boundary_deviation (aligned)}. Returns why not, empty on success;
// `what` names the refinement in the messages.
std::string bring_back_to_input(const Refinement_chain& chain, Face_field& field, int N,
                                const std::vector<std::pair<vertex_descriptor, double>>& cones, bool aligned, bool orthogonal,
                                const std::string& what, Json& json);

// --edit FILE ('vertex x y z [weight]') and --length FILE ('vertex length [weight]'): the pairs
// and the weight of each (0, no weight given: hard).
struct Constraint_lines
{
  std::vector<std::pair<vertex_descriptor, K::Vector_3>> directions;
  std::vector<std::pair<vertex_descriptor, double>> lengths;
  std::vector<double> weights;
  std::size_t hard() const { return std::size_t(std::count(weights.begin(), weights.end(), 0.)); }
};

// Reads --edit (lengths = false) or --length; Errors name the file and the line.
Constraint_lines read_constraint_file(const std::string& file, const Mesh& mesh, bool lengths);

// --cones auto: the singularities of a smooth curvature-aligned N-RoSy field
// (automatic_singularities(), --alignment-weight, --smoothing-steps; following the boundary for
// --boundary parallel|orthogonal) as cones; `json` receives {N, alignment_weight,
// smoothing_steps, singularities, max_rotation_over_pi_over_N}.
std::vector<std::pair<vertex_descriptor, double>> automatic_cones(const Args& args, const std::string& file, const Mesh& mesh,
                                                                  int N, Boundary_mode mode, Json& json);

// The indices the cones prescribe at interior vertices (rounded to multiples of 1/N, zeros left out).
std::map<vertex_descriptor, double> prescribed_indices(const Mesh& mesh, const std::vector<std::pair<vertex_descriptor, double>>& cones,
                                                       int N);

// --holonomy: per loop of the basis {kind: handle|boundary|cone, cone (its vertex), rotation_over_pi,
// translation, compatible (with the N-RoSy test of `rc`)}.
Json holonomy_loops_json(const SMDF::Homotopy_basis<Mesh>& basis, const SMDF::Holonomy_group& group, const SMDF::Rosy_compatibility& rc);

// The JSON of a flat cone metric: {converged, iterations, max_curvature_error,
// triangulation_changed, on} (`on` only when given: what the metric lives on).
Json metric_json(const SMDF::Cone_metric_status& cm, const char* on);

// smdf rosy with interior cones of index 1 or more (rosy_punched.cpp): holes punched there
// (Lai et al. 4.1.1), the field of the holed surface's flat metric (parallel with --method
// parallel and along the boundary, else its trivial connection: the handles' holonomy
// compensated) carried to the input, each hole filled by unfolding its ring's faces inward, the
// spokes' matching chosen so that the ring vertices keep their indices; read back on the input.
// `targets` are those of the input (cones and boundary turnings); returns the JSON, throws
// Failed_result on a failed read-back. When the holed surface's Ricci flow does not converge and
// `holed_failure` is given, closed meshes and free boundaries (fields that need not be parallel)
// return an empty JSON with its message there instead, for the caller's other route.
Json run_rosy_punched(const Args& args, const std::string& file, Mesh& mesh, int N,
                      const std::vector<std::pair<vertex_descriptor, double>>& cones, Vertex_double_property targets,
                      Rosy_method method, Boundary_mode mode, const SMDF::Svg_options& svg, std::string* holed_failure = nullptr);

// Where holes fail (run_rosy_punched()'s holed_failure): every interior cone of index k >= 1
// keeps the curvature 2 pi (k - floor k) in `targets`, its d neighbours gain 2 pi floor(k) / d
// each; returns [{vertex, index, ring}]. The trivial connection with the cones' own indices then
// gives the field.
Json spread_to_neighbours(const Mesh& mesh, const std::vector<std::pair<vertex_descriptor, double>>& cones, Vertex_double_property targets);

// The least compensation: every generator of `tc` turns by the multiple of 2 pi / N nearest its
// Levi-Civita holonomy (as rotation compensation chooses by default).
void turn_generators_least(SMDF::Trivial_connection<Mesh>& tc, int N);

// {energy, max_rotation, max_holonomy_error, scaled_residual} of a trivial connection's solve.
Json trivial_connection_json(const SMDF::Trivial_connection_status& ts);

// --hatching-svg: streamlines of the face field `vectors` traced on the mesh, drawn in pen and
// ink; returns {strokes, total_length}.
Json write_hatching_svg(const Args& args, const std::string& file, const Mesh& mesh, const Face_vector_property& vectors, int N,
                        const SMDF::Svg_options& svg);

} // namespace smdf_cli

#endif // SMDF_CLI_ROSY_INPUTS_H
