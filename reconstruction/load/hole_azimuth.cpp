#include "reconstruction/load/hole_azimuth.h"

#include <cmath>

#include "reconstruction/section/arm_geometry.h"

namespace caliper3d::reconstruction {

void deriveHoleAzimuth(io::SectionTable& table) {
    const std::size_t rows = table.rowCount();
    table.hazi_deg.assign(rows, io::kNaN);
    if (table.p1az_deg.size() != rows || table.rb_deg.size() != rows) return;
    for (std::size_t i = 0; i < rows; ++i) {
        const double p1az = table.p1az_deg[i], rb = table.rb_deg[i];
        if (std::isfinite(p1az) && std::isfinite(rb)) table.hazi_deg[i] = wrap360(p1az - rb);
    }
}

void resolveHoleAzimuth(io::SectionTable& table, const io::HoleAzimuthPlan& plan,
                        io::Diagnostics* diagnostics) {
    table.holeAzimuth = plan.kind;
    if (plan.kind == io::SectionTable::HoleAzimuth::Derived) {
        deriveHoleAzimuth(table);
        if (diagnostics) diagnostics->warn(table.source, 0, "hole azimuth " + plan.description);
    } else if (plan.kind == io::SectionTable::HoleAzimuth::Unknown && diagnostics) {
        diagnostics->warn(table.source, 0,
                          "hole azimuth " + plan.description +
                              ". The path is drawn straight down at its TVD (the direction of its "
                              "departure is not known), and the report leaves north, east and "
                              "azimuth empty where they depend on it");
    }
}

}  // namespace caliper3d::reconstruction
