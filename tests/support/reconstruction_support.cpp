#include "support/reconstruction_support.h"

#include "reconstruction/section/arm_geometry.h"

namespace caliper3d::reconstruction {

double armAzimuth_deg(int arm, int armCount, double p1az_deg) {
    return wrap360(p1az_deg + armClockwiseAngle_deg(arm, armCount));
}

std::vector<BoreholeClass> classifySections(const std::vector<ClassifierInput>& sections,
                                            const ClassificationRules& rules) {
    std::vector<BoreholeClass> out(sections.size());
    for (std::size_t i = 0; i < sections.size(); ++i) out[i] = classifyShape(sections[i], rules);
    applyBreakoutZoneRules(
        out, [&](std::size_t i) { return sections[i].md_m; },
        [&](std::size_t i) { return sections[i].toolAzimuth_deg; }, rules);
    return out;
}

HoleVolume holeVolume(const std::vector<double>& md, const std::vector<double>& area,
                      const std::vector<double>& bit, const VolumeOptions& o) {
    HoleVolumeAccumulator volume(o, md.empty() ? 0.0 : md.front(), md.empty() ? 0.0 : md.back());
    for (std::size_t i = 0; i + 1 < md.size(); ++i)  // nothing to add for an empty log
        volume.addStep(md[i], area[i], bit[i], md[i + 1], area[i + 1], bit[i + 1]);
    return volume.result();
}

std::vector<double> repairedRadii(const WellGeometry& geometry, std::size_t row) {
    std::vector<double> out(static_cast<std::size_t>(geometry.table().armCount));
    geometry.repairRadii(row, out.data());
    return out;
}

}  // namespace caliper3d::reconstruction
