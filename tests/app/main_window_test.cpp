#include "app/desktop/main_window.h"

#include <cstdlib>
#include <fstream>
#include <memory>

#include <gtest/gtest.h>
#include <QApplication>
#include <QEventLoop>
#include <QGLWidget>
#include <QTimer>

#include <Inventor/Qt/viewers/SoQtExaminerViewer.h>

#include "app/desktop/gui_session.h"
#include "app/desktop/well_session.h"
#include "io/column_text_writer.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "scenegraph/label_style.h"
#include "test_support.h"

using namespace caliper3d;

namespace {

class MainWindowTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        if (!app::haveDisplay()) return;
        static int argc = 1;
        static char name[] = "app_tests";
        static char* argv[] = {name, nullptr};
        s_application = new QApplication(argc, argv);
        app::initGui();
    }
    void SetUp() override {
        if (!app::haveDisplay()) GTEST_SKIP() << "no display (run under xvfb-run)";
    }
    // Waits for `signal` on the event loop, at most `ms` milliseconds.
    template <typename Signal>
    static bool waitFor(app::MainWindow& window, Signal signal, int ms) {
        app::WellSession& session = window.session();
        QEventLoop loop;
        bool fired = false;
        QObject::connect(&session, signal, &loop, [&] {
            fired = true;
            loop.quit();
        });
        QTimer::singleShot(ms, &loop, &QEventLoop::quit);
        loop.exec();
        return fired;
    }
    // Runs the event loop until the window's labels are placed for its camera as it is now
    // (they follow the camera once it rests), at most `ms` milliseconds.
    static bool waitForLabels(app::MainWindow& window, int ms) {
        QEventLoop loop;
        QTimer poll;
        QObject::connect(&poll, &QTimer::timeout, &loop, [&] {
            if (window.labelsPlaced()) loop.quit();
        });
        poll.start(10);
        QTimer::singleShot(ms, &loop, &QEventLoop::quit);
        if (!window.labelsPlaced()) loop.exec();
        return window.labelsPlaced();
    }
    static QApplication* s_application;
};
QApplication* MainWindowTest::s_application = nullptr;

}  // namespace

TEST_F(MainWindowTest, OpensTheExampleAndRendersTheWell) {
    const auto log = test::scratch("window_example.txt");
    io::writeColumnTextFile(
        log.string(),
        reconstruction::makeSyntheticWell(reconstruction::syntheticProfile("example", 60.0, 0.1)));
    app::MainWindow window;
    window.resize(1280, 960);
    window.show();
    app::LoadOptions options;
    options.read.bitSize_mm = 215.9;
    window.session().openWell(QString::fromStdString(log.string()), options);
    ASSERT_TRUE(waitFor(window, &app::WellSession::wellLoaded, 60000)) << "the well did not load";
    EXPECT_FALSE(window.session().loading());

    auto* gl = qobject_cast<QGLWidget*>(window.viewer()->getGLWidget());
    ASSERT_NE(gl, nullptr);
    window.viewer()->render();
    const QImage frame = gl->grabFrameBuffer();
    ASSERT_FALSE(frame.isNull());
    const QRgb background = frame.pixel(0, 0);
    std::size_t drawn = 0;
    for (int y = 0; y < frame.height(); ++y)
        for (int x = 0; x < frame.width(); ++x) drawn += frame.pixel(x, y) != background ? 1 : 0;
    // A 60 m well framed whole is a thin line of a few hundred pixels.
    EXPECT_GT(drawn, 200u);
}

namespace {
// Pixels of `frame` within 8 (of 255) of `colour` (0-1) in each channel.
std::size_t pixelsOfColour(const QImage& frame, const float colour[3]) {
    std::size_t count = 0;
    for (int y = 0; y < frame.height(); ++y)
        for (int x = 0; x < frame.width(); ++x) {
            const QRgb p = frame.pixel(x, y);
            const int rgb[3] = {qRed(p), qGreen(p), qBlue(p)};
            bool close = true;
            for (int c = 0; c < 3; ++c)
                close = close && std::abs(rgb[c] - int(colour[c] * 255.0f + 0.5f)) <= 8;
            count += close ? 1 : 0;
        }
    return count;
}
}  // namespace

TEST_F(MainWindowTest, ShowsDepthLabelsTheWellsNameAndTheNorthArrow) {
    const auto log = test::scratch("window_labels.txt");
    io::writeColumnTextFile(
        log.string(),
        reconstruction::makeSyntheticWell(reconstruction::syntheticProfile("example", 60.0, 0.1)));
    app::MainWindow window;
    window.resize(1280, 960);
    window.show();
    app::LoadOptions options;
    options.radialExaggeration = 10.0;
    window.session().keepExaggeration();  // as caliper3d view --exaggerate 10
    window.session().openWell(QString::fromStdString(log.string()), options);
    ASSERT_TRUE(waitFor(window, &app::WellSession::allWellsLoaded, 60000))
        << "the well did not load";
    ASSERT_TRUE(waitForLabels(window, 10000)) << "the labels were not placed for the camera";
    auto* gl = qobject_cast<QGLWidget*>(window.viewer()->getGLWidget());
    ASSERT_NE(gl, nullptr);
    window.viewer()->render();
    const QImage frame = gl->grabFrameBuffer();
    frame.save(QString::fromStdString(test::scratch("window_labels.png").string()));
    // Labels of the ticks every 5 m and the caption; the file's name at the wellhead (a
    // column-text log has no WELL field); the arrow's north in red.
    EXPECT_GT(pixelsOfColour(frame, scenegraph::kLabelColour), 300u);
    EXPECT_GT(pixelsOfColour(frame, scenegraph::kNameColour), 40u);
    const float north[3] = {0.95f, 0.30f, 0.25f};
    EXPECT_GT(pixelsOfColour(frame, north), 20u);
}

TEST_F(MainWindowTest, BadFileReportsFailureWithFileAndLine) {
    const auto bad = test::scratch("window_bad.txt");
    { std::ofstream(bad) << "1 2 3 4 5 6 7 8 9 10\n2 2 3\n3 2 3 4 5 6 7 8 9 10\n"; }
    app::MainWindow window;
    QString message;
    QObject::connect(&window.session(), &app::WellSession::wellFailed,
                     [&](const QString&, const QString& m) { message = m; });
    window.session().openWell(QString::fromStdString(bad.string()), app::LoadOptions{});
    ASSERT_TRUE(waitFor(window, &app::WellSession::wellFailed, 30000));
    EXPECT_TRUE(message.contains(QString::fromStdString(bad.string() + ":2")))
        << message.toStdString();
}

TEST_F(MainWindowTest, ShowsSeveralWellsAtOnce) {
    const auto a = test::scratch("window_a.txt");
    const auto b = test::scratch("window_b.txt");
    io::writeColumnTextFile(a.string(), reconstruction::makeSyntheticWell(
                                            reconstruction::syntheticProfile("circle", 20.0, 0.1)));
    io::writeColumnTextFile(
        b.string(),
        reconstruction::makeSyntheticWell(reconstruction::syntheticProfile("example", 30.0, 0.1)));
    app::MainWindow window;
    int loaded = 0;
    QObject::connect(&window.session(), &app::WellSession::wellLoaded, [&](int) { ++loaded; });
    window.session().openWell(QString::fromStdString(a.string()), app::LoadOptions{});
    window.session().addWell(QString::fromStdString(b.string()), app::LoadOptions{});
    ASSERT_TRUE(waitFor(window, &app::WellSession::allWellsLoaded, 60000));
    EXPECT_EQ(loaded, 2);
    EXPECT_EQ(window.session().wellCount(), 2u);
    EXPECT_FALSE(window.session().loading());
}

TEST_F(MainWindowTest, ReaderWarningsOfALoadedWellAreCountedAndListed) {
    const auto log = test::scratch("window_warned.txt");
    io::writeColumnTextFile(
        log.string(),
        reconstruction::makeSyntheticWell(reconstruction::syntheticProfile("circle", 20.0, 0.5)));
    std::size_t lines = 0;
    {
        std::ifstream in(log);
        std::string line;
        while (std::getline(in, line)) ++lines;
    }
    // A truncated last row: the reader skips it with a warning on its line.
    { std::ofstream(log, std::ios::app) << "20.5 1.0 2.0\n"; }
    app::MainWindow window;
    window.session().openWell(QString::fromStdString(log.string()), app::LoadOptions{});
    ASSERT_TRUE(waitFor(window, &app::WellSession::wellLoaded, 60000)) << "the well did not load";
    EXPECT_EQ(window.session().warningCount(), 1u) << window.session().warningsText().toStdString();
    EXPECT_TRUE(window.session().warningsText().contains(
        QString::fromStdString(log.string() + ":" + std::to_string(lines + 1) + ": warning: ")))
        << window.session().warningsText().toStdString();
    EXPECT_TRUE(window.statusText().endsWith(", 1 warning")) << window.statusText().toStdString();
}

TEST_F(MainWindowTest, RecolouringAndReExaggeratingReuseTheWellInMemory) {
    const auto log = test::scratch("window_restyle.txt");
    io::writeColumnTextFile(
        log.string(),
        reconstruction::makeSyntheticWell(reconstruction::syntheticProfile("washout", 40.0, 0.1)));
    app::MainWindow window;
    window.resize(1280, 960);
    window.show();
    app::LoadOptions options;
    options.read.bitSize_mm = 215.9;
    window.session().openWell(QString::fromStdString(log.string()), options);
    ASSERT_TRUE(waitFor(window, &app::WellSession::allWellsLoaded, 60000)) << "no load";
    const auto loaded = window.session().geometry(0);
    ASSERT_NE(loaded, nullptr);
    ASSERT_NE(window.session().legend(), nullptr);
    EXPECT_EQ(window.session().legend()->title, "radius - bit radius");

    reconstruction::ColourRequest byClass;
    byClass.quantity = "class";
    ASSERT_TRUE(window.session().restyle(20.0, byClass)) << window.statusText().toStdString();
    const auto styled = window.session().geometry(0);
    ASSERT_NE(styled, loaded);
    EXPECT_EQ(&styled->table(), &loaded->table());  // not read again
    EXPECT_EQ(&styled->path(), &loaded->path());    // not placed again
    EXPECT_EQ(styled->options().radialExaggeration, 20.0);
    ASSERT_NE(window.session().legend(), nullptr);
    EXPECT_EQ(window.session().legend()->title, "class");
    EXPECT_NE(window.statusText().indexOf("nothing read again"), -1)
        << window.statusText().toStdString();
    // The washout's sections now draw in the washout's colour.
    const reconstruction::SegmentMesh segment = styled->buildSegment(2);  // 20-30 m (10 m each)
    ASSERT_FALSE(segment.levels.front().colours.empty());
    EXPECT_EQ(segment.levels.front().colours.front(), 0xD55E00FFu);

    reconstruction::ColourRequest bogus;
    bogus.quantity = "porosity";
    EXPECT_FALSE(window.session().restyle(1.0, bogus));
    EXPECT_NE(window.statusText().indexOf("cannot colour by 'porosity'"), -1);
    EXPECT_EQ(window.session().geometry(0), styled);  // left as it was
}
