#pragma once

#include "scenegraph/picture/picture.h"

class SoCamera;

namespace caliper3d::app {

class WellSession;

// File > Save picture: what `caliper3d render` would draw of the session's visible wells (the
// geometry as shown, their look and legend) seen through `camera` (the viewer's), at `width`
// x `height`: the same request to the same recipe (scenegraph::drawPicture), so the detail is
// chosen for the picture's size, not the viewer's. Main thread only. Throws
// std::runtime_error when no offscreen context can be made.
scenegraph::PictureRequest windowPictureRequest(const WellSession& session, const SoCamera& camera,
                                                int width, int height);
scenegraph::Picture drawWindowPicture(const WellSession& session, const SoCamera& camera, int width,
                                      int height);

}  // namespace caliper3d::app
