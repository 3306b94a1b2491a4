#pragma once

#include <cstddef>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "scenegraph/camera_setup.h"
#include "scenegraph/node_ref.h"
#include "scenegraph/offscreen_renderer.h"
#include "scenegraph/segment_node_builder.h"
#include "scenegraph/well_annotations.h"

class SoCamera;
class SoSeparator;

namespace caliper3d::reconstruction {
class WellGeometry;
struct ColourLegend;
}  // namespace caliper3d::reconstruction

namespace caliper3d::scenegraph {

class ViewOverlay;
class WellScene;

// One well of a picture: its geometry as drawn (restyled) and its scene, built with its
// coarse levels; the picture adds the finer levels its camera wants.
struct PictureWell {
    std::shared_ptr<const reconstruction::WellGeometry> geometry;
    std::shared_ptr<WellScene> scene;
    // A well held lean (`geometry` sampled: WellGeometry::sampled): reads its rows again, as
    // drawn, when the camera wants finer levels of it. Null: `geometry` holds every row.
    std::function<std::shared_ptr<const reconstruction::WellGeometry>()> rows{};
};

// Scenes for `geometries`, every segment's coarse levels built here (main thread).
std::vector<PictureWell> pictureWells(
    const std::vector<std::shared_ptr<const reconstruction::WellGeometry>>& geometries);

// What a picture shows and how: `caliper3d render` and the window's Save picture both ask
// for theirs so, and get the same picture for the same request.
struct PictureRequest {
    int width = 1024;
    int height = 768;
    // The camera: a viewer's (copied, its aspect made the picture's), else a pose inside the
    // hole (unlit wall, fog), else the logged wells framed from `view` (the path above each
    // log drawn where it falls in view; the annotations from each log's top), or for
    // ViewDirection::Map the whole wells (the annotations from top_m: the wellheads).
    const SoCamera* camera = nullptr;
    std::optional<CameraPose> pose;
    ViewDirection view = ViewDirection::Iso;
    // Measured depths labelled (each well's path clamps them); tick marks off the wall.
    double top_m = 0.0;
    double bottom_m = std::numeric_limits<double>::infinity();
    bool tickMarks = true;
    // Of several wells, the one whose depths are ticked (the current one); the others are
    // named only.
    std::size_t tickedWell = 0;
    bool unloggedPath = false;  // the dashed path above each log (a view of whole wells)
    double radialExaggeration = 1.0;
    std::vector<std::string> caption;  // lines above the exaggeration's
    float pixelTolerance = kDefaultPixelTolerance;
    const reconstruction::ColourLegend* legend = nullptr;  // drawn in a corner when given
    bool stats = false;  // time 5 more frames and count the triangles drawn
};

// A picture and what it cost.
struct Picture {
    Picture();
    ~Picture();
    Picture(Picture&&) noexcept;
    Picture& operator=(Picture&&) noexcept;

    RenderedImage image;
    // What was drawn: camera, lights, the wells, annotations, overlay (for picking).
    NodeRef<SoSeparator> root;
    std::unique_ptr<ViewOverlay> overlay;  // lives as long as the root it is drawn in
    std::size_t refinedSegments = 0;       // finer levels built for this camera
    NamesInView names;                     // wells named in view, and those with no room
    double render_ms = 0.0;  // from the call to the first frame read back (scene, detail, draw)
    // With PictureRequest::stats: the mean of 5 frames drawn after it, and the triangles drawn.
    double frame_ms = std::numeric_limits<double>::quiet_NaN();
    std::size_t trianglesDrawn = 0;
    std::size_t nodesTraversed = 0;  // with stats: nodes a frame visits, culling included
                                     //   (RenderedImage::nodesVisited)
};

// Draws `wells` as `request` asks, offscreen (main thread). Throws std::runtime_error when no
// offscreen context can be made.
Picture drawPicture(const std::vector<PictureWell>& wells, const PictureRequest& request);

// Sets every well's level switches for `view`, then builds and attaches, on the calling
// (main) thread with a helper thread for the meshes, the finer levels each segment should
// show from `eye` (scene frame): what the window's detail worker does as the camera moves,
// done at once for one picture. Returns the segments refined.
std::size_t refineForView(const std::vector<PictureWell>& wells, const glm::vec3& eye,
                          const LodView& view);
// refineForView from the first camera under `renderRoot` for a picture `height` pixels high.
std::size_t refineForCamera(const std::vector<PictureWell>& wells, SoNode* renderRoot, int height,
                            float pixelTolerance = kDefaultPixelTolerance);

}  // namespace caliper3d::scenegraph
