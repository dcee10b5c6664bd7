# SPDX-License-Identifier: GPL-3.0-or-later
# Run with `cmake -P` by the CTest test `downstream_find_package` (see
# Surface_mesh_direction_fieldsTesting.cmake): install the build tree into a fresh prefix,
# then configure, build and run a standalone consumer that uses find_package() on it.

foreach(_v SMDF_BUILD_DIR SMDF_PREFIX SMDF_DOWNSTREAM_SOURCE_DIR SMDF_DOWNSTREAM_BUILD_DIR)
  if(NOT ${_v})
    message(FATAL_ERROR "${_v} must be set")
  endif()
endforeach()
if(NOT SMDF_CONFIG)
  set(SMDF_CONFIG Release)
endif()

function(smdf_step what)
  message(STATUS "downstream: ${what}")
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE _rc)
  if(NOT _rc EQUAL 0)
    message(FATAL_ERROR "downstream: ${what} failed (${_rc})")
  endif()
endfunction()

file(REMOVE_RECURSE "${SMDF_PREFIX}" "${SMDF_DOWNSTREAM_BUILD_DIR}")

smdf_step("install into ${SMDF_PREFIX}"
  "${CMAKE_COMMAND}" --install "${SMDF_BUILD_DIR}" --prefix "${SMDF_PREFIX}" --config "${SMDF_CONFIG}")

set(_args -S "${SMDF_DOWNSTREAM_SOURCE_DIR}" -B "${SMDF_DOWNSTREAM_BUILD_DIR}"
  "-DCMAKE_PREFIX_PATH=${SMDF_PREFIX}"
  "-DSMDF_EXPECTED_PREFIX=${SMDF_PREFIX}"
  "-DCMAKE_BUILD_TYPE=${SMDF_CONFIG}"
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
if(SMDF_GENERATOR)
  list(APPEND _args -G "${SMDF_GENERATOR}")
endif()
if(SMDF_MAKE_PROGRAM)
  list(APPEND _args "-DCMAKE_MAKE_PROGRAM=${SMDF_MAKE_PROGRAM}")
endif()
if(SMDF_CXX_COMPILER)
  list(APPEND _args "-DCMAKE_CXX_COMPILER=${SMDF_CXX_COMPILER}")
endif()
if(SMDF_CXX_COMPILER_LAUNCHER)
  list(APPEND _args "-DCMAKE_CXX_COMPILER_LAUNCHER=${SMDF_CXX_COMPILER_LAUNCHER}")
endif()
smdf_step("configure" "${CMAKE_COMMAND}" ${_args})
smdf_step("build" "${CMAKE_COMMAND}" --build "${SMDF_DOWNSTREAM_BUILD_DIR}" --config "${SMDF_CONFIG}")

find_program(_exe smdf_downstream
  PATHS "${SMDF_DOWNSTREAM_BUILD_DIR}" "${SMDF_DOWNSTREAM_BUILD_DIR}/${SMDF_CONFIG}" NO_DEFAULT_PATH)
if(NOT _exe)
  message(FATAL_ERROR "downstream: smdf_downstream executable not found")
endif()
smdf_step("run" "${_exe}")
message(STATUS "downstream: OK")
