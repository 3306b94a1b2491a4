#pragma once

#include <cstddef>
#include <vector>

#include "io/log_info.h"
#include "io/section_table.h"

namespace caliper3d::io {

// What a reader learns from the rows it hands on, whatever the format: their count and
// depth range, the bit sizes met and the median step (from the first rows).
class RowTally {
public:
    // Counts a chunk about to be delivered (rows in depth order).
    void add(const SectionTable& chunk, LogInfo& info);
    // Writes the bit-size range and the median step into `info`.
    void finish(LogInfo& info);

private:
    std::vector<double> m_steps;
    double m_bitSizeMin = 1e300, m_bitSizeMax = -1e300;
};

}  // namespace caliper3d::io
