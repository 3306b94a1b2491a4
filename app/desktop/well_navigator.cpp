#include "app/desktop/well_navigator.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include <Inventor/Qt/viewers/SoQtExaminerViewer.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/nodes/SoBaseColor.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoDrawStyle.h>
#include <Inventor/nodes/SoEnvironment.h>
#include <Inventor/nodes/SoLightModel.h>
#include <Inventor/nodes/SoLineSet.h>
#include <Inventor/nodes/SoOrthographicCamera.h>
#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoPickStyle.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoSwitch.h>

#include "app/desktop/desk_model.h"
#include "reconstruction/mesh/lod_levels.h"
#include "reconstruction/well_geometry.h"
#include "scenegraph/camera_setup.h"

namespace caliper3d::app {

namespace {

// Outside, the camera comes this many drawn hole diameters from the current section (a few
// metres of hole in view, its shape plain), and no nearer than the minimum.
constexpr float kFollowDistance_m = 2.0f;
constexpr float kFollowDiameters = 12.0f;
constexpr float kMarkerColour[3] = {1.0f, 0.85f, 0.1f};  // a yellow no colour map uses

}  // namespace

WellNavigator::WellNavigator(DeskModel& model, SoQtExaminerViewer& viewer, SoSeparator* viewRoot,
                             SoNode* sceneRoot, QObject* parent)
    : QObject(parent),
      m_model(model),
      m_viewer(viewer),
      m_viewRoot(viewRoot),
      m_sceneRoot(sceneRoot) {
    m_viewRoot->ref();
    m_insideLook = new SoSwitch;
    m_insideLook->whichChild = SO_SWITCH_NONE;
    // Inside the hole every wall is seen at a grazing angle (render's own inside view does
    // the same): the wall's colours unlit, and fog in the background colour for depth.
    auto* lightModel = new SoLightModel;
    lightModel->model = SoLightModel::BASE_COLOR;
    auto* fog = new SoEnvironment;
    fog->fogType = SoEnvironment::HAZE;
    fog->fogColor.setValue(scenegraph::kBackgroundColour);
    fog->fogVisibility = 25.0f;
    m_insideLook->addChild(lightModel);
    m_insideLook->addChild(fog);
    m_viewRoot->insertChild(m_insideLook, 0);

    m_marker = new SoSeparator;
    auto* style = new SoDrawStyle;
    style->lineWidth = 3.0f;
    auto* colour = new SoBaseColor;
    colour->rgb.setValue(kMarkerColour);
    auto* unlit = new SoLightModel;
    unlit->model = SoLightModel::BASE_COLOR;
    auto* unpickable = new SoPickStyle;  // a pick goes through the outline to the wall
    unpickable->style = SoPickStyle::UNPICKABLE;
    m_markerPoints = new SoCoordinate3;
    m_markerLine = new SoLineSet;
    m_markerLine->numVertices.setNum(0);
    m_marker->addChild(unpickable);
    m_marker->addChild(unlit);
    m_marker->addChild(style);
    m_marker->addChild(colour);
    m_marker->addChild(m_markerPoints);
    m_marker->addChild(m_markerLine);
    m_viewRoot->addChild(m_marker);

    connect(&m_model, &DeskModel::currentChanged, this, &WellNavigator::onCurrentChanged);
    connect(&m_model, &DeskModel::wellChanged, this, [this](int well) {
        if (well == m_model.currentWell()) updateMarker();  // restyled: the ring moved
    });
    connect(&m_model, &DeskModel::wellsChanged, this, &WellNavigator::updateMarker);
    m_flight.setInterval(kFlightTick_ms);
    connect(&m_flight, &QTimer::timeout, this, &WellNavigator::flightStep);
}

WellNavigator::~WellNavigator() {
    m_viewRoot->removeChild(m_marker);
    m_viewRoot->removeChild(m_insideLook);
    m_viewRoot->unref();
}

void WellNavigator::onCurrentChanged() {
    updateMarker();
    if (!m_picking) follow();
}

void WellNavigator::showPicked(int well, std::size_t row, double azimuth_deg) {
    m_picking = true;  // the model's currentChanged arrives within the call below
    m_model.setCurrentRow(well, row);
    m_picking = false;
    m_model.setCurrentAzimuth(azimuth_deg);
}

void WellNavigator::viewAll() {
    if (!m_viewer.getCamera()) return;
    leaveInside();
    frameAndRemember([this] {
        SoCamera* camera = m_viewer.getCamera();
        scenegraph::frameAll(camera, m_sceneRoot, m_viewer.getViewportRegion());
        scenegraph::keepLeftOf(camera, m_sceneRoot, m_viewer.getViewportRegion(), m_rightMargin_px);
    });
}

void WellNavigator::viewFrom(scenegraph::ViewDirection direction) {
    if (!m_viewer.getCamera()) return;
    leaveInside();
    frameAndRemember([this, direction] {
        SoCamera* camera = m_viewer.getCamera();
        scenegraph::frameFrom(camera, m_sceneRoot, m_viewer.getViewportRegion(), direction);
        scenegraph::keepLeftOf(camera, m_sceneRoot, m_viewer.getViewportRegion(), m_rightMargin_px);
    });
}

void WellNavigator::frameLogs(std::function<std::vector<SoNode*>()> wells) {
    if (!m_viewer.getCamera() || m_inside) return;
    frameAndRemember([this, wells = std::move(wells)] {
        const std::vector<SoNode*> scenes = wells();
        if (scenes.empty()) return;
        SoCamera* camera = m_viewer.getCamera();
        // The logged paths of the wells shown, where the model has them: tighter than the
        // scenes' box for wells that turn or spread.
        const std::vector<SbVec3f> paths = loggedPaths();
        if (!paths.empty() && camera->isOfType(SoPerspectiveCamera::getClassTypeId())) {
            const float pad = drawnRadius_m();
            scenegraph::framePoints(camera, paths, m_viewer.getViewportRegion(),
                                    scenegraph::kViewAllRoom, pad);
            scenegraph::keepLeftOf(camera, paths, m_viewer.getViewportRegion(), m_rightMargin_px,
                                   pad);
            return;
        }
        auto* logs = new SoSeparator;
        logs->ref();
        for (SoNode* well : scenes) logs->addChild(well);
        SoGetBoundingBoxAction box(m_viewer.getViewportRegion());
        box.apply(logs);
        if (!box.getBoundingBox().isEmpty()) {
            scenegraph::frameAll(camera, logs, m_viewer.getViewportRegion());
            scenegraph::keepLeftOf(camera, logs, m_viewer.getViewportRegion(), m_rightMargin_px);
        }
        logs->unref();
    });
}

std::vector<SbVec3f> WellNavigator::loggedPaths() const {
    std::vector<SbVec3f> points;
    for (int i = 0; i < m_model.wellCount(); ++i) {
        const DeskWell& well = m_model.well(i);
        if (!well.visible || !well.geometry || well.geometry->table().rowCount() == 0) continue;
        const auto& depth = well.geometry->table().depth_m;
        // About 500 points a well: the framing is to a pixel or so of a long well's drawn tube.
        const double spacing = std::max(1.0, (depth.back() - depth.front()) / 500.0);
        for (const glm::vec3& p : reconstruction::pathLine(*well.geometry, spacing))
            points.emplace_back(p.x, p.y, p.z);
    }
    return points;
}

float WellNavigator::drawnRadius_m() const {
    double most = 0.0;
    for (int i = 0; i < m_model.wellCount(); ++i) {
        const DeskWell& well = m_model.well(i);
        if (!well.visible || !well.geometry) continue;
        const io::SectionTable& table = well.geometry->table();
        double radius = 0.0;
        for (const double r : table.radius_mm)
            if (std::isfinite(r)) radius = std::max(radius, r);
        most = std::max(most, radius / 1000.0 * well.geometry->options().radialExaggeration);
    }
    return static_cast<float>(most);
}

void WellNavigator::frameAndRemember(std::function<void()> frame) {
    frame();
    m_lastFraming = std::move(frame);
    m_framedPose = pose();
}

std::optional<WellNavigator::CameraPose> WellNavigator::pose() const {
    const SoCamera* camera = m_viewer.getCamera();
    if (!camera) return std::nullopt;
    CameraPose p;
    p.position = camera->position.getValue();
    p.orientation = camera->orientation.getValue().getValue();
    p.focalDistance = camera->focalDistance.getValue();
    if (const auto* perspective = dynamic_cast<const SoPerspectiveCamera*>(camera))
        p.height = perspective->heightAngle.getValue();
    else if (const auto* ortho = dynamic_cast<const SoOrthographicCamera*>(camera))
        p.height = ortho->height.getValue();
    return p;
}

void WellNavigator::setRightMargin(float px) {
    if (px == m_rightMargin_px) return;
    m_rightMargin_px = px;
    // Framed beside the old margin and not moved since: framed again beside the new one.
    if (m_lastFraming && !m_inside && m_framedPose && pose() == m_framedPose)
        frameAndRemember(m_lastFraming);
}

void WellNavigator::leaveInside() {
    if (!m_inside) return;
    m_inside = false;
    m_insideLook->whichChild = SO_SWITCH_NONE;
    stopFlight();
    emit insideChanged(false);
}

void WellNavigator::updateMarker() {
    const DeskWell* well = m_model.current();
    std::vector<glm::vec3> ring;
    if (well && well->geometry)
        ring = reconstruction::sectionRing(*well->geometry, m_model.currentRow());
    m_markerPoints->point.setNum(static_cast<int>(ring.empty() ? 0 : ring.size() + 1));
    SbVec3f* points = m_markerPoints->point.startEditing();
    for (std::size_t i = 0; i < ring.size(); ++i)
        points[i].setValue(ring[i].x, ring[i].y, ring[i].z);
    if (!ring.empty()) points[ring.size()] = points[0];  // closed
    m_markerPoints->point.finishEditing();
    if (ring.empty())
        m_markerLine->numVertices.setNum(0);
    else
        m_markerLine->numVertices.setValue(static_cast<int>(ring.size() + 1));
}

int WellNavigator::markerPoints() const {
    return m_markerPoints->point.getNum();
}

SbVec3f WellNavigator::focus() const {
    const SoCamera* camera = m_viewer.getCamera();
    if (!camera) return SbVec3f(0.0f, 0.0f, 0.0f);
    SbVec3f look;
    camera->orientation.getValue().multVec(SbVec3f(0.0f, 0.0f, -1.0f), look);
    return camera->position.getValue() + look * camera->focalDistance.getValue();
}

void WellNavigator::follow() {
    const DeskWell* well = m_model.current();
    SoCamera* camera = m_viewer.getCamera();
    if (!well || !well->geometry || !camera) return;
    const reconstruction::WellGeometry& g = *well->geometry;
    const std::size_t row = m_model.currentRow();
    if (m_inside) {
        const scenegraph::CameraPose pose = scenegraph::downHolePose(g, m_model.currentDepth_m());
        const SbVec3f eye(pose.eye), look(pose.look);
        camera->position = eye;
        camera->pointAt(eye + look, SbVec3f(pose.up));
        camera->focalDistance = 5.0f;
        return;
    }
    const glm::dvec3 centre = reconstruction::toScene(g.centre(row));
    float drawnDiameter_m = 0.0f;
    for (const glm::vec3& p : reconstruction::sectionRing(g, row))
        drawnDiameter_m = std::max(drawnDiameter_m,
                                   2.0f * static_cast<float>(glm::length(glm::dvec3(p) - centre)));
    const float distance =
        std::min(camera->focalDistance.getValue(),
                 std::max(kFollowDistance_m, kFollowDiameters * drawnDiameter_m));
    SbVec3f look;
    camera->orientation.getValue().multVec(SbVec3f(0.0f, 0.0f, -1.0f), look);
    const SbVec3f target(static_cast<float>(centre.x), static_cast<float>(centre.y),
                         static_cast<float>(centre.z));
    camera->position = target - look * distance;
    camera->focalDistance = distance;
}

void WellNavigator::setInside(bool inside) {
    if (m_inside == inside) return;
    m_inside = inside;
    m_insideLook->whichChild = inside ? SO_SWITCH_ALL : SO_SWITCH_NONE;
    if (!inside) stopFlight();
    emit insideChanged(inside);
    follow();
}

void WellNavigator::startFlight(double speed_m_s) {
    m_speed_m_s = speed_m_s;
    setInside(true);
    m_flight.start();
}

void WellNavigator::stopFlight() {
    if (!m_flight.isActive()) return;
    m_flight.stop();
    emit flightStopped();
}

void WellNavigator::flightStep() {
    const DeskWell* well = m_model.current();
    if (!well || !well->geometry) {
        stopFlight();
        return;
    }
    const double bottom = well->geometry->table().depth_m.back();
    const double next = m_model.currentDepth_m() + m_speed_m_s * kFlightTick_ms / 1000.0;
    m_model.setCurrentDepth(std::min(next, bottom));
    if (next >= bottom) stopFlight();
}

bool WellNavigator::nextZone() {
    const DeskWell* well = m_model.current();
    if (!well || !well->analysis) return false;
    for (const reconstruction::Zone& zone : well->analysis->zones)
        if (zone.firstSection > m_model.currentRow()) {
            m_model.setCurrentRow(m_model.currentWell(), zone.firstSection);
            return true;
        }
    return false;
}

bool WellNavigator::previousZone() {
    const DeskWell* well = m_model.current();
    if (!well || !well->analysis) return false;
    const auto& zones = well->analysis->zones;
    for (auto zone = zones.rbegin(); zone != zones.rend(); ++zone)
        if (zone->firstSection < m_model.currentRow()) {
            m_model.setCurrentRow(m_model.currentWell(), zone->firstSection);
            return true;
        }
    return false;
}

}  // namespace caliper3d::app
