#include "io/log_reader.h"

#include <sys/mman.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>

#include "io/casing_program.h"
#include "io/hole_azimuth_plan.h"
#include "io/median.h"
#include "io/parse_error.h"
#include "io/survey_reader.h"
#include "io/text_encoding.h"

namespace caliper3d::io {

namespace {

// The table is filled once, front to back, right after it is reserved: where
// Linux gives transparent huge pages on request, take them, so that filling
// 100+ MiB takes 512 times fewer page faults (about a tenth of the reading
// time of the 4 km well, docs/benchmarks.md, "Reading logs"). Harmless where declined.
void reserveFilledOnce(std::vector<double>& v, std::size_t n) {
    v.reserve(n);
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    // The whole huge pages inside the buffer: its start moved up to the next page boundary
    // (a pointer moved, not an integer made a pointer).
    constexpr std::uintptr_t kHugePage = 2u << 20;
    char* const begin = reinterpret_cast<char*>(v.data());
    const std::uintptr_t address = reinterpret_cast<std::uintptr_t>(begin);
    const std::size_t bytes = v.capacity() * sizeof(double);
    const std::size_t skip =
        static_cast<std::size_t>((kHugePage - (address & (kHugePage - 1))) & (kHugePage - 1));
    if (v.empty() && bytes > skip) {
        const std::size_t length = (bytes - skip) & ~static_cast<std::size_t>(kHugePage - 1);
        if (length > 0) ::madvise(begin + skip, length, MADV_HUGEPAGE);
    }
#endif
}

// Accumulates streamed chunks into one table, reserving from the reader's
// estimate so that growth does not double the peak memory.
LoadedLog accumulate(const std::function<LogInfo(const ChunkConsumer&, const StreamOptions&)>& read,
                     const StreamOptions& stream) {
    LoadedLog loaded;
    SectionTable& t = loaded.table;
    std::size_t estimate = 0;
    bool first = true;
    StreamOptions s = stream;
    s.onStart = [&](const LogInfo& info, std::size_t estimatedRows) {
        if (stream.onStart) stream.onStart(info, estimatedRows);
        estimate = estimatedRows;
    };
    const ChunkConsumer consumer = [&](const SectionTable& chunk) {
        if (first) {
            // The first chunk shows which optional curves exist: reserve those only.
            first = false;
            t.armCount = chunk.armCount;
            const std::size_t rows = std::max(estimate, chunk.rowCount());
            reserveFilledOnce(t.depth_m, rows);
            reserveFilledOnce(t.radius_mm, rows * static_cast<std::size_t>(chunk.armCount));
            std::vector<double> SectionTable::*const optional[] = {
                &SectionTable::p1az_deg, &SectionTable::devi_deg, &SectionTable::hazi_deg,
                &SectionTable::rb_deg, &SectionTable::bitSize_mm};
            for (auto curve : optional)
                if (!(chunk.*curve).empty()) reserveFilledOnce(t.*curve, rows);
            for (const ExtraCurve& e : chunk.extraCurves) {
                t.extraCurves.push_back({e.mnemonic, e.unit, e.description, {}});
                reserveFilledOnce(t.extraCurves.back().values, rows);
            }
        }
        t.append(chunk);
        if (stream.onChunk) stream.onChunk(chunk);
    };
    loaded.info = read(consumer, s);
    if (loaded.info.cancelled) throw ReadCancelled(loaded.info.file);
    return loaded;
}

}  // namespace

LoadedLog loadCaliperLog(const std::string& path, const ReadOptions& options,
                         const StreamOptions& stream) {
    LoadedLog loaded = accumulate(
        [&](const ChunkConsumer& consumer, const StreamOptions& s) {
            return streamCaliperLog(path, options, consumer, s);
        },
        stream);
    loaded.table.source = path;
    loaded.table.wellName = loaded.info.wellName;
    loaded.table.casing = options.casing.empty() ? loaded.info.casing : options.casing;
    return loaded;
}

LoadedLog loadCaliperText(std::string_view text, const std::string& name,
                          const ReadOptions& options, const StreamOptions& stream) {
    LoadedLog loaded = accumulate(
        [&](const ChunkConsumer& consumer, const StreamOptions& s) {
            return streamCaliperText(text, name, options, consumer, s);
        },
        stream);
    loaded.table.source = name;
    loaded.table.wellName = loaded.info.wellName;
    loaded.table.casing = options.casing.empty() ? loaded.info.casing : options.casing;
    return loaded;
}

SectionTable readCaliperLog(const std::string& path, const ReadOptions& options,
                            Diagnostics* diagnostics) {
    LoadedLog loaded = loadCaliperLog(path, options);
    if (loaded.table.armCount == 0)
        throw ParseError(path, 0, 0,
                         "expected caliper curves (radii R1..Rn, RAD1..n, fingers F01..Fnn, "
                         "diameters C1, C2, or one "
                         "diameter CALI), "
                         "found none among " +
                             std::to_string(loaded.info.curves.size()) +
                             " curves; name them with --radii or --diameters");
    if (diagnostics) diagnostics->merge(loaded.info.diagnostics);
    return std::move(loaded.table);
}

namespace {

// The first bytes of a file, enough to tell a survey from a log.
std::string fileHead(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string head(64u << 10, '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(in.gcount()));
    return head;
}

LogInfo describeSurvey(const std::string& path, const ReadOptions& options) {
    LogInfo info;
    info.file = path;
    info.survey = true;
    SurveyReadOptions surveyOptions;
    surveyOptions.depthUnit = options.depthUnit;
    const SurveyTable s = readSurvey(path, surveyOptions, &info.diagnostics);
    const char* delimiter = s.delimiter == ','    ? "comma-separated"
                            : s.delimiter == ';'  ? "semicolon-separated"
                            : s.delimiter == '\t' ? "tab-separated"
                                                  : "columns separated by spaces";
    info.format = "deviation survey (" + std::string(delimiter) + ", column names on line " +
                  std::to_string(s.headerLine) + ")";
    info.wellName = s.wellName;
    info.depthUnit = std::string(unitName(s.depthUnit));
    info.rows = s.stationCount();
    info.top_m = s.md_m.front();
    info.bottom_m = s.md_m.back();
    std::vector<double> steps;
    for (std::size_t i = 1; i < s.md_m.size(); ++i) steps.push_back(s.md_m[i] - s.md_m[i - 1]);
    info.step_m = medianInPlace(steps);
    info.armSource = "none: a deviation survey, not a caliper log (give it to a log with --survey)";
    auto nullsIn = [](const std::vector<double>& v) {
        return static_cast<std::size_t>(
            std::count_if(v.begin(), v.end(), [](double x) { return std::isnan(x); }));
    };
    for (const SurveyColumn& c : s.columns) {
        CurveInfo curve{c.name, c.unit, c.role.empty() ? "not read" : c.role, 0, {}};
        if (c.role.rfind("TVD", 0) == 0) curve.nulls = nullsIn(s.tvd_m);
        if (c.role.rfind("north", 0) == 0) curve.nulls = nullsIn(s.north_m);
        if (c.role.rfind("east", 0) == 0) curve.nulls = nullsIn(s.east_m);
        info.curves.push_back(std::move(curve));
    }
    return info;
}

}  // namespace

LogInfo describeLog(const std::string& path, const ReadOptions& options) {
    return describeLog(path, options, [](const SectionTable&) {});
}

LogInfo describeLog(const std::string& path, const ReadOptions& options,
                    const std::function<void(const SectionTable&)>& onRows, bool surveyGiven) {
    const std::string head = fileHead(path);
    if (!hasUtf16Mark(head) && looksLikeSurvey(head)) return describeSurvey(path, options);
    LogInfo info = streamCaliperLog(path, options, onRows);
    if (!options.casing.empty()) info.casing = options.casing;
    const HoleAzimuthPlan plan = holeAzimuthPlan(info, surveyGiven);
    info.holeAzimuth = plan.description;
    if (plan.kind == SectionTable::HoleAzimuth::Unknown)
        info.diagnostics.warn(path, 0,
                              "hole azimuth unknown: north, east and azimuth are not known where "
                              "the hole is inclined (give --survey)");
    return info;
}

std::string formatLogInfo(const LogInfo& info) {
    std::ostringstream out;
    out << "file:      " << info.file << "\n";
    out << "format:    " << info.format << "\n";
    for (std::size_t i = 0; i < info.details.size(); ++i)
        out << (i == 0 ? "contents:  " : "           ") << info.details[i] << "\n";
    if (!info.wellName.empty()) out << "well:      " << info.wellName << "\n";
    out << formatWellLocation(info.location);
    out << "rows:      " << info.rows << (info.survey ? " stations\n" : " sections\n");
    out.setf(std::ios::fixed);
    out.precision(4);
    out << (info.survey ? "MD:        " : "depth:     ") << info.top_m << " to " << info.bottom_m
        << " m, step " << info.step_m << (info.survey ? " m (median)" : " m");
    if (!info.depthUnit.empty()) out << " (file unit " << info.depthUnit << ")";
    out << "\n";
    out << "arms:      " << info.arms << " from " << info.armSource << "\n";
    out.precision(1);
    if (info.survey) {
    } else if (std::isfinite(info.bitSize_mm) && std::isfinite(info.bitSizeMax_mm) &&
               info.bitSizeMax_mm > info.bitSize_mm)
        out << "bit size:  " << info.bitSize_mm << " to " << info.bitSizeMax_mm << " mm\n";
    else if (std::isfinite(info.bitSize_mm))
        out << "bit size:  " << info.bitSize_mm << " mm\n";
    else
        out << "bit size:  unknown (give --bit-size)\n";
    if (!info.declaredNull.empty())
        out << "null:      " << info.declaredNull << " (declared in the header)\n";
    else if (info.format.rfind("LAS", 0) == 0)
        out << "null:      none declared in the header\n";
    if (!info.holeAzimuth.empty()) out << "hole azi:  " << info.holeAzimuth << "\n";
    if (!info.north.resolved.empty()) out << "north:     " << info.north.resolved << "\n";
    for (const CasingString& c : info.casing) out << "casing:    " << describeCasing(c) << "\n";
    out << (info.survey ? "columns:\n" : "curves:\n");
    // Characters, not bytes: a decoded UTF-16 header may hold non-ASCII mnemonics.
    auto shown = [](const std::string& s) {
        return static_cast<std::size_t>(std::count_if(s.begin(), s.end(), [](char c) {
            return (static_cast<unsigned char>(c) & 0xC0) != 0x80;
        }));
    };
    std::size_t width =
        12;  // long survey column names ("Measured Depth ( ft )") widen the name column
    std::size_t unitWidth = 8;  // "in (assumed)" widens the unit column
    for (const CurveInfo& c : info.curves) {
        width = std::max(width, shown(c.mnemonic));
        unitWidth = std::max(unitWidth, shown(c.unit));
    }
    // The role (with the nulls), then the file's own description in a column of its own.
    auto roleText = [](const CurveInfo& c) {
        std::string text = c.role;
        if (c.nulls) text += ", " + std::to_string(c.nulls) + (c.nulls == 1 ? " null" : " nulls");
        return text;
    };
    std::size_t roleWidth = 0;
    for (const CurveInfo& c : info.curves) roleWidth = std::max(roleWidth, shown(roleText(c)));
    for (const CurveInfo& c : info.curves) {
        out << "  " << c.mnemonic;
        for (std::size_t i = shown(c.mnemonic); i < width; ++i) out << ' ';
        out << " " << (c.unit.empty() ? "-" : c.unit);
        for (std::size_t i = c.unit.empty() ? 1 : shown(c.unit); i < unitWidth; ++i) out << ' ';
        const std::string role = roleText(c);
        out << " " << role;
        if (!c.description.empty()) {
            for (std::size_t i = shown(role); i < roleWidth; ++i) out << ' ';
            out << "  " << c.description;
        }
        out << "\n";
    }
    out << "warnings:  " << info.diagnostics.warningCount << "\n";
    for (const Warning& w : info.diagnostics.warnings) {
        out << "  " << w.file;
        if (w.line) out << ":" << w.line;
        out << ": " << w.message << "\n";
    }
    if (info.diagnostics.warningCount > info.diagnostics.warnings.size())
        out << "  (" << info.diagnostics.warningCount - info.diagnostics.warnings.size()
            << " more)\n";
    return out.str();
}

}  // namespace caliper3d::io
