#include "io/log_reader.h"

#include <cmath>
#include <sstream>

#include "io/parse_error.h"

namespace caliper3d::io {

namespace {

// Accumulates streamed chunks into one table, reserving from the reader's
// estimate so that growth does not double the peak memory.
LoadedLog accumulate(const std::function<LogInfo(const ChunkConsumer&, const StreamOptions&)>& read,
                     const StreamOptions& stream) {
    LoadedLog loaded;
    SectionTable& t = loaded.table;
    bool first = true;
    StreamOptions s = stream;
    s.onStart = [&](const LogInfo& info, std::size_t estimatedRows) {
        t.armCount = info.arms;
        if (stream.onStart) stream.onStart(info, estimatedRows);
        t.reserve(estimatedRows);
    };
    const ChunkConsumer consumer = [&](const SectionTable& chunk) {
        if (first) {
            // The first chunk fixes which optional curves exist; keep the reservation.
            t.armCount = chunk.armCount;
            t.extraCurves = chunk.extraCurves;
            for (ExtraCurve& e : t.extraCurves) {
                e.values.reserve(t.depth_m.capacity());
                e.values.clear();
            }
            first = false;
        }
        t.append(chunk);
    };
    loaded.info = read(consumer, s);
    if (loaded.info.cancelled) throw ReadCancelled(loaded.info.file);
    return loaded;
}

}  // namespace

LoadedLog loadCaliperLog(const std::string& path, const ReadOptions& options, const StreamOptions& stream) {
    LoadedLog loaded = accumulate(
        [&](const ChunkConsumer& consumer, const StreamOptions& s) { return streamCaliperLog(path, options, consumer, s); },
        stream);
    loaded.table.source = path;
    return loaded;
}

LoadedLog loadCaliperText(std::string_view text, const std::string& name, const ReadOptions& options,
                          const StreamOptions& stream) {
    LoadedLog loaded = accumulate(
        [&](const ChunkConsumer& consumer, const StreamOptions& s) {
            return streamCaliperText(text, name, options, consumer, s);
        },
        stream);
    loaded.table.source = name;
    return loaded;
}

SectionTable readCaliperLog(const std::string& path, const ReadOptions& options, Diagnostics* diagnostics) {
    LoadedLog loaded = loadCaliperLog(path, options);
    if (loaded.table.armCount == 0)
        throw ParseError(path, 0, 0,
                         "expected caliper curves (radii R1..Rn, RAD1..n, fingers F01..Fnn, or diameters C1, C2), "
                         "found none among " + std::to_string(loaded.info.curves.size()) +
                             " curves; name them with --radii or --diameters");
    if (diagnostics) {
        for (const Warning& w : loaded.info.diagnostics.warnings) diagnostics->warn(w.file, w.line, w.message);
        diagnostics->warningCount += loaded.info.diagnostics.warningCount - loaded.info.diagnostics.warnings.size();
    }
    return std::move(loaded.table);
}

LogInfo describeLog(const std::string& path, const ReadOptions& options) {
    return streamCaliperLog(path, options, [](const SectionTable&) {});
}

std::string formatLogInfo(const LogInfo& info) {
    std::ostringstream out;
    out << "file:      " << info.file << "\n";
    out << "format:    " << info.format << "\n";
    if (!info.wellName.empty()) out << "well:      " << info.wellName << "\n";
    out << "rows:      " << info.rows << " sections\n";
    out.setf(std::ios::fixed);
    out.precision(4);
    out << "depth:     " << info.top_m << " to " << info.bottom_m << " m, step " << info.step_m << " m";
    if (!info.depthUnit.empty()) out << " (file unit " << info.depthUnit << ")";
    out << "\n";
    out << "arms:      " << info.arms << " from " << info.armSource << "\n";
    out.precision(1);
    if (std::isfinite(info.bitSize_mm) && std::isfinite(info.bitSizeMax_mm) && info.bitSizeMax_mm > info.bitSize_mm)
        out << "bit size:  " << info.bitSize_mm << " to " << info.bitSizeMax_mm << " mm\n";
    else if (std::isfinite(info.bitSize_mm)) out << "bit size:  " << info.bitSize_mm << " mm\n";
    else out << "bit size:  unknown (give --bit-size)\n";
    out << "curves:\n";
    for (const CurveInfo& c : info.curves) {
        out << "  " << c.mnemonic;
        for (std::size_t i = c.mnemonic.size(); i < 12; ++i) out << ' ';
        out << " " << (c.unit.empty() ? "-" : c.unit);
        for (std::size_t i = c.unit.empty() ? 1 : c.unit.size(); i < 8; ++i) out << ' ';
        out << " " << c.role;
        if (c.nulls) out << ", " << c.nulls << " nulls";
        out << "\n";
    }
    out << "warnings:  " << info.diagnostics.warningCount << "\n";
    for (const Warning& w : info.diagnostics.warnings) {
        out << "  " << w.file;
        if (w.line) out << ":" << w.line;
        out << ": " << w.message << "\n";
    }
    if (info.diagnostics.warningCount > info.diagnostics.warnings.size())
        out << "  (" << info.diagnostics.warningCount - info.diagnostics.warnings.size() << " more)\n";
    return out.str();
}

}  // namespace caliper3d::io
