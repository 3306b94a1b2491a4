#include "scenegraph/camera_setup.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <Inventor/SbViewVolume.h>
#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/nodes/SoDirectionalLight.h>
#include <Inventor/nodes/SoEnvironment.h>
#include <Inventor/nodes/SoLightModel.h>
#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoSeparator.h>

#include "reconstruction/section/section_frame.h"
#include "reconstruction/well_geometry.h"
#include "scenegraph/main_thread.h"

namespace caliper3d::scenegraph {

std::optional<ViewDirection> parseViewDirection(const std::string& name) {
    if (name == "iso") return ViewDirection::Iso;
    if (name == "north") return ViewDirection::North;
    if (name == "east") return ViewDirection::East;
    if (name == "top") return ViewDirection::Top;
    if (name == "map") return ViewDirection::Map;
    return std::nullopt;
}

SbViewVolume shownViewVolume(const SoCamera& camera, float aspect) {
    SbViewVolume volume = const_cast<SoCamera&>(camera).getViewVolume(aspect);
    if (camera.viewportMapping.getValue() == SoCamera::ADJUST_CAMERA && aspect > 0.0f &&
        aspect < 1.0f)
        volume.scale(1.0f / aspect);
    return volume;
}

namespace {

constexpr float kMaxMargin = 0.6f;  // of a view's width, at most, kept clear on its right

// The 8 corners of `box`.
std::vector<SbVec3f> cornersOf(const SbBox3f& box) {
    SbVec3f lo, hi;
    box.getBounds(lo, hi);
    std::vector<SbVec3f> corners;
    corners.reserve(8);
    for (int corner = 0; corner < 8; ++corner)
        corners.emplace_back((corner & 1) ? hi[0] : lo[0], (corner & 2) ? hi[1] : lo[1],
                             (corner & 4) ? hi[2] : lo[2]);
    return corners;
}

// The 8 corners of `root`'s bounding box; none when it is empty.
std::vector<SbVec3f> boxCorners(SoNode* root, const SbViewportRegion& viewport) {
    SoGetBoundingBoxAction bbox(viewport);
    bbox.apply(root);
    const SbBox3f& box = bbox.getBoundingBox();
    return box.isEmpty() ? std::vector<SbVec3f>{} : cornersOf(box);
}

// The distance from `centre`, looking along the camera's view, at which every one of `points`
// lies inside a perspective view whose half-widths at unit distance are `tanH` across and
// `tanV` up.
float fittingDistance(const std::vector<SbVec3f>& points, const SbVec3f& centre,
                      const SbRotation& orientation, float tanH, float tanV) {
    SbVec3f look, right, up;
    orientation.multVec(SbVec3f(0.0f, 0.0f, -1.0f), look);
    orientation.multVec(SbVec3f(1.0f, 0.0f, 0.0f), right);
    orientation.multVec(SbVec3f(0.0f, 1.0f, 0.0f), up);
    float distance = 0.01f;
    for (const SbVec3f& p : points) {
        const SbVec3f d = p - centre;
        const float depth = d.dot(look);  // positive: beyond the centre
        distance = std::max(distance, std::abs(d.dot(up)) / tanV - depth);
        distance = std::max(distance, std::abs(d.dot(right)) / tanH - depth);
    }
    return distance;
}

// The points' extent across the picture (0 to 1, left to right) from the camera as it is,
// each widened by `pad` either side.
std::pair<float, float> acrossOf(const SoCamera* camera, const std::vector<SbVec3f>& points,
                                 const SbViewportRegion& viewport, float pad = 0.0f) {
    const SbViewVolume volume = shownViewVolume(*camera, viewport.getViewportAspectRatio());
    SbVec3f across;
    camera->orientation.getValue().multVec(SbVec3f(pad, 0.0f, 0.0f), across);
    float left = 1.0f, right = 0.0f;
    for (const SbVec3f& p : points) {
        SbVec3f a, b;
        volume.projectToScreen(p - across, a);
        volume.projectToScreen(p + across, b);
        left = std::min({left, a[0], b[0]});
        right = std::max({right, a[0], b[0]});
    }
    return {left, right};
}

}  // namespace

void frameAll(SoCamera* camera, SoNode* root, const SbViewportRegion& viewport, float room) {
    assertMainThread("frameAll");
    camera->viewAll(root, viewport);  // near and far planes, and an orthographic camera
    if (camera->isOfType(SoPerspectiveCamera::getClassTypeId())) {
        SoGetBoundingBoxAction bbox(viewport);
        bbox.apply(root);
        const SbBox3f& box = bbox.getBoundingBox();
        // The view's own half-widths, as Coin draws it.
        const SbViewVolume volume = shownViewVolume(*camera, viewport.getViewportAspectRatio());
        const float near = volume.getNearDist();
        if (!box.isEmpty() && near > 0.0f && volume.getWidth() > 0.0f &&
            volume.getHeight() > 0.0f) {
            const SbVec3f centre = box.getCenter();
            const float distance =
                fittingDistance(cornersOf(box), centre, camera->orientation.getValue(),
                                volume.getWidth() / 2.0f / near, volume.getHeight() / 2.0f / near);
            SbVec3f look;
            camera->orientation.getValue().multVec(SbVec3f(0.0f, 0.0f, -1.0f), look);
            camera->position = centre - look * (distance * room);
            camera->focalDistance = distance * room;
            return;
        }
    }
    SbVec3f look;
    camera->orientation.getValue().multVec(SbVec3f(0.0f, 0.0f, -1.0f), look);
    const float distance = camera->focalDistance.getValue();
    const SbVec3f focus = camera->position.getValue() + look * distance;
    camera->position = focus - look * (distance * room);
    camera->focalDistance = distance * room;
}

void keepLeftOf(SoCamera* camera, SoNode* root, const SbViewportRegion& viewport,
                float rightMargin_px) {
    assertMainThread("keepLeftOf");
    keepLeftOf(camera, boxCorners(root, viewport), viewport, rightMargin_px);
}

void keepLeftOf(SoCamera* camera, const std::vector<SbVec3f>& points,
                const SbViewportRegion& viewport, float rightMargin_px, float pad) {
    assertMainThread("keepLeftOf");
    const float width = viewport.getViewportSizePixels()[0];
    if (!(rightMargin_px > 0.0f) || !(width > 0.0f) || points.empty()) return;
    // A narrow view keeps what it can: the wells keep at least this much of its width.
    rightMargin_px = std::min(rightMargin_px, kMaxMargin * width);
    const float room = 1.0f - rightMargin_px / width;  // of the width, from the left
    SbVec3f look, right;
    camera->orientation.getValue().multVec(SbVec3f(0.0f, 0.0f, -1.0f), look);
    camera->orientation.getValue().multVec(SbVec3f(1.0f, 0.0f, 0.0f), right);
    // Back off (about the focus) by `factor`.
    const auto backOff = [&](float factor) {
        const float distance = camera->focalDistance.getValue();
        const SbVec3f focus = camera->position.getValue() + look * distance;
        camera->position = focus - look * (distance * factor);
        camera->focalDistance = distance * factor;
    };
    // Move across by `shift` of the picture's width as seen at the focal distance.
    const auto moveAcross = [&](float shift) {
        const SbViewVolume volume = shownViewVolume(*camera, viewport.getViewportAspectRatio());
        const float distance = camera->focalDistance.getValue();
        const SbVec3f focus = camera->position.getValue() + look * distance;
        SbVec3f a, b;
        volume.projectToScreen(focus, a);
        volume.projectToScreen(focus + right * distance, b);
        const float perUnit = (b[0] - a[0]) / distance;  // of the width, per scene unit across
        if (perUnit > 0.0f)
            camera->position = camera->position.getValue() + right * (shift / perUnit);
    };
    // Its centre, when right of it, to the middle of the room.
    const auto centreInRoom = [&] {
        const auto [left, rightEdge] = acrossOf(camera, points, viewport, pad);
        if (0.5f * (left + rightEdge) > 0.5f * room)
            moveAcross(0.5f * (left + rightEdge) - 0.5f * room);
    };
    // Wider than the room: back off until it fits.
    const auto [left, rightEdge] = acrossOf(camera, points, viewport, pad);
    if (rightEdge - left > room) backOff((rightEdge - left) / room);
    centreInRoom();
    // A scene deep along the view (a well seen end on) moves across more at its near end than
    // at the focus: checked, and backed off further until it lies in the room.
    for (int round = 0; round < 16; ++round) {
        const auto [l, r] = acrossOf(camera, points, viewport, pad);
        if (l >= 0.0f && r <= room) return;
        backOff(1.25f);
        centreInRoom();
    }
}

void framePoints(SoCamera* camera, const std::vector<SbVec3f>& points,
                 const SbViewportRegion& viewport, float room, float pad) {
    assertMainThread("framePoints");
    if (points.empty() || !camera->isOfType(SoPerspectiveCamera::getClassTypeId())) return;
    const SbViewVolume volume = shownViewVolume(*camera, viewport.getViewportAspectRatio());
    const float near = volume.getNearDist();
    if (!(near > 0.0f) || !(volume.getWidth() > 0.0f) || !(volume.getHeight() > 0.0f)) return;
    // Half-widths at unit distance, narrowed by the room to spare.
    const float tanH = volume.getWidth() / 2.0f / near / room;
    const float tanV = volume.getHeight() / 2.0f / near / room;
    SbVec3f look, right, up;
    camera->orientation.getValue().multVec(SbVec3f(0.0f, 0.0f, -1.0f), look);
    camera->orientation.getValue().multVec(SbVec3f(1.0f, 0.0f, 0.0f), right);
    camera->orientation.getValue().multVec(SbVec3f(0.0f, 1.0f, 0.0f), up);
    // The points in the camera's axes about their box's centre; the eye sought as an offset
    // across (a, b) and a distance back (d) from there: each round takes the distance at which
    // every point fits, then centres the points' extent in the picture at that distance.
    SbBox3f box;
    for (const SbVec3f& p : points) box.extendBy(p);
    const SbVec3f centre = box.getCenter();
    std::vector<SbVec3f> local;
    local.reserve(points.size());
    for (const SbVec3f& p : points) {
        const SbVec3f d = p - centre;
        local.emplace_back(d.dot(right), d.dot(up), d.dot(look));
    }
    float a = 0.0f, b = 0.0f, d = 0.0f;
    for (int round = 0; round < 4; ++round) {
        d = 1e-3f;
        for (const SbVec3f& q : local)
            d = std::max({d, (std::abs(q[0] - a) + pad) / tanH - q[2],
                          (std::abs(q[1] - b) + pad) / tanV - q[2]});
        float x0 = 1e30f, x1 = -1e30f, y0 = 1e30f, y1 = -1e30f;
        for (const SbVec3f& q : local) {
            const float depth = d + q[2];
            x0 = std::min(x0, (q[0] - a - pad) / depth);
            x1 = std::max(x1, (q[0] - a + pad) / depth);
            y0 = std::min(y0, (q[1] - b - pad) / depth);
            y1 = std::max(y1, (q[1] - b + pad) / depth);
        }
        a += 0.5f * (x0 + x1) * d;
        b += 0.5f * (y0 + y1) * d;
    }
    d = 1e-3f;
    for (const SbVec3f& q : local)
        d = std::max({d, (std::abs(q[0] - a) + pad) / tanH - q[2],
                      (std::abs(q[1] - b) + pad) / tanV - q[2]});
    camera->position = centre + right * a + up * b - look * d;
    camera->focalDistance = d;
}

void frameFrom(SoCamera* camera, SoNode* root, const SbViewportRegion& viewport,
               ViewDirection view) {
    assertMainThread("frameFrom");
    SoGetBoundingBoxAction bbox(viewport);
    bbox.apply(root);
    if (bbox.getBoundingBox().isEmpty()) return;
    aimCamera(camera, view, bbox.getBoundingBox().getCenter());
    frameAll(camera, root, viewport);
}

void aimCamera(SoCamera* camera, ViewDirection view, const SbVec3f& centre) {
    SbVec3f look(-1.0f, -0.7f, -1.0f), up(0.0f, 1.0f, 0.0f);
    switch (view) {
        case ViewDirection::Iso:
            break;
        case ViewDirection::North:
            look.setValue(0.0f, 0.0f, -1.0f);
            break;
        case ViewDirection::East:
            look.setValue(1.0f, 0.0f, 0.0f);
            break;
        case ViewDirection::Top:
        case ViewDirection::Map:
            look.setValue(0.0f, -1.0f, 0.0f);
            up.setValue(0.0f, 0.0f, -1.0f);
            break;
    }
    look.normalize();
    camera->position = centre - look;
    camera->pointAt(centre, up);
}

namespace {

// A light shining along `camera`'s view, like the examiner viewer's headlight.
SoDirectionalLight* headlight(const SoCamera& camera) {
    SbVec3f look;
    camera.orientation.getValue().multVec(SbVec3f(0.0f, 0.0f, -1.0f), look);
    look.normalize();
    auto* light = new SoDirectionalLight;
    light->direction = look;
    return light;
}

}  // namespace

SoSeparator* makeRenderRoot(SoNode* scene, const SoCamera& camera, int width, int height) {
    assertMainThread("makeRenderRoot");
    auto* root = new SoSeparator;
    auto* copy = static_cast<SoCamera*>(camera.copy());
    copy->aspectRatio = static_cast<float>(width) / static_cast<float>(height);
    root->addChild(copy);
    root->addChild(headlight(*copy));
    root->addChild(scene);
    return root;
}

SoSeparator* makeRenderRoot(SoNode* scene, ViewDirection view, int width, int height,
                            SoNode* framed) {
    assertMainThread("makeRenderRoot");
    const SbViewportRegion viewport(static_cast<short>(width), static_cast<short>(height));
    SoGetBoundingBoxAction bbox(viewport);
    bbox.apply(framed ? framed : scene);
    const SbVec3f centre =
        bbox.getBoundingBox().isEmpty() ? SbVec3f(0, 0, 0) : bbox.getBoundingBox().getCenter();

    auto* root = new SoSeparator;
    auto* camera = new SoPerspectiveCamera;
    aimCamera(camera, view, centre);
    SbVec3f look;
    camera->orientation.getValue().multVec(SbVec3f(0.0f, 0.0f, -1.0f), look);
    look.normalize();
    root->addChild(camera);
    root->addChild(headlight(*camera));
    root->addChild(scene);
    // Back off until every corner of the bounding box is inside the view
    // frustum: tighter than SoCamera::viewAll's bounding sphere for a long, thin
    // well (and viewAll also clips the sphere's rim and ignores slack).
    const SbBox3f& box = bbox.getBoundingBox();
    SbVec3f lo(0, 0, 0), hi(0, 0, 0);
    if (!box.isEmpty()) box.getBounds(lo, hi);
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    const float tanV = std::tan(camera->heightAngle.getValue() / 2.0f);
    const float tanH = tanV * aspect;
    float distance = fittingDistance(cornersOf(SbBox3f(lo, hi)), centre,
                                     camera->orientation.getValue(), tanH, tanV);
    const float radius = std::max(0.01f, (hi - centre).length());
    distance *= 1.05f;
    camera->position = centre - look * distance;
    camera->nearDistance = std::max(distance - radius * 1.1f, distance * 1e-3f);
    camera->farDistance = distance + radius * 1.1f;
    return root;
}

SoSeparator* makeRenderRoot(SoNode* scene, const CameraPose& pose) {
    assertMainThread("makeRenderRoot");
    auto* root = new SoSeparator;
    auto* camera = new SoPerspectiveCamera;
    const SbVec3f eye(pose.eye), look(pose.look);
    camera->position = eye;
    camera->pointAt(eye + look, SbVec3f(pose.up));
    camera->heightAngle = pose.heightAngle_rad;
    camera->nearDistance = 0.01f;
    camera->farDistance = 500.0f;
    // Inside the hole every wall is seen at a grazing angle, so lighting from
    // the eye leaves it black: show the wall colours unlit and let fog in the
    // background colour give depth.
    auto* lightModel = new SoLightModel;
    lightModel->model = SoLightModel::BASE_COLOR;
    auto* fog = new SoEnvironment;
    fog->fogType = SoEnvironment::HAZE;
    fog->fogColor.setValue(pose.fogColour);
    fog->fogVisibility = pose.fogVisibility_m;
    root->addChild(camera);
    root->addChild(lightModel);
    root->addChild(fog);
    root->addChild(scene);
    return root;
}

CameraPose downHolePose(const reconstruction::WellGeometry& geometry, double md_m) {
    const auto& depth = geometry.table().depth_m;
    const std::size_t row = static_cast<std::size_t>(
        std::lower_bound(depth.begin(), depth.end(), md_m) - depth.begin());
    const std::size_t r = std::min(row, depth.size() - 1);
    const reconstruction::PathPoint& p = geometry.path()[r];
    const glm::dvec3 eye = reconstruction::toScene(geometry.centre(r));
    const glm::dvec3 look =
        reconstruction::toScene(reconstruction::holeTangent(p.inc_deg, p.azi_deg));
    const glm::dvec3 up = reconstruction::toScene(reconstruction::highSide(p.inc_deg, p.azi_deg));
    CameraPose pose;
    for (int i = 0; i < 3; ++i) {
        pose.eye[i] = static_cast<float>(eye[i]);
        pose.look[i] = static_cast<float>(look[i]);
        pose.up[i] = static_cast<float>(up[i]);
    }
    return pose;
}

}  // namespace caliper3d::scenegraph
