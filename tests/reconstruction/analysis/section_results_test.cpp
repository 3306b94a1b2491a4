#include "reconstruction/analysis/section_results.h"

#include <cmath>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "test_support.h"

using namespace caliper3d;
using namespace caliper3d::reconstruction;

namespace {

// Three stations: vertical to 100 m, then leaning (TVD short of MD) at 110 m and 120 m.
std::shared_ptr<const std::vector<PathPoint>> leaningPath() {
    std::vector<PathPoint> path(3);
    path[0] = {100.0, 0.0, 0.0, 100.0, 0.0, 0.0, 0.0, 0.0};
    path[1] = {110.0, 0.5, 0.25, 109.98, 10.0, 30.0, 10.0, 30.0};
    path[2] = {120.0, 2.0, 1.0, 119.8, 20.0, 30.0, 10.0, 30.0};
    return std::make_shared<const std::vector<PathPoint>>(path);
}

SectionMeasure measure(double dmin_mm, BoreholeClass cls) {
    SectionMeasure m;
    m.bit_mm = 215.9;
    m.area_mm2 = 36000.0;
    m.equivalentDiameter_mm = 214.1;
    m.dmin_mm = dmin_mm;
    m.dmax_mm = 228.0;
    m.ellipticity = 228.0 / dmin_mm;
    m.majorAzimuth_deg = 135.0;
    m.majorFromHighSide_deg = 105.0;
    m.centreOffset_mm = 3.5;
    m.centreOffsetAzimuth_deg = 310.0;
    m.repairedArms = 2;
    m.cls = cls;
    return m;
}

}  // namespace

TEST(SectionResultsTest, EachRowIsItsPathPointAndItsMeasure) {
    const auto path = leaningPath();
    SectionResults results(path, true);
    ASSERT_EQ(results.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i)
        results.set(i, measure(200.0 + double(i),
                               i == 2 ? BoreholeClass::Breakout : BoreholeClass::InGauge));
    const SectionResult r = results[1];
    EXPECT_EQ(r.md_m, 110.0);
    EXPECT_EQ(r.north_m, 0.5);
    EXPECT_EQ(r.east_m, 0.25);
    EXPECT_EQ(r.tvd_m, 109.98);
    EXPECT_EQ(r.inc_deg, 10.0);
    EXPECT_EQ(r.azi_deg, 30.0);
    EXPECT_EQ(r.dls_degPer30m, 30.0);
    EXPECT_EQ(r.bit_mm, 215.9);
    EXPECT_EQ(r.area_mm2, 36000.0);
    // The measurements come back as stored, in single precision.
    EXPECT_EQ(r.equivalentDiameter_mm, static_cast<float>(214.1));
    EXPECT_EQ(r.dmin_mm, 201.0);
    EXPECT_EQ(r.dmax_mm, 228.0);
    EXPECT_EQ(r.ellipticity, static_cast<float>(228.0 / 201.0));
    EXPECT_NEAR(r.ellipticity, 228.0 / 201.0, test::storedInFloat(1.0));
    EXPECT_EQ(r.majorAzimuth_deg, 135.0);
    EXPECT_EQ(r.majorFromHighSide_deg, 105.0);
    EXPECT_EQ(r.centreOffset_mm, 3.5);
    EXPECT_EQ(r.centreOffsetAzimuth_deg, 310.0);
    EXPECT_EQ(r.repairedArms, 2);
    EXPECT_EQ(r.cls, BoreholeClass::InGauge);
    EXPECT_EQ(results.back().cls, BoreholeClass::Breakout);
    EXPECT_EQ(results.front().md_m, 100.0);
    EXPECT_EQ(results.md_m(2), 120.0);
    // A change to a row's measure is what the row reads next.
    results.measure(0).cls = BoreholeClass::NoData;
    EXPECT_EQ(results[0].cls, BoreholeClass::NoData);
    std::vector<double> dmin;
    for (const SectionResult& s : results) dmin.push_back(s.dmin_mm);
    EXPECT_EQ(dmin, (std::vector<double>{200.0, 201.0, 202.0}));
}

TEST(SectionResultsTest, WithoutAHoleAzimuthNoAzimuthAndNoDepartureWhereThePathLeaned) {
    const auto path = leaningPath();
    SectionResults results(path, false);
    for (std::size_t i = 0; i < 3; ++i) results.set(i, measure(200.0, BoreholeClass::InGauge));
    // Vertical so far: no departure to know, so north and east stay 0; the azimuth is unknown.
    EXPECT_EQ(results[0].north_m, 0.0);
    EXPECT_EQ(results[0].east_m, 0.0);
    EXPECT_TRUE(std::isnan(results[0].azi_deg));
    for (std::size_t i = 1; i < 3; ++i) {
        const SectionResult r = results[i];
        EXPECT_TRUE(std::isnan(r.north_m)) << i;
        EXPECT_TRUE(std::isnan(r.east_m)) << i;
        EXPECT_TRUE(std::isnan(r.azi_deg)) << i;
        EXPECT_EQ(r.tvd_m, (*path)[i].tvd) << i;  // TVD and inclination are known
        EXPECT_EQ(r.inc_deg, (*path)[i].inc_deg) << i;
    }
}
