#pragma once

#include <QString>

namespace caliper3d::app {

// True when a window can be shown (an X11 or Wayland display is set).
bool haveDisplay();

// Initialises SoQt on the existing QApplication (Coin included) and installs a
// fatal-error handler that reports and exits instead of opening a modal
// dialog (which would hang an unattended run). Call before creating nodes.
void initGui();

}  // namespace caliper3d::app
