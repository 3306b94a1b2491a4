#include "reconstruction/load/streamed_load.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

#include "io/hole_azimuth_plan.h"
#include "io/log_stream.h"
#include "reconstruction/load/hole_azimuth.h"
#include "reconstruction/load/well_input.h"
#include "reconstruction/load/well_warnings.h"
#include "reconstruction/mesh/lod_levels.h"
#include "reconstruction/path/north_reference.h"
#include "reconstruction/segment_length.h"

namespace caliper3d::reconstruction {

namespace {

// Rows the reading thread may hold for the meshing thread before it stops feeding it (about
// 25 MB); the whole geometry then builds the segments not streamed.
constexpr std::size_t kMaxPendingRows = std::size_t{1} << 18;

// What the reading thread hands to the meshing thread.
struct Handover {
    std::mutex mutex;
    std::condition_variable changed;
    io::SectionTable pending;  // rows read and not yet taken, hole azimuth settled
    // False once the meshing thread fell too far behind or gave up; read without the lock
    // so that the reading thread copies no more chunks from then on.
    std::atomic<bool> feeding{true};
    bool done = false;  // the reading thread has ended (whole or error set)
    std::optional<io::SectionTable> whole;
    std::exception_ptr error;
};

// The meshing side: the rows since the last segment boundary placed, and the segments sent.
class StretchBuilder {
public:
    StretchBuilder(GeometryOptions options, const StreamedLoadSink& sink)
        : m_options(std::move(options)), m_sink(sink) {}

    // Takes rows read; builds a stretch once they complete two segments or more. Returns
    // false when the rows cannot be drawn alone (streaming stops there).
    bool add(io::SectionTable&& rows) {
        if (m_rows.rowCount() == 0)
            m_rows = std::move(rows);
        else
            m_rows.append(rows);
        const std::size_t n = m_rows.rowCount();
        if (!(m_options.segmentLength_m > 0.0)) {
            // Automatic: set by the well's first rows, as the whole well's geometry sets it.
            if (n < kSegmentStepRows) return true;
            m_options.segmentLength_m = autoSegmentLength(m_rows.depth_m);
        }
        if (n < 2 || m_rows.depth_m[n - 1] - m_rows.depth_m[0] < 2.0 * m_options.segmentLength_m)
            return true;
        return buildStretch();
    }

    // The segment length the stretches were cut to; 0 while still automatic (none built).
    double segmentLength_m() const { return m_options.segmentLength_m; }

private:
    bool buildStretch() {
        GeometryOptions options = m_options;
        options.continueFrom = m_from;
        options.threads = 1;
        std::shared_ptr<const WellGeometry> stretch;
        try {
            stretch = std::make_shared<const WellGeometry>(
                std::make_shared<const io::SectionTable>(std::move(m_rows)), options);
        } catch (const GeometryCancelled&) {
            throw;
        } catch (const std::exception&) {
            return false;  // e.g. no caliper data in these rows: the whole geometry says why
        }
        const std::size_t complete = stretch->segmentCount() - 1;  // the last may grow
        if (m_sink.stretch) m_sink.stretch(stretch);
        for (std::size_t s = 0; s < complete; ++s) {
            if (m_options.cancel && m_options.cancel->load()) throw GeometryCancelled();
            SegmentMesh segment = buildCoarseSegment(*stretch, s, m_sink.firstCoarseLevel);
            segment.index += m_sent;
            segment.firstRow += m_rowOffset;
            segment.lastRow += m_rowOffset;
            m_sink.segment(std::move(segment));
        }
        const std::size_t keepFrom = stretch->segmentRows(complete).first;
        m_from = stretch->path()[keepFrom];
        m_rows = stretch->table().rows(keepFrom, stretch->table().rowCount());
        m_rowOffset += keepFrom;
        m_sent += complete;
        return true;
    }

    GeometryOptions m_options;
    const StreamedLoadSink& m_sink;
    io::SectionTable m_rows;
    std::optional<PathPoint> m_from;
    std::size_t m_rowOffset = 0;
    std::size_t m_sent = 0;
};

// Hands each stretch the reader has parsed to the builder until the reader is done; stops
// feeding (the reader then keeps only the whole table) where a stretch cannot be streamed.
// Throws GeometryCancelled when the load is cancelled.
void feedStretches(Handover& handover, StretchBuilder& builder, const LoadOptions& options) {
    bool streaming = true;
    for (;;) {
        io::SectionTable rows;
        bool done = false;
        {
            std::unique_lock<std::mutex> lock(handover.mutex);
            handover.changed.wait(lock,
                                  [&] { return handover.done || handover.pending.rowCount() > 0; });
            rows = std::move(handover.pending);
            handover.pending = io::SectionTable{};
            done = handover.done;
            streaming = streaming && handover.feeding;
        }
        if (options.cancel && options.cancel->load()) throw GeometryCancelled();
        if (streaming && rows.rowCount() > 0 && !builder.add(std::move(rows))) {
            streaming = false;
            const std::lock_guard<std::mutex> lock(handover.mutex);
            handover.feeding = false;
            handover.pending = io::SectionTable{};
        }
        if (done) break;
    }
}

}  // namespace

LoadedWell loadWellStreamed(const WellSource& source, const LoadOptions& options,
                            const Wellhead& origin, const StreamedLoadSink& sink) {
    LoadedWell out;
    GeometryOptions geometry = wellGeometryOptions(source, options, origin, &out.diagnostics);
    const bool surveyGiven = !source.surveyPath.empty();

    Handover handover;
    handover.feeding = sink.stream;
    io::Diagnostics readDiagnostics;
    std::thread reader([&] {
        try {
            io::StreamOptions stream;
            stream.cancel = options.cancel;
            stream.threads = options.readThreads;
            // Blocks of 2 MB: the first stretch comes sooner, and a cancel is seen within a
            // block parsed while the meshing thread shares the cores.
            stream.blockBytes = 2u << 20;
            io::HoleAzimuthPlan plan;
            NorthCorrection north;
            std::size_t estimatedRows = 0, rowsRead = 0;
            stream.onStart = [&](const io::LogInfo& info, std::size_t estimate) {
                plan = io::holeAzimuthPlan(info, surveyGiven);
                north = resolveNorth(info.north, info.location, options.read);
                estimatedRows = estimate;
            };
            stream.onChunk = [&](const io::SectionTable& chunk) {
                rowsRead += chunk.rowCount();
                if (sink.read && estimatedRows > 0)
                    sink.read(std::min(1.0, double(rowsRead) / double(estimatedRows)));
                if (!handover.feeding.load()) return;
                io::SectionTable rows = chunk;
                applyNorth(rows, north);                  // as loadWellTable does the whole log
                resolveHoleAzimuth(rows, plan, nullptr);  // row by row: as the whole log's
                {
                    const std::lock_guard<std::mutex> lock(handover.mutex);
                    if (!handover.feeding) return;
                    if (handover.pending.rowCount() == 0)
                        handover.pending = std::move(rows);
                    else
                        handover.pending.append(rows);
                    if (handover.pending.rowCount() > kMaxPendingRows) {
                        handover.feeding = false;
                        handover.pending = io::SectionTable{};
                    }
                }
                handover.changed.notify_one();
            };
            io::SectionTable whole = loadWellTable(source.path, readOptionsFor(source, options),
                                                   surveyGiven, &readDiagnostics, stream);
            const std::lock_guard<std::mutex> lock(handover.mutex);
            handover.whole = std::move(whole);
            handover.done = true;
        } catch (...) {
            const std::lock_guard<std::mutex> lock(handover.mutex);
            handover.error = std::current_exception();
            handover.done = true;
        }
        handover.changed.notify_one();
    });

    StretchBuilder builder(geometry, sink);
    try {
        feedStretches(handover, builder, options);
    } catch (...) {
        {
            const std::lock_guard<std::mutex> lock(handover.mutex);
            handover.feeding = false;
        }
        reader.join();
        throw;
    }
    reader.join();
    if (handover.error) std::rethrow_exception(handover.error);

    if (options.cancel && options.cancel->load()) throw GeometryCancelled();
    out.diagnostics.merge(readDiagnostics);
    io::SectionTable& whole = *handover.whole;
    whole.source = source.path;
    out.table = std::make_shared<const io::SectionTable>(std::move(whole));
    // The reading thread has ended: the threads the read had place the whole well (both cores,
    // or one where other wells' loads share them).
    geometry.threads = std::max(1, options.readThreads);
    // The segments already sent were cut to this length: the whole well keeps it.
    if (builder.segmentLength_m() > 0.0) geometry.segmentLength_m = builder.segmentLength_m();
    out.geometry = std::make_shared<const WellGeometry>(out.table, geometry);
    if (options.cancel && options.cancel->load()) throw GeometryCancelled();
    if (options.geometryWarnings) warnGeometry(*out.geometry, out.diagnostics);
    return out;
}

}  // namespace caliper3d::reconstruction
