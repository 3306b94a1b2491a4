#include "app/desktop/well_viewer.h"

#include <chrono>

#include <Inventor/nodes/SoCube.h>
#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>
#include <QApplication>
#include <QMouseEvent>
#include <QTest>
#include <QWidget>

#include "desktop_test_support.h"

namespace caliper3d {
namespace {

using namespace std::chrono_literals;

class WellViewerTest : public ::testing::Test {
protected:
    void SetUp() override {
        if (!test::ensureGuiApplication()) GTEST_SKIP() << "no display";
        m_host = std::make_unique<QWidget>();
        m_host->resize(320, 240);
        m_viewer = std::make_unique<app::WellViewer>(m_host.get());
        m_root = new SoSeparator;
        m_root->ref();
        m_cube = new SoCube;
        m_root->addChild(m_cube);
        m_viewer->setSceneGraph(m_root);
        m_host->show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(m_host.get()));
        // The frames the showing asked for are drawn before a test counts.
        QTest::qWait(200);
    }
    void TearDown() override {
        m_viewer.reset();
        m_host.reset();
        if (m_root) m_root->unref();
    }

    // A change of the scene: the scene manager asks for a frame.
    void changeScene() { m_cube->width = m_cube->width.getValue() + 0.01f; }
    int frames() const { return m_viewer->framesDrawn(); }

    std::unique_ptr<QWidget> m_host;
    std::unique_ptr<app::WellViewer> m_viewer;
    SoSeparator* m_root = nullptr;
    SoCube* m_cube = nullptr;
};

TEST_F(WellViewerTest, WithoutALimitEveryChangeIsDrawn) {
    for (int i = 0; i < 20; ++i) {
        const int before = frames();
        changeScene();
        // At least one: the window system may ask for frames of its own (an expose).
        ASSERT_TRUE(test::waitUntil([&] { return frames() > before; }, 5000))
            << "change " << i << " was not drawn";
    }
}

// While a limit holds, a change draws the first frame at once, later ones at most one an
// interval, the last always; the user's own input and lifting the limit draw at once. The
// interval is long (ten seconds), so that a frame held back cannot come while the test waits
// on a slow machine.
TEST_F(WellViewerTest, ALimitHoldsFramesBackButNotTheFirstTheUsersOrTheLast) {
    m_viewer->limitFrames(10s);
    const int start = frames();
    changeScene();
    ASSERT_TRUE(test::waitUntil([&] { return frames() == start + 1; }, 5000))
        << "the first frame under a limit is drawn at once (a field's first picture)";
    for (int i = 0; i < 10; ++i) {
        changeScene();
        QTest::qWait(20);
    }
    QTest::qWait(300);
    EXPECT_EQ(frames(), start + 1) << "changes within the interval are held back";

    // A mouse move over the view is the user's: the frame asked for now is drawn at once.
    QMouseEvent move(QEvent::MouseMove, QPointF(100, 100), Qt::NoButton, Qt::NoButton,
                     Qt::NoModifier);
    QApplication::sendEvent(m_viewer->getGLWidget(), &move);
    changeScene();
    ASSERT_TRUE(test::waitUntil([&] { return frames() > start + 1; }, 5000))
        << "a frame after the user's input is not held back";

    // Past the input's grace, held back again; lifting the limit draws the held frame at once
    // (well before the ten seconds). Counted from here: within the grace the window system may
    // have asked for frames of its own, drawn at once too.
    QTest::qWait(700);
    const int held = frames();
    changeScene();
    QTest::qWait(300);
    EXPECT_EQ(frames(), held);
    m_viewer->limitFrames(0ms);
    EXPECT_TRUE(test::waitUntil([&] { return frames() > held; }, 5000))
        << "the frame held back comes once the limit is lifted";
}

// Frames come at most one an interval however fast the scene changes, and the last change
// is drawn once the interval has passed.
TEST_F(WellViewerTest, AFastChangingSceneIsDrawnAtMostOnceAnInterval) {
    constexpr auto kInterval = 150ms;
    m_viewer->limitFrames(kInterval);
    const int start = frames();
    const auto from = std::chrono::steady_clock::now();
    for (int i = 0; i < 60; ++i) {
        changeScene();
        QTest::qWait(10);
    }
    const auto elapsed = std::chrono::steady_clock::now() - from;
    const int drawn = frames() - start;
    // The first at once, then one an interval at most.
    EXPECT_LE(drawn, 1 + static_cast<int>(elapsed / kInterval) + 1);
    EXPECT_GE(drawn, 1);
    // One more change: drawn with any held back, within the interval.
    const int before = frames();
    changeScene();
    EXPECT_TRUE(test::waitUntil([&] { return frames() > before; }, 5000))
        << "the last change is drawn";
}

}  // namespace
}  // namespace caliper3d
