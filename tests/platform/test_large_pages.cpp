// platform/large_pages.h: freed memory kept for the next allocation; the heap grown once and
// advised for huge pages, and later allocations (large ones too, which glibc would map apart)
// served from that reserve.
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "platform/large_pages.h"

#if defined(__linux__) && defined(__GLIBC__)
#include <unistd.h>
#endif

namespace sylva {
namespace {

// glibc's malloc is the one these settings are for; a sanitizer brings its own.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define SYLVA_GLIBC_MALLOC 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define SYLVA_GLIBC_MALLOC 0
#endif
#endif
#ifndef SYLVA_GLIBC_MALLOC
#define SYLVA_GLIBC_MALLOC 1
#endif

#if defined(__linux__) && defined(__GLIBC__) && SYLVA_GLIBC_MALLOC
bool huge_pages_offered() {
    std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string modes;
    std::getline(in, modes);
    return !modes.empty() && modes.find("[never]") == std::string::npos;
}

std::uintptr_t heap_top() {
    return reinterpret_cast<std::uintptr_t>(sbrk(0));
}

TEST(LargePages, FreedMemoryIsKeptForTheNextTree) {
    keep_freed_memory();
    constexpr std::size_t kSize = std::size_t{16} << 20;  // glibc maps that apart by default
    auto* block = new char[kSize];
    block[0] = 1;
    const auto first = reinterpret_cast<std::uintptr_t>(block);
    delete[] block;
    // It came from the heap, which kept it after the free...
    EXPECT_LE(first + kSize, heap_top());
    // ...and gives it to the next allocation of its size.
    auto* again = new char[kSize];
    again[0] = 1;
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(again), first);
    delete[] again;
}

TEST(LargePages, TheHeapIsAdvisedOnceAndServesLaterAllocations) {
    if (!huge_pages_offered()) GTEST_SKIP() << "this kernel offers no transparent huge pages";
    const std::size_t advised = use_large_pages(std::size_t{64} << 20);
    const std::uintptr_t top = heap_top();
    EXPECT_GE(advised, std::size_t{60} << 20);  // 64 MB, less what aligning to 2 MB cuts
    // 16 MB: glibc maps that apart by default; here it comes from the advised reserve at the
    // heap's top, which does not grow for it.
    std::vector<char> block(std::size_t{16} << 20, 1);
    const auto end = reinterpret_cast<std::uintptr_t>(block.data()) + block.size();
    EXPECT_GT(end, top - advised);
    EXPECT_LE(end, top);
    EXPECT_EQ(heap_top(), top) << "the heap grew instead of using its reserve";
}
#endif

}  // namespace
}  // namespace sylva
