#pragma once

// What the dock tests share: a QApplication, and a synthetic well as the window would publish it.

#include <cstdlib>
#include <memory>
#include <string>

#include <QApplication>
#include <QColor>
#include <QImage>
#include <QWidget>

#include "app/desktop/desk_model.h"
#include "app/desktop/gui_session.h"
#include "desktop_test_support.h"
#include "reconstruction/synthetic/synthetic_well.h"

namespace caliper3d::test {

// The process's QApplication (made once; null with no display).
inline QApplication* deskApplication() {
    return ensureGuiApplication() ? qobject_cast<QApplication*>(QCoreApplication::instance())
                                  : nullptr;
}

// A synthetic well (reconstruction::syntheticProfile `profile`, `length_m` from 100 m in
// `step_m` rows) with its geometry and, when `analysed`, the report's analysis.
inline app::DeskWell syntheticDeskWell(const std::string& profile, double length_m, double step_m,
                                       bool analysed = true) {
    io::SectionTable table = reconstruction::makeSyntheticWell(
        reconstruction::syntheticProfile(profile, length_m, step_m));
    app::DeskWell well;
    well.name = QString::fromStdString(profile);
    well.geometry = std::make_shared<const reconstruction::WellGeometry>(
        std::make_shared<const io::SectionTable>(std::move(table)),
        reconstruction::GeometryOptions{});
    if (analysed)
        well.analysis = std::make_shared<const reconstruction::WellAnalysis>(
            reconstruction::analyseWell(*well.geometry, reconstruction::AnalysisOptions{}));
    return well;
}

// The same from a table already made.
inline app::DeskWell deskWellOf(io::SectionTable table, const QString& name) {
    app::DeskWell well;
    well.name = name;
    well.geometry = std::make_shared<const reconstruction::WellGeometry>(
        std::make_shared<const io::SectionTable>(std::move(table)),
        reconstruction::GeometryOptions{});
    well.analysis = std::make_shared<const reconstruction::WellAnalysis>(
        reconstruction::analyseWell(*well.geometry, reconstruction::AnalysisOptions{}));
    return well;
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
