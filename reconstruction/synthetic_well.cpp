#include "reconstruction/synthetic_well.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>

#include "reconstruction/arm_geometry.h"

namespace caliper3d::reconstruction {

double ellipseRadius_mm(double dmax_mm, double dmin_mm, double angle_deg) {
    const double a = dmax_mm / 2.0, b = dmin_mm / 2.0;
    const double t = glm::radians(angle_deg);
    const double c = std::cos(t) / a, s = std::sin(t) / b;
    return 1.0 / std::sqrt(c * c + s * s);
}

SyntheticWellSpec syntheticProfile(const std::string& name, double length_m, double step_m) {
    SyntheticWellSpec spec;
    spec.length_m = length_m;
    spec.step_m = step_m;
    if (name == "circle") return spec;
    if (name == "example") {
        // Positions scale with the length so that a short or long well shows every feature.
        const double L = length_m;
        spec.kickoff_m = L / 3.0;
        spec.buildRate_degPer30m = 3.0;
        spec.endOfBuild_m = L * 5.0 / 6.0;
        spec.holeAzimuth_deg = 45.0;
        spec.features.push_back({SyntheticFeature::Kind::Breakout, L * 0.2, L * 0.2667, 245.9, 217.9, 135.0});
        spec.features.push_back({SyntheticFeature::Kind::Washout, L * 0.5, L * 0.5333, 265.9, 265.9, 0.0});
        return spec;
    }
    throw std::invalid_argument("unknown synthetic profile '" + name + "'");
}

std::vector<std::string> syntheticProfileNames() { return {"example", "circle"}; }

double syntheticInclination_deg(const SyntheticWellSpec& spec, double md_m) {
    if (md_m <= spec.kickoff_m) return 0.0;
    const double end = std::min(md_m, spec.endOfBuild_m);
    return (end - spec.kickoff_m) * spec.buildRate_degPer30m / 30.0;
}

io::SectionTable makeSyntheticWell(const SyntheticWellSpec& spec) {
    if (!(spec.step_m > 0.0) || !(spec.length_m > spec.step_m))
        throw std::invalid_argument("synthetic well: need length > step > 0");
    if (spec.armCount < 3 || spec.armCount > 256)
        throw std::invalid_argument("synthetic well: arm count must be 3..256");
    io::SectionTable t;
    t.source = "synthetic";
    t.armCount = spec.armCount;
    const std::size_t rows = static_cast<std::size_t>(std::floor(spec.length_m / spec.step_m)) + 1;
    t.reserve(rows);
    t.bitSize_mm.reserve(rows);
    for (std::size_t i = 0; i < rows; ++i) {
        const double md = static_cast<double>(i) * spec.step_m;
        const double p1az = wrap360(md * spec.toolRotation_degPerM);
        t.depth_m.push_back(md);
        t.p1az_deg.push_back(p1az);
        t.devi_deg.push_back(syntheticInclination_deg(spec, md));
        t.hazi_deg.push_back(spec.holeAzimuth_deg);
        t.bitSize_mm.push_back(spec.bitSize_mm);
        const SyntheticFeature* feature = nullptr;
        for (const auto& f : spec.features)
            if (md >= f.top_m && md <= f.bottom_m) feature = &f;
        for (int k = 1; k <= spec.armCount; ++k) {
            double r = spec.bitSize_mm / 2.0;
            if (feature && feature->kind == SyntheticFeature::Kind::Washout) {
                r = feature->dmax_mm / 2.0;
            } else if (feature) {
                const double shapeAzimuth = armAzimuth_deg(k, spec.armCount, p1az);
                r = ellipseRadius_mm(feature->dmax_mm, feature->dmin_mm,
                                     shapeAzimuth - feature->majorAzimuth_deg);
            }
            t.radius_mm.push_back(r);
        }
    }
    return t;
}

}  // namespace caliper3d::reconstruction
