// Analysis of the real logs in ../shared/data/real (skipped when absent).
#include <algorithm>
#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>

#include <gtest/gtest.h>

#include "io/log_reader.h"
#include "reconstruction/analysis/well_analysis.h"
#include "reconstruction/section/section_analysis.h"
#include "test_support.h"

using namespace caliper3d;
using namespace caliper3d::reconstruction;

namespace {
WellAnalysis analyseFile(const std::filesystem::path& file,
                         std::shared_ptr<const io::SectionTable>* keep = nullptr) {
    io::Diagnostics diagnostics;
    auto table = std::make_shared<const io::SectionTable>(
        io::readCaliperLog(file.string(), io::ReadOptions{}, &diagnostics));
    if (keep) *keep = table;
    const WellGeometry geometry(table, GeometryOptions{});
    return analyseWell(geometry, AnalysisOptions{});
}
}  // namespace

TEST(RealDataTest, BakerStarOpenHoleIsNearBitSizeWithFewBreakouts) {
    const auto file = test::sharedData() / "real" / "1AA072209208W400_WL_0477502_STAR_FIELD.las";
    CALIPER3D_REQUIRE_DATA(file);
    const WellAnalysis a = analyseFile(file);
    // Casing bottom 49.4 m (CBLO): the open hole is below it.
    std::vector<double> d;
    std::size_t breakouts = 0;
    for (const SectionResult& r : a.sections) {
        if (r.md_m < 50.0) continue;
        d.push_back(r.equivalentDiameter_mm);
        breakouts += r.cls == BoreholeClass::Breakout ? 1 : 0;
    }
    ASSERT_GT(d.size(), 1000u);
    std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2), d.end());
    EXPECT_NEAR(d[d.size() / 2], 156.0, 5.0);
    EXPECT_LT(static_cast<double>(breakouts) / static_cast<double>(d.size()), 0.05);
}

TEST(RealDataTest, FmiFourArmRunsEndToEndWithPadAzimuthAgreeingWithHoleAzimuthPlusBearing) {
    const auto file = test::sharedData() / "real" / "1AA063409108W400_FMI_SONIC_MAIN.las";
    CALIPER3D_REQUIRE_DATA(file);
    std::shared_ptr<const io::SectionTable> table;
    const WellAnalysis a = analyseFile(file, &table);
    EXPECT_EQ(table->armCount, 4);
    EXPECT_EQ(a.sections.size(), table->rowCount());
    ASSERT_GT(a.padAzimuthOffset.samples, 100u);
    EXPECT_NEAR(a.padAzimuthOffset.mean_deg, 0.0, 1.5);
    EXPECT_LT(a.padAzimuthOffset.sd_deg, 1.5);
}

TEST(RealDataTest, FortyFingerPipeIsTwoHundredFiftyFourMillimetresWithTheToolOffCentre) {
    const auto file = test::sharedData() / "real" / "multifinger40_data.txt";
    CALIPER3D_REQUIRE_DATA(file);
    std::ifstream in(file);
    std::string line;
    const SectionAnalyzer analyzer(40, 48);
    std::vector<double> sampled(48), offsets, diameters;
    while (std::getline(in, line)) {
        std::istringstream fields(line);
        std::vector<double> r;
        double v;
        while (fields >> v) r.push_back(v);
        if (r.size() != 40) continue;
        const SectionShape s = analyzer.analyse(r.data(), sampled.data());
        offsets.push_back(s.centreOffset_mm);
        diameters.push_back((s.dmax_mm + s.dmin_mm) / 2.0);
    }
    ASSERT_EQ(offsets.size(), 201u);
    // The tool stays 15.5 mm off the pipe axis on every row.
    for (double o : offsets) {
        EXPECT_NEAR(o, 15.5, 0.5);
    }
    // The pipe is 254 mm at both ends; the data set swells it to about 306 mm
    // half-way (a simulated bulge), which the fit must follow.
    EXPECT_NEAR(diameters.front(), 254.0, 3.0);
    EXPECT_NEAR(diameters.back(), 254.0, 3.0);
    EXPECT_NEAR(*std::max_element(diameters.begin(), diameters.end()), 306.0, 3.0);
}
