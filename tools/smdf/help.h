// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// smdf: `smdf --help` and `smdf <command> --help`, assembled from the table of commands.

#ifndef SMDF_CLI_HELP_H
#define SMDF_CLI_HELP_H

#include "args.h"

#include <ostream>

namespace smdf_cli {

// The general usage text and one line per command of commands().
void print_usage(std::ostream& os);

// The synopsis, description and options of one command.
void print_command_usage(const Command& cmd, std::ostream& os);

} // namespace smdf_cli

#endif // SMDF_CLI_HELP_H
