// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// libFuzzer target: the command-line tool's file parsers, through the tool itself (main.cpp is
// compiled with main renamed): the bytes after the first one are written to a file that is
// passed, on data/torus.off, as --singularities-file or --constraints (connection), --lengths
// (holonomy, connection, remesh), --field or --matching (singularities), --polycube (remesh),
// --edit or --length (rosy), chosen by the first byte.
// Every input must end with an exit code of 0 to 3; a crash or an escaping exception is a bug.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>
#include <unistd.h>

int smdf_tool_main(int argc, char** argv);

namespace {

std::string write_temp(const std::string& tag, const std::uint8_t* data, std::size_t size)
{
  const std::string file = "/tmp/smdf_fuzz_" + tag + "_" + std::to_string(getpid()) + ".txt";
  std::ofstream out(file, std::ios::binary);
  out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  return file;
}

std::stringstream sink;

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  std::cout.rdbuf(sink.rdbuf());
  std::cerr.rdbuf(sink.rdbuf());
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size == 0) return 0;
  const std::string mesh = SMDF_FUZZ_MESH;
  const std::string file = write_temp("input", data + 1, size - 1);
  std::vector<std::string> args;
  const std::string out = "/tmp/smdf_fuzz_remesh_" + std::to_string(getpid()) + ".off";
  switch(data[0] % 10) {
    case 8: args = {"rosy", mesh, "--cones", "10:pi/2,100:-pi/2", "--edit", file}; break;
    case 9: args = {"rosy", mesh, "--cones", "10:pi/2,100:-pi/2", "--length", file}; break;
    case 6: args = {"remesh", mesh, "--lengths", file, "--faces", "200", "--out", out}; break;
    case 7: args = {"remesh", mesh, "--polycube", file, "--faces", "200", "--out", out}; break;
    case 0: args = {"connection", mesh, "--singularities-file", file}; break;
    case 1: args = {"connection", mesh, "--N", "4", "--constraints", file}; break;
    case 2: args = {"holonomy", mesh, "--lengths", file}; break;
    case 3: args = {"connection", mesh, "--lengths", file}; break;
    case 4: args = {"singularities", mesh, "--field", file}; break;
    default: args = {"singularities", mesh, "--field", SMDF_FUZZ_FIELD, "--N", "4", "--matching", file}; break;
  }
  std::vector<char*> argv;
  static char name[] = "smdf";
  argv.push_back(name);
  for(std::string& a : args) argv.push_back(&a[0]);
  argv.push_back(nullptr);
  const int code = smdf_tool_main(int(args.size() + 1), argv.data());
  sink.str("");
  std::remove(file.c_str());
  std::remove(out.c_str());
  if(code < 0 || code > 3) std::abort();
  return 0;
}
