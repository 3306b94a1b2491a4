#include "io/stream/row_tally.h"

#include <cmath>

#include "io/median.h"

namespace caliper3d::io {

namespace {
constexpr std::size_t kStepSamples = 65536;
}

void RowTally::add(const SectionTable& chunk, LogInfo& info) {
    if (chunk.rowCount() == 0) return;
    const std::size_t before = info.rows;
    info.rows += chunk.rowCount();
    if (before == 0) info.top_m = chunk.depth_m.front();
    info.bottom_m = chunk.depth_m.back();
    for (double b : chunk.bitSize_mm)
        if (std::isfinite(b)) {
            m_bitSizeMin = std::min(m_bitSizeMin, b);
            m_bitSizeMax = std::max(m_bitSizeMax, b);
        }
    for (std::size_t r = 1; r < chunk.rowCount() && m_steps.size() < kStepSamples; ++r)
        m_steps.push_back(chunk.depth_m[r] - chunk.depth_m[r - 1]);
}

void RowTally::finish(LogInfo& info) {
    if (m_bitSizeMin <= m_bitSizeMax) {
        info.bitSize_mm = m_bitSizeMin;
        info.bitSizeMax_mm = m_bitSizeMax;
    }
    if (!m_steps.empty()) info.step_m = medianInPlace(m_steps);
}

}  // namespace caliper3d::io
