// The View menu in a window: the radial exaggeration it shows and takes, and View all and the
// view presets bringing the camera out of the hole.
#include "app/desktop/view_menu.h"

#include <cmath>

#include <gtest/gtest.h>
#include <QApplication>
#include <QInputDialog>
#include <QMenu>
#include <QMenuBar>
#include <QTimer>

#include <Inventor/Qt/viewers/SoQtExaminerViewer.h>
#include <Inventor/SbViewVolume.h>
#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoSeparator.h>

#include "app/desktop/desk_model.h"
#include "app/desktop/main_window.h"
#include "app/desktop/well_navigator.h"
#include "app/desktop/well_session.h"
#include "desktop_test_support.h"
#include "io/column_text_writer.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "scenegraph/camera_setup.h"

using namespace caliper3d;

namespace {

class ViewMenuTest : public ::testing::Test {
protected:
    void SetUp() override {
        if (!test::ensureGuiApplication()) GTEST_SKIP() << "no display (run under xvfb-run)";
    }
    // Opens `log` as `caliper3d view FILE` does (no --exaggerate) and waits for its analysis.
    static void open(app::MainWindow& window, const std::filesystem::path& log) {
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
        QApplication::processEvents();
    }
    static QMenu* menu(const app::MainWindow& window, const QString& name) {
        return window.menuBar()->findChild<QMenu*>(name);
    }
    static QAction* action(QMenu* menu, const QString& text) {
        for (QAction* a : menu->actions())
            if (a->text().remove('&') == text) return a;
        return nullptr;
    }
};

}  // namespace

TEST_F(ViewMenuTest, OpensWithTheExaggerationRenderChoosesAndTakesAnyOther) {
    app::MainWindow window;
    // 300 m of 8.5 in hole: render draws it 1.5 % of the picture's height across, 0.015 x
    // 300 m / 215.9 mm = 20.8 times its radii, up the 1-2-3-5 series: 30.
    open(window, test::syntheticLog("circle", 300.0, 0.1));
    EXPECT_DOUBLE_EQ(window.session().look().radialExaggeration, 30.0);
    EXPECT_DOUBLE_EQ(window.model().well(0).options.radialExaggeration, 30.0);
    EXPECT_FALSE(window.session().exaggerationKept());
    QMenu* exaggeration = menu(window, "exaggerationMenu");
    ASSERT_NE(exaggeration, nullptr);
    EXPECT_EQ(exaggeration->title().remove('&'), "Radial exaggeration (x30)");
    QAction* other = window.findChild<QAction*>("otherExaggeration");
    ASSERT_NE(other, nullptr);
    EXPECT_TRUE(other->isChecked()) << "30 is none of the presets";
    EXPECT_EQ(other->text().remove('&'), "Other (x30)...");

    // A preset.
    QAction* ten = action(exaggeration, "x10");
    ASSERT_NE(ten, nullptr);
    ten->trigger();
    EXPECT_DOUBLE_EQ(window.session().look().radialExaggeration, 10.0);
    EXPECT_TRUE(ten->isChecked());
    EXPECT_FALSE(other->isChecked());
    EXPECT_EQ(exaggeration->title().remove('&'), "Radial exaggeration (x10)");
    EXPECT_TRUE(window.session().exaggerationKept()) << "the user's factor stays";

    // Any factor --exaggerate takes, through the dialog.
    bool answered = false;
    QTimer::singleShot(0, [&] {
        for (QWidget* top : QApplication::topLevelWidgets())
            if (auto* dialog = qobject_cast<QInputDialog*>(top); dialog && dialog->isVisible()) {
                EXPECT_DOUBLE_EQ(dialog->doubleValue(), 10.0) << "it starts from the factor drawn";
                EXPECT_DOUBLE_EQ(dialog->doubleMinimum(), 1.0);
                EXPECT_DOUBLE_EQ(dialog->doubleMaximum(), 1000.0);
                dialog->setDoubleValue(7.5);
                dialog->accept();
                answered = true;
            }
    });
    other->trigger();
    EXPECT_TRUE(answered);
    EXPECT_DOUBLE_EQ(window.session().look().radialExaggeration, 7.5);
    EXPECT_DOUBLE_EQ(window.model().well(0).options.radialExaggeration, 7.5);
    EXPECT_EQ(exaggeration->title().remove('&'), "Radial exaggeration (x7.5)");
    EXPECT_TRUE(other->isChecked());
}

TEST_F(ViewMenuTest, AnExaggerationGivenIsKept) {
    app::MainWindow window;
    window.session().keepExaggeration();  // caliper3d view --exaggerate 1
    open(window, test::syntheticLog("circle", 300.0, 0.1));
    EXPECT_DOUBLE_EQ(window.session().look().radialExaggeration, 1.0);
    QMenu* exaggeration = menu(window, "exaggerationMenu");
    ASSERT_NE(exaggeration, nullptr);
    EXPECT_TRUE(action(exaggeration, "x1")->isChecked());
}

TEST_F(ViewMenuTest, ViewAllAndThePresetsLeaveTheHole) {
    app::MainWindow window;
    open(window, test::syntheticLog("circle", 300.0, 0.1));
    QMenu* view = menu(window, "viewMenu");
    ASSERT_NE(view, nullptr);
    QAction* inside = action(view, "Inside the hole");
    QAction* viewAll = action(view, "View all");
    ASSERT_NE(inside, nullptr);
    ASSERT_NE(viewAll, nullptr);
    SoCamera* camera = window.viewer()->getCamera();
    ASSERT_NE(camera, nullptr);
    const auto eyeFromAxis = [&] {
        const SbVec3f eye = camera->position.getValue();
        return std::hypot(eye[0], eye[2]);  // the well is vertical under the origin
    };
    // Every corner of the scene's box in front of the camera and inside the picture.
    const auto framesTheScene = [&] {
        const SbViewportRegion viewport = window.viewer()->getViewportRegion();
        SoGetBoundingBoxAction box(viewport);
        box.apply(window.session().sceneRoot());
        SbVec3f lo, hi, look;
        box.getBoundingBox().getBounds(lo, hi);
        camera->orientation.getValue().multVec(SbVec3f(0.0f, 0.0f, -1.0f), look);
        const SbViewVolume volume =
            scenegraph::shownViewVolume(*camera, viewport.getViewportAspectRatio());
        for (int corner = 0; corner < 8; ++corner) {
            const SbVec3f p((corner & 1) ? hi[0] : lo[0], (corner & 2) ? hi[1] : lo[1],
                            (corner & 4) ? hi[2] : lo[2]);
            if ((p - camera->position.getValue()).dot(look) <= 0.0f) return false;
            SbVec3f screen;
            volume.projectToScreen(p, screen);
            if (screen[0] < 0.0f || screen[0] > 1.0f || screen[1] < 0.0f || screen[1] > 1.0f)
                return false;
        }
        return true;
    };

    inside->trigger();
    ASSERT_TRUE(window.navigator().inside());
    EXPECT_LT(eyeFromAxis(), 0.2f) << "on the hole's axis";
    viewAll->trigger();
    EXPECT_FALSE(window.navigator().inside());
    EXPECT_FALSE(inside->isChecked()) << "the menu says the camera is out";
    EXPECT_TRUE(framesTheScene()) << "the whole well in view";

    for (const QString& preset :
         QStringList{"Iso", "Looking north", "Looking east", "From top (map)"}) {
        inside->trigger();
        ASSERT_TRUE(window.navigator().inside()) << preset.toStdString();
        QAction* from = action(view, preset);
        ASSERT_NE(from, nullptr) << preset.toStdString();
        from->trigger();
        EXPECT_FALSE(window.navigator().inside()) << preset.toStdString();
        EXPECT_FALSE(inside->isChecked()) << preset.toStdString();
        EXPECT_TRUE(framesTheScene()) << preset.toStdString();
    }
}
