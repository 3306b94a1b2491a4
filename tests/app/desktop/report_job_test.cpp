#include "app/desktop/report_job.h"

#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <QCoreApplication>
#include <QEventLoop>
#include <QTimer>

#include "desk_test_support.h"
#include "reconstruction/analysis/report_writer.h"
#include "reconstruction/synthetic/synthetic_well.h"

using namespace caliper3d;

namespace {
std::string slurp(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}
}  // namespace

TEST(ReportJobTest, NamesTheZoneTableBesideTheSectionReport) {
    EXPECT_EQ(app::ReportJob::zonesPathFor("/r/w.csv"), "/r/w-zones.csv");
    EXPECT_EQ(app::ReportJob::zonesPathFor("/r.d/w"), "/r.d/w-zones.csv");
}

TEST(ReportJobTest, WritesTheReportCommandsFilesOnAWorker) {
    const test::EventLoopApplication application;  // a worker and a queued call: no window
    auto table = std::make_shared<const io::SectionTable>(
        reconstruction::makeSyntheticWell(reconstruction::syntheticProfile("example", 20.0, 0.1)));
    const reconstruction::WellGeometry geometry(table, reconstruction::GeometryOptions{});
    auto analysis = std::make_shared<const reconstruction::WellAnalysis>(
        reconstruction::analyseWell(geometry, reconstruction::AnalysisOptions{}));
    const std::string sections = test::scratch("report_job.csv").string();
    const std::string zones = app::ReportJob::zonesPathFor(sections);
    std::remove(sections.c_str());
    std::remove(zones.c_str());

    QObject context;
    QEventLoop loop;
    bool ok = false;
    std::string message;
    app::ReportJob job(&context, analysis, sections, zones, [&](bool done, const std::string& m) {
        ok = done;
        message = m;
        loop.quit();
    });
    QTimer::singleShot(30000, &loop, &QEventLoop::quit);
    loop.exec();
    ASSERT_TRUE(ok) << message;
    std::ostringstream expectedSections, expectedZones;
    reconstruction::writeSectionReport(expectedSections, *analysis);
    reconstruction::writeZoneReport(expectedZones, *analysis);
    EXPECT_EQ(slurp(sections), expectedSections.str());
    EXPECT_EQ(slurp(zones), expectedZones.str());
    EXPECT_GT(expectedSections.str().size(), 100u);
}

TEST(ReportJobTest, AnUnwritableFileIsReportedByName) {
    const test::EventLoopApplication application;  // a worker and a queued call: no window
    auto table = std::make_shared<const io::SectionTable>(
        reconstruction::makeSyntheticWell(reconstruction::syntheticProfile("example", 5.0, 0.1)));
    const reconstruction::WellGeometry geometry(table, reconstruction::GeometryOptions{});
    auto analysis = std::make_shared<const reconstruction::WellAnalysis>(
        reconstruction::analyseWell(geometry, reconstruction::AnalysisOptions{}));
    QObject context;
    QEventLoop loop;
    bool ok = true;
    std::string message;
    app::ReportJob job(&context, analysis, "/no/such/folder/r.csv", "/no/such/folder/r-zones.csv",
                       [&](bool done, const std::string& m) {
                           ok = done;
                           message = m;
                           loop.quit();
                       });
    QTimer::singleShot(30000, &loop, &QEventLoop::quit);
    loop.exec();
    EXPECT_FALSE(ok);
    EXPECT_NE(message.find("/no/such/folder/r.csv"), std::string::npos) << message;
}
