// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// Global operator new and delete of the smdf tool (and the benchmark drivers), replaced so that
// large blocks are marked for transparent huge pages before first use, as CHOLMOD's are with
// enable_cholmod_huge_pages(). A program owns its allocator; the library never does this.
// Measured at 1M faces (trivial-connection setup, benchmark/README.md): page faults 210k -> 9k
// with both. Not under sanitizers, which provide their own operator new.

#include "huge_page_new.h"

#include <CGAL/Surface_mesh_direction_fields/huge_pages.h>

#include <atomic>
#include <cstdlib>
#include <new>

namespace smdf_memory {

namespace {
std::atomic<bool> huge_pages{false};
}

void enable_huge_pages()
{
  CGAL::Surface_mesh_direction_fields::enable_cholmod_huge_pages();
  huge_pages.store(true, std::memory_order_relaxed);
}

} // namespace smdf_memory

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define SMDF_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
#define SMDF_SANITIZED 1
#endif
#endif

#ifndef SMDF_SANITIZED

namespace {

void* allocate(std::size_t n) noexcept
{
  if(n == 0) n = 1;
  if(smdf_memory::huge_pages.load(std::memory_order_relaxed))
    return CGAL::Surface_mesh_direction_fields::internal::huge_page_malloc(n);
  return std::malloc(n);
}

void* allocate_or_throw(std::size_t n)
{
  for(;;) {
    if(void* p = allocate(n)) return p;
    std::new_handler handler = std::get_new_handler();
    if(!handler) throw std::bad_alloc();
    handler();
  }
}

} // namespace

void* operator new(std::size_t n) { return allocate_or_throw(n); }
void* operator new[](std::size_t n) { return allocate_or_throw(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept
{
  try {
    return allocate_or_throw(n);
  } catch(...) {
    return nullptr;
  }
}
void* operator new[](std::size_t n, const std::nothrow_t& t) noexcept { return operator new(n, t); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }

#endif
