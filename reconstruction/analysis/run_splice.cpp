#include "reconstruction/analysis/run_splice.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace caliper3d::reconstruction {

namespace {

double medianStep(const std::vector<double>& depth) {
    if (depth.size() < 2) return 0.0;
    std::vector<double> steps;
    for (std::size_t i = 1; i < depth.size(); ++i) steps.push_back(depth[i] - depth[i - 1]);
    std::nth_element(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2),
                     steps.end());
    return steps[steps.size() / 2];
}

std::string metres(double v) {
    std::ostringstream s;
    s.setf(std::ios::fixed);
    s.precision(3);
    s << v << " m";
    return s.str();
}

// The curves of every run: each optional curve where any run has it, every extra curve by
// mnemonic, and RUN. No casing: placeCasing gives each run's its rows.
io::SectionTable emptyLog(const std::vector<const io::SectionTable*>& runs) {
    const io::SectionTable& first = *runs.front();
    io::SectionTable out = first.rows(0, 0);
    out.extraCurves.clear();
    for (const io::SectionTable* t : runs) {
        for (const io::ExtraCurve& e : t->extraCurves) {
            const bool known =
                std::any_of(out.extraCurves.begin(), out.extraCurves.end(),
                            [&](const io::ExtraCurve& o) { return o.mnemonic == e.mnemonic; });
            if (!known) out.extraCurves.push_back({e.mnemonic, e.unit, e.description, {}});
        }
    }
    out.casing.clear();
    out.extraCurves.push_back({"RUN", "", "Run the row came from (1: the first log given)", {}});
    return out;
}

void pushOptional(const std::vector<double>& from, std::size_t row, bool any,
                  std::vector<double>& to) {
    if (!any) return;
    to.push_back(from.empty() ? io::kNaN : from[row]);
}

// Flags of which optional curves the log carries.
struct Carried {
    bool p1az = false, devi = false, hazi = false, rb = false, bit = false;
};

void appendRow(io::SectionTable& log, const Carried& carried, const io::SectionTable& run,
               std::size_t row, double depth, double runNumber) {
    log.depth_m.push_back(depth);
    const double* r = run.radii(row);
    log.radius_mm.insert(log.radius_mm.end(), r, r + run.armCount);
    pushOptional(run.p1az_deg, row, carried.p1az, log.p1az_deg);
    pushOptional(run.devi_deg, row, carried.devi, log.devi_deg);
    pushOptional(run.hazi_deg, row, carried.hazi, log.hazi_deg);
    pushOptional(run.rb_deg, row, carried.rb, log.rb_deg);
    pushOptional(run.bitSize_mm, row, carried.bit, log.bitSize_mm);
    for (io::ExtraCurve& e : log.extraCurves) {
        if (e.mnemonic == "RUN") {
            e.values.push_back(runNumber);
            continue;
        }
        double v = io::kNaN;
        for (const io::ExtraCurve& from : run.extraCurves)
            if (from.mnemonic == e.mnemonic) v = from.values[row];
        e.values.push_back(v);
    }
}

// This run's depths in the log's: the composition of every join's mapping so far.
struct LogDepth {
    double shift = 0.0, stretch = 0.0;  // log = (d - shift) / (1 + stretch)
    double operator()(double d) const { return (d - shift) / (1.0 + stretch); }
};

// Each run's casing program over the log's rows from that run (from and to the midpoints with
// the neighbouring rows of other runs), its shoes in the log's depths: the casing a run was
// logged in, and only that, cases its rows.
void placeCasing(io::SectionTable& log, const std::vector<const io::SectionTable*>& runs,
                 const std::vector<LogDepth>& toLog) {
    const std::vector<double>& run = log.extraCurves.back().values;  // RUN
    const std::vector<double>& depth = log.depth_m;
    const std::size_t rows = log.rowCount();
    for (std::size_t first = 0; first < rows;) {
        std::size_t last = first;
        while (last + 1 < rows && run[last + 1] == run[first]) ++last;
        const auto k = static_cast<std::size_t>(run[first]) - 1;
        const double from = first == 0 ? depth[first] : 0.5 * (depth[first - 1] + depth[first]);
        const double to = last + 1 == rows ? depth[last] : 0.5 * (depth[last] + depth[last + 1]);
        for (const io::CasingString& c : runs[k]->casing) {
            io::CasingString placed = c;
            placed.bottom_m = toLog[k](c.bottom_m);
            // A run spliced before keeps its own limits within these.
            placed.appliesFrom_m =
                std::isfinite(c.appliesFrom_m) ? std::max(from, toLog[k](c.appliesFrom_m)) : from;
            placed.appliesTo_m =
                std::isfinite(c.appliesTo_m) ? std::min(to, toLog[k](c.appliesTo_m)) : to;
            if (placed.appliesFrom_m <= placed.appliesTo_m) log.casing.push_back(placed);
        }
        first = last + 1;
    }
}

}  // namespace

SplicedLog spliceRuns(const std::vector<const io::SectionTable*>& runs,
                      const std::vector<DepthMapping>& mappings, const SpliceOptions& options) {
    if (runs.size() < 2) throw std::invalid_argument("splice: give at least two runs");
    if (mappings.size() + 1 != runs.size())
        throw std::invalid_argument("splice: one depth mapping per joined run");
    Carried carried;
    for (const io::SectionTable* t : runs) {
        if (t->armCount != runs.front()->armCount)
            throw std::runtime_error(t->source + ": " + std::to_string(t->armCount) +
                                     " arms, where " + runs.front()->source + " has " +
                                     std::to_string(runs.front()->armCount) +
                                     ": splice joins runs of one tool");
        if (t->rowCount() == 0) throw std::runtime_error(t->source + ": no rows");
        carried.p1az |= !t->p1az_deg.empty();
        carried.devi |= !t->devi_deg.empty();
        carried.hazi |= !t->hazi_deg.empty();
        carried.rb |= !t->rb_deg.empty();
        carried.bit |= !t->bitSize_mm.empty();
    }
    SplicedLog out;
    out.table = emptyLog(runs);
    const io::SectionTable& first = *runs.front();
    for (std::size_t i = 0; i < first.rowCount(); ++i)
        appendRow(out.table, carried, first, i, first.depth_m[i], 1.0);
    const double step1 = medianStep(first.depth_m);
    LogDepth toLog;
    std::vector<LogDepth> toLogOf(1);  // each run's, the first's the identity
    for (std::size_t k = 1; k < runs.size(); ++k) {
        const io::SectionTable& run = *runs[k];
        const DepthMapping& m = mappings[k - 1];
        // d_before = m.toRun1(d): compose with the mapping of the run before.
        const double stretch = (1.0 + toLog.stretch) * (1.0 + m.stretch) - 1.0;
        double shift = toLog.shift * (1.0 + m.stretch) + m.shift_m - m.stretch * m.reference_m;
        const double step = medianStep(run.depth_m);
        if (!options.exactShift && stretch == 0.0 && std::abs(step - step1) < 1e-6 * step1 &&
            step1 > 0.0)
            shift = std::round(shift / step1) * step1;
        toLog = {shift, stretch};
        toLogOf.push_back(toLog);

        SpliceJoin join;
        join.run = k;
        join.mapping = m;
        join.appliedShift_m = shift;
        join.stretch = stretch;
        const std::vector<double>& have = out.table.depth_m;
        const double a = toLog(run.depth_m.front()), b = toLog(run.depth_m.back());
        if (a < have.front() - 1e-9)
            throw std::runtime_error(run.source + " starts at " + metres(a) +
                                     " of the log, above the log spliced so far (" +
                                     metres(have.front()) + "): give the runs from the shallowest");
        join.overlapTop_m = a;
        join.overlapBottom_m = std::min(b, have.back());
        if (!(join.overlapBottom_m >= join.overlapTop_m))
            throw std::runtime_error(run.source +
                                     " does not overlap the log before it: it starts at " +
                                     metres(a) + " of the log, which ends at " +
                                     metres(have.back()) + " (give --shift to join it anyway)");
        const bool inset = b < have.back();
        const double asked = k - 1 < options.at_m.size() ? options.at_m[k - 1] : io::kNaN;
        join.at_m = std::isnan(asked)
                        ? (inset ? a : 0.5 * (join.overlapTop_m + join.overlapBottom_m))
                        : asked;
        if (join.at_m < join.overlapTop_m - 1e-9 || join.at_m > join.overlapBottom_m + 1e-9)
            throw std::runtime_error("the join of " + run.source + " at " + metres(join.at_m) +
                                     " lies outside its overlap, " + metres(join.overlapTop_m) +
                                     " to " + metres(join.overlapBottom_m));
        if (inset) join.until_m = b;

        // The log so far above the join, this run from it (to its end, or over an inset only),
        // then for an inset the log so far below it.
        io::SectionTable before = std::move(out.table);
        out.table = emptyLog(runs);
        out.table.extraCurves = before.extraCurves;
        for (io::ExtraCurve& e : out.table.extraCurves) e.values.clear();
        const double tolerance = 1e-6;
        std::size_t i = 0;
        for (; i < before.rowCount() && before.depth_m[i] < join.at_m - tolerance; ++i)
            out.table.appendRows(before, i, i + 1);
        for (std::size_t j = 0; j < run.rowCount(); ++j) {
            const double d = toLog(run.depth_m[j]);
            if (d >= join.at_m - tolerance)
                appendRow(out.table, carried, run, j, d, static_cast<double>(k + 1));
        }
        if (inset)
            for (; i < before.rowCount(); ++i)
                if (before.depth_m[i] > b + tolerance) out.table.appendRows(before, i, i + 1);
        out.joins.push_back(join);
    }
    placeCasing(out.table, runs, toLogOf);
    return out;
}

}  // namespace caliper3d::reconstruction
