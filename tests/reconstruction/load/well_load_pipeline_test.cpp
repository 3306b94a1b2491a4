// The window's load worker: a cancel stops it, the read of the log included, and opening
// and cancelling loads over and over is clean (run under ThreadSanitizer by make tsan-test).
#include "reconstruction/load/well_load_pipeline.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <variant>

#include <gtest/gtest.h>

#include "io/column_text_writer.h"
#include "reconstruction/mesh/lod_levels.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "test_support.h"

using namespace caliper3d;
using namespace caliper3d::reconstruction;

namespace {

// A 60 m well logged every 2.5 mm (24,001 rows, about 3.5 MB of text), written once per test
// process (ctest runs the tests of this file in parallel processes: one file each).
const std::string& wellFile() {
    static const std::string path = [] {
        const auto file =
            test::scratch("pipeline_60m_" + std::to_string(static_cast<long>(::getpid())) + ".txt");
        io::writeColumnTextFile(file.string(),
                                makeSyntheticWell(syntheticProfile("example", 60.0, 0.0025)));
        return file.string();
    }();
    return path;
}

// Every event up to the last one (Finished or Failed).
std::vector<LoadEvent> drainAll(WellLoadPipeline& pipeline) {
    std::vector<LoadEvent> events;
    for (;;) {
        auto event = pipeline.events().waitPop();
        events.push_back(std::move(*event));
        if (std::holds_alternative<LoadFinished>(events.back()) ||
            std::holds_alternative<LoadFailed>(events.back()))
            return events;
    }
}

// The whole geometry a load sent (LoadStarted), where among its events it came.
const WellGeometry& geometrySent(const std::vector<LoadEvent>& events) {
    const auto started = std::find_if(events.begin(), events.end(), [](const LoadEvent& e) {
        return std::holds_alternative<LoadStarted>(e);
    });
    if (started == events.end()) throw std::runtime_error("no LoadStarted among the events");
    return *std::get<LoadStarted>(*started).geometry;
}

// Every event of the test well loaded as `sends` says, and how much of it was read by the end.
struct Sent {
    std::vector<LoadEvent> events;
    double readFraction = 0.0;
};
Sent loadSending(LoadSends sends, const LoadOptions& options = {}) {
    WellLoadPipeline pipeline(WellSource{wellFile(), {}, {}, {}}, options, Wellhead{});
    pipeline.start(sends);
    Sent sent;
    sent.events = drainAll(pipeline);
    sent.readFraction = pipeline.readFraction();
    return sent;
}

}  // namespace

TEST(WellLoadPipelineTest, StreamsStretchesAndTheirSegmentsWhileReadingThenTheWholeWell) {
    WellLoadPipeline pipeline(WellSource{wellFile(), {}, {}, {}}, LoadOptions{}, Wellhead{});
    EXPECT_EQ(pipeline.readFraction(), 0.0);
    pipeline.start();
    const std::vector<LoadEvent> events = drainAll(pipeline);
    EXPECT_EQ(pipeline.readFraction(), 1.0);  // the whole log read
    // A stretch of the rows read so far comes first, its segments after it; the whole
    // geometry once the log is read, then the segments not streamed.
    ASSERT_TRUE(std::holds_alternative<LoadStretch>(events.front()));
    std::shared_ptr<const WellGeometry> whole;
    std::vector<const LoadStretch*> stretches;
    std::vector<const SegmentMesh*> segments;
    std::size_t beforeWhole = 0;
    for (const LoadEvent& e : events) {
        if (const auto* started = std::get_if<LoadStarted>(&e)) whole = started->geometry;
        if (const auto* stretch = std::get_if<LoadStretch>(&e)) {
            EXPECT_FALSE(whole);
            stretches.push_back(stretch);
        }
        if (const auto* segment = std::get_if<SegmentMesh>(&e)) {
            segments.push_back(segment);
            if (!whole) ++beforeWhole;
        }
    }
    ASSERT_TRUE(whole);
    EXPECT_GE(beforeWhole, 2u);
    EXPECT_EQ(std::get<LoadFinished>(events.back()).segments, 60u);  // 1 m segments in all
    ASSERT_EQ(segments.size(), 60u);
    for (std::size_t s = 0; s < segments.size(); ++s) {
        EXPECT_EQ(segments[s]->index, s);
        EXPECT_EQ(segments[s]->firstLevel, kFirstCoarseLevel);  // finer ones near the camera
        EXPECT_EQ(segments[s]->firstRow, whole->segmentRows(s).first);
        EXPECT_EQ(segments[s]->lastRow, whole->segmentRows(s).second);
    }
    // The stretches' path lines follow each other down the well, and every point is where
    // the whole geometry places that row, bit for bit.
    std::size_t row = 0;
    double bottom = -1.0;
    for (const LoadStretch* stretch : stretches) {
        EXPECT_GT(stretch->bottom_m, bottom);
        bottom = stretch->bottom_m;
        for (const glm::vec3& point : stretch->path) {
            while (row < whole->table().rowCount() &&
                   glm::vec3(toScene(whole->centre(row))) != point)
                ++row;
            ASSERT_LT(row, whole->table().rowCount()) << "a point off the whole well's path";
            EXPECT_LE(whole->table().depth_m[row], stretch->bottom_m);
        }
    }
    EXPECT_EQ(glm::vec3(toScene(whole->centre(0))), stretches.front()->path.front());
    // The streamed segments are the whole well's, bit for bit.
    for (std::size_t s = 0; s < beforeWhole; ++s) {
        const SegmentMesh again = buildCoarseSegment(*whole, s);
        ASSERT_EQ(again.levels.size(), segments[s]->levels.size());
        for (std::size_t l = 0; l < again.levels.size(); ++l) {
            EXPECT_EQ(again.levels[l].positions, segments[s]->levels[l].positions) << s << "/" << l;
            EXPECT_EQ(again.levels[l].normals, segments[s]->levels[l].normals) << s << "/" << l;
            EXPECT_EQ(again.levels[l].colours, segments[s]->levels[l].colours) << s << "/" << l;
            EXPECT_EQ(again.levels[l].stripIndices, segments[s]->levels[l].stripIndices);
        }
    }
}

TEST(WellLoadPipelineTest, AWellNotStreamedSendsNoStretchAndTheWholeWellsSegmentsAfterIt) {
    const Sent streamed = loadSending(LoadSends::streamed), whole = loadSending(LoadSends::whole);
    const std::vector<LoadEvent>& a = streamed.events;
    const std::vector<LoadEvent>& b = whole.events;
    EXPECT_EQ(whole.readFraction, 1.0);
    // Nothing before the whole geometry; then every segment, in order, then the spans.
    ASSERT_TRUE(std::holds_alternative<LoadStarted>(b.front()));
    const WellGeometry& placed = geometrySent(b);
    const WellGeometry& reference = geometrySent(a);
    ASSERT_EQ(placed.table().rowCount(), reference.table().rowCount());
    EXPECT_EQ(placed.segmentCount(), reference.segmentCount());
    std::vector<const SegmentMesh*> segments;
    std::size_t spans = 0;
    for (const LoadEvent& e : b) {
        EXPECT_FALSE(std::holds_alternative<LoadStretch>(e));
        if (const auto* segment = std::get_if<SegmentMesh>(&e)) {
            EXPECT_EQ(spans, 0u) << "a segment after a span";
            segments.push_back(segment);
        }
        if (std::holds_alternative<SpanMesh>(e)) ++spans;
    }
    EXPECT_EQ(std::get<LoadFinished>(b.back()).segments, 60u);
    ASSERT_EQ(segments.size(), 60u);
    EXPECT_GT(spans, 0u);
    // The same segments as the streamed load's, bit for bit.
    std::size_t s = 0;
    for (const LoadEvent& e : a) {
        const auto* segment = std::get_if<SegmentMesh>(&e);
        if (!segment) continue;
        ASSERT_LT(s, segments.size());
        EXPECT_EQ(segment->index, segments[s]->index);
        ASSERT_EQ(segment->levels.size(), segments[s]->levels.size());
        for (std::size_t l = 0; l < segment->levels.size(); ++l) {
            EXPECT_EQ(segment->levels[l].positions, segments[s]->levels[l].positions);
            EXPECT_EQ(segment->levels[l].normals, segments[s]->levels[l].normals);
        }
        ++s;
    }
    EXPECT_EQ(s, 60u);
}

TEST(WellLoadPipelineTest, AWellSentAsGeometryOnlySendsItsWholeGeometryAndNoMesh) {
    const Sent streamed = loadSending(LoadSends::streamed),
               bare = loadSending(LoadSends::geometryOnly);
    const std::vector<LoadEvent>& a = streamed.events;
    const std::vector<LoadEvent>& b = bare.events;
    EXPECT_EQ(bare.readFraction, 1.0);
    // The whole geometry, then the end counting the well's segments: nothing between.
    ASSERT_EQ(b.size(), 2u);
    ASSERT_TRUE(std::holds_alternative<LoadStarted>(b.front()));
    ASSERT_TRUE(std::holds_alternative<LoadFinished>(b.back()));
    const WellGeometry& placed = geometrySent(b);
    const WellGeometry& reference = geometrySent(a);
    ASSERT_EQ(placed.table().rowCount(), reference.table().rowCount());
    EXPECT_EQ(placed.segmentCount(), 60u);
    EXPECT_EQ(std::get<LoadFinished>(b.back()).segments, 60u);
    EXPECT_EQ(std::get<LoadFinished>(a.back()).segments, 60u);
    for (std::size_t row = 0; row < placed.table().rowCount(); row += 997)
        EXPECT_EQ(placed.centre(row), reference.centre(row)) << row;
}

// A well the window loads beside others reads and is placed on one thread
// (LoadOptions::readThreads): the same well, bit for bit, as on two.
TEST(WellLoadPipelineTest, AWellReadAndPlacedOnOneThreadIsTheWellOnTwo) {
    LoadOptions one;
    one.readThreads = 1;
    for (const LoadSends sends : {LoadSends::geometryOnly, LoadSends::streamed}) {
        const Sent a = loadSending(sends), b = loadSending(sends, one);
        const WellGeometry& two = geometrySent(a.events);
        const WellGeometry& single = geometrySent(b.events);
        ASSERT_EQ(single.table().rowCount(), 24'001u);
        EXPECT_EQ(single.table().depth_m, two.table().depth_m);
        EXPECT_EQ(single.table().radius_mm, two.table().radius_mm);
        EXPECT_EQ(single.table().p1az_deg, two.table().p1az_deg);
        EXPECT_EQ(single.table().devi_deg, two.table().devi_deg);
        EXPECT_EQ(single.table().hazi_deg, two.table().hazi_deg);
        ASSERT_EQ(single.segmentCount(), two.segmentCount());
        for (std::size_t row = 0; row < single.table().rowCount(); ++row) {
            const PathPoint &p = single.path()[row], &q = two.path()[row];
            ASSERT_EQ(p.north, q.north) << row;
            ASSERT_EQ(p.east, q.east) << row;
            ASSERT_EQ(p.tvd, q.tvd) << row;
            ASSERT_EQ(p.dls_degPer30m, q.dls_degPer30m) << row;
        }
        EXPECT_EQ(std::get<LoadFinished>(b.events.back()).segments,
                  std::get<LoadFinished>(a.events.back()).segments);
    }
}

TEST(WellLoadPipelineTest, StreamsALogWithExtraCurves) {
    // Real logs carry gamma ray and the like beside the caliper: a stretch's remaining rows
    // carry them on into the next stretch.
    io::SectionTable table = makeSyntheticWell(syntheticProfile("example", 20.0, 0.0025));
    table.extraCurves.push_back({"GR", "gAPI", "gamma ray", {}});
    for (std::size_t r = 0; r < table.rowCount(); ++r)
        table.extraCurves[0].values.push_back(40.0 + static_cast<double>(r % 100));
    const auto file =
        test::scratch("pipeline_gr_" + std::to_string(static_cast<long>(::getpid())) + ".txt");
    io::writeColumnTextFile(file.string(), table);
    WellLoadPipeline pipeline(WellSource{file.string(), {}, {}, {}}, LoadOptions{}, Wellhead{});
    pipeline.start();
    const std::vector<LoadEvent> events = drainAll(pipeline);
    ASSERT_TRUE(std::holds_alternative<LoadFinished>(events.back()));
    EXPECT_EQ(std::get<LoadFinished>(events.back()).segments, 20u);
    std::shared_ptr<const WellGeometry> whole;
    std::size_t streamed = 0;
    for (const LoadEvent& e : events) {
        if (const auto* started = std::get_if<LoadStarted>(&e)) whole = started->geometry;
        if (const auto* segment = std::get_if<SegmentMesh>(&e); segment && !whole) {
            ++streamed;
            EXPECT_EQ(segment->firstRow, segment->index * 400);
        }
    }
    ASSERT_TRUE(whole);
    ASSERT_EQ(whole->table().extraCurves.size(), 1u);
    EXPECT_GE(streamed, 2u);
}

TEST(WellLoadPipelineTest, StreamsTheRealLogsAsTheirWholeWells) {
    // The window's load of each real log: every segment arrives, those streamed before the
    // whole geometry are its own bit for bit (skipped when ../shared/data is absent).
    CALIPER3D_REQUIRE_DATA(test::sharedData() / "real");
    for (const std::string& name : test::referenceLogs()) {
        SCOPED_TRACE(name);
        const auto file = test::sharedData() / name;
        if (!std::filesystem::exists(file)) continue;
        WellLoadPipeline pipeline(WellSource{file.string(), {}, {}, {}}, LoadOptions{}, Wellhead{});
        pipeline.start();
        const std::vector<LoadEvent> events = drainAll(pipeline);
        ASSERT_TRUE(std::holds_alternative<LoadFinished>(events.back()));
        std::shared_ptr<const WellGeometry> whole;
        std::vector<const SegmentMesh*> streamed;
        for (const LoadEvent& e : events) {
            if (const auto* started = std::get_if<LoadStarted>(&e)) whole = started->geometry;
            if (const auto* segment = std::get_if<SegmentMesh>(&e); segment && !whole)
                streamed.push_back(segment);
        }
        ASSERT_TRUE(whole);
        EXPECT_EQ(std::get<LoadFinished>(events.back()).segments, whole->segmentCount());
        for (const SegmentMesh* segment : streamed) {
            const SegmentMesh again = buildCoarseSegment(*whole, segment->index);
            ASSERT_EQ(again.levels.size(), segment->levels.size());
            for (std::size_t l = 0; l < again.levels.size(); ++l)
                EXPECT_EQ(again.levels[l].positions, segment->levels[l].positions)
                    << segment->index << "/" << l;
        }
    }
}

TEST(WellLoadPipelineTest, ACancelBeforeTheReadEndsStopsTheReadItself) {
    WellLoadPipeline pipeline(WellSource{wellFile(), {}, {}, {}}, LoadOptions{}, Wellhead{});
    pipeline.cancel();
    pipeline.start();
    const std::vector<LoadEvent> events = drainAll(pipeline);
    // The reader stopped at its first block: no geometry, no segment, nothing failed.
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(std::get<LoadFinished>(events.front()).segments, 0u);
}

TEST(WellLoadPipelineTest, OpeningAndCancellingHundredsOfTimesIsClean) {
    std::mt19937 random(7);
    std::uniform_int_distribution<int> delay_us(0, 4000);
    std::size_t stoppedInTheRead = 0, stoppedLater = 0;
    for (int i = 0; i < 200; ++i) {
        WellLoadPipeline pipeline(WellSource{wellFile(), {}, {}, {}}, LoadOptions{}, Wellhead{});
        pipeline.start();
        std::this_thread::sleep_for(std::chrono::microseconds(delay_us(random)));
        pipeline.cancel();
        const std::vector<LoadEvent> events = drainAll(pipeline);
        ASSERT_FALSE(std::holds_alternative<LoadFailed>(events.back())) << i;
        bool started = false;
        for (const LoadEvent& e : events)
            started = started || std::holds_alternative<LoadStarted>(e);
        if (started)
            ++stoppedLater;
        else
            ++stoppedInTheRead;
        // The destructor joins the worker here, every time.
    }
    EXPECT_EQ(stoppedInTheRead + stoppedLater, 200u);
    EXPECT_GT(stoppedInTheRead, 0u);
}

TEST(WellLoadPipelineTest, ALogSampledEveryDecimetreIsCutIntoTenMetreSegments) {
    // 4,001 rows 0.1 m apart: the automatic segment length is 100 rows, 10 m, the same for the
    // stretches streamed while reading and for the whole well.
    const auto file =
        test::scratch("pipeline_dm_" + std::to_string(static_cast<long>(::getpid())) + ".txt");
    io::writeColumnTextFile(file.string(),
                            makeSyntheticWell(syntheticProfile("example", 400.0, 0.1)));
    WellLoadPipeline pipeline(WellSource{file.string(), {}, {}, {}}, LoadOptions{}, Wellhead{});
    pipeline.start();
    const std::vector<LoadEvent> events = drainAll(pipeline);
    ASSERT_TRUE(std::holds_alternative<LoadFinished>(events.back()));
    std::shared_ptr<const WellGeometry> whole;
    std::vector<const SegmentMesh*> segments;
    for (const LoadEvent& e : events) {
        if (const auto* started = std::get_if<LoadStarted>(&e)) whole = started->geometry;
        if (const auto* segment = std::get_if<SegmentMesh>(&e)) segments.push_back(segment);
    }
    ASSERT_TRUE(whole);
    EXPECT_EQ(whole->options().segmentLength_m, 10.0);
    EXPECT_EQ(std::get<LoadFinished>(events.back()).segments, 40u);
    ASSERT_EQ(segments.size(), 40u);
    for (std::size_t s = 0; s < segments.size(); ++s) {
        EXPECT_EQ(segments[s]->index, s);
        EXPECT_EQ(segments[s]->firstRow, 100 * s);
        EXPECT_EQ(segments[s]->lastRow, 100 * (s + 1));
        EXPECT_EQ(segments[s]->firstRow, whole->segmentRows(s).first);
        EXPECT_EQ(segments[s]->lastRow, whole->segmentRows(s).second);
    }
}
