// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

/*!
\ingroup PkgSurfaceMeshDirectionFieldsConcepts
\brief A progress callback of the discrete Ricci flow of
`CGAL::Surface_mesh_direction_fields::compute_cone_metric()`.

\cgalConcept

The type of the `visitor` named parameter of
`CGAL::Surface_mesh_direction_fields::compute_cone_metric()` (see \ref SMDFSecConeMetrics).

It is called as `visitor(iteration, max_error)`:

- once with `iteration == 0`, for the input metric, before the first Newton step (not at all
  if the input metric is already invalid for the flow, e.g. a degenerate triangle);
- then once after every accepted Newton step, with `iteration` = 1, 2, 3, ... The numbering
  goes on when the flow switches from the input triangulation to the intrinsic Delaunay
  triangulation (\ref SMDFSecConeMetrics); iteration 0 is not reported again then. The
  `iteration` of the last call equals `CGAL::Surface_mesh_direction_fields::Cone_metric_status::iterations` of the result (the
  final area normalisation is not a Newton step and is not reported).

`max_error` is \f$\max_v |K_v - \bar K_v|\f$ over the non-isolated vertices, in radians, for
the current metric: the unscaled error, whereas the stopping test
(`curvature_tolerance`) scales it and adds the rounding level \f$\rho_v\f$. When holes are
punched at cones of index \f$\geq 1\f$, the flow and hence the visitor run on the holed
surface, whose boundary vertices around the holes carry geodesic curvature.

The return value, if any, is ignored: a visitor cannot stop the flow (use
`number_of_iterations` for that).

<b>Copies.</b> The named-parameter pack stores a copy of the visitor, and
`compute_cone_metric()` copies it once more; the copy is then called (it may be modified: a
non-`const` `operator()` is fine). State that the caller wants to read afterwards must
therefore live outside the visitor: capture it by reference in a lambda, or pass
`std::ref(visitor)`.

\cgalHasModelsBegin
\cgalHasModels{any callable with signature `void(int, double)`: a lambda such as
  `[&log](int it, double err) { log.push_back(err); }`, a function pointer,
  `std::function<void(int, double)>`, or `std::ref` of a function object}
\cgalHasModelsEnd

\code{.cpp}
std::vector<double> errors;
SMDF::Cone_metric_status st = SMDF::compute_cone_metric(mesh, target, lengths,
    SMDF::parameters::visitor([&errors](int iteration, double max_error) {
      errors.push_back(max_error);   // errors[iteration]
    }));
\endcode
*/
class ConeMetricVisitor
{
public:
  /// \name Creation
  /// @{

  /// Copy constructor (the visitor is passed by value).
  ConeMetricVisitor(const ConeMetricVisitor& other);

  /// @}

  /// \name Operations
  /// @{

  /// Called with the number of Newton iterations done so far (0 for the input metric) and
  /// the current maximum curvature error \f$\max_v |K_v - \bar K_v|\f$ in radians.
  void operator()(int iteration, double max_error);

  /// @}
};
