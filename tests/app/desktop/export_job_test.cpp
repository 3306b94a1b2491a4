#include "app/desktop/export_job.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <QEventLoop>
#include <QTimer>

#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/nodes/SoSeparator.h>

#include "desk_test_support.h"
#include "io/atomic_output.h"
#include "io/column_text_writer.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "scenegraph/main_thread.h"

using namespace caliper3d;

namespace {

std::string writeWell(const std::string& name, double length_m, double step_m) {
    const auto path = test::scratch(name);
    io::writeColumnTextFile(path.string(),
                            reconstruction::makeSyntheticWell(
                                reconstruction::syntheticProfile("example", length_m, step_m)));
    return path.string();
}

struct Outcome {
    bool ended = false;
    bool ok = false;
    QString message;
    std::vector<std::pair<int, int>> progress;
};

// Runs `job` until it ends (at most `ms`); `onProgress` may act on each progress line.
Outcome run(app::ExportJob& job, int ms, const std::function<void()>& onProgress = {}) {
    Outcome out;
    QEventLoop loop;
    QObject::connect(&job, &app::ExportJob::progress, &loop, [&](int done, int total) {
        out.progress.emplace_back(done, total);
        if (onProgress) onProgress();
    });
    QObject::connect(&job, &app::ExportJob::finished, &loop, [&](bool ok, const QString& m) {
        out.ended = true;
        out.ok = ok;
        out.message = m;
        loop.quit();
    });
    QTimer::singleShot(ms, &loop, &QEventLoop::quit);
    job.start();
    loop.exec();
    return out;
}

// The temporaries of `target` in its folder (an export writes one, then renames it).
std::vector<std::string> temporariesOf(const std::filesystem::path& target) {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(target.parent_path()))
        if (io::isTemporaryOf(entry.path().filename().string(), target.filename().string()))
            names.push_back(entry.path().string());
    return names;
}

}  // namespace

TEST(ExportJobTest, ReadsProgressLines) {
    int done = 0, total = 0;
    EXPECT_TRUE(app::ExportJob::parseProgress("progress 12/340 segments", done, total));
    EXPECT_EQ(done, 12);
    EXPECT_EQ(total, 340);
    EXPECT_TRUE(app::ExportJob::parseProgress("progress 3/3 steps", done, total));
    EXPECT_FALSE(app::ExportJob::parseProgress("caliper3d: progress 1/2 x", done, total));
    EXPECT_FALSE(app::ExportJob::parseProgress("progress 4/3 steps", done, total));
    EXPECT_FALSE(app::ExportJob::parseProgress("progress 1/0 steps", done, total));
}

TEST(ExportJobTest, WritesAReadableIvThroughTheChildProcess) {
    const test::EventLoopApplication application;
    scenegraph::initCoin();  // to read the file back
    const std::string log = writeWell("export_job.txt", 30.0, 0.05);
    const auto out = test::scratch("export_job.iv");
    std::filesystem::remove(out);
    app::LoadOptions options;
    options.read.bitSize_mm = 215.9;
    options.radialExaggeration = 10.0;
    app::ExportJob job(CALIPER3D_BINARY, {{log, "", {}}}, options,
                       QString::fromStdString(out.string()));
    const Outcome outcome = run(job, 60000);
    ASSERT_TRUE(outcome.ended);
    ASSERT_TRUE(outcome.ok) << outcome.message.toStdString();
    ASSERT_FALSE(outcome.progress.empty());
    EXPECT_EQ(outcome.progress.back().first, outcome.progress.back().second);
    EXPECT_TRUE(temporariesOf(out).empty());

    SoInput input;
    ASSERT_TRUE(input.openFile(out.c_str()));
    SoSeparator* root = SoDB::readAll(&input);
    ASSERT_NE(root, nullptr);
    root->ref();
    EXPECT_GT(root->getNumChildren(), 0);
    root->unref();
}

TEST(ExportJobTest, CancelStopsTheChildAndLeavesNoFile) {
    const test::EventLoopApplication application;
    const std::string log = writeWell("export_cancel.txt", 400.0, 0.01);
    const auto out = test::scratch("export_cancel.glb");
    std::filesystem::remove(out);
    app::ExportJob job(CALIPER3D_BINARY, {{log, "", {}}}, {}, QString::fromStdString(out.string()));
    bool cancelled = false;
    const Outcome outcome = run(job, 60000, [&] {
        if (cancelled) return;
        cancelled = true;
        job.cancel();  // at the first line: the well is still being read
    });
    ASSERT_TRUE(outcome.ended);
    EXPECT_FALSE(outcome.ok);
    EXPECT_TRUE(outcome.message.contains("cancelled")) << outcome.message.toStdString();
    EXPECT_FALSE(job.running());
    EXPECT_FALSE(std::filesystem::exists(out));
    EXPECT_TRUE(temporariesOf(out).empty());
}

TEST(ExportJobTest, AFailedExportNamesTheFileAndLeavesTheOldOneAsItWas) {
    const test::EventLoopApplication application;
    const auto bad = test::scratch("export_bad.txt");
    std::ofstream(bad) << "{\"not\": \"a log\"}\n";
    const auto out = test::scratch("export_bad.iv");
    std::ofstream(out) << "old\n";
    app::ExportJob job(CALIPER3D_BINARY, {{bad.string(), "", {}}}, {},
                       QString::fromStdString(out.string()));
    const Outcome outcome = run(job, 60000);
    ASSERT_TRUE(outcome.ended);
    EXPECT_FALSE(outcome.ok);
    EXPECT_TRUE(outcome.message.startsWith(QString::fromStdString(out.string())))
        << outcome.message.toStdString();
    EXPECT_TRUE(outcome.message.contains(QString::fromStdString(bad.string()) + ":1"))
        << outcome.message.toStdString();
    std::ifstream in(out);
    std::string first;
    std::getline(in, first);
    EXPECT_EQ(first, "old");
    EXPECT_TRUE(temporariesOf(out).empty());
}

TEST(ExportJobTest, TheChildIsGivenNoDisplay) {
    // The export only writes a file: without DISPLAY the child can neither open the window's
    // display nor fail where that display refuses a connection. A script stands in for the
    // program and writes down the environment it was given.
    const test::EventLoopApplication application;
    const std::string log = writeWell("export_env.txt", 10.0, 0.1);
    const auto script = test::scratch("export_env.sh");
    const auto seen = test::scratch("export_env_seen.txt");
    std::filesystem::remove(seen);
    std::ofstream(script) << "#!/bin/sh\nenv > '" << seen.string() << "'\n";
    std::filesystem::permissions(script, std::filesystem::perms::owner_all);
    const QByteArray display = qgetenv("DISPLAY");
    qputenv("DISPLAY", ":31999");
    qputenv("WAYLAND_DISPLAY", "wayland-31999");
    app::ExportJob job(QString::fromStdString(script.string()), {{log, "", {}}}, {},
                       QString::fromStdString(test::scratch("export_env.iv").string()));
    qunsetenv("WAYLAND_DISPLAY");
    if (display.isNull())
        qunsetenv("DISPLAY");
    else
        qputenv("DISPLAY", display);
    const Outcome outcome = run(job, 60000);
    ASSERT_TRUE(outcome.ended);
    std::ifstream in(seen);
    ASSERT_TRUE(in) << "the script did not run: " << outcome.message.toStdString();
    int lines = 0;
    for (std::string line; std::getline(in, line); ++lines) {
        EXPECT_NE(line.rfind("DISPLAY=", 0), 0U) << line;
        EXPECT_NE(line.rfind("WAYLAND_DISPLAY=", 0), 0U) << line;
    }
    EXPECT_GT(lines, 0);
}
