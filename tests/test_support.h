#pragma once

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace caliper3d::test {

// Folder of the read-only reference data (../shared/data beside the checkout),
// or the CALIPER3D_SHARED_DATA environment variable when set.
inline std::filesystem::path sharedData() {
    if (const char* env = std::getenv("CALIPER3D_SHARED_DATA")) return env;
    return CALIPER3D_SHARED_DATA;
}

// How far a measurement the analysis stores in single precision (SectionMeasure) may lie from
// the double it was computed as: half a float's spacing at that size, and a little room.
inline double storedInFloat(double expected) {
    return std::abs(expected) * std::numeric_limits<float>::epsilon() + 1e-9;
}

// A scratch folder for files a test writes.
inline std::filesystem::path scratch(const std::string& name) {
    std::filesystem::path dir = std::filesystem::path(CALIPER3D_TEST_TMP);
    std::filesystem::create_directories(dir);
    return dir / name;
}

// An empty scratch folder of its own (what a test left there before is removed).
inline std::filesystem::path freshScratchFolder(const std::string& name) {
    const std::filesystem::path dir = scratch(name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

// Every real caliper log of the reference data, as paths relative to sharedData(): the
// logs in real/ and the other vendors' logs in vendors/ (read since the CMI imager's names
// are known).
inline const std::vector<std::string>& referenceLogs() {
    static const std::vector<std::string> logs = {
        "real/1AA072209208W400_WL_0477502_STAR_FIELD.las",
        "real/1AA063409108W400_FMI_SONIC_MAIN.las",
        "real/multifinger40_data.txt",
        "vendors/WL_0486896_AA-03-08-092-07W4-00_REPEAT_PASS DIPMETER.las",
    };
    return logs;
}

}  // namespace caliper3d::test

// Skips the current test when a reference data file is absent.
#define CALIPER3D_REQUIRE_DATA(path)                                           \
    do {                                                                       \
        if (!std::filesystem::exists(path))                                    \
            GTEST_SKIP() << "reference data not present: " << (path).string(); \
    } while (0)
