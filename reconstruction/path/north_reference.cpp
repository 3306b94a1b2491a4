#include "reconstruction/path/north_reference.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "reconstruction/path/magnetic_declination.h"

namespace caliper3d::reconstruction {

namespace {

std::string fixed(double v, int decimals) {
    char buffer[48];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
    return buffer;
}

std::string placeText(const io::WellLocation& l) {
    return fixed(std::fabs(l.latitude_deg), 4) + (l.latitude_deg < 0 ? " S, " : " N, ") +
           fixed(std::fabs(l.longitude_deg), 4) + (l.longitude_deg < 0 ? " W" : " E");
}

struct Angle {
    double deg = std::nan("");
    std::string source;
    std::string why;  // when none
};

Angle declinationFor(const io::AzimuthNorth& north, const io::WellLocation& location,
                     const io::ReadOptions& options) {
    Angle a;
    if (options.declination_deg) {
        a.deg = *options.declination_deg;
        a.source = "--declination";
        return a;
    }
    if (north.declination.found()) {
        a.deg = north.declination.deg;
        a.source = "the header's " + north.declination.source;
        return a;
    }
    const ModelDeclination model =
        modelDeclination(location.latitude_deg, location.longitude_deg, north.logYear);
    if (model.found()) {
        a.deg = model.deg;
        a.source = model.model + " at " + placeText(location) + " on " + north.dateSource;
        return a;
    }
    a.why =
        "no --declination, no declination in the header (MDEC, DECL, MAGDEC, ...), and the "
        "magnetic model cannot give one: " +
        model.why;
    return a;
}

Angle convergenceFor(const io::AzimuthNorth& north, const io::ReadOptions& options) {
    Angle a;
    if (options.gridConvergence_deg) {
        a.deg = *options.gridConvergence_deg;
        a.source = "--grid-convergence";
    } else if (north.convergence.found()) {
        a.deg = north.convergence.deg;
        a.source = "the header's " + north.convergence.source;
    } else {
        a.why =
            "no --grid-convergence and no grid convergence in the header (GRIDCONV, GCONV, "
            "...)";
    }
    return a;
}

double wrap360(double deg) {
    double r = std::fmod(deg, 360.0);
    if (r < 0.0) r += 360.0;
    return r >= 360.0 ? 0.0 : r;
}

}  // namespace

std::string eastAngleText(double deg) {
    if (deg == 0.0) return "0.00";
    return fixed(std::fabs(deg), 2) + (deg < 0.0 ? " W" : " E");
}

NorthCorrection resolveNorth(const io::AzimuthNorth& north, const io::WellLocation& location,
                             const io::ReadOptions& options) {
    NorthCorrection out;
    if (north.curves.empty()) {
        if (options.declination_deg)
            out.warnings.emplace_back(
                "--declination given, but the log has no azimuth curve: not applied");
        if (options.gridConvergence_deg)
            out.warnings.emplace_back(
                "--grid-convergence given, but the log has no azimuth curve: not applied");
        return out;
    }
    std::vector<io::CurveNorth> curves = north.curves;
    for (io::CurveNorth& c : curves)
        if (!c.stated && options.azimuthNorth != io::North::Unknown) {
            c.north = options.azimuthNorth;
            c.evidence = "--azimuth-north";
        }

    bool magnetic = false, grid = false;
    for (const io::CurveNorth& c : curves) {
        magnetic = magnetic || c.north == io::North::Magnetic;
        grid = grid || c.north == io::North::Grid;
    }
    const Angle declination = magnetic ? declinationFor(north, location, options) : Angle{};
    const Angle convergence = grid ? convergenceFor(north, options) : Angle{};

    std::string summary;
    for (const io::CurveNorth& c : curves) {
        std::string text = c.mnemonic + " (" + c.role + ") from " + io::northName(c.north);
        switch (c.north) {
            case io::North::True:
                text += ", " + c.evidence;
                break;
            case io::North::Magnetic:
                text += ", " + c.evidence;
                if (std::isfinite(declination.deg)) {
                    out.add_deg[c.angle] = declination.deg;
                    text += ": declination " + eastAngleText(declination.deg) + " from " +
                            declination.source + " applied, now from true north";
                } else {
                    text += ": no declination known, left from magnetic north";
                    out.warnings.push_back(c.mnemonic + " is from magnetic north (" + c.evidence +
                                           ") and " + declination.why +
                                           ": its azimuths are left from magnetic north (give "
                                           "--declination DEG, east positive)");
                }
                break;
            case io::North::Grid:
                text += ", " + c.evidence;
                if (std::isfinite(convergence.deg)) {
                    out.add_deg[c.angle] = convergence.deg;
                    text += ": grid convergence " + eastAngleText(convergence.deg) + " from " +
                            convergence.source + " applied, now from true north";
                } else {
                    text += ": no grid convergence known, left from grid north";
                    out.warnings.push_back(c.mnemonic + " is from grid north (" + c.evidence +
                                           ") and " + convergence.why +
                                           ": its azimuths are left from grid north (give "
                                           "--grid-convergence DEG)");
                }
                break;
            case io::North::Unknown: {
                text += ": taken as true north, no declination applied";
                std::string warning =
                    c.mnemonic + " (" + c.role +
                    "): no description, header item or --azimuth-north says which north it is "
                    "from: taken as true north, no declination applied";
                if (north.declination.found())
                    warning += " (the header gives a declination of " +
                               eastAngleText(north.declination.deg) + ", " +
                               north.declination.source + ": --azimuth-north magnetic applies it)";
                else
                    warning += " (--azimuth-north magnetic|grid|true says)";
                out.warnings.push_back(std::move(warning));
                break;
            }
        }
        summary += (summary.empty() ? "" : "; ") + text;
    }
    if (!magnetic) {
        if (options.declination_deg) {
            summary += "; --declination " + eastAngleText(*options.declination_deg) +
                       " not applied: no azimuth is from magnetic north";
            out.warnings.emplace_back(
                "--declination given, but no azimuth curve is from magnetic "
                "north: not applied (--azimuth-north magnetic says it is)");
        } else if (north.declination.found()) {
            summary += "; declination " + eastAngleText(north.declination.deg) + " in " +
                       north.declination.source + " not applied: no azimuth is from magnetic north";
        }
    }
    if (!grid && options.gridConvergence_deg) {
        summary += "; --grid-convergence " + eastAngleText(*options.gridConvergence_deg) +
                   " not applied: no azimuth is from grid north";
        out.warnings.emplace_back(
            "--grid-convergence given, but no azimuth curve is from grid "
            "north: not applied (--azimuth-north grid says it is)");
    }
    out.summary = std::move(summary);
    return out;
}

void applyNorth(io::SectionTable& table, const NorthCorrection& correction) {
    table.north = correction.summary;
    auto add = [](std::vector<double>& values, double deg) {
        if (deg == 0.0) return;
        for (double& v : values)
            if (!std::isnan(v)) v = wrap360(v + deg);
    };
    add(table.p1az_deg, correction.add_deg[0]);
    add(table.hazi_deg, correction.add_deg[2]);
}

}  // namespace caliper3d::reconstruction
