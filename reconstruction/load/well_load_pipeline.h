#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <variant>
#include <vector>

#include <glm/vec3.hpp>

#include "io/diagnostics.h"
#include "io/section_table.h"
#include "reconstruction/load/load_well.h"
#include "reconstruction/load/streamed_load.h"
#include "reconstruction/mesh/lod_tree.h"
#include "reconstruction/parallel/segment_queue.h"
#include "reconstruction/well_geometry.h"

namespace caliper3d::reconstruction {

// What a load worker hands to the main thread, in order: the geometry (path,
// frames) and the well's warnings once, then every segment, then the merged mesh of every
// span of the level-of-detail tree (reconstruction/mesh/lod_tree.h), then Finished or
// Failed.
struct LoadStarted {
    std::shared_ptr<const WellGeometry> geometry;
    io::Diagnostics diagnostics;
};
// Sent while the log is still being read, by a streamed load: the path line of the next
// stretch of rows (the path extended from where the last stretch ended), then the segments it
// completes, which are the whole well's segments bit for bit. LoadStarted with the whole
// geometry follows once the log is read, then the remaining segments.
struct LoadStretch {
    std::vector<glm::vec3> path;  // pathLine of the stretch's rows below the last one sent
    double bottom_m = 0.0;        // measured depth of its last row
};
struct LoadFinished {
    std::size_t segments = 0;
};
struct LoadFailed {
    std::string message;
};
using LoadEvent =
    std::variant<LoadStretch, LoadStarted, SegmentMesh, SpanMesh, LoadFinished, LoadFailed>;

// What a load sends between its geometry and LoadFinished.
enum class LoadSends {
    // Streamed (loadWellStreamed): each stretch's path and segments while the log is read,
    // then the rest of the segments, then the spans.
    streamed,
    // The log read whole first (StreamedLoadSink::stream false), then every segment, then the
    // spans: nothing is placed twice.
    whole,
    // The log read whole, then no segment and no span: a well the caller draws its own way
    // (the window's well of a field held lean, from its plan). LoadFinished counts the well's
    // segments.
    geometryOnly,
};

// Owns one worker thread that loads a well (streamed, or by the loader it is
// given), then pushes its segment meshes into its queue. Makes no Coin or Qt
// call. Cancelled by a token checked per segment; the destructor cancels and
// joins.
class WellLoadPipeline {
public:
    using Loader = std::function<LoadedWell()>;
    using Reader = std::function<io::SectionTable()>;

    // Loads `source` streamed (loadWellStreamed: the log read on a reading thread while this
    // worker, the meshing thread, sends each stretch read and its segments), `origin` being
    // the scene origin; then the whole well's geometry and warnings and the rest.
    // Segments come with their levels from `firstCoarseLevel` on (lod_levels.h).
    WellLoadPipeline(WellSource source, LoadOptions options, const Wellhead& origin,
                     int firstCoarseLevel = kFirstCoarseLevel);
    explicit WellLoadPipeline(Loader loader);
    // A table from `reader` (e.g. one made in memory), reconstructed with
    // `options`; no warnings of its own.
    WellLoadPipeline(Reader reader, GeometryOptions options);
    ~WellLoadPipeline();
    WellLoadPipeline(const WellLoadPipeline&) = delete;
    WellLoadPipeline& operator=(const WellLoadPipeline&) = delete;

    // What a streamed load sends (LoadSends); other loaders send every segment and span.
    void start(LoadSends sends = LoadSends::streamed);
    void cancel() { m_cancelled.store(true); }
    bool cancelled() const { return m_cancelled.load(); }
    // How much of the log a streamed load has read, 0 to 1 (any thread; 0 for other loaders
    // until their geometry comes).
    double readFraction() const { return m_readFraction.load(); }
    HandOffQueue<LoadEvent>& events() { return m_events; }

private:
    void run();

    using StreamedLoader = std::function<LoadedWell(const StreamedLoadSink&)>;

    Loader m_loader;
    StreamedLoader m_streamed;  // when set, used instead of m_loader
    HandOffQueue<LoadEvent> m_events;
    std::atomic<bool> m_cancelled{false};
    std::atomic<double> m_readFraction{0.0};
    int m_firstCoarseLevel = kFirstCoarseLevel;
    LoadSends m_sends = LoadSends::streamed;  // set before the worker starts
    std::thread m_worker;
};

}  // namespace caliper3d::reconstruction
