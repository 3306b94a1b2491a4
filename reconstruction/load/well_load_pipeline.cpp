#include "reconstruction/load/well_load_pipeline.h"

#include "io/log_reader.h"
#include "reconstruction/mesh/lod_levels.h"

#include <exception>

namespace caliper3d::reconstruction {

WellLoadPipeline::WellLoadPipeline(Loader loader) : m_loader(std::move(loader)) {}

WellLoadPipeline::WellLoadPipeline(WellSource source, LoadOptions options, Wellhead origin)
    : WellLoadPipeline(
          [this, source = std::move(source), options = std::move(options), origin]() mutable {
              options.cancel = &m_cancelled;  // a cancel stops the read too, within a block
              return loadWell(source, options, origin);
          }) {}

WellLoadPipeline::WellLoadPipeline(Reader reader, GeometryOptions options)
    : WellLoadPipeline([reader = std::move(reader), options = std::move(options)] {
          LoadedWell well;
          well.table = std::make_shared<const io::SectionTable>(reader());
          well.geometry = std::make_shared<const WellGeometry>(well.table, options);
          return well;
      }) {}

WellLoadPipeline::~WellLoadPipeline() {
    cancel();
    if (m_worker.joinable()) m_worker.join();
}

void WellLoadPipeline::start() {
    if (!m_worker.joinable()) m_worker = std::thread([this] { run(); });
}

void WellLoadPipeline::run() {
    try {
        LoadedWell well = m_loader();
        const std::shared_ptr<const WellGeometry> geometry = well.geometry;
        m_events.push(LoadStarted{geometry, std::move(well.diagnostics)});
        std::size_t built = 0;
        for (std::size_t s = 0; s < geometry->segmentCount(); ++s) {
            if (m_cancelled.load()) break;
            m_events.push(buildSegmentLevels(*geometry, s, kFirstCoarseLevel, 1 << 30));
            ++built;
        }
        m_events.push(LoadFinished{built});
    } catch (const io::ReadCancelled&) {
        m_events.push(LoadFinished{0});  // cancelled while reading: nothing was shown
    } catch (const GeometryCancelled&) {
        m_events.push(LoadFinished{0});  // cancelled while building the path and frames
    } catch (const std::exception& e) {
        m_events.push(LoadFailed{e.what()});
    }
}

}  // namespace caliper3d::reconstruction
