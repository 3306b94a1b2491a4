#include "io/las_writer.h"

#include <cmath>
#include <sstream>

#include <gtest/gtest.h>

#include "io/las_reader.h"
#include "io/log_reader.h"
#include "test_support.h"

using namespace caliper3d::io;

namespace {
SectionTable sample() {
    SectionTable t;
    t.armCount = 6;
    for (int r = 0; r < 50; ++r) {
        t.depth_m.push_back(1000.0 + 0.0025 * r);
        for (int k = 0; k < 6; ++k) t.radius_mm.push_back(107.95 + 0.1 * k + 1.0 / (r + 3.0));
        t.p1az_deg.push_back(std::fmod(359.98 + 7.3 * r, 360.0));
        t.devi_deg.push_back(0.5 + r / 7.0);
        t.hazi_deg.push_back(123.456789);
        t.rb_deg.push_back(10.0 / 3.0);
        t.bitSize_mm.push_back(215.9);
    }
    t.radius_mm[7] = kNaN;
    t.extraCurves.push_back({"GR", "GAPI", "gamma ray", {}});
    for (int r = 0; r < 50; ++r)
        t.extraCurves[0].values.push_back(r % 5 == 0 ? kNaN : 40.0 + std::sqrt(r));
    return t;
}

// The value of the header line that starts with `start` (" NULL.").
std::string itemValue(const std::string& text, const std::string& start) {
    const std::size_t at = text.find("\n" + start);
    if (at == std::string::npos) return "(absent)";
    std::istringstream line(
        text.substr(at + 1 + start.size(), text.find('\n', at + 1) - at - 1 - start.size()));
    std::string value;
    line >> value;
    return value;
}

void expectSame(const std::vector<double>& a, const std::vector<double>& b, const char* what) {
    ASSERT_EQ(a.size(), b.size()) << what;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (std::isnan(a[i]))
            EXPECT_TRUE(std::isnan(b[i])) << what << " " << i;
        else
            EXPECT_EQ(a[i], b[i]) << what << " " << i;  // exact, not near
    }
}
}  // namespace

TEST(LasWriterTest, ReaderReadsBackExactlyWhatWasWritten) {
    const SectionTable written = sample();
    std::ostringstream out;
    LasWriteOptions options;
    options.wellName = "ROUND-TRIP";
    writeLas(out, written, options);
    const LoadedLog read = loadCaliperText(out.str(), "rt.las", ReadOptions{});
    EXPECT_EQ(read.info.format, "LAS 2.0");
    EXPECT_EQ(read.info.wellName, "ROUND-TRIP");
    ASSERT_EQ(read.table.armCount, 6);
    expectSame(written.depth_m, read.table.depth_m, "depth");
    expectSame(written.radius_mm, read.table.radius_mm, "radii");
    expectSame(written.p1az_deg, read.table.p1az_deg, "p1az");
    expectSame(written.devi_deg, read.table.devi_deg, "devi");
    expectSame(written.hazi_deg, read.table.hazi_deg, "hazi");
    expectSame(written.rb_deg, read.table.rb_deg, "rb");
    expectSame(written.bitSize_mm, read.table.bitSize_mm, "bit size");
    ASSERT_EQ(read.table.extraCurves.size(), 1u);
    EXPECT_EQ(read.table.extraCurves[0].unit, "GAPI");
    expectSame(written.extraCurves[0].values, read.table.extraCurves[0].values, "GR");
    EXPECT_EQ(read.info.diagnostics.warningCount, 0u);
}

TEST(LasWriterTest, OptionalCurvesAbsentFromTheTableAreNotWritten) {
    SectionTable t;
    t.armCount = 3;
    t.depth_m = {1.0, 2.0};
    t.radius_mm = {1, 2, 3, 4, 5, 6};
    std::ostringstream out;
    writeLas(out, t);
    EXPECT_EQ(out.str().find("P1AZ"), std::string::npos);
    const LoadedLog read = loadCaliperText(out.str(), "min.las", ReadOptions{});
    EXPECT_TRUE(read.table.p1az_deg.empty());
    EXPECT_TRUE(read.table.bitSize_mm.empty());
    EXPECT_EQ(read.table.radius_mm, t.radius_mm);
}

TEST(LasWriterTest, ColumnsWithStrideDecimalsParametersAndOtherReadBack) {
    // Two rows of a row-major table of three values: a stride of 3 picks one column.
    const std::vector<double> depth = {10.0, 10.5};
    const std::vector<double> matrix = {1.23456, 2.0, 3.0, 4.5, 5.0, kNaN};
    LasWriteOptions options;
    options.wellName = "COLUMNS";
    options.parameters.push_back({"BS", "MM", "215.9", "bit size"});
    options.other = "free text about the curves";
    std::ostringstream out;
    writeLasColumns(out, 2,
                    {{"DEPT", "M", "depth", depth.data(), 1, -1},
                     {"A", "MM", "first of three", matrix.data(), 3, 2},
                     {"C", "MM", "third of three", matrix.data() + 2, 3, -1}},
                    options);
    const std::string text = out.str();
    EXPECT_NE(text.find("\n10 1.23 3\n"), std::string::npos) << text;
    EXPECT_NE(text.find("\n10.5 4.50 -999.25\n"), std::string::npos) << text;
    Diagnostics diagnostics;
    const LasLog log = readLas(text, "columns.las", {}, &diagnostics);
    ASSERT_EQ(log.curves.size(), 3u);
    EXPECT_EQ(log.curves[1].mnemonic, "A");
    EXPECT_EQ(log.curves[1].values, (std::vector<double>{1.23, 4.5}));
    EXPECT_EQ(log.curves[2].values[0], 3.0);
    EXPECT_TRUE(std::isnan(log.curves[2].values[1]));
    ASSERT_NE(log.header.parameter("BS"), nullptr);
    EXPECT_EQ(log.header.parameter("BS")->value, "215.9");
    EXPECT_NE(log.header.other.find("free text about the curves"), std::string::npos);
    EXPECT_EQ(log.header.wellItem("WELL")->value, "COLUMNS");
}

TEST(LasWriterTest, TrueValuesEqualToNullMarkersReadBackAsValues) {
    SectionTable t = sample();
    t.radius_mm[3] = -999.25;  // the preferred NULL: another is chosen
    t.extraCurves[0].values[1] =
        9999.0;  // common nulls, kept because the file declares its NULL only
    t.extraCurves[0].values[2] = -9999.0;
    t.extraCurves[0].values[3] = 999.25;
    std::ostringstream out;
    writeLas(out, t);
    EXPECT_EQ(itemValue(out.str(), " NULL."), "-9999.25") << "NULL not moved off -999.25";
    EXPECT_EQ(itemValue(out.str(), " NULLS."), "DECLARED");
    const LoadedLog read =
        loadCaliperText(out.str(), "nulls.las", ReadOptions{});  // default: common nulls
    expectSame(t.radius_mm, read.table.radius_mm, "radii");
    expectSame(t.extraCurves[0].values, read.table.extraCurves[0].values, "GR");
    EXPECT_EQ(read.table.radius_mm[3], -999.25);
    EXPECT_EQ(read.table.extraCurves[0].values[1], 9999.0);
    EXPECT_TRUE(std::isnan(read.table.extraCurves[0].values[0]));  // a true null stays null
}

TEST(LasWriterTest, StepIsNominalWhenRegularAndZeroWhenNot) {
    SectionTable t = sample();  // 0.0025 m steps
    auto stepOf = [](const SectionTable& table) {
        std::ostringstream out;
        writeLas(out, table);
        return itemValue(out.str(), " STEP.M");
    };
    EXPECT_EQ(stepOf(t), "0.0025");
    t.depth_m[10] += 0.001;
    EXPECT_EQ(stepOf(t), "0");
}

TEST(LasWriterTest, ADepthThatIsNotFiniteIsRefused) {
    SectionTable t = sample();
    t.depth_m[5] = kNaN;
    std::ostringstream out;
    EXPECT_THROW(writeLas(out, t), std::invalid_argument);
}

TEST(LasWriterTest, ALargeTableReadBackOnTwoThreadsInSmallBlocksIsExact) {
    SectionTable t;
    t.armCount = 8;
    for (int r = 0; r < 20000; ++r) {
        t.depth_m.push_back(250.0 + 0.0025 * r);
        for (int k = 0; k < 8; ++k)
            t.radius_mm.push_back(100.0 + std::sin(0.001 * r + k) * 7.0 + 1e-9 * r);
        t.rb_deg.push_back(std::fmod(0.37 * r, 360.0));
    }
    const auto path = caliper3d::test::scratch("round_trip_large.las");
    writeLasFile(path.string(), t);
    StreamOptions stream;
    stream.blockBytes = 64u << 10;
    stream.chunkRows = 100;
    const LoadedLog read = loadCaliperLog(path.string(), ReadOptions{}, stream);
    expectSame(t.depth_m, read.table.depth_m, "depth");
    expectSame(t.radius_mm, read.table.radius_mm, "radii");
    expectSame(t.rb_deg, read.table.rb_deg, "rb");
    EXPECT_TRUE(read.table.p1az_deg.empty());
}

// Each real log, read, written and read again, is the same table.
TEST(LasWriterTest, RealLogsRoundTripExactly) {
    const auto dir = caliper3d::test::sharedData();
    CALIPER3D_REQUIRE_DATA(dir / "real");
    for (const std::string& name : caliper3d::test::referenceLogs()) {
        SCOPED_TRACE(name);
        if (!std::filesystem::exists(dir / name)) continue;
        const LoadedLog first = loadCaliperLog((dir / name).string(), ReadOptions{});
        std::ostringstream out;
        writeLas(out, first.table);
        const LoadedLog second = loadCaliperText(out.str(), "again.las", ReadOptions{});
        ASSERT_EQ(second.table.armCount, first.table.armCount);
        expectSame(first.table.depth_m, second.table.depth_m, "depth");
        expectSame(first.table.radius_mm, second.table.radius_mm, "radii");
        expectSame(first.table.p1az_deg, second.table.p1az_deg, "p1az");
        expectSame(first.table.devi_deg, second.table.devi_deg, "devi");
        expectSame(first.table.hazi_deg, second.table.hazi_deg, "hazi");
        expectSame(first.table.rb_deg, second.table.rb_deg, "rb");
        expectSame(first.table.bitSize_mm, second.table.bitSize_mm, "bit size");
        ASSERT_EQ(second.table.extraCurves.size(), first.table.extraCurves.size());
        for (std::size_t e = 0; e < first.table.extraCurves.size(); ++e) {
            EXPECT_EQ(second.table.extraCurves[e].mnemonic, first.table.extraCurves[e].mnemonic);
            EXPECT_EQ(second.table.extraCurves[e].unit, first.table.extraCurves[e].unit);
            expectSame(first.table.extraCurves[e].values, second.table.extraCurves[e].values,
                       first.table.extraCurves[e].mnemonic.c_str());
        }
    }
}
