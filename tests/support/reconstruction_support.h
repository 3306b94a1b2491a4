#pragma once

// Conveniences that only the tests use, built on the library's own API: the library keeps one
// way to do each thing (the program's), the tests keep these shorter forms of it.

#include <cstddef>
#include <vector>

#include "reconstruction/analysis/borehole_classifier.h"
#include "reconstruction/analysis/hole_volume.h"
#include "reconstruction/well_geometry.h"

namespace caliper3d::reconstruction {

// Azimuth of arm k in a vertical hole: P1AZ + (k-1)*360/n, in [0, 360).
double armAzimuth_deg(int arm, int armCount, double p1az_deg);

// Classes of a sequence of sections, md ascending: classifyShape on each, then the zone rules
// of breakouts over the sequence (applyBreakoutZoneRules), as analyseWell applies them.
std::vector<BoreholeClass> classifySections(const std::vector<ClassifierInput>& sections,
                                            const ClassificationRules& rules);

// The volumes of a whole log through HoleVolumeAccumulator: md ascending; area_mm2 and bit_mm
// one per section (bit NaN: the section adds nothing to the gauge volumes).
HoleVolume holeVolume(const std::vector<double>& md_m, const std::vector<double>& area_mm2,
                      const std::vector<double>& bit_mm, const VolumeOptions& options);

// WellGeometry::repairRadii of one row as a vector (armCount values, millimetres).
std::vector<double> repairedRadii(const WellGeometry& geometry, std::size_t row);

}  // namespace caliper3d::reconstruction
