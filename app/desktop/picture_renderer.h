#pragma once

#include <QImage>
#include <QSize>

#include "reconstruction/mesh/wall_colouring.h"

class SoCamera;
class SoNode;

namespace caliper3d::app {

// File > Save picture: the window's 3D view drawn offscreen at any size (the render verb's
// renderer: scenegraph::OffscreenRenderer), seen through a copy of the viewer's camera with a
// headlight as the viewer has, the legend drawn over it as `caliper3d render` draws it. Main
// thread only (Coin). Throws std::runtime_error when no offscreen context can be made.
QImage renderPicture(SoNode* viewRoot, const SoCamera& camera,
                     const reconstruction::ColourLegend* legend, QSize size);

}  // namespace caliper3d::app
