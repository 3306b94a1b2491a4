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

#include "io/parse_error.h"
#include "reconstruction/load/load_well.h"
#include "reconstruction/mesh/lod_levels.h"
#include "reconstruction/well_geometry.h"
#include "scenegraph/colour_legend.h"
#include "scenegraph/render_stats.h"
#include "scenegraph/well_scene.h"

namespace caliper3d::app {

AssembledScene assembleScene(const std::vector<std::string>& files, const LoadOptions& options) {
    std::vector<WellSource> wells;
    wells.reserve(files.size());
    for (const std::string& file : files) wells.push_back({file, {}, {}});
    return assembleScene(wells, options);
}

std::vector<std::shared_ptr<const reconstruction::WallColouring>> wallColourings(
    const std::vector<std::shared_ptr<const reconstruction::WellGeometry>>& wells,
    const reconstruction::ColourRequest& request,
    const std::vector<const reconstruction::SectionValues*>& values) {
    auto valuesOf = [&values](std::size_t w) { return w < values.size() ? values[w] : nullptr; };
    std::vector<std::shared_ptr<const reconstruction::WallColouring>> out;
    for (std::size_t w = 0; w < wells.size(); ++w)
        out.push_back(reconstruction::makeWallColouring(*wells[w], request, valuesOf(w)));
    if (out.size() < 2 || request.range ||
        out.front()->legend().kind != reconstruction::ColourMapKind::Sequential)
        return out;
    double lo = out.front()->legend().lo, hi = out.front()->legend().hi;
    for (const auto& colouring : out) {
        lo = std::min(lo, colouring->legend().lo);
        hi = std::max(hi, colouring->legend().hi);
    }
    reconstruction::ColourRequest shared = request;
    shared.range = std::make_pair(lo, hi);
    for (std::size_t w = 0; w < wells.size(); ++w) {
        auto colouring = reconstruction::makeWallColouring(*wells[w], shared, valuesOf(w));
        reconstruction::ColourLegend legend = colouring->legend();
        legend.range =
            out[w]->legend().range + ", over all " + std::to_string(wells.size()) + " wells";
        out[w] = std::make_shared<const reconstruction::WallColouring>(
            colouring->withLegend(std::move(legend)));
    }
    return out;
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
    std::vector<std::size_t> loadedInput;  // each loaded well's place in out.inputs
    for (const WellSource& well : wells) {
        InputSummary& input = out.inputs.emplace_back();
        input.file = well.path;
        try {
            reconstruction::LoadedWell one = reconstruction::loadWell(well, options, origin);
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
    if (plan && !loaded.empty()) plan(loaded, exaggeration);
    std::vector<std::shared_ptr<const reconstruction::WallColouring>> colourings;
    try {
        colourings = wallColourings(loaded, options.colour);
    } catch (const std::exception& e) {
        out.failures += static_cast<int>(loaded.size());
        std::fprintf(stderr, "caliper3d: %s\n", e.what());
        for (const std::size_t input : loadedInput)
            out.inputs[input].error = inputErrorFrom(e, out.inputs[input].file);
        loaded.clear();
    }
    for (std::size_t w = 0; w < loaded.size(); ++w) {
        const auto geometry = std::make_shared<const reconstruction::WellGeometry>(
            loaded[w]->restyled(exaggeration, colourings[w]));
        auto scene = std::make_shared<scenegraph::WellScene>();
        scene->buildAll(*geometry);
        out.geometries.push_back(geometry);
        out.scenes.push_back(scene);
        out.root->addChild(scene->root());
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

std::size_t refineForView(AssembledScene& scene, const glm::vec3& eye,
                          const scenegraph::LodView& view) {
    std::size_t refined = 0;
    for (std::size_t w = 0; w < scene.scenes.size(); ++w) {
        scenegraph::WellScene& well = *scene.scenes[w];
        const reconstruction::WellGeometry& geometry = *scene.geometries[w];
        well.setLodView(view);
        const std::vector<scenegraph::DetailRequest> wanted = well.wantedDetail(eye);
        std::vector<reconstruction::SegmentMesh> meshes(wanted.size());
        // Meshes on two threads (they read the immutable geometry only); nodes on this one.
        auto build = [&](std::size_t from) {
            for (std::size_t i = from; i < wanted.size(); i += 2)
                meshes[i] = reconstruction::buildSegmentLevels(geometry, wanted[i].segment,
                                                               wanted[i].level, wanted[i].heldFrom);
        };
        std::thread helper(build, 1);
        build(0);
        helper.join();
        for (const reconstruction::SegmentMesh& mesh : meshes) well.attachFinerLevels(mesh);
        refined += wanted.size();
    }
    return refined;
}

std::size_t refineForCamera(AssembledScene& scene, SoNode* renderRoot, int height,
                            float pixelTolerance) {
    auto* camera = dynamic_cast<SoPerspectiveCamera*>(scenegraph::findCamera(renderRoot));
    if (!camera) return 0;
    const SbVec3f eye = camera->position.getValue();
    scenegraph::LodView view =
        scenegraph::lodViewFor(height, camera->heightAngle.getValue(), pixelTolerance);
    view.visibility_m = scenegraph::fogVisibility(renderRoot);
    return refineForView(scene, glm::vec3(eye[0], eye[1], eye[2]), view);
}

void addColourLegend(SoSeparator* renderRoot, const AssembledScene& scene) {
    if (const reconstruction::ColourLegend* legend = scene.legend())
        renderRoot->addChild(scenegraph::makeColourLegend(*legend));
}

scenegraph::CameraPose downHolePose(const reconstruction::WellGeometry& geometry, double md_m) {
    const auto& depth = geometry.table().depth_m;
    const std::size_t row = static_cast<std::size_t>(
        std::lower_bound(depth.begin(), depth.end(), md_m) - depth.begin());
    const std::size_t r = std::min(row, depth.size() - 1);
    const reconstruction::PathPoint& p = geometry.path()[r];
    const glm::dvec3 eye = reconstruction::toScene(geometry.centre(r));
    const glm::dvec3 look =
        reconstruction::toScene(reconstruction::holeTangent(p.inc_deg, p.azi_deg));
    const glm::dvec3 up = reconstruction::toScene(reconstruction::highSide(p.inc_deg, p.azi_deg));
    scenegraph::CameraPose pose;
    for (int i = 0; i < 3; ++i) {
        pose.eye[i] = static_cast<float>(eye[i]);
        pose.look[i] = static_cast<float>(look[i]);
        pose.up[i] = static_cast<float>(up[i]);
    }
    return pose;
}

std::string exampleWellPath() {
    if (const char* env = std::getenv("CALIPER3D_EXAMPLE")) return env;
    return CALIPER3D_EXAMPLE_WELL;
}

}  // namespace caliper3d::app
