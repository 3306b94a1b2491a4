#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "reconstruction/mesh/mesh.h"
#include "reconstruction/parallel/segment_queue.h"
#include "reconstruction/well_geometry.h"

namespace caliper3d::reconstruction {

// Reads a well held lean again, whole and as drawn (docs/architecture.md, "A field held lean");
// throws, saying why, when it cannot (its log changed since it was loaded).
using WholeWellReader = std::function<std::shared_ptr<const WellGeometry>()>;

// Finer levels of one segment, to build.
struct DetailJob {
    std::size_t well = 0;  // the caller's key for the well
    std::shared_ptr<const WellGeometry> geometry;
    // Set for a well held lean: its levels are built from the whole well this reads (kept for
    // the next jobs, kWholeWellsKept wells at most), not from `geometry`.
    std::shared_ptr<const WholeWellReader> readWhole;
    std::size_t segment = 0;
    int from = 0;  // pyramid levels [from, to)
    int to = 0;
};
struct DetailResult {
    std::size_t well = 0;
    SegmentMesh mesh;   // levels [job.from, job.to) of job.segment
    std::string error;  // why the well held lean could not be read again (mesh empty)
};

// One worker thread that builds the finer levels of segments near the camera, nearest first
// (but every job of the well held lean it read last before any other's), for the window (the
// main thread attaches them: scenegraph::DetailLoader). Each new list of jobs replaces the jobs
// not started yet, so a camera that moves on never waits for detail it has left behind. Makes
// no Coin or Qt call; the destructor stops and joins.
class DetailWorker {
public:
    // Wells held lean read whole again and kept for the jobs that follow: a camera down one
    // hole, or between two, reads each once (about 160 bytes a row each: 130 MB for two 1 km
    // wells at 2.5 mm).
    static constexpr std::size_t kWholeWellsKept = 2;

    DetailWorker();
    ~DetailWorker();
    DetailWorker(const DetailWorker&) = delete;
    DetailWorker& operator=(const DetailWorker&) = delete;

    // Returns the jobs it dropped (queued, not started).
    std::vector<DetailJob> replaceJobs(std::vector<DetailJob> jobs);
    HandOffQueue<DetailResult>& results() { return m_results; }
    // Jobs queued or being built.
    std::size_t pending() const;
    // Lets go of the wells read whole again (their readers changed: the wells were restyled).
    void forgetWholeWells();
    // How many wells read whole it keeps now.
    std::size_t wholeWellsKept() const;

private:
    void run();
    // The whole well `job` wants: kept, or read now (outside the lock); throws
    // std::runtime_error with the reader's message when it could not be read.
    std::shared_ptr<const WellGeometry> wholeWell(const DetailJob& job);

    mutable std::mutex m_mutex;
    std::condition_variable m_wake;
    std::deque<DetailJob> m_jobs;
    std::size_t m_building = 0;
    bool m_stop = false;
    // The wells read whole (or why they could not be: each is read once), most recently wanted
    // last, by their reader.
    struct Whole {
        std::shared_ptr<const WholeWellReader> reader;
        std::shared_ptr<const WellGeometry> geometry;
        std::string error;
    };
    std::deque<Whole> m_wholes;
    HandOffQueue<DetailResult> m_results;
    std::thread m_thread;
};

}  // namespace caliper3d::reconstruction
