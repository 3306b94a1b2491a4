#pragma once

#include <cstddef>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include <optional>

#include "reconstruction/analysis/well_analysis.h"
#include "reconstruction/path/wellhead.h"

namespace caliper3d::reconstruction {

struct ReportOptions {
    // 0: one row per section. Otherwise one row per `step_m` metres of MD:
    // the section nearest to top + k * step (sections are reported as
    // measured, never averaged, so that a row is always a real section).
    double step_m = 0.0;
    // When known, rows also carry map coordinates and depth below the datum:
    // easting_m, northing_m (the wellhead's grid) and tvdss_m (TVD minus the
    // wellhead's elevation; positive below the datum).
    std::optional<Wellhead> wellhead;
};

// The per-section CSV (docs/analysis.md, "Report CSV"): one header line, then
//   md_m,tvd_m,north_m,east_m,inc_deg,azi_deg,dmin_mm,dmax_mm,ellipticity,
//   major_azimuth_deg,area_mm2,centre_offset_mm,class,
// followed by dls_deg_per_30m,bit_mm,equivalent_diameter_mm,
//   major_from_high_side_deg,centre_offset_azimuth_deg,repaired_arms
// (and easting_m,northing_m,tvdss_m with a wellhead).
// An undefined value (major azimuth of a vertical axis, unknown bit size) is
// an empty field; a no_data section keeps its position, path and bit size and
// leaves every measurement and repaired_arms empty. Decimal point, no thousands separator, whatever
// the locale.
void writeSectionReport(std::ostream& out, const WellAnalysis& analysis,
                        const ReportOptions& options = {});

// One section's row of that CSV as (column, text) pairs, in the CSV's order and with its
// digits (the same code writes both): an undefined value is empty, and a no_data section
// leaves every measurement and repaired_arms empty.
std::vector<std::pair<std::string, std::string>> sectionReportFields(
    const SectionResult& section, const ReportOptions& options = {});

// The sections a report lists (indices into analysis.sections, ascending).
std::vector<std::size_t> reportedSections(const WellAnalysis& analysis,
                                          const ReportOptions& options);

// The report's rows as LAS 2.0 curves (one line per reported section), read
// back by any LAS reader: DEPT (M), TVD, NORTH, EAST (M), INC, AZI (DEG),
// DLS (DEG/30M), BS, DMIN, DMAX (MM), ELLIP, MAJAZ, MAJHS (DEG), AREA (MM2),
// DEQ, CENOFF (MM), CENAZ (DEG), CLASS (code: 0 in_gauge, 1 undergauge,
// 2 washout, 3 breakout, 4 keyseat, 5 cased) and REPAIRED (arms interpolated).
// Undefined values are the null value. `wellName` goes into ~Well.
void writeAnalysisLas(std::ostream& out, const WellAnalysis& analysis,
                      const ReportOptions& options = {}, const std::string& wellName = "CALIPER3D");
void writeAnalysisLas(const std::string& path, const WellAnalysis& analysis,
                      const ReportOptions& options = {}, const std::string& wellName = "CALIPER3D");

// The zone table: kind,top_m,bottom_m,length_m,mean_azimuth_deg,
// circular_sd_deg,mean_dmax_mm,mean_dmin_mm,sections.
void writeZoneReport(std::ostream& out, const WellAnalysis& analysis);

// Human-readable interval summary (breakouts with WSM quality, volumes and
// the interval they could not cover, orientation check), several "key: value"
// lines. Warnings are not in it: reconstruction::warnAnalysis counts them.
std::string formatAnalysisSummary(const WellAnalysis& analysis);

// The same to files, each whole or not at all (io/atomic_output.h: a run killed midway leaves
// the previous file); throw std::runtime_error naming the file when it cannot be written.
void writeSectionReport(const std::string& path, const WellAnalysis& analysis,
                        const ReportOptions& options = {});
void writeZoneReport(const std::string& path, const WellAnalysis& analysis);

}  // namespace caliper3d::reconstruction
