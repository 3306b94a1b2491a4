#include "io/stream/depth_order.h"

#include <algorithm>
#include <cmath>

#include "io/parse_error.h"

namespace caliper3d::io {

DepthOrdering::DepthOrdering(const SectionTable& empty, DepthOrder policy, std::string file,
                             double depthScale, std::size_t chunkRows)
    : m_file(std::move(file)),
      m_policy(policy),
      m_depthScale(depthScale),
      m_chunkRows(chunkRows),
      m_current(empty),
      m_held(empty) {}

void DepthOrdering::holdEverything() {
    m_descending = true;
    m_directionKnown = true;
    m_held.appendRows(m_current, 0, m_current.rowCount());
    m_current.clearRows();
}

void DepthOrdering::add(const SectionTable& t, const std::vector<std::size_t>& lines,
                        const Emit& emit) {
    const std::size_t n = t.rowCount();
    if (!m_directionKnown) decideDirection(t);
    std::size_t runStart = 0;
    m_kept.clear();
    auto flush = [&](std::size_t end) {
        if (end > runStart) m_kept.emplace_back(runStart, end);
        runStart = end + 1;
    };
    for (std::size_t r = 0; r < n; ++r) {
        const double d = t.depth_m[r];
        if (!std::isfinite(d)) {
            if (!m_nullDepths++) m_firstNullDepthLine = lines[r];
            flush(r);
            continue;
        }
        if (m_haveLast && !m_descending) {
            if (d == m_last) {
                if (!m_repeated++) m_firstRepeatedLine = lines[r];
                flush(r);
                continue;
            }
            if (d < m_last) {
                if (!m_directionKnown) {
                    holdEverything();  // recorded upwards: sort at the end
                } else if (m_policy == DepthOrder::Reject) {
                    throw ParseError(m_file, lines[r], 0,
                                     "expected depth increasing past " +
                                         std::to_string(m_last / m_depthScale) + ", found " +
                                         std::to_string(d / m_depthScale));
                } else {
                    if (!m_backwards++) m_firstBackwardsLine = lines[r];
                    flush(r);
                    continue;
                }
            } else {
                m_directionKnown = true;
            }
        }
        m_haveLast = true;
        m_last = d;
    }
    flush(n);
    // The common case, a whole run in order: hand it on without a copy.
    if (m_directionKnown && !m_descending && m_current.rowCount() == 0 && m_kept.size() == 1 &&
        m_kept.front().first == 0 && m_kept.front().second == n && n >= m_chunkRows) {
        emit(t);
        return;
    }
    for (const auto& [a, b] : m_kept) (m_descending ? m_held : m_current).appendRows(t, a, b);
}

// The trend over the rows read so far decides the direction, not the first
// pair of rows: a log recorded upwards that starts with one row out of order
// is sorted whole, not cut down to the rows after that pair. (A thread's
// share of a block holds thousands of rows, so the trend is clear.)
void DepthOrdering::decideDirection(const SectionTable& t) {
    const std::size_t n = t.rowCount();
    std::size_t first = 0;
    while (!m_haveFirst && first < n) {
        if (std::isfinite(t.depth_m[first])) {
            m_first = t.depth_m[first];
            m_haveFirst = true;
        }
        ++first;
    }
    std::size_t last = n;
    while (last > 0 && !std::isfinite(t.depth_m[last - 1])) --last;
    if (!m_haveFirst || last == 0 || t.depth_m[last - 1] == m_first) return;
    m_directionKnown = true;
    if (t.depth_m[last - 1] < m_first) holdEverything();
}

void DepthOrdering::emitReady(const Emit& emit) {
    if (m_descending || !m_directionKnown || m_current.rowCount() < m_chunkRows) return;
    emit(m_current);
    m_current.clearRows();
}

void DepthOrdering::finish(bool deliver, const Emit& emit, const std::function<bool()>& keepGoing,
                           Diagnostics& d) {
    if (deliver && m_descending) {
        std::vector<std::size_t> order(m_held.rowCount());
        for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
        std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
            return m_held.depth_m[a] < m_held.depth_m[b];
        });
        std::size_t outOfOrder = 0;
        for (std::size_t i = 1; i < m_held.rowCount(); ++i)
            outOfOrder += m_held.depth_m[i] > m_held.depth_m[i - 1];
        std::vector<std::size_t> kept;
        kept.reserve(order.size());
        for (std::size_t r : order) {
            if (!kept.empty() && m_held.depth_m[r] == m_held.depth_m[kept.back()]) {
                ++m_repeated;
                continue;
            }
            kept.push_back(r);
        }
        m_held.keepRows(kept);
        d.warn(m_file, 0,
               outOfOrder == 0 ? "log recorded upwards; rows sorted by increasing depth"
                               : "log recorded upwards with " + std::to_string(outOfOrder) +
                                     " rows out of order; rows sorted by increasing depth");
        SectionTable chunk = m_current;  // no rows, the log's curves
        for (std::size_t a = 0; a < m_held.rowCount(); a += m_chunkRows) {
            if (!keepGoing()) break;
            chunk.clearRows();
            chunk.appendRows(m_held, a, std::min(m_held.rowCount(), a + m_chunkRows));
            emit(chunk);
        }
    } else if (deliver && m_current.rowCount() > 0) {
        emit(m_current);
    }
    if (m_nullDepths)
        d.warn(m_file, m_firstNullDepthLine,
               std::to_string(m_nullDepths) + " rows without a depth skipped");
    if (m_repeated)
        d.warn(m_file, m_firstRepeatedLine,
               std::to_string(m_repeated) + " rows repeat the depth of the row before; skipped");
    if (m_backwards)
        d.warn(m_file, m_firstBackwardsLine,
               std::to_string(m_backwards) +
                   " rows go back up the hole in a log recorded downwards; skipped");
}

}  // namespace caliper3d::io
