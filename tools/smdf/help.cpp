// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "help.h"

#include "commands.h"

#include <algorithm>
#include <iomanip>
#include <string>

namespace smdf_cli {

namespace {

// "smdf <name> <positionals> [--option VALUE]...".
std::string synopsis(const Command& cmd)
{
  std::string s = "smdf " + cmd.name;
  for(const std::string& p : cmd.positionals) s += " " + p;
  for(const Option_spec& o : cmd.options)
    s += " [--" + o.name + (o.value_name.empty() ? "" : " " + o.value_name) + "]";
  return s;
}

} // namespace

void print_usage(std::ostream& os)
{
  os << "usage: smdf <command> [options] MESH\n"
        "       smdf <command> --help\n"
        "       smdf --version\n\n"
        "Reads a triangle mesh (OFF, OBJ, PLY or STL; it must be an orientable 2-manifold, possibly\n"
        "with boundary and several components) and prints one JSON object on stdout. Vertex and\n"
        "face indices are 0-based in file order. On failure prints one line to stderr and exits\n"
        "with 1 (input that cannot be processed) or 2 (usage error); exit code 3 means the JSON\n"
        "object was printed but the result failed, with one stderr line (cone-metric: not\n"
        "converged; connection: the solve failed or the field's read-back differs from the\n"
        "prescription).\n\n"
        "commands:\n";
  for(const Command& c : commands())
    os << "  " << std::left << std::setw(14) << c.name << c.summary << "\n";
}

void print_command_usage(const Command& cmd, std::ostream& os)
{
  os << "usage: " << synopsis(cmd) << "\n\n" << cmd.description;
  os << "\noptions:\n";
  auto head = [](const Option_spec& o) { return "--" + o.name + (o.value_name.empty() ? "" : " " + o.value_name); };
  std::size_t width = std::string("-h, --help").size();
  for(const Option_spec& o : cmd.options) width = (std::max)(width, head(o).size());
  width += 2;   // the descriptions start two columns after the longest option
  for(const Option_spec& o : cmd.options) os << "  " << std::left << std::setw(int(width)) << head(o) << o.help << "\n";
  os << "  " << std::left << std::setw(int(width)) << "-h, --help" << "print this help and exit\n";
}

} // namespace smdf_cli
