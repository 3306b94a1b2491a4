#include "reconstruction/synthetic/synthetic_well.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>

#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "reconstruction/section/arm_geometry.h"
#include "reconstruction/section/section_analysis.h"
#include "reconstruction/section/section_frame.h"

namespace caliper3d::reconstruction {

double ellipseRadius_mm(double dmax_mm, double dmin_mm, double angle_deg) {
    const double a = dmax_mm / 2.0, b = dmin_mm / 2.0;
    const double t = glm::radians(angle_deg);
    const double c = std::cos(t) / a, s = std::sin(t) / b;
    return 1.0 / std::sqrt(c * c + s * s);
}

SyntheticWellSpec syntheticProfile(const std::string& name, double length_m, double step_m) {
    using K = SyntheticFeature::Kind;
    SyntheticWellSpec spec;
    spec.length_m = length_m;
    spec.step_m = step_m;
    const double L = length_m;
    const double bit = spec.bitSize_mm;
    if (name == "circle" || name == "vertical") return spec;
    if (name == "example") {
        // Positions scale with the length so that a short or long well shows every feature.
        spec.kickoff_m = L / 3.0;
        spec.buildRate_degPer30m = 3.0;
        spec.endOfBuild_m = L * 5.0 / 6.0;
        spec.holeAzimuth_deg = 45.0;
        spec.features.push_back({K::Breakout, L * 0.2, L * 0.2667, 245.9, 217.9, 135.0, 0.0});
        spec.features.push_back({K::Washout, L * 0.5, L * 0.5333, 265.9, 265.9, 0.0, 0.0});
        return spec;
    }
    if (name == "ellipse") {
        spec.features.push_back({K::Breakout, 0.0, L, bit + 30.0, bit + 2.0, 60.0, 0.0});
        return spec;
    }
    if (name == "washout") {
        spec.features.push_back({K::Washout, 0.4 * L, 0.6 * L, bit + 40.0, bit + 40.0, 0.0, 0.0});
        return spec;
    }
    if (name == "undergauge") {
        spec.features.push_back(
            {K::Undergauge, 0.4 * L, 0.6 * L, bit - 12.0, bit - 12.0, 0.0, 0.0});
        return spec;
    }
    if (name == "keyseat") {
        spec.kickoff_m = 0.2 * L;
        spec.buildRate_degPer30m = 6.0;
        spec.endOfBuild_m = 1e9;
        spec.holeAzimuth_deg = 120.0;
        spec.features.push_back({K::Keyseat, 0.6 * L, 0.8 * L, bit + 25.0, bit, 0.0, 12.5});
        return spec;
    }
    if (name == "offcentre") {
        spec.toolOffset_mm = 15.0;
        spec.toolOffsetAzimuth_deg = 90.0;
        return spec;
    }
    if (name == "stuck-arm") {
        spec.stuckArm = 3;
        spec.stuckTop_m = 0.4 * L;
        spec.stuckBottom_m = 0.6 * L;
        return spec;
    }
    if (name == "build" || name == "hold") {
        spec.kickoff_m = 0.1 * L;
        spec.buildRate_degPer30m = 3.0;
        spec.endOfBuild_m = name == "hold" ? 0.4 * L : 1e9;
        spec.holeAzimuth_deg = 30.0;
        return spec;
    }
    if (name == "turn") {
        spec.initialInclination_deg = 30.0;
        spec.holeAzimuth_deg = 10.0;
        spec.turnRate_degPer30m = 3.0;
        return spec;
    }
    throw std::invalid_argument("unknown synthetic profile '" + name + "'");
}

std::vector<std::string> syntheticProfileNames() {
    return {"example", "circle",    "vertical",  "ellipse", "washout", "undergauge",
            "keyseat", "offcentre", "stuck-arm", "build",   "hold",    "turn"};
}

double syntheticInclination_deg(const SyntheticWellSpec& spec, double md_m) {
    if (md_m <= spec.kickoff_m) return spec.initialInclination_deg;
    const double end = std::min(md_m, spec.endOfBuild_m);
    const double built =
        spec.initialInclination_deg + (end - spec.kickoff_m) * spec.buildRate_degPer30m / 30.0;
    return std::min(built, std::max(spec.maxInclination_deg, spec.initialInclination_deg));
}

double syntheticAzimuth_deg(const SyntheticWellSpec& spec, double md_m) {
    if (md_m <= spec.turnStart_m) return wrap360(spec.holeAzimuth_deg);
    return wrap360(spec.holeAzimuth_deg +
                   (md_m - spec.turnStart_m) * spec.turnRate_degPer30m / 30.0);
}

namespace {

// Clockwise angle from arm 1, in the frame's plane, of a unit in-plane vector.
double angleInFrame_rad(const SectionFrame& f, const Ned& v) {
    return std::atan2(glm::dot(v, f.side), glm::dot(v, f.arm1));
}

// Distance from the origin along direction phi to an ellipse (semi-axes a, b,
// major axis at theta, centre c), all in the section plane.
double rayToEllipse(double phi, double a, double b, double theta, glm::dvec2 c) {
    const glm::dvec2 d(std::cos(phi), std::sin(phi));
    const glm::dvec2 e1(std::cos(theta), std::sin(theta)), e2(-std::sin(theta), std::cos(theta));
    const double dx = glm::dot(d, e1), dy = glm::dot(d, e2), cx = glm::dot(c, e1),
                 cy = glm::dot(c, e2);
    const double A = dx * dx / (a * a) + dy * dy / (b * b);
    const double B = -2.0 * (dx * cx / (a * a) + dy * cy / (b * b));
    const double C = cx * cx / (a * a) + cy * cy / (b * b) - 1.0;
    return (-B + std::sqrt(std::max(0.0, B * B - 4.0 * A * C))) / (2.0 * A);
}

}  // namespace

double syntheticGammaRay_api(double md_m) {
    // Periods (m) with no common multiple below kilometres, and their amplitudes (gAPI):
    // thick beds carry most of the signal, thin ones make the correlation peak sharp.
    static constexpr double kPeriod_m[] = {0.43, 0.71, 1.17,  1.93, 3.19,
                                           5.27, 8.71, 14.39, 23.8, 49.1};
    static constexpr double kAmplitude[] = {4.0, 5.0, 7.0, 9.0, 11.0, 12.0, 10.0, 9.0, 8.0, 6.0};
    static constexpr double kPhase_rad[] = {0.3, 2.1, 4.0, 1.2, 5.5, 0.8, 3.3, 2.7, 4.9, 1.6};
    double gr = 75.0;
    for (std::size_t k = 0; k < std::size(kPeriod_m); ++k)
        gr += kAmplitude[k] * std::sin(glm::two_pi<double>() * md_m / kPeriod_m[k] + kPhase_rad[k]);
    return gr;
}

io::SectionTable makeSyntheticWell(const SyntheticWellSpec& spec) {
    if (!(spec.step_m > 0.0) || !(spec.length_m > spec.step_m))
        throw std::invalid_argument("synthetic well: need length > step > 0");
    if (spec.armCount < io::kMinArms || spec.armCount > io::kMaxArms)
        throw std::invalid_argument("synthetic well: arm count must be " +
                                    std::to_string(io::kMinArms) + ".." +
                                    std::to_string(io::kMaxArms));
    io::SectionTable t;
    t.source = "synthetic";
    t.armCount = spec.armCount;
    const std::size_t rows = static_cast<std::size_t>(std::floor(spec.length_m / spec.step_m)) + 1;
    t.reserve(rows);
    t.bitSize_mm.reserve(rows);
    t.rb_deg.reserve(rows);
    if (spec.gammaRay) t.extraCurves.push_back({"GR", "GAPI", "Gamma ray (synthetic)", {}});
    for (std::size_t i = 0; i < rows; ++i) {
        // Every shape and angle is that of the true depth; the depth written is the counter's.
        const double written = spec.top_m + static_cast<double>(i) * spec.step_m;
        const double md = written - spec.depthOffset_m;
        const double p1az = wrap360(spec.initialToolAzimuth_deg + md * spec.toolRotation_degPerM);
        const double inc = syntheticInclination_deg(spec, md);
        const double azi = syntheticAzimuth_deg(spec, md);
        const SectionFrame frame = frameFromPadAzimuth(inc, azi, p1az);
        t.depth_m.push_back(written);
        if (spec.gammaRay) t.extraCurves.front().values.push_back(syntheticGammaRay_api(md));
        t.p1az_deg.push_back(p1az);
        t.devi_deg.push_back(inc);
        t.hazi_deg.push_back(azi);
        t.rb_deg.push_back(angleFromHighSide_deg(frame, inc, azi, 0.0));
        t.bitSize_mm.push_back(spec.bitSize_mm);
        const SyntheticFeature* feature = nullptr;
        for (const auto& f : spec.features)
            if (md >= f.top_m && md <= f.bottom_m) feature = &f;

        // The shape in the section plane: semi-axes, major axis angle, centre.
        double a = spec.bitSize_mm / 2.0, b = a, theta = 0.0;
        glm::dvec2 centre(0.0);
        if (spec.toolOffset_mm != 0.0) {
            const double dir = angleInFrame_rad(
                frame, frameFromPadAzimuth(inc, azi, spec.toolOffsetAzimuth_deg).arm1);
            centre += spec.toolOffset_mm * glm::dvec2(std::cos(dir), std::sin(dir));
        }
        if (feature) {
            switch (feature->kind) {
                case SyntheticFeature::Kind::Washout:
                case SyntheticFeature::Kind::Undergauge:
                    a = b = feature->dmax_mm / 2.0;
                    break;
                case SyntheticFeature::Kind::Breakout:
                    a = feature->dmax_mm / 2.0;
                    b = feature->dmin_mm / 2.0;
                    theta = angleInFrame_rad(
                        frame, frameFromPadAzimuth(inc, azi, feature->majorAzimuth_deg).arm1);
                    break;
                case SyntheticFeature::Kind::Keyseat:
                    a = feature->dmax_mm / 2.0;
                    b = feature->dmin_mm / 2.0;
                    theta = angleInFrame_rad(
                        frame, frameFromRelativeBearing(inc, azi, feature->majorAzimuth_deg).arm1);
                    centre += feature->offset_mm * glm::dvec2(std::cos(theta), std::sin(theta));
                    break;
            }
        }
        for (int k = 1; k <= spec.armCount; ++k) {
            const double phi = glm::radians(armClockwiseAngle_deg(k, spec.armCount));
            double r = rayToEllipse(phi, a, b, theta, centre);
            if (k == spec.stuckArm && md >= spec.stuckTop_m && md <= spec.stuckBottom_m)
                r = spec.stuckValue_mm;
            if (md >= spec.closedTop_m && md <= spec.closedBottom_m) r = spec.closedRadius_mm;
            t.radius_mm.push_back(r);
        }
    }
    return t;
}

}  // namespace caliper3d::reconstruction
