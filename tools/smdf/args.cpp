// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "args.h"

#include <CGAL/number_type_config.h>   // CGAL_PI

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace smdf_cli {

double Args::real(const std::string& name, double fallback) const
{
  if(!has(name)) return fallback;
  const std::string& s = options.at(name);
  char* end = nullptr;
  const double d = s.empty() ? 0 : std::strtod(s.c_str(), &end);
  if(s.empty() || *end != '\0' || !std::isfinite(d))
    throw Usage_error("option --" + name + " expects a finite number, got '" + s + "'");
  return d;
}

long Args::integer(const std::string& name, long fallback) const
{
  if(!has(name)) return fallback;
  const std::string& s = options.at(name);
  char* end = nullptr;
  errno = 0;
  const long v = s.empty() ? 0 : std::strtol(s.c_str(), &end, 10);
  if(s.empty() || *end != '\0' || errno == ERANGE)
    throw Usage_error("option --" + name + " expects an integer, got '" + s + "'");
  return v;
}

std::string see_help(const std::string& command)
{
  return command.empty() ? " (see 'smdf --help')" : " (see 'smdf " + command + " --help')";
}

Args parse_args(const Command& cmd, const std::vector<std::string>& argv)
{
  Args a;
  a.command = cmd.name;
  bool only_positionals = false;
  for(std::size_t i = 0; i < argv.size(); ++i) {
    const std::string& arg = argv[i];
    if(only_positionals || arg.size() < 2 || arg[0] != '-') {
      a.positional.push_back(arg);
      continue;
    }
    if(arg == "--") { only_positionals = true; continue; }
    if(arg == "-h" || arg == "--help") { a.help = true; return a; }
    if(arg.compare(0, 2, "--") != 0)
      throw Usage_error("unknown option '" + arg + "'" + see_help(cmd.name));
    const std::size_t eq = arg.find('=');
    const std::string name = arg.substr(2, eq == std::string::npos ? std::string::npos : eq - 2);
    auto spec = std::find_if(cmd.options.begin(), cmd.options.end(),
                             [&](const Option_spec& o) { return o.name == name; });
    if(spec == cmd.options.end())
      throw Usage_error("unknown option '--" + name + "'" + see_help(cmd.name));
    if(a.has(name))
      throw Usage_error("option --" + name + " given twice");
    if(spec->value_name.empty()) {
      if(eq != std::string::npos)
        throw Usage_error("option --" + name + " takes no value");
      a.options[name] = "";
    } else {
      if(eq == std::string::npos && i + 1 >= argv.size())
        throw Usage_error("option --" + name + " needs a value " + spec->value_name + see_help(cmd.name));
      const std::string value = eq != std::string::npos ? arg.substr(eq + 1) : argv[++i];
      if(value.empty())
        throw Usage_error("option --" + name + " needs a non-empty value " + spec->value_name);
      a.options[name] = value;
    }
  }
  for(std::size_t k = 0; k < a.positional.size() && k < cmd.positionals.size(); ++k)
    if(a.positional[k].empty())
      throw Usage_error("empty argument " + cmd.positionals[k] + see_help(cmd.name));
  std::size_t required = 0;
  for(const std::string& p : cmd.positionals)
    if(p.empty() || p[0] != '[') ++required;
  if(a.positional.size() < required)
    throw Usage_error("missing argument " + cmd.positionals[a.positional.size()] + see_help(cmd.name));
  if(a.positional.size() > cmd.positionals.size())
    throw Usage_error("unexpected argument '" + a.positional[cmd.positionals.size()] + "'" + see_help(cmd.name));
  return a;
}

long symmetry_order_option(const Args& args)
{
  const long N = args.integer("N", 1);
  if(N < 1 || N > 1000000)
    throw Usage_error("option --N expects an integer >= 1, got '" + args.value("N") + "'");
  return N;
}

std::string shorten(const std::string& s, std::size_t n)
{
  // printable ASCII as it is, every other byte as \xNN, so that an error stays one line
  static const char hex[] = "0123456789abcdef";
  std::string r;
  for(std::size_t i = 0; i < s.size() && i < n; ++i) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if(c >= 0x20 && c < 0x7f) r += char(c);
    else { r += "\\x"; r += hex[c >> 4]; r += hex[c & 15]; }
  }
  return s.size() <= n ? r : r + "...";
}

bool parse_index(const std::string& s, std::size_t& out)
{
  if(s.empty() || s.size() > 18 || !std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return false;
  out = std::size_t(std::stoull(s));
  return true;
}

bool parse_real(const std::string& s, double& out)
{
  if(s.empty() || std::isspace(static_cast<unsigned char>(s[0]))) return false;
  char* end = nullptr;
  out = std::strtod(s.c_str(), &end);
  return *end == '\0' && std::isfinite(out);
}

bool parse_number(const std::string& s, double& out)
{
  const std::size_t slash = s.find('/');
  if(slash == std::string::npos) return parse_real(s, out);
  double p, q;
  if(!parse_real(s.substr(0, slash), p) || !parse_real(s.substr(slash + 1), q) || q == 0) return false;
  out = p / q;
  return std::isfinite(out);
}

bool parse_angle(const std::string& s, double& out)
{
  const std::size_t p = s.find("pi");
  if(p == std::string::npos) return parse_number(s, out);
  if(s.find("pi", p + 2) != std::string::npos) return false;
  std::string pre = s.substr(0, p);
  const std::string post = s.substr(p + 2);
  double c = 1, d = 1;
  if(!pre.empty() && pre.back() == '*') {
    pre.pop_back();
    if(pre.empty() || pre == "-" || pre == "+") return false;   // "*pi", "-*pi"
  }
  if(pre == "-") c = -1;
  else if(pre == "+") c = 1;
  else if(!pre.empty() && !parse_number(pre, c)) return false;
  if(!post.empty()) {
    if(post[0] != '/' || post.find('/', 1) != std::string::npos || !parse_number(post.substr(1), d) || d == 0)
      return false;
  }
  out = c * CGAL_PI / d;
  return std::isfinite(out);
}

Indexed_values pairs_option(const Args& args, const std::string& option,
                            bool (*parse)(const std::string&, double&), const std::string& expected)
{
  Indexed_values out;
  if(!args.has(option)) return out;
  const std::string s = args.value(option);
  std::size_t start = 0;
  while(start <= s.size()) {
    std::size_t comma = s.find(',', start);
    if(comma == std::string::npos) comma = s.size();
    const std::string item = s.substr(start, comma - start);
    const std::size_t colon = item.find(':');
    std::size_t i;
    double k;
    if(colon == std::string::npos || !parse_index(item.substr(0, colon), i) || !parse(item.substr(colon + 1), k))
      throw Usage_error("option --" + option + " expects " + expected + ", got '" + shorten(item) + "'");
    out.push_back(std::make_pair(i, k));
    start = comma + 1;
  }
  return out;
}

Indexed_values index_list_option(const Args& args, const std::string& option)
{
  return pairs_option(args, option, parse_number, "'i:k,i:k,...' (k an integer, p/q or a decimal)");
}

} // namespace smdf_cli
