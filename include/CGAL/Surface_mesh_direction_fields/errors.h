// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_ERRORS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_ERRORS_H

#include <stdexcept>
#include <string>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/// \ingroup PkgSurfaceMeshDirectionFieldsRef
/// The one exception type of the package: thrown when the input given by the caller
/// cannot be processed. The message names the problem and the numbers involved;
/// `kind()` lets programs react to the category.
/// Expected numerical outcomes (a solver that does not converge) are reported by status
/// objects instead, never by this exception.
class Input_error : public std::invalid_argument
{
public:
  /// Category of the problem.
  enum Kind {
    NOT_TRIANGLE_MESH,   ///< a face has a number of vertices other than three
    NON_MANIFOLD_EDGE,   ///< an edge is shared by more than two faces
    NON_MANIFOLD_VERTEX, ///< the faces around a vertex do not form one fan (pinched vertex)
    NON_ORIENTABLE,      ///< the faces cannot be oriented consistently
    DEGENERATE_FACE,     ///< a face with a zero-length edge, zero area or lengths violating the triangle inequality; in a file, a face with fewer than 3 or repeated vertices
    INVALID_GEOMETRY,    ///< non-finite coordinates or lengths
    INVALID_CYCLE,       ///< a halfedge sequence that is not a cycle of the expected kind
    INCONSISTENT_INDICES, ///< singularity indices of a closed component do not sum to its Euler characteristic
    INVALID_ARGUMENT,    ///< any other argument out of its documented range
    FILE_ERROR           ///< a file that cannot be read or parsed
  };

  Input_error(Kind kind, const std::string& what)
    : std::invalid_argument(what), kind_(kind)
  {}

  /// The category of the problem.
  Kind kind() const { return kind_; }

  /// A short stable name of a category, such as `"non_manifold_edge"`.
  static const char* kind_name(Kind k)
  {
    switch(k) {
      case NOT_TRIANGLE_MESH: return "not_triangle_mesh";
      case NON_MANIFOLD_EDGE: return "non_manifold_edge";
      case NON_MANIFOLD_VERTEX: return "non_manifold_vertex";
      case NON_ORIENTABLE: return "non_orientable";
      case DEGENERATE_FACE: return "degenerate_face";
      case INVALID_GEOMETRY: return "invalid_geometry";
      case INVALID_CYCLE: return "invalid_cycle";
      case INCONSISTENT_INDICES: return "inconsistent_indices";
      case INVALID_ARGUMENT: return "invalid_argument";
      case FILE_ERROR: return "file_error";
    }
    return "unknown";
  }

private:
  Kind kind_;
};

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_ERRORS_H
