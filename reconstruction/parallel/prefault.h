#pragma once

#include <atomic>

#include <cstddef>

namespace caliper3d::reconstruction {

// Faults in the pages of a fresh buffer that is about to be written, on
// `threads` threads at once. Allocating and zeroing the pages is most of the
// cost of first writing a fresh buffer, and a 4 km well's path, frames and
// section results are ~450 MB: touched by one thread, that was the largest
// sequential part of its reconstruction. Uses Linux's MADV_POPULATE_WRITE
// (5.14 and later), which is also cheaper than a page fault per page; where
// it is unavailable the pages are faulted in when first written, as before.
// Changes no byte of the buffer.
// Stops early (the pages left fault on first write instead) once `cancel` is set.
void prefaultPages(void* data, std::size_t bytes, int threads,
                   const std::atomic<bool>* cancel = nullptr);

}  // namespace caliper3d::reconstruction
