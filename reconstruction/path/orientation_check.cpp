#include "reconstruction/path/orientation_check.h"

#include <algorithm>
#include <cmath>

#include <glm/trigonometric.hpp>

#include "reconstruction/section/section_analysis.h"
#include "reconstruction/section/section_frame.h"

namespace caliper3d::reconstruction {

bool hasPadAzimuthCurves(const io::SectionTable& t) {
    const std::size_t rows = t.rowCount();
    return t.p1az_deg.size() == rows && t.hazi_deg.size() == rows && t.rb_deg.size() == rows &&
           t.devi_deg.size() == rows;
}

PadAzimuthSums padAzimuthSums(const io::SectionTable& t, std::size_t first, std::size_t last,
                              double minInclination_deg) {
    PadAzimuthSums out;
    HoleDirection direction;
    for (std::size_t i = first; i < last; ++i) {
        const double p1az = t.p1az_deg[i], hazi = t.hazi_deg[i], rb = t.rb_deg[i],
                     inc = t.devi_deg[i];
        if (!std::isfinite(p1az) || !std::isfinite(hazi) || !std::isfinite(rb) ||
            !std::isfinite(inc))
            continue;
        if (inc < minInclination_deg) continue;
        direction.update(inc, hazi);
        // The predicted pad-1 direction; its azimuth is that of its horizontal
        // projection, undefined when the projection is too short.
        const Ned arm1 = frameFromRelativeBearing(direction, rb).arm1;
        const double horizontal = std::hypot(arm1.x, arm1.y);
        if (horizontal < 1e-3) continue;
        // cos and sin of P1AZ minus the predicted azimuth atan2(y, x), by the
        // angle-difference identities: no atan2 and no second sin/cos.
        const double p = glm::radians(p1az);
        const double cosP = std::cos(p), sinP = std::sin(p);
        out.cosSum += (cosP * arm1.x + sinP * arm1.y) / horizontal;
        out.sinSum += (sinP * arm1.x - cosP * arm1.y) / horizontal;
        ++out.samples;
    }
    return out;
}

OrientationOffset padAzimuthOffset(const PadAzimuthSums& sums) {
    OrientationOffset out;
    out.samples = sums.samples;
    if (out.samples == 0) {
        out.mean_deg = out.sd_deg = std::nan("");
        return out;
    }
    out.mean_deg = glm::degrees(std::atan2(sums.sinSum, sums.cosSum));
    const double r =
        std::min(1.0, std::hypot(sums.cosSum, sums.sinSum) / static_cast<double>(out.samples));
    out.sd_deg = r > 0.0 ? glm::degrees(std::sqrt(std::max(0.0, -2.0 * std::log(r))))
                         : 180.0;  // r = 1 gives 0, not -0
    return out;
}

OrientationOffset padAzimuthOffset(const io::SectionTable& t, double minInclination_deg) {
    if (!hasPadAzimuthCurves(t)) return padAzimuthOffset(PadAzimuthSums{});
    PadAzimuthSums total;
    const std::size_t rows = t.rowCount();
    for (std::size_t first = 0; first < rows; first += kPadAzimuthBlockRows)
        total.add(padAzimuthSums(t, first, std::min(rows, first + kPadAzimuthBlockRows),
                                 minInclination_deg));
    return padAzimuthOffset(total);
}

}  // namespace caliper3d::reconstruction
