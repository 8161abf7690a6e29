// Fewer page faults: freed memory kept for the next tree, and the CLI's heap on transparent
// huge pages (2 MB) where Linux offers them.
//
// Sylva allocates its meshes fresh for every tree. On the virtual machines it is measured on
// (2 cores), a first touch of a 4 KB page costs about 11 us, so a default export's 2,400
// page faults were a third of its time (oak: 60 ms, 26 of them in the kernel). With the heap
// on huge pages, one fault maps 2 MB: 2,400 -> about 850 faults on the oak, 6,300 -> about
// 1,000 on the ternary (/usr/bin/time -f %R; the rest are the process's start and its
// threads). Desktop kernels fault faster, but fewer faults never cost.
#pragma once

#include <cstddef>

namespace sylva {

// For a long-running process (the studio): call first thing in main(). Freed memory stays
// with the process up to `keep` bytes (not trimmed, and nothing below 32 MB mapped apart, which
// glibc unmaps on free), so the next tree's meshes reuse pages already faulted in instead of
// faulting fresh ones: the studio's willow release (--bench-release tropism=0.6 under Xvfb,
// 6 runs each, alternated) 157-241 ms (median 229) -> 184-209 ms (median 195). A no-op
// without glibc.
void keep_freed_memory(std::size_t keep = std::size_t{256} << 20);

// For a short-lived process (the CLI): call first thing in main(), before any thread starts.
// Keeps the process's allocations in one heap (one malloc arena, nothing handed back to the
// kernel, nothing mapped apart below 32 MB), grows it by `reserve` bytes at once and asks the
// kernel to back that range with huge pages (madvise MADV_HUGEPAGE; memory is only used where
// touched). A no-op where glibc or huge pages are missing. Returns the bytes advised (0 when
// nothing was done). Not for the studio: a long-running process reuses its heap anyway, and
// there one arena for every thread was as fast or slower (sylva-bench-export: median at 800
// 31 -> 37 ms in one process; the studio's willow release unchanged within noise).
std::size_t use_large_pages(std::size_t reserve = std::size_t{256} << 20);

}  // namespace sylva
