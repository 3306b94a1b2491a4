#include "scenegraph/picture/picture.h"

#include <algorithm>
#include <chrono>
#include <thread>

#include <glm/vec3.hpp>

#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoSeparator.h>

#include "reconstruction/mesh/lod_levels.h"
#include "reconstruction/well_geometry.h"
#include "scenegraph/colour_legend.h"
#include "scenegraph/main_thread.h"
#include "scenegraph/render_stats.h"
#include "scenegraph/view_overlay.h"
#include "scenegraph/well_annotations.h"
#include "scenegraph/well_scene.h"

namespace caliper3d::scenegraph {

namespace {

double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

}  // namespace

Picture::Picture() = default;
Picture::~Picture() = default;
Picture::Picture(Picture&&) noexcept = default;
Picture& Picture::operator=(Picture&&) noexcept = default;

std::vector<PictureWell> pictureWells(
    const std::vector<std::shared_ptr<const reconstruction::WellGeometry>>& geometries) {
    std::vector<PictureWell> wells;
    for (const auto& geometry : geometries) {
        auto scene = std::make_shared<WellScene>();
        scene->buildAll(*geometry);
        wells.push_back({geometry, std::move(scene)});
    }
    return wells;
}

Picture drawPicture(const std::vector<PictureWell>& wells, const PictureRequest& request) {
    assertMainThread("drawPicture");
    const auto start = std::chrono::steady_clock::now();
    const int width = request.width, height = request.height;
    // The wells, then the path above each log: a picture framed from `view` frames the logged
    // wells only, the path drawn where it falls in view (a short log deep in a well is the
    // picture, not a dot under the path from the wellhead).
    auto* scene = new SoSeparator;
    auto* logged = new SoSeparator;
    scene->addChild(logged);
    for (const PictureWell& well : wells) {
        logged->addChild(well.scene->root());
        if (request.unloggedPath)
            if (SoSeparator* above = makeUnloggedPath(*well.geometry)) scene->addChild(above);
    }
    Picture out;
    const bool framedFromView = !request.camera && !request.pose;
    // A map frames the whole wells and names them at their wellheads; other views frame the
    // logs and name each at its top.
    const bool map = framedFromView && request.view == ViewDirection::Map;
    if (request.camera)
        out.root = makeRef(makeRenderRoot(scene, *request.camera, width, height));
    else if (request.pose)
        out.root = makeRef(makeRenderRoot(scene, *request.pose));
    else
        out.root =
            makeRef(makeRenderRoot(scene, request.view, width, height, map ? nullptr : logged));
    SoSeparator* root = out.root.get();
    out.overlay = std::make_unique<ViewOverlay>();
    std::vector<std::string> caption = request.caption;
    caption.push_back(exaggerationCaption(request.radialExaggeration));
    out.overlay->setCaption(caption);
    // Depth ticks, labels and each well's name for this camera (no part in its framing); in a
    // picture framed on the logs, from the top of each log (the name there, in view). With
    // several wells only the current one is ticked; every label of every well is placed at
    // once, clear of the others, the overlay and the legend.
    if (const SoCamera* camera = findCamera(root)) {
        std::vector<AnnotatedWell> annotated;
        for (std::size_t i = 0; i < wells.size(); ++i) {
            const std::vector<double>& depth = wells[i].geometry->table().depth_m;
            const double top = framedFromView && !map && !depth.empty()
                                   ? std::max(request.top_m, depth.front())
                                   : request.top_m;
            annotated.push_back({wells[i].geometry.get(), top, request.radialExaggeration,
                                 wells.size() == 1 || i == request.tickedWell});
        }
        PlacedAnnotations placed;
        out.names = placeClearOfNamesLine(wells.size(), [&](const std::string& namesLine) {
            std::vector<std::string> lines = caption;
            if (!namesLine.empty()) lines.push_back(namesLine);
            out.overlay->setCaption(lines);
            std::vector<ScreenBox> obstacles = out.overlay->occupied(height);
            if (request.legend) obstacles.push_back(legendPanel_px(*request.legend, width, height));
            placed = placeAnnotations(annotated, *camera, width, height, request.bottom_m,
                                      request.tickMarks, obstacles);
            return namesInView(placed);
        });
        if (const std::string leftOut = namesLeftOutCaption(out.names); !leftOut.empty())
            caption.push_back(leftOut);
        out.overlay->setCaption(caption);
        for (std::size_t i = 0; i < wells.size(); ++i)
            root->addChild(
                makeWellAnnotations(*wells[i].geometry, placed.views[i], placed.labels[i]));
    }
    root->addChild(out.overlay->root());
    out.refinedSegments = refineForCamera(wells, root, height, request.pixelTolerance);
    if (request.legend) root->addChild(makeColourLegend(*request.legend, height));
    OffscreenRenderer renderer;
    out.image = renderer.render(root, width, height, kBackgroundColour);
    out.render_ms = msSince(start);
    if (request.stats) {
        out.frame_ms = renderer.timeFrames(root, width, height, kBackgroundColour, 5);
        out.trianglesDrawn = trianglesDrawn(root, width, height);
        out.nodesTraversed = out.image.nodesVisited;
    }
    return out;
}

std::size_t refineForView(const std::vector<PictureWell>& wells, const glm::vec3& eye,
                          const LodView& view) {
    std::size_t refined = 0;
    for (const PictureWell& picture : wells) {
        WellScene& well = *picture.scene;
        well.setLodView(view);
        const std::vector<DetailRequest> wanted = well.wantedDetail(eye);
        if (wanted.empty()) continue;
        // A well held lean is read again for its finer levels, and let go after.
        const std::shared_ptr<const reconstruction::WellGeometry> whole =
            picture.rows ? picture.rows() : picture.geometry;
        const reconstruction::WellGeometry& geometry = *whole;
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

std::size_t refineForCamera(const std::vector<PictureWell>& wells, SoNode* renderRoot, int height,
                            float pixelTolerance) {
    auto* camera = dynamic_cast<SoPerspectiveCamera*>(findCamera(renderRoot));
    if (!camera) return 0;
    const SbVec3f eye = camera->position.getValue();
    LodView view = lodViewFor(height, camera->heightAngle.getValue(), pixelTolerance);
    view.visibility_m = fogVisibility(renderRoot);
    return refineForView(wells, glm::vec3(eye[0], eye[1], eye[2]), view);
}

}  // namespace caliper3d::scenegraph
