// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_HUGE_PAGES_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_HUGE_PAGES_H

// Transparent huge pages for large buffers. On a mesh of a million faces about a third of the
// trivial-connection setup was first-touch page faults (4 KiB each); a 2 MiB page costs one.
// The kernel backs a range with huge pages when the system's THP mode is "always", or "madvise"
// (Debian's default) and the range was marked with madvise(MADV_HUGEPAGE) before first use.
//
// The library marks the large arrays it allocates itself (internal::Huge_page_allocator); that
// touches only its own memory. CHOLMOD allocates through SuiteSparse's process-wide hooks, which
// a library must not replace behind its user's back: enable_cholmod_huge_pages() is the opt-in.

#include <SuiteSparse_config.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// Blocks from this size on are marked (smaller ones hold less than one aligned huge page).
constexpr std::size_t huge_page_min_bytes = std::size_t(4) << 20;

// Marks the 2 MiB-aligned part of [p, p + bytes) for huge pages. Harmless where unsupported.
inline void advise_huge_pages(void* p, std::size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  if(!p || bytes < huge_page_min_bytes) return;
  const std::uintptr_t page = std::uintptr_t(2) << 20;
  const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(p) + page - 1) & ~(page - 1);
  const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(p) + bytes) & ~(page - 1);
  if(end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
  (void)p;
  (void)bytes;
#endif
}

inline void* huge_page_malloc(std::size_t bytes)
{
  void* p = std::malloc(bytes);
  advise_huge_pages(p, bytes);
  return p;
}

inline void* huge_page_calloc(std::size_t count, std::size_t size)
{
  void* p = std::calloc(count, size);   // fresh large blocks are untouched zero pages
  if(p && size != 0 && count <= (std::numeric_limits<std::size_t>::max)() / size) advise_huge_pages(p, count * size);
  return p;
}

inline void* huge_page_realloc(void* old, std::size_t bytes)
{
  void* p = std::realloc(old, bytes);
  advise_huge_pages(p, bytes);
  return p;
}

inline void huge_page_free(void* p) { std::free(p); }

// std::allocator with large blocks marked for huge pages, for the library's big arrays.
template <typename T>
struct Huge_page_allocator
{
  typedef T value_type;
  Huge_page_allocator() = default;
  template <typename U>
  Huge_page_allocator(const Huge_page_allocator<U>&) noexcept {}
  T* allocate(std::size_t n)
  {
    if(n > (std::numeric_limits<std::size_t>::max)() / sizeof(T)) throw std::bad_array_new_length();
    void* p = huge_page_malloc(n * sizeof(T));
    if(!p && n != 0) throw std::bad_alloc();
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t) noexcept { huge_page_free(p); }
  template <typename U>
  bool operator==(const Huge_page_allocator<U>&) const noexcept { return true; }
  template <typename U>
  bool operator!=(const Huge_page_allocator<U>&) const noexcept { return false; }
};

} // namespace internal

/// \ingroup PkgSurfaceMeshDirectionFieldsSolvers
/// Makes CHOLMOD's large blocks (its factors and workspaces) eligible for transparent huge pages,
/// by replacing SuiteSparse's allocation hooks with `malloc`/`calloc`/`realloc` followed by
/// `madvise(MADV_HUGEPAGE)` for blocks of 4 MiB and more, and `free`. Measured: trivial
/// connection setup at 1M faces about 10-25% faster on a Debian VM in THP "madvise" mode (see
/// benchmark/README.md). The `smdf` tool calls it at start-up.
///
/// \warning This is a process-wide setting of SuiteSparse, which other code of the program may
/// use too, so the library never calls it by itself: call it once, at start-up, before any
/// thread uses CHOLMOD. Blocks allocated before the call may be freed after it.
///
/// \return `false` where `madvise()` is not available (nothing is changed then)
inline bool enable_cholmod_huge_pages()
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
#if SUITESPARSE_MAIN_VERSION >= 7
  SuiteSparse_config_malloc_func_set(&internal::huge_page_malloc);
  SuiteSparse_config_calloc_func_set(&internal::huge_page_calloc);
  SuiteSparse_config_realloc_func_set(&internal::huge_page_realloc);
  SuiteSparse_config_free_func_set(&internal::huge_page_free);
#else
  SuiteSparse_config.malloc_func = &internal::huge_page_malloc;
  SuiteSparse_config.calloc_func = &internal::huge_page_calloc;
  SuiteSparse_config.realloc_func = &internal::huge_page_realloc;
  SuiteSparse_config.free_func = &internal::huge_page_free;
#endif
  return true;
#else
  return false;
#endif
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_HUGE_PAGES_H
