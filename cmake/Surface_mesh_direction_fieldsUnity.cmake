# SPDX-License-Identifier: GPL-3.0-or-later
# smdf_unity_groups(target dir): compile the smdf tool's heavy sources in dir as two unity files
# (used by the tool and by the fuzz target that links the whole tool).
include_guard(GLOBAL)

# smdf_tool_sources(out dir): every source of the smdf tool, as paths under dir. The tool and the
# fuzz target that links the whole tool both take this list, so a new source file cannot be
# missing from one of them.
function(smdf_tool_sources out dir)
  set(names main args help huge_page_new common cmd_info cmd_generators cmd_holonomy cmd_connection
    cmd_singularities cmd_cone_metric cmd_rosy rosy_inputs rosy_punched cmd_remesh cmd_remesh_help
    remesh_measures remesh_pictures remesh_polyhedra remesh_untangle remesh_placed_cones)
  set(paths)
  foreach(n ${names})
    list(APPEND paths "${dir}/${n}.cpp")
  endforeach()
  set(${out} ${paths} PARENT_SCOPE)
endfunction()

# Each heavy source includes CGAL and the package; as two unity files, every template the
# commands share (Surface_mesh, the reader, Trivial_connection, the cone metric) is instantiated
# twice instead of eleven times (fresh Release build of smdf on 2 cores: 263 s as 15 files,
# 134 s this way). Two groups keep both cores busy. main, args and help stay separate.
function(smdf_unity_groups target dir)
  if(CMAKE_VERSION VERSION_LESS 3.18)
    return()
  endif()
  set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_MODE GROUP)
  foreach(f common cmd_info cmd_generators cmd_holonomy cmd_connection cmd_singularities rosy_inputs rosy_punched cmd_rosy)
    set_source_files_properties("${dir}/${f}.cpp" TARGET_DIRECTORY ${target} PROPERTIES UNITY_GROUP fields)
  endforeach()
  foreach(f cmd_cone_metric cmd_remesh remesh_measures remesh_pictures remesh_polyhedra remesh_untangle remesh_placed_cones)
    set_source_files_properties("${dir}/${f}.cpp" TARGET_DIRECTORY ${target} PROPERTIES UNITY_GROUP metrics)
  endforeach()
endfunction()
