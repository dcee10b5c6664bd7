// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// libFuzzer target: the command-line tool's parsers of numbers, angles, index lists
// (--singularities, --generator-turning, --cones) and argument vectors. The first byte chooses
// the parser, the rest is the text (for argument vectors: tokens separated by NUL bytes). Every
// input must be accepted or end in a Usage_error / Error.
#include "args.h"

#include <cstdint>
#include <string>
#include <vector>

using namespace smdf_cli;

namespace {

Json no_run(const Args&) { return Json(); }

const Command& test_command()
{
  static const Command c = {"test", {"MESH", "[EXTRA]"},
                            {{"singularities", "LIST", ""}, {"cones", "LIST", ""}, {"N", "n", ""},
                             {"flag", "", ""}, {"width", "PX", ""}},
                            "", "", no_run};
  return c;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size == 0) return 0;
  const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);
  double x = 0;
  std::size_t i = 0;
  try {
    switch(data[0] % 6) {
      case 0: parse_number(text, x); break;
      case 1: parse_angle(text, x); break;
      case 2: parse_real(text, x); parse_index(text, i); break;
      case 3: {
        Args a;
        a.options["singularities"] = text;
        index_list_option(a, "singularities");
        break;
      }
      case 4: {
        Args a;
        a.options["cones"] = text;
        pairs_option(a, "cones", parse_angle, "radians");
        break;
      }
      default: {
        std::vector<std::string> argv;
        std::string tok;
        for(char ch : text) { if(ch == '\0') { argv.push_back(tok); tok.clear(); } else tok += ch; }
        argv.push_back(tok);
        const Args a = parse_args(test_command(), argv);
        symmetry_order_option(a);
        a.real("width", 1);
        a.integer("width", 1);
      }
    }
  } catch(const Usage_error&) {
  } catch(const Error&) {
  }
  shorten(text);
  return 0;
}
