#include "reconstruction/section/section_coverage.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "reconstruction/section/invalid_arm_readings.h"

namespace caliper3d::reconstruction {

int minValidArms(int armCount, double fraction) {
    // The small tolerance keeps 0.5 * 6 at 3, whatever the rounding of fraction.
    const int needed = static_cast<int>(std::ceil(fraction * armCount - 1e-9));
    return std::min(armCount, std::max(2, needed));
}

int countValidArms(const double* radii, int armCount, double lo, double hi) {
    int good = 0;
    for (int k = 0; k < armCount; ++k)
        good += std::isfinite(radii[k]) && radii[k] > lo && radii[k] <= hi;
    return good;
}

std::vector<NoDataInterval> noDataIntervals(const std::vector<unsigned char>& measured,
                                            const std::vector<double>& depth) {
    std::vector<NoDataInterval> out;
    const std::size_t n = measured.size();
    for (std::size_t i = 0; i < n; ++i) {
        if (measured[i]) continue;
        std::size_t j = i;
        while (j + 1 < n && !measured[j + 1]) ++j;
        out.push_back({i, j, depth[i], depth[j]});
        i = j;
    }
    return out;
}

std::string describeNoDataInterval(const NoDataInterval& interval) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "%.2f-%.2f m (%zu section%s)", interval.top_m, interval.bottom_m,
                  interval.sections(), interval.sections() == 1 ? "" : "s");
    return buf;
}

void InvalidArmReadings::add(const io::SectionTable& rows, double fraction, double lo, double hi) {
    const int arms = rows.armCount;
    const int needed = minValidArms(arms, fraction);
    for (std::size_t i = 0; i < rows.rowCount(); ++i) {
        const double* radii = rows.radii(i);
        if (countValidArms(radii, arms, lo, hi) >= needed) continue;
        if (sections++ == 0) firstDepth_m = rows.depth_m[i];
        for (int k = 0; k < arms; ++k) {
            ++readings;
            if (std::isnan(radii[k]))
                ++missing;
            else if (radii[k] <= lo)
                ++tooSmall;
            else if (radii[k] > hi)
                ++beyondReach;
        }
    }
}

std::string describeInvalidArmReadings(const InvalidArmReadings& c, double lo, double hi) {
    char small[64], reach[64];
    if (lo == 0.0)
        std::snprintf(small, sizeof small, "zero or negative");
    else
        std::snprintf(small, sizeof small, "at or below %g mm", lo);
    std::snprintf(reach, sizeof reach, "beyond the tool's reach of %g mm", hi);
    const char* nullText = "null (NaN or the file's NULL value)";
    if (c.readings == 0) return "no arm readings";
    if (c.missing == c.readings) return std::string("every arm reading is ") + nullText;
    if (c.tooSmall == c.readings) return std::string("every arm reading is ") + small;
    if (c.beyondReach == c.readings) return std::string("every arm reading is ") + reach;
    std::string out = "of their " + std::to_string(c.readings) + " arm readings";
    const char* separator = " ";
    auto part = [&](std::size_t n, const std::string& what) {
        if (n == 0) return;
        out += separator + std::to_string(n) + " " + (n == 1 ? "is " : "are ") + what;
        separator = ", ";
    };
    part(c.missing, nullText);
    part(c.tooSmall, small);
    part(c.beyondReach, reach);
    const std::size_t valid = c.readings - c.missing - c.tooSmall - c.beyondReach;
    part(valid, "valid, too few in any one section");
    return out;
}

std::size_t countMeasuredSections(const io::SectionTable& rows, double minValidArmFraction,
                                  double minRadius_mm, double maxRadius_mm) {
    const int arms = rows.armCount;
    const int needed = minValidArms(arms, minValidArmFraction);
    std::size_t measured = 0;
    for (std::size_t i = 0; i < rows.rowCount(); ++i)
        measured += countValidArms(rows.radii(i), arms, minRadius_mm, maxRadius_mm) >= needed;
    return measured;
}

}  // namespace caliper3d::reconstruction
