// Fewer page faults: freed memory kept for the next tree, and the CLI's heap on transparent
// huge pages (2 MB) where Linux offers them.
//
// Sylva allocates its meshes fresh for every tree, and on a small virtual machine the first
// touch of each 4 KB page is a large share of an export's time. With the heap on huge pages
// one fault maps 2 MB, so a tree takes a fraction of the faults. Desktop kernels fault
// faster, but fewer faults never cost.
#pragma once

#include <cstddef>

namespace sylva {

// For a long-running process (the studio): call first thing in main(). Freed memory stays
// with the process up to `keep` bytes (not trimmed, and nothing below 32 MB mapped apart, which
// glibc unmaps on free), so the next tree's meshes reuse pages already faulted in instead of
// faulting fresh ones, and the game mesh after a slider's release arrives sooner. A no-op
// without glibc.
void keep_freed_memory(std::size_t keep = std::size_t{256} << 20);

// For a short-lived process (the CLI): call first thing in main(), before any thread starts.
// Keeps the process's allocations in one heap (one malloc arena, nothing handed back to the
// kernel, nothing mapped apart below 32 MB), grows it by `reserve` bytes at once and asks the
// kernel to back that range with huge pages (madvise MADV_HUGEPAGE; memory is only used where
// touched). A no-op where glibc or huge pages are missing. Returns the bytes advised (0 when
// nothing was done). Not for the studio: a long-running process reuses its heap anyway, and
// there one arena for every thread is no faster, and slower for repeated exports.
std::size_t use_large_pages(std::size_t reserve = std::size_t{256} << 20);

}  // namespace sylva
