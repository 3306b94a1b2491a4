#include "app/desktop/gui_session.h"

#include <cstdio>
#include <cstdlib>

#include <Inventor/Qt/SoQt.h>

#include "scenegraph/main_thread.h"

namespace caliper3d::app {

namespace {
// The message by value is SoQt::FatalErrorCB's signature, which setFatalErrorHandler takes.
// NOLINTNEXTLINE(performance-unnecessary-value-param): that signature, not ours to change
void fatalError(const SbString message, SoQt::FatalErrors, void*) {
    std::fprintf(stderr, "caliper3d: OpenGL failure: %s\n", message.getString());
    std::exit(1);
}
}  // namespace

bool haveDisplay() {
    const char* x = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (x && *x) || (wayland && *wayland);
}

void initGui() {
    scenegraph::initCoin();
    SoQt::init("caliper3d");
    SoQt::setFatalErrorHandler(&fatalError, nullptr);
}

}  // namespace caliper3d::app
