// A peer's LAS corpus (lasio's and welly's test files, ../shared/data/las_corpus): every file
// is described or refused naming itself, and the files lasio's own tests say how to read are
// read so (each check names the lasio test, tests/*.py of kinverarity1/lasio). The rules behind
// them are checked on constructed text as well, so that they hold without the corpus.
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/las_reader.h"
#include "io/log_reader.h"
#include "io/parse_error.h"
#include "support/curve_lookup.h"
#include "test_support.h"

using namespace caliper3d::io;

namespace {

std::filesystem::path corpus() {
    return caliper3d::test::sharedData() / "las_corpus";
}

std::string corpusFile(const std::string& name) {
    return (corpus() / name).string();
}

std::string fileText(const std::string& path) {
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) return {};
    std::string text;
    char buffer[65536];
    std::size_t n = 0;
    while ((n = std::fread(buffer, 1, sizeof buffer, f)) > 0) text.append(buffer, n);
    std::fclose(f);
    return text;
}

const Warning* warning(const LogInfo& info, const std::string& text) {
    for (const Warning& w : info.diagnostics.warnings)
        if (w.message.find(text) != std::string::npos) return &w;
    return nullptr;
}

using caliper3d::test::curve;
using caliper3d::test::extra;

// A six-arm log written here: DEPT, six radii in millimetres and the curves in `more`
// (names and units), with the data lines given.
std::string sixArmLog(const std::string& more, const std::string& data,
                      const std::string& version = " VERS. 2.0 : v\n WRAP. NO : w\n") {
    std::string text =
        "~Version\n" + version + "~Well\n NULL. -999.25 : null\n~Curve\n DEPT.M : d\n";
    for (int k = 1; k <= 6; ++k) text += " R" + std::to_string(k) + ".MM : radius\n";
    return text + more + "~A\n" + data;
}

}  // namespace

// No crash, no hang, and every refusal names the file (lasio reads or refuses each with an
// exception of its own; caliper3d's refusals are ParseErrors whose message starts with the file).
TEST(LasCorpusTest, EveryFileIsDescribedOrRefusedNamingTheFile) {
    CALIPER3D_REQUIRE_DATA(corpus());
    std::size_t files = 0, described = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(corpus())) {
        if (!entry.is_regular_file()) continue;
        std::string ext = entry.path().extension().string();
        for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        if (ext != ".las") continue;
        const std::string path = entry.path().string();
        SCOPED_TRACE(path);
        ++files;
        try {
            const LogInfo info = describeLog(path, ReadOptions{});
            EXPECT_GT(info.rows, 0u);
            for (const Warning& w : info.diagnostics.warnings) EXPECT_EQ(w.file, path);
            ++described;
        } catch (const ParseError& e) {
            EXPECT_EQ(e.file(), path);
            EXPECT_EQ(std::string(e.what()).rfind(path, 0), 0u) << e.what();
            EXPECT_FALSE(e.message().empty());
        }
    }
    // 131 lasio files and 3 of welly's at the corpus's commit; most are read.
    EXPECT_GE(files, 130u);
    EXPECT_GT(described, files / 2) << described << " of " << files;
}

// test_read_v30_tab_dlm_normal_engine (lasio issue 554): DLM TAB, a text value with spaces
// ("DOLOMITE WI/VUGS"); three rows, DEPT[1] = 1669.875.
TEST(LasCorpusTest, TabDelimitedLas30ReadsTextWithSpaces) {
    const std::string path = corpusFile("lasio/3.0/sample_3.0_tab_dlm.las");
    CALIPER3D_REQUIRE_DATA(std::filesystem::path(path));
    Diagnostics d;
    const LasLog log = readLas(fileText(path), path, {}, &d);
    ASSERT_EQ(log.rowCount(), 3u);
    EXPECT_DOUBLE_EQ(log.curves[0].values[1], 1669.875);
    const LogInfo info = describeLog(path, ReadOptions{});
    EXPECT_EQ(info.rows, 3u);
    EXPECT_EQ(info.format, "LAS 3.0");
}

TEST(LasCorpusTest, TabDelimiterPartsValuesThatHoldSpaces) {
    const std::string header =
        "~Version\n VERS. 3.0 : v\n WRAP. NO : w\n DLM . TAB : tab\n~Well\n NULL. -999.25 : n\n"
        "~Log_Definition\n DEPT.M : d\n LITH. : lithology {S}\n GR.GAPI : g {F}\n"
        "~Log_Data | Log_Definition\n";
    const std::string text = header +
                             "100.0\tSAND SHALY \t 45.5\n100.5\tLOST INTERVAL\t-999.25\n"
                             "101.0  OOLITE  47\n";  // a line without a tab: blanks
    const LasLog log = readLas(text, "tab.las", {}, nullptr);
    ASSERT_EQ(log.rowCount(), 3u);
    EXPECT_DOUBLE_EQ(log.curves[2].values[0], 45.5);
    EXPECT_TRUE(std::isnan(log.curves[2].values[1]));
    EXPECT_DOUBLE_EQ(log.curves[2].values[2], 47.0);
    // A space inside a number's field is still refused with its place.
    try {
        readLas(header + "100.0\tSAND\t4 5\n", "tab.las", {}, nullptr);
        FAIL() << "expected a refusal";
    } catch (const ParseError& e) {
        EXPECT_EQ(e.line(), 12u);
    }
}

// test_mnemonic_leading_period: ".ILM .OHMM" is the curve ILM in OHMM.
TEST(LasCorpusTest, MnemonicWithALeadingPeriod) {
    const std::string path = corpusFile("lasio/mnemonic_leading_period.las");
    CALIPER3D_REQUIRE_DATA(std::filesystem::path(path));
    const LogInfo info = describeLog(path, ReadOptions{});
    std::vector<std::string> names;
    for (const CurveInfo& c : info.curves) names.push_back(c.mnemonic);
    EXPECT_EQ(names, (std::vector<std::string>{"DEPT", "DT", "RHOB", "NPHI", "SFLU", "SFLA", "ILM",
                                               "ILD"}));
    EXPECT_EQ(curve(info, "ILM")->unit, "OHMM");
    EXPECT_NE(warning(info, "'ILM' is written with a leading period"), nullptr);

    LasItem item;
    ASSERT_TRUE(splitLasItem(".ILM .OHMM  :  7  MEDIUM RESISTIVITY", item));
    EXPECT_EQ(item.mnemonic, "ILM");
    EXPECT_EQ(item.unit, "OHMM");
    ASSERT_TRUE(splitLasItem(".OHMM : nameless", item));  // a lone period stays the separator
    EXPECT_EQ(item.mnemonic, "");
    EXPECT_EQ(item.unit, "OHMM");
}

// test_autodepthindex_point_one_inch: "DEPT  ..1IN" is DEPT in tenths of an inch (the ".."
// of a mnemonic that ends in a dot follows a non-blank). caliper3d has no such depth unit: it
// refuses the file naming the unit lasio reads.
TEST(LasCorpusTest, UnitThatStartsWithAPeriod) {
    LasItem item;
    ASSERT_TRUE(splitLasItem(" DEPT  ..1IN      : ", item, true));
    EXPECT_EQ(item.mnemonic, "DEPT");
    EXPECT_EQ(item.unit, ".1IN");
    ASSERT_TRUE(splitLasItem("STRT    ..1IN   986904.0000   : START INDEX", item, false));
    EXPECT_EQ(item.mnemonic, "STRT");
    EXPECT_EQ(item.unit, ".1IN");
    EXPECT_EQ(item.value, "986904.0000");
    ASSERT_TRUE(splitLasItem("Cond..MS/M : Cond.", item, true));  // issue-264-dot-delimiter
    EXPECT_EQ(item.mnemonic, "Cond.");
    EXPECT_EQ(item.unit, "MS/M");

    const std::string path = corpusFile("lasio/autodepthindex_point_one_inch.las");
    CALIPER3D_REQUIRE_DATA(std::filesystem::path(path));
    try {
        describeLog(path, ReadOptions{});
        FAIL() << "expected a refusal of the depth unit";
    } catch (const ParseError& e) {
        EXPECT_NE(e.message().find("found '.1IN'"), std::string::npos) << e.what();
    }
}

// LAS 1.2 ~Well: the value follows the colon except for STRT, STOP, STEP and NULL (LAS 1.2;
// lasio's ORDER_DEFINITIONS; test_open_file.py's header "WELL.  WELL:  ANY ET AL OIL WELL #12").
TEST(LasCorpusTest, Las12WellValuesAfterTheColon) {
    const std::string path = corpusFile("lasio/1.2/sample.las");
    CALIPER3D_REQUIRE_DATA(std::filesystem::path(path));
    const LogInfo info = describeLog(path, ReadOptions{});
    EXPECT_EQ(info.wellName, "ANY ET AL OIL WELL #12");
    EXPECT_EQ(info.rows, 3u);
    EXPECT_EQ(info.location.uwi, "100091604920W300");

    const std::string v12 =
        "~V\n VERS. 1.2 : v\n WRAP. NO : w\n~W\n STRT.M 1670.0 : start\n NULL. -999.25 : n\n"
        " WELL. WELL : ANY ET AL 12\n LOC . LOCATION : \n~C\n DEPT.M : d\n GR.GAPI : g\n~A\n"
        "1670 1\n";
    const LasLog log = readLas(v12, "v12.las", {}, nullptr);
    EXPECT_EQ(log.header.wellItem("WELL")->value, "ANY ET AL 12");
    EXPECT_EQ(log.header.wellItem("WELL")->description, "WELL");
    EXPECT_EQ(log.header.wellItem("STRT")->value, "1670.0");
    EXPECT_EQ(log.header.wellItem("LOC")->value, "LOCATION");  // nothing after the colon
    // LAS 2.0 keeps the value before the colon.
    const std::string path20 = corpusFile("lasio/2.0/sample_2.0.las");
    if (std::filesystem::exists(path20)) {
        const LogInfo info20 = describeLog(path20, ReadOptions{});
        EXPECT_EQ(info20.wellName, "AAAAA_2");
    }
}

// test_wrong_stop_value: STOP 1660 over data that end at 1669.75; the data are used (lasio
// rewrites STOP from them). caliper3d warns, at the header line.
TEST(LasCorpusTest, HeaderRangeThatDisagreesWithTheDataIsWarned) {
    const std::string path = corpusFile("lasio/2.0/sample_2.0_wrong_stop_value.las");
    CALIPER3D_REQUIRE_DATA(std::filesystem::path(path));
    const LogInfo info = describeLog(path, ReadOptions{});
    EXPECT_DOUBLE_EQ(info.top_m, 1669.75);
    EXPECT_DOUBLE_EQ(info.bottom_m, 1670.0);
    const Warning* stop = warning(info, "header STOP 1660.0000 disagrees with the data");
    ASSERT_NE(stop, nullptr);
    EXPECT_EQ(stop->line, 8u);
    EXPECT_EQ(warning(info, "header STRT"), nullptr);
    EXPECT_EQ(warning(info, "header STEP"), nullptr);
    EXPECT_EQ(info.declaredNull, "-999.25");
    EXPECT_NE(formatLogInfo(info).find("null:      -999.25 (declared in the header)\n"),
              std::string::npos);
}

TEST(LasCorpusTest, HeaderRangeIsCheckedOnConstructedText) {
    const std::string data = "100.0 1 1 1 1 1 1\n100.5 1 1 1 1 1 1\n101.0 1 1 1 1 1 1\n";
    auto read = [&](const std::string& range) {
        std::string text = sixArmLog("", data);
        text.insert(text.find(" NULL."), range);
        return loadCaliperText(text, "range.las", ReadOptions{}).info;
    };
    const LogInfo agree = read(" STRT.M 100.0 : s\n STOP.M 101.0 : s\n STEP.M 0.5 : s\n");
    EXPECT_EQ(warning(agree, "header"), nullptr);
    const LogInfo varying = read(" STRT.M 100.000 : s\n STOP.M 101.0 : s\n STEP.M 0 : s\n");
    EXPECT_EQ(warning(varying, "header"), nullptr);  // STEP 0: a varying step
    const LogInfo unknown = read(" STRT.M -999.25 : s\n STOP.M -999.25 : s\n");
    EXPECT_EQ(warning(unknown, "header"), nullptr);  // declared unknown
    const LogInfo wrong = read(" STRT.M 99.0 : s\n STOP.M 101.0 : s\n STEP.M 0.25 : s\n");
    EXPECT_EQ(wrong.diagnostics.warningCount, 2u);
    const Warning* strt = warning(wrong, "header STRT 99.0 disagrees with the data");
    ASSERT_NE(strt, nullptr);
    EXPECT_EQ(strt->line, 5u);
    EXPECT_NE(warning(wrong, "header STEP 0.25 disagrees with the data: their step is 0.5 M"),
              nullptr);
}

// An image log's breakout picks: depth, azimuth and a text column in LAS 2.0 (no {S}).
// lasio reads the strings (test_data_characters_*); caliper3d does not need the column: its
// values are null, counted in one warning naming the first line.
TEST(LasCorpusTest, TextInACurveTheReaderDoesNotNeed) {
    const std::string picks =
        "~Version\n VERS. 2.0 : v\n WRAP. NO : w\n~Well\n NULL. -999.25 : n\n~Curve\n"
        " DEPT.M : depth\n BOAZ.DEG : breakout azimuth\n TYPE. : pick type\n~A\n"
        "120.5 35.0 BREAKOUT\n121.0 215.0 BREAKOUT\n133.2 80.0 DITF\n";
    const LoadedLog log = loadCaliperText(picks, "picks.las", ReadOptions{});
    EXPECT_EQ(log.info.rows, 3u);
    const Warning* text = warning(log.info, "curve TYPE: 3 values are not a number");
    ASSERT_NE(text, nullptr);
    EXPECT_EQ(text->line, 11u);
    EXPECT_NE(text->message.find("(the first 'BREAKOUT')"), std::string::npos) << text->message;
    EXPECT_DOUBLE_EQ(extra(log.table, "BOAZ")->values[2], 80.0);
}

// One "12.3.4" in an unused curve: that value is null and counted, the well is read. In an
// arm or the depth it is refused naming file and line.
TEST(LasCorpusTest, BadValueOnlyRefusedInANeededCurve) {
    const std::string good = "100.0 80 80 80 80 80 80 10\n";
    const std::string bad = "100.5 80 80 80 80 80 80 12.3.4\n";
    const LoadedLog log =
        loadCaliperText(sixArmLog(" GR.GAPI : g\n", good + bad + "101.0 80 80 80 80 80 80 11\n"),
                        "gr.las", ReadOptions{});
    EXPECT_EQ(log.table.rowCount(), 3u);
    const Warning* w = warning(log.info, "curve GR: 1 value is not a number (the first '12.3.4')");
    ASSERT_NE(w, nullptr);
    EXPECT_EQ(w->line, 17u);
    EXPECT_TRUE(std::isnan(extra(log.table, "GR")->values[1]));
    try {
        loadCaliperText(sixArmLog(" GR.GAPI : g\n", good + "100.5 80 80 12.3.4 80 80 80 10\n"),
                        "arm.las", ReadOptions{});
        FAIL() << "expected a refusal";
    } catch (const ParseError& e) {
        EXPECT_EQ(e.file(), "arm.las");
        EXPECT_EQ(e.line(), 17u);
        EXPECT_NE(e.message().find("expected a number for curve R3, found '12.3.4'"),
                  std::string::npos)
            << e.what();
    }
    try {
        loadCaliperText(sixArmLog("", "1O0.0 80 80 80 80 80 80\n"), "depth.las", ReadOptions{});
        FAIL() << "expected a refusal";
    } catch (const ParseError& e) {
        EXPECT_EQ(e.line(), 15u);
        EXPECT_NE(e.message().find("curve DEPT"), std::string::npos) << e.what();
    }
}

TEST(LasCorpusTest, InfoShowsTheDeclaredNull) {
    const std::string text = sixArmLog("", "100.0 80 80 80 80 80 80\n");
    LogInfo info = loadCaliperText(text, "n.las", ReadOptions{}).info;
    EXPECT_EQ(info.declaredNull, "-999.25");
    EXPECT_NE(formatLogInfo(info).find("null:      -999.25 (declared in the header)"),
              std::string::npos);
    std::string none = text;
    none.erase(none.find(" NULL."), std::string(" NULL. -999.25 : null\n").size());
    info = loadCaliperText(none, "n.las", ReadOptions{}).info;
    EXPECT_EQ(info.declaredNull, "");
    EXPECT_NE(formatLogInfo(info).find("null:      none declared in the header"),
              std::string::npos);
}

// test_quoted_substrings_in_data_section: quoted text with blanks in a curve the log is not
// read for is one value; null_policy_runon.las: two values run together leave a row short,
// refused with the value named.
TEST(LasCorpusTest, QuotedTextAndRunOnValues) {
    const std::string header =
        "~Version\n VERS. 2.0 : v\n WRAP. NO : w\n~Well\n NULL. -999.25 : n\n~Curve\n"
        " MD.M : d\n TEST.CPS : t\n ZONE. : z\n~A\n";
    const LoadedLog log = loadCaliperText(
        header + "321.16 100 pick_alpha\n1953.5 200 \"pick gamma\"\n2141.05 205 'pick delta'\n",
        "quoted.las", ReadOptions{});
    EXPECT_EQ(log.info.rows, 3u);
    EXPECT_NE(warning(log.info, "curve ZONE: 3 values are not a number"), nullptr);
    try {
        // Not on the first data line, which settles how many values a row holds.
        loadCaliperText(header + "320.0 1 x\n321.16 7.020101130.188\n322.0 1 x\n", "runon.las",
                        ReadOptions{});
        FAIL() << "expected a refusal";
    } catch (const ParseError& e) {
        EXPECT_EQ(e.line(), 12u);
        EXPECT_NE(
            e.message().find("found 2 values (curve TEST's '7.020101130.188' is not a number)"),
            std::string::npos)
            << e.what();
    }
}
