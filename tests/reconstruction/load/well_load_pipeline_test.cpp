// The window's load worker: a cancel stops it, the read of the log included, and opening
// and cancelling loads over and over is clean (run under ThreadSanitizer by make tsan-test).
#include "reconstruction/load/well_load_pipeline.h"

#include <unistd.h>

#include <chrono>
#include <random>
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

}  // namespace

TEST(WellLoadPipelineTest, PreviewsTheTopThenLoadsTheWholeAndItsRemainingSegments) {
    WellLoadPipeline pipeline(WellSource{wellFile(), {}, {}}, LoadOptions{}, Wellhead{});
    pipeline.start();
    const std::vector<LoadEvent> events = drainAll(pipeline);
    // The first 4,096 rows (about 10 m) come first, then the whole well.
    ASSERT_TRUE(std::holds_alternative<LoadPreview>(events.front()));
    const auto& preview = std::get<LoadPreview>(events.front()).geometry;
    EXPECT_GE(preview->table().rowCount(), WellLoadPipeline::kPreviewRows);
    EXPECT_LT(preview->table().rowCount(), 24'001u);
    std::shared_ptr<const WellGeometry> whole;
    std::vector<const SegmentMesh*> segments;
    std::size_t beforeWhole = 0;
    for (const LoadEvent& e : events) {
        if (const auto* started = std::get_if<LoadStarted>(&e)) whole = started->geometry;
        if (const auto* segment = std::get_if<SegmentMesh>(&e)) {
            segments.push_back(segment);
            if (!whole) ++beforeWhole;
        }
    }
    ASSERT_TRUE(whole);
    EXPECT_EQ(beforeWhole, preview->segmentCount() - 1);             // its complete segments
    EXPECT_EQ(std::get<LoadFinished>(events.back()).segments, 60u);  // 1 m segments in all
    ASSERT_EQ(segments.size(), 60u);
    for (std::size_t s = 0; s < segments.size(); ++s) {
        EXPECT_EQ(segments[s]->index, s);
        EXPECT_EQ(segments[s]->firstLevel, kFirstCoarseLevel);  // finer ones near the camera
    }
    // The preview's segments are the whole well's, bit for bit.
    for (std::size_t s = 0; s < beforeWhole; ++s) {
        const SegmentMesh again = buildCoarseSegment(*whole, s);
        ASSERT_EQ(again.levels.size(), segments[s]->levels.size());
        for (std::size_t l = 0; l < again.levels.size(); ++l)
            EXPECT_EQ(again.levels[l].positions, segments[s]->levels[l].positions) << s << "/" << l;
    }
}

TEST(WellLoadPipelineTest, ACancelBeforeTheReadEndsStopsTheReadItself) {
    WellLoadPipeline pipeline(WellSource{wellFile(), {}, {}}, LoadOptions{}, Wellhead{});
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
        WellLoadPipeline pipeline(WellSource{wellFile(), {}, {}}, LoadOptions{}, Wellhead{});
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
