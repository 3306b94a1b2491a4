#include "reconstruction/analysis/report_writer.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "io/las_reader.h"
#include "reconstruction/synthetic/synthetic_well.h"

using namespace caliper3d;
using namespace caliper3d::reconstruction;

namespace {
WellAnalysis exampleAnalysis() {
    auto table = std::make_shared<const io::SectionTable>(
        makeSyntheticWell(syntheticProfile("example", 300.0, 0.5)));
    WellGeometry g(table, GeometryOptions{});
    return analyseWell(g, {});
}
std::size_t lines(const std::string& s) {
    std::size_t n = 0;
    for (char c : s) n += c == '\n';
    return n;
}
}  // namespace

TEST(ReportWriterTest, HeaderStartsWithTheExactColumns) {
    std::ostringstream out;
    writeSectionReport(out, exampleAnalysis());
    const std::string s = out.str();
    EXPECT_EQ(s.rfind("md_m,tvd_m,north_m,east_m,inc_deg,azi_deg,dmin_mm,dmax_mm,ellipticity,major_"
                      "azimuth_deg,"
                      "area_mm2,centre_offset_mm,class,",
                      0),
              0u);
    EXPECT_EQ(lines(s), 1u + 601u);
    EXPECT_NE(s.find(",breakout,"), std::string::npos);
    EXPECT_NE(s.find(",washout,"), std::string::npos);
    EXPECT_NE(s.find("\n0.0000,0.0000,0.0000,0.0000,0.000,45.000,215.90,215.90,1.0000,"),
              std::string::npos);
}

TEST(ReportWriterTest, StepKeepsOneSectionPerStep) {
    std::ostringstream out;
    writeSectionReport(out, exampleAnalysis(), ReportOptions{10.0, {}});
    EXPECT_EQ(lines(out.str()), 1u + 31u);
    EXPECT_NE(out.str().find("\n10.0000,"), std::string::npos);
}

TEST(ReportWriterTest, ZoneTableAndSummary) {
    const WellAnalysis a = exampleAnalysis();
    std::ostringstream out;
    writeZoneReport(out, a);
    const std::string s = out.str();
    EXPECT_EQ(s.rfind("kind,top_m,bottom_m,length_m,mean_azimuth_deg,circular_sd_deg,mean_dmax_mm,"
                      "mean_dmin_mm,sections\n",
                      0),
              0u);
    EXPECT_NE(s.find("\nbreakout,59.7500,"), std::string::npos);
    EXPECT_NE(s.find("\nwashout,"), std::string::npos);
    const std::string summary = formatAnalysisSummary(a);
    EXPECT_NE(summary.find("WSM quality D"), std::string::npos);
}

TEST(ReportWriterTest, UnwritableFileIsAnError) {
    EXPECT_THROW(writeSectionReport("/nonexistent/dir/out.csv", exampleAnalysis()),
                 std::runtime_error);
}

TEST(ReportWriterTest, AnalysisLasHoldsTheReportedSectionsCurveByCurve) {
    const WellAnalysis a = exampleAnalysis();
    const ReportOptions every10m{10.0, {}};
    std::ostringstream out;
    writeAnalysisLas(out, a, every10m, "EXAMPLE");
    io::Diagnostics diagnostics;
    const io::LasLog log = io::readLas(out.str(), "analysis.las", {}, &diagnostics);
    EXPECT_EQ(diagnostics.warningCount, 0u);
    EXPECT_EQ(log.header.wellItem("WELL")->value, "EXAMPLE");
    const std::vector<std::size_t> rows = reportedSections(a, every10m);
    ASSERT_EQ(rows.size(), 31u);
    ASSERT_EQ(log.rowCount(), rows.size());
    auto curve = [&](const std::string& name) -> const std::vector<double>& {
        for (const io::LasCurve& c : log.curves)
            if (c.mnemonic == name) return c.values;
        ADD_FAILURE() << "no curve " << name;
        static const std::vector<double> none;
        return none;
    };
    const auto& depth = curve("DEPT");
    const auto& tvd = curve("TVD");
    const auto& dmax = curve("DMAX");
    const auto& cls = curve("CLASS");
    const auto& majaz = curve("MAJAZ");
    ASSERT_EQ(depth.size(), rows.size());
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const SectionResult& r = a.sections[rows[k]];
        EXPECT_NEAR(depth[k], r.md_m, 5e-5);
        EXPECT_NEAR(tvd[k], r.tvd_m, 5e-5);
        EXPECT_NEAR(dmax[k], r.dmax_mm, 5e-3);
        EXPECT_EQ(cls[k], static_cast<double>(r.cls)) << r.md_m;
        if (std::isnan(r.majorAzimuth_deg))
            EXPECT_TRUE(std::isnan(majaz[k]));
        else
            EXPECT_NEAR(majaz[k], r.majorAzimuth_deg, 5e-3);
    }
    // The example's breakout spans 60-80 m: the 70 m row carries the breakout code.
    EXPECT_EQ(cls[7], static_cast<double>(BoreholeClass::Breakout));
    EXPECT_NE(log.header.other.find("3 breakout"), std::string::npos);
}

TEST(ReportWriterTest, WellheadAddsMapCoordinatesAndDepthBelowDatum) {
    const WellAnalysis a = exampleAnalysis();
    ReportOptions options;
    options.wellhead = Wellhead{500000.0, 6800000.0, 30.0};
    std::ostringstream out;
    writeSectionReport(out, a, options);
    std::istringstream in(out.str());
    std::string header, line;
    std::getline(in, header);
    EXPECT_NE(header.find(",repaired_arms,easting_m,northing_m,tvdss_m"), std::string::npos);
    // The last row: the example builds towards azimuth 45 from 100 m.
    std::string last;
    while (std::getline(in, line)) last = line;
    const SectionResult& r = a.sections.back();
    char expected[128];
    std::snprintf(expected, sizeof expected, ",%.4f,%.4f,%.4f", 500000.0 + r.east_m,
                  6800000.0 + r.north_m, r.tvd_m - 30.0);
    ASSERT_GT(r.east_m, 1.0);
    EXPECT_EQ(last.substr(last.size() - std::strlen(expected)), expected);
}

TEST(ReportWriterTest, OneSectionsFieldsAreItsCsvLine) {
    WellAnalysis a = exampleAnalysis();
    SectionMeasure& seventh = a.sections.measure(7);
    seventh.cls = BoreholeClass::NoData;  // as analyseWell leaves a section without data
    seventh.dmin_mm = seventh.dmax_mm = seventh.equivalentDiameter_mm = io::kNaN;
    for (const bool withWellhead : {false, true}) {
        ReportOptions options;
        if (withWellhead) options.wellhead = Wellhead{500000.0, 6800000.0, 30.0};
        std::ostringstream out;
        writeSectionReport(out, a, options);
        std::istringstream in(out.str());
        std::string header, line;
        std::getline(in, header);
        for (std::size_t i = 0; std::getline(in, line); ++i) {
            const auto fields = sectionReportFields(a.sections[i], options);
            std::string names, values;
            for (std::size_t k = 0; k < fields.size(); ++k) {
                names += (k ? "," : "") + fields[k].first;
                values += (k ? "," : "") + fields[k].second;
            }
            ASSERT_EQ(names, header);
            ASSERT_EQ(values, line) << i;
        }
    }
    const auto noData = sectionReportFields(a.sections[7]);
    EXPECT_EQ(noData[12].first, "class");
    EXPECT_EQ(noData[12].second, "no_data");
    EXPECT_EQ(noData[6].first, "dmin_mm");
    EXPECT_EQ(noData[6].second, "");
}
