// caliper3d batch and the verbs over many files: manifests of good and bad rows, outputs per
// input, --row, -j, summary lines and their merge, the progress line.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_run.h"
#include "test_support.h"

using caliper3d::test::CommandRun;
using caliper3d::test::runCaliper3d;
using caliper3d::test::runCaliper3dStderr;
using caliper3d::test::scratch;
namespace fs = std::filesystem;

namespace {

std::string synth(const fs::path& file, const std::string& profile, double length = 100.0) {
    const CommandRun r = runCaliper3d("synth -o " + file.string() + " --profile " + profile +
                                      " --length " + std::to_string(length) + " --step 0.1");
    EXPECT_EQ(r.status, 0) << r.output;
    return file.string();
}

void writeText(const fs::path& file, const std::string& text) {
    std::ofstream(file, std::ios::binary) << text;
}

std::string readText(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::vector<nlohmann::json> readSummary(const fs::path& file) {
    std::vector<nlohmann::json> lines;
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);) lines.push_back(nlohmann::json::parse(line));
    return lines;
}

std::size_t lineCount(const fs::path& file) {
    std::ifstream in(file);
    std::size_t n = 0;
    for (std::string line; std::getline(in, line);) ++n;
    return n;
}

// A summary line without what changes from run to run.
nlohmann::json stable(nlohmann::json line) {
    for (const char* key : {"seconds", "peak_rss_mb", "outputs"}) line.erase(key);
    return line;
}

// A column-text log whose 6th line has 3 values for 12 columns.
fs::path badLineLog(const fs::path& dir) {
    const std::string good = readText(synth(dir / "good.txt", "circle", 10.0));
    std::istringstream in(good);
    std::string text, line;
    for (int n = 1; std::getline(in, line) && n <= 20; ++n)
        text += (n == 6 ? std::string("0.45 1 2\n") : "") + line + "\n";
    writeText(dir / "badline.txt", text);
    return dir / "badline.txt";
}

}  // namespace

TEST(BatchCommandTest, RunsTheGoodRowsAndGivesEachBadRowItsReason) {
    const fs::path dir = caliper3d::test::freshScratchFolder("batch_bad_rows");
    synth(dir / "A.las", "example");
    synth(dir / "B.txt", "keyseat");
    badLineLog(dir);
    writeText(dir / "m.csv",
              "# a manifest with good and bad rows\n"
              "file,verb,wellhead\n"
              "A.las,report,\"0,0,0\"\n"
              "missing.las,report,\n"
              "badline.txt,report,\n"
              "A.las,frobnicate,\n"
              "B.txt,report,\"30,0,0\"\n");
    const fs::path out = dir / "out";
    const CommandRun r = runCaliper3d("batch " + (dir / "m.csv").string() + " -o " + out.string() +
                                      "/ --summary " + (dir / "s.jsonl").string());
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_TRUE(fs::exists(out / "A.csv"));
    EXPECT_TRUE(fs::exists(out / "B.csv"));
    EXPECT_FALSE(fs::exists(out / "missing.csv"));
    const std::vector<nlohmann::json> lines = readSummary(dir / "s.jsonl");
    ASSERT_EQ(lines.size(), 5U);
    for (std::size_t i = 0; i < lines.size(); ++i) EXPECT_EQ(lines[i]["row"], i);
    EXPECT_EQ(lines[0]["status"], "ok");
    EXPECT_EQ(lines[4]["status"], "ok");
    EXPECT_EQ(lines[1]["status"], "failed");
    EXPECT_NE(lines[1]["error"]["reason"].get<std::string>().find("cannot open"),
              std::string::npos);
    EXPECT_EQ(lines[2]["error"]["file"], (dir / "badline.txt").string());
    EXPECT_EQ(lines[2]["error"]["line"], 6);
    EXPECT_EQ(lines[2]["error"]["reason"], "expected 12 named columns, found 3 values");
    EXPECT_EQ(lines[3]["error"]["file"], (dir / "m.csv").string());
    EXPECT_EQ(lines[3]["error"]["line"], 6);  // the manifest's line
    EXPECT_NE(lines[3]["error"]["reason"].get<std::string>().find("unknown verb 'frobnicate'"),
              std::string::npos);
    EXPECT_NE(r.output.find("unknown verb 'frobnicate'"), std::string::npos) << r.output;
}

TEST(BatchCommandTest, SummaryLinesHoldTheReportsNumbers) {
    // The example profile over 100 m: a breakout at 20-26.7 m and a washout at 50-53.3 m.
    const fs::path dir = caliper3d::test::freshScratchFolder("batch_numbers");
    synth(dir / "E.las", "example");
    writeText(dir / "m.json",
              "{\"wells\": [{\"file\": \"E.las\", \"verb\": [\"report\"], \"wellhead\": [0, 0, "
              "0], \"output\": \"rep/\", \"options\": \"--zones " +
                  (dir / "zones.csv").string() + "\"}]}");
    // The summary's folder is made as the outputs' are.
    const CommandRun r = runCaliper3d("batch " + (dir / "m.json").string() + " --summary " +
                                      (dir / "new" / "s.jsonl").string());
    ASSERT_EQ(r.status, 0) << r.output;
    const std::vector<nlohmann::json> lines = readSummary(dir / "new" / "s.jsonl");
    ASSERT_EQ(lines.size(), 1U);
    const nlohmann::json& line = lines.front();
    EXPECT_EQ(line["status"], "ok");
    EXPECT_EQ(line["verb"], "report");
    EXPECT_EQ(line["rows"], lineCount(dir / "rep" / "E.csv") - 1);  // the CSV's header
    EXPECT_EQ(line["rows"], 1001);
    EXPECT_EQ(line["zones"], lineCount(dir / "zones.csv") - 1);
    EXPECT_EQ(line["zones"], 2);
    EXPECT_EQ(line["zones_by_class"]["breakout"], 1);
    EXPECT_EQ(line["zones_by_class"]["washout"], 1);
    EXPECT_DOUBLE_EQ(line["depth_m"][0].get<double>(), 0.0);
    EXPECT_DOUBLE_EQ(line["depth_m"][1].get<double>(), 100.0);
    std::size_t classed = 0;
    for (const auto& [name, count] : line["classes"].items()) classed += count.get<std::size_t>();
    EXPECT_EQ(classed, 1001U);
    EXPECT_GT(line["volumes_m3"]["hole"].get<double>(),
              line["volumes_m3"]["gauge_hole"].get<double>());
    EXPECT_NE(r.output.find("2 zones"), std::string::npos) << r.output;
}

TEST(BatchCommandTest, AJsonManifestThatIsNotAManifestIsRefusedNamingIt) {
    // A number too large for a double is JSON's out_of_range, not a syntax error (found by
    // fuzz_batch_manifest): refused with the manifest's name like any bad JSON.
    const fs::path dir = caliper3d::test::freshScratchFolder("batch_bad_json");
    writeText(dir / "m.json", "{\"wells\": [{\"file\": \"a.las\", \"bit_size\": 1e99999}]}");
    const CommandRun r =
        runCaliper3d("batch " + (dir / "m.json").string() + " -o " + (dir / "out").string() + "/");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.output.find((dir / "m.json").string()), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("not JSON"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("terminate"), std::string::npos) << r.output;
}

TEST(BatchCommandTest, RowRunsOnlyThatRowCountedFromZero) {
    const fs::path dir = caliper3d::test::freshScratchFolder("batch_row");
    const CommandRun field = runCaliper3d("synth --field 3 --length 50 -o " + dir.string() + "/");
    ASSERT_EQ(field.status, 0) << field.output;
    const std::string manifest = (dir / "manifest.csv").string();
    const CommandRun r =
        runCaliper3d("batch " + manifest + " --row 1 -o " + (dir / "out").string() +
                     "/ --summary " + (dir / "s1.jsonl").string());
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_FALSE(fs::exists(dir / "out" / "well-000.csv"));
    EXPECT_TRUE(fs::exists(dir / "out" / "well-001.csv"));
    EXPECT_FALSE(fs::exists(dir / "out" / "well-002.csv"));
    const std::vector<nlohmann::json> lines = readSummary(dir / "s1.jsonl");
    ASSERT_EQ(lines.size(), 1U);
    EXPECT_EQ(lines[0]["row"], 1);
    EXPECT_EQ(lines[0]["file"], (dir / "well-001.las").string());
    EXPECT_EQ(runCaliper3d("batch " + manifest + " --row 3 -o out/").status, 2);
}

TEST(BatchCommandTest, RowRangeRunsThatBlockAndStopsAtTheManifestsEnd) {
    const fs::path dir = caliper3d::test::freshScratchFolder("batch_row_range");
    ASSERT_EQ(runCaliper3d("synth --field 5 --length 30 -o " + dir.string() + "/").status, 0);
    const std::string manifest = (dir / "manifest.csv").string();
    // Rows 3 to 9 of 5: a cluster array's last block of 7 rows, cut at the last row.
    const CommandRun r =
        runCaliper3d("batch " + manifest + " --row 3-9 -o " + (dir / "out").string() +
                     "/ --summary " + (dir / "s.jsonl").string());
    ASSERT_EQ(r.status, 0) << r.output;
    for (int w = 0; w < 5; ++w)
        EXPECT_EQ(fs::exists(dir / "out" / ("well-00" + std::to_string(w) + ".csv")), w >= 3) << w;
    const std::vector<nlohmann::json> lines = readSummary(dir / "s.jsonl");
    ASSERT_EQ(lines.size(), 2U);
    EXPECT_EQ(lines[0]["row"], 3);
    EXPECT_EQ(lines[1]["row"], 4);
    for (const char* bad : {"5-6", "2-1", "x-3", "1-", "-1"})
        EXPECT_EQ(runCaliper3d("batch " + manifest + " --row " + bad + " -o out/").status, 2)
            << bad;
}

TEST(BatchCommandTest, TwoJobsGiveTheSameOutputsAsOne) {
    const fs::path dir = caliper3d::test::freshScratchFolder("batch_jobs");
    ASSERT_EQ(runCaliper3d("synth --field 6 --length 60 -o " + dir.string() + "/").status, 0);
    const std::string manifest = (dir / "manifest.csv").string();
    for (const char* jobs : {"1", "2"}) {
        const CommandRun r =
            runCaliper3d("batch " + manifest + " -j " + jobs + " -o " +
                         (dir / ("out" + std::string(jobs))).string() + "/ --summary " +
                         (dir / (jobs + std::string(".jsonl"))).string());
        ASSERT_EQ(r.status, 0) << r.output;
    }
    for (int w = 0; w < 6; ++w) {
        const std::string name = "well-00" + std::to_string(w) + ".csv";
        const std::string one = readText(dir / "out1" / name);
        EXPECT_FALSE(one.empty()) << name;
        EXPECT_EQ(one, readText(dir / "out2" / name)) << name;
    }
    const std::vector<nlohmann::json> one = readSummary(dir / "1.jsonl");
    const std::vector<nlohmann::json> two = readSummary(dir / "2.jsonl");
    ASSERT_EQ(one.size(), 6U);
    ASSERT_EQ(two.size(), 6U);
    for (std::size_t i = 0; i < one.size(); ++i) EXPECT_EQ(stable(one[i]), stable(two[i]));
}

TEST(BatchCommandTest, MergeConcatenatesTheSummariesInRowOrder) {
    const fs::path dir = caliper3d::test::freshScratchFolder("batch_merge");
    ASSERT_EQ(runCaliper3d("synth --field 3 --length 50 -o " + dir.string() + "/").status, 0);
    const std::string manifest = (dir / "manifest.csv").string();
    std::string parts;
    for (const char* row : {"2", "0", "1"}) {
        const fs::path part = dir / ("summary-" + std::string(row) + ".jsonl");
        ASSERT_EQ(runCaliper3d("batch " + manifest + " --row " + row + " -o " +
                               (dir / "out").string() + "/ --summary " + part.string())
                      .status,
                  0);
        parts += " " + part.string();
    }
    const CommandRun merge = runCaliper3d("batch --merge " + (dir / "all.jsonl").string() + parts);
    ASSERT_EQ(merge.status, 0) << merge.output;
    const std::vector<nlohmann::json> merged = readSummary(dir / "all.jsonl");
    ASSERT_EQ(merged.size(), 3U);
    for (std::size_t i = 0; i < merged.size(); ++i) EXPECT_EQ(merged[i]["row"], i);
    // The same lines as one run over the whole manifest writes.
    ASSERT_EQ(runCaliper3d("batch " + manifest + " -o " + (dir / "out").string() + "/ --summary " +
                           (dir / "whole.jsonl").string())
                  .status,
              0);
    const std::vector<nlohmann::json> whole = readSummary(dir / "whole.jsonl");
    ASSERT_EQ(whole.size(), 3U);
    for (std::size_t i = 0; i < whole.size(); ++i) EXPECT_EQ(stable(whole[i]), stable(merged[i]));
}

TEST(BatchCommandTest, ProgressIsSilentWhenStderrIsNotATerminal) {
    const fs::path dir = caliper3d::test::freshScratchFolder("batch_progress");
    ASSERT_EQ(runCaliper3d("synth --field 2 --length 30 -o " + dir.string() + "/").status, 0);
    const std::string args =
        "batch " + (dir / "manifest.csv").string() + " -o " + (dir / "out").string() + "/";
    const CommandRun piped = runCaliper3dStderr(args);
    ASSERT_EQ(piped.status, 0) << piped.output;
    EXPECT_EQ(piped.output.find('\r'), std::string::npos) << piped.output;
    EXPECT_EQ(piped.output.find("[1/2"), std::string::npos) << piped.output;
    // On a terminal (script(1) gives it one) the line shows the wells done of the total.
    if (std::system("command -v script >/dev/null 2>&1") != 0) GTEST_SKIP() << "no script(1)";
    const std::string command =
        "script -qec '" + std::string(CALIPER3D_BINARY) + " " + args + " >/dev/null' /dev/null";
    FILE* pipe = popen(command.c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    std::string terminal;
    char buffer[4096];
    while (std::fgets(buffer, sizeof buffer, pipe)) terminal += buffer;
    pclose(pipe);
    EXPECT_NE(terminal.find("[2/2]"), std::string::npos) << terminal;
}

TEST(ManyInputsTest, ReportWritesOneReportPerFileWhereTheFolderOrPatternSays) {
    const fs::path dir = caliper3d::test::freshScratchFolder("many_report");
    const std::string a = synth(dir / "A.las", "example");
    const std::string b = synth(dir / "B.txt", "washout");
    const CommandRun folder = runCaliper3d("report " + a + " " + b + " -o " + (dir / "f").string() +
                                           "/ --zones " + (dir / "f").string() + "/");
    ASSERT_EQ(folder.status, 0) << folder.output;
    for (const char* name : {"A.csv", "A-zones.csv", "B.csv", "B-zones.csv"})
        EXPECT_TRUE(fs::exists(dir / "f" / name)) << name;
    const CommandRun pattern =
        runCaliper3d("report " + a + " " + b + " " + (dir / "missing.las").string() + " -o '" +
                     (dir / "p").string() + "/{index}-{stem}.csv'");
    EXPECT_EQ(pattern.status, 1) << pattern.output;
    EXPECT_TRUE(fs::exists(dir / "p" / "0-A.csv"));
    EXPECT_TRUE(fs::exists(dir / "p" / "1-B.csv"));
    // One file for several reports is refused, as are two inputs writing one name.
    EXPECT_EQ(runCaliper3d("report " + a + " " + b + " -o " + (dir / "one.csv").string()).status,
              2);
    EXPECT_EQ(runCaliper3d("report " + a + " " + a + " -o " + (dir / "d").string() + "/").status,
              2);
}

TEST(ManyInputsTest, ExportWritesOneFilePerInputOrOneSceneForAll) {
    const fs::path dir = caliper3d::test::freshScratchFolder("many_export");
    const std::string a = synth(dir / "A.las", "example", 30.0);
    const std::string b = synth(dir / "B.txt", "circle", 30.0);
    const CommandRun each = runCaliper3d("export " + a + " " + b + " -o " + (dir / "e").string() +
                                         "/ --summary " + (dir / "each.jsonl").string());
    ASSERT_EQ(each.status, 0) << each.output;
    EXPECT_TRUE(fs::exists(dir / "e" / "A.iv"));
    EXPECT_TRUE(fs::exists(dir / "e" / "B.iv"));
    const CommandRun one =
        runCaliper3d("export " + a + " " + b + " " + (dir / "missing.las").string() + " -o " +
                     (dir / "all.iv").string() + " --summary " + (dir / "one.jsonl").string());
    EXPECT_EQ(one.status, 1) << one.output;
    EXPECT_NE(one.output.find("(2 wells)"), std::string::npos) << one.output;
    const std::vector<nlohmann::json> lines = readSummary(dir / "one.jsonl");
    ASSERT_EQ(lines.size(), 3U);
    EXPECT_EQ(lines[0]["outputs"][0], (dir / "all.iv").string());
    EXPECT_EQ(lines[1]["outputs"][0], (dir / "all.iv").string());
    EXPECT_EQ(lines[0]["rows"], 301);
    EXPECT_EQ(lines[2]["status"], "failed");
    EXPECT_EQ(lines[2].count("outputs"), 0U);
}

TEST(ManyInputsTest, RenderDrawsOnePicturePerInputWithAPattern) {
    const fs::path dir = caliper3d::test::freshScratchFolder("many_render");
    const std::string a = synth(dir / "A.las", "example", 30.0);
    const std::string b = synth(dir / "B.txt", "circle", 30.0);
    const CommandRun r = runCaliper3d("render " + a + " " + b + " -o '" + (dir / "p").string() +
                                      "/{stem}-east.png' --view east --width 96 --height 64 "
                                      "--summary " +
                                      (dir / "s.jsonl").string());
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_TRUE(fs::exists(dir / "p" / "A-east.png"));
    EXPECT_TRUE(fs::exists(dir / "p" / "B-east.png"));
    const std::vector<nlohmann::json> lines = readSummary(dir / "s.jsonl");
    ASSERT_EQ(lines.size(), 2U);
    EXPECT_EQ(lines[1]["verb"], "render");
    EXPECT_EQ(lines[1]["outputs"][0], (dir / "p" / "B-east.png").string());
}

TEST(ManyInputsTest, InfoSummaryGivesRowsAndDepthsAndTheReadersReason) {
    const fs::path dir = caliper3d::test::freshScratchFolder("many_info");
    const std::string a = synth(dir / "A.las", "example", 30.0);
    const fs::path bad = badLineLog(dir);
    const CommandRun r =
        runCaliper3d("info " + a + " " + bad.string() + " --summary " + (dir / "s.jsonl").string());
    EXPECT_EQ(r.status, 1) << r.output;
    const std::vector<nlohmann::json> lines = readSummary(dir / "s.jsonl");
    ASSERT_EQ(lines.size(), 2U);
    EXPECT_EQ(lines[0]["status"], "ok");
    EXPECT_EQ(lines[0]["rows"], 301);
    EXPECT_DOUBLE_EQ(lines[0]["depth_m"][1].get<double>(), 30.0);
    EXPECT_EQ(lines[1]["status"], "failed");
    EXPECT_EQ(lines[1]["error"]["line"], 6);
    EXPECT_EQ(lines[1]["error"]["reason"], "expected 12 named columns, found 3 values");
}
