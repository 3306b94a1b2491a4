#include "scenegraph/drawn_only.h"

#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/elements/SoSwitchElement.h>
#include <Inventor/misc/SoState.h>
#include <Inventor/nodes/SoCallback.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoSwitch.h>

#include "scenegraph/main_thread.h"

namespace caliper3d::scenegraph {

namespace {
// An SoSwitch whose whichChild is SO_SWITCH_INHERIT shows what SoSwitchElement says.
void gate(void*, SoAction* action) {
    SoState* state = action->getState();
    if (!state || !state->isElementEnabled(SoSwitchElement::getClassStackIndex())) return;
    SoSwitchElement::set(state, action->isOfType(SoGLRenderAction::getClassTypeId())
                                    ? SO_SWITCH_ALL
                                    : SO_SWITCH_NONE);
}
}  // namespace

SoSeparator* makeDrawnOnly(SoNode* content) {
    assertMainThread("makeDrawnOnly");
    auto* group = new SoSeparator;
    group->setName("drawn_only");
    auto* callback = new SoCallback;
    callback->setCallback(gate, nullptr);
    auto* onlyDrawn = new SoSwitch;
    onlyDrawn->whichChild = SO_SWITCH_INHERIT;
    onlyDrawn->addChild(content);
    group->addChild(callback);
    group->addChild(onlyDrawn);
    return group;
}

}  // namespace caliper3d::scenegraph
