#include "io/log_stream.h"

#include <atomic>
#include <cmath>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "io/log_reader.h"
#include "io/parse_error.h"
#include "io/stream/text_source.h"

using namespace caliper3d::io;

namespace {
// Reference column text, `rows` lines of about 80 bytes.
std::string columnText(std::size_t rows) {
    std::string text;
    for (std::size_t r = 0; r < rows; ++r) {
        text += std::to_string(1000.0 + 0.0025 * static_cast<double>(r));
        for (int k = 0; k < 6; ++k) text += " " + std::to_string(4.25 + 0.01 * k);
        text += " 12.5 0.75 33.0\n";
    }
    return text;
}

StreamOptions smallBlocks() {
    StreamOptions s;
    s.blockBytes = 300u << 10;  // several blocks, each split between two threads
    s.chunkRows = 1000;
    return s;
}
}  // namespace

TEST(LogStreamTest, ChunksArriveInDepthOrderAndMatchASingleThreadRead) {
    const std::string text = columnText(20000);
    std::vector<std::size_t> sizes;
    std::vector<double> depths;
    const LogInfo info = streamCaliperText(
        text, "s.txt", ReadOptions{},
        [&](const SectionTable& chunk) {
            sizes.push_back(chunk.rowCount());
            depths.insert(depths.end(), chunk.depth_m.begin(), chunk.depth_m.end());
        },
        smallBlocks());
    EXPECT_EQ(info.rows, 20000u);
    ASSERT_GT(sizes.size(), 3u);
    for (std::size_t i = 0; i + 1 < sizes.size(); ++i) EXPECT_GE(sizes[i], 1000u);
    for (std::size_t i = 1; i < depths.size(); ++i) ASSERT_LT(depths[i - 1], depths[i]) << i;
    StreamOptions single;
    single.threads = 1;
    const LoadedLog reference = loadCaliperText(text, "s.txt", ReadOptions{}, single);
    EXPECT_EQ(reference.table.depth_m, depths);
    EXPECT_NEAR(info.step_m, 0.0025, 1e-9);
}

TEST(LogStreamTest, AnErrorLateInASplitBlockNamesItsExactLine) {
    std::string text = columnText(12000);
    // Spoil line 11500 (in the second half of a block).
    std::size_t at = 0;
    for (int line = 1; line < 11500; ++line) at = text.find('\n', at) + 1;
    text.replace(at, 4, "1x00");
    try {
        loadCaliperText(text, "bad.txt", ReadOptions{}, smallBlocks());
        FAIL();
    } catch (const ParseError& e) {
        EXPECT_EQ(e.line(), 11500u);
        EXPECT_EQ(e.column(), 1u);
        EXPECT_NE(std::string(e.what()).find("expected a number for depth, found '1x00"),
                  std::string::npos)
            << e.what();
    }
}

TEST(LogStreamTest, CancellationFromTheConsumerStopsTheRead) {
    const std::string text = columnText(20000);
    std::atomic<bool> cancel{false};
    StreamOptions s = smallBlocks();
    s.cancel = &cancel;
    std::size_t rows = 0;
    const LogInfo info = streamCaliperText(
        text, "c.txt", ReadOptions{},
        [&](const SectionTable& chunk) {
            rows += chunk.rowCount();
            cancel = true;
        },
        s);
    EXPECT_TRUE(info.cancelled);
    EXPECT_GT(rows, 0u);
    EXPECT_LT(rows, 20000u);
    EXPECT_THROW(loadCaliperText(text, "c.txt", ReadOptions{}, s), ReadCancelled);
}

TEST(LogStreamTest, CancellationFromAnotherThreadStopsTheRead) {
    // The reader's consumer waits, after its first chunk, until a second thread
    // (a window's "stop" button, say) has set the flag; the read then ends there.
    const std::string text = columnText(20000);
    std::atomic<bool> cancel{false}, firstChunk{false};
    StreamOptions s = smallBlocks();
    s.cancel = &cancel;
    std::thread stopper([&] {
        while (!firstChunk.load()) std::this_thread::yield();
        cancel.store(true);
    });
    std::size_t rows = 0;
    const LogInfo info = streamCaliperText(
        text, "t.txt", ReadOptions{},
        [&](const SectionTable& chunk) {
            rows += chunk.rowCount();
            firstChunk.store(true);
            while (!cancel.load()) std::this_thread::yield();
        },
        s);
    stopper.join();
    EXPECT_TRUE(info.cancelled);
    EXPECT_GT(rows, 0u);
    EXPECT_LT(rows, 20000u);
}

TEST(LogStreamTest, OnStartReportsRolesAndARowEstimateBeforeData) {
    const std::string text = columnText(5000);
    StreamOptions s;
    std::size_t estimate = 0;
    int arms = 0;
    s.onStart = [&](const LogInfo& info, std::size_t rows) {
        estimate = rows;
        arms = static_cast<int>(info.curves.size());
    };
    streamCaliperText(
        text, "e.txt", ReadOptions{}, [](const SectionTable&) {}, s);
    EXPECT_EQ(arms, 10);
    EXPECT_GE(estimate, 5000u);
    EXPECT_LT(estimate, 5300u);
}

TEST(LogStreamTest, BackwardRowsInADownwardLogAreSkippedOrRejected) {
    const std::string text =
        "1.0 1 1 1 1 1 1 0 0 0\n2.0 1 1 1 1 1 1 0 0 0\n1.5 1 1 1 1 1 1 0 0 0\n3.0 1 1 1 1 1 1 0 0 "
        "0\n";
    const LoadedLog log = loadCaliperText(text, "b.txt", ReadOptions{});
    EXPECT_EQ(log.table.depth_m, (std::vector<double>{1.0, 2.0, 3.0}));
    ReadOptions reject;
    reject.depthOrder = DepthOrder::Reject;
    try {
        loadCaliperText(text, "b.txt", reject);
        FAIL();
    } catch (const ParseError& e) {
        EXPECT_EQ(e.line(), 3u);
    }
}

TEST(LogStreamTest, TruncatedLastLineIsCountedAndSkipped) {
    const std::string text = "1.0 1 1 1 1 1 1 0 0 0\n2.0 1 1 1 1 1 1 0 0 0\n3.0 1 1 1";
    const LoadedLog log = loadCaliperText(text, "t.txt", ReadOptions{});
    EXPECT_EQ(log.table.rowCount(), 2u);
    EXPECT_EQ(log.info.diagnostics.warningCount, 1u);
    EXPECT_EQ(log.info.diagnostics.warnings[0].line, 3u);
}

TEST(LogStreamTest, AnUpwardLogWhoseFirstTwoRowsGoDownIsStillSortedWhole) {
    // The first pair increases (a glitch); the log as a whole was recorded upwards.
    std::string text = "100.0 1 1 1 1 1 1 0 0 0\n100.5 1 1 1 1 1 1 0 0 0\n";
    for (int r = 1; r <= 40; ++r) text += std::to_string(100.0 - 0.25 * r) + " 1 1 1 1 1 1 0 0 0\n";
    const LoadedLog log = loadCaliperText(text, "up.txt", ReadOptions{});
    ASSERT_EQ(log.table.rowCount(), 42u);
    EXPECT_DOUBLE_EQ(log.table.depth_m.front(), 90.0);
    EXPECT_DOUBLE_EQ(log.table.depth_m.back(), 100.5);
    for (std::size_t i = 1; i < log.table.rowCount(); ++i)
        ASSERT_LT(log.table.depth_m[i - 1], log.table.depth_m[i]);
    bool warned = false;
    for (const Warning& w : log.info.diagnostics.warnings)
        warned = warned || w.message.find("log recorded upwards with 1 rows out of order") !=
                               std::string::npos;
    EXPECT_TRUE(warned);
}

namespace {
// The runs a BlockReader hands out for `text`, checked to end at line ends but the last.
std::string readInRuns(const std::string& text, std::size_t blockBytes, std::size_t& runs) {
    MemorySource source(text);
    BlockReader reader(source, blockBytes);
    std::string out;
    runs = 0;
    while (!reader.done()) {
        const std::string_view run = reader.next();
        ++runs;
        if (!reader.done()) {
            EXPECT_EQ(run.back(), '\n') << "run " << runs;
        }
        out += run;
    }
    return out;
}
}  // namespace

TEST(LogStreamTest, ABlockKeptForTheNextFileOnItsThreadReadsThatFileExactly) {
    // One thread reads, in turn: a text of many blocks, a short one, one whose line is longer
    // than a block (the block grows), and the first again. Each block is the last one's kept
    // (text_source.cpp), so what a file leaves in it must never show in the next.
    const std::string many = columnText(500);  // about 40 kB: ten blocks of 4 kB
    const std::string shortText = "1000.0 1 2 3\n1000.5 1 2 3";
    const std::string longLine = std::string(10000, '7') + "\n" + many.substr(0, 800);
    std::thread reader([&] {
        std::size_t runs = 0;
        EXPECT_EQ(readInRuns(many, 4096, runs), many);
        EXPECT_GE(runs, 9u);
        EXPECT_EQ(readInRuns(shortText, 4096, runs), shortText);
        EXPECT_EQ(runs, 1u);
        EXPECT_EQ(readInRuns(longLine, 4096, runs), longLine);
        EXPECT_EQ(readInRuns(many, 4096, runs), many);
        EXPECT_GE(runs, 9u);
        EXPECT_EQ(readInRuns(shortText, 4096, runs), shortText);
    });
    reader.join();
}
