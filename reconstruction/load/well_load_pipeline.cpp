#include "reconstruction/load/well_load_pipeline.h"

#include "io/log_reader.h"
#include "reconstruction/mesh/lod_levels.h"

#include <exception>

namespace caliper3d::reconstruction {

WellLoadPipeline::WellLoadPipeline(Loader loader) : m_loader(std::move(loader)) {}

WellLoadPipeline::WellLoadPipeline(WellSource source, LoadOptions options, const Wellhead& origin,
                                   int firstCoarseLevel)
    : m_firstCoarseLevel(firstCoarseLevel) {
    m_streamed = [this, source = std::move(source), options = std::move(options),
                  origin](const StreamedLoadSink& sink) mutable {
        options.cancel = &m_cancelled;  // a cancel stops the read too, within a block
        return loadWellStreamed(source, options, origin, sink);
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

void WellLoadPipeline::start(LoadSends sends) {
    if (m_worker.joinable()) return;
    m_sends = sends;
    m_worker = std::thread([this] { run(); });
}

void WellLoadPipeline::run() {
    std::size_t built = 0;
    try {
        LoadedWell well;
        if (m_streamed) {
            StreamedLoadSink sink;
            sink.firstCoarseLevel = m_firstCoarseLevel;
            sink.stream = m_sends == LoadSends::streamed;
            double drawnTo = -1.0e300;  // the path line sent so far ends here
            sink.stretch = [this, &drawnTo](const std::shared_ptr<const WellGeometry>& stretch) {
                if (m_cancelled.load()) return;
                // Points only: the stretch's table and frames are freed once its segments are
                // built, not held in the queue until the window takes them.
                LoadStretch event{pathLine(*stretch, 1.0, drawnTo),
                                  stretch->table().depth_m.back()};
                drawnTo = event.bottom_m;
                m_events.push(std::move(event));
            };
            sink.read = [this](double fraction) { m_readFraction.store(fraction); };
            sink.segment = [this, &built](SegmentMesh&& segment) {
                if (m_cancelled.load()) return;
                m_events.push(std::move(segment));
                ++built;
            };
            well = m_streamed(sink);
        } else {
            well = m_loader();
        }
        m_readFraction.store(1.0);
        const std::shared_ptr<const WellGeometry> geometry = well.geometry;
        m_events.push(LoadStarted{geometry, std::move(well.diagnostics)});
        if (m_streamed && m_sends == LoadSends::geometryOnly) {
            m_events.push(LoadFinished{geometry->segmentCount()});
            return;
        }
        for (std::size_t s = built; s < geometry->segmentCount(); ++s) {
            if (m_cancelled.load()) break;
            m_events.push(buildCoarseSegment(*geometry, s, m_firstCoarseLevel));
            ++built;
        }
        // The tree's merged meshes, once every segment is out: until a span's arrives, the
        // span shows its segments.
        if (!m_cancelled.load())
            for (SpanMesh& span : buildSpanMeshes(*geometry, &m_cancelled))
                m_events.push(std::move(span));
        m_events.push(LoadFinished{built});
    } catch (const io::ReadCancelled&) {
        m_events.push(LoadFinished{built});  // cancelled while reading: the segments streamed
    } catch (const GeometryCancelled&) {
        m_events.push(LoadFinished{built});  // cancelled while building the path and frames
    } catch (const std::exception& e) {
        m_events.push(LoadFailed{e.what()});
    }
}

}  // namespace caliper3d::reconstruction
