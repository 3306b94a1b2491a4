#pragma once

namespace caliper3d::app {

// Only the product's own messages reach the console: Qt's debug output,
// notes and warnings (platform plug-in chatter, XDG_RUNTIME_DIR, ...) are
// dropped, Qt's critical and fatal messages are printed as "caliper3d: Qt: ...".
// With CALIPER3D_DEBUG set in the environment everything Qt says is printed.
// Coin's own messages are routed the same way by scenegraph::initCoin().
void installMessageFilter();

}  // namespace caliper3d::app
