#include "io/units.h"

#include <gtest/gtest.h>

using namespace caliper3d::io;

TEST(UnitsTest, EveryUnitConvertsToMillimetresAndBack) {
    EXPECT_DOUBLE_EQ(toMillimetres(LengthUnit::Inch), 25.4);
    EXPECT_DOUBLE_EQ(toMillimetres(LengthUnit::Foot), 304.8);
    EXPECT_DOUBLE_EQ(toMillimetres(LengthUnit::Metre), 1000.0);
    EXPECT_DOUBLE_EQ(toMillimetres(LengthUnit::Centimetre), 10.0);
    EXPECT_DOUBLE_EQ(toMillimetres(LengthUnit::Millimetre), 1.0);
    EXPECT_DOUBLE_EQ(toMetres(LengthUnit::Foot), 0.3048);
    for (LengthUnit u : {LengthUnit::Metre, LengthUnit::Foot, LengthUnit::Inch,
                         LengthUnit::Millimetre, LengthUnit::Centimetre}) {
        EXPECT_EQ(parseLengthUnit(unitName(u)), u) << unitName(u);
    }
}

TEST(UnitsTest, ParsesHeaderSpellings) {
    EXPECT_EQ(parseLengthUnit("M"), LengthUnit::Metre);
    EXPECT_EQ(parseLengthUnit("F"), LengthUnit::Foot);
    EXPECT_EQ(parseLengthUnit("IN"), LengthUnit::Inch);
    EXPECT_EQ(parseLengthUnit("MM"), LengthUnit::Millimetre);
    EXPECT_FALSE(parseLengthUnit("furlong").has_value());
}
