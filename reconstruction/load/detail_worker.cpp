#include "reconstruction/load/detail_worker.h"

#include <algorithm>
#include <exception>
#include <stdexcept>
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

void DetailWorker::forgetWholeWells() {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_wholes.clear();
}

std::size_t DetailWorker::wholeWellsKept() const {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_wholes.size();
}

std::shared_ptr<const WellGeometry> DetailWorker::wholeWell(const DetailJob& job) {
    Whole kept;
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        const auto it = std::find_if(m_wholes.begin(), m_wholes.end(),
                                     [&](const Whole& w) { return w.reader == job.readWhole; });
        if (it != m_wholes.end()) {
            kept = std::move(*it);
            m_wholes.erase(it);
        }
    }
    if (!kept.reader) {
        kept.reader = job.readWhole;
        try {
            kept.geometry = (*job.readWhole)();
        } catch (const std::exception& e) {
            kept.error = e.what();
        }
    }
    std::shared_ptr<const WellGeometry> whole = kept.geometry;
    std::string error = kept.error;
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        while (m_wholes.size() >= kWholeWellsKept) m_wholes.pop_front();
        m_wholes.push_back(std::move(kept));
    }
    if (!whole) throw std::runtime_error(error);
    return whole;
}

void DetailWorker::run() {
    for (;;) {
        DetailJob job;
        {
            std::unique_lock<std::mutex> lock(m_mutex);
            m_wake.wait(lock, [this] { return m_stop || !m_jobs.empty(); });
            if (m_stop) return;
            // The jobs of the well held lean read last come first: it is read once for them
            // all, however the camera's requests interleave the wells.
            auto next = m_jobs.begin();
            if (!m_wholes.empty()) {
                const auto& last = m_wholes.back().reader;
                const auto same =
                    std::find_if(m_jobs.begin(), m_jobs.end(),
                                 [&](const DetailJob& j) { return j.readWhole == last; });
                if (same != m_jobs.end()) next = same;
            }
            job = std::move(*next);
            m_jobs.erase(next);
            ++m_building;
        }
        DetailResult result;
        result.well = job.well;
        try {
            const std::shared_ptr<const WellGeometry> geometry =
                job.readWhole ? wholeWell(job) : job.geometry;
            result.mesh = buildSegmentLevels(*geometry, job.segment, job.from, job.to);
        } catch (const std::exception& e) {
            result.mesh.index = job.segment;
            result.error = e.what();
        }
        m_results.push(std::move(result));
        std::lock_guard<std::mutex> lock(m_mutex);
        --m_building;
    }
}

}  // namespace caliper3d::reconstruction
