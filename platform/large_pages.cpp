#include "platform/large_pages.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>

#if defined(__linux__) && defined(__GLIBC__)
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace sylva {

void keep_freed_memory(std::size_t keep) {
#if defined(__linux__) && defined(__GLIBC__)
    mallopt(M_MMAP_THRESHOLD, 32 << 20);  // glibc's largest
    mallopt(M_TRIM_THRESHOLD, static_cast<int>(std::min<std::size_t>(keep, 1u << 30)));
#else
    (void)keep;
#endif
}

std::size_t use_large_pages(std::size_t reserve) {
#if defined(__linux__) && defined(__GLIBC__) && defined(MADV_HUGEPAGE)
    constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
    // One arena: worker threads allocate from the same (advised) heap; glibc's per-thread
    // caches keep small allocations off its lock.
    mallopt(M_ARENA_MAX, 1);
    keep_freed_memory(std::size_t{1} << 30);
    // A free top would serve the allocation below without growing the heap.
    malloc_trim(0);
    const auto before = reinterpret_cast<std::uintptr_t>(sbrk(0));
    // Grows the heap by `reserve` (an allocation above what its top holds, returned at once:
    // the top stays, since nothing is trimmed).
    mallopt(M_TOP_PAD, static_cast<int>(reserve));
    void* volatile grow = std::malloc(1 << 20);  // volatile: kept, not optimised away
    std::free(grow);
    mallopt(M_TOP_PAD, 128 << 10);  // glibc's default for later growth
    const auto after = reinterpret_cast<std::uintptr_t>(sbrk(0));
    const std::uintptr_t begin = (before + kHugePage - 1) & ~(kHugePage - 1);
    const std::uintptr_t end = after & ~(kHugePage - 1);
    if (end <= begin) return 0;
    if (madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE) != 0) return 0;
    return end - begin;
#else
    (void)reserve;
    return 0;
#endif
}

}  // namespace sylva
