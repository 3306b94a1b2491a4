#pragma once

#include <QObject>
#include <QTimer>

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

#include <Inventor/SbVec3f.h>
#include <Inventor/SbVec4f.h>

#include "scenegraph/camera_setup.h"

class SoCamera;
class SoCoordinate3;
class SoLineSet;
class SoNode;
class SoQtExaminerViewer;
class SoSeparator;
class SoSwitch;

namespace caliper3d::app {

class DeskModel;

// The 3D camera's side of the current depth: it follows the depth the other views set,
// outlines the current section in the scene, goes inside the hole, flies along the well
// and steps from zone to zone. Coin calls on the main thread only, like every view.
class WellNavigator : public QObject {
    Q_OBJECT

public:
    // Adds its nodes (the marker, the inside-the-hole look) under `viewRoot`; frames
    // `sceneRoot` (the wells, under `viewRoot`) on View all and the view presets.
    WellNavigator(DeskModel& model, SoQtExaminerViewer& viewer, SoSeparator* viewRoot,
                  SoNode* sceneRoot, QObject* parent = nullptr);
    ~WellNavigator() override;
    WellNavigator(const WellNavigator&) = delete;
    WellNavigator& operator=(const WellNavigator&) = delete;

    // A section picked in the 3D view becomes current: the marker moves, the camera stays
    // where the user put it.
    void showPicked(int well, std::size_t row, double azimuth_deg);
    // The whole scene in view (from the wellheads), with room for the labels at its ends;
    // from inside the hole, the camera comes out first.
    void viewAll();
    // The whole scene from a preset direction (from outside the hole).
    void viewFrom(scenegraph::ViewDirection direction);
    // The logs of the wells `wells` gives (each a well's scene, without the path above its
    // log) in view, as `caliper3d render` frames them: what a window opens on.
    void frameLogs(std::function<std::vector<SoNode*>()> wells);
    // What the framings above keep clear at the view's right edge (the colour legend),
    // pixels. A legend that arrives (or changes width) after a framing the user has not
    // moved the camera from since frames the scene again beside it.
    void setRightMargin(float px);
    // Looks at the current depth: from inside the hole down it, or from outside, from the
    // side the camera looks from now, close enough to see the section.
    void follow();
    // Inside the hole (looking down it from the current depth, lit by the wall's own colours
    // and fog) or outside (the viewer's usual light).
    void setInside(bool inside);
    bool inside() const { return m_inside; }
    // Moves the current depth down the well at `speed_m_s`, the camera inside, until the
    // end of the log or stopFlight().
    void startFlight(double speed_m_s);
    void stopFlight();
    bool flying() const { return m_flight.isActive(); }
    // The current depth to the top of the next (previous) zone of the current well's
    // analysis; false when there is none that way (or no analysis yet).
    bool nextZone();
    bool previousZone();
    // What the camera looks at (scene frame): the point at its focal distance.
    SbVec3f focus() const;
    // The outline of the current section (for tests): its points, scene frame.
    int markerPoints() const;

signals:
    void flightStopped();
    void insideChanged(bool inside);

private:
    void onCurrentChanged();
    void updateMarker();
    void flightStep();
    void leaveInside();  // outside, the camera left where it is
    // `frame` done now, and remembered with where it left the camera (setRightMargin).
    void frameAndRemember(std::function<void()> frame);
    struct CameraPose {
        SbVec3f position;
        SbVec4f orientation;
        float focalDistance = 0.0f;
        float height = 0.0f;  // height angle, or an orthographic camera's height
        bool operator==(const CameraPose& o) const {
            return position == o.position && orientation == o.orientation &&
                   focalDistance == o.focalDistance && height == o.height;
        }
    };
    std::optional<CameraPose> pose() const;
    // Points along the logged part of every well shown (scene frame): what frameLogs fits.
    std::vector<SbVec3f> loggedPaths() const;
    // The largest radius drawn (exaggerated) among the wells shown, metres: the tube's room
    // about its path.
    float drawnRadius_m() const;

    DeskModel& m_model;
    SoQtExaminerViewer& m_viewer;
    SoSeparator* m_viewRoot = nullptr;
    SoNode* m_sceneRoot = nullptr;
    SoSwitch* m_insideLook = nullptr;  // BASE_COLOR light model and fog, on inside the hole
    SoSeparator* m_marker = nullptr;
    SoCoordinate3* m_markerPoints = nullptr;
    SoLineSet* m_markerLine = nullptr;
    bool m_inside = false;
    float m_rightMargin_px = 0.0f;
    std::function<void()> m_lastFraming;     // the last framing, to redo beside a legend
    std::optional<CameraPose> m_framedPose;  // where it left the camera
    bool m_picking = false;                  // within showPicked: the camera stays
    QTimer m_flight;
    double m_speed_m_s = 5.0;
    static constexpr int kFlightTick_ms = 40;
};

}  // namespace caliper3d::app
