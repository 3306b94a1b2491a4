// Rows parked in a scratch file come back exactly as they were, under the curves of a table of
// the same log; a table with other curves is refused.
#include "io/parked_rows.h"

#include <cmath>
#include <cstring>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "io/section_table.h"

namespace caliper3d::io {
namespace {

// A table of `rows` rows with three arms, every optional curve but the relative bearing, two
// extra curves and a few NaN readings; its metadata set.
SectionTable table(std::size_t rows) {
    SectionTable t;
    t.source = "/logs/well-7.las";
    t.wellName = "WELL-7";
    t.fileDepthUnit = "FT";
    t.fileCaliperUnit = "IN";
    t.armCount = 3;
    t.holeAzimuth = SectionTable::HoleAzimuth::Derived;
    t.north = "grid";
    t.extraCurves.push_back({"GR", "gAPI", "gamma ray", {}});
    t.extraCurves.push_back({"RT", "ohmm", "resistivity", {}});
    for (std::size_t i = 0; i < rows; ++i) {
        const double x = static_cast<double>(i);
        t.depth_m.push_back(1000.0 + 0.0025 * x);
        for (int a = 0; a < 3; ++a) t.radius_mm.push_back(i % 97 == 5 ? kNaN : 108.0 + a + x / 7.0);
        t.p1az_deg.push_back(std::fmod(x * 0.37, 360.0));
        t.devi_deg.push_back(12.5 + x * 1e-6);
        t.hazi_deg.push_back(i % 50 == 0 ? kNaN : 210.25);
        t.bitSize_mm.push_back(215.9);
        t.extraCurves[0].values.push_back(40.0 + x / 3.0);
        t.extraCurves[1].values.push_back(i % 11 == 0 ? kNaN : 2.0 + x);
    }
    return t;
}

// Bit for bit: NaN readings included.
bool same(const std::vector<double>& a, const std::vector<double>& b) {
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

TEST(ParkedRowsTest, RowsComeBackBitForBitUnderTheCurvesOfASample) {
    const SectionTable whole = table(100000);
    const ParkedRows parked(whole);
    EXPECT_EQ(parked.rowCount(), 100000u);
    EXPECT_EQ(parked.bytes(), 100000u * (1 + 3 + 4 + 2) * sizeof(double));
    // The shape: a sample of the same log, as a field held lean keeps.
    SectionTable sample = whole.rows(0, 0);
    for (std::size_t row = 0; row < whole.rowCount(); row += 1000)
        sample.appendRows(whole, row, row + 1);
    // Read back from two threads at once, as the worker and the main thread may.
    SectionTable a, b;
    std::thread other([&] { a = parked.read(sample); });
    b = parked.read(sample);
    other.join();
    for (const SectionTable* back : {&a, &b}) {
        EXPECT_EQ(back->source, whole.source);
        EXPECT_EQ(back->wellName, "WELL-7");
        EXPECT_EQ(back->fileDepthUnit, "FT");
        EXPECT_EQ(back->armCount, 3);
        EXPECT_EQ(back->holeAzimuth, SectionTable::HoleAzimuth::Derived);
        EXPECT_EQ(back->north, "grid");
        EXPECT_TRUE(same(back->depth_m, whole.depth_m));
        EXPECT_TRUE(same(back->radius_mm, whole.radius_mm));
        EXPECT_TRUE(same(back->p1az_deg, whole.p1az_deg));
        EXPECT_TRUE(same(back->devi_deg, whole.devi_deg));
        EXPECT_TRUE(same(back->hazi_deg, whole.hazi_deg));
        EXPECT_TRUE(back->rb_deg.empty());
        EXPECT_TRUE(same(back->bitSize_mm, whole.bitSize_mm));
        ASSERT_EQ(back->extraCurves.size(), 2u);
        EXPECT_EQ(back->extraCurves[1].mnemonic, "RT");
        EXPECT_TRUE(same(back->extraCurves[0].values, whole.extraCurves[0].values));
        EXPECT_TRUE(same(back->extraCurves[1].values, whole.extraCurves[1].values));
    }
}

TEST(ParkedRowsTest, ATableOfOtherCurvesIsRefused) {
    const SectionTable whole = table(100);
    const ParkedRows parked(whole);
    SectionTable withBearing = whole;
    withBearing.rb_deg.assign(whole.rowCount(), 0.0);
    EXPECT_THROW(parked.read(withBearing), std::runtime_error);
    SectionTable lessExtra = whole;
    lessExtra.extraCurves.pop_back();
    EXPECT_THROW(parked.read(lessExtra), std::runtime_error);
    SectionTable otherArms = whole.rows(0, 2);
    otherArms.armCount = 4;
    EXPECT_THROW(parked.read(otherArms), std::runtime_error);
    // No rows at all: nothing to write, nothing to read.
    const SectionTable none = whole.rows(0, 0);
    const ParkedRows empty(none);
    EXPECT_EQ(empty.rowCount(), 0u);
    EXPECT_EQ(empty.read(none).rowCount(), 0u);
}

}  // namespace
}  // namespace caliper3d::io
