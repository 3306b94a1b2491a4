#include "app/freed_memory.h"

#include <sys/resource.h>

#include <cstddef>
#include <cstdlib>

#include <gtest/gtest.h>

namespace {

// The minor page faults taken while a fresh block of `bytes` is allocated, written a byte a
// page (through a volatile pointer, so that the block is not optimised away), and freed.
long faultsWritingABlock(std::size_t bytes) {
    rusage before{}, after{};
    getrusage(RUSAGE_SELF, &before);
    auto* block = static_cast<volatile char*>(std::malloc(bytes));
    if (!block) return -1;
    for (std::size_t at = 0; at < bytes; at += 4096) block[at] = 1;
    getrusage(RUSAGE_SELF, &after);
    std::free(const_cast<char*>(block));
    return after.ru_minflt - before.ru_minflt;
}

}  // namespace

// A well's table of 96 MiB freed is what the next well's allocates: its pages are not faulted in
// again. With glibc's defaults the block is mapped afresh for each (24,576 faults of 4 KiB, or
// 48 of 2 MiB where the kernel gives huge pages to every process).
TEST(FreedMemoryTest, ABlockFreedIsReusedWithoutFaultingItsPagesInAgain) {
#if !defined(__GLIBC__) || defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
    GTEST_SKIP() << "glibc's malloc only (a sanitizer brings its own)";
#else
    caliper3d::app::keepFreedMemoryForReuse();
    constexpr std::size_t kBytes = std::size_t{96} << 20;
    const long first = faultsWritingABlock(kBytes);
    ASSERT_GE(first, 0);
    const long again = faultsWritingABlock(kBytes);
    ASSERT_GE(again, 0);
    EXPECT_LT(again, 16) << "the first block took " << first << " faults";
#endif
}
