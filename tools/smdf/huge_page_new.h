// Copyright (c) 2026 The Surface_mesh_direction_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef SMDF_TOOL_HUGE_PAGE_NEW_H
#define SMDF_TOOL_HUGE_PAGE_NEW_H

namespace smdf_memory {

// From now on, blocks of 4 MiB and more from operator new and from CHOLMOD are marked for
// transparent huge pages (huge_page_new.cpp). Call once, at start-up, before other threads run.
void enable_huge_pages();

} // namespace smdf_memory

#endif
