// The window as a whole: picking, the camera following the current depth, zones, cancelling
// a load, the error dialog and the docks it holds.
#include "app/desktop/main_window.h"

#include "app/desktop/well_session.h"

#include <cmath>
#include <cstdio>
#include <fstream>

#include <gtest/gtest.h>
#include <QElapsedTimer>
#include <QGLWidget>
#include <QMessageBox>
#include <QProgressBar>
#include <QTest>
#include <QTreeWidget>
#include <QtCharts/QChart>
#include <QtCharts/QChartView>

#include <Inventor/Qt/viewers/SoQtExaminerViewer.h>
#include <Inventor/SoSceneManager.h>
#include <Inventor/nodes/SoCamera.h>

#include "app/desktop/desk_model.h"
#include "app/desktop/log_track_dock.h"
#include "app/desktop/section_inspector_dock.h"
#include "app/desktop/warnings_dock.h"
#include "app/desktop/well_navigator.h"
#include "app/desktop/well_viewer.h"
#include "app/desktop/wells_dock.h"
#include "desktop_test_support.h"
#include "io/las_writer.h"
#include "reconstruction/analysis/report_writer.h"
#include "scenegraph/camera_setup.h"
#include "scenegraph/label_style.h"
#include "scenegraph/section_pick.h"
#include "support/drawn_labels.h"

using namespace caliper3d;
QT_CHARTS_USE_NAMESPACE

namespace {

class DesktopWindowTest : public ::testing::Test {
protected:
    void SetUp() override {
        if (!test::ensureGuiApplication()) GTEST_SKIP() << "no display (run under xvfb-run)";
    }
    // Opens `log` in `window` (shown at 800 x 600) and waits for it to load and be analysed.
    static void openAndAnalyse(app::MainWindow& window, const std::filesystem::path& log) {
        window.resize(1280, 960);
        window.show();
        app::LoadOptions options;
        options.read.bitSize_mm = 215.9;
        window.session().openWell(QString::fromStdString(log.string()), options);
        ASSERT_TRUE(test::waitUntil(
            [&] {
                return window.model().wellCount() == 1 && window.model().well(0).analysis &&
                       !window.session().loading();
            },
            120000))
            << "the well did not load and analyse";
    }
};

}  // namespace

TEST_F(DesktopWindowTest, AClickOnTheWallMakesItsSectionCurrentAndTheCameraStays) {
    app::MainWindow window;
    openAndAnalyse(window, test::syntheticLog("example", 100.0, 0.05));
    window.navigator().setInside(true);
    window.model().setCurrentDepth(30.0);
    window.viewer()->render();
    SoCamera* camera = window.viewer()->getCamera();
    const SbVec3f eye = camera->position.getValue();

    // Looking down the hole from 30 m, a pixel near the bottom edge meets the wall deeper.
    const SbVec2s size = window.viewer()->getViewportRegion().getViewportSizePixels();
    const SbVec2s pixel(size[0] / 2, static_cast<short>(size[1] / 10));
    const app::DeskWell& well = window.model().well(0);
    // What the click must find: the same pick made here (the camera does not move).
    std::vector<scenegraph::PickableWell> wells{
        {nullptr, well.geometry.get(), well.analysis.get(), "example"}};
    QWidget* gl = window.viewer()->getGLWidget();
    QTest::mouseClick(gl, Qt::LeftButton, Qt::NoModifier, QPoint(pixel[0], size[1] - 1 - pixel[1]));
    QApplication::processEvents();

    EXPECT_GT(window.model().currentDepth_m(), 30.0) << "the wall met is deeper than the eye";
    EXPECT_LT(window.model().currentDepth_m(), 60.0);
    EXPECT_TRUE(std::isfinite(window.model().currentAzimuth_deg()));
    EXPECT_EQ(camera->position.getValue(), eye) << "a pick does not move the camera";
    EXPECT_TRUE(window.statusText().contains("radius")) << window.statusText().toStdString();
    // The row is the one whose section the ray meets: the wall point lies in its plane.
    const std::size_t row = window.model().currentRow();
    EXPECT_TRUE(well.geometry->measured(row));
    EXPECT_EQ(window.navigator().markerPoints(), well.geometry->sampler().samples() + 1);

    // The section inspector shows the report's numbers for the section picked.
    auto* inspector = window.findChild<app::SectionInspectorDock*>("sectionInspector");
    ASSERT_NE(inspector, nullptr);
    int fields = 0;
    for (const auto& [field, text] :
         reconstruction::sectionReportFields(well.analysis->sections[row]))
        if (!inspector->value(QString::fromStdString(field)).isEmpty()) {
            const QString shown = inspector->value(QString::fromStdString(field));
            if (text.empty())  // undefined in the report: the inspector says why
                EXPECT_TRUE(shown == "none" || shown == "unknown") << field;
            else
                EXPECT_EQ(shown.toStdString(), text) << field;
            ++fields;
        }
    EXPECT_GE(fields, 8) << "md, dmin, dmax, ellipticity, azimuth, area, offset, class";
}

TEST_F(DesktopWindowTest, AClickOnTheLogTrackMovesTheCameraToThatDepth) {
    app::MainWindow window;
    openAndAnalyse(window, test::syntheticLog("example", 100.0, 0.05));
    auto* track = window.findChild<app::LogTrackDock*>("logTrack");
    ASSERT_NE(track, nullptr);
    ASSERT_TRUE(test::waitUntil([&] { return track->showsChart(); }, 5000));
    track->setDepthWindow(60.0, 80.0);  // 20 m over the track: a pixel is less than a row
    QApplication::processEvents();
    QChart* chart = track->chart();
    const QPointF inChart = chart->mapToPosition(QPointF(230.0, 70.0), chart->series().back());
    const QPoint pixel = track->chartView()->mapFromScene(chart->mapToScene(inChart));
    QTest::mouseClick(track->chartView()->viewport(), Qt::LeftButton, {}, pixel);
    QApplication::processEvents();

    EXPECT_NEAR(window.model().currentDepth_m(), 70.0, 0.15);
    const app::DeskWell& well = window.model().well(0);
    const glm::dvec3 centre =
        reconstruction::toScene(well.geometry->centre(window.model().currentRow()));
    const SbVec3f focus = window.navigator().focus();
    EXPECT_NEAR(focus[0], centre.x, 0.01);
    EXPECT_NEAR(focus[1], centre.y, 0.01);
    EXPECT_NEAR(focus[2], centre.z, 0.01);
}

TEST_F(DesktopWindowTest, TheCameraFollowsTheCurrentDepthAndStepsFromZoneToZone) {
    app::MainWindow window;
    openAndAnalyse(window, test::syntheticLog("example", 100.0, 0.05));
    const app::DeskWell& well = window.model().well(0);
    window.model().setCurrentDepth(42.0);
    const std::size_t row = window.model().currentRow();
    const glm::dvec3 centre = reconstruction::toScene(well.geometry->centre(row));
    const SbVec3f focus = window.navigator().focus();
    EXPECT_NEAR(focus[0], centre.x, 0.01);
    EXPECT_NEAR(focus[1], centre.y, 0.01);
    EXPECT_NEAR(focus[2], centre.z, 0.01);

    // The example's breakout (60-80 m) is a zone of the analysis: the next zone from 42 m.
    const auto& zones = well.analysis->zones;
    ASSERT_FALSE(zones.empty());
    ASSERT_TRUE(window.navigator().nextZone());
    const reconstruction::Zone* expected = nullptr;
    for (const auto& zone : zones)
        if (zone.firstSection > row) {
            expected = &zone;
            break;
        }
    ASSERT_NE(expected, nullptr);
    EXPECT_EQ(window.model().currentRow(), expected->firstSection);
    EXPECT_DOUBLE_EQ(window.model().currentDepth_m(),
                     well.geometry->table().depth_m[expected->firstSection]);
    ASSERT_TRUE(window.navigator().previousZone() || expected == &zones.front());
}

TEST_F(DesktopWindowTest, CancelsAFourKilometreLoadWithinATenthOfASecond) {
    const auto log = test::syntheticLog("example", 4000.0, 0.01);
    app::MainWindow window;
    window.resize(1280, 960);
    window.show();
    window.session().openWell(QString::fromStdString(log.string()), app::LoadOptions{});
    // While the log is being read: the bar shows the fraction read.
    ASSERT_TRUE(test::waitUntil([&] { return window.loadProgress()->value() > 0; }, 20000))
        << "progress " << window.loadProgress()->value() << ", loading "
        << window.session().loading();
    EXPECT_TRUE(window.loadProgress()->isVisible());
    EXPECT_TRUE(window.session().loading());
    const int progress = window.loadProgress()->value();
    EXPECT_LT(progress, window.loadProgress()->maximum());
    QElapsedTimer clock;
    clock.start();
    window.session().cancelLoading();
    const qint64 took = clock.elapsed();
    EXPECT_LT(took, 100) << "cancelling took " << took << " ms";
    RecordProperty("cancel_ms", static_cast<int>(took));
    std::printf("cancelled the 4 km load at %.0f %% of its bar in %lld ms\n",
                100.0 * progress / window.loadProgress()->maximum(), static_cast<long long>(took));
    EXPECT_FALSE(window.session().loading());
    EXPECT_EQ(window.session().wellCount(), 0u);
    EXPECT_EQ(window.model().wellCount(), 0);
    EXPECT_FALSE(window.loadProgress()->isVisible());
    EXPECT_TRUE(window.statusText().contains("cancelled")) << window.statusText().toStdString();
    // Its worker stops at the end of the block it was reading, off the window's thread.
    EXPECT_TRUE(test::waitUntil([&] { return window.session().retiredLoadsRunning() == 0; }, 5000));
}

TEST_F(DesktopWindowTest, ABadFileOpensAnErrorDialogNamingTheFileAndLine) {
    const auto bad = test::scratch("desktop_bad.txt");
    { std::ofstream(bad) << "1 2 3 4 5 6 7 8 9 10\n2 2 3\n3 2 3 4 5 6 7 8 9 10\n"; }
    app::MainWindow window;
    window.show();
    window.session().openWell(QString::fromStdString(bad.string()), app::LoadOptions{});
    QMessageBox* dialog = nullptr;
    ASSERT_TRUE(test::waitUntil(
        [&] {
            dialog = window.findChild<QMessageBox*>("loadError");
            return dialog != nullptr && dialog->isVisible();
        },
        30000))
        << "no error dialog";
    EXPECT_TRUE(dialog->text().contains(QString::fromStdString(bad.string() + ":2")))
        << dialog->text().toStdString();
    EXPECT_TRUE(dialog->windowTitle().contains("desktop_bad.txt"));
    // The wells dock says it failed; the warnings pane shows the reason.
    auto* wells = window.findChild<app::WellsDock*>("wells");
    ASSERT_NE(wells, nullptr);
    EXPECT_EQ(wells->tree()->topLevelItem(0)->text(app::WellsDock::State), "failed");
    auto* warnings = window.findChild<app::WarningsDock*>("warnings");
    ASSERT_NE(warnings, nullptr);
    EXPECT_TRUE(warnings->text().contains(QString::fromStdString(bad.string() + ":2")));
    dialog->accept();
}

TEST_F(DesktopWindowTest, TheWellsAndWarningsDocksDrawTheWellAndHideIt) {
    app::MainWindow window;
    // A short file name: the well's name, which is left out where it does not fit, and a
    // long one can be as wide as the view beside the docks (it depends on the fonts).
    const std::string path = test::scratch("w1.txt").string();
    io::writeColumnTextFile(path, reconstruction::makeSyntheticWell(
                                      reconstruction::syntheticProfile("example", 100.0, 0.05)));
    openAndAnalyse(window, path);
    auto* wells = window.findChild<app::WellsDock*>("wells");
    ASSERT_NE(wells, nullptr);
    QTreeWidgetItem* item = wells->tree()->topLevelItem(0);
    ASSERT_NE(item, nullptr);
    EXPECT_EQ(item->text(app::WellsDock::State), "loaded");
    EXPECT_EQ(item->text(app::WellsDock::Rows),
              QString::number(window.model().well(0).geometry->table().rowCount()));
    EXPECT_TRUE(item->text(app::WellsDock::BitSize).startsWith("215.9 mm"));
    // The units as the file wrote them (our column text writes the caliper's, inches).
    const io::SectionTable& table = window.model().well(0).geometry->table();
    EXPECT_EQ(table.fileCaliperUnit, "in");
    EXPECT_EQ(item->text(app::WellsDock::Units).toStdString(),
              "depth " + (table.fileDepthUnit.empty() ? "none written" : table.fileDepthUnit) +
                  ", caliper in");
    const QImage shown = wells->grab().toImage();
    shown.save(QString::fromStdString(test::scratch("desktop_wells_dock.png").string()));
    EXPECT_GT(test::drawnPixels(shown), 500u);

    // Unticking the well hides it in 3D (the tube, its ticks and labels go; the legend and
    // the caption stay) and in the model. Its labels first placed for the camera (they
    // follow it once it rests).
    ASSERT_TRUE(test::waitUntil([&] { return window.labelsPlaced(); }, 10000));
    auto* gl = qobject_cast<QGLWidget*>(window.viewer()->getGLWidget());
    ASSERT_NE(gl, nullptr);
    window.viewer()->render();
    const QImage beforeImage = gl->grabFrameBuffer();
    item->setCheckState(app::WellsDock::Name, Qt::Unchecked);
    EXPECT_FALSE(window.model().well(0).visible);
    window.viewer()->render();
    const QImage afterImage = gl->grabFrameBuffer();
    beforeImage.save(QString::fromStdString(test::scratch("desktop_shown.png").string()));
    afterImage.save(QString::fromStdString(test::scratch("desktop_hidden.png").string()));
    // The well's name at its wellhead, in its own colour: there before, gone after (the
    // legend and the caption stay).
    const QColor name = QColor::fromRgbF(scenegraph::kNameColour[0], scenegraph::kNameColour[1],
                                         scenegraph::kNameColour[2]);
    const auto namePixels = [&](const QImage& image) {
        return std::size_t(image.width()) * std::size_t(image.height()) -
               test::pixelsUnlike(image, name, 30);
    };
    EXPECT_GT(namePixels(beforeImage), 150u);
    EXPECT_LT(namePixels(afterImage), 30u) << "only the current section's outline is left";

    auto* warnings = window.findChild<app::WarningsDock*>("warnings");
    ASSERT_NE(warnings, nullptr);
    EXPECT_EQ(warnings->text(), "No warnings.");
    EXPECT_GT(test::drawnPixels(warnings->grab().toImage()), 100u);
}

// The wells of a pad, their wellheads 3 m apart, seen whole: their names would all sit on
// the same few pixels. Once the camera rests, every name and depth label drawn keeps clear of
// the others, inside the view; when the camera turns, they are placed again for it.
TEST_F(DesktopWindowTest, ThePadsWellNamesArePlacedApartForTheCameraOnceItRests) {
    app::MainWindow window;
    window.resize(1280, 960);
    window.show();
    app::LoadOptions options;
    options.read.bitSize_mm = 215.9;
    const std::vector<std::string> profiles{"example", "circle", "ellipse", "washout"};
    for (std::size_t i = 0; i < profiles.size(); ++i) {
        // Named in the header, as a field's logs are (file names are longer than a view).
        const io::SectionTable table = reconstruction::makeSyntheticWell(
            reconstruction::syntheticProfile(profiles[i], 100.0, 0.05));
        io::LasWriteOptions las;
        las.wellName = "PAD-" + std::to_string(i + 1);
        reconstruction::WellSource source;
        source.path = test::scratch("desktop_pad_" + profiles[i] + ".las").string();
        io::writeLasFile(source.path, table, las);
        reconstruction::Wellhead head;
        head.easting_m = 3.0 * double(i);
        source.wellhead = head;
        if (i == 0)
            window.session().openWell(source, options);
        else
            window.session().addWell(source, options);
    }
    ASSERT_TRUE(test::waitUntil(
        [&] {
            if (window.model().wellCount() != int(profiles.size()) || window.session().loading())
                return false;
            for (int i = 0; i < window.model().wellCount(); ++i)
                if (!window.model().well(i).analysis) return false;
            return true;
        },
        120000))
        << "the wells did not load and analyse";

    SoCamera* camera = window.viewer()->getCamera();
    ASSERT_NE(camera, nullptr);
    const auto labelsNow = [&] {
        window.viewer()->render();  // the viewer's clipping planes for this camera
        const SbVec2s size = window.viewer()->getViewportRegion().getViewportSizePixels();
        return test::drawnLabels(window.session().sceneRoot(), *camera, size[0], size[1]);
    };
    const auto apart = [&](const std::vector<test::DrawnLabel>& labels) {
        const SbVec2s size = window.viewer()->getViewportRegion().getViewportSizePixels();
        const scenegraph::ScreenBox frame{0.0f, 0.0f, float(size[0]), float(size[1])};
        int names = 0;
        for (std::size_t i = 0; i < labels.size(); ++i) {
            names += labels[i].name ? 1 : 0;
            if (!scenegraph::contains(frame, labels[i].box)) return false;
            for (std::size_t j = 0; j < i; ++j)
                if (scenegraph::overlaps(labels[i].box, labels[j].box)) return false;
        }
        return names >= 2;
    };
    std::vector<test::DrawnLabel> labels;
    EXPECT_TRUE(test::waitUntil(
        [&] {
            labels = labelsNow();
            return apart(labels);
        },
        10000))
        << "the names still meet at the wellheads";
    int names = 0;
    for (const test::DrawnLabel& label : labels) names += label.name ? 1 : 0;
    EXPECT_GE(names, 2);
    // The caption counts the names left out, or has no line for them.
    const std::vector<std::string> caption = window.caption();
    ASSERT_FALSE(caption.empty());
    EXPECT_EQ(caption.front().rfind("radii", 0), 0u) << caption.front();
    if (names < int(profiles.size()))
        EXPECT_EQ(caption.back(), std::to_string(profiles.size() - std::size_t(names)) + " of " +
                                      std::to_string(profiles.size()) + " names left out: no room");
    else
        EXPECT_EQ(caption.size(), 1u) << caption.back();

    // Seen from the east: placed again for this camera (they move from where the labels
    // placed for the last one are seen from here).
    window.navigator().viewFrom(scenegraph::ViewDirection::East);
    const std::vector<test::DrawnLabel> stale = labelsNow();
    const auto moved = [&stale](const std::vector<test::DrawnLabel>& now) {
        if (now.size() != stale.size()) return true;
        for (std::size_t i = 0; i < now.size(); ++i)
            if (now[i].text != stale[i].text || std::abs(now[i].box.x0 - stale[i].box.x0) > 1.0f ||
                std::abs(now[i].box.y0 - stale[i].box.y0) > 1.0f)
                return true;
        return false;
    };
    EXPECT_TRUE(test::waitUntil(
        [&] {
            labels = labelsNow();
            return moved(labels) && apart(labels);
        },
        10000))
        << "the labels were not placed again for the turned camera";
}

// The labels keep clear of the legend's panel where the window draws it (in the lower half
// of its view, not where a picture puts it): the panel's box is where its fill is drawn.
TEST_F(DesktopWindowTest, TheLegendsPanelIsWhereTheViewerDrawsIt) {
    app::MainWindow window;
    openAndAnalyse(window, test::syntheticLog("example", 100.0, 0.05));
    auto* viewer = dynamic_cast<app::WellViewer*>(window.viewer());
    ASSERT_NE(viewer, nullptr);
    auto* gl = qobject_cast<QGLWidget*>(viewer->getGLWidget());
    ASSERT_NE(gl, nullptr);
    // The panel's fill, 0x262B36 (scenegraph/colour_legend.cpp), drawn unlit.
    const QColor fill(0x26, 0x2B, 0x36);
    const auto expectPanelWhereItsBoxSays = [&](const char* when) {
        const std::optional<scenegraph::ScreenBox> panel = viewer->legendPanel();
        ASSERT_TRUE(panel) << "a well coloured by its radius shows a legend";
        viewer->render();
        const QImage image = gl->grabFrameBuffer();
        const SbVec2s size = viewer->getViewportRegion().getViewportSizePixels();
        ASSERT_EQ(image.width(), size[0]);
        ASSERT_EQ(image.height(), size[1]);
        std::size_t inside = 0, outside = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) {
                const QColor c = image.pixelColor(x, y);
                if (std::abs(c.red() - fill.red()) > 2 || std::abs(c.green() - fill.green()) > 2 ||
                    std::abs(c.blue() - fill.blue()) > 2)
                    continue;
                const bool in = x + 0.5f >= panel->x0 - 1.0f && x + 0.5f <= panel->x1 + 1.0f &&
                                y + 0.5f >= panel->y0 - 1.0f && y + 0.5f <= panel->y1 + 1.0f;
                (in ? inside : outside) += 1;
            }
        EXPECT_GT(double(inside), 0.5 * double(panel->width() * panel->height()))
            << when << ": the panel is filled where its box says";
        EXPECT_LT(outside, 50u) << when << ": no fill outside the box";
    };
    expectPanelWhereItsBoxSays("as opened");
    // Its text is laid out in pixels for the view's height: made again when that changes.
    const int before = viewer->getViewportRegion().getViewportSizePixels()[1];
    window.resize(1280, 800);
    ASSERT_TRUE(test::waitUntil(
        [&] { return viewer->getViewportRegion().getViewportSizePixels()[1] != before; }, 5000))
        << "the view is still " << before << " pixels high";
    // The window system resizes the GL widget's drawable in its own time: until then a
    // frame reads back black.
    ASSERT_TRUE(test::waitUntil(
        [&] {
            viewer->render();
            return gl->grabFrameBuffer().pixelColor(1, 1) != QColor(Qt::black);
        },
        5000));
    expectPanelWhereItsBoxSays("after the window was made lower");
}

// While a field loads, once its first picture is drawn, the viewer draws a frame a quarter
// second at most (each well drawn asked for one, and they took the cores the load reads with);
// the limit ends with the load, and a well opened alone is drawn as it streams.
TEST_F(DesktopWindowTest, AFieldsLoadLimitsTheViewersFramesUntilItEnds) {
    app::MainWindow window;
    window.resize(1280, 960);
    window.show();
    auto* viewer = dynamic_cast<app::WellViewer*>(window.viewer());
    ASSERT_NE(viewer, nullptr);
    std::vector<std::chrono::milliseconds> asLoaded;
    QObject::connect(&window.session(), &app::WellSession::wellLoaded,
                     [&](int) { asLoaded.push_back(viewer->frameLimit()); });
    const std::string log = test::syntheticLog("example", 100.0, 0.05).string();
    const auto loadedAll = [&] {
        return test::waitUntil([&] { return !window.session().loading(); }, 120000);
    };

    window.session().openWell(QString::fromStdString(log), app::LoadOptions{});
    ASSERT_TRUE(loadedAll());
    ASSERT_EQ(asLoaded.size(), 1u);
    EXPECT_EQ(asLoaded[0].count(), 0) << "a well alone";

    asLoaded.clear();
    app::WellSource first{log, {}, reconstruction::Wellhead{0.0, 0.0, 0.0}, {}};
    window.session().openWell(first, app::LoadOptions{});
    for (const double east : {30.0, 60.0}) {
        app::WellSource next{log, {}, reconstruction::Wellhead{east, 0.0, 0.0}, {}};
        window.session().addWell(next, app::LoadOptions{});
    }
    ASSERT_TRUE(loadedAll());
    ASSERT_EQ(asLoaded.size(), 3u);
    for (const std::chrono::milliseconds limit : asLoaded)
        EXPECT_EQ(limit.count(), 250) << "each well of the field loaded under the limit";
    EXPECT_EQ(viewer->frameLimit().count(), 0) << "the limit ends with the load";
}
