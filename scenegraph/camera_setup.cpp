#include "scenegraph/camera_setup.h"

#include <algorithm>
#include <cmath>

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
    return std::nullopt;
}

void frameAll(SoCamera* camera, SoNode* root, const SbViewportRegion& viewport, float room) {
    assertMainThread("frameAll");
    camera->viewAll(root, viewport);
    SbVec3f look;
    camera->orientation.getValue().multVec(SbVec3f(0.0f, 0.0f, -1.0f), look);
    const float distance = camera->focalDistance.getValue();
    const SbVec3f focus = camera->position.getValue() + look * distance;
    camera->position = focus - look * (distance * room);
    camera->focalDistance = distance * room;
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

SoSeparator* makeRenderRoot(SoNode* scene, ViewDirection view, int width, int height) {
    assertMainThread("makeRenderRoot");
    const SbViewportRegion viewport(static_cast<short>(width), static_cast<short>(height));
    SoGetBoundingBoxAction bbox(viewport);
    bbox.apply(scene);
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
    SbVec3f right, up;
    camera->orientation.getValue().multVec(SbVec3f(1.0f, 0.0f, 0.0f), right);
    camera->orientation.getValue().multVec(SbVec3f(0.0f, 1.0f, 0.0f), up);
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    const float tanV = std::tan(camera->heightAngle.getValue() / 2.0f);
    const float tanH = tanV * aspect;
    float distance = 0.01f, radius = 0.01f;
    for (int corner = 0; corner < 8; ++corner) {
        const SbVec3f p((corner & 1) ? hi[0] : lo[0], (corner & 2) ? hi[1] : lo[1],
                        (corner & 4) ? hi[2] : lo[2]);
        const SbVec3f d = p - centre;
        const float depth = d.dot(look);  // positive: beyond the centre
        distance = std::max(distance, std::abs(d.dot(up)) / tanV - depth);
        distance = std::max(distance, std::abs(d.dot(right)) / tanH - depth);
        radius = std::max(radius, d.length());
    }
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
