#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "reconstruction/mesh/mesh.h"
#include "reconstruction/parallel/segment_queue.h"
#include "reconstruction/well_geometry.h"

namespace caliper3d::reconstruction {

// Finer levels of one segment, to build.
struct DetailJob {
    std::size_t well = 0;  // the caller's key for the well
    std::shared_ptr<const WellGeometry> geometry;
    std::size_t segment = 0;
    int from = 0;  // pyramid levels [from, to)
    int to = 0;
};
struct DetailResult {
    std::size_t well = 0;
    SegmentMesh mesh;  // levels [job.from, job.to) of job.segment
};

// One worker thread that builds the finer levels of segments near the camera, nearest first,
// for the window (the main thread attaches them: scenegraph::DetailLoader). Each new list of
// jobs replaces the jobs not started yet, so a camera that moves on never waits for detail it
// has left behind. Makes no Coin or Qt call; the destructor stops and joins.
class DetailWorker {
public:
    DetailWorker();
    ~DetailWorker();
    DetailWorker(const DetailWorker&) = delete;
    DetailWorker& operator=(const DetailWorker&) = delete;

    // Returns the jobs it dropped (queued, not started).
    std::vector<DetailJob> replaceJobs(std::vector<DetailJob> jobs);
    HandOffQueue<DetailResult>& results() { return m_results; }
    // Jobs queued or being built.
    std::size_t pending() const;

private:
    void run();

    mutable std::mutex m_mutex;
    std::condition_variable m_wake;
    std::deque<DetailJob> m_jobs;
    std::size_t m_building = 0;
    bool m_stop = false;
    HandOffQueue<DetailResult> m_results;
    std::thread m_thread;
};

}  // namespace caliper3d::reconstruction
