#include "reconstruction/report_writer.h"

#include <memory>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "reconstruction/synthetic_well.h"

using namespace caliper3d;
using namespace caliper3d::reconstruction;

namespace {
WellAnalysis exampleAnalysis() {
    auto table = std::make_shared<const io::SectionTable>(makeSyntheticWell(syntheticProfile("example", 300.0, 0.5)));
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
    EXPECT_EQ(s.rfind("md_m,tvd_m,north_m,east_m,inc_deg,azi_deg,dmin_mm,dmax_mm,ellipticity,major_azimuth_deg,"
                      "area_mm2,centre_offset_mm,class,",
                      0),
              0u);
    EXPECT_EQ(lines(s), 1u + 601u);
    EXPECT_NE(s.find(",breakout,"), std::string::npos);
    EXPECT_NE(s.find(",washout,"), std::string::npos);
    EXPECT_NE(s.find("\n0.0000,0.0000,0.0000,0.0000,0.000,45.000,215.90,215.90,1.0000,"), std::string::npos);
}

TEST(ReportWriterTest, StepKeepsOneSectionPerStep) {
    std::ostringstream out;
    writeSectionReport(out, exampleAnalysis(), ReportOptions{10.0});
    EXPECT_EQ(lines(out.str()), 1u + 31u);
    EXPECT_NE(out.str().find("\n10.0000,"), std::string::npos);
}

TEST(ReportWriterTest, ZoneTableAndSummary) {
    const WellAnalysis a = exampleAnalysis();
    std::ostringstream out;
    writeZoneReport(out, a);
    const std::string s = out.str();
    EXPECT_EQ(s.rfind("kind,top_m,bottom_m,length_m,mean_azimuth_deg,circular_sd_deg,mean_dmax_mm,mean_dmin_mm,sections\n", 0), 0u);
    EXPECT_NE(s.find("\nbreakout,59.7500,"), std::string::npos);
    EXPECT_NE(s.find("\nwashout,"), std::string::npos);
    const std::string summary = formatAnalysisSummary(a);
    EXPECT_NE(summary.find("WSM quality D"), std::string::npos);
}

TEST(ReportWriterTest, UnwritableFileIsAnError) {
    EXPECT_THROW(writeSectionReport("/nonexistent/dir/out.csv", exampleAnalysis()), std::runtime_error);
}
