#pragma once

#include <optional>
#include <string>
#include <vector>

class SbVec3f;
class SbViewVolume;
class SbViewportRegion;
class SoCamera;
class SoNode;
class SoSeparator;

namespace caliper3d::reconstruction {
class WellGeometry;
}

namespace caliper3d::scenegraph {

// Where a picture is taken from. Scene frame: x east, y up, z south.
//   iso:   from above the south-east, looking down at 35 degrees
//   north: looking north (east on the right)
//   east:  looking east (north on the left)
//   top:   looking straight down, north up
//   map:   as top, but a picture frames the whole wells (wellheads and the paths above the
//          logs too) and names each well beside its wellhead (docs/user-guide.md, "Map")
enum class ViewDirection { Iso, North, East, Top, Map };
std::optional<ViewDirection> parseViewDirection(const std::string& name);

// Turns `camera` to look at `centre` from `view` (position moved one unit
// back along the view; call viewAll afterwards to frame the scene).
void aimCamera(SoCamera* camera, ViewDirection view, const SbVec3f& centre);

// The view volume `camera` draws with in a view of `aspect` (width / height), as Coin maps it
// (SoCamera's ADJUST_CAMERA: a view taller than wide widens the volume by 1 / aspect, keeping
// the camera's angle across). SoCamera::getViewVolume alone leaves that out.
SbViewVolume shownViewVolume(const SoCamera& camera, float aspect);

// `root` in view from the camera's direction: a perspective camera looks at the centre of
// its bounding box from the distance at which every corner of the box is inside the view
// (SoCamera::viewAll fits the box's bounding sphere into the view's narrower side, which
// leaves a long well a quarter of a tall view's height), an orthographic one as
// SoCamera::viewAll puts it; then backed off along the view by `room` (so that the ends of a
// long well are not on the view's edges, nor a vertical well's name half outside).
constexpr float kViewAllRoom = 1.12f;
void frameAll(SoCamera* camera, SoNode* root, const SbViewportRegion& viewport,
              float room = kViewAllRoom);
// Then, when `rightMargin_px` > 0 (a legend drawn over the view's right edge), moved sideways
// and backed off further where needed so that `root`'s box lies left of the margin (of at
// most 60 % of the view's width).
void keepLeftOf(SoCamera* camera, SoNode* root, const SbViewportRegion& viewport,
                float rightMargin_px);
// The same two for a scene given as points (scene frame; a well's path, say): a
// perspective camera is moved across and back until every point lies inside the view with
// `room` to spare, tighter than a box's corners for wells that turn or spread (the corners of
// the box round an L-shaped well or a field seen from the side lie far outside them). Nothing
// when `points` is empty; an orthographic camera is left as it is.
// `pad`: the points stand for spheres of that radius (a well's drawn tube about its path).
void framePoints(SoCamera* camera, const std::vector<SbVec3f>& points,
                 const SbViewportRegion& viewport, float room = kViewAllRoom, float pad = 0.0f);
void keepLeftOf(SoCamera* camera, const std::vector<SbVec3f>& points,
                const SbViewportRegion& viewport, float rightMargin_px, float pad = 0.0f);
// aimCamera at the centre of `root`'s bounding box from `view`, then frameAll; nothing when
// `root` is empty.
void frameFrom(SoCamera* camera, SoNode* root, const SbViewportRegion& viewport,
               ViewDirection view);

// A root ready to render: perspective camera framing `scene` (or `framed`, a part of it,
// when given: what lies outside is drawn where it falls in view) from `view` for the given
// aspect ratio, a light from the camera, then the scene.
SoSeparator* makeRenderRoot(SoNode* scene, ViewDirection view, int width, int height,
                            SoNode* framed = nullptr);
// A viewer's camera seen by a picture of another shape: a copy of `camera` with the picture's
// aspect (a viewer keeps its camera's aspect to its window), its headlight, then the scene.
SoSeparator* makeRenderRoot(SoNode* scene, const SoCamera& camera, int width, int height);

// The scene's background, on screen and in pictures (RGB, 0-1); the fog fades into it.
constexpr float kBackgroundColour[3] = {0.11f, 0.13f, 0.17f};

// A camera inside the hole: at `eye`, looking along `look`, with `up` up
// (scene frame): the fly-through view, wall colours unlit with depth fog.
struct CameraPose {
    float eye[3];
    float look[3];
    float up[3];
    float heightAngle_rad = 0.3f;
    // The background: far walls fade into it.
    float fogColour[3] = {kBackgroundColour[0], kBackgroundColour[1], kBackgroundColour[2]};
    float fogVisibility_m = 25.0f;
};
SoSeparator* makeRenderRoot(SoNode* scene, const CameraPose& pose);

// The fly-through view: a camera on `geometry`'s axis at the row nearest below measured
// depth `md_m`, looking down the hole, high side up.
CameraPose downHolePose(const reconstruction::WellGeometry& geometry, double md_m);

}  // namespace caliper3d::scenegraph
