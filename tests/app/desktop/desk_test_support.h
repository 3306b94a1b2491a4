#pragma once

#include <memory>

#include <QApplication>
#include <QCoreApplication>
#include <QSettings>
#include <QStandardPaths>

#include "desktop_test_support.h"

namespace caliper3d::test {

// The one QApplication of desktop_tests (with SoQt), made on first use, with QSettings in a
// scratch folder; null without a display.
inline QApplication* guiApplication() {
    return ensureGuiApplication() ? qobject_cast<QApplication*>(QCoreApplication::instance())
                                  : nullptr;
}

// For a test that needs an event loop but no window (a child process, a worker's queued call):
// the process's application when a test before it made one, otherwise a QCoreApplication of the
// test's own, gone with it. Such a test connects to no display: it runs without one, and an X
// server that refuses a connection cannot fail it.
class EventLoopApplication {
public:
    EventLoopApplication() {
        static int argc = 1;
        static char name[] = "desktop_tests";
        static char* argv[] = {name, nullptr};
        if (!QCoreApplication::instance()) m_own = std::make_unique<QCoreApplication>(argc, argv);
    }

private:
    std::unique_ptr<QCoreApplication> m_own;
};

}  // namespace caliper3d::test

#define CALIPER3D_REQUIRE_GUI()                                                                    \
    do {                                                                                           \
        if (!caliper3d::test::guiApplication()) GTEST_SKIP() << "no display (run under xvfb-run)"; \
    } while (false)
