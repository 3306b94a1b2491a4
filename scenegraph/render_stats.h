#pragma once

#include <cstddef>

class SoCamera;
class SoNode;

namespace caliper3d::scenegraph {

// The first camera under `root` (nullptr when none).
SoCamera* findCamera(SoNode* root);

// The visibility of the first haze fog under `root` (SoEnvironment), metres; 0 when none.
float fogVisibility(SoNode* root);

// Triangles a render of `root` (camera included) at width x height draws: SoLOD picks its
// child from the camera as when rendering (SoGetPrimitiveCountAction).
std::size_t trianglesDrawn(SoNode* root, int width, int height);

// Nodes a render of `root` at width x height visits: every node of the graph on the way, but
// of each SoLOD only the child it picks from the camera (SoCallbackAction, which switches
// level of detail as rendering does). What a frame costs beside its triangles.
std::size_t nodesTraversed(SoNode* root, int width, int height);

// Peak resident memory of this process, MiB (getrusage).
double peakRss_mb();

}  // namespace caliper3d::scenegraph
