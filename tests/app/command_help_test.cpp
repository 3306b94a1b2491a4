// What a newcomer types first: help for every verb, a file as the only
// argument, and options that cannot apply (issue: the first five minutes).
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include "app/well_option_table.h"
#include "cli_run.h"
#include "test_support.h"

namespace {

using caliper3d::test::CommandRun;
CommandRun run(const std::string& arguments) {
    return caliper3d::test::runCaliper3d(arguments);
}
CommandRun stdoutOf(const std::string& arguments) {
    return caliper3d::test::runCaliper3d(arguments, false);
}

struct VerbHelp {
    const char* verb;
    const char* ownOption;  // an option only this verb's help lists
};

class VerbHelpTest : public testing::TestWithParam<VerbHelp> {};

TEST_P(VerbHelpTest, HelpDashHAndHelpVerbPrintTheVerbsOwnOptions) {
    const std::string verb = GetParam().verb;
    const CommandRun longForm = stdoutOf(verb + " --help");
    const CommandRun shortForm = stdoutOf(verb + " -h");
    const CommandRun helpVerb = stdoutOf("help " + verb);
    for (const CommandRun* r : {&longForm, &shortForm, &helpVerb}) {
        EXPECT_EQ(r->status, 0) << r->output;
        EXPECT_EQ(r->output.rfind("Usage: caliper3d " + verb + " [options]", 0), 0u) << r->output;
        EXPECT_NE(r->output.find(GetParam().ownOption), std::string::npos) << r->output;
    }
    EXPECT_EQ(longForm.output, shortForm.output);
    EXPECT_EQ(longForm.output, helpVerb.output);
    // Qt's --help-all too prints help and does nothing else.
    const CommandRun helpAll = stdoutOf(verb + " --help-all");
    EXPECT_EQ(helpAll.status, 0) << helpAll.output;
    EXPECT_EQ(helpAll.output.rfind("Usage: caliper3d " + verb + " [options]", 0), 0u)
        << helpAll.output;
}

INSTANTIATE_TEST_SUITE_P(
    EveryVerb, VerbHelpTest,
    testing::Values(VerbHelp{"view", "--survey"}, VerbHelp{"info", "--nulls"},
                    VerbHelp{"export", "--ascii"}, VerbHelp{"render", "--view"},
                    VerbHelp{"report", "--casing-od"}, VerbHelp{"synth", "--profile"},
                    VerbHelp{"batch", "--merge"}),
    [](const testing::TestParamInfo<VerbHelp>& info) { return std::string(info.param.verb); });

std::filesystem::path exampleLog() {
    static const std::filesystem::path log = [] {
        const auto path = caliper3d::test::scratch("help_example.txt");
        const CommandRun r = run("synth -o " + path.string() + " --length 40 --step 0.1");
        EXPECT_EQ(r.status, 0) << r.output;
        return path;
    }();
    return log;
}

}  // namespace

TEST(CommandHelpTest, EveryOptionOfTheTableIsInTheHelpOfEachVerbThatTakesIt) {
    for (const std::string verb : {"view", "info", "export", "render", "report"}) {
        const CommandRun help = stdoutOf("help " + verb);
        ASSERT_EQ(help.status, 0) << help.output;
        for (const caliper3d::app::WellOption& option : caliper3d::app::wellOptions()) {
            const std::string listed =
                std::string("--") + option.name + " <" + option.valueName + ">";
            EXPECT_EQ(help.output.find(listed) != std::string::npos,
                      caliper3d::app::takes(verb, option.group))
                << verb << " " << listed << "\n"
                << help.output;
        }
    }
}

TEST(CommandHelpTest, HelpAloneAndHelpOfAnUnknownVerb) {
    const CommandRun usage = stdoutOf("help");
    EXPECT_EQ(usage.status, 0);
    EXPECT_NE(usage.output.find("caliper3d help VERB"), std::string::npos) << usage.output;
    const CommandRun unknown = run("help frobnicate");
    EXPECT_EQ(unknown.status, 2);
    EXPECT_NE(unknown.output.find("unknown verb 'frobnicate'"), std::string::npos)
        << unknown.output;
}

TEST(CommandHelpTest, AFileAsTheFirstArgumentOpensTheWindowOnIt) {
    // With no display the window cannot open, and view says so: proof that the
    // file went to view, not to "unknown verb".
    const std::string file = exampleLog().string();
    const CommandRun r =
        caliper3d::test::runCaliper3dStderr(file, "env -u DISPLAY -u WAYLAND_DISPLAY");
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("caliper3d view: no display"), std::string::npos) << r.output;
    const CommandRun typo = run("exprot " + file);
    EXPECT_EQ(typo.status, 2);
    EXPECT_NE(typo.output.find("unknown verb 'exprot'"), std::string::npos) << typo.output;
}

TEST(CommandHelpTest, RenderPrintsNothingButTheProductsOwnMessages) {
    const std::string png = caliper3d::test::scratch("help_quiet.png").string();
    // Under the test's X server (where Coin's GL glue used to complain about
    // GLX) and with no display at all.
    for (const std::string environment : {"", "env -u DISPLAY -u WAYLAND_DISPLAY"}) {
        const CommandRun r = caliper3d::test::runCaliper3dStderr(
            "render " + exampleLog().string() + " -o " + png + " --width 64 --height 48",
            environment);
        EXPECT_EQ(r.status, 0) << r.output;
        std::istringstream lines(r.output);
        for (std::string line; std::getline(lines, line);)
            ADD_FAILURE() << "not the product's own message on stderr: " << line;
    }
}

TEST(CommandHelpTest, RenderAtOnlyWithTheHoleViewAndWithinTheLog) {
    const std::string log = exampleLog().string();
    const std::string png = caliper3d::test::scratch("help_at.png").string();
    const CommandRun iso = run("render " + log + " -o " + png + " --at 10");
    EXPECT_EQ(iso.status, 2);
    EXPECT_NE(iso.output.find("--at places the eye of --view hole"), std::string::npos)
        << iso.output;
    const CommandRun beyond = run("render " + log + " -o " + png + " --view hole --at 41");
    EXPECT_EQ(beyond.status, 2);
    EXPECT_NE(beyond.output.find("outside the logged depths"), std::string::npos) << beyond.output;
    EXPECT_NE(beyond.output.find("(0.00 to 40.00 m)"), std::string::npos) << beyond.output;
    const CommandRun inside =
        run("render " + log + " -o " + png + " --view hole --at 20 --width 64 --height 48");
    EXPECT_EQ(inside.status, 0) << inside.output;
}

TEST(CommandHelpTest, ExportToAGzipNameWritesGzip) {
    const auto out = caliper3d::test::scratch("help_scene.iv.gz");
    std::filesystem::remove(out);
    const CommandRun r = run("export " + exampleLog().string() + " -o " + out.string());
    ASSERT_EQ(r.status, 0) << r.output;
    std::ifstream in(out, std::ios::binary);
    unsigned char magic[2] = {0, 0};
    in.read(reinterpret_cast<char*>(magic), 2);
    EXPECT_EQ(magic[0], 0x1f);
    EXPECT_EQ(magic[1], 0x8b);
    // The content is the Inventor scene.
    FILE* pipe = popen(("gzip -dc " + out.string() + " | head -c 21").c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    char text[32] = {};
    ASSERT_NE(std::fgets(text, sizeof text, pipe), nullptr);
    pclose(pipe);
    EXPECT_EQ(std::string(text).rfind("#Inventor V2.1 binary", 0), 0u) << text;
    const CommandRun wrongName = run("export " + exampleLog().string() + " -o scene.dae");
    EXPECT_EQ(wrongName.status, 2);
}

TEST(CommandHelpTest, AnUnknownSynthProfileListsTheValidOnes) {
    const CommandRun r = run("synth -o x.txt --profile bogus");
    EXPECT_EQ(r.status, 2);
    for (const char* profile : {"example", "circle", "washout", "keyseat", "stuck-arm", "build"})
        EXPECT_NE(r.output.find(profile), std::string::npos) << profile << "\n" << r.output;
}

TEST(CommandHelpTest, CasingWiderThanTheHoleWarnsAndIsCounted) {
    // The example is drilled with an 8.5 in bit; a 9 in casing cannot fit.
    const std::string csv = caliper3d::test::scratch("help_casing.csv").string();
    const CommandRun wide =
        run("report " + exampleLog().string() + " -o " + csv + " --bit-size 8.5in --casing-od 9in");
    EXPECT_EQ(wide.status, 0) << wide.output;
    EXPECT_NE(wide.output.find("--casing-od 228.6 mm is not smaller than the bit size on 401 of "
                               "401 sections"),
              std::string::npos)
        << wide.output;
    const CommandRun fits =
        run("report " + exampleLog().string() + " -o " + csv + " --bit-size 8.5in --casing-od 7in");
    EXPECT_EQ(fits.status, 0) << fits.output;
    EXPECT_EQ(fits.output.find("--casing-od"), std::string::npos) << fits.output;
}

TEST(CommandHelpTest, OptionsAVerbCannotUseAreErrors) {
    const std::string log = exampleLog().string();
    const CommandRun info = run("info " + log + " --exaggerate 5");
    EXPECT_EQ(info.status, 2);
    EXPECT_NE(info.output.find("--exaggerate does not apply"), std::string::npos) << info.output;
    const CommandRun report = run("report " + log + " -o - --segment-length 5");
    EXPECT_EQ(report.status, 2);
    EXPECT_NE(report.output.find("--segment-length does not apply"), std::string::npos)
        << report.output;
}
