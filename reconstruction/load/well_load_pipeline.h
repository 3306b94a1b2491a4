#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <variant>

#include "io/diagnostics.h"
#include "io/section_table.h"
#include "reconstruction/load/load_well.h"
#include "reconstruction/parallel/segment_queue.h"
#include "reconstruction/well_geometry.h"

namespace caliper3d::reconstruction {

// What a load worker hands to the main thread, in order: the geometry (path,
// frames) and the well's warnings once, then every segment, then Finished or
// Failed.
struct LoadStarted {
    std::shared_ptr<const WellGeometry> geometry;
    io::Diagnostics diagnostics;
};
// Sent first when the start of a long log was read quickly: its geometry (the path of the
// first rows) and, after it, that prefix's complete segments, which are the whole well's first
// segments; LoadStarted with the whole geometry follows, then the remaining segments.
struct LoadPreview {
    std::shared_ptr<const WellGeometry> geometry;
};
struct LoadFinished {
    std::size_t segments = 0;
};
struct LoadFailed {
    std::string message;
};
using LoadEvent = std::variant<LoadPreview, LoadStarted, SegmentMesh, LoadFinished, LoadFailed>;

// Owns one worker thread that loads a well (loadWell, or the loader it is
// given), then pushes its segment meshes into its queue. Makes no Coin or Qt
// call. Cancelled by a token checked per segment; the destructor cancels and
// joins.
class WellLoadPipeline {
public:
    using Loader = std::function<LoadedWell()>;
    using Reader = std::function<io::SectionTable()>;

    // Loads `source` with loadWell on the worker (survey, log, geometry and
    // their warnings), `origin` being the scene origin. A log longer than
    // kPreviewRows rows is previewed first (LoadPreview): a first picture of its
    // top while the rest is read.
    WellLoadPipeline(WellSource source, LoadOptions options, Wellhead origin);
    explicit WellLoadPipeline(Loader loader);
    // A table from `reader` (e.g. one made in memory), reconstructed with
    // `options`; no warnings of its own.
    WellLoadPipeline(Reader reader, GeometryOptions options);
    ~WellLoadPipeline();
    WellLoadPipeline(const WellLoadPipeline&) = delete;
    WellLoadPipeline& operator=(const WellLoadPipeline&) = delete;

    static constexpr std::size_t kPreviewRows = 4096;

    void start();
    void cancel() { m_cancelled.store(true); }
    bool cancelled() const { return m_cancelled.load(); }
    HandOffQueue<LoadEvent>& events() { return m_events; }

private:
    void run();

    Loader m_loader;
    Loader m_preview;  // may be empty
    HandOffQueue<LoadEvent> m_events;
    std::atomic<bool> m_cancelled{false};
    std::thread m_worker;
};

}  // namespace caliper3d::reconstruction
