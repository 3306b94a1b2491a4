#include "reconstruction/section/section_analysis.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "reconstruction/synthetic/synthetic_well.h"

using namespace caliper3d::reconstruction;

TEST(SectionAnalysisTest, CircleOfBitSizeHasItsAreaAndDiameter) {
    const SectionAnalyzer analyzer(6, 48);
    const std::vector<double> pads(6, 107.95);
    std::vector<double> sampled(48);
    const SectionShape s = analyzer.analyse(pads.data(), sampled.data());
    // The 48-gon inscribed in the circle: area = 24 r^2 sin(2 pi / 48).
    EXPECT_NEAR(s.area_mm2, 24.0 * 107.95 * 107.95 * std::sin(2 * M_PI / 48), 1e-6);
    EXPECT_NEAR(s.equivalentDiameter_mm, 215.9 * std::sqrt(24.0 / M_PI * std::sin(2 * M_PI / 48)),
                1e-9);
    EXPECT_NEAR(s.dmax_mm, 215.9, 1e-6);
    EXPECT_NEAR(s.dmin_mm, 215.9, 1e-6);
    EXPECT_NEAR(s.centreOffset_mm, 0.0, 1e-9);
    EXPECT_TRUE(s.ellipseFitted);
}

TEST(SectionAnalysisTest, ManyFingersOnAnEllipseGiveItsAxesAndAngle) {
    const int n = 40;
    std::vector<double> pads(n);
    for (int k = 0; k < n; ++k) pads[k] = ellipseRadius_mm(250.0, 220.0, 360.0 * k / n - 30.0);
    const SectionAnalyzer analyzer(n, 48);
    std::vector<double> sampled(48);
    const SectionShape s = analyzer.analyse(pads.data(), sampled.data());
    EXPECT_NEAR(s.dmax_mm, 250.0, 0.2);
    EXPECT_NEAR(s.dmin_mm, 220.0, 0.2);
    EXPECT_NEAR(s.majorAngle_deg, 30.0, 0.2);
    EXPECT_NEAR(s.ellipticity, 250.0 / 220.0, 0.002);
}

TEST(SectionAnalysisTest, OffCentreToolGivesTheOffsetOfTheHoleCentre) {
    // Circle of radius 127 whose centre is 15.5 mm along arm 1 from the tool.
    const int n = 40;
    std::vector<double> pads(n);
    for (int k = 0; k < n; ++k) {
        const double phi = 2 * M_PI * k / n, c = 15.5;
        pads[k] =
            c * std::cos(phi) + std::sqrt(127.0 * 127.0 - c * c * std::sin(phi) * std::sin(phi));
    }
    const SectionAnalyzer analyzer(n, 48);
    std::vector<double> sampled(48);
    const SectionShape s = analyzer.analyse(pads.data(), sampled.data());
    EXPECT_NEAR(s.centreOffset_mm, 15.5, 0.1);
    EXPECT_NEAR(s.centroidV_mm, 0.0, 1e-6);
    EXPECT_NEAR(s.dmax_mm, 254.0, 0.3);
    EXPECT_NEAR(s.dmin_mm, 254.0, 0.3);
}

TEST(SectionAnalysisTest, InPlaneAzimuthIsTheHorizontalProjectionAndUndefinedWhenVertical) {
    const SectionFrame vertical = frameFromPadAzimuth(0.0, 0.0, 40.0);
    EXPECT_NEAR(inPlaneAzimuth_deg(vertical, 90.0), 130.0, 1e-9);
    const SectionFrame horizontal = frameFromRelativeBearing(90.0, 0.0, 0.0);  // arm 1 points up
    EXPECT_TRUE(std::isnan(inPlaneAzimuth_deg(horizontal, 0.0)));
    EXPECT_NEAR(inPlaneAzimuth_deg(horizontal, 90.0), 90.0, 1e-9);  // right of a north hole: east
    EXPECT_NEAR(angleFromHighSide_deg(horizontal, 90.0, 0.0, 90.0), 90.0, 1e-9);
}
