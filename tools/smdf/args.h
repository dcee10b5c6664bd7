// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// smdf: error types, the command-line parser and the parsers of option values (numbers,
// angles, index lists). No CGAL header: this part builds in a second.

#ifndef SMDF_CLI_ARGS_H
#define SMDF_CLI_ARGS_H

#include "json.h"

#include <cstddef>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace smdf_cli {

// ---- Errors -------------------------------------------------------------------------------

// Bad invocation: exit code 2.
struct Usage_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// Input that cannot be processed: exit code 1. The message is the whole error line without
// the "smdf: error: " prefix, e.g. "mesh.off: face 3 ... [degenerate_face]".
struct Error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// A result that is printed (the JSON object on stdout) but is a failure all the same: the
// message goes to stderr as the one error line and the process exits with `exit_code` (3).
// Used by cone-metric when Newton does not converge.
struct Failed_result
{
  Json json;
  std::string message;
  int exit_code;
};

// ---- Command-line arguments ---------------------------------------------------------------

struct Option_spec
{
  std::string name;        // without the leading "--"
  std::string value_name;  // e.g. "FILE"; empty for a flag
  std::string help;
};

// The parsed arguments of one subcommand.
struct Args
{
  std::string command;
  std::vector<std::string> positional;
  std::map<std::string, std::string> options;  // name -> value ("" for flags)
  bool help = false;

  bool has(const std::string& name) const { return options.count(name) != 0; }

  std::string value(const std::string& name, const std::string& fallback = "") const
  {
    auto it = options.find(name);
    return it == options.end() ? fallback : it->second;
  }

  // A real option value; malformed or non-finite values are usage errors.
  double real(const std::string& name, double fallback) const;

  // An integer option value; malformed or out-of-range values are usage errors.
  long integer(const std::string& name, long fallback) const;
};

// One subcommand: its name, arguments, help text and the function that runs it.
struct Command
{
  std::string name;
  std::vector<std::string> positionals;  // names; "[NAME]" marks an optional trailing one
  std::vector<Option_spec> options;
  std::string summary;                   // one line, for `smdf --help`
  std::string description;               // for `smdf <command> --help`
  Json (*run)(const Args&);
};

// " (see 'smdf --help')" for an empty `command`, else " (see 'smdf <command> --help')".
std::string see_help(const std::string& command);

// The arguments after the command name; Usage_error for unknown or repeated options, missing
// values and a wrong number of positional arguments. Stops at -h/--help (sets `help`).
Args parse_args(const Command& cmd, const std::vector<std::string>& argv);

// --N: the symmetry order, an integer in [1, 1000000] (default 1).
long symmetry_order_option(const Args& args);

// ---- Option values ------------------------------------------------------------------------

// (index, value) pairs: singularities, cones, generator turning numbers, ...
typedef std::vector<std::pair<std::size_t, double>> Indexed_values;

// The first `n` characters of `s`, followed by "..." if it is longer (for error messages).
std::string shorten(const std::string& s, std::size_t n = 40);

// A non-negative decimal integer without sign, or false.
bool parse_index(const std::string& s, std::size_t& out);

// A finite number as strtod() reads it, without leading white space; false if malformed.
bool parse_real(const std::string& s, double& out);

// A number written as an integer, a fraction "p/q" or a decimal; false if malformed.
bool parse_number(const std::string& s, double& out);

// An angle in radians: a number as parse_number() reads it (integer, p/q, decimal), or a
// multiple of pi written [c][*]pi[/d], c and d numbers as above: pi, -pi, pi/2, -4pi, 3*pi/4,
// 0.5pi, 1/3*pi. False if malformed.
bool parse_angle(const std::string& s, double& out);

// The pairs "i:x,i:x,..." of option --<option>, x read by `parse` (parse_number, parse_angle,
// ...); empty if the option is absent. A malformed item is a Usage_error
// "option --<option> expects <expected>, got '<item>'".
Indexed_values pairs_option(const Args& args, const std::string& option,
                            bool (*parse)(const std::string&, double&), const std::string& expected);

// pairs_option() with numbers (integer, p/q or decimal): --singularities, --generator-turning.
Indexed_values index_list_option(const Args& args, const std::string& option);

} // namespace smdf_cli

#endif // SMDF_CLI_ARGS_H
