#pragma once

#include <cmath>
#include <limits>
#include <string>

namespace caliper3d::io {

// One casing string set in the hole, from the surface down to its shoe (a liner's top is not
// read: docs/analysis.md, "Cased hole"). Read from the LAS ~Parameter section
// (io/casing_program.h) or given with --casing; lengths in metres and millimetres.
struct CasingString {
    double bottom_m = std::numeric_limits<double>::quiet_NaN();       // shoe, measured depth
    double size_mm = std::numeric_limits<double>::quiet_NaN();        // nominal outer diameter
    double weight_kgPerM = std::numeric_limits<double>::quiet_NaN();  // nominal weight, NaN unknown
    // Nominal inner diameter: given, or from size and weight by the API 5CT nominal wall
    // (io::nominalCasingId_mm); NaN when neither tells it.
    double innerDiameter_mm = std::numeric_limits<double>::quiet_NaN();
    std::string type;    // CSGT ("SURFACE", "INTERMEDIATE", ...); empty when not given
    std::string source;  // where it was read: "~Parameter CSGL, CSGS, CSGW", "--casing"
    // The measured depths of the log this string holds over, both included; NaN: the whole
    // log. A log spliced from runs (caliper3d splice) keeps each run's casing over that run's
    // rows only: a string set after a run was logged does not case that run's open hole.
    double appliesFrom_m = std::numeric_limits<double>::quiet_NaN();
    double appliesTo_m = std::numeric_limits<double>::quiet_NaN();
};

inline bool operator==(const CasingString& a, const CasingString& b) {
    auto same = [](double x, double y) { return x == y || (std::isnan(x) && std::isnan(y)); };
    return same(a.bottom_m, b.bottom_m) && same(a.size_mm, b.size_mm) &&
           same(a.weight_kgPerM, b.weight_kgPerM) && same(a.innerDiameter_mm, b.innerDiameter_mm) &&
           a.type == b.type && a.source == b.source && same(a.appliesFrom_m, b.appliesFrom_m) &&
           same(a.appliesTo_m, b.appliesTo_m);
}

}  // namespace caliper3d::io
