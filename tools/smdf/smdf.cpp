// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// smdf: command-line front end of the Surface_mesh_direction_fields package.
//
//   smdf <command> [options] MESH      one JSON object on stdout, or one error line on stderr
//
// Exit codes: 0 success, 1 the input cannot be processed, 2 usage error, 3 a result that is
// printed but flagged as failed (cone-metric: not converged; JSON on stdout and one error line).
// Vertex and face indices are 0-based in file order (read_triangle_mesh() keeps it).
//
// Adding a subcommand: write `Json run_<name>(const Args&)` and add one entry to `commands()`
// (name, positional arguments, options, help text); parsing, --help and error reporting are
// shared. Throw `Usage_error` for bad invocations and `Error` (or let `SMDF::Input_error`
// escape, wrapped by `on_file()`) for bad input.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_mesh_direction_fields/cone_metric.h>
#include <CGAL/Surface_mesh_direction_fields/errors.h>
#include <CGAL/Surface_mesh_direction_fields/field_singularities.h>
#include <CGAL/Surface_mesh_direction_fields/holonomy.h>
#include <CGAL/Surface_mesh_direction_fields/homology_generators.h>
#include <CGAL/Surface_mesh_direction_fields/intrinsic_geometry.h>
#include <CGAL/Surface_mesh_direction_fields/parameters.h>
#include <CGAL/Surface_mesh_direction_fields/IO/read_triangle_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/IO/svg_writer.h>
#include <CGAL/Surface_mesh_direction_fields/topology.h>
#include <CGAL/Surface_mesh_direction_fields/Trivial_connection.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <locale>
#include <map>
#include <new>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <unistd.h>   // isatty

#ifndef SMDF_VERSION
#define SMDF_VERSION "unknown"
#endif

namespace SMDF = CGAL::Surface_mesh_direction_fields;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;
typedef boost::graph_traits<Mesh>::edge_descriptor edge_descriptor;
typedef boost::graph_traits<Mesh>::face_descriptor face_descriptor;

namespace {

// ---- JSON ---------------------------------------------------------------------------------

// A JSON value with insertion-ordered objects. Reals are written with 17 significant digits;
// non-finite reals, which JSON cannot represent, are written as null.
class Json
{
public:
  Json() : type_(NUL) {}
  Json(bool b) : type_(BOOL), bool_(b) {}
  template <typename T,
            typename std::enable_if<std::is_integral<T>::value && !std::is_same<T, bool>::value,
                                    int>::type = 0>
  Json(T v) : type_(std::is_signed<T>::value ? INT : UINT), int_(static_cast<long long>(v)),
              uint_(static_cast<unsigned long long>(v)) {}
  Json(double d) : type_(REAL), real_(d) {}
  Json(const char* s) : type_(STRING), string_(s) {}
  Json(std::string s) : type_(STRING), string_(std::move(s)) {}

  static Json array() { Json j; j.type_ = ARRAY; return j; }
  static Json object() { Json j; j.type_ = OBJECT; return j; }
  // [a, b]: vertex pairs, 2D vectors, ...
  template <typename A, typename B>
  static Json pair(const A& a, const B& b) { Json j = array(); j.push_back(a); j.push_back(b); return j; }

  // Appends to an array.
  Json& push_back(Json v)
  {
    require(ARRAY);
    items_.push_back(std::move(v));
    return items_.back();
  }
  // Member of an object, appended (null) if absent.
  Json& operator[](const std::string& key)
  {
    require(OBJECT);
    for(std::size_t i = 0; i < keys_.size(); ++i)
      if(keys_[i] == key) return items_[i];
    keys_.push_back(key);
    items_.emplace_back();
    return items_.back();
  }

  void write(std::ostream& os) const
  {
    switch(type_) {
      case NUL: os << "null"; break;
      case BOOL: os << (bool_ ? "true" : "false"); break;
      case INT: os << int_; break;
      case UINT: os << uint_; break;
      case REAL: write_real(os, real_); break;
      case STRING: write_string(os, string_); break;
      case ARRAY:
        os << '[';
        for(std::size_t i = 0; i < items_.size(); ++i) {
          if(i) os << ',';
          items_[i].write(os);
        }
        os << ']';
        break;
      case OBJECT:
        os << '{';
        for(std::size_t i = 0; i < items_.size(); ++i) {
          if(i) os << ',';
          write_string(os, keys_[i]);
          os << ':';
          items_[i].write(os);
        }
        os << '}';
        break;
    }
  }

  std::string str() const
  {
    std::ostringstream os;
    os.imbue(std::locale::classic());
    write(os);
    return os.str();
  }

private:
  enum Type { NUL, BOOL, INT, UINT, REAL, STRING, ARRAY, OBJECT };
  Type type_;
  bool bool_ = false;
  long long int_ = 0;
  unsigned long long uint_ = 0;
  double real_ = 0;
  std::string string_;
  std::vector<Json> items_;        // array elements or object values
  std::vector<std::string> keys_;  // object keys

  void require(Type t) const
  {
    if(type_ != t) throw std::logic_error("Json: wrong value type for this operation");
  }

  static void write_real(std::ostream& os, double d)
  {
    if(!std::isfinite(d)) { os << "null"; return; }
    const std::streamsize old = os.precision(17);
    os << d;
    os.precision(old);
  }

  // Length of the valid UTF-8 sequence starting at s[i], or 0 if it is not valid.
  static std::size_t utf8_length(const std::string& s, std::size_t i)
  {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    std::size_t n;
    unsigned int cp;
    if(c < 0x80) return 1;
    else if((c & 0xE0) == 0xC0) { n = 2; cp = c & 0x1F; }
    else if((c & 0xF0) == 0xE0) { n = 3; cp = c & 0x0F; }
    else if((c & 0xF8) == 0xF0) { n = 4; cp = c & 0x07; }
    else return 0;
    if(i + n > s.size()) return 0;
    for(std::size_t k = 1; k < n; ++k) {
      const unsigned char d = static_cast<unsigned char>(s[i + k]);
      if((d & 0xC0) != 0x80) return 0;
      cp = (cp << 6) | (d & 0x3F);
    }
    static const unsigned int min_cp[5] = {0, 0, 0x80, 0x800, 0x10000};
    if(cp < min_cp[n] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return 0;
    return n;
  }

  // Quotes and escapes a string; bytes that are not valid UTF-8 become U+FFFD.
  static void write_string(std::ostream& os, const std::string& s)
  {
    os << '"';
    for(std::size_t i = 0; i < s.size();) {
      const unsigned char c = static_cast<unsigned char>(s[i]);
      switch(c) {
        case '"': os << "\\\""; ++i; continue;
        case '\\': os << "\\\\"; ++i; continue;
        case '\b': os << "\\b"; ++i; continue;
        case '\f': os << "\\f"; ++i; continue;
        case '\n': os << "\\n"; ++i; continue;
        case '\r': os << "\\r"; ++i; continue;
        case '\t': os << "\\t"; ++i; continue;
        default: break;
      }
      if(c < 0x20 || c == 0x7F) {
        static const char* hex = "0123456789abcdef";
        os << "\\u00" << hex[c >> 4] << hex[c & 15];
        ++i;
        continue;
      }
      const std::size_t n = utf8_length(s, i);
      if(n == 0) { os << "\\ufffd"; ++i; continue; }
      os.write(s.data() + i, std::streamsize(n));
      i += n;
    }
    os << '"';
  }
};

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

Error file_error(const std::string& file, const std::string& message, const char* kind)
{
  return Error(file + ": " + message + " [" + kind + "]");
}

// Runs f(), turning a library Input_error into an Error that names `file`.
template <typename F>
auto on_file(const std::string& file, F f) -> decltype(f())
{
  try {
    return f();
  } catch(const SMDF::Input_error& e) {
    std::string message = e.what();
    const std::string quoted = "'" + file + "' ";   // "'f.obj' line 3: ..." -> "line 3: ..."
    if(message.compare(0, quoted.size(), quoted) == 0) message.erase(0, quoted.size());
    throw file_error(file, message, SMDF::Input_error::kind_name(e.kind()));
  }
}

// Silences std::cerr while alive: CGAL's readers may print diagnostics of their own, and the
// tool promises exactly one error line.
class Silence_cerr
{
public:
  Silence_cerr() : old_(std::cerr.rdbuf(sink_.rdbuf())) {}
  ~Silence_cerr() { std::cerr.rdbuf(old_); }
  Silence_cerr(const Silence_cerr&) = delete;
  Silence_cerr& operator=(const Silence_cerr&) = delete;

private:
  std::ostringstream sink_;
  std::streambuf* old_;
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
  double real(const std::string& name, double fallback) const
  {
    if(!has(name)) return fallback;
    const std::string& s = options.at(name);
    char* end = nullptr;
    const double d = s.empty() ? 0 : std::strtod(s.c_str(), &end);
    if(s.empty() || *end != '\0' || !std::isfinite(d))
      throw Usage_error("option --" + name + " expects a finite number, got '" + s + "'");
    return d;
  }

  // An integer option value; malformed or out-of-range values are usage errors.
  long integer(const std::string& name, long fallback) const
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

const std::vector<Command>& commands();

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

std::string synopsis(const Command& cmd)
{
  std::string s = "smdf " + cmd.name;
  for(const std::string& p : cmd.positionals) s += " " + p;
  for(const Option_spec& o : cmd.options)
    s += " [--" + o.name + (o.value_name.empty() ? "" : " " + o.value_name) + "]";
  return s;
}

void print_usage(std::ostream& os)
{
  os << "usage: smdf <command> [options] MESH\n"
        "       smdf <command> --help\n"
        "       smdf --version\n\n"
        "Reads a triangle mesh (OFF, OBJ or PLY; it must be an orientable 2-manifold, possibly\n"
        "with boundary and several components) and prints one JSON object on stdout. Vertex and\n"
        "face indices are 0-based in file order. On failure prints one line to stderr and exits\n"
        "with 1 (input that cannot be processed) or 2 (usage error); exit code 3 means the JSON\n"
        "object was printed but the result failed (cone-metric: not converged, one stderr line).\n\n"
        "commands:\n";
  for(const Command& c : commands())
    os << "  " << std::left << std::setw(14) << c.name << c.summary << "\n";
}

void print_command_usage(const Command& cmd, std::ostream& os)
{
  os << "usage: " << synopsis(cmd) << "\n\n" << cmd.description;
  os << "\noptions:\n";
  for(const Option_spec& o : cmd.options) {
    const std::string head = "--" + o.name + (o.value_name.empty() ? "" : " " + o.value_name);
    os << "  " << std::left << std::setw(18) << head << o.help << "\n";
  }
  os << "  " << std::left << std::setw(18) << "-h, --help" << "print this help and exit\n";
}

// ---- Helpers shared by subcommands --------------------------------------------------------

class Stopwatch
{
public:
  Stopwatch() : start_(clock::now()), lap_(start_) {}
  // Seconds since the previous lap (or the start).
  double lap()
  {
    const clock::time_point now = clock::now();
    const double s = std::chrono::duration<double>(now - lap_).count();
    lap_ = now;
    return s;
  }
  double total() const { return std::chrono::duration<double>(clock::now() - start_).count(); }

private:
  typedef std::chrono::steady_clock clock;
  clock::time_point start_, lap_;
};

std::size_t index(vertex_descriptor v) { return std::size_t(v); }

// Reads and validates a mesh; errors name the file.
SMDF::Polygon_soup_report load_mesh(const std::string& file, Mesh& mesh)
{
  return on_file(file, [&] {
    Silence_cerr quiet;
    return SMDF::read_triangle_mesh(file, mesh);
  });
}

const char* kind_name(SMDF::Generator_kind k)
{
  return k == SMDF::HANDLE_GENERATOR ? "handle" : "boundary";
}

// Faces whose Euclidean edge lengths do not form a proper triangle: the same test as the
// library's metric validation (is_valid_triangle() and relative area above 1e-14).
std::size_t count_degenerate_faces(const Mesh& mesh)
{
  const auto len = SMDF::get_edge_length_map(mesh);
  std::size_t n = 0;
  for(face_descriptor f : faces(mesh)) {
    const halfedge_descriptor h0 = halfedge(f, mesh), h1 = next(h0, mesh), h2 = next(h1, mesh);
    const double l0 = get(len, edge(h0, mesh)), l1 = get(len, edge(h1, mesh)),
                 l2 = get(len, edge(h2, mesh));
    const double lmax = (std::max)(l0, (std::max)(l1, l2));
    if(!SMDF::is_valid_triangle(l0, l1, l2) || SMDF::triangle_area(l0, l1, l2) <= 1e-14 * lmax * lmax)
      ++n;
  }
  return n;
}

std::string shorten(const std::string& s, std::size_t n = 40)
{
  return s.size() <= n ? s : s.substr(0, n) + "...";
}

// A non-negative decimal integer without sign, or false.
bool parse_index(const std::string& s, std::size_t& out)
{
  if(s.empty() || s.size() > 18 || !std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return false;
  out = std::size_t(std::stoull(s));
  return true;
}

typedef Mesh::Property_map<edge_descriptor, double> Edge_length_property;

// Reads an edge-length file: one line `i j length` per edge of `mesh` (vertex indices in
// either order); blank lines and lines starting with '#' are ignored. Every problem is an
// Error naming the file and the line.
Edge_length_property read_edge_lengths(const std::string& file, Mesh& mesh)
{
  std::ifstream in(file);
  if(!in) throw file_error(file, "cannot open file", "file_error");
  Edge_length_property lengths =
    mesh.add_property_map<edge_descriptor, double>("e:smdf_length", 0.).first;
  std::vector<std::size_t> given_on(num_edges(mesh), 0);   // line number per edge, 0 = missing
  const std::size_t nv = num_vertices(mesh);
  std::string line;
  std::size_t line_no = 0;
  auto fail = [&](const std::string& what) {
    return file_error(file, "line " + std::to_string(line_no) + ": " + what, "file_error");
  };
  while(std::getline(in, line)) {
    ++line_no;
    std::istringstream is(line);
    std::vector<std::string> tok;
    for(std::string t; is >> t;) tok.push_back(t);
    if(tok.empty() || tok[0][0] == '#') continue;
    if(tok.size() != 3)
      throw fail("expected 'i j length', got " + std::to_string(tok.size()) + " fields");
    std::size_t ij[2];
    for(int k = 0; k < 2; ++k) {
      if(!parse_index(tok[k], ij[k]))
        throw fail("'" + shorten(tok[k]) + "' is not a vertex index");
      if(ij[k] >= nv)
        throw fail("vertex " + tok[k] + " does not exist (the mesh has " + std::to_string(nv) + " vertices)");
    }
    const std::string pair = "(" + tok[0] + ", " + tok[1] + ")";
    const auto h = halfedge(vertex_descriptor(Mesh::size_type(ij[0])),
                            vertex_descriptor(Mesh::size_type(ij[1])), mesh);
    if(!h.second)
      throw fail("vertices " + tok[0] + " and " + tok[1] + " are not joined by an edge of the mesh");
    const edge_descriptor e = edge(h.first, mesh);
    if(given_on[std::size_t(e)] != 0)
      throw fail("edge " + pair + " was already given on line " + std::to_string(given_on[std::size_t(e)]));
    char* end = nullptr;
    const double l = std::strtod(tok[2].c_str(), &end);
    if(*end != '\0')
      throw fail("'" + shorten(tok[2]) + "' is not a number");
    if(!std::isfinite(l) || !(l > 0))
      throw fail("the length of edge " + pair + " must be positive and finite, got " + shorten(tok[2]));
    put(lengths, e, l);
    given_on[std::size_t(e)] = line_no;
  }
  if(in.bad()) throw file_error(file, "read error", "file_error");
  const std::size_t missing = std::size_t(std::count(given_on.begin(), given_on.end(), std::size_t(0)));
  if(missing > 0) {
    for(edge_descriptor e : edges(mesh))
      if(given_on[std::size_t(e)] == 0) {
        const halfedge_descriptor h = halfedge(e, mesh);
        throw file_error(file, "no length for edge (" + std::to_string(index(source(h, mesh))) + ", " +
                         std::to_string(index(target(h, mesh))) + "); " + std::to_string(missing) +
                         " of " + std::to_string(num_edges(mesh)) + " edges are missing", "file_error");
      }
  }
  return lengths;
}

// ---- info ---------------------------------------------------------------------------------

Json run_info(const Args& args)
{
  const std::string& file = args.positional[0];
  Mesh mesh;
  const SMDF::Polygon_soup_report report = load_mesh(file, mesh);
  const SMDF::Mesh_topology<Mesh> topo = on_file(file, [&] { return SMDF::mesh_topology(mesh); });

  Json genus = Json::array();
  for(const SMDF::Component_topology& c : topo.components) genus.push_back(c.genus);

  Json out = Json::object();
  out["file"] = file;
  out["vertices"] = num_vertices(mesh);
  out["edges"] = num_edges(mesh);
  out["faces"] = num_faces(mesh);
  out["components"] = topo.components.size();
  out["boundary_loops"] = topo.boundary_loops.size();
  out["euler_characteristic"] = topo.euler_characteristic();
  out["genus"] = genus;
  out["closed"] = topo.is_closed();
  out["betti_1"] = topo.betti_1();
  out["isolated_vertices"] = topo.isolated_vertices;
  out["reoriented_faces"] = report.reoriented_polygons;
  out["degenerate_faces"] = count_degenerate_faces(mesh);
  return out;
}

// ---- generators ---------------------------------------------------------------------------

Json run_generators(const Args& args)
{
  const std::string& file = args.positional[0];
  Mesh mesh;
  load_mesh(file, mesh);
  const SMDF::Mesh_topology<Mesh> topo = on_file(file, [&] { return SMDF::mesh_topology(mesh); });
  const std::vector<SMDF::Homology_generator<Mesh>> gens =
    on_file(file, [&] { return SMDF::tree_cotree_generators(mesh); });

  Json list = Json::array();
  for(const SMDF::Homology_generator<Mesh>& g : gens) {
    Json dual = Json::array();
    for(halfedge_descriptor h : g.dual_cycle)
      dual.push_back(Json::pair(index(source(h, mesh)), index(target(h, mesh))));
    Json primal = Json::array();
    for(halfedge_descriptor h : g.primal_loop) primal.push_back(index(source(h, mesh)));
    Json j = Json::object();
    j["kind"] = kind_name(g.kind);
    j["component"] = g.component;
    j["dual_edges"] = std::move(dual);
    j["primal_loop"] = std::move(primal);
    list.push_back(std::move(j));
  }
  Json out = Json::object();
  out["file"] = file;
  out["count"] = gens.size();
  out["betti_1"] = topo.betti_1();
  out["generators"] = std::move(list);
  return out;
}

// ---- holonomy -----------------------------------------------------------------------------

// Gauss-Bonnet and the holonomy of every generator for the metric given by `np`, read from
// `metric_file` (errors of the metric, such as degenerate faces, name that file).
template <typename NamedParameters>
void holonomy_report(const std::string& file, const std::string& metric_file, const Mesh& mesh,
                     const NamedParameters& np, Json& out, Json& timings, Stopwatch& clock)
{
  const SMDF::Mesh_topology<Mesh> topo = on_file(file, [&] { return SMDF::mesh_topology(mesh); });
  const double total = on_file(metric_file, [&] { return SMDF::total_angle_defect(mesh, np); });
  timings["curvature"] = clock.lap();
  const SMDF::Intrinsic_holonomy<Mesh> holonomy =
    on_file(metric_file, [&] { return SMDF::Intrinsic_holonomy<Mesh>(mesh, np); });
  timings["precompute"] = clock.lap();
  const std::vector<SMDF::Homology_generator<Mesh>> gens =
    on_file(file, [&] { return SMDF::tree_cotree_generators(mesh); });
  timings["generators"] = clock.lap();

  Json list = Json::array();
  for(const SMDF::Homology_generator<Mesh>& g : gens) {
    const double lc = on_file(file, [&] { return holonomy.levi_civita_holonomy(g.dual_cycle); });
    const SMDF::Rigid_motion_2 m = on_file(file, [&] { return holonomy.generalized_holonomy(g.dual_cycle); });
    Json gh = Json::object();
    gh["rotation"] = m.rotation;
    gh["translation"] = Json::pair(m.translation.x(), m.translation.y());
    Json j = Json::object();
    j["kind"] = kind_name(g.kind);
    j["component"] = g.component;
    j["dual_cycle_length"] = g.dual_cycle.size();
    j["levi_civita_holonomy"] = lc;
    j["generalized_holonomy"] = std::move(gh);
    list.push_back(std::move(j));
  }
  timings["holonomy"] = clock.lap();

  const double two_pi_chi = 2 * CGAL_PI * double(topo.euler_characteristic());
  out["euler_characteristic"] = topo.euler_characteristic();
  out["total_angle_defect"] = total;
  out["two_pi_chi"] = two_pi_chi;
  out["gauss_bonnet_error"] = std::abs(total - two_pi_chi);
  out["generators"] = std::move(list);
}

Json run_holonomy(const Args& args)
{
  Stopwatch clock;
  const std::string& file = args.positional[0];
  Json out = Json::object();
  Json timings = Json::object();
  Mesh mesh;
  load_mesh(file, mesh);
  timings["read"] = clock.lap();
  out["file"] = file;
  if(args.has("lengths")) {
    const std::string lengths_file = args.value("lengths");
    const Edge_length_property lengths = read_edge_lengths(lengths_file, mesh);
    timings["lengths"] = clock.lap();
    out["metric"] = "lengths";
    out["lengths_file"] = lengths_file;
    holonomy_report(file, lengths_file, mesh, SMDF::parameters::edge_length_map(lengths), out,
                    timings, clock);
  } else {
    out["metric"] = "euclidean";
    holonomy_report(file, file, mesh, SMDF::parameters::default_values(), out, timings, clock);
  }
  timings["total"] = clock.total();
  out["timings"] = std::move(timings);
  return out;
}

// ---- Trivial connections: shared parsing --------------------------------------------------

// A number written as an integer, a fraction "p/q" or a decimal; false if malformed.
bool parse_number(const std::string& s, double& out)
{
  auto real = [](const std::string& t, double& d) {
    if(t.empty() || std::isspace(static_cast<unsigned char>(t[0]))) return false;
    char* end = nullptr;
    d = std::strtod(t.c_str(), &end);
    return *end == '\0' && std::isfinite(d);
  };
  const std::size_t slash = s.find('/');
  if(slash == std::string::npos) return real(s, out);
  double p, q;
  if(!real(s.substr(0, slash), p) || !real(s.substr(slash + 1), q) || q == 0) return false;
  out = p / q;
  return std::isfinite(out);
}

std::string format_real(double d)
{
  std::ostringstream os;
  os.imbue(std::locale::classic());
  os.precision(17);
  os << d;
  return os.str();
}

// "i:k,i:k,...": pairs (index, number); syntax errors are usage errors naming `option`.
std::vector<std::pair<std::size_t, double>> parse_pairs(const std::string& option, const std::string& s)
{
  std::vector<std::pair<std::size_t, double>> out;
  std::size_t start = 0;
  while(start <= s.size()) {
    std::size_t comma = s.find(',', start);
    if(comma == std::string::npos) comma = s.size();
    const std::string item = s.substr(start, comma - start);
    const std::size_t colon = item.find(':');
    std::size_t i;
    double k;
    if(colon == std::string::npos || !parse_index(item.substr(0, colon), i) ||
       !parse_number(item.substr(colon + 1), k))
      throw Usage_error("option --" + option + " expects 'i:k,i:k,...' (k an integer, p/q or a "
                        "decimal), got '" + shorten(item) + "'");
    out.push_back(std::make_pair(i, k));
    start = comma + 1;
  }
  return out;
}

// Lines of a text file split into fields; blank lines and '#' comments are skipped. Calls
// f(line_no, fields) for every other line.
template <typename F>
void for_each_data_line(const std::string& file, F f)
{
  std::ifstream in(file);
  if(!in) throw file_error(file, "cannot open file", "file_error");
  std::string line;
  std::size_t line_no = 0;
  while(std::getline(in, line)) {
    ++line_no;
    const std::size_t hash = line.find('#');
    if(hash != std::string::npos) line.erase(hash);
    std::istringstream is(line);
    std::vector<std::string> tok;
    for(std::string t; is >> t;) tok.push_back(t);
    if(tok.empty()) continue;
    f(line_no, tok);
  }
  if(in.bad()) throw file_error(file, "read error", "file_error");
}

Error line_error(const std::string& file, std::size_t line_no, const std::string& what)
{
  return file_error(file, "line " + std::to_string(line_no) + ": " + what, "file_error");
}

// Angle of the projection of (x, y, z) on the plane of f, in the frame of vectors_to_face_angles().
bool direction_angle(const Mesh& mesh, face_descriptor f, const double v[3], double& angle)
{
  const halfedge_descriptor h = halfedge(f, mesh);
  const K::Point_3& p0 = mesh.point(source(h, mesh));
  const K::Point_3& p1 = mesh.point(target(h, mesh));
  const K::Point_3& p2 = mesh.point(target(next(h, mesh), mesh));
  const double e1[3] = {p1.x() - p0.x(), p1.y() - p0.y(), p1.z() - p0.z()};
  const double e2[3] = {p2.x() - p0.x(), p2.y() - p0.y(), p2.z() - p0.z()};
  const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
  const double b[3] = {n[1] * e1[2] - n[2] * e1[1], n[2] * e1[0] - n[0] * e1[2], n[0] * e1[1] - n[1] * e1[0]};
  const double le = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
  const double lb = std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
  if(!(le > 0) || !(lb > 0)) return false;
  const double x = (v[0] * e1[0] + v[1] * e1[1] + v[2] * e1[2]) / le;
  const double y = (v[0] * b[0] + v[1] * b[1] + v[2] * b[2]) / lb;
  const double norm = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if(!(std::hypot(x, y) > 1e-12 * norm)) return false;   // normal to the face
  angle = std::atan2(y, x);
  if(angle < 0) angle += 2 * CGAL_PI;
  return true;
}

long symmetry_order_option(const Args& args)
{
  const long N = args.integer("N", 1);
  if(N < 1 || N > 1000000)
    throw Usage_error("option --N expects an integer >= 1, got '" + args.value("N") + "'");
  return N;
}

Json singularity_list(const std::vector<std::pair<std::size_t, double>>& s)
{
  Json list = Json::array();
  for(const auto& p : s) {
    Json j = Json::object();
    j["vertex"] = p.first;
    j["index"] = p.second;
    list.push_back(std::move(j));
  }
  return list;
}

template <typename Topology>
Json found_list(const Topology& topo)
{
  std::vector<std::pair<std::size_t, double>> s;
  for(const auto& p : topo.singularities) s.push_back(std::make_pair(index(p.first), p.second));
  std::sort(s.begin(), s.end());
  return singularity_list(s);
}

typedef Mesh::Property_map<face_descriptor, double> Face_angle_property;
typedef Mesh::Property_map<face_descriptor, K::Vector_3> Face_vector_property;

void write_lines_file(const std::string& file, const std::string& text)
{
  std::ofstream out(file);
  if(!out) throw file_error(file, "cannot open file for writing", "file_error");
  out << text;
  out.flush();
  if(!out) throw file_error(file, "write error", "file_error");
}

// ---- connection ---------------------------------------------------------------------------

Json run_connection(const Args& args)
{
  const std::string& file = args.positional[0];
  const long N = symmetry_order_option(args);
  const std::string weights_name = args.value("weights", "cotan");
  SMDF::Connection_weights weights;
  if(weights_name == "cotan") weights = SMDF::COTAN_WEIGHTS;
  else if(weights_name == "unit") weights = SMDF::UNIT_WEIGHTS;
  else throw Usage_error("option --weights expects 'cotan' or 'unit', got '" + shorten(weights_name) + "'");
  const long edits = args.integer("edit-benchmark", 0);
  if(edits < 0) throw Usage_error("option --edit-benchmark expects a non-negative integer");

  SMDF::Svg_options svg;
  if(!args.has("svg") && (args.has("view") || args.has("width")))
    throw Usage_error(std::string("option --") + (args.has("view") ? "view" : "width") + " needs --svg FILE");
  if(args.has("view")) {
    const std::string view = args.value("view");
    const std::size_t comma = view.find(',');
    const std::size_t comma2 = comma == std::string::npos ? comma : view.find(',', comma + 1);
    auto real = [](const std::string& t, double& d) {
      if(t.empty() || std::isspace(static_cast<unsigned char>(t[0]))) return false;
      char* end = nullptr;
      d = std::strtod(t.c_str(), &end);
      return *end == '\0' && std::isfinite(d);
    };
    double a = 0, e = 0;
    const std::string axis = comma2 == std::string::npos ? "z" : view.substr(comma2 + 1);
    if(comma == std::string::npos || !real(view.substr(0, comma), a) ||
       !real(view.substr(comma + 1, comma2 == std::string::npos ? std::string::npos : comma2 - comma - 1), e) ||
       (axis != "x" && axis != "y" && axis != "z"))
      throw Usage_error("option --view expects 'azimuth,elevation' in degrees, optionally followed by ',x', "
                        "',y' or ',z' (the up axis, default z), got '" + shorten(view) + "'");
    svg.up_axis = axis[0] - 'x';
    svg.azimuth = a;
    svg.elevation = e;
  }
  if(args.has("width")) {
    const long w = args.integer("width", 800);
    if(w < 1 || w > 100000) throw Usage_error("option --width expects a number of pixels in [1, 100000], got '" + args.value("width") + "'");
    svg.width = int(w);
  }

  std::vector<std::pair<std::size_t, double>> sing, turning;
  if(args.has("singularities")) sing = parse_pairs("singularities", args.value("singularities"));
  if(args.has("generator-turning")) turning = parse_pairs("generator-turning", args.value("generator-turning"));

  Mesh mesh;
  load_mesh(file, mesh);
  const std::size_t nv = num_vertices(mesh), nf = num_faces(mesh);

  std::vector<std::string> given_by(nv);   // where each vertex's index was given
  for(const auto& s : sing) {
    if(s.first >= nv)
      throw Error("--singularities: vertex " + std::to_string(s.first) + " does not exist (the mesh has " +
                  std::to_string(nv) + " vertices)");
    if(!given_by[s.first].empty())
      throw Error("--singularities: vertex " + std::to_string(s.first) + " is given twice");
    given_by[s.first] = "--singularities";
  }
  if(args.has("singularities-file")) {
    const std::string sf = args.value("singularities-file");
    for_each_data_line(sf, [&](std::size_t line_no, const std::vector<std::string>& tok) {
      std::size_t v;
      double k;
      if(tok.size() != 2) throw line_error(sf, line_no, "expected 'vertex index', got " + std::to_string(tok.size()) + " fields");
      if(!parse_index(tok[0], v)) throw line_error(sf, line_no, "'" + shorten(tok[0]) + "' is not a vertex index");
      if(v >= nv) throw line_error(sf, line_no, "vertex " + tok[0] + " does not exist (the mesh has " + std::to_string(nv) + " vertices)");
      if(!parse_number(tok[1], k)) throw line_error(sf, line_no, "'" + shorten(tok[1]) + "' is not a number (integer, p/q or decimal)");
      if(!given_by[v].empty()) throw line_error(sf, line_no, "vertex " + tok[0] + " was already given by " + given_by[v]);
      given_by[v] = "line " + std::to_string(line_no);
      sing.push_back(std::make_pair(v, k));
    });
  }

  std::vector<std::pair<face_descriptor, double>> constraints;
  if(args.has("constraints")) {
    const std::string cf = args.value("constraints");
    std::vector<std::size_t> seen(nf, 0);
    for_each_data_line(cf, [&](std::size_t line_no, const std::vector<std::string>& tok) {
      std::size_t fi;
      if(tok.size() != 2 && tok.size() != 4)
        throw line_error(cf, line_no, "expected 'face angle' or 'face x y z', got " + std::to_string(tok.size()) + " fields");
      if(!parse_index(tok[0], fi)) throw line_error(cf, line_no, "'" + shorten(tok[0]) + "' is not a face index");
      if(fi >= nf) throw line_error(cf, line_no, "face " + tok[0] + " does not exist (the mesh has " + std::to_string(nf) + " faces)");
      if(seen[fi]) throw line_error(cf, line_no, "face " + tok[0] + " was already constrained on line " + std::to_string(seen[fi]));
      seen[fi] = line_no;
      double v[3];
      for(std::size_t k = 1; k < tok.size(); ++k) {
        char* end = nullptr;
        v[k - 1] = std::strtod(tok[k].c_str(), &end);
        if(*end != '\0' || !std::isfinite(v[k - 1]))
          throw line_error(cf, line_no, "'" + shorten(tok[k]) + "' is not a finite number");
      }
      const face_descriptor f = face_descriptor(Mesh::size_type(fi));
      double angle = v[0];
      if(tok.size() == 4 && !direction_angle(mesh, f, v, angle))
        throw line_error(cf, line_no, "the direction of face " + tok[0] + " has no component in the face plane");
      constraints.push_back(std::make_pair(f, angle));
    });
  }

  Stopwatch clock;
  SMDF::Trivial_connection<Mesh> tc(mesh, SMDF::parameters::symmetry_order(int(N)).connection_weights(weights));
  const double construct_s = clock.lap();
  for(const auto& s : sing) tc.set_singularity(vertex_descriptor(Mesh::size_type(s.first)), s.second);
  for(const auto& t : turning) tc.set_generator_turning_number(t.first, t.second);
  if(!constraints.empty()) tc.set_directional_constraints(constraints);
  clock.lap();
  const SMDF::Trivial_connection_status st = tc.solve();
  clock.lap();
  if(!st.success) throw Error(file + ": trivial connection solve failed: " + st.message);

  Face_angle_property angles = mesh.add_property_map<face_descriptor, double>("f:smdf_angle", 0.).first;
  tc.field_angles(angles);
  const double field_s = clock.lap();
  const SMDF::Field_topology<Mesh> topo =
    on_file(file, [&] { return SMDF::field_singularities(mesh, angles, SMDF::parameters::symmetry_order(int(N))); });

  if(args.has("field-out") || args.has("svg")) {
    Face_vector_property vectors =
      mesh.add_property_map<face_descriptor, K::Vector_3>("f:smdf_vector", K::Vector_3(0, 0, 0)).first;
    tc.angles_to_vectors(angles, vectors);
    if(args.has("svg")) {
      std::ostringstream os;
      SMDF::write_field_svg(os, mesh, vectors, int(N), topo.singularities, svg);
      write_lines_file(args.value("svg"), os.str());
    }
  }
  if(args.has("field-out")) {
    Face_vector_property vectors = mesh.property_map<face_descriptor, K::Vector_3>("f:smdf_vector").first;
    std::ostringstream os;
    os.imbue(std::locale::classic());
    os.precision(17);
    for(face_descriptor f : faces(mesh)) {
      const K::Vector_3& v = get(vectors, f);
      os << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
    }
    write_lines_file(args.value("field-out"), os.str());
  }
  if(args.has("connection-out")) {
    std::ostringstream os;
    os.imbue(std::locale::classic());
    os.precision(17);
    for(edge_descriptor e : edges(mesh)) {
      if(is_border(e, mesh)) continue;
      const halfedge_descriptor h = halfedge(e, mesh);
      os << index(source(h, mesh)) << ' ' << index(target(h, mesh)) << ' ' << tc.adjustment_angle(h) << '\n';
    }
    write_lines_file(args.value("connection-out"), os.str());
  }

  // Editing benchmark: move a random singularity to a random free interior vertex, re-solve.
  Json edit_median;
  if(edits > 0 && !sing.empty()) {
    std::vector<vertex_descriptor> interior;
    for(vertex_descriptor v : vertices(mesh))
      if(!is_border(v, mesh) && halfedge(v, mesh) != boost::graph_traits<Mesh>::null_halfedge())
        interior.push_back(v);
    std::vector<std::pair<vertex_descriptor, double>> current;
    for(const auto& s : sing)
      if(s.second != 0) current.push_back(std::make_pair(vertex_descriptor(Mesh::size_type(s.first)), s.second));
    std::mt19937 rng(12345);
    std::vector<double> times;
    for(long k = 0; k < edits && !current.empty(); ++k) {
      auto& s = current[std::uniform_int_distribution<std::size_t>(0, current.size() - 1)(rng)];
      vertex_descriptor to = s.first;
      for(int tries = 0; tries < 100 && tc.singularity_index(to) != 0; ++tries)
        to = interior[std::uniform_int_distribution<std::size_t>(0, interior.size() - 1)(rng)];
      if(tc.singularity_index(to) != 0) continue;
      tc.set_singularity(s.first, 0);
      tc.set_singularity(to, s.second);
      s.first = to;
      Stopwatch edit_clock;
      const SMDF::Trivial_connection_status est = tc.solve();
      if(!est.success) throw Error(file + ": trivial connection solve failed during --edit-benchmark: " + est.message);
      tc.field_angles(angles);
      times.push_back(edit_clock.total());
    }
    if(!times.empty()) {
      std::sort(times.begin(), times.end());
      const std::size_t m = times.size() / 2;
      edit_median = times.size() % 2 ? times[m] : 0.5 * (times[m - 1] + times[m]);
    }
  }

  // As set before the edits, rounded to multiples of 1/N as the library stores them.
  std::sort(sing.begin(), sing.end());
  std::vector<std::pair<std::size_t, double>> prescribed;
  for(const auto& s : sing)
    if(s.second != 0) prescribed.push_back(std::make_pair(s.first, std::round(s.second * double(N)) / double(N)));

  Json turning_numbers = Json::array();
  for(double t : topo.generator_turning_numbers) turning_numbers.push_back(t);
  Json timings = Json::object();
  timings["setup_s"] = construct_s + st.factor_seconds;
  timings["solve_s"] = st.solve_seconds;
  timings["field_s"] = field_s;
  timings["edit_median_s"] = edit_median;

  Json out = Json::object();
  out["N"] = N;
  out["weights"] = weights_name;
  out["prescribed"] = singularity_list(prescribed);
  out["found"] = found_list(topo);
  out["generator_turning_numbers"] = std::move(turning_numbers);
  out["energy"] = st.energy;
  out["residual"] = st.residual;
  out["max_holonomy_error"] = st.max_holonomy_error;
  out["success"] = st.success;
  out["timings"] = std::move(timings);
  return out;
}

// ---- singularities ------------------------------------------------------------------------

Json run_singularities(const Args& args)
{
  const std::string& file = args.positional[0];
  const long N = symmetry_order_option(args);
  if(!args.has("field")) throw Usage_error("missing option --field FILE" + see_help(args.command));
  const std::string ff = args.value("field");
  Mesh mesh;
  load_mesh(file, mesh);
  const std::size_t nf = num_faces(mesh);
  Face_vector_property vectors =
    mesh.add_property_map<face_descriptor, K::Vector_3>("f:smdf_vector", K::Vector_3(0, 0, 0)).first;
  std::size_t count = 0;
  for_each_data_line(ff, [&](std::size_t line_no, const std::vector<std::string>& tok) {
    if(count >= nf)
      throw line_error(ff, line_no, "more vectors than the " + std::to_string(nf) + " faces of the mesh");
    if(tok.size() != 3)
      throw line_error(ff, line_no, "expected 'x y z', got " + std::to_string(tok.size()) + " fields");
    double v[3];
    for(int k = 0; k < 3; ++k) {
      char* end = nullptr;
      v[k] = std::strtod(tok[k].c_str(), &end);
      if(*end != '\0' || !std::isfinite(v[k]))
        throw line_error(ff, line_no, "'" + shorten(tok[k]) + "' is not a finite number");
    }
    if(v[0] == 0 && v[1] == 0 && v[2] == 0)
      throw line_error(ff, line_no, "the vector of face " + std::to_string(count) + " is zero");
    put(vectors, face_descriptor(Mesh::size_type(count)), K::Vector_3(v[0], v[1], v[2]));
    ++count;
  });
  if(count < nf)
    throw file_error(ff, "only " + std::to_string(count) + " vectors for the " + std::to_string(nf) +
                     " faces of the mesh (one line 'x y z' per face)", "file_error");
  Face_angle_property angles = mesh.add_property_map<face_descriptor, double>("f:smdf_angle", 0.).first;
  SMDF::vectors_to_face_angles(mesh, vectors, angles);
  const SMDF::Field_topology<Mesh> topo =
    on_file(file, [&] { return SMDF::field_singularities(mesh, angles, SMDF::parameters::symmetry_order(int(N))); });
  Json turning_numbers = Json::array();
  for(double t : topo.generator_turning_numbers) turning_numbers.push_back(t);
  Json out = Json::object();
  out["N"] = N;
  out["singularities"] = found_list(topo);
  out["generator_turning_numbers"] = std::move(turning_numbers);
  out["max_rounding_error"] = topo.max_rounding_error;
  return out;
}

// ---- cone-metric --------------------------------------------------------------------------

// An angle in radians: a number as parse_number() reads it (integer, p/q, decimal), or a
// multiple of pi written [c][*]pi[/d], c and d numbers as above: pi, -pi, pi/2, -4pi, 3*pi/4,
// 0.5pi, 1/3*pi. False if malformed.
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

// "v:x,v:x,...": pairs (vertex, x) with x read by `parse` (parse_angle or parse_number);
// syntax errors are usage errors naming `option`.
std::vector<std::pair<std::size_t, double>> parse_vertex_values(const std::string& option, const std::string& s,
                                                                 bool (*parse)(const std::string&, double&),
                                                                 const char* what)
{
  std::vector<std::pair<std::size_t, double>> out;
  std::size_t start = 0;
  while(start <= s.size()) {
    std::size_t comma = s.find(',', start);
    if(comma == std::string::npos) comma = s.size();
    const std::string item = s.substr(start, comma - start);
    const std::size_t colon = item.find(':');
    std::size_t i;
    double k;
    if(colon == std::string::npos || !parse_index(item.substr(0, colon), i) || !parse(item.substr(colon + 1), k))
      throw Usage_error("option --" + option + " expects 'v:x,v:x,...' (x " + what + "), got '" + shorten(item) + "'");
    out.push_back(std::make_pair(i, k));
    start = comma + 1;
  }
  return out;
}

// Blue (negative) - white (0) - red (positive) colour of t in [-1, 1].
std::string diverging_color(double t)
{
  t = (std::max)(-1., (std::min)(1., std::isfinite(t) ? t : 0.));
  const double blue[3] = {33, 102, 172}, red[3] = {178, 24, 43};
  const double* end = t < 0 ? blue : red;
  const double a = std::abs(t);
  char buf[8];
  int rgb[3];
  for(int k = 0; k < 3; ++k) rgb[k] = int(std::lround(255 * (1 - a) + end[k] * a));
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", rgb[0], rgb[1], rgb[2]);
  return buf;
}

// The flattened disk as SVG: one triangle per face, filled by the mean conformal factor u of
// its vertices (blue u < 0, white 0, red u > 0, scaled by max |u|); y points up.
std::string layout_svg(const Mesh& mesh, const std::vector<K::Point_2>& uv, const std::vector<double>& u)
{
  double xmin = std::numeric_limits<double>::infinity(), ymin = xmin, xmax = -xmin, ymax = -xmin, umax = 0;
  for(vertex_descriptor v : vertices(mesh)) {
    const K::Point_2& p = uv[index(v)];
    xmin = (std::min)(xmin, p.x()); xmax = (std::max)(xmax, p.x());
    ymin = (std::min)(ymin, p.y()); ymax = (std::max)(ymax, p.y());
    umax = (std::max)(umax, std::abs(u[index(v)]));
  }
  const double width = 800, margin = 10;
  const double span = (std::max)(xmax - xmin, ymax - ymin);
  const double scale = span > 0 ? (width - 2 * margin) / span : 1;
  const double height = (ymax - ymin) * scale + 2 * margin;
  std::ostringstream os;
  os.imbue(std::locale::classic());
  os << std::fixed << std::setprecision(2);
  os << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
     << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << int(width) << "\" height=\"" << int(std::ceil(height))
     << "\" viewBox=\"0 0 " << width << ' ' << std::ceil(height) << "\">\n"
     << "<title>cone metric layout, faces coloured by the conformal factor u (max |u| = "
     << std::setprecision(4) << umax << std::setprecision(2) << ")</title>\n"
     << "<g stroke=\"#404040\" stroke-width=\"0.1\" stroke-linejoin=\"round\">\n";
  for(face_descriptor f : faces(mesh)) {
    os << "<polygon points=\"";
    double us = 0;
    int k = 0;
    for(vertex_descriptor v : vertices_around_face(halfedge(f, mesh), mesh)) {
      const K::Point_2& p = uv[index(v)];
      os << (k++ ? " " : "") << margin + (p.x() - xmin) * scale << ',' << margin + (ymax - p.y()) * scale;
      us += u[index(v)];
    }
    os << "\" fill=\"" << diverging_color(umax > 0 ? us / 3 / umax : 0) << "\"/>\n";
  }
  os << "</g>\n</svg>\n";
  return os.str();
}

Json run_cone_metric(const Args& args)
{
  const std::string& file = args.positional[0];
  const long iterations = args.integer("iterations", 200);
  if(iterations < 0 || iterations > 1000000)
    throw Usage_error("option --iterations expects an integer in [0, 1000000], got '" + args.value("iterations") + "'");
  const double tolerance = args.real("tolerance", 1e-10);
  if(!(tolerance > 0))
    throw Usage_error("option --tolerance expects a positive number, got '" + args.value("tolerance") + "'");
  std::vector<std::pair<std::size_t, double>> cones, indices, kappa;
  if(args.has("cones")) cones = parse_vertex_values("cones", args.value("cones"), parse_angle, "radians: decimal, p/q, pi/2, -4pi, 3*pi/4, ...");
  if(args.has("cone-indices")) indices = parse_vertex_values("cone-indices", args.value("cone-indices"), parse_number, "an index k, K = 2 pi k: integer, p/q or decimal");
  if(args.has("boundary-curvature")) kappa = parse_vertex_values("boundary-curvature", args.value("boundary-curvature"), parse_angle, "radians: decimal, p/q, pi/2, -pi/4, ...");
  const bool want_uv = args.has("uv-out") || args.has("svg");
  const bool progress = args.has("progress") || isatty(2);

  Mesh mesh;
  load_mesh(file, mesh);
  const std::size_t nv = num_vertices(mesh);
  if(want_uv) {
    const SMDF::Mesh_topology<Mesh> topo = on_file(file, [&] { return SMDF::mesh_topology(mesh); });
    if(topo.components.size() != 1 || topo.components[0].boundary_loops != 1 || topo.components[0].genus != 0 ||
       topo.isolated_vertices != 0)
      throw Usage_error(std::string("option --") + (args.has("uv-out") ? "uv-out" : "svg") +
                        " needs a topological disk (one component, one boundary loop, genus 0, no isolated "
                        "vertex); " + file + " has " + std::to_string(topo.components.size()) + " component(s), " +
                        std::to_string(topo.boundary_loops.size()) + " boundary loop(s)");
  }

  // targets: 0 everywhere, then the options
  Mesh::Property_map<vertex_descriptor, double> targets =
    mesh.add_property_map<vertex_descriptor, double>("v:smdf_target_curvature", 0.).first;
  std::vector<const char*> given_by(nv, nullptr);
  auto set_target = [&](const char* option, std::size_t v, double k, bool boundary_option) {
    if(v >= nv)
      throw Error(std::string("--") + option + ": vertex " + std::to_string(v) + " does not exist (the mesh has " +
                  std::to_string(nv) + " vertices)");
    if(given_by[v])
      throw Error(std::string("--") + option + ": vertex " + std::to_string(v) + " is given twice" +
                  (given_by[v] == option ? std::string() : std::string(" (also by --") + given_by[v] + ")"));
    const vertex_descriptor vd = vertex_descriptor(Mesh::size_type(v));
    if(halfedge(vd, mesh) == boost::graph_traits<Mesh>::null_halfedge())
      throw Error(std::string("--") + option + ": vertex " + std::to_string(v) + " is isolated");
    const bool boundary = bool(CGAL::is_border(vd, mesh));
    if(boundary && !boundary_option)
      throw Error(std::string("--") + option + ": vertex " + std::to_string(v) +
                  " is on the boundary: give its geodesic curvature with --boundary-curvature");
    if(!boundary && boundary_option)
      throw Error(std::string("--") + option + ": vertex " + std::to_string(v) +
                  " is an interior vertex: give its curvature with --cones or --cone-indices");
    given_by[v] = option;
    put(targets, vd, k);
  };
  for(const auto& c : cones) set_target("cones", c.first, c.second, false);
  for(const auto& c : indices) set_target("cone-indices", c.first, 2 * CGAL_PI * c.second, false);
  for(const auto& c : kappa) set_target("boundary-curvature", c.first, c.second, true);

  Mesh::Property_map<edge_descriptor, double> lengths =
    mesh.add_property_map<edge_descriptor, double>("e:smdf_cone_length", 0.).first;
  Mesh::Property_map<vertex_descriptor, double> ufac =
    mesh.add_property_map<vertex_descriptor, double>("v:smdf_conformal_factor", 0.).first;
  auto visitor = [progress](int it, double err) {
    if(!progress) return;
    std::ostringstream os;
    os.imbue(std::locale::classic());
    os << "smdf: cone-metric: iteration " << it << ", max curvature error " << std::setprecision(3) << err << '\n';
    std::cerr << os.str() << std::flush;
  };
  SMDF::Cone_metric_status st;
  try {
    st = SMDF::compute_cone_metric(mesh, targets, lengths,
                                   SMDF::parameters::conformal_factor_map(ufac)
                                       .number_of_iterations(int(iterations))
                                       .curvature_tolerance(tolerance)
                                       .intrinsic_edge_flips(!args.has("no-flips"))
                                       .visitor(visitor));
  } catch(const SMDF::Input_error& e) {
    if(e.kind() != SMDF::Input_error::INCONSISTENT_INDICES) throw file_error(file, e.what(), SMDF::Input_error::kind_name(e.kind()));
    // Gauss-Bonnet: also state the totals as cone indices (K / 2 pi) against chi, per component
    std::vector<std::size_t> parent(nv);
    for(std::size_t v = 0; v < nv; ++v) parent[v] = v;
    std::function<std::size_t(std::size_t)> root = [&](std::size_t v) {
      while(parent[v] != v) v = parent[v] = parent[parent[v]];
      return v;
    };
    for(edge_descriptor ed : edges(mesh)) {
      const halfedge_descriptor h = halfedge(ed, mesh);
      parent[root(index(source(h, mesh)))] = root(index(target(h, mesh)));
    }
    std::map<std::size_t, std::pair<double, long>> comp;   // root -> (sum of targets, chi)
    for(vertex_descriptor v : vertices(mesh))
      if(halfedge(v, mesh) != boost::graph_traits<Mesh>::null_halfedge()) {
        auto& c = comp[root(index(v))];
        c.first += get(targets, v);
        c.second += 1;
      }
    for(edge_descriptor ed : edges(mesh)) comp[root(index(source(halfedge(ed, mesh), mesh)))].second -= 1;
    for(face_descriptor f : faces(mesh)) comp[root(index(target(halfedge(f, mesh), mesh)))].second += 1;
    std::string detail;
    for(const auto& c : comp)
      if(std::abs(c.second.first - 2 * CGAL_PI * double(c.second.second)) >
         1e-8 * (std::max)(1., 2 * CGAL_PI * std::abs(double(c.second.second)))) {
        detail = "; as cone indices (K / 2pi): the targets sum to " + format_real(c.second.first / (2 * CGAL_PI)) +
                 " but the Euler characteristic is " + std::to_string(c.second.second);
        break;
      }
    throw file_error(file, e.what() + detail, SMDF::Input_error::kind_name(e.kind()));
  }

  // With flips the metric lives on the intrinsic triangulation: its edges (not the input's)
  // go to --lengths-out, its faces to --triangulation-out.
  const bool changed = st.triangulation_changed;
  const SMDF::Intrinsic_triangulation& itri = st.intrinsic_triangulation;
  if(args.has("lengths-out")) {
    std::ostringstream os;
    os.imbue(std::locale::classic());
    os.precision(17);
    if(changed) {
      for(std::size_t e = 0; e < itri.number_of_edges(); ++e)
        os << itri.source(int(2 * e)) << ' ' << itri.target(int(2 * e)) << ' ' << itri.length(int(e)) << '\n';
    } else {
      for(edge_descriptor e : edges(mesh)) {
        if(std::isnan(get(lengths, e))) continue;   // inside a punched hole
        const halfedge_descriptor h = halfedge(e, mesh);
        os << index(source(h, mesh)) << ' ' << index(target(h, mesh)) << ' ' << get(lengths, e) << '\n';
      }
    }
    write_lines_file(args.value("lengths-out"), os.str());
  }
  if(args.has("triangulation-out")) {
    std::ostringstream os;
    os.imbue(std::locale::classic());
    os.precision(17);
    std::vector<char> punched(nv, 0);
    for(std::size_t v : st.punched_vertices) punched[v] = 1;
    std::vector<face_descriptor> kept;   // without the faces of punched holes
    for(face_descriptor f : faces(mesh)) {
      bool in_hole = false;
      for(vertex_descriptor v : vertices_around_face(halfedge(f, mesh), mesh)) in_hole = in_hole || punched[index(v)];
      if(!in_hole) kept.push_back(f);
    }
    os << "OFF\n" << nv << ' ' << (changed ? itri.number_of_faces() : kept.size()) << " 0\n";
    for(vertex_descriptor v : vertices(mesh)) {
      const K::Point_3& p = mesh.point(v);
      os << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
    }
    if(changed) {
      for(std::size_t f = 0; f < itri.number_of_faces(); ++f) {
        const std::array<int, 3> t = itri.face_vertices(int(f));
        os << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
      }
    } else {
      for(face_descriptor f : kept) {
        os << '3';
        for(vertex_descriptor v : vertices_around_face(halfedge(f, mesh), mesh)) os << ' ' << index(v);
        os << '\n';
      }
    }
    write_lines_file(args.value("triangulation-out"), os.str());
  }

  std::size_t ncones = 0, nkappa = 0;
  for(vertex_descriptor v : vertices(mesh))
    if(get(targets, v) != 0) ++(CGAL::is_border(v, mesh) ? nkappa : ncones);
  Json out = Json::object();
  out["status"] = st.converged ? "converged" : "not_converged";
  out["converged"] = st.converged;
  out["iterations"] = st.iterations;
  out["max_curvature_error"] = st.max_curvature_error;
  out["rounding_level"] = st.rounding_level;
  out["time_s"] = st.seconds;
  out["method"] = args.has("no-flips")
                    ? "discrete conformal vertex scaling (Newton, CHOLMOD) on the input triangulation"
                    : "discrete conformal vertex scaling (Newton, CHOLMOD), continued on an intrinsic "
                      "Delaunay triangulation (edge flips) if the input triangulation cannot carry the metric";
  out["message"] = st.message;
  out["cones"] = ncones;
  out["boundary_corners"] = nkappa;
  Json holes = Json::array();
  for(std::size_t v : st.punched_vertices) holes.push_back(v);
  out["punched_vertices"] = holes;
  out["triangulation_changed"] = changed;
  out["edge_flips"] = st.edge_flips;
  if(changed) {
    Json t = Json::object();
    t["faces"] = itri.number_of_faces();
    t["edges"] = itri.number_of_edges();
    t["new_edges"] = itri.number_of_new_edges();
    out["intrinsic_triangulation"] = std::move(t);
  }

  if(!st.converged) {
    std::ostringstream os;
    os.imbue(std::locale::classic());
    os << file << ": cone metric not converged (tolerance " << std::setprecision(3) << tolerance
       << ", " << st.iterations << " iterations): " << st.message
       << (want_uv ? " (--uv-out/--svg not written)" : "");
    throw Failed_result{out, os.str(), 3};
  }

  if(want_uv) {
    // with flips, lay out (and draw) a copy of the intrinsic triangulation: same vertices
    Mesh copy;
    Mesh::Property_map<edge_descriptor, double> copy_lengths =
      copy.add_property_map<edge_descriptor, double>("e:smdf_intrinsic_length", 0.).first;
    if(changed) SMDF::copy_intrinsic_triangulation(itri, mesh, copy, copy_lengths);
    Mesh& flat = changed ? copy : mesh;   // vertex i of the copy is vertex i of the input
    std::vector<K::Point_2> uv(nv, K::Point_2(0, 0));
    Mesh::Property_map<vertex_descriptor, K::Point_2> uvmap =
      flat.add_property_map<vertex_descriptor, K::Point_2>("v:smdf_uv", K::Point_2(0, 0)).first;
    const bool injective = on_file(file, [&] {
      const auto np = SMDF::parameters::curvature_tolerance((std::max)(1e-8, 10 * tolerance));
      return changed ? SMDF::lay_out_disk(copy, copy_lengths, uvmap, np) : SMDF::lay_out_disk(mesh, lengths, uvmap, np);
    });
    for(vertex_descriptor v : vertices(flat)) uv[index(v)] = get(uvmap, v);
    out["uv_positively_oriented"] = injective;
    if(args.has("uv-out")) {
      std::ostringstream os;
      os.imbue(std::locale::classic());
      os.precision(17);
      for(vertex_descriptor v : vertices(mesh)) os << uv[index(v)].x() << ' ' << uv[index(v)].y() << '\n';
      write_lines_file(args.value("uv-out"), os.str());
    }
    if(args.has("svg")) {
      std::vector<double> u(nv, 0.);
      for(vertex_descriptor v : vertices(mesh)) u[index(v)] = get(ufac, v);
      write_lines_file(args.value("svg"), layout_svg(flat, uv, u));
    }
  }
  return out;
}

// ---- Dispatch table -----------------------------------------------------------------------

const std::vector<Command>& commands()
{
  static const std::vector<Command> table = {
    {"info", {"MESH"}, {},
     "topology of a mesh: counts, components, boundary loops, genus",
     "Prints {file, vertices, edges, faces, components, boundary_loops, euler_characteristic,\n"
     "genus (one per component), closed, betti_1, isolated_vertices, reoriented_faces,\n"
     "degenerate_faces}. euler_characteristic and betti_1 are summed over the components\n"
     "(isolated vertices excluded); reoriented_faces counts faces flipped to make the\n"
     "orientation consistent; degenerate_faces counts faces of zero area (relative 1e-14) in\n"
     "the Euclidean metric, which info accepts but the geometric commands reject.\n",
     run_info},
    {"generators", {"MESH"}, {},
     "tree-cotree homology generators (handle and boundary loops)",
     "Prints {file, count, betti_1, generators: [{kind: \"handle\"|\"boundary\", component,\n"
     "dual_edges, primal_loop}]}. dual_edges lists, in cycle order, the edges the dual cycle\n"
     "crosses, each as the vertex pair [i, j] of the halfedge i->j it crosses from its right\n"
     "face into its left face. primal_loop lists the vertices of a closed primal edge loop\n"
     "(the first vertex is not repeated at the end).\n",
     run_generators},
    {"holonomy", {"MESH"},
     {{"lengths", "FILE", "intrinsic metric: one line 'i j length' per edge"}},
     "Gauss-Bonnet check and Levi-Civita / generalized holonomy of every generator",
     "Prints {file, metric, euler_characteristic, total_angle_defect, two_pi_chi,\n"
     "gauss_bonnet_error, generators: [{kind, component, dual_cycle_length,\n"
     "levi_civita_holonomy, generalized_holonomy: {rotation, translation: [x, y]}}], timings}.\n"
     "Angles are in radians, in (-pi, pi]; timings are in seconds. The metric is Euclidean\n"
     "unless --lengths gives one length per edge (vertex indices in either order; blank lines\n"
     "and lines starting with '#' are ignored). Faces of zero area are an error.\n",
     run_holonomy},
    {"connection", {"MESH"},
     {{"singularities", "LIST", "prescribed indices 'v:k,v:k,...' (k integer, p/q or decimal)"},
      {"singularities-file", "FILE", "prescribed indices, one line 'v k' per vertex"},
      {"N", "n", "symmetry order (1 vectors, 2 lines, 4 crosses; default 1)"},
      {"weights", "W", "cotan (default) or unit"},
      {"generator-turning", "LIST", "turning numbers 'g:t,...' of the generators (default 0)"},
      {"constraints", "FILE", "directional constraints: lines 'face angle' or 'face x y z'"},
      {"field-out", "FILE", "write one unit direction 'x y z' per face"},
      {"connection-out", "FILE", "write 'i j angle' per interior edge (adjustment angle)"},
      {"edit-benchmark", "K", "time K random singularity moves (re-solve + field)"},
      {"svg", "FILE", "write an SVG picture of the field and its found singularities"},
      {"view", "A,E[,UP]", "view of --svg: azimuth,elevation in degrees, up axis x|y|z (default 30,20,z)"},
      {"width", "PX", "width of the --svg picture in pixels (default 800)"}},
     "trivial connection with prescribed singularities and its N-RoSy field",
     "Computes the trivial connection closest to Levi-Civita with the prescribed singularity\n"
     "indices (multiples of 1/N at interior vertices; on a closed component they must sum to\n"
     "its Euler characteristic) and generator turning numbers, and the face field it transports.\n"
     "Prints {N, weights, prescribed: [{vertex, index}], found: [{vertex, index}] (read back\n"
     "from the computed field), generator_turning_numbers (read back), energy, residual,\n"
     "max_holonomy_error, success, timings: {setup_s, solve_s, field_s, edit_median_s}}.\n"
     "Constraint angles are in radians in the face frame, counterclockwise from halfedge(f);\n"
     "3D directions are projected on the face plane. Files may hold blank lines and '#'\n"
     "comments. --connection-out writes, per interior edge, the vertices i j of halfedge(e) and\n"
     "the adjustment angle for crossing it from its right face into its left face.\n"
     "--edit-benchmark K moves a random singularity K times (pseudo-random, fixed seed) and\n"
     "reports the median time of solve + field (null without singularities).\n"
     "--svg draws the mesh (orthographic view, back faces culled), the field (one\n"
     "glyph per visible face, thinned out on large meshes) and the found singularities (red\n"
     "positive, blue negative).\n",
     run_connection},
    {"singularities", {"MESH"},
     {{"field", "FILE", "one direction 'x y z' per face, in file order (required)"},
      {"N", "n", "symmetry order (default 1)"}},
     "singularities and generator turning numbers of a face field",
     "Reads one 3D direction per face (as written by 'connection --field-out'), projects it on\n"
     "the face plane and prints {N, singularities: [{vertex, index}], generator_turning_numbers,\n"
     "max_rounding_error}. Indices are multiples of 1/N; generators are those of 'generators'.\n",
     run_singularities},
    {"cone-metric", {"MESH"},
     {{"cones", "LIST", "target curvatures 'v:K,...' of interior vertices, K in radians"},
      {"cone-indices", "LIST", "the same as indices 'v:k,...', K = 2 pi k (k integer, p/q, decimal)"},
      {"boundary-curvature", "LIST", "target geodesic curvatures 'v:kappa,...' of boundary vertices"},
      {"lengths-out", "FILE", "write the metric: one line 'i j length' per edge (intrinsic edges after flips)"},
      {"triangulation-out", "FILE", "write the triangulation carrying the metric as OFF (input faces if no flips)"},
      {"uv-out", "FILE", "disks only: write the flat layout, one line 'u v' per vertex"},
      {"svg", "FILE", "disks only: draw the flat layout, faces coloured by the conformal factor"},
      {"iterations", "n", "maximum number of Newton iterations (default 200)"},
      {"tolerance", "t", "max curvature error accepted, radians (default 1e-10)"},
      {"no-flips", "", "keep the input triangulation (no intrinsic edge flips)"},
      {"progress", "", "print the error of every iteration to stderr (default: only on a terminal)"}},
     "flat cone metric with prescribed cone angles (discrete conformal map)",
     "Computes edge lengths, conformally equivalent to the Euclidean ones (l_ij = l0_ij\n"
     "exp((u_i + u_j) / 2)), whose discrete curvature is the target at every vertex: the angle\n"
     "defect 2 pi - sum(angles) at interior vertices (0 unless given by --cones/--cone-indices;\n"
     "a cone K >= 2 pi, index >= 1, is punched as a hole whose d ring vertices get the geodesic\n"
     "curvature (K - 2 pi) / d; the output files then describe the holed surface) and the\n"
     "geodesic curvature pi - sum(angles) at boundary vertices (0 unless given by\n"
     "--boundary-curvature; must be < pi). On every component the targets must sum to\n"
     "2 pi chi (Gauss-Bonnet), e.g. eight cones of pi/2 on a sphere, or four boundary corners of\n"
     "pi/2 on a disk (a rectangle).\n"
     "Newton's method runs on the input triangulation first; if that triangulation cannot\n"
     "carry the target metric (triangles degenerate), the flow continues on an intrinsic\n"
     "Delaunay triangulation of the same vertices (edge flips; same numbers of edges and faces),\n"
     "unless --no-flips is given.\n"
     "Angles K, kappa: a decimal or p/q in radians, or a multiple of pi written [c][*]pi[/d]\n"
     "(pi, -pi, pi/2, 3*pi/4, -4pi, 0.5pi). Each vertex may be given once, by one option.\n"
     "Prints {status: \"converged\"|\"not_converged\", converged, iterations,\n"
     "max_curvature_error (radians), rounding_level (largest rounding level of an angle sum:\n"
     "the error allowed beyond the tolerance at a vertex next to needle triangles, about 1e-14\n"
     "elsewhere; see curvature_tolerance in the manual), time_s, method, message (empty when\n"
     "converged), cones\n"
     "(interior vertices with K != 0), boundary_corners (boundary vertices with kappa != 0),\n"
     "triangulation_changed (the metric lives on an intrinsic triangulation that differs from\n"
     "the input's), edge_flips (intrinsic flips performed), intrinsic_triangulation: {faces,\n"
     "edges, new_edges (edges that are not input edges)} (only when triangulation_changed),\n"
     "punched_vertices (cones of index >= 1 punched as holes), uv_positively_oriented (with\n"
     "--uv-out/--svg: every laid-out triangle is counterclockwise)}.\n"
     "--lengths-out writes 'i j length' per edge (i j 0-based vertex indices in file order, 17\n"
     "digits). Without flips these are the input's edges (i j the vertices of halfedge(e)),\n"
     "readable by 'holonomy --lengths'. When triangulation_changed they are the intrinsic\n"
     "triangulation's edges in its order: the edge list differs from the input's (some input\n"
     "edges are gone, new ones join other vertex pairs, two edges may join the same pair) and\n"
     "the faces are those of --triangulation-out. --triangulation-out writes an OFF file with\n"
     "the input vertex positions (for display only: the geometry is in the lengths) and the\n"
     "faces of the triangulation carrying the metric (the input faces if it did not change).\n"
     "An intrinsic triangulation may have two edges joining the same vertices or a face with a\n"
     "repeated vertex; smdf cannot read such an OFF back (its reader rejects non-manifold\n"
     "soups). --uv-out and --svg need a topological disk (usage error otherwise); the layout\n"
     "unfolds the faces (of the intrinsic triangulation when triangulation_changed, also the\n"
     "faces drawn by --svg) breadth-first from face 0 and may overlap itself globally. The SVG\n"
     "colours faces by the mean conformal factor u of their vertices (blue u < 0, white 0,\n"
     "red u > 0, scaled by max |u|).\n"
     "Not converged (tolerance not reached in --iterations, or, with --no-flips, the target\n"
     "metric does not exist on this triangulation): the JSON object is still printed on stdout,\n"
     "one error line goes to stderr and the exit code is 3; --lengths-out and\n"
     "--triangulation-out then hold the last valid iterate and --uv-out/--svg are not written.\n",
     run_cone_metric},
  };
  return table;
}

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
  }
  std::cout << json << '\n' << std::flush;
  if(!std::cout) throw Error("cannot write to standard output");
  if(code != EXIT_SUCCESS) print_error(failure);
  return code;
}

} // namespace

int main(int argc, char** argv)
{
#ifdef __linux__
  // Large meshes: a third of the solver setup is first-touch page faults of the factorisation
  // (1M faces, 4 KB pages on this VM); glibc maps large blocks with transparent huge pages only
  // if told at start-up, so restart once with that tunable unless the user set GLIBC_TUNABLES
  // (trivial connection setup at 1M faces: 4.5 s -> 3.3 s). SMDF_NO_HUGEPAGES=1 disables it.
  if(!std::getenv("GLIBC_TUNABLES") && !std::getenv("SMDF_NO_HUGEPAGES")) {
    setenv("GLIBC_TUNABLES", "glibc.malloc.hugetlb=1", 1);
    execv("/proc/self/exe", argv);
    unsetenv("GLIBC_TUNABLES");   // exec failed: go on without
  }
#endif
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
