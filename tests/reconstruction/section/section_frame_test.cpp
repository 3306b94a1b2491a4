#include "reconstruction/section/section_frame.h"

#include <cmath>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>

using namespace caliper3d::reconstruction;

namespace {
void expectOrthonormal(const SectionFrame& f) {
    EXPECT_NEAR(glm::length(f.arm1), 1.0, 1e-12);
    EXPECT_NEAR(glm::length(f.side), 1.0, 1e-12);
    EXPECT_NEAR(glm::dot(f.arm1, f.tangent), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(f.side, f.tangent), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(f.arm1, f.side), 0.0, 1e-12);
}
double horizontalAzimuth(const Ned& v) {
    double a = glm::degrees(std::atan2(v.y, v.x));
    return a < 0 ? a + 360.0 : a;
}
}  // namespace

TEST(SectionFrameTest, VerticalHoleArmOneAtPadAzimuthAndClockwise) {
    const SectionFrame f = frameFromPadAzimuth(0.0, 0.0, 30.0);
    expectOrthonormal(f);
    EXPECT_NEAR(horizontalAzimuth(f.arm1), 30.0, 1e-9);
    // 90 degrees clockwise seen from above is azimuth 120.
    EXPECT_NEAR(horizontalAzimuth(f.side), 120.0, 1e-9);
    EXPECT_NEAR(horizontalAzimuth(f.direction(glm::radians(60.0))), 90.0, 1e-9);
}

TEST(SectionFrameTest, DeviatedHoleKeepsPadAzimuthInProjection) {
    for (double p1az : {0.0, 45.0, 200.0, 300.0}) {
        const SectionFrame f = frameFromPadAzimuth(40.0, 120.0, p1az);
        expectOrthonormal(f);
        EXPECT_NEAR(horizontalAzimuth(f.arm1), p1az, 1e-9);
    }
}

TEST(SectionFrameTest, RelativeBearingZeroIsHighSideNinetyIsRight) {
    // Hole inclined 30 degrees towards north: the high side leans back south and up.
    const SectionFrame f = frameFromRelativeBearing(30.0, 0.0, 0.0);
    expectOrthonormal(f);
    EXPECT_LT(f.arm1.z, 0.0);           // points up
    EXPECT_NEAR(f.arm1.y, 0.0, 1e-12);  // in the vertical plane of the hole
    EXPECT_NEAR(f.arm1.x, std::cos(glm::radians(30.0)), 1e-12);
    // RB 90: clockwise looking down a north-going hole is east.
    const SectionFrame g = frameFromRelativeBearing(30.0, 0.0, 90.0);
    EXPECT_NEAR(g.arm1.y, 1.0, 1e-12);
}

TEST(SectionFrameTest, PadAzimuthEqualsHoleAzimuthPlusRelativeBearingWhenSteep) {
    // In an inclined hole, arm 1 at high side has horizontal azimuth = hole azimuth.
    const SectionFrame hs = frameFromRelativeBearing(25.0, 70.0, 0.0);
    const SectionFrame p = frameFromPadAzimuth(25.0, 70.0, 70.0);
    EXPECT_NEAR(glm::length(hs.arm1 - p.arm1), 0.0, 1e-9);
}

TEST(SectionFrameTest, SceneFrameIsEastUpSouth) {
    const glm::dvec3 north = toScene({1, 0, 0}), east = toScene({0, 1, 0}),
                     down = toScene({0, 0, 1});
    EXPECT_EQ(north, glm::dvec3(0, 0, -1));
    EXPECT_EQ(east, glm::dvec3(1, 0, 0));
    EXPECT_EQ(down, glm::dvec3(0, -1, 0));
    // Right-handed: east x up = south.
    EXPECT_EQ(glm::cross(east, -down), -north);
}

TEST(SectionFrameTest, FramesFromSinesAndCosinesAreTheFramesFromAngles) {
    auto expectSame = [](const SectionFrame& a, const SectionFrame& b) {
        EXPECT_EQ(a.tangent, b.tangent);
        EXPECT_EQ(a.arm1, b.arm1);
        EXPECT_EQ(a.side, b.side);
    };
    for (double inc : {0.0, 3.0, 45.0, 89.99999, 90.0}) {
        const HoleDirection d(inc, 123.4);
        expectSame(frameFromPadAzimuth(d, 271.3), frameFromPadAzimuth(inc, 123.4, 271.3));
        expectSame(frameFromRelativeBearing(d, 33.0), frameFromRelativeBearing(inc, 123.4, 33.0));
        EXPECT_EQ(highSide(d), highSide(inc, 123.4));
        EXPECT_EQ(holeTangent(d), holeTangent(inc, 123.4));
    }
}
