#include "app/pick_output.h"

#include <algorithm>
#include <filesystem>
#include <thread>
#include <vector>

#include <Inventor/SbViewportRegion.h>
#include <QString>
#include <QStringList>

#include "app/input_options.h"
#include "reconstruction/analysis/well_analysis.h"
#include "scenegraph/section_pick.h"

namespace caliper3d::app {

void addPickOption(QCommandLineParser& parser) {
    parser.addOption(
        {"pick",
         "After the picture, print what the wall shows at pixel X,Y (origin at the top left, x "
         "right, y down) as key=value lines: picked=X,Y, well and well_name, section (the row), "
         "segment, level, the angle around the section (angle_from_high_side_deg: clockwise "
         "from the high side looking down the hole, north in a vertical hole), radius_mm of the "
         "true section there, then the report's columns for that section as 'caliper3d report' "
         "writes them with its default rules (an empty value is undefined; a section without "
         "data says no_data). A pixel that shows no wall prints 'nothing picked at X,Y'; the "
         "exit status is 0 either way.",
         "X,Y"});
}

std::optional<PickPixel> pickPixelFrom(const QCommandLineParser& parser, int width, int height,
                                       const std::string& verb) {
    if (!parser.isSet("pick")) return std::nullopt;
    const QString text = parser.value("pick");
    const QStringList parts = text.split(',');
    bool okX = false, okY = false;
    const int x = parts.size() == 2 ? parts[0].trimmed().toInt(&okX) : -1;
    const int y = parts.size() == 2 ? parts[1].trimmed().toInt(&okY) : -1;
    if (!okX || !okY || x < 0 || y < 0 || x >= width || y >= height)
        throw UsageError(verb + ": --pick takes X,Y: a pixel of the " + std::to_string(width) +
                         "x" + std::to_string(height) +
                         " picture, origin at the top left (found '" + text.toStdString() + "')");
    return PickPixel{x, y};
}

std::string describePick(const AssembledScene& scene, SoNode* renderRoot, int width, int height,
                         const PickPixel& pixel) {
    const auto [x, y] = pixel;
    // The report's analysis of each well, with its default rules.
    reconstruction::AnalysisOptions options;
    options.threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    std::vector<reconstruction::WellAnalysis> analyses;
    analyses.reserve(scene.geometries.size());
    for (const auto& geometry : scene.geometries)
        analyses.push_back(reconstruction::analyseWell(*geometry, options));
    std::vector<scenegraph::PickableWell> wells;
    for (std::size_t w = 0; w < scene.geometries.size(); ++w) {
        const reconstruction::WellGeometry& geometry = *scene.geometries[w];
        wells.push_back({scene.scenes[w].get(), &geometry, &analyses[w],
                         std::filesystem::path(geometry.table().source).stem().string()});
    }
    // Coin counts pixels from the bottom left.
    const SbVec2s coinPixel(static_cast<short>(x), static_cast<short>(height - 1 - y));
    const std::optional<scenegraph::SectionPick> pick = scenegraph::pickSection(
        renderRoot, SbViewportRegion(static_cast<short>(width), static_cast<short>(height)),
        coinPixel, wells);
    if (!pick) return "nothing picked at " + std::to_string(x) + "," + std::to_string(y) + "\n";
    return "picked=" + std::to_string(x) + "," + std::to_string(y) + "\n" +
           scenegraph::formatSectionPick(*pick);
}

}  // namespace caliper3d::app
