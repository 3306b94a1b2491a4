#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <assimp/scene.h>
#include <gtest/gtest.h>
#include <assimp/Importer.hpp>
#include "cli_run.h"
#include "test_support.h"

namespace {
using caliper3d::test::CommandRun;
CommandRun run(const std::string& arguments) {
    return caliper3d::test::runCaliper3d(arguments);
}
}  // namespace

TEST(CommandLineTest, SynthThenExportWritesAnInventorFile) {
    const auto log = caliper3d::test::scratch("cli_synth.txt");
    const auto iv = caliper3d::test::scratch("cli_synth.iv");
    std::filesystem::remove(iv);
    CommandRun synth = run("synth -o " + log.string() + " --length 30 --step 0.1");
    ASSERT_EQ(synth.status, 0) << synth.output;
    EXPECT_NE(synth.output.find("301 sections"), std::string::npos) << synth.output;
    const auto header = [&iv] {
        std::ifstream in(iv);
        std::string line;
        std::getline(in, line);
        return line;
    };
    CommandRun exported = run("export " + log.string() + " -o " + iv.string());
    ASSERT_EQ(exported.status, 0) << exported.output;
    EXPECT_EQ(header().rfind("#Inventor V2.1 binary", 0), 0u) << header();
    exported = run("export " + log.string() + " -o " + iv.string() + " --ascii");
    ASSERT_EQ(exported.status, 0) << exported.output;
    EXPECT_EQ(header().rfind("#Inventor V2.1 ascii", 0), 0u) << header();
    exported = run("export " + log.string() + " -o " + iv.string() + " --ascii --binary");
    EXPECT_EQ(exported.status, 2) << exported.output;
    EXPECT_NE(exported.output.find("not both"), std::string::npos) << exported.output;
}

TEST(CommandLineTest, ExportWritesTheMeshFormatItsExtensionNames) {
    const auto log = caliper3d::test::scratch("cli_mesh_example.txt");
    ASSERT_EQ(run("synth --profile example -o " + log.string() + " --length 30 --step 0.1").status,
              0);
    const auto glb = caliper3d::test::scratch("cli_example.glb");
    std::filesystem::remove(glb);
    CommandRun exported = run("export " + log.string() + " -o " + glb.string());
    ASSERT_EQ(exported.status, 0) << exported.output;
    // Rows 0.1 m apart: 3 segments of 100 rows (10 m), one mesh each; the triangles it
    // reports are those in the file.
    EXPECT_NE(exported.output.find("(1 well, 3 meshes, "), std::string::npos) << exported.output;
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(glb.string(), 0);
    ASSERT_NE(scene, nullptr) << importer.GetErrorString();
    ASSERT_EQ(scene->mNumMeshes, 3u);
    std::size_t faces = 0;
    for (unsigned int m = 0; m < scene->mNumMeshes; ++m) faces += scene->mMeshes[m]->mNumFaces;
    EXPECT_NE(exported.output.find(" vertices, " + std::to_string(faces) + " triangles)"),
              std::string::npos)
        << exported.output;
    EXPECT_TRUE(scene->mMeshes[0]->HasVertexColors(0));

    // The same well at full detail: every section, 2 x 48 triangles between rows.
    exported = run("export " + log.string() + " -o " + glb.string() + " --detail full");
    ASSERT_EQ(exported.status, 0) << exported.output;
    EXPECT_NE(exported.output.find(" vertices, " + std::to_string(2 * 48 * 300) + " triangles)"),
              std::string::npos)
        << exported.output;

    for (const char* name : {"cli_example.ply", "cli_example.stl", "cli_example.obj"}) {
        const auto out = caliper3d::test::scratch(name);
        exported = run("export " + log.string() + " -o " + out.string());
        ASSERT_EQ(exported.status, 0) << exported.output;
        Assimp::Importer again;
        const aiScene* read = again.ReadFile(out.string(), 0);
        ASSERT_NE(read, nullptr) << name << ": " << again.GetErrorString();
        std::size_t readFaces = 0;
        for (unsigned int m = 0; m < read->mNumMeshes; ++m)
            readFaces += read->mMeshes[m]->mNumFaces;
        EXPECT_EQ(readFaces, faces) << name;
    }
}

TEST(CommandLineTest, ExportRefusesAnUnknownExtensionOrAnOptionTheFormatIgnores) {
    const auto log = caliper3d::test::scratch("cli_mesh_usage.txt");
    ASSERT_EQ(run("synth -o " + log.string() + " --length 5 --step 0.1").status, 0);
    const std::string input = "export " + log.string() + " -o ";
    CommandRun r = run(input + caliper3d::test::scratch("x.dae").string());
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("the output must end in .iv, .iv.gz, .glb, .ply, .stl or .obj"),
              std::string::npos)
        << r.output;
    EXPECT_FALSE(std::filesystem::exists(caliper3d::test::scratch("x.dae")));
    r = run(input + caliper3d::test::scratch("x.glb").string() + " --gzip");
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("--gzip applies to .iv only"), std::string::npos) << r.output;
    for (const char* name : {"x.obj", "x.ply", "x.glb"}) {
        r = run(input + caliper3d::test::scratch(name).string() + " --ascii");
        EXPECT_EQ(r.status, 2) << r.output;
        EXPECT_NE(r.output.find("--ascii and --binary apply to .iv and .stl"), std::string::npos)
            << r.output;
    }
    // STL is binary unless --ascii asks for text, as Inventor is.
    const auto firstWord = [](const std::filesystem::path& path) {
        std::ifstream in(path);
        std::string word;
        in >> word;
        return word;
    };
    const auto stl = caliper3d::test::scratch("cli_ascii.stl");
    ASSERT_EQ(run(input + stl.string()).status, 0);
    EXPECT_NE(firstWord(stl), "solid");
    r = run(input + stl.string() + " --ascii");
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(firstWord(stl), "solid");
}

TEST(CommandLineTest, BadInputExitsOneNamingFileAndLine) {
    const auto bad = caliper3d::test::scratch("cli_bad.txt");
    { std::ofstream(bad) << "1 2 3 4 5 6 7 8 9 10\n2 2 3 4 5 6 7 8 9\n3 2 3 4 5 6 7 8 9 10\n"; }
    CommandRun r =
        run("export " + bad.string() + " -o " + caliper3d::test::scratch("cli_bad.iv").string());
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find(bad.string() + ":2"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("expected 10 columns"), std::string::npos) << r.output;
}

TEST(CommandLineTest, BatchKeepsGoingPastABadFile) {
    const auto good = caliper3d::test::scratch("cli_good.txt");
    const auto bad = caliper3d::test::scratch("cli_bad2.txt");
    { std::ofstream(bad) << "not numbers at all\n"; }
    ASSERT_EQ(run("synth -o " + good.string() + " --length 20 --step 0.5").status, 0);
    const auto iv = caliper3d::test::scratch("cli_batch.iv");
    CommandRun r = run("export " + bad.string() + " " + good.string() + " -o " + iv.string());
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find(good.string() + ": 41 sections"), std::string::npos) << r.output;
    EXPECT_TRUE(std::filesystem::exists(iv));
}

TEST(CommandLineTest, BadUsageExitsTwo) {
    EXPECT_EQ(run("frobnicate").status, 2);
    EXPECT_EQ(run("export").status, 2);
    EXPECT_EQ(run("export x.txt").status, 2);  // no -o
    EXPECT_EQ(run("synth -o x.txt --step -1").status, 2);
    EXPECT_EQ(run("render x.txt -o x.png --view sideways").status, 2);
    EXPECT_EQ(run("export x.txt -o x.iv --arms 1").status, 2);
    EXPECT_EQ(run("--help").status, 0);
}

TEST(CommandLineTest, AnglesOutOfRangeExitOneNamingFileAndLine) {
    const auto text = caliper3d::test::scratch("cli_inc181.txt");
    {
        std::ofstream(text) << "1 4 4 4 4 4 4 10 1 20\n2 4 4 4 4 4 4 10 181 20\n"
                               "3 4 4 4 4 4 4 10 1 20\n";
    }
    CommandRun r = run("report " + text.string() + " -o " +
                       caliper3d::test::scratch("cli_inc181.csv").string());
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find(text.string() + ":2: expected an inclination from 0 to 180 degrees"),
              std::string::npos)
        << r.output;
    const auto las = caliper3d::test::scratch("cli_azi361.las");
    {
        std::ofstream(las) << "~V\n VERS. 2.0 :\n WRAP. NO :\n~C\n DEPT.M :\n R1.MM :\n R2.MM :\n"
                              " R3.MM :\n HAZI.DEG :\n~A\n1 100 100 100 10\n2 100 100 100 361\n";
    }
    r = run("export " + las.string() + " -o " + caliper3d::test::scratch("cli_azi361.iv").string());
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find(las.string() + ":12: expected a hole azimuth from 0 to 360 degrees"),
              std::string::npos)
        << r.output;
}

TEST(CommandLineTest, InfoShowsDepthReferenceLocationAndHoleAzimuth) {
    const auto star =
        caliper3d::test::sharedData() / "real" / "1AA072209208W400_WL_0477502_STAR_FIELD.las";
    const auto fmi = caliper3d::test::sharedData() / "real" / "1AA063409108W400_FMI_SONIC_MAIN.las";
    CALIPER3D_REQUIRE_DATA(star);
    CALIPER3D_REQUIRE_DATA(fmi);
    const CommandRun r = run("info " + star.string() + " " + fmi.string());
    EXPECT_EQ(r.status, 0) << r.output;
    for (const char* shown :
         {"depth ref: K.B., elevation 440.70 m from EKB", "lat/long:  57.017500, -111.419000",
          "UWI:       1AA072209208W400", "hole azi:  unknown: no HAZI curve",
          "depth ref: KB, elevation 449.00 m from EREF", "lat/long:  56.934500, -111.205400",
          "UWI:       1AA063409108W400", "hole azi:  from HAZI"})
        EXPECT_NE(r.output.find(shown), std::string::npos) << shown << "\n" << r.output;
}

TEST(CommandLineTest, VerbsThatOpenNoWindowRunWhereNoDisplayCanBeReached) {
    // Only view opens a window. With Qt told to use X and a display named that no server
    // answers, every other verb still does its work: none connects to a display at all.
    const std::string noDisplay = "env -u WAYLAND_DISPLAY DISPLAY=:31999 QT_QPA_PLATFORM=xcb";
    const auto folder = caliper3d::test::scratch("no_display");
    std::filesystem::create_directories(folder);
    const std::string log = (folder / "well.las").string();
    const std::string iv = (folder / "well.iv").string();
    { std::ofstream(folder / "manifest.csv") << "file,verb\nwell.las,report\n"; }
    const std::vector<std::string> runs = {
        "synth -o " + log + " --length 20 --step 0.1",
        "info " + log,
        "report " + log + " -o " + (folder / "well.csv").string() + " --zones " +
            (folder / "zones.csv").string() + " --las " + (folder / "report.las").string(),
        "export " + log + " -o " + iv,
        "export " + log + " -o " + (folder / "well.glb").string(),
        "render " + log + " -o " + (folder / "well.png").string() + " --width 64 --height 48",
        "batch " + (folder / "manifest.csv").string() + " -o " + (folder / "batch").string() + "/",
    };
    for (const std::string& arguments : runs) {
        const CommandRun r = caliper3d::test::runCaliper3dStderr(arguments, noDisplay);
        EXPECT_EQ(r.status, 0) << arguments << ":\n" << r.output;
        EXPECT_EQ(r.output.find("display"), std::string::npos) << arguments << ":\n" << r.output;
    }
    std::ifstream in(iv);
    std::string header;
    std::getline(in, header);
    EXPECT_EQ(header.rfind("#Inventor V2.1", 0), 0U) << header;
}

// Every verb takes --survey and --wellhead (once per file); info shows what each well is given.
TEST(CommandLineTest, InfoTakesSurveyAndWellheadAndShowsThem) {
    const auto folder = caliper3d::test::scratch("info_survey");
    std::filesystem::create_directories(folder);
    const std::string log = (folder / "well.las").string();
    const std::string survey = (folder / "survey.csv").string();
    ASSERT_EQ(run("synth -o " + log + " --length 30 --step 0.1").status, 0);
    { std::ofstream(survey) << "MD,INC,AZI\n0,0,0\n50,2,90\n100,4,90\n"; }
    const CommandRun r =
        run("info " + log + " --survey " + survey + " --wellhead 512300,6801200,25.5");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("survey:    " + survey + ": 3 stations, MD 0.00 to 100.00 m"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("wellhead:  E 512300.00 m, N 6801200.00 m, elevation 25.50 m"),
              std::string::npos)
        << r.output;
    // Once per file, as for every verb.
    EXPECT_EQ(run("info " + log + " " + log + " --survey " + survey).status, 2);
    // A survey that cannot be read fails that file, naming the survey.
    const CommandRun bad = run("info " + log + " --survey " + (folder / "none.csv").string());
    EXPECT_EQ(bad.status, 1) << bad.output;
    EXPECT_NE(bad.output.find("none.csv"), std::string::npos) << bad.output;
}

// A synthetic log with these lines added to its ~Well section.
std::string logWithWellItems(const std::filesystem::path& folder, const std::string& name,
                             const std::string& items) {
    const std::string log = (folder / name).string();
    EXPECT_EQ(run("synth -o " + log + " --length 20 --step 0.1").status, 0);
    std::ifstream in(log);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::size_t well = text.find("~W");
    text.insert(text.find('\n', well) + 1, items);
    std::ofstream(log) << text;
    return log;
}

// info shows where the header places a well, the projection, and the offsets of a field.
TEST(CommandLineTest, InfoShowsTheHeaderPlacementAndItsProjection) {
    const auto folder = caliper3d::test::freshScratchFolder("info_placement");
    const std::string a = logWithWellItems(
        folder, "a.las", " LATI. 60 30 15.24 N :\n LONG. 2 27 36.9 E :\n LMF. KB :\n EKB.M 25 :\n");
    const std::string b =
        logWithWellItems(folder, "b.las", " LAT. 60.5 :\n LON. 2.4 :\n EREF.M 40 :\n");
    const std::string bare = logWithWellItems(folder, "bare.las", "");
    const CommandRun r = run("info " + a + " " + b + " " + bare);
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("placement: from the header's lat/long (WGS 84: no datum named), UTM "
                            "zone 31N (EPSG:32631): E "),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("elevation KB 25.00 m (EKB)\n           the scene origin\n"),
              std::string::npos)
        << r.output;
    // b: 60.5 N 2.4 E; a and b in UTM zone 31N by GeographicLib (a different implementation
    // from PROJ's): a E 470353.531 N 6707690.204 (meridian convergence -0.469798 degrees),
    // b E 467039.983 N 6707247.375; the grid offset (-3313.548 E, -442.829 N) turned to true
    // north at a: 469.984 m south, 3309.805 m west. b's reference is 15 m higher.
    const std::size_t line = r.output.find("m north, ");
    ASSERT_NE(line, std::string::npos) << r.output;
    double north = 0, east = 0, down = 0;
    ASSERT_EQ(std::sscanf(r.output.c_str() + r.output.rfind('\n', line) + 1,
                          " %lf m north, %lf m east, %lf m down", &north, &east, &down),
              3)
        << r.output;
    EXPECT_NEAR(north, -469.984, 0.5);
    EXPECT_NEAR(east, -3309.805, 0.5);
    EXPECT_DOUBLE_EQ(down, -15.0);
    EXPECT_NE(r.output.find("placement: at the first well's head (not placed): the header gives "
                            "no latitude/longitude or map coordinates"),
              std::string::npos)
        << r.output;
    // --wellhead decides; alone, a file without coordinates opens at the origin and says why.
    const CommandRun given = run("info " + a + " --wellhead 1,2,3");
    EXPECT_NE(given.output.find("placement: by --wellhead: E 1.00 N 2.00, elevation 3.00 m"),
              std::string::npos)
        << given.output;
    const CommandRun alone = run("info " + bare);
    EXPECT_NE(alone.output.find("placement: at the scene origin: the header gives no "
                                "latitude/longitude or map coordinates"),
              std::string::npos)
        << alone.output;
}

// synth --field writes header coordinates: its three wells open on a ring, 25 m from one
// another, their kelly bushings 1 and 2 m higher than the first's.
TEST(CommandLineTest, SynthFieldOpensAtItsHeaderPlaces) {
    const auto folder = caliper3d::test::freshScratchFolder("synth_field_places");
    ASSERT_EQ(run("synth --field 3 --length 20 -o " + folder.string() + "/").status, 0);
    std::string files;
    for (int w = 0; w < 3; ++w)
        files += " " + (folder / ("well-00" + std::to_string(w) + ".las")).string();
    const CommandRun r = run("info" + files);
    ASSERT_EQ(r.status, 0) << r.output;
    std::vector<std::array<double, 3>> offsets;
    for (std::size_t at = r.output.find("placement: from"); at != std::string::npos;
         at = r.output.find("placement: from", at + 1)) {
        const std::size_t line = r.output.find('\n', at) + 1;
        std::array<double, 3> o{0.0, 0.0, 0.0};
        if (std::sscanf(r.output.c_str() + line, " %lf m north, %lf m east, %lf m down", &o[0],
                        &o[1], &o[2]) != 3)
            o = {0.0, 0.0, 0.0};  // "the scene origin"
        offsets.push_back(o);
    }
    ASSERT_EQ(offsets.size(), 3U) << r.output;
    // Grid metres differ from the ground's by the scale factor, 0.9996 near the zone's
    // middle: 1 cm over 25 m.
    const auto apart = [&offsets](std::size_t a, std::size_t b) {
        return std::hypot(offsets[a][0] - offsets[b][0], offsets[a][1] - offsets[b][1]);
    };
    EXPECT_NEAR(apart(0, 1), 25.0, 0.5);
    EXPECT_NEAR(apart(1, 2), 25.0, 0.5);
    EXPECT_NEAR(apart(2, 0), 25.0, 0.5);
    EXPECT_DOUBLE_EQ(offsets[1][2], -1.0);
    EXPECT_DOUBLE_EQ(offsets[2][2], -2.0);
}

// synth --field names each well after its file (FIELD-000 in well-000.las), in the LAS header.
TEST(CommandLineTest, SynthFieldNamesEveryWell) {
    const auto folder = caliper3d::test::scratch("synth_field_names");
    std::filesystem::remove_all(folder);
    ASSERT_EQ(run("synth --field 3 --length 20 -o " + folder.string() + "/").status, 0);
    for (int w = 0; w < 3; ++w) {
        const std::string file = (folder / ("well-00" + std::to_string(w) + ".las")).string();
        const CommandRun info = run("info " + file);
        EXPECT_EQ(info.status, 0) << info.output;
        EXPECT_NE(info.output.find("well:      FIELD-00" + std::to_string(w) + "\n"),
                  std::string::npos)
            << info.output;
    }
}

// view --stats, for benchmarks: the window opens the wells, draws them, loads them, says when
// and how much memory it took, and closes itself.
TEST(CommandLineTest, ViewStatsTimesTheFirstPictureAndTheLoadThenCloses) {
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no display (run under xvfb-run)";
    const auto folder = caliper3d::test::scratch("view_stats");
    std::filesystem::remove_all(folder);
    ASSERT_EQ(run("synth --field 2 -o " + folder.string() + "/ --length 100 --step 0.1").status, 0);
    const CommandRun r = run("view --stats " + (folder / "well-000.las").string() + " " +
                             (folder / "well-001.las").string());
    EXPECT_EQ(r.status, 0) << r.output;
    const auto line = r.output.find("first_picture_ms=");
    ASSERT_NE(line, std::string::npos) << r.output;
    double first = -1.0, complete = -1.0, settled = -1.0, rss = -1.0, open = -1.0;
    int frames = -1;
    ASSERT_EQ(std::sscanf(r.output.c_str() + line,
                          "first_picture_ms=%lf complete_ms=%lf settled_ms=%lf rss_mb=%lf "
                          "frames_loading=%d open_ms=%lf",
                          &first, &complete, &settled, &rss, &frames, &open),
              6)
        << r.output;
    EXPECT_GT(first, 0.0);
    EXPECT_GT(complete, 0.0);
    EXPECT_GE(settled, complete);
    EXPECT_GT(rss, 1.0);
    EXPECT_GE(frames, 0);
    // The wells are opened once Qt and the window have started, before anything is drawn.
    EXPECT_GT(open, 0.0);
    EXPECT_LT(open, first);
}
