// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// smdf: command-line front end of the Surface_mesh_direction_fields package.
//
//   smdf <command> [options] MESH      one JSON object on stdout, or one error line on stderr
//
// Exit codes: 0 success, 1 the input cannot be processed, 2 usage error, 3 a result that is
// printed but flagged as failed (cone-metric: not converged; JSON on stdout and one error line).
// Vertex and face indices are 0-based in file order (read_triangle_mesh() keeps it).
//
// Sources (tools/smdf/):
//   main.cpp          main(), dispatch and the table of commands, commands()
//   commands.h        run_<name>() and <name>_command() of every subcommand
//   cmd_<name>.cpp    one subcommand: its run function and its table entry
//   args.h/.cpp       error types, the argument parser, parsers of option values
//   help.h/.cpp       `smdf --help` and `smdf <command> --help`
//   json.h            the JSON value every subcommand returns
//   common.h/.cpp     the mesh type and helpers shared by several subcommands
// CGAL's kernel and Surface_mesh, and the package's algorithms, are included by common.h and
// the cmd_*.cpp files only (each 10 to 25 s to compile); main, args and help build quickly.
//
// Adding a subcommand <name>:
//   1. write cmd_<name>.cpp defining `Json run_<name>(const Args&)` and `Command
//      <name>_command()`, which returns its entry: name, positional arguments, options, the
//      one-line summary of `smdf --help`, the description of `smdf <name> --help`, run_<name>;
//   2. declare both in commands.h;
//   3. add `<name>_command()` to the table of commands() below (its place is its place in
//      `smdf --help`) and <name> to smdf_tool_sources() in
//      cmake/Surface_mesh_direction_fieldsUnity.cmake (the tool and the fuzz target share it).
// Parsing, --help and error reporting are shared. Throw `Usage_error` for bad invocations and
// `Error` (or let `SMDF::Input_error` escape, wrapped by `on_file()`) for bad input; throw
// `Failed_result` to print the JSON object and still fail (exit code 3). Helpers needed by
// more than one subcommand belong in common.h (or args.h if they need no CGAL header).

#include "args.h"
#include "commands.h"
#include "help.h"
#include "huge_page_new.h"
#include "json.h"

#if defined(__unix__) || defined(__APPLE__)
#include <dlfcn.h>
#endif

#include <CGAL/Surface_mesh_direction_fields/errors.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <locale>
#include <new>
#include <string>
#include <vector>

#ifndef SMDF_VERSION
#define SMDF_VERSION "unknown"
#endif

namespace smdf_cli {

const std::vector<Command>& commands()
{
  static const std::vector<Command> table = {
    info_command(),
    generators_command(),
    holonomy_command(),
    connection_command(),
    singularities_command(),
    cone_metric_command(),
    rosy_command(),
    remesh_command(),
  };
  return table;
}

namespace {

namespace SMDF = CGAL::Surface_mesh_direction_fields;

const Command* find_command(const std::string& name)
{
  for(const Command& c : commands())
    if(c.name == name) return &c;
  return nullptr;
}

// One line on stderr, whatever the message contains.
void print_error(const std::string& message)
{
  std::string line = "smdf: error: " + message;
  std::replace(line.begin(), line.end(), '\n', ' ');
  std::replace(line.begin(), line.end(), '\r', ' ');
  std::cerr << line << std::endl;
}

int run(const std::vector<std::string>& argv)
{
  if(argv.empty()) throw Usage_error("missing command" + see_help(""));
  const std::string& first = argv[0];
  if(first == "-h" || first == "--help") { print_usage(std::cout); return EXIT_SUCCESS; }
  if(first == "--version") { std::cout << "smdf " << SMDF_VERSION << "\n"; return EXIT_SUCCESS; }
  if(first == "help") {
    if(argv.size() == 1) { print_usage(std::cout); return EXIT_SUCCESS; }
    const Command* cmd = find_command(argv[1]);
    if(cmd == nullptr) throw Usage_error("unknown command '" + argv[1] + "'" + see_help(""));
    if(argv.size() > 2) throw Usage_error("unexpected argument '" + argv[2] + "'" + see_help(""));
    print_command_usage(*cmd, std::cout);
    return EXIT_SUCCESS;
  }
  const Command* cmd = find_command(first);
  if(cmd == nullptr) {
    if(first.size() > 1 && first[0] == '-') throw Usage_error("unknown option '" + first + "'" + see_help(""));
    throw Usage_error("unknown command '" + first + "'" + see_help(""));
  }
  const Args args = parse_args(*cmd, std::vector<std::string>(argv.begin() + 1, argv.end()));
  if(args.help) { print_command_usage(*cmd, std::cout); return EXIT_SUCCESS; }

  std::string json;
  std::string failure;
  int code = EXIT_SUCCESS;
  try {
    json = cmd->run(args).str();   // fully built before anything is printed
  } catch(const Failed_result& r) {
    json = r.json.str();
    failure = r.message;
    code = r.exit_code;
  } catch(const SMDF::Input_error& e) {
    // every error about the input names it first, as "<mesh>: ..." (errors about options
    // start with "--option: ..." instead)
    const std::string what = e.what();
    if(args.positional.empty() || what.compare(0, args.positional[0].size(), args.positional[0]) == 0 ||
       what.compare(0, 2, "--") == 0)
      throw;
    throw SMDF::Input_error(e.kind(), args.positional[0] + ": " + what);
  }
  std::cout << json << '\n' << std::flush;
  if(!std::cout) throw Error("cannot write to standard output");
  if(code != EXIT_SUCCESS) print_error(failure);
  return code;
}

} // namespace

} // namespace smdf_cli

namespace {

void single_threaded_openblas()
{
#if defined(__unix__) || defined(__APPLE__)
  typedef void (*Setter)(int);
  if(const Setter set = reinterpret_cast<Setter>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"))) set(1);
#endif
}

} // namespace

int main(int argc, char** argv)
{
  using namespace smdf_cli;
  // The tool owns its process: large blocks on transparent huge pages (huge_page_new.cpp).
  // SMDF_NO_HUGEPAGES=1 keeps the default allocation.
  if(!std::getenv("SMDF_NO_HUGEPAGES")) smdf_memory::enable_huge_pages();
  // The package's solvers split large factorisations over two threads themselves; OpenBLAS's
  // own pool then only spins against them (a 114k-face remesh: 4.3 s instead of 4.8-5.6 s).
  // OPENBLAS_NUM_THREADS, when set, is left to decide.
  if(!std::getenv("OPENBLAS_NUM_THREADS")) single_threaded_openblas();
  std::cout.imbue(std::locale::classic());
  try {
    return run(std::vector<std::string>(argv + 1, argv + argc));
  } catch(const Usage_error& e) {
    print_error(e.what());
    return 2;
  } catch(const Error& e) {
    print_error(e.what());
  } catch(const SMDF::Input_error& e) {
    print_error(std::string(e.what()) + " [" + SMDF::Input_error::kind_name(e.kind()) + "]");
  } catch(const std::bad_alloc&) {
    print_error("out of memory");
  } catch(const std::exception& e) {
    print_error(std::string("internal error: ") + e.what());
  } catch(...) {
    print_error("internal error: unknown exception");
  }
  return EXIT_FAILURE;
}
