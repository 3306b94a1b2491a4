#include "reconstruction/analysis/borehole_classifier.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "support/reconstruction_support.h"

using namespace caliper3d::reconstruction;

namespace {
ClassifierInput section(double dmin, double dmax, double inc = 0.0, double fromHighSide = 90.0) {
    ClassifierInput s;
    s.dmin_mm = dmin;
    s.dmax_mm = dmax;
    s.bit_mm = 215.9;
    s.inc_deg = inc;
    s.majorFromHighSide_deg = fromHighSide;
    return s;
}
}  // namespace

TEST(BoreholeClassifierTest, ShapeClassesFollowTheDefaultThresholds) {
    const ClassificationRules r;
    EXPECT_EQ(classifyShape(section(214, 218), r), BoreholeClass::InGauge);
    EXPECT_EQ(classifyShape(section(200, 209.8), r), BoreholeClass::Undergauge);
    EXPECT_EQ(classifyShape(section(200, 210.0), r), BoreholeClass::InGauge);  // dmax = bit - 5.9
    EXPECT_EQ(classifyShape(section(228.7, 240), r), BoreholeClass::Washout);
    EXPECT_EQ(classifyShape(section(228.5, 240), r), BoreholeClass::Breakout);
    EXPECT_EQ(classifyShape(section(216, 221.8), r), BoreholeClass::InGauge);  // elongation < 6
    EXPECT_EQ(classifyShape(section(216, 240, 20.0, 10.0), r), BoreholeClass::Keyseat);
    EXPECT_EQ(classifyShape(section(216, 240, 20.0, 172.0), r),
              BoreholeClass::Keyseat);  // low side
    EXPECT_EQ(classifyShape(section(216, 240, 20.0, 30.0), r), BoreholeClass::Breakout);
    EXPECT_EQ(classifyShape(section(216, 240, 4.0, 10.0), r),
              BoreholeClass::Breakout);  // not deviated
    ClassifierInput unknown = section(216, 240);
    unknown.bit_mm = std::nan("");
    EXPECT_EQ(classifyShape(unknown, r), BoreholeClass::InGauge);
}

TEST(BoreholeClassifierTest, ThresholdsAreParameters) {
    ClassificationRules r;
    r.washout_mm = 30.0;
    EXPECT_EQ(classifyShape(section(240, 250), r), BoreholeClass::InGauge);
    r.breakoutMinGauge_mm = 30.0;
    EXPECT_EQ(classifyShape(section(240, 250), r), BoreholeClass::Breakout);
}

TEST(BoreholeClassifierTest, BreakoutRunShorterThanOneMetreIsNotABreakout) {
    std::vector<ClassifierInput> s;
    for (int i = 0; i < 100; ++i) {
        const bool elongated =
            (i >= 10 && i < 17) || (i >= 40 && i < 60);  // 0.7 m and 2.0 m at 0.1 m
        ClassifierInput c = elongated ? section(216, 240) : section(215, 216);
        c.md_m = 0.1 * i;
        c.toolAzimuth_deg = 0.0;
        s.push_back(c);
    }
    const auto classes = classifySections(s, ClassificationRules{});
    EXPECT_EQ(classes[12], BoreholeClass::InGauge);
    EXPECT_EQ(classes[50], BoreholeClass::Breakout);
    EXPECT_EQ(classes[40], BoreholeClass::Breakout);
    EXPECT_EQ(classes[59], BoreholeClass::Breakout);
}

TEST(BoreholeClassifierTest, RotatingToolRejectsABreakoutAcrossNorth) {
    std::vector<ClassifierInput> slow, fast;
    for (int i = 0; i < 100; ++i) {
        ClassifierInput c = section(216, 240);
        c.md_m = 0.1 * i;                                       // a 10 m zone
        c.toolAzimuth_deg = std::fmod(350.0 + 0.8 * i, 360.0);  // 40 deg per 5 m, wraps at north
        slow.push_back(c);
        c.toolAzimuth_deg = std::fmod(350.0 + 1.0 * i, 360.0);  // 50 deg per 5 m
        fast.push_back(c);
    }
    EXPECT_EQ(classifySections(slow, ClassificationRules{})[50], BoreholeClass::Breakout);
    EXPECT_EQ(classifySections(fast, ClassificationRules{})[50], BoreholeClass::InGauge);
}

TEST(BoreholeClassifierTest, ClassNamesAreTheReportNames) {
    EXPECT_EQ(className(BoreholeClass::InGauge), "in_gauge");
    EXPECT_EQ(className(BoreholeClass::Undergauge), "undergauge");
    EXPECT_EQ(className(BoreholeClass::Washout), "washout");
    EXPECT_EQ(className(BoreholeClass::Breakout), "breakout");
    EXPECT_EQ(className(BoreholeClass::Keyseat), "keyseat");
}
