#pragma once

#include <functional>
#include <memory>
#include <thread>

#include "reconstruction/analysis/well_analysis.h"

class QObject;

namespace caliper3d::app {

// Analyses a loaded well on a worker thread (reconstruction::analyseWell: the report's own
// numbers) and hands the result to `done` on the main thread, through `context`'s event
// queue. The worker makes no Qt or Coin call but the queued hand-over. The destructor waits
// for the worker (about a second for a 4 km well); `done` is not called after it.
class AnalysisJob {
public:
    using Done = std::function<void(std::shared_ptr<const reconstruction::WellAnalysis>)>;

    AnalysisJob(QObject* context, std::shared_ptr<const reconstruction::WellGeometry> geometry,
                const reconstruction::AnalysisOptions& options, Done done);
    ~AnalysisJob();
    AnalysisJob(const AnalysisJob&) = delete;
    AnalysisJob& operator=(const AnalysisJob&) = delete;

private:
    std::shared_ptr<bool> m_alive;  // main thread only: false once destroyed
    std::thread m_worker;
};

}  // namespace caliper3d::app
