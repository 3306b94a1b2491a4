// The report's numbers do not follow the locale: a Qt application sets LC_NUMERIC from the
// environment on Unix, and a comma-decimal locale must not turn 215.90 into "215,90" in a
// comma-separated file, a LAS file or the summary (docs/conventions.md, "Report precision").
#include <clocale>
#include <locale>
#include <memory>
#include <regex>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <QApplication>
#include <QCoreApplication>

#include "app/desktop/gui_session.h"
#include "reconstruction/analysis/report_writer.h"
#include "reconstruction/synthetic/synthetic_well.h"

using namespace caliper3d;
using namespace caliper3d::reconstruction;

namespace {

// Every output of the report writer, one after the other.
std::string allReportOutputs(const WellAnalysis& a) {
    ReportOptions options;
    options.wellhead = Wellhead{512345.25, 6712345.75, 31.5};
    std::ostringstream out;
    writeSectionReport(out, a, options);
    out << "----\n";
    writeZoneReport(out, a);
    out << "----\n";
    writeAnalysisLas(out, a, options);
    out << "----\n" << formatAnalysisSummary(a);
    return out.str();
}

WellAnalysis exampleAnalysis() {
    auto table = std::make_shared<const io::SectionTable>(
        makeSyntheticWell(syntheticProfile("example", 300.0, 0.5)));
    WellGeometry geometry(table, GeometryOptions{});
    AnalysisOptions options;
    options.volume.casingOd_mm = 177.8;  // the annulus and cement line of the summary too
    options.volume.excess = 0.3;
    return analyseWell(geometry, options);
}

// Puts the process in a comma-decimal locale for C (printf) and C++ (streams); restores "C".
class CommaLocale {
public:
    CommaLocale() {
        for (const char* name :
             {"de_DE.UTF-8", "de_DE.utf8", "fr_FR.UTF-8", "fr_FR.utf8", "de_DE"}) {
            if (std::setlocale(LC_ALL, name)) {
                m_name = name;
                std::locale::global(std::locale(name));
                break;
            }
        }
    }
    ~CommaLocale() {
        std::setlocale(LC_ALL, "C");
        std::locale::global(std::locale::classic());
    }
    // Whether printf really writes a decimal comma now (the locale exists and took effect).
    bool active() const {
        char buf[16];
        std::snprintf(buf, sizeof buf, "%.1f", 1.5);
        return !m_name.empty() && std::string(buf) == "1,5";
    }
    const std::string& name() const { return m_name; }

private:
    std::string m_name;
};

}  // namespace

TEST(ReportLocaleTest, NumbersKeepADecimalPointUnderACommaLocaleWithQtAlive) {
    // Qt calls setlocale(LC_ALL, "") when its application starts: that is the trap.
    std::unique_ptr<QCoreApplication> application;
    static int argc = 1;
    static char name[] = "app_tests";
    static char* argv[] = {name, nullptr};
    if (!QCoreApplication::instance()) {
        if (app::haveDisplay())
            application = std::make_unique<QApplication>(argc, argv);
        else
            application = std::make_unique<QCoreApplication>(argc, argv);
    }
    const WellAnalysis analysis = exampleAnalysis();
    const std::string inC = allReportOutputs(analysis);
    ASSERT_NE(inC.find("215.90"), std::string::npos);  // bit size: a number with decimals

    std::string inComma;
    {
        CommaLocale comma;
        if (!comma.active())
            GTEST_SKIP() << "no comma-decimal locale installed (scripts/install-deps.sh makes "
                            "de_DE.UTF-8)";
        inComma = allReportOutputs(analysis);
    }
    // No digit, comma, digit anywhere outside the CSV's separators: compare whole outputs, and
    // look for a decimal comma in the parts that are not comma-separated.
    EXPECT_EQ(inComma, inC);
    const std::string las = inComma.substr(inComma.find("~Version"));
    EXPECT_FALSE(std::regex_search(las, std::regex("[0-9],[0-9]")))
        << "a decimal comma in the LAS file or the summary";
    EXPECT_NE(las.find("0.5"), std::string::npos);  // the STEP of a 0.5 m log
}
