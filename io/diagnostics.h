#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace caliper3d::io {

// A row or field that was skipped or repaired safely while reading.
struct Warning {
    std::string file;
    std::size_t line = 0;
    std::string message;
};

// Warnings collected while reading one file. Readers never print; the command
// or dialog that called them reports the count and the first few messages.
struct Diagnostics {
    static constexpr std::size_t kKeptMessages = 100;

    std::vector<Warning> warnings;  // first kKeptMessages only
    std::size_t warningCount = 0;   // all of them

    void warn(const std::string& file, std::size_t line, std::string message) {
        ++warningCount;
        if (warnings.size() < kKeptMessages) warnings.push_back({file, line, std::move(message)});
    }

    // Adds every warning of `other` (the kept messages while there is room, and
    // the count of all of them).
    void merge(const Diagnostics& other) {
        for (const Warning& w : other.warnings)
            if (warnings.size() < kKeptMessages) warnings.push_back(w);
        warningCount += other.warningCount;
    }
};

}  // namespace caliper3d::io
