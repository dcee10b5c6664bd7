// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// X-macro list of the package's own named parameters (no include guard on purpose).
// Each line: CGAL_SMDF_add_named_parameter(tag_type, tag_value, function_name)

CGAL_SMDF_add_named_parameter(edge_length_t, edge_length, edge_length_map)
CGAL_SMDF_add_named_parameter(symmetry_order_t, symmetry_order, symmetry_order)
CGAL_SMDF_add_named_parameter(connection_weights_t, connection_weights, connection_weights)
CGAL_SMDF_add_named_parameter(generator_turning_numbers_t, generator_turning_numbers, generator_turning_numbers)
CGAL_SMDF_add_named_parameter(solver_t, solver, solver)
CGAL_SMDF_add_named_parameter(cotangent_clamp_t, cotangent_clamp, cotangent_clamp)
CGAL_SMDF_add_named_parameter(conformal_factor_t, conformal_factor, conformal_factor_map)
CGAL_SMDF_add_named_parameter(curvature_tolerance_t, curvature_tolerance, curvature_tolerance)
CGAL_SMDF_add_named_parameter(singularity_index_t, singularity_index, singularity_index_map)
CGAL_SMDF_add_named_parameter(directional_constraints_t, directional_constraints, directional_constraints)
CGAL_SMDF_add_named_parameter(guide_directions_t, guide_directions, guide_directions)
CGAL_SMDF_add_named_parameter(guide_weight_t, guide_weight, guide_weight)
CGAL_SMDF_add_named_parameter(face_angle_t, face_angle, face_angle_map)
CGAL_SMDF_add_named_parameter(intrinsic_edge_flips_t, intrinsic_edge_flips, intrinsic_edge_flips)
