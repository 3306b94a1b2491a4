#include <memory>
#include <stdexcept>

#include <gtest/gtest.h>

#include "reconstruction/synthetic/synthetic_well.h"
#include "reconstruction/well_geometry.h"
#include "reconstruction/well_interval.h"

namespace caliper3d::reconstruction {
namespace {

TEST(WellIntervalTest, HoldsTheRowsInTheIntervalPlacedAsInTheWholeWell) {
    // A build from 100 m: rows deep in the interval lie off the vertical, where a log that
    // started there would be tied in from the surface instead.
    auto table = std::make_shared<const io::SectionTable>(
        makeSyntheticWell(syntheticProfile("example", 300.0, 0.1)));
    const WellGeometry whole(table, GeometryOptions{});
    GeometryOptions options = whole.options();
    options.radialExaggeration = 20.0;
    const auto part = intervalGeometry(whole, 150.0, 200.0, options);
    const auto& depth = part->table().depth_m;
    ASSERT_EQ(part->table().rowCount(), 501u);
    EXPECT_NEAR(depth.front(), 150.0, 1e-9);
    EXPECT_NEAR(depth.back(), 200.0, 1e-9);
    EXPECT_DOUBLE_EQ(part->options().radialExaggeration, 20.0);
    const std::size_t offset = 1500;  // row of 150 m in the whole well
    ASSERT_NEAR(table->depth_m[offset], 150.0, 1e-9);
    for (std::size_t row = 0; row < depth.size(); row += 50) {
        const Ned a = part->centre(row), b = whole.centre(row + offset);
        EXPECT_DOUBLE_EQ(a.x, b.x) << "row " << row;
        EXPECT_DOUBLE_EQ(a.y, b.y) << "row " << row;
        EXPECT_DOUBLE_EQ(a.z, b.z) << "row " << row;
    }
    // Its segments start at the interval's top.
    EXPECT_EQ(part->segmentRows(0).first, 0u);
    EXPECT_EQ(part->segmentCount(), 50u);
}

TEST(WellIntervalTest, RefusesAnIntervalWithFewerThanTwoRows) {
    auto table = std::make_shared<const io::SectionTable>(
        makeSyntheticWell(syntheticProfile("circle", 10.0, 0.5)));
    const WellGeometry whole(table, GeometryOptions{});
    EXPECT_THROW(intervalGeometry(whole, 2.1, 2.4, whole.options()), std::invalid_argument);
}

}  // namespace
}  // namespace caliper3d::reconstruction
