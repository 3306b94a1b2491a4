#pragma once

#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>

namespace caliper3d::io {

// Shares the pieces of one block between the calling thread and one worker
// thread that lives as long as the read. Pieces are claimed one at a time, so
// when the other core is busy with another job the caller simply parses more
// of them instead of waiting for a fixed half (which made two threads slower
// than one on a loaded machine). Hand-written: a general pool (Boost.Asio's
// thread_pool) would start its threads per read and cannot let the caller
// take part.
class PieceSharing {
public:
    explicit PieceSharing(bool withWorker);
    ~PieceSharing();
    PieceSharing(const PieceSharing&) = delete;
    PieceSharing& operator=(const PieceSharing&) = delete;

    // Runs task(i) for every i below count and returns when all have run.
    // The task must not throw (the row parser keeps its error).
    void run(std::size_t count, const std::function<void(std::size_t)>& task);

private:
    void work();

    std::thread m_worker;
    std::mutex m_mutex;
    std::condition_variable m_wake, m_finished;
    const std::function<void(std::size_t)>* m_task = nullptr;
    std::size_t m_count = 0, m_next = 0, m_done = 0;
    std::uint64_t m_generation = 0;
    bool m_stop = false;
};

}  // namespace caliper3d::io
