#pragma once

namespace caliper3d::scenegraph {

// Routes Coin's own diagnostics so that a user sees only the product's
// messages: Coin's warnings and notes (its GL glue probing GLX while pictures
// are drawn through EGL prints "Couldn't get current GLX context" on every
// render) are dropped, Coin's errors are printed as "caliper3d: graphics: ...".
// With CALIPER3D_DEBUG set in the environment everything Coin says is printed.
// Called by initCoin(); safe to call again.
void routeCoinMessages();

// True when CALIPER3D_DEBUG is set (to anything but empty or 0).
bool debugMessagesWanted();

}  // namespace caliper3d::scenegraph
