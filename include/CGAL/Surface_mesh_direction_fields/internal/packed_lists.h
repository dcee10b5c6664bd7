// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_PACKED_LISTS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_PACKED_LISTS_H

// Many short lists of indices (a polygon's corners, a vertex's faces or neighbours) in one array
// with offsets: one allocation instead of one per list, which at 433k vertices cost more than
// the work done with them.

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

template <typename T>
class Packed_lists
{
public:
  struct Range
  {
    const T* first;
    const T* last;
    const T* begin() const { return first; }
    const T* end() const { return last; }
    std::size_t size() const { return std::size_t(last - first); }
    const T& operator[](std::size_t k) const { return first[k]; }
  };

  Packed_lists() : start_(1, 0) {}

  std::size_t size() const { return start_.size() - 1; }
  Range operator[](std::size_t i) const { return Range{items_.data() + start_[i], items_.data() + start_[i + 1]}; }

  // Appends an item to the last list; close_list() ends it and begins the next.
  void push_back(const T& x) { items_.push_back(x); }
  void close_list() { start_.push_back(items_.size()); }
  void reserve(std::size_t lists, std::size_t items)
  {
    start_.reserve(lists + 1);
    items_.reserve(items);
  }

  // For every item value in [0, n), the lists that contain it, in increasing order.
  Packed_lists<std::size_t> transposed(std::size_t n) const
  {
    Packed_lists<std::size_t> t;
    t.start_.assign(n + 1, 0);
    for(const T& x : items_) ++t.start_[std::size_t(x) + 1];
    for(std::size_t v = 0; v < n; ++v) t.start_[v + 1] += t.start_[v];
    t.items_.resize(items_.size());
    std::vector<std::size_t> fill(t.start_.begin(), t.start_.end() - 1);
    for(std::size_t i = 0; i < size(); ++i)
      for(const T& x : (*this)[i]) t.items_[fill[std::size_t(x)]++] = i;
    return t;
  }

private:
  template <typename> friend class Packed_lists;
  std::vector<std::size_t> start_;
  std::vector<T> items_;
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_PACKED_LISTS_H
