#include "reconstruction/parallel/prefault.h"

#include <algorithm>
#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

#include "reconstruction/parallel/ordered_blocks.h"

#if defined(__linux__) && !defined(MADV_POPULATE_WRITE)
#define MADV_POPULATE_WRITE 23  // linux/mman.h since 5.14; older headers lack it
#endif

namespace caliper3d::reconstruction {

void prefaultPages(void* data, std::size_t bytes, int threads, const std::atomic<bool>* cancel) {
#if defined(__linux__)
    const auto page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
    if (bytes == 0 || page == 0) return;
    // madvise takes whole pages; the partial pages at the ends belong to the
    // buffer's allocation too, so populating them changes nothing. The start of
    // the first page is `data` moved back, not an integer made a pointer.
    char* const begin =
        static_cast<char*>(data) - (reinterpret_cast<std::uintptr_t>(data) & (page - 1));
    char* const end = static_cast<char*>(data) + bytes;
    constexpr std::size_t kChunk = std::size_t{8} << 20;  // 8 MiB per task
    const std::size_t chunks = (static_cast<std::size_t>(end - begin) + kChunk - 1) / kChunk;
    forEachBlockInOrder(
        chunks, threads,
        [&](std::size_t chunk, std::size_t) {
            if (cancel && cancel->load(std::memory_order_relaxed)) return;
            char* const first = begin + chunk * kChunk;
            const std::size_t length = std::min(static_cast<std::size_t>(end - first), kChunk);
            // Refused by an older kernel (EINVAL): the first write faults instead.
            madvise(first, length, MADV_POPULATE_WRITE);
        },
        [](std::size_t) {});
#else
    (void)data;
    (void)bytes;
    (void)threads;
    (void)cancel;
#endif
}

}  // namespace caliper3d::reconstruction
