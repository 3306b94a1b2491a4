#include "app/desktop/trace_decimation.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace caliper3d::app {

namespace {

// Collects one run: the current bucket's lowest and highest rows (and the run's first and
// last rows, so the line reaches its gaps), flushed into the run when the bucket changes.
class RunBuilder {
public:
    RunBuilder(const RowCurve& depth_m, const RowCurve& value) : m_depth(depth_m), m_value(value) {}

    void add(std::size_t row, long long bucket) {
        if (m_open && bucket != m_bucket) flushBucket(false);
        if (!m_open) {
            m_open = true;
            m_bucket = bucket;
            m_first = m_low = m_high = row;
        }
        if (m_value[row] < m_value[m_low]) m_low = row;
        if (m_value[row] > m_value[m_high]) m_high = row;
        m_last = row;
    }
    // Ends the run (a row without data, or the end): returns it.
    TraceRun take() {
        if (m_open) flushBucket(true);
        TraceRun run;
        run.swap(m_run);
        return run;
    }

private:
    void flushBucket(bool lastOfRun) {
        std::size_t rows[4] = {m_low, m_high, m_low, m_high};
        if (m_run.empty()) rows[2] = m_first;
        if (lastOfRun) rows[3] = m_last;
        std::sort(std::begin(rows), std::end(rows));
        const std::size_t* end = std::unique(std::begin(rows), std::end(rows));
        for (const std::size_t* r = std::begin(rows); r != end; ++r)
            m_run.push_back({m_depth[*r], m_value[*r]});
        m_open = false;
    }

    const RowCurve& m_depth;
    const RowCurve& m_value;
    TraceRun m_run;
    bool m_open = false;
    long long m_bucket = 0;
    std::size_t m_first = 0, m_last = 0, m_low = 0, m_high = 0;
};

// The first of rows [0, rows) whose depth is not below `limit` (`above` false), or above
// it (true): std::lower_bound and std::upper_bound over a curve read in place.
std::size_t firstRow(const RowCurve& depth_m, std::size_t rows, double limit, bool above) {
    std::size_t low = 0, high = rows;
    while (low < high) {
        const std::size_t mid = low + (high - low) / 2;
        if (above ? !(limit < depth_m[mid]) : depth_m[mid] < limit)
            low = mid + 1;
        else
            high = mid;
    }
    return low;
}

}  // namespace

std::vector<TraceRun> decimateTrace(const RowCurve& depth_m, const RowCurve& value, double top_m,
                                    double bottom_m, int buckets) {
    std::vector<TraceRun> runs;
    const std::size_t rows = std::min(depth_m.size(), value.size());
    if (rows == 0 || !(bottom_m > top_m) || buckets < 1) return runs;
    std::size_t begin = firstRow(depth_m, rows, top_m, false);
    std::size_t end = firstRow(depth_m, rows, bottom_m, true);
    if (begin > 0) --begin;
    if (end < rows) ++end;
    const double bucket_m = (bottom_m - top_m) / buckets;
    RunBuilder builder(depth_m, value);
    for (std::size_t row = begin; row < end; ++row) {
        if (!std::isfinite(value[row])) {
            TraceRun run = builder.take();
            if (!run.empty()) runs.push_back(std::move(run));
            continue;
        }
        builder.add(row, static_cast<long long>(std::floor((depth_m[row] - top_m) / bucket_m)));
    }
    TraceRun run = builder.take();
    if (!run.empty()) runs.push_back(std::move(run));
    return runs;
}

}  // namespace caliper3d::app
