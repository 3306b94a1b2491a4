#include "scenegraph/coin_messages.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <Inventor/C/base/string.h>
#include <Inventor/C/errors/debugerror.h>
#include <Inventor/errors/SoDebugError.h>

namespace caliper3d::scenegraph {

namespace {

void print(const char* kind, const char* text) {
    std::fprintf(stderr, "caliper3d: graphics %s: %s\n", kind, text);
}

// Coin's C layer (the GL glue among others) posts through this one.
void onCoinCMessage(const cc_debugerror* error, void*) {
    const CC_DEBUGERROR_SEVERITY severity = cc_debugerror_get_severity(error);
    const char* text = cc_string_get_text(cc_error_get_debug_string(&error->super));
    if (severity == CC_DEBUGERROR_ERROR)
        print("error", text);
    else if (debugMessagesWanted())
        print(severity == CC_DEBUGERROR_WARNING ? "warning" : "note", text);
}

// Coin's C++ layer (nodes, actions) posts through this one.
void onCoinMessage(const SoError* error, void*) {
    const auto* debug = static_cast<const SoDebugError*>(error);
    const SoDebugError::Severity severity = debug->getSeverity();
    const char* text = error->getDebugString().getString();
    if (severity == SoDebugError::ERROR)
        print("error", text);
    else if (debugMessagesWanted())
        print(severity == SoDebugError::WARNING ? "warning" : "note", text);
}

}  // namespace

bool debugMessagesWanted() {
    const char* value = std::getenv("CALIPER3D_DEBUG");
    return value && *value && std::strcmp(value, "0") != 0;
}

void routeCoinMessages() {
    cc_debugerror_set_handler_callback(&onCoinCMessage, nullptr);
    SoDebugError::setHandlerCallback(&onCoinMessage, nullptr);
}

}  // namespace caliper3d::scenegraph
