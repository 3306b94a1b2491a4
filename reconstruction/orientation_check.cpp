#include "reconstruction/orientation_check.h"

#include <cmath>

#include <glm/trigonometric.hpp>

#include "reconstruction/section_analysis.h"
#include "reconstruction/section_frame.h"

namespace caliper3d::reconstruction {

OrientationOffset padAzimuthOffset(const io::SectionTable& t, double minInclination_deg) {
    OrientationOffset out;
    const std::size_t rows = t.rowCount();
    if (t.p1az_deg.size() != rows || t.hazi_deg.size() != rows || t.rb_deg.size() != rows ||
        t.devi_deg.size() != rows) {
        out.mean_deg = out.sd_deg = std::nan("");
        return out;
    }
    double c = 0.0, s = 0.0;
    for (std::size_t i = 0; i < rows; ++i) {
        const double p1az = t.p1az_deg[i], hazi = t.hazi_deg[i], rb = t.rb_deg[i], inc = t.devi_deg[i];
        if (!std::isfinite(p1az) || !std::isfinite(hazi) || !std::isfinite(rb) || !std::isfinite(inc)) continue;
        if (inc < minInclination_deg) continue;
        const SectionFrame f = frameFromRelativeBearing(inc, hazi, rb);
        const double predicted = inPlaneAzimuth_deg(f, 0.0);
        if (!std::isfinite(predicted)) continue;
        const double d = glm::radians(p1az - predicted);
        c += std::cos(d);
        s += std::sin(d);
        ++out.samples;
    }
    if (out.samples == 0) {
        out.mean_deg = out.sd_deg = std::nan("");
        return out;
    }
    out.mean_deg = glm::degrees(std::atan2(s, c));
    const double r = std::min(1.0, std::hypot(c, s) / static_cast<double>(out.samples));
    out.sd_deg = r > 0.0 ? glm::degrees(std::sqrt(-2.0 * std::log(r))) : 180.0;
    return out;
}

}  // namespace caliper3d::reconstruction
