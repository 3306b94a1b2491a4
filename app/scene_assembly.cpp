#include "app/scene_assembly.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <memory>
#include <thread>
#include <tuple>
#include <utility>
#include <vector>

#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoSeparator.h>

#include "app/change_colouring.h"
#include "io/parse_error.h"
#include "io/picks_reader.h"
#include "reconstruction/load/load_well.h"
#include "reconstruction/mesh/lod_levels.h"
#include "reconstruction/well_geometry.h"
#include "scenegraph/colour_legend.h"
#include "scenegraph/pick_markers.h"
#include "scenegraph/render_stats.h"
#include "scenegraph/well_scene.h"

namespace caliper3d::app {

AssembledScene assembleScene(const std::vector<std::string>& files, const LoadOptions& options) {
    std::vector<WellSource> wells;
    wells.reserve(files.size());
    for (const std::string& file : files) wells.push_back({file, {}, {}});
    return assembleScene(wells, options);
}

AssembledScene assembleScene(const std::vector<WellSource>& wells, const LoadOptions& options) {
    return assembleScene(wells, options, ScenePlan());
}

AssembledScene assembleScene(const std::vector<WellSource>& wells, const LoadOptions& options,
                             const ScenePlan& plan) {
    const auto start = std::chrono::steady_clock::now();
    AssembledScene out;
    out.root = scenegraph::NodeRef<SoSeparator>(new SoSeparator);
    out.root->setName("caliper3d_scene");
    const reconstruction::Wellhead origin = reconstruction::sceneOrigin(wells);
    std::vector<std::shared_ptr<const reconstruction::WellGeometry>> loaded;
    std::vector<std::string> files;
    std::vector<io::Diagnostics> diagnostics;
    std::vector<std::size_t> loadedInput;      // each loaded well's place in out.inputs
    std::vector<std::vector<io::Pick>> picks;  // each loaded well's image-log picks
    for (const WellSource& well : wells) {
        InputSummary& input = out.inputs.emplace_back();
        input.file = well.path;
        try {
            reconstruction::LoadedWell one = reconstruction::loadWell(well, options, origin);
            io::PickFile wellPicks;
            if (!well.picksPath.empty()) wellPicks = io::readPicks(well.picksPath);
            one.diagnostics.merge(wellPicks.diagnostics);
            picks.push_back(std::move(wellPicks.picks));
            loaded.push_back(one.geometry);
            files.push_back(well.path);
            const std::vector<double>& md = one.table->depth_m;
            input.rows = md.size();
            if (!md.empty())
                std::tie(input.top_m, input.bottom_m) = std::pair(md.front(), md.back());
            input.addWarnings(one.diagnostics);
            loadedInput.push_back(out.inputs.size() - 1);
            diagnostics.push_back(std::move(one.diagnostics));
        } catch (const std::exception& e) {
            ++out.failures;
            std::fprintf(stderr, "caliper3d: %s\n", e.what());
            input.error = inputErrorFrom(e, well.path);
        }
    }
    double exaggeration = options.radialExaggeration;
    // A well that cannot be coloured as asked fails them all: they share one legend.
    const auto failAll = [&](const std::exception& e) {
        out.failures += static_cast<int>(loaded.size());
        std::fprintf(stderr, "caliper3d: %s\n", e.what());
        for (const std::size_t input : loadedInput)
            out.inputs[input].error = inputErrorFrom(e, out.inputs[input].file);
        loaded.clear();
    };
    // Colour by change: each whole log against the other run, before a plan cuts an interval
    // out of it (the depth match wants the whole overlap).
    std::vector<reconstruction::RunChange> changes;
    if (coloursByChange(options) && !loaded.empty()) {
        try {
            const ChangeReference reference(options);
            for (const auto& well : loaded) changes.push_back(reference.against(*well));
            for (std::size_t w = 0; w < changes.size(); ++w)
                out.inputs[loadedInput[w]].compared = comparedRuns(changes[w], reference.path());
        } catch (const UsageError&) {
            throw;
        } catch (const std::exception& e) {
            failAll(e);
        }
    }
    if (plan && !loaded.empty()) plan(loaded, exaggeration);
    std::vector<std::shared_ptr<const reconstruction::WallColouring>> colourings;
    try {
        if (coloursByChange(options)) {
            std::vector<const reconstruction::RunChange*> each;
            each.reserve(changes.size());
            for (const reconstruction::RunChange& change : changes) each.push_back(&change);
            colourings = reconstruction::changeColourings(loaded, each, options.colour.range);
        } else {
            colourings = reconstruction::wallColourings(loaded, options.colour);
        }
    } catch (const std::exception& e) {
        failAll(e);
    }
    for (std::size_t w = 0; w < loaded.size(); ++w) {
        const auto geometry = std::make_shared<const reconstruction::WellGeometry>(
            loaded[w]->restyled(exaggeration, colourings[w]));
        auto scene = std::make_shared<scenegraph::WellScene>();
        scene->buildAll(*geometry);
        out.geometries.push_back(geometry);
        out.scenes.push_back(scene);
        out.root->addChild(scene->root());
        if (!picks[w].empty())
            out.root->addChild(scenegraph::makePickMarkers(*geometry, picks[w], exaggeration));
        ++out.wells;
        std::printf("%s: %zu sections, %zu segments, %zu triangles at full detail, %zu warnings\n",
                    files[w].c_str(), geometry->table().rowCount(), scene->segmentCount(),
                    scene->fullDetailTriangles(), diagnostics[w].warningCount);
        printWarnings(diagnostics[w]);
    }
    out.load_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return out;
}

const reconstruction::ColourLegend* AssembledScene::legend() const {
    if (geometries.empty() || !geometries.front()->options().colouring) return nullptr;
    return &geometries.front()->options().colouring->legend();
}

std::vector<scenegraph::PictureWell> AssembledScene::pictureWells() const {
    std::vector<scenegraph::PictureWell> wells;
    for (std::size_t w = 0; w < geometries.size(); ++w) wells.push_back({geometries[w], scenes[w]});
    return wells;
}

}  // namespace caliper3d::app
