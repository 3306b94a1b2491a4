#include "app/desktop/analysis_job.h"

#include <utility>

namespace caliper3d::app {

AnalysisJob::AnalysisJob(QObject* context,
                         std::shared_ptr<const reconstruction::WellGeometry> geometry,
                         const reconstruction::AnalysisOptions& options, Done done)
    : m_job(context,
            [geometry = std::move(geometry), options,
             done = std::move(done)]() -> std::function<void()> {
                auto result = std::make_shared<const reconstruction::WellAnalysis>(
                    reconstruction::analyseWell(*geometry, options));
                return [result = std::move(result), done]() { done(result); };
            }) {}

}  // namespace caliper3d::app
