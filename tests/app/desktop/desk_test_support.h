#pragma once

#include <QApplication>
#include <QSettings>
#include <QStandardPaths>

#include "app/gui_session.h"
#include "test_support.h"

namespace caliper3d::test {

// QSettings of every test here goes to a scratch folder, never the user's.
inline QString scratchSettingsFolder() {
    const std::filesystem::path folder = scratch("settings");
    std::filesystem::create_directories(folder);
    return QString::fromStdString(folder.string());
}
inline void useScratchSettings() {
    const QString folder = scratchSettingsFolder();
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, folder);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, folder);
}

// The one QApplication of desktop_tests (with SoQt), made on first use; null without a display.
inline QApplication* guiApplication() {
    static QApplication* application = [] {
        if (!app::haveDisplay()) return static_cast<QApplication*>(nullptr);
        static int argc = 1;
        static char name[] = "desktop_tests";
        static char* argv[] = {name, nullptr};
        auto* a = new QApplication(argc, argv);
        app::initGui();
        return a;
    }();
    useScratchSettings();
    return application;
}

}  // namespace caliper3d::test

#define CALIPER3D_REQUIRE_GUI()                                                                    \
    do {                                                                                           \
        if (!caliper3d::test::guiApplication()) GTEST_SKIP() << "no display (run under xvfb-run)"; \
    } while (false)
