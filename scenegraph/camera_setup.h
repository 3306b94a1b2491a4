#pragma once

#include <optional>
#include <string>

class SbVec3f;
class SoCamera;
class SoNode;
class SoSeparator;

namespace caliper3d::scenegraph {

// Where a picture is taken from. Scene frame: x east, y up, z south.
//   iso:   from above the south-east, looking down at 35 degrees
//   north: looking north (east on the right)
//   east:  looking east (north on the left)
//   top:   looking straight down, north up
enum class ViewDirection { Iso, North, East, Top };
std::optional<ViewDirection> parseViewDirection(const std::string& name);

// Turns `camera` to look at `centre` from `view` (position moved one unit
// back along the view; call viewAll afterwards to frame the scene).
void aimCamera(SoCamera* camera, ViewDirection view, const SbVec3f& centre);

// A root ready to render: perspective camera framing `scene` from `view`
// for the given aspect ratio, a light from the camera, then the scene.
SoSeparator* makeRenderRoot(SoNode* scene, ViewDirection view, int width, int height);

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

}  // namespace caliper3d::scenegraph
