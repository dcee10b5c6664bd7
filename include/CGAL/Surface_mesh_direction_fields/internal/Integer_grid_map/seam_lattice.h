// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INTEGER_GRID_MAP_SEAM_LATTICE_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INTEGER_GRID_MAP_SEAM_LATTICE_H

// The integer solutions of the seams' conditions of integer_grid_map() (integer_grid_map.h): the
// closings around the vertices, the boundary's lines and the gauge are linear conditions C y = 0
// with integer coefficients on the small unknowns y (translations, lines, singularity and corner
// positions, real and imaginary parts), and rounding adds y_k = v one value at a time. Which
// integers v keep the system solvable in integers is exact here: a cone of -pi puts a coefficient
// 2 into its closing, and rounding without this had to guess parities (and could reach a value
// with no admissible integer at all).
//
// Every integer solution is y = U w + c for integer w, U integer: starting from U = identity,
// c = 0, each condition is written in the current w. A coefficient +-1 expresses that variable by
// the others, which are substituted for it; otherwise two of its variables are replaced by two
// integer combinations of them (extended Euclid, determinant 1) until one coefficient is their gcd
// g and the others 0, and g w = r fixes that variable (no integer solution if g does not divide
// r). y_k can take the value v iff the gcd of its coefficients in w divides v - c_k. B = the
// columns of U of the variables left, T = the matching rows of U^-1 (T B = I): y = B t + c.

#include <CGAL/Surface_mesh_direction_fields/internal/Integer_grid_map/seam_layout.h>

#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

class Seam_lattice
{
public:
  typedef long long Int;
  typedef std::map<int, Int> Sparse;   // index -> nonzero coefficient

  // variables of index `kept_from` and up are eliminated only where no other can be
  explicit Seam_lattice(int n, int kept_from)
    : kept_from_(kept_from), expr_(std::size_t(n)), offset_(std::size_t(n), 0), uses_(std::size_t(n)), coordinate_(std::size_t(n)),
      alive_(std::size_t(n), 1)
  {
    for(int k = 0; k < n; ++k) {
      expr_[std::size_t(k)][k] = 1;
      uses_[std::size_t(k)].insert(k);
      coordinate_[std::size_t(k)][k] = 1;
    }
  }

  // sum_k c_k y_k = value over the integer solutions so far. The variable eliminated by a
  // coefficient +-1 is one below `kept_from` if there is one, among those the one in the fewest y
  // (the least fill). False with `msg` if there is then no integer solution, or if a coefficient
  // grows beyond 2^30 (no shared mesh came near).
  bool add(const Sparse& condition, std::string& msg, Int value = 0)
  {
    Sparse row;   // the condition in the current variables w: row . w = r
    Int r = value;
    for(const auto& c : condition) {
      for(const auto& e : expr_[std::size_t(c.first)])
        if(!accumulate(row, e.first, c.second, e.second, msg)) return false;
      r -= c.second * offset_[std::size_t(c.first)];
      if(!fits(r, msg)) return false;
    }
    for(;;) {
      if(row.empty()) {
        if(r != 0) { msg = "the seams' conditions have no integer solution"; return false; }
        return true;
      }
      int pivot = -1, smallest = -1;
      auto preferred = [&](int a, int b) {   // a is a better pivot than b
        if((a < kept_from_) != (b < kept_from_)) return a < kept_from_;
        return uses_[std::size_t(a)].size() < uses_[std::size_t(b)].size();
      };
      for(const auto& e : row) {
        if(std::llabs(e.second) == 1 && (pivot < 0 || preferred(e.first, pivot))) pivot = e.first;
        if(smallest < 0 || std::llabs(e.second) < std::llabs(row[smallest])) smallest = e.first;
      }
      if(pivot < 0 && row.size() == 1) pivot = smallest;   // g w = 0: w = 0
      if(pivot >= 0) {
        const Int cp = row[pivot];
        Sparse by;   // w_pivot = sum_j by_j w_j + r / cp
        if(std::llabs(cp) == 1)
          for(const auto& e : row) if(e.first != pivot) by[e.first] = -e.second * cp;
        else if(r % cp != 0) { msg = "the seams' conditions have no integer solution"; return false; }
        return substitute(pivot, by, r / cp, msg);
      }
      // no unit coefficient: combine the smallest with another so that one of them carries gcd
      int other = -1;   // the next smallest: the gcd comes in few steps
      for(const auto& e : row)
        if(e.first != smallest && (other < 0 || std::llabs(e.second) < std::llabs(row[other]))) other = e.first;
      const Int ca = row[smallest], cb = row[other];
      Int x, y;
      const Int g = extended_gcd(ca, cb, x, y);   // x ca + y cb = g > 0
      // (w_a, w_b) = [[x, -cb/g], [y, ca/g]] (w_a', w_b'), determinant 1; w_a' gets g, w_b' 0
      if(!change_pair(smallest, other, x, -cb / g, y, ca / g, ca / g, cb / g, -y, x, msg)) return false;
      row[smallest] = g;
      row.erase(other);
    }
  }

  // whether y_k = v leaves an integer solution: the gcd of y_k's coefficients divides v - c_k
  bool admits(int k, Int v) const
  {
    Int g = 0;
    for(const auto& e : expr_[std::size_t(k)]) g = gcd(g, std::llabs(e.second));
    const Int d = v - offset_[std::size_t(k)];
    return g == 0 ? d == 0 : d % g == 0;
  }
  // y_k is fixed by the conditions so far (to offset(k))
  bool determined(int k) const { return expr_[std::size_t(k)].empty(); }
  Int offset(int k) const { return offset_[std::size_t(k)]; }

  // the free variables t, in increasing index
  std::vector<int> free_variables() const
  {
    std::vector<int> f;
    for(std::size_t w = 0; w < alive_.size(); ++w) if(alive_[w]) f.push_back(int(w));
    return f;
  }
  // y in terms of the free variable w: the column of B, {k: coefficient}
  Sparse column(int w) const
  {
    Sparse c;
    for(int k : uses_[std::size_t(w)]) c[k] = expr_[std::size_t(k)].at(w);
    return c;
  }
  // the free variable w in terms of y: the row of T
  const Sparse& coordinate(int w) const { return coordinate_[std::size_t(w)]; }

private:
  static constexpr Int limit = Int(1) << 30;

  static bool fits(Int v, std::string& msg)
  {
    if(std::llabs(v) < limit) return true;
    msg = "the seams' conditions need integer coefficients beyond 2^30";
    return false;
  }
  // s[i] += a * b, the entry erased when it becomes 0
  static bool accumulate(Sparse& s, int i, Int a, Int b, std::string& msg)
  {
    if(!fits(a, msg) || !fits(b, msg)) return false;
    const Int v = (s.count(i) ? s[i] : 0) + a * b;
    if(!fits(v, msg)) return false;
    if(v == 0) s.erase(i); else s[i] = v;
    return true;
  }
  static Int gcd(Int a, Int b) { while(b != 0) { const Int r = a % b; a = b; b = r; } return a; }
  static Int extended_gcd(Int a, Int b, Int& x, Int& y)
  {
    Int x0 = 1, y0 = 0, x1 = 0, y1 = 1;
    while(b != 0) {
      const Int q = a / b, r = a - q * b;
      a = b; b = r;
      const Int x2 = x0 - q * x1, y2 = y0 - q * y1;
      x0 = x1; y0 = y1; x1 = x2; y1 = y2;
    }
    if(a < 0) { a = -a; x0 = -x0; y0 = -y0; }
    x = x0; y = y0;
    return a;
  }
  // w_p = sum_j by_j w_j + constant in every y; w_p is then no longer a variable
  bool substitute(int p, const Sparse& by, Int constant, std::string& msg)
  {
    const std::set<int> users = uses_[std::size_t(p)];
    for(int k : users) {
      Sparse& e = expr_[std::size_t(k)];
      const Int c = e[p];
      e.erase(p);
      offset_[std::size_t(k)] += c * constant;
      if(!fits(offset_[std::size_t(k)], msg)) return false;
      for(const auto& b : by) {
        if(!accumulate(e, b.first, c, b.second, msg)) return false;
        if(e.count(b.first)) uses_[std::size_t(b.first)].insert(k); else uses_[std::size_t(b.first)].erase(k);
      }
    }
    uses_[std::size_t(p)].clear();
    coordinate_[std::size_t(p)].clear();
    alive_[std::size_t(p)] = 0;
    return true;
  }
  // (w_a, w_b) = [[u00, u01], [u10, u11]] (w_a', w_b') in every y, and the coordinates
  // (w_a', w_b') = [[v00, v01], [v10, v11]] (w_a, w_b) (the inverse matrix)
  bool change_pair(int a, int b, Int u00, Int u01, Int u10, Int u11, Int v00, Int v01, Int v10, Int v11, std::string& msg)
  {
    std::set<int> users = uses_[std::size_t(a)];
    users.insert(uses_[std::size_t(b)].begin(), uses_[std::size_t(b)].end());
    for(int k : users) {
      Sparse& e = expr_[std::size_t(k)];
      const Int ea = e.count(a) ? e[a] : 0, eb = e.count(b) ? e[b] : 0;
      e.erase(a); e.erase(b);
      if(!accumulate(e, a, ea, u00, msg) || !accumulate(e, a, eb, u10, msg) ||
         !accumulate(e, b, ea, u01, msg) || !accumulate(e, b, eb, u11, msg)) return false;
      for(int v : {a, b}) { if(e.count(v)) uses_[std::size_t(v)].insert(k); else uses_[std::size_t(v)].erase(k); }
    }
    const Sparse ra = coordinate_[std::size_t(a)], rb = coordinate_[std::size_t(b)];
    Sparse na, nb;
    for(const auto& e : ra) { if(!accumulate(na, e.first, v00, e.second, msg) || !accumulate(nb, e.first, v10, e.second, msg)) return false; }
    for(const auto& e : rb) { if(!accumulate(na, e.first, v01, e.second, msg) || !accumulate(nb, e.first, v11, e.second, msg)) return false; }
    coordinate_[std::size_t(a)] = std::move(na);
    coordinate_[std::size_t(b)] = std::move(nb);
    return true;
  }

  int kept_from_;
  std::vector<Sparse> expr_;          // per y_k: its expression in the variables w (U's row k)
  std::vector<Int> offset_;           // per y_k: its constant c_k
  std::vector<std::set<int>> uses_;   // per variable w: the y_k whose expression holds it
  std::vector<Sparse> coordinate_;    // per variable w: its expression in y (a row of U^-1)
  std::vector<char> alive_;           // w is still a variable (not expressed by the others)
};

// The seams' conditions of `layout` as integer rows over the real small unknowns (2 k and 2 k + 1:
// the real and imaginary parts of small unknown k), each = 0: the closings, the lines' values
// real, the boundary's line conditions, and the gauge (`first_point` at the origin if there is
// one, else the first line at 0). False if a coefficient is no integer (sums of powers of i are).
inline bool seam_condition_rows(const Corner_layout& layout, int narcs, int nlines, int first_point, std::vector<Seam_lattice::Sparse>& rows)
{
  typedef Seam_lattice::Sparse Row;
  bool integral = true;
  auto put = [&](Row& row, int k, double c) {
    const double r = std::round(c);
    if(std::abs(c - r) > 1e-9) integral = false;
    if(r == 0) return;
    const Seam_lattice::Int v = row[k] + Seam_lattice::Int(r);
    if(v == 0) row.erase(k); else row[k] = v;
  };
  auto add = [&](Row&& row) { if(!row.empty()) rows.push_back(std::move(row)); };
  for(const Corner_layout::Closing& c : layout.closings) {
    Row re, imr;
    for(const auto& p : c.t) {
      put(re, 2 * p.first, p.second.real()); put(re, 2 * p.first + 1, -p.second.imag());
      put(imr, 2 * p.first, p.second.imag()); put(imr, 2 * p.first + 1, p.second.real());
    }
    add(std::move(re));
    add(std::move(imr));
  }
  auto unit_row = [](int k) { Row e; e[k] = 1; return e; };
  for(int k = narcs; k < narcs + nlines; ++k) add(unit_row(2 * k + 1));   // the lines' values are real
  for(const Corner_layout::Line_condition& lc : layout.line_conditions) {   // Im(sum c_k S_k) - Re(line) = 0
    Row row;
    for(const auto& p : lc.t) { put(row, 2 * p.first, p.second.imag()); put(row, 2 * p.first + 1, p.second.real()); }
    put(row, 2 * lc.line, -1);
    add(std::move(row));   // inside a line: 0 = 0, none
  }
  if(first_point >= 0) {   // the first singularity or corner at the origin
    add(unit_row(2 * first_point));
    add(unit_row(2 * first_point + 1));
  } else if(nlines > 0)
    add(unit_row(2 * narcs));
  return integral;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_INTEGER_GRID_MAP_SEAM_LATTICE_H
