#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <Inventor/nodes/SoSeparator.h>
#include "app/input_options.h"
#include "app/input_summary.h"

#include "reconstruction/well_geometry.h"
#include "scenegraph/camera_setup.h"
#include "scenegraph/node_ref.h"
#include "scenegraph/well_scene.h"

class SoNode;
class SoSeparator;

namespace caliper3d::app {

// Every readable well of `files` in one scene, each under its own separator.
// Reports each file's result on stdout (bad files on stderr) and keeps going.
struct AssembledScene {
    scenegraph::NodeRef<SoSeparator> root;
    int wells = 0;
    int failures = 0;
    std::vector<std::shared_ptr<const reconstruction::WellGeometry>> geometries;
    std::vector<std::shared_ptr<scenegraph::WellScene>> scenes;  // one per geometry
    double load_ms = 0.0;  // reading, geometry and the coarse levels of every well
    // One per well asked for, in order: rows, depths and warnings, or why it failed (the
    // verb's name, outputs and cost are the caller's to add).
    std::vector<InputSummary> inputs;
    // What the wall's colours mean (every well shares it); null with no well.
    const reconstruction::ColourLegend* legend() const;
};
// The wall colourings `request` asks for, one per well, sharing one colour range so a colour
// means the same value in each (the union of their own ranges, when it comes from the
// data). Throws std::invalid_argument as reconstruction::makeWallColouring does.
// `values`: each well's reconstruction::sectionValues where known (null or missing: computed
// when the quantity needs them).
std::vector<std::shared_ptr<const reconstruction::WallColouring>> wallColourings(
    const std::vector<std::shared_ptr<const reconstruction::WellGeometry>>& wells,
    const reconstruction::ColourRequest& request,
    const std::vector<const reconstruction::SectionValues*>& values = {});

// The first well's wellhead is the scene origin; each well's survey, if
// given, replaces its log's DEVI/HAZI for the path.
AssembledScene assembleScene(const std::vector<WellSource>& wells, const LoadOptions& options);
AssembledScene assembleScene(const std::vector<std::string>& files, const LoadOptions& options);

// What of the wells a scene draws, decided once every readable well is loaded and before it
// is coloured or any node is built: it may replace a well's geometry with an interval of it
// (reconstruction::intervalGeometry) and change the radial exaggeration the wells are drawn
// with (options.radialExaggeration on entry): render_command.cpp. An exception it throws
// leaves assembleScene.
using ScenePlan =
    std::function<void(std::vector<std::shared_ptr<const reconstruction::WellGeometry>>& wells,
                       double& radialExaggeration)>;
AssembledScene assembleScene(const std::vector<WellSource>& wells, const LoadOptions& options,
                             const ScenePlan& plan);

// Sets every well's level switches for `view`, then builds and attaches, on the calling
// (main) thread with a helper thread for the meshes, the finer levels each segment should
// show from `eye` (scene frame): what the window's detail worker does as the camera moves,
// done at once for one picture. Returns the segments refined.
std::size_t refineForView(AssembledScene& scene, const glm::vec3& eye,
                          const scenegraph::LodView& view);

// refineForView from the first camera under `renderRoot` (a root made by
// scenegraph::makeRenderRoot over scene.root) for a picture `height` pixels high.
std::size_t refineForCamera(AssembledScene& scene, SoNode* renderRoot, int height,
                            float pixelTolerance = scenegraph::kDefaultPixelTolerance);

// Adds the legend of the scene's wall colours over a picture made from `renderRoot` (a
// root made by scenegraph::makeRenderRoot over scene.root); nothing without a well.
void addColourLegend(SoSeparator* renderRoot, const AssembledScene& scene);

// The fly-through view: a camera on the first well's axis at measured depth
// `md_m`, looking down the hole, high side up.
scenegraph::CameraPose downHolePose(const reconstruction::WellGeometry& geometry, double md_m);

// The bundled example well (written by 'caliper3d synth' at build time).
std::string exampleWellPath();

}  // namespace caliper3d::app
