#pragma once

#include <QApplication>
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

}  // namespace caliper3d::test

#define CALIPER3D_REQUIRE_GUI()                                                                    \
    do {                                                                                           \
        if (!caliper3d::test::guiApplication()) GTEST_SKIP() << "no display (run under xvfb-run)"; \
    } while (false)
