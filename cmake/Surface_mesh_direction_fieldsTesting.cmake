# SPDX-License-Identifier: GPL-3.0-or-later
# Test helpers for Surface_mesh_direction_fields (included by the top-level CMakeLists.txt).
#
#   smdf_add_test(<name> <target> [args...])
#     add_test(NAME <name> COMMAND <target> args...) with single-threaded BLAS/OpenMP
#     (CONVENTIONS section 7) and exit code 77 meaning "skipped" (e.g. ../shared absent).
#     Add labels etc. afterwards with set_property(TEST <name> APPEND PROPERTY ...), not
#     with set_tests_properties(... ENVIRONMENT ...), which would replace the environment.
#
#   smdf_add_downstream_test()
#     CTest test `downstream_find_package`: installs this build tree into
#     <build>/downstream_prefix, then configures, builds and runs the standalone project in
#     test/Surface_mesh_direction_fields/downstream against it through find_package().

include_guard(GLOBAL)

set(SMDF_TEST_ENVIRONMENT "OPENBLAS_NUM_THREADS=1;OMP_NUM_THREADS=1")
set(_smdf_testing_dir "${CMAKE_CURRENT_LIST_DIR}")

function(smdf_add_test name target)
  add_test(NAME ${name} COMMAND ${target} ${ARGN})
  set_tests_properties(${name} PROPERTIES
    ENVIRONMENT "${SMDF_TEST_ENVIRONMENT}"
    SKIP_RETURN_CODE 77)
endfunction()

function(smdf_add_downstream_test)
  set(_src "${PROJECT_SOURCE_DIR}/test/Surface_mesh_direction_fields/downstream")
  if(NOT EXISTS "${_src}/CMakeLists.txt")
    message(WARNING "smdf_add_downstream_test: ${_src}/CMakeLists.txt not found, test not added")
    return()
  endif()
  set(_bin "${PROJECT_BINARY_DIR}")
  add_test(NAME downstream_find_package
    COMMAND ${CMAKE_COMMAND}
      "-DSMDF_BUILD_DIR=${_bin}"
      "-DSMDF_PREFIX=${_bin}/downstream_prefix"
      "-DSMDF_DOWNSTREAM_SOURCE_DIR=${_src}"
      "-DSMDF_DOWNSTREAM_BUILD_DIR=${_bin}/downstream_build"
      "-DSMDF_CONFIG=$<CONFIG>"
      "-DSMDF_GENERATOR=${CMAKE_GENERATOR}"
      "-DSMDF_MAKE_PROGRAM=${CMAKE_MAKE_PROGRAM}"
      "-DSMDF_CXX_COMPILER=${CMAKE_CXX_COMPILER}"
      "-DSMDF_CXX_COMPILER_LAUNCHER=${CMAKE_CXX_COMPILER_LAUNCHER}"
      -P "${_smdf_testing_dir}/Surface_mesh_direction_fieldsDownstreamTest.cmake")
  set_tests_properties(downstream_find_package PROPERTIES
    ENVIRONMENT "${SMDF_TEST_ENVIRONMENT}"
    LABELS "downstream;install"
    TIMEOUT 900)
endfunction()
