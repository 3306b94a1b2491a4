#include "app/scene_assembly.h"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <memory>
#include <vector>

#include <Inventor/nodes/SoSeparator.h>

#include "io/parse_error.h"
#include "reconstruction/load/load_well.h"
#include "reconstruction/well_geometry.h"
#include "scenegraph/well_scene.h"

namespace caliper3d::app {

AssembledScene assembleScene(const std::vector<std::string>& files, const LoadOptions& options) {
    std::vector<WellSource> wells;
    wells.reserve(files.size());
    for (const std::string& file : files) wells.push_back({file, {}, {}});
    return assembleScene(wells, options);
}

AssembledScene assembleScene(const std::vector<WellSource>& wells, const LoadOptions& options) {
    AssembledScene out;
    out.root = scenegraph::NodeRef<SoSeparator>(new SoSeparator);
    out.root->setName("caliper3d_scene");
    const reconstruction::Wellhead origin = reconstruction::sceneOrigin(wells);
    for (const WellSource& well : wells) {
        const std::string& file = well.path;
        try {
            const reconstruction::LoadedWell loaded =
                reconstruction::loadWell(well, options, origin);
            scenegraph::WellScene scene;
            scene.buildAll(*loaded.geometry);
            out.geometries.push_back(loaded.geometry);
            out.root->addChild(scene.root());
            ++out.wells;
            const io::Diagnostics& diagnostics = loaded.diagnostics;
            std::printf(
                "%s: %zu sections, %zu segments, %zu triangles at full detail, %zu warnings\n",
                file.c_str(), loaded.table->rowCount(), scene.segmentCount(),
                scene.fullDetailTriangles(), diagnostics.warningCount);
            printWarnings(diagnostics);
        } catch (const std::exception& e) {
            ++out.failures;
            std::fprintf(stderr, "caliper3d: %s\n", e.what());
        }
    }
    return out;
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
