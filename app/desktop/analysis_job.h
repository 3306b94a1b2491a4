#pragma once

#include <functional>
#include <memory>

#include "app/desktop/background_job.h"
#include "reconstruction/analysis/well_analysis.h"

class QObject;

namespace caliper3d::app {

// Analyses a loaded well on a worker thread (reconstruction::analyseWell: the report's own
// numbers) and hands the result to `done` on the main thread, through `context`'s event
// queue (a BackgroundJob). The destructor waits for the worker (about a second for a 4 km
// well); `done` is not called after it.
class AnalysisJob {
public:
    using Done = std::function<void(std::shared_ptr<const reconstruction::WellAnalysis>)>;

    AnalysisJob(QObject* context, std::shared_ptr<const reconstruction::WellGeometry> geometry,
                const reconstruction::AnalysisOptions& options, Done done);

private:
    BackgroundJob m_job;
};

}  // namespace caliper3d::app
