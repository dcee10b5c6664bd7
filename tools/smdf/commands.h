// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// smdf: the subcommands. cmd_<name>.cpp defines run_<name>() and <name>_command(), the entry
// of commands() (name, positional arguments, options, help text, run function); remesh's entry
// is in cmd_remesh_help.cpp.

#ifndef SMDF_CLI_COMMANDS_H
#define SMDF_CLI_COMMANDS_H

#include "args.h"
#include "json.h"

#include <vector>

namespace smdf_cli {

// The table of subcommands, in the order of `smdf --help` (main.cpp).
const std::vector<Command>& commands();

Json run_info(const Args& args);            Command info_command();
Json run_generators(const Args& args);      Command generators_command();
Json run_holonomy(const Args& args);        Command holonomy_command();
Json run_connection(const Args& args);      Command connection_command();
Json run_singularities(const Args& args);   Command singularities_command();
Json run_cone_metric(const Args& args);     Command cone_metric_command();
Json run_rosy(const Args& args);            Command rosy_command();
Json run_remesh(const Args& args);          Command remesh_command();

} // namespace smdf_cli

#endif // SMDF_CLI_COMMANDS_H
