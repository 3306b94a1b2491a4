#pragma once

#include <cstddef>
#include <vector>

namespace caliper3d::reconstruction {

// Rows a segment holds at least when its length is automatic (GeometryOptions::segmentLength_m
// of 0).
inline constexpr int kRowsPerSegment = 100;
// How many leading rows set the automatic segment length: the same rows whether the well is
// read whole or streamed (reconstruction/load/streamed_load.cpp).
inline constexpr std::size_t kSegmentStepRows = 1001;

// The automatic segment length of a log whose rows lie at `depth_m`: 1 m, or the whole metres
// kRowsPerSegment rows span where rows are sparser than 1 cm. A segment's nodes cost the same
// whatever it holds, so a log sampled every 0.1 m gets 10 m segments, not 1 m ones that would
// make a field of such logs mostly nodes (docs/architecture.md). Set by the median step of the
// first kSegmentStepRows rows; 1 m with fewer than 2 rows.
double autoSegmentLength(const std::vector<double>& depth_m);

}  // namespace caliper3d::reconstruction
