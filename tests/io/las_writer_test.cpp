#include "io/las_writer.h"

#include <cmath>
#include <sstream>

#include <gtest/gtest.h>

#include "io/las_reader.h"
#include "io/log_reader.h"

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
    for (int r = 0; r < 50; ++r) t.extraCurves[0].values.push_back(r % 5 == 0 ? kNaN : 40.0 + std::sqrt(r));
    return t;
}

void expectSame(const std::vector<double>& a, const std::vector<double>& b, const char* what) {
    ASSERT_EQ(a.size(), b.size()) << what;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (std::isnan(a[i])) EXPECT_TRUE(std::isnan(b[i])) << what << " " << i;
        else EXPECT_EQ(a[i], b[i]) << what << " " << i;  // exact, not near
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
