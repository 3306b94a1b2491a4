// A table's rows taken as a table of their own keep every curve, extra ones included.
#include "io/section_table.h"

#include <vector>

#include <gtest/gtest.h>

using caliper3d::io::ExtraCurve;
using caliper3d::io::SectionTable;

TEST(SectionTableTest, RowsAsATableKeepEveryCurveAndOnlyThoseRows) {
    SectionTable t;
    t.source = "well.las";
    t.armCount = 2;
    t.holeAzimuth = SectionTable::HoleAzimuth::Derived;
    t.extraCurves.push_back({"GR", "gAPI", "gamma ray", {}});
    for (int i = 0; i < 5; ++i) {
        t.depth_m.push_back(100.0 + i);
        t.radius_mm.push_back(10.0 * i);
        t.radius_mm.push_back(10.0 * i + 1.0);
        t.devi_deg.push_back(i);
        t.extraCurves[0].values.push_back(50.0 + i);
    }
    const SectionTable tail = t.rows(3, 5);
    EXPECT_EQ(tail.source, "well.las");
    EXPECT_EQ(tail.armCount, 2);
    EXPECT_EQ(tail.holeAzimuth, SectionTable::HoleAzimuth::Derived);
    EXPECT_EQ(tail.depth_m, (std::vector<double>{103.0, 104.0}));
    EXPECT_EQ(tail.radius_mm, (std::vector<double>{30.0, 31.0, 40.0, 41.0}));
    EXPECT_EQ(tail.devi_deg, (std::vector<double>{3.0, 4.0}));
    EXPECT_TRUE(tail.p1az_deg.empty());  // a curve the log lacks stays absent
    ASSERT_EQ(tail.extraCurves.size(), 1u);
    EXPECT_EQ(tail.extraCurves[0].mnemonic, "GR");
    EXPECT_EQ(tail.extraCurves[0].unit, "gAPI");
    EXPECT_EQ(tail.extraCurves[0].values, (std::vector<double>{53.0, 54.0}));
    // The rest appends to it as to the table it came from.
    SectionTable more = tail;
    more.appendRows(t, 0, 1);
    EXPECT_EQ(more.extraCurves[0].values.back(), 50.0);
    EXPECT_EQ(t.rows(4, 99).rowCount(), 1u);  // clipped at the end
    EXPECT_EQ(t.rows(2, 2).rowCount(), 0u);
}
