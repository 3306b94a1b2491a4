#pragma once

#include <ostream>
#include <string>

#include "reconstruction/well_analysis.h"

namespace caliper3d::reconstruction {

struct ReportOptions {
    // 0: one row per section. Otherwise one row per `step_m` metres of MD:
    // the section nearest to top + k * step (sections are reported as
    // measured, never averaged, so that a row is always a real section).
    double step_m = 0.0;
};

// The per-section CSV (design section 8): one header line, then
//   md_m,tvd_m,north_m,east_m,inc_deg,azi_deg,dmin_mm,dmax_mm,ellipticity,
//   major_azimuth_deg,area_mm2,centre_offset_mm,class,
// followed by dls_deg_per_30m,bit_mm,equivalent_diameter_mm,
//   major_from_high_side_deg,centre_offset_azimuth_deg,repaired_arms.
// An undefined value (major azimuth of a vertical axis, unknown bit size) is
// an empty field. Decimal point, no thousands separator, whatever the locale.
void writeSectionReport(std::ostream& out, const WellAnalysis& analysis, const ReportOptions& options = {});

// The zone table: kind,top_m,bottom_m,length_m,mean_azimuth_deg,
// circular_sd_deg,mean_dmax_mm,mean_dmin_mm,sections.
void writeZoneReport(std::ostream& out, const WellAnalysis& analysis);

// Human-readable interval summary (breakouts with WSM quality, volumes,
// orientation check, repaired arms), several "key: value" lines.
std::string formatAnalysisSummary(const WellAnalysis& analysis);

// The same to files; throw std::runtime_error naming the file when it cannot be written.
void writeSectionReport(const std::string& path, const WellAnalysis& analysis, const ReportOptions& options = {});
void writeZoneReport(const std::string& path, const WellAnalysis& analysis);

}  // namespace caliper3d::reconstruction
