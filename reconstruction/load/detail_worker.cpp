#include "reconstruction/load/detail_worker.h"

#include <utility>

#include "reconstruction/mesh/lod_levels.h"

namespace caliper3d::reconstruction {

DetailWorker::DetailWorker() : m_thread([this] { run(); }) {}

DetailWorker::~DetailWorker() {
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_stop = true;
        m_jobs.clear();
    }
    m_wake.notify_all();
    m_thread.join();
}

std::vector<DetailJob> DetailWorker::replaceJobs(std::vector<DetailJob> jobs) {
    std::vector<DetailJob> dropped;
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        dropped.assign(std::make_move_iterator(m_jobs.begin()),
                       std::make_move_iterator(m_jobs.end()));
        m_jobs.assign(std::make_move_iterator(jobs.begin()), std::make_move_iterator(jobs.end()));
    }
    m_wake.notify_one();
    return dropped;
}

std::size_t DetailWorker::pending() const {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_jobs.size() + m_building;
}

void DetailWorker::run() {
    for (;;) {
        DetailJob job;
        {
            std::unique_lock<std::mutex> lock(m_mutex);
            m_wake.wait(lock, [this] { return m_stop || !m_jobs.empty(); });
            if (m_stop) return;
            job = std::move(m_jobs.front());
            m_jobs.pop_front();
            ++m_building;
        }
        DetailResult result;
        result.well = job.well;
        result.mesh = buildSegmentLevels(*job.geometry, job.segment, job.from, job.to);
        m_results.push(std::move(result));
        std::lock_guard<std::mutex> lock(m_mutex);
        --m_building;
    }
}

}  // namespace caliper3d::reconstruction
