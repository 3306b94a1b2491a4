// Framing a scene from the camera's direction (scenegraph::frameAll, keepLeftOf): a long,
// thin well fills a tall, narrow view up and down, and a legend's margin keeps it left of it.
#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

#include <Inventor/SbViewVolume.h>
#include <Inventor/SbViewportRegion.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoCube.h>
#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoPointSet.h>
#include <Inventor/nodes/SoSeparator.h>

#include "coin_fixture.h"
#include "scenegraph/camera_setup.h"
#include "scenegraph/node_ref.h"

namespace caliper3d::scenegraph {
namespace {

// The points' extent in the picture, 0 to 1 across and up, as the camera sees them.
struct Extent {
    float left = 1.0f, right = 0.0f, bottom = 1.0f, top = 0.0f;
};
Extent extentOf(const SoCamera& camera, const SbViewportRegion& viewport,
                const std::vector<SbVec3f>& points) {
    const SbViewVolume volume = shownViewVolume(camera, viewport.getViewportAspectRatio());
    Extent e;
    for (const SbVec3f& p : points) {
        SbVec3f s;
        volume.projectToScreen(p, s);
        e.left = std::min(e.left, s[0]);
        e.right = std::max(e.right, s[0]);
        e.bottom = std::min(e.bottom, s[1]);
        e.top = std::max(e.top, s[1]);
    }
    return e;
}
// The same for the 8 corners of the box [lo, hi].
Extent extentOf(const SoCamera& camera, const SbViewportRegion& viewport, const SbVec3f& lo,
                const SbVec3f& hi) {
    std::vector<SbVec3f> corners;
    corners.reserve(8);
    for (int corner = 0; corner < 8; ++corner)
        corners.emplace_back((corner & 1) ? hi[0] : lo[0], (corner & 2) ? hi[1] : lo[1],
                             (corner & 4) ? hi[2] : lo[2]);
    return extentOf(camera, viewport, corners);
}

class CameraFramingTest : public CoinTest {};

// A 100 m "well" (a 0.3 m square column) seen from the north in a view half as wide as it is
// tall: the sphere SoCamera::viewAll fits into the view's width left it 45 % of the height;
// fitted by its corners it takes the height less the room on either end.
TEST_F(CameraFramingTest, ALongWellFillsATallNarrowViewUpAndDown) {
    auto root = makeRef(new SoSeparator);
    auto* column = new SoCube;
    column->width = 0.3f;
    column->height = 100.0f;
    column->depth = 0.3f;
    root->addChild(column);
    auto camera = makeRef(new SoPerspectiveCamera);
    const SbViewportRegion viewport(400, 800);
    aimCamera(camera.get(), ViewDirection::North, SbVec3f(0.0f, 0.0f, 0.0f));
    frameAll(camera.get(), root.get(), viewport);
    const SbVec3f lo(-0.15f, -50.0f, -0.15f), hi(0.15f, 50.0f, 0.15f);
    const Extent e = extentOf(*camera.get(), viewport, lo, hi);
    EXPECT_GT(e.top - e.bottom, 0.85f);  // 1 / kViewAllRoom of the height, near enough
    EXPECT_LE(e.top, 1.0f);
    EXPECT_GE(e.bottom, 0.0f);
    EXPECT_NEAR(0.5f * (e.left + e.right), 0.5f, 0.01f);
    // The same in a wide view: the height still decides.
    const SbViewportRegion wide(1200, 800);
    frameAll(camera.get(), root.get(), wide);
    const Extent w = extentOf(*camera.get(), wide, lo, hi);
    EXPECT_GT(w.top - w.bottom, 0.85f);
    EXPECT_LE(w.top, 1.0f);

    // A legend 240 px wide on the right of the narrow view: the well moves left of it.
    keepLeftOf(camera.get(), root.get(), viewport, 240.0f);
    const Extent k = extentOf(*camera.get(), viewport, lo, hi);
    EXPECT_LE(k.right, 1.0f - 240.0f / 400.0f + 1e-3f);
    EXPECT_GE(k.bottom, 0.0f);
}

// Seen end on (looking down a vertical well, as from inside it), the near end moves across
// far more than the focus does: kept left of a legend, every corner still lies in the room.
TEST_F(CameraFramingTest, AWellSeenEndOnIsKeptLeftOfALegendWhole) {
    auto root = makeRef(new SoSeparator);
    auto* column = new SoCube;
    column->width = 6.5f;
    column->height = 300.0f;
    column->depth = 6.5f;
    root->addChild(column);
    auto camera = makeRef(new SoPerspectiveCamera);
    camera->position.setValue(0.0f, 140.0f, 0.0f);
    camera->pointAt(SbVec3f(0.0f, 0.0f, 0.0f), SbVec3f(0.0f, 0.0f, -1.0f));
    const SbViewportRegion viewport(500, 800);
    frameAll(camera.get(), root.get(), viewport);
    keepLeftOf(camera.get(), root.get(), viewport, 220.0f);
    const Extent k = extentOf(*camera.get(), viewport, SbVec3f(-3.25f, -150.0f, -3.25f),
                              SbVec3f(3.25f, 150.0f, 3.25f));
    EXPECT_GE(k.left, 0.0f);
    EXPECT_LE(k.right, 1.0f - 220.0f / 500.0f + 1e-3f);
    EXPECT_GE(k.bottom, 0.0f);
    EXPECT_LE(k.top, 1.0f);
}

// A wide, flat scene (wells spread over a field, seen from the top) is fitted across.
TEST_F(CameraFramingTest, AWideSceneFitsAcross) {
    auto root = makeRef(new SoSeparator);
    auto* slab = new SoCube;
    slab->width = 400.0f;
    slab->height = 1.0f;
    slab->depth = 100.0f;
    root->addChild(slab);
    auto camera = makeRef(new SoPerspectiveCamera);
    const SbViewportRegion viewport(800, 800);
    aimCamera(camera.get(), ViewDirection::Top, SbVec3f(0.0f, 0.0f, 0.0f));
    frameAll(camera.get(), root.get(), viewport);
    const Extent e = extentOf(*camera.get(), viewport, SbVec3f(-200.0f, -0.5f, -50.0f),
                              SbVec3f(200.0f, 0.5f, 50.0f));
    EXPECT_GT(e.right - e.left, 0.85f);
    EXPECT_LE(e.right, 1.0f);
    EXPECT_GE(e.left, 0.0f);
}

// An L-shaped well (1 km down, then 1 km east) seen from the iso direction: fitted by its
// path's points it fills the view up or across, with the room to spare on either side; the
// corners of its box lie far outside it, and a box fit leaves it much smaller.
TEST_F(CameraFramingTest, AnLShapedWellFittedByItsPathFillsTheView) {
    std::vector<SbVec3f> path;
    for (int i = 0; i <= 100; ++i) path.emplace_back(0.0f, -10.0f * float(i), 0.0f);
    for (int i = 1; i <= 100; ++i) path.emplace_back(10.0f * float(i), -1000.0f, 0.0f);
    const SbViewportRegion viewport(600, 800);
    const auto extentOfPath = [&](const SoCamera& camera) {
        return extentOf(camera, viewport, path);
    };
    auto camera = makeRef(new SoPerspectiveCamera);
    aimCamera(camera.get(), ViewDirection::Iso, SbVec3f(500.0f, -500.0f, 0.0f));
    framePoints(camera.get(), path, viewport);
    const Extent e = extentOfPath(*camera.get());
    EXPECT_GE(e.left, 0.0f);
    EXPECT_LE(e.right, 1.0f);
    EXPECT_GE(e.bottom, 0.0f);
    EXPECT_LE(e.top, 1.0f);
    // One side fills the view less the room (1 / 1.12 = 0.89), and the points are centred.
    EXPECT_GT(std::max(e.right - e.left, e.top - e.bottom), 0.87f);
    EXPECT_NEAR(0.5f * (e.left + e.right), 0.5f, 0.01f);
    EXPECT_NEAR(0.5f * (e.bottom + e.top), 0.5f, 0.01f);

    // The same well's box fit, for comparison: smaller.
    auto root = makeRef(new SoSeparator);
    auto* coords = new SoCoordinate3;
    coords->point.setValues(0, int(path.size()), path.data());
    root->addChild(coords);
    root->addChild(new SoPointSet);
    auto boxed = makeRef(new SoPerspectiveCamera);
    aimCamera(boxed.get(), ViewDirection::Iso, SbVec3f(500.0f, -500.0f, 0.0f));
    frameAll(boxed.get(), root.get(), viewport);
    const Extent b = extentOfPath(*boxed.get());
    EXPECT_LT(std::max(b.right - b.left, b.top - b.bottom),
              std::max(e.right - e.left, e.top - e.bottom) - 0.1f);

    // A tube 50 m in radius drawn about the path: its sides in view too.
    auto padded = makeRef(new SoPerspectiveCamera);
    aimCamera(padded.get(), ViewDirection::Iso, SbVec3f(500.0f, -500.0f, 0.0f));
    framePoints(padded.get(), path, viewport, kViewAllRoom, 50.0f);
    SbVec3f across, up;
    padded->orientation.getValue().multVec(SbVec3f(50.0f, 0.0f, 0.0f), across);
    padded->orientation.getValue().multVec(SbVec3f(0.0f, 50.0f, 0.0f), up);
    std::vector<SbVec3f> sides;
    for (const SbVec3f& p : path)
        for (const SbVec3f& side : {p + across, p - across, p + up, p - up}) sides.push_back(side);
    const Extent t = extentOf(*padded.get(), viewport, sides);
    EXPECT_GE(t.left, 0.0f);
    EXPECT_LE(t.right, 1.0f);
    EXPECT_GE(t.bottom, 0.0f);
    EXPECT_LE(t.top, 1.0f);
    EXPECT_GT(std::max(t.right - t.left, t.top - t.bottom), 0.87f);
    keepLeftOf(padded.get(), path, viewport, 200.0f, 50.0f);
    EXPECT_LE(extentOf(*padded.get(), viewport, sides).right, 1.0f - 200.0f / 600.0f + 1e-3f);

    // Kept left of a 200 px legend: every point left of it.
    keepLeftOf(camera.get(), path, viewport, 200.0f);
    const Extent k = extentOfPath(*camera.get());
    EXPECT_LE(k.right, 1.0f - 200.0f / 600.0f + 1e-3f);
    EXPECT_GE(k.left, 0.0f);
}

}  // namespace
}  // namespace caliper3d::scenegraph
