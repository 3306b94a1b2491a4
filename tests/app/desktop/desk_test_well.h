#pragma once

// What the tests of the window's views share: the one QApplication of the process, a
// synthetic well with a known breakout, and a count of what a view drew.

#include <memory>

#include <QApplication>
#include <QColor>
#include <QImage>
#include <QWidget>

#include "app/desktop/desk_model.h"
#include "app/gui_session.h"
#include "reconstruction/synthetic/synthetic_well.h"

namespace caliper3d::test {

// The process's QApplication (made on first use), or null when there is no display.
inline QApplication* deskApplication() {
    if (!app::haveDisplay()) return nullptr;
    if (auto* existing = qobject_cast<QApplication*>(QCoreApplication::instance())) return existing;
    static int argc = 1;
    static char name[] = "desktop_tests";
    static char* argv[] = {name, nullptr};
    return new QApplication(argc, argv);
}

// The "example" profile, 300 m with rows every 5 cm: a breakout 245.9 x 217.9 mm at azimuth
// 135 over 60-80 m, a washout of 265.9 mm over 150-160 m, in a 215.9 mm (8.5 in) hole.
// With its analysis (reconstruction::analyseWell) unless `analysed` is false.
inline app::DeskWell exampleDeskWell(bool analysed = true) {
    auto table = std::make_shared<const io::SectionTable>(reconstruction::makeSyntheticWell(
        reconstruction::syntheticProfile("example", 300.0, 0.05)));
    app::DeskWell well;
    well.name = "example";
    well.geometry = std::make_shared<const reconstruction::WellGeometry>(
        table, reconstruction::GeometryOptions{});
    if (analysed)
        well.analysis = std::make_shared<const reconstruction::WellAnalysis>(
            reconstruction::analyseWell(*well.geometry, reconstruction::AnalysisOptions{}));
    return well;
}

// Pixels of `widget`'s picture that differ from its most common colour (the background).
inline int drawnPixels(QWidget& widget) {
    const QImage image = widget.grab().toImage().convertToFormat(QImage::Format_RGB32);
    const QRgb background = image.pixel(image.width() / 2, 2);
    int drawn = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) drawn += image.pixel(x, y) != background;
    return drawn;
}

// Pixels of `widget`'s picture within `tolerance` of `colour` in each channel.
inline int pixelsNear(QWidget& widget, QColor colour, int tolerance) {
    const QImage image = widget.grab().toImage().convertToFormat(QImage::Format_RGB32);
    int count = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            count += std::abs(c.red() - colour.red()) <= tolerance &&
                     std::abs(c.green() - colour.green()) <= tolerance &&
                     std::abs(c.blue() - colour.blue()) <= tolerance;
        }
    return count;
}

}  // namespace caliper3d::test
