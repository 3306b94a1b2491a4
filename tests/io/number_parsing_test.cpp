#include "io/number_parsing.h"

#include <gtest/gtest.h>

using caliper3d::io::parseNumber;

TEST(NumberParsingTest, ReadsDecimalPointAndDecimalComma) {
    double v = 0;
    ASSERT_TRUE(parseNumber("359.97920", v));
    EXPECT_DOUBLE_EQ(v, 359.9792);
    ASSERT_TRUE(parseNumber("359,98610", v));
    EXPECT_DOUBLE_EQ(v, 359.9861);
    ASSERT_TRUE(parseNumber("-1.5e3", v));
    EXPECT_DOUBLE_EQ(v, -1500.0);
    ASSERT_TRUE(parseNumber("+2", v));
    EXPECT_DOUBLE_EQ(v, 2.0);
}

TEST(NumberParsingTest, RejectsPartialAndAmbiguousTokens) {
    double v = 0;
    EXPECT_FALSE(parseNumber("", v));
    EXPECT_FALSE(parseNumber("12abc", v));
    EXPECT_FALSE(parseNumber("1,234.5", v));
    EXPECT_FALSE(parseNumber("1,2,3", v));
    EXPECT_FALSE(parseNumber("abc", v));
}
