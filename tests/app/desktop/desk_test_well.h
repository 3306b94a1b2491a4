#pragma once

// What the dock tests share: a QApplication, and a synthetic well as the window would publish it.

#include <memory>
#include <string>

#include <QApplication>

#include "app/desktop/desk_model.h"
#include "app/gui_session.h"
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

}  // namespace caliper3d::test
