#include "io/warnings_text.h"

#include <cstdio>

namespace caliper3d::io {

std::string formatWarnings(const Diagnostics& diagnostics) {
    std::string out;
    for (const Warning& w : diagnostics.warnings) {
        out += w.file;
        if (w.line > 0) out += ":" + std::to_string(w.line);  // none: about the whole well
        out += ": warning: " + w.message + "\n";
    }
    if (diagnostics.warningCount > diagnostics.warnings.size()) {
        char count[96];
        std::snprintf(count, sizeof count, "... and %zu more warnings\n",
                      diagnostics.warningCount - diagnostics.warnings.size());
        out += count;
    }
    return out;
}

}  // namespace caliper3d::io
