#pragma once

#include <string>

#include "io/diagnostics.h"

namespace caliper3d::io {

// The warnings, one a line ("file:line: warning: ..."; no line for one about the whole well),
// and how many more there were than the diagnostics kept: what the console prints and the
// window's warnings list shows.
std::string formatWarnings(const Diagnostics& diagnostics);

}  // namespace caliper3d::io
