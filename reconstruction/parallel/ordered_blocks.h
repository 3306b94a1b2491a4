#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace caliper3d::reconstruction {

// Runs `work(block, worker)` for every block in [0, count) on `threads`
// workers (the calling thread is worker 0), and `finish(block)` for each block
// once its work is done, strictly in block order, one at a time. The work of
// a block runs in parallel with other blocks; `finish` carries what must run
// in sequence (a prefix sum, a sum in row order), so that the results are the
// same, bit for bit, whatever the number of threads. `finish` runs on
// whichever worker completes the chain, so it may only use the block's
// outputs, never a worker's scratch. Workers are started and joined here: no
// thread outlives the call. The first exception thrown by `work` or `finish`
// stops the remaining blocks and is rethrown.
template <class Work, class Finish>
void forEachBlockInOrder(std::size_t count, int threads, Work&& work, Finish&& finish) {
    const std::size_t workers = std::max<std::size_t>(
        1, std::min<std::size_t>(count, static_cast<std::size_t>(std::max(1, threads))));
    if (workers == 1) {
        for (std::size_t b = 0; b < count; ++b) {
            work(b, std::size_t{0});
            finish(b);
        }
        return;
    }
    std::atomic<std::size_t> next{0};
    std::atomic<bool> failed{false};
    std::mutex mutex;  // guards done, frontier, error; held while a block is finished
    std::vector<unsigned char> done(count, 0);
    std::size_t frontier = 0;  // blocks below it are finished
    std::exception_ptr error;
    auto run = [&](std::size_t worker) {
        try {
            for (;;) {
                const std::size_t b = next.fetch_add(1, std::memory_order_relaxed);
                if (b >= count || failed.load(std::memory_order_relaxed)) return;
                work(b, worker);
                std::lock_guard<std::mutex> lock(mutex);
                done[b] = 1;
                while (frontier < count && done[frontier]) {
                    finish(frontier);
                    ++frontier;
                }
            }
        } catch (...) {
            std::lock_guard<std::mutex> lock(mutex);
            if (!error) error = std::current_exception();
            failed.store(true, std::memory_order_relaxed);
        }
    };
    std::vector<std::thread> pool;
    pool.reserve(workers - 1);
    for (std::size_t w = 1; w < workers; ++w) {
        try {
            pool.emplace_back(run, w);
        } catch (const std::system_error&) {
            break;  // no more threads to be had: the ones running take every block
        }
    }
    run(0);
    for (std::thread& t : pool) t.join();
    if (error) std::rethrow_exception(error);
}

}  // namespace caliper3d::reconstruction
