#include "app/input_summary.h"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include <sys/resource.h>

#include <nlohmann/json.hpp>

#include "app/input_options.h"
#include "io/parse_error.h"
#include "reconstruction/analysis/borehole_classifier.h"
#include "reconstruction/analysis/well_analysis.h"

namespace caliper3d::app {

namespace {

// The figures of a comparison as `compare` writes them (docs/formats.md, "Summary lines").
nlohmann::ordered_json comparisonJson(const reconstruction::RunComparison& r,
                                      std::size_t sections) {
    const auto finite = [](double v) {
        return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
    };
    nlohmann::ordered_json zones = nlohmann::ordered_json::array();
    for (const reconstruction::ZoneChange& z : r.zones)
        zones.push_back({{"change", std::string(reconstruction::zoneChangeName(z.kind))},
                         {"class", std::string(reconstruction::className(z.cls))},
                         {"top1_m", z.top1_m},
                         {"bottom1_m", z.bottom1_m},
                         {"top2_m", z.top2_m},
                         {"bottom2_m", z.bottom2_m},
                         {"max_d_dmax_mm", finite(z.maxDmaxChange_mm)}});
    const auto largest = [&](const reconstruction::LargestChange& c) {
        return nlohmann::ordered_json{{"change_mm", finite(c.change)}, {"md_m", finite(c.md1_m)}};
    };
    return {{"shift_m", r.mapping.shift_m},
            {"shift_given", r.mapping.given},
            {"match_curve", r.mapping.curve},
            {"correlation", finite(r.mapping.match.correlation)},
            {"stretch_mm_per_m", r.mapping.stretch * 1000.0},
            {"overlap_m", {r.overlapTop1_m, r.overlapBottom1_m}},
            {"sections", sections},
            {"compared", r.compared},
            {"oriented", r.oriented},
            {"outlines_skipped", r.outlinesSkipped},
            {"bias_mm", {finite(r.bias1.offset_mm), finite(r.bias2.offset_mm)}},
            {"repeatability_mm", r.repeatability95_mm},
            {"significant", r.significant},
            {"significant_m", r.significant_m},
            {"class_changes", r.classChanges},
            {"largest_d_deq", largest(r.deq)},
            {"largest_d_dmin", largest(r.dmin)},
            {"largest_d_dmax", largest(r.dmax)},
            {"volumes_m3", {r.volume1_m3, r.volume2_m3}},
            {"volume_length_m", r.volumeLength_m},
            {"zones", zones},
            {"agree", r.agree()}};
}

}  // namespace

InputError inputErrorFrom(const std::exception& e, const std::string& input) {
    if (const auto* parse = dynamic_cast<const io::ParseError*>(&e))
        return {parse->file(), parse->line(), parse->message()};
    return {input, 0, e.what()};
}

void InputSummary::addWarnings(const io::Diagnostics& diagnostics) {
    warningCount += diagnostics.warningCount;
    for (const io::Warning& w : diagnostics.warnings) {
        if (warnings.size() >= kKeptWarnings) break;
        std::string text = w.file;
        if (w.line > 0) text += ":" + std::to_string(w.line);
        warnings.push_back(text + ": " + w.message);
    }
}

void InputSummary::addAnalysis(const reconstruction::WellAnalysis& analysis) {
    rows = analysis.sections.size();
    if (analysis.sections.size() > 0) {
        top_m = analysis.sections[0].md_m;
        bottom_m = analysis.sections[analysis.sections.size() - 1].md_m;
    }
    for (const reconstruction::SectionResult& section : analysis.sections)
        ++classes[std::string(reconstruction::className(section.cls))];
    zones = analysis.zones.size();
    for (const reconstruction::Zone& zone : analysis.zones)
        ++zonesByClass[std::string(reconstruction::className(zone.kind))];
    volume = analysis.volume;
    breakouts = analysis.breakouts;
    unorientedSections = analysis.unorientedSections;
    casing = analysis.casing;
    armsNotOpen = analysis.armsNotOpen;
}

nlohmann::ordered_json toJson(const InputSummary& s) {
    nlohmann::ordered_json line = nlohmann::ordered_json::object();
    line["file"] = s.file;
    line["verb"] = s.verb;
    line["status"] = s.error ? "failed" : "ok";
    if (s.error) {
        nlohmann::ordered_json where;
        where["file"] = s.error->file;
        where["line"] = s.error->line > 0 ? nlohmann::ordered_json(s.error->line) : nullptr;
        where["reason"] = s.error->reason;
        line["error"] = where;
    }
    if (!s.outputs.empty()) line["outputs"] = s.outputs;
    if (s.rows) line["rows"] = *s.rows;
    if (s.top_m && s.bottom_m) line["depth_m"] = {*s.top_m, *s.bottom_m};
    if (!s.classes.empty()) line["classes"] = s.classes;
    if (s.zones) {
        line["zones"] = *s.zones;
        line["zones_by_class"] = s.zonesByClass.empty() ? nlohmann::ordered_json::object()
                                                        : nlohmann::ordered_json(s.zonesByClass);
    }
    if (s.volume) {
        const reconstruction::HoleVolume& v = *s.volume;
        line["volumes_m3"] = {{"top_m", v.top_m},
                              {"bottom_m", v.bottom_m},
                              {"hole", v.hole_m3},
                              {"gauge_hole", v.gaugeHole_m3},
                              {"annulus", v.annulus_m3},
                              {"gauge_annulus", v.gaugeAnnulus_m3},
                              {"cement", v.cement_m3},
                              {"gauge_cement", v.gaugeCement_m3},
                              {"uncovered_m", v.uncovered_m},
                              {"cased_m", v.cased_m}};
    }
    if (!s.casing.empty()) {
        nlohmann::ordered_json strings = nlohmann::ordered_json::array();
        for (const reconstruction::CasingCheck& c : s.casing)
            strings.push_back({{"bottom_m", c.casing.bottom_m},
                               {"size_mm", c.casing.size_mm},
                               {"weight_kg_per_m", c.casing.weight_kgPerM},
                               {"nominal_id_mm", c.casing.innerDiameter_mm},
                               {"source", c.casing.source},
                               {"sections", c.sections},
                               {"median_reading_mm", c.medianDiameter_mm},
                               {"offset_mm", c.offset_mm}});
        line["casing"] = strings;
    }
    if (!s.armsNotOpen.empty()) {
        nlohmann::ordered_json gaps = nlohmann::ordered_json::array();
        for (const reconstruction::NoDataInterval& gap : s.armsNotOpen)
            gaps.push_back({{"top_m", gap.top_m},
                            {"bottom_m", gap.bottom_m},
                            {"sections", gap.sections()},
                            {"reason", "arms not open"}});
        line["arms_not_open"] = gaps;
    }
    if (s.breakouts) {
        // An azimuth that is not known is null, never a number from an assumed north.
        auto angle = [](double deg) {
            return std::isfinite(deg) ? nlohmann::ordered_json(deg) : nlohmann::ordered_json();
        };
        const reconstruction::BreakoutSummary& b = *s.breakouts;
        line["breakouts"] = {{"zones", b.zoneCount},
                             {"combined_m", b.combinedLength_m},
                             {"mean_azimuth_deg", angle(b.meanAzimuth_deg)},
                             {"circular_sd_deg", angle(b.circularSd_deg)},
                             {"shmax_azimuth_deg", angle(b.shmaxAzimuth_deg)},
                             {"wsm_quality", std::string(1, b.quality)}};
        line["unoriented_sections"] = s.unorientedSections;
    }
    if (s.compared && s.compared->comparison) {
        line["file2"] = s.compared->file2;
        nlohmann::ordered_json comparison =
            comparisonJson(*s.compared->comparison, s.compared->sections);
        if (!s.compared->wallColour.empty()) comparison["wall_colour"] = s.compared->wallColour;
        line["comparison"] = std::move(comparison);
    }
    line["warnings"] = s.warningCount;
    line["warning_messages"] = s.warnings;
    line["seconds"] = s.seconds;
    line["peak_rss_mb"] = s.peakRss_mb;
    return line;
}

SummaryFile::SummaryFile(const std::string& path) : m_path(path) {
    if (path.empty()) return;
    // Its folder is made as -o DIR/ makes the outputs' ("--summary out/summary.jsonl").
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    std::error_code made;
    if (!folder.empty()) std::filesystem::create_directories(folder, made);
    m_file = std::fopen(path.c_str(), "wb");
    if (!m_file)
        throw UsageError("--summary: cannot open '" + path + "' for writing" +
                         (made ? " (cannot make its folder: " + made.message() + ")" : ""));
}

SummaryFile::~SummaryFile() {
    if (m_file) std::fclose(m_file);
}

void SummaryFile::write(const InputSummary& summary) {
    write(toJson(summary));
}

void SummaryFile::write(const nlohmann::ordered_json& line) {
    if (!m_file) return;
    // NaN (a gauge volume without a bit size) is written null; bytes of a file name that are
    // not UTF-8 are replaced rather than refused.
    const std::string text =
        line.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
    std::fputs(text.c_str(), m_file);
    std::fputc('\n', m_file);
    if (std::fflush(m_file) != 0) throw std::runtime_error(m_path + ": write failed");
}

double steadySeconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

void stampCost(InputSummary& summary, double startSeconds) {
    summary.seconds = steadySeconds() - startSeconds;
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    summary.peakRss_mb = static_cast<double>(usage.ru_maxrss) / 1024.0;  // KiB on Linux
}

}  // namespace caliper3d::app
