#include "reconstruction/load/well_load_pipeline.h"

#include "io/log_reader.h"
#include "reconstruction/mesh/lod_levels.h"

#include <exception>

namespace caliper3d::reconstruction {

WellLoadPipeline::WellLoadPipeline(Loader loader) : m_loader(std::move(loader)) {}

WellLoadPipeline::WellLoadPipeline(WellSource source, LoadOptions options, Wellhead origin)
    : WellLoadPipeline([this, source, options, origin]() mutable {
          options.cancel = &m_cancelled;  // a cancel stops the read too, within a block
          return loadWell(source, options, origin);
      }) {
    m_preview = [this, source = std::move(source), options = std::move(options), origin]() mutable {
        options.cancel = &m_cancelled;
        return loadWellPreview(source, options, origin, kPreviewRows);
    };
}

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
        // The top of a long log first: its complete segments are the whole well's.
        std::size_t sent = 0;
        if (m_preview) {
            const LoadedWell preview = m_preview();
            if (preview.geometry && preview.geometry->segmentCount() > 1 && !m_cancelled.load()) {
                m_events.push(LoadPreview{preview.geometry});
                for (; sent + 1 < preview.geometry->segmentCount(); ++sent)
                    m_events.push(buildCoarseSegment(*preview.geometry, sent));
            }
        }
        LoadedWell well = m_loader();
        const std::shared_ptr<const WellGeometry> geometry = well.geometry;
        m_events.push(LoadStarted{geometry, std::move(well.diagnostics)});
        std::size_t built = sent;
        for (std::size_t s = sent; s < geometry->segmentCount(); ++s) {
            if (m_cancelled.load()) break;
            m_events.push(buildCoarseSegment(*geometry, s));
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
