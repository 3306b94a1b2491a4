#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <Inventor/nodes/SoSeparator.h>
#include "app/input_options.h"
#include "app/input_summary.h"
#include "app/lean_well.h"

#include "reconstruction/mesh/lod_levels.h"
#include "reconstruction/well_geometry.h"
#include "scenegraph/camera_setup.h"
#include "scenegraph/node_ref.h"
#include "scenegraph/picture/picture.h"
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
    // As drawn; a well of a field held lean (FieldRows) by a sample of its rows.
    std::vector<std::shared_ptr<const reconstruction::WellGeometry>> geometries;
    std::vector<std::shared_ptr<scenegraph::WellScene>> scenes;  // one per geometry
    // One per geometry: reads a well held lean again, as drawn (null for a well held whole).
    std::vector<std::function<std::shared_ptr<const reconstruction::WellGeometry>()>> rows;
    // The first well's colouring, where its geometry is a sample without one (the legend).
    std::shared_ptr<const reconstruction::WallColouring> legendColouring;
    double load_ms = 0.0;  // reading, geometry and the coarse levels of every well
    // One per well asked for, in order: rows, depths and warnings, or why it failed (the
    // verb's name, outputs and cost are the caller's to add).
    std::vector<InputSummary> inputs;
    // What the wall's colours mean (every well shares it); null with no well.
    const reconstruction::ColourLegend* legend() const;
    // Each well's geometry and scene, for scenegraph::drawPicture.
    std::vector<scenegraph::PictureWell> pictureWells() const;
};
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
// How many of a field's rows a scene holds (docs/architecture.md, "A field held lean"). With a
// budget, once the wells read hold more rows than it, every well is kept by a sample of its
// rows (WellGeometry::sampled: enough for its labels, framing and scale), read again to build
// its nodes, and again when a picture's camera wants its finer levels. The plan then sees the
// samples: it may choose the exaggeration, not cut an interval. Colour by change holds every row.
struct FieldRows {
    std::size_t budget = 0;       // rows; 0: every well holds every row
    bool keepFirstWhole = false;  // the first well keeps every row (a picture down its hole)
    // A picture makes each span's segment nodes as its camera comes near (refineForCamera).
    scenegraph::SegmentNodes segmentNodes = scenegraph::SegmentNodes::now;
};

// Each well's segments come with their levels from `firstCoarseLevel` on (a picture of a field
// needs fewer up front: reconstruction::kFieldFirstCoarseLevel). Several wells are read side by
// side, one on each of the machine's threads, and each well's meshes are built on a worker
// while the nodes of the one before are made here.
AssembledScene assembleScene(const std::vector<WellSource>& wells, const LoadOptions& options,
                             const ScenePlan& plan,
                             int firstCoarseLevel = reconstruction::kFirstCoarseLevel,
                             const FieldRows& rows = {});

}  // namespace caliper3d::app
