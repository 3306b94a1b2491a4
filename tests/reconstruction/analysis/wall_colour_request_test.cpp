#include "reconstruction/analysis/wall_colour_request.h"

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "reconstruction/synthetic/synthetic_well.h"

using namespace caliper3d::reconstruction;
using caliper3d::io::SectionTable;

namespace {

std::shared_ptr<const WellGeometry> wellOf(SectionTable table) {
    return std::make_shared<const WellGeometry>(
        std::make_shared<const SectionTable>(std::move(table)), GeometryOptions{});
}

std::shared_ptr<const WellGeometry> profile(const std::string& name, double length = 40.0) {
    return wellOf(makeSyntheticWell(syntheticProfile(name, length, 0.1)));
}

ColourRequest by(const std::string& quantity) {
    ColourRequest r;
    r.quantity = quantity;
    return r;
}

// The equivalent diameter of a circle of diameter d as analysed: the area of the 48-point
// polygon inscribed in it (docs/analysis.md).
double sampledDiameter(double d) {
    const double n = 48.0, pi = 3.14159265358979323846;
    return d * std::sqrt(n * std::sin(2.0 * pi / n) / (2.0 * pi));
}

// The first row at or below `md`.
std::size_t rowAt(const WellGeometry& g, double md) {
    const auto& d = g.table().depth_m;
    return static_cast<std::size_t>(std::lower_bound(d.begin(), d.end(), md) - d.begin());
}

}  // namespace

// "washout": a 255.9 mm circle over 16-24 m of a 215.9 mm hole: its wall is 20 mm out.
TEST(WallColourRequestTest, DepartureIsFromTheBitSizeOverAFixedRange) {
    const auto g = profile("washout");
    const auto c = makeWallColouring(*g, by("departure"));
    EXPECT_EQ(c->legend().title, "radius - bit radius");
    EXPECT_EQ(c->legend().unit, "mm");
    EXPECT_EQ(c->legend().lo, -kDepartureRange_mm);
    EXPECT_EQ(c->legend().hi, kDepartureRange_mm);
    EXPECT_EQ(c->legend().range, "fixed");
    EXPECT_TRUE(c->legend().note.empty());
    const std::size_t gauge = rowAt(*g, 5.0), washout = rowAt(*g, 20.0);
    EXPECT_EQ(c->colour(gauge, 215.9 / 2), divergingColour(0.5));
    EXPECT_EQ(c->colour(washout, 255.9 / 2), divergingColour(0.5 + 0.5 * 20.0 / 25.0));
}

TEST(WallColourRequestTest, DiameterIsTheReportsOverIts2To98Percentile) {
    const auto g = profile("washout");
    const WellAnalysis a = analyseWell(*g, {});
    const auto c = makeWallColouring(*g, by("Diameter"));  // names in any case
    EXPECT_EQ(c->legend().title, "equivalent diameter");
    EXPECT_EQ(c->legend().kind, ColourMapKind::Sequential);
    EXPECT_EQ(c->legend().range, "2-98 percentile");
    // A fifth of the well is the washout: the 2nd percentile is the gauge hole, the 98th
    // the washout.
    EXPECT_NEAR(c->legend().lo, sampledDiameter(215.9), 0.01);
    EXPECT_NEAR(c->legend().hi, sampledDiameter(255.9), 0.01);
    for (std::size_t row = 0; row < g->table().rowCount(); row += 37) {
        const double ed = a.sections[row].equivalentDiameter_mm;
        EXPECT_EQ(c->colour(row, 0.0),
                  sequentialColour(mapPosition(ColourMapKind::Sequential, static_cast<float>(ed),
                                               c->legend().lo, c->legend().hi)))
            << row;
    }
}

TEST(WallColourRequestTest, ClassesAreTheReportsInFixedColours) {
    const auto g = profile("washout");
    const WellAnalysis a = analyseWell(*g, {});
    const auto c = makeWallColouring(*g, by("class"));
    EXPECT_EQ(c->legend().kind, ColourMapKind::Categorical);
    ASSERT_EQ(c->legend().categories.size(), 5u);  // no casing: no "cased" swatch
    EXPECT_EQ(c->legend().categories[2].first, "washout");
    std::size_t washouts = 0;
    for (std::size_t row = 0; row < g->table().rowCount(); ++row) {
        EXPECT_EQ(c->colour(row, 0.0), classColour(a.sections[row].cls)) << row;
        washouts += a.sections[row].cls == BoreholeClass::Washout;
    }
    EXPECT_GT(washouts, 50u);
    EXPECT_EQ(c->colour(rowAt(*g, 20.0), 0.0), 0xD55E00FFu);  // vermillion
    EXPECT_EQ(c->colour(rowAt(*g, 5.0), 0.0), classColour(BoreholeClass::InGauge));
    // The values a window keeps give the same colours as the analysis done here.
    const SectionValues values = sectionValues(*g);
    const auto again = makeWallColouring(*g, by("class"), &values);
    for (std::size_t row = 0; row < g->table().rowCount(); row += 11)
        EXPECT_EQ(again->colour(row, 0.0), c->colour(row, 0.0));
}

TEST(WallColourRequestTest, AnExtraCurveIsColouredByItsOwnValuesAndNullsSayNoValue) {
    SectionTable table = makeSyntheticWell(syntheticProfile("circle", 40.0, 0.1));
    caliper3d::io::ExtraCurve gr;
    gr.mnemonic = "GR";
    gr.unit = "gAPI";
    gr.description = "gamma ray";
    for (std::size_t row = 0; row < table.rowCount(); ++row)
        gr.values.push_back(row % 50 == 7 ? std::nan("") : 100.0 * row / (table.rowCount() - 1));
    table.extraCurves.push_back(gr);
    const auto g = wellOf(table);
    EXPECT_EQ(colourQuantities(g->table()).back(), "GR");
    const auto c = makeWallColouring(*g, by("gr"));
    EXPECT_EQ(c->legend().title, "GR");
    EXPECT_EQ(c->legend().unit, "gAPI");
    EXPECT_EQ(c->legend().note, "gamma ray");
    EXPECT_TRUE(c->legend().noValue);
    EXPECT_NEAR(c->legend().lo, 2.0, 0.5);  // a ramp from 0 to 100
    EXPECT_NEAR(c->legend().hi, 98.0, 0.5);
    EXPECT_EQ(c->colour(7, 0.0), kNoValueColour);
    EXPECT_EQ(c->colour(table.rowCount() - 1, 0.0), sequentialColour(1.0));
}

TEST(WallColourRequestTest, AnUnknownNameListsWhatTheWellCanBeColouredBy) {
    const auto g = profile("circle");
    try {
        (void)makeWallColouring(*g, by("porosity"));
        FAIL() << "no error";
    } catch (const std::invalid_argument& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("cannot colour by 'porosity'"), std::string::npos) << what;
        EXPECT_NE(what.find("departure, diameter, ellipticity, class, dls"), std::string::npos)
            << what;
    }
}

TEST(WallColourRequestTest, WithoutABitSizeDeparturesAreFromTheMedianDiameterAsInTheReport) {
    SectionTable table = makeSyntheticWell(syntheticProfile("washout", 40.0, 0.1));
    table.bitSize_mm.clear();
    const auto g = wellOf(table);
    const WellAnalysis a = analyseWell(*g, {});
    ASSERT_TRUE(a.bitSizeFromSections);
    const double gauge = a.sections[0].bit_mm;
    EXPECT_NEAR(gauge, sampledDiameter(215.9), 0.01);  // the median: most of it is in gauge
    const auto c = makeWallColouring(*g, by("departure"));
    EXPECT_EQ(c->legend().title, "radius - gauge radius");
    EXPECT_NE(c->legend().note.find("median equivalent diameter"), std::string::npos);
    EXPECT_EQ(c->colour(3, gauge / 2), divergingColour(0.5));
    EXPECT_EQ(c->colour(3, gauge / 2 + 25.0), divergingColour(1.0));
}

TEST(WallColourRequestTest, AGivenRangeIsUsedAndADepartureRangeMustHoldZero) {
    const auto g = profile("washout");
    ColourRequest request = by("departure");
    request.range = std::make_pair(-10.0, 40.0);
    const auto c = makeWallColouring(*g, request);
    EXPECT_EQ(c->legend().lo, -10.0);
    EXPECT_EQ(c->legend().hi, 40.0);
    EXPECT_EQ(c->legend().range, "given");
    request.range = std::make_pair(5.0, 10.0);
    EXPECT_THROW((void)makeWallColouring(*g, request), std::invalid_argument);
    request = by("diameter");
    request.range = std::make_pair(200.0, 300.0);
    const auto d = makeWallColouring(*g, request);
    EXPECT_EQ(d->legend().lo, 200.0);
    EXPECT_EQ(d->colour(rowAt(*g, 5.0), 0.0),
              sequentialColour((static_cast<float>(sampledDiameter(215.9)) - 200.0) / 100.0));
}

TEST(WallColourRequestTest, DoglegSeverityIsThePathsOwn) {
    const auto g = profile("build", 300.0);  // 3 deg/30 m from 30 m down
    const auto c = makeWallColouring(*g, by("dls"));
    EXPECT_EQ(c->legend().unit, "deg/30m");
    EXPECT_NEAR(c->legend().hi, 3.0, 0.01);
    EXPECT_NEAR(c->legend().lo, 0.0, 0.01);
    const std::size_t building = rowAt(*g, 200.0), vertical = rowAt(*g, 10.0);
    EXPECT_NEAR(g->path()[building].dls_degPer30m, 3.0, 0.01);
    EXPECT_EQ(c->colour(vertical, 0.0), sequentialColour(0.0));
    EXPECT_EQ(c->colour(building, 0.0),
              sequentialColour(mapPosition(ColourMapKind::Sequential,
                                           static_cast<float>(g->path()[building].dls_degPer30m),
                                           c->legend().lo, c->legend().hi)));
}

TEST(WallColourRequestTest, RobustPercentileSkipsNaNAndTakesTheNearestRank) {
    EXPECT_EQ(robustPercentile({5.0f, std::nanf(""), 1.0f, 3.0f}, 0.0), 1.0);
    EXPECT_EQ(robustPercentile({5.0f, std::nanf(""), 1.0f, 3.0f}, 1.0), 5.0);
    EXPECT_EQ(robustPercentile({5.0f, 1.0f, 3.0f}, 0.5), 3.0);
    EXPECT_TRUE(std::isnan(robustPercentile({std::nanf("")}, 0.5)));
}
