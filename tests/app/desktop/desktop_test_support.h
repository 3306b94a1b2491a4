#pragma once

#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <QApplication>
#include <QColor>
#include <QCoreApplication>
#include <QEventLoop>
#include <QImage>
#include <QSettings>
#include <QString>
#include <QTimer>
#include <QWidget>

#include "app/desktop/gui_session.h"
#include "io/column_text_writer.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "test_support.h"

namespace caliper3d::test {

// QSettings of every test here goes to a scratch folder, never the user's: one a test, since
// ctest runs the tests as processes at once and two writing one settings file see each
// other's values.
inline QString scratchSettingsFolder() {
    const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::string name = test ? std::string(test->test_suite_name()) + "." + test->name()
                                  : "pid" + std::to_string(QCoreApplication::applicationPid());
    const std::filesystem::path folder = scratch("settings") / name;
    std::filesystem::create_directories(folder);
    return QString::fromStdString(folder.string());
}
inline void useScratchSettings() {
    const QString folder = scratchSettingsFolder();
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, folder);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, folder);
}

// The one QApplication of the desktop tests (made by the first suite that needs it, with
// SoQt); false when there is no display (the caller skips).
inline bool ensureGuiApplication() {
    if (!app::haveDisplay()) return false;
    static bool made = false;
    if (!made) {
        static int argc = 1;
        static char name[] = "desktop_tests";
        static char* argv[] = {name, nullptr};
        if (!QApplication::instance()) new QApplication(argc, argv);  // lives as long as the tests
        app::initGui();
        made = true;
    }
    useScratchSettings();
    return true;
}

// Runs the event loop until `done()` holds or `ms` milliseconds pass; returns done().
template <typename Predicate>
bool waitUntil(Predicate done, int ms) {
    QEventLoop loop;
    QTimer poll;
    QObject::connect(&poll, &QTimer::timeout, &loop, [&] {
        if (done()) loop.quit();
    });
    poll.start(10);
    QTimer::singleShot(ms, &loop, &QEventLoop::quit);
    if (!done()) loop.exec();
    return done();
}

// A synthetic well written as column text into the scratch folder (kept between runs when
// it is there already: the 4 km one takes seconds to write). Tests run as separate processes
// at once may both find it missing: the writer's temporary is named by its process and the
// rename is atomic, so each writes its own whole copy and the last rename wins, never part of one.
inline std::filesystem::path syntheticLog(const std::string& profile, double length_m,
                                          double step_m) {
    const auto path = scratch("desktop_" + profile + "_" + std::to_string(int(length_m)) + "m_" +
                              std::to_string(int(step_m * 1000)) + "mm.txt");
    if (!std::filesystem::exists(path))
        io::writeColumnTextFile(path.string(),
                                reconstruction::makeSyntheticWell(
                                    reconstruction::syntheticProfile(profile, length_m, step_m)));
    return path;
}

// Pixels of `image` more than `tolerance` (0-255, any channel) from `background`.
inline std::size_t pixelsUnlike(const QImage& image, const QColor& background, int tolerance = 24) {
    std::size_t count = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            count += std::abs(c.red() - background.red()) > tolerance ||
                             std::abs(c.green() - background.green()) > tolerance ||
                             std::abs(c.blue() - background.blue()) > tolerance
                         ? 1
                         : 0;
        }
    return count;
}

// Pixels of `image` that differ from its top-left pixel (the background).
inline std::size_t drawnPixels(const QImage& image) {
    if (image.isNull()) return 0;
    const QRgb background = image.pixel(0, 0);
    std::size_t drawn = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) drawn += image.pixel(x, y) != background ? 1 : 0;
    return drawn;
}

}  // namespace caliper3d::test
