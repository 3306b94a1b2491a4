#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace caliper3d::reconstruction {
class WellLoadPipeline;
}

namespace caliper3d::app {

// Where a cancelled load goes to finish. Its worker sees the cancel at the end of the block
// of the log it is parsing (tens to a couple of hundred milliseconds on a busy machine);
// waiting for that on the main thread would hold the window. Each retired pipeline is
// destroyed (joined) on a thread of its own; the destructor waits for them all. No Qt nor
// Coin call is made here.
class RetiredLoads {
public:
    RetiredLoads() = default;
    ~RetiredLoads();
    RetiredLoads(const RetiredLoads&) = delete;
    RetiredLoads& operator=(const RetiredLoads&) = delete;

    // Cancels `pipeline` and destroys it off this thread.
    void retire(std::unique_ptr<reconstruction::WellLoadPipeline> pipeline);
    // Loads retired whose workers have not stopped yet.
    int running() const { return m_running.load(); }

private:
    std::mutex m_mutex;
    std::vector<std::thread> m_threads;
    std::atomic<int> m_running{0};
};

}  // namespace caliper3d::app
