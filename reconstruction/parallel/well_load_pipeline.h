#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <variant>

#include "io/section_table.h"
#include "reconstruction/parallel/segment_queue.h"
#include "reconstruction/well_geometry.h"

namespace caliper3d::reconstruction {

// What a load worker hands to the main thread, in order: the geometry (path,
// frames) once, then every segment, then Finished or Failed.
struct LoadStarted {
    std::shared_ptr<const WellGeometry> geometry;
};
struct LoadFinished {
    std::size_t segments = 0;
};
struct LoadFailed {
    std::string message;
};
using LoadEvent = std::variant<LoadStarted, SegmentMesh, LoadFinished, LoadFailed>;

// Owns one worker thread that reads a log (with the reader it is given),
// reconstructs it and pushes segment meshes into its queue. Makes no Coin or
// Qt call. Cancelled by a token checked per segment; the destructor cancels
// and joins.
class WellLoadPipeline {
public:
    using Reader = std::function<io::SectionTable()>;

    WellLoadPipeline(Reader reader, GeometryOptions options);
    ~WellLoadPipeline();
    WellLoadPipeline(const WellLoadPipeline&) = delete;
    WellLoadPipeline& operator=(const WellLoadPipeline&) = delete;

    void start();
    void cancel() { m_cancelled.store(true); }
    bool cancelled() const { return m_cancelled.load(); }
    HandOffQueue<LoadEvent>& events() { return m_events; }

private:
    void run();

    Reader m_reader;
    GeometryOptions m_options;
    HandOffQueue<LoadEvent> m_events;
    std::atomic<bool> m_cancelled{false};
    std::thread m_worker;
};

}  // namespace caliper3d::reconstruction
