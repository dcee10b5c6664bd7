# SPDX-License-Identifier: GPL-3.0-or-later
# Finds SuiteSparse's CHOLMOD and SPQR and defines the imported targets
#   SuiteSparse::CHOLMOD   cholmod + amd, colamd, camd, ccolamd, suitesparseconfig, LAPACK, BLAS
#   SuiteSparse::SPQR      spqr + SuiteSparse::CHOLMOD
# Their include directory is the one holding cholmod.h and SuiteSparseQR.hpp, so that
# `#include <cholmod.h>` / `#include <SuiteSparseQR.hpp>` (as Eigen's CholmodSupport and
# SPQRSupport write them) work.  Debian 12 (SuiteSparse 5.12) ships no CMake config, hence
# this module; SuiteSparse >= 7 ships one with the same target names, which is used if present.
# Safe to include more than once.  Hint: -DSuiteSparse_ROOT=<prefix>.

if(TARGET SuiteSparse::SPQR AND TARGET SuiteSparse::CHOLMOD)
  return()
endif()

# SuiteSparse >= 7 (e.g. Debian 13) provides CMake package configs.
find_package(SPQR CONFIG QUIET)
if(TARGET SuiteSparse::SPQR AND TARGET SuiteSparse::CHOLMOD)
  message(STATUS "SuiteSparse: using CMake config of SPQR ${SPQR_VERSION}")
  return()
endif()

set(_smdf_ss_hints ${SuiteSparse_ROOT} $ENV{SuiteSparse_ROOT})

find_path(SuiteSparse_CHOLMOD_INCLUDE_DIR cholmod.h
  HINTS ${_smdf_ss_hints} PATH_SUFFIXES include/suitesparse suitesparse include)
find_path(SuiteSparse_SPQR_INCLUDE_DIR SuiteSparseQR.hpp
  HINTS ${_smdf_ss_hints} PATH_SUFFIXES include/suitesparse suitesparse include)

set(_smdf_ss_missing)
foreach(_c IN ITEMS cholmod spqr suitesparseconfig amd colamd camd ccolamd)
  string(TOUPPER ${_c} _C)
  find_library(SuiteSparse_${_C}_LIBRARY NAMES ${_c} HINTS ${_smdf_ss_hints} PATH_SUFFIXES lib lib64)
  if(NOT SuiteSparse_${_C}_LIBRARY)
    list(APPEND _smdf_ss_missing "lib${_c}")
  endif()
  mark_as_advanced(SuiteSparse_${_C}_LIBRARY)
endforeach()
foreach(_h IN ITEMS CHOLMOD SPQR)
  if(NOT SuiteSparse_${_h}_INCLUDE_DIR)
    list(APPEND _smdf_ss_missing "${_h} headers")
  endif()
endforeach()
if(_smdf_ss_missing)
  list(JOIN _smdf_ss_missing ", " _smdf_ss_missing)
  message(FATAL_ERROR "SuiteSparse (CHOLMOD/SPQR) not found; missing: ${_smdf_ss_missing}.\n"
    "On Debian/Ubuntu install it with:  apt-get install libsuitesparse-dev\n"
    "or point -DSuiteSparse_ROOT=<prefix> at an installation.")
endif()

# CHOLMOD and SPQR call LAPACK/BLAS; Debian's shared libraries record that already,
# listing them explicitly just avoids relying on it.
find_package(BLAS QUIET)
find_package(LAPACK QUIET)

add_library(SuiteSparse::CHOLMOD UNKNOWN IMPORTED)
set_target_properties(SuiteSparse::CHOLMOD PROPERTIES
  IMPORTED_LOCATION "${SuiteSparse_CHOLMOD_LIBRARY}"
  INTERFACE_INCLUDE_DIRECTORIES "${SuiteSparse_CHOLMOD_INCLUDE_DIR}"
  INTERFACE_LINK_LIBRARIES "${SuiteSparse_AMD_LIBRARY};${SuiteSparse_COLAMD_LIBRARY};${SuiteSparse_CAMD_LIBRARY};${SuiteSparse_CCOLAMD_LIBRARY};${SuiteSparse_SUITESPARSECONFIG_LIBRARY}")
foreach(_t IN ITEMS LAPACK::LAPACK BLAS::BLAS)
  if(TARGET ${_t})
    set_property(TARGET SuiteSparse::CHOLMOD APPEND PROPERTY INTERFACE_LINK_LIBRARIES ${_t})
  endif()
endforeach()
# The two-thread factorisation calls dsyrk/dlauum/dpotrf/dtrmv/dtrsv itself; without BLAS and
# LAPACK targets to link, it uses Eigen's dense kernels instead.
if(NOT TARGET LAPACK::LAPACK OR NOT TARGET BLAS::BLAS)
  set_property(TARGET SuiteSparse::CHOLMOD APPEND PROPERTY INTERFACE_COMPILE_DEFINITIONS CGAL_SMDF_NO_DIRECT_BLAS)
endif()

add_library(SuiteSparse::SPQR UNKNOWN IMPORTED)
set_target_properties(SuiteSparse::SPQR PROPERTIES
  IMPORTED_LOCATION "${SuiteSparse_SPQR_LIBRARY}"
  INTERFACE_INCLUDE_DIRECTORIES "${SuiteSparse_SPQR_INCLUDE_DIR}"
  INTERFACE_LINK_LIBRARIES SuiteSparse::CHOLMOD)

message(STATUS "SuiteSparse: ${SuiteSparse_SPQR_LIBRARY}, ${SuiteSparse_CHOLMOD_LIBRARY}, "
               "headers in ${SuiteSparse_SPQR_INCLUDE_DIR}")
mark_as_advanced(SuiteSparse_CHOLMOD_INCLUDE_DIR SuiteSparse_SPQR_INCLUDE_DIR)
unset(_smdf_ss_hints)
unset(_smdf_ss_missing)
