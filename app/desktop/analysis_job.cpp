#include "app/desktop/analysis_job.h"

#include <QMetaObject>
#include <QObject>

namespace caliper3d::app {

AnalysisJob::AnalysisJob(QObject* context,
                         std::shared_ptr<const reconstruction::WellGeometry> geometry,
                         const reconstruction::AnalysisOptions& options, Done done)
    : m_alive(std::make_shared<bool>(true)) {
    m_worker = std::thread([context, geometry = std::move(geometry), options,
                            done = std::move(done), alive = m_alive]() mutable {
        auto result = std::make_shared<const reconstruction::WellAnalysis>(
            reconstruction::analyseWell(*geometry, options));
        // `alive` is read on the main thread only, inside the queued call.
        QMetaObject::invokeMethod(
            context,
            [result = std::move(result), done = std::move(done), alive]() {
                if (*alive) done(result);
            },
            Qt::QueuedConnection);
    });
}

AnalysisJob::~AnalysisJob() {
    *m_alive = false;
    if (m_worker.joinable()) m_worker.join();
}

}  // namespace caliper3d::app
