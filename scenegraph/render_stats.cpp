#include "scenegraph/render_stats.h"

#include <sys/resource.h>

#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoCallbackAction.h>
#include <Inventor/actions/SoGetPrimitiveCountAction.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoEnvironment.h>

#include "scenegraph/main_thread.h"

namespace caliper3d::scenegraph {

namespace {
// The first node of `type` in a depth-first walk from `root`, or null.
SoNode* findFirst(SoNode* root, SoType type) {
    SoSearchAction search;
    search.setType(type);
    search.setInterest(SoSearchAction::FIRST);
    search.apply(root);
    SoPath* path = search.getPath();
    return path ? path->getTail() : nullptr;
}
}  // namespace

SoCamera* findCamera(SoNode* root) {
    assertMainThread("findCamera");
    return static_cast<SoCamera*>(findFirst(root, SoCamera::getClassTypeId()));
}

float fogVisibility(SoNode* root) {
    assertMainThread("fogVisibility");
    const auto* environment =
        static_cast<SoEnvironment*>(findFirst(root, SoEnvironment::getClassTypeId()));
    if (!environment) return 0.0f;
    return environment->fogType.getValue() == SoEnvironment::NONE
               ? 0.0f
               : environment->fogVisibility.getValue();
}

std::size_t trianglesDrawn(SoNode* root, int width, int height) {
    assertMainThread("trianglesDrawn");
    SoGetPrimitiveCountAction count(
        SbViewportRegion(static_cast<short>(width), static_cast<short>(height)));
    count.apply(root);
    return static_cast<std::size_t>(count.getTriangleCount());
}

std::size_t nodesTraversed(SoNode* root, int width, int height) {
    assertMainThread("nodesTraversed");
    SoCallbackAction action(
        SbViewportRegion(static_cast<short>(width), static_cast<short>(height)));
    std::size_t nodes = 0;
    action.addPreCallback(
        SoNode::getClassTypeId(),
        [](void* count, SoCallbackAction*, const SoNode*) {
            ++*static_cast<std::size_t*>(count);
            return SoCallbackAction::CONTINUE;
        },
        &nodes);
    action.apply(root);
    return nodes;
}

double peakRss_mb() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

}  // namespace caliper3d::scenegraph
