#include "io/median.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

using caliper3d::io::medianInPlace;

TEST(MedianTest, OddCountIsTheMiddleValue) {
    std::vector<double> v{5.0, 1.0, 3.0};
    EXPECT_EQ(medianInPlace(v), 3.0);
}

TEST(MedianTest, EvenCountIsTheUpperMiddleValueNeverAnAverage) {
    std::vector<double> v{4.0, 1.0, 2.0, 3.0};
    EXPECT_EQ(medianInPlace(v), 3.0);  // sorted 1 2 3 4: values[2]
}

TEST(MedianTest, EmptyHasNoMedian) {
    std::vector<double> v;
    EXPECT_TRUE(std::isnan(medianInPlace(v)));
}
