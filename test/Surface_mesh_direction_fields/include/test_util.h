// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Small always-on test helpers (Release builds define NDEBUG, so no assert()).
#ifndef SMDF_TEST_UTIL_H
#define SMDF_TEST_UTIL_H

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace smdf_test {

inline int& passed() { static int n = 0; return n; }
inline int& failed() { static int n = 0; return n; }

inline void report(bool ok, const std::string& what, const char* file, int line)
{
  if(ok) { ++passed(); return; }
  ++failed();
  std::cout << "FAILED: " << what << "  (" << file << ":" << line << ")" << std::endl;
}

inline int finish()
{
  std::cout << passed() << " passed, " << failed() << " failed" << std::endl;
  return failed() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

// Directory holding MANIFEST.tsv and meshes/, or "" when ../shared is absent.
inline std::string shared_data_dir()
{
  if(const char* env = std::getenv("SMDF_SHARED_DATA")) return env;
#ifdef SMDF_SHARED_DATA_DIR
  std::ifstream probe(std::string(SMDF_SHARED_DATA_DIR) + "/MANIFEST.tsv");
  if(probe) return SMDF_SHARED_DATA_DIR;
#endif
  return "";
}

struct Manifest_entry
{
  std::string file;
  std::size_t V = 0, F = 0, E = 0, components = 0, boundary_loops = 0;
  std::string genus, manifold, pure_tri, orientable;
  std::size_t degenerate_faces = 0;
  double megabytes = 0;
};

// The manifest's meshes, without those of more than $SMDF_TEST_MAX_FACES faces when that is set
// (the sanitizer run of ./run.sh sanitize uses a reduced mesh set).
inline std::vector<Manifest_entry> read_manifest(const std::string& dir)
{
  std::vector<Manifest_entry> out;
  const char* limit = std::getenv("SMDF_TEST_MAX_FACES");
  const std::size_t max_faces = limit ? std::size_t(std::stoul(limit)) : std::size_t(-1);
  std::ifstream in(dir + "/MANIFEST.tsv");
  std::string line;
  std::getline(in, line);   // header
  while(std::getline(in, line)) {
    std::vector<std::string> c;
    std::stringstream ss(line);
    std::string cell;
    while(std::getline(ss, cell, '\t')) c.push_back(cell);
    if(c.size() < 16) continue;
    Manifest_entry e;
    e.file = c[0];
    e.V = std::stoul(c[3]); e.F = std::stoul(c[4]); e.E = std::stoul(c[5]);
    e.components = std::stoul(c[6]); e.boundary_loops = std::stoul(c[7]);
    e.genus = c[8]; e.manifold = c[9]; e.pure_tri = c[10]; e.orientable = c[11];
    e.degenerate_faces = std::stoul(c[12]);
    e.megabytes = std::stod(c[14]);
    if(e.F > max_faces) { std::cout << e.file << ": skipped (SMDF_TEST_MAX_FACES=" << limit << ")" << std::endl; continue; }
    out.push_back(e);
  }
  return out;
}

inline double wrap(double a)
{
  a = std::remainder(a, 2 * M_PI);
  return a;
}

} // namespace smdf_test

#define SMDF_CHECK(cond) ::smdf_test::report(static_cast<bool>(cond), #cond, __FILE__, __LINE__)
#define SMDF_CHECK_MSG(cond, msg)                                                        \
  do { std::ostringstream smdf_os_; smdf_os_ << #cond << " | " << msg;                   \
       ::smdf_test::report(static_cast<bool>(cond), smdf_os_.str(), __FILE__, __LINE__); } while(0)

#endif
