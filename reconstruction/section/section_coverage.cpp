#include "reconstruction/section/section_coverage.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

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
