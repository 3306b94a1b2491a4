#pragma once

class SoNode;
class SoSeparator;

namespace caliper3d::scenegraph {

// A separator whose content is drawn (SoGLRenderAction) and nothing else: it takes no part
// in bounding boxes (so it never moves the framing of a picture or the viewer's View all;
// SoText2's box depends on the camera), picking, searches or SoCallbackAction traversals
// (mesh exports). For labels and overlays, which annotate the scene but are not of it.
//   SoSeparator { SoCallback (sets SoSwitchElement), SoSwitch (whichChild INHERIT) { content } }
SoSeparator* makeDrawnOnly(SoNode* content);

}  // namespace caliper3d::scenegraph
