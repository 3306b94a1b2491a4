#include "reconstruction/parallel/well_load_pipeline.h"

#include <exception>

namespace caliper3d::reconstruction {

WellLoadPipeline::WellLoadPipeline(Reader reader, GeometryOptions options)
    : m_reader(std::move(reader)), m_options(options) {}

WellLoadPipeline::~WellLoadPipeline() {
    cancel();
    if (m_worker.joinable()) m_worker.join();
}

void WellLoadPipeline::start() {
    if (!m_worker.joinable()) m_worker = std::thread([this] { run(); });
}

void WellLoadPipeline::run() {
    try {
        auto table = std::make_shared<const io::SectionTable>(m_reader());
        auto geometry = std::make_shared<const WellGeometry>(table, m_options);
        m_events.push(LoadStarted{geometry});
        std::size_t built = 0;
        for (std::size_t s = 0; s < geometry->segmentCount(); ++s) {
            if (m_cancelled.load()) break;
            m_events.push(geometry->buildSegment(s));
            ++built;
        }
        m_events.push(LoadFinished{built});
    } catch (const std::exception& e) {
        m_events.push(LoadFailed{e.what()});
    }
}

}  // namespace caliper3d::reconstruction
