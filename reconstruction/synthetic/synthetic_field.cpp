#include "reconstruction/synthetic/synthetic_field.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace caliper3d::reconstruction {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kFirstBearing_deg = 45.0;
}  // namespace

SyntheticFieldWell syntheticFieldWell(std::size_t index, std::size_t wells, double length_m,
                                      double step_m) {
    const std::vector<std::string> profiles = syntheticProfileNames();
    SyntheticFieldWell well;
    well.profile = profiles[index % profiles.size()];
    well.spec = syntheticProfile(well.profile, length_m, step_m);
    const double n = static_cast<double>(std::max<std::size_t>(wells, 1));
    // The chord between neighbours is the spacing: 2 R sin(pi / n) (one well: any radius).
    const double radius = wells > 1 ? kSyntheticFieldSpacing_m / (2.0 * std::sin(kPi / n)) : 0.0;
    const double bearing_deg = kFirstBearing_deg + 360.0 * static_cast<double>(index) / n;
    const double first = kFirstBearing_deg * kPi / 180.0, own = bearing_deg * kPi / 180.0;
    well.north_m = radius * (std::cos(own) - std::cos(first));
    well.east_m = radius * (std::sin(own) - std::sin(first));
    well.spec.holeAzimuth_deg = std::fmod(bearing_deg, 360.0);
    well.elevation_m = 25.0 + static_cast<double>(index % 3);
    return well;
}

}  // namespace caliper3d::reconstruction
