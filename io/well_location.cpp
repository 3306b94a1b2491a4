#include "io/well_location.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "io/number_parsing.h"
#include "io/text.h"
#include "io/units.h"

namespace caliper3d::io {

namespace {

// "K.B.", "KB", "Kelly Bushing" -> "KB": letters only, and the long names shortened.
std::string referenceCode(const std::string& name) {
    std::string letters;
    for (unsigned char c : name)
        if (std::isalpha(c)) letters += static_cast<char>(std::toupper(c));
    if (letters == "KELLYBUSHING") return "KB";
    if (letters == "DRILLFLOOR" || letters == "DERRICKFLOOR") return "DF";
    if (letters == "GROUNDLEVEL") return "GL";
    return letters;
}

const LasItem* item(const LasHeader& h, const char* mnemonic) {
    const LasItem* i = h.parameter(mnemonic);
    if (!i || i->value.empty()) i = h.wellItem(mnemonic);
    return i && !i->value.empty() ? i : nullptr;
}

std::string text(const LasHeader& h, std::initializer_list<const char*> mnemonics) {
    for (const char* m : mnemonics)
        if (const LasItem* i = item(h, m)) return i->value;
    return {};
}

// A length item in metres; NaN (with a warning when it is there but unusable)
// otherwise. An item without a unit is in the unit of the depth index (STRT).
double metres(const LasHeader& h, const char* mnemonic, const std::string& file,
              Diagnostics* diagnostics) {
    const LasItem* i = item(h, mnemonic);
    if (!i) return kNaN;
    double v = 0.0;
    if (!parseNumber(i->value, v) || !std::isfinite(v) || (h.hasNull && v == h.null)) return kNaN;
    std::string unit = i->unit;
    if (unit.empty())
        if (const LasItem* strt = h.wellItem("STRT")) unit = strt->unit;
    const auto u = parseLengthUnit(unit);
    if (!u) {
        if (diagnostics)
            diagnostics->warn(file, i->line,
                              std::string(mnemonic) + " " + i->value + " has no length unit (" +
                                  (unit.empty() ? "none" : "'" + unit + "'") + "); not read");
        return kNaN;
    }
    return v * toMetres(*u);
}

}  // namespace

bool WellLocation::hasProjected() const {
    return std::isfinite(easting_m) && std::isfinite(northing_m);
}

bool WellLocation::empty() const {
    return uwi.empty() && depthReference.empty() && !std::isfinite(referenceElevation_m) &&
           !std::isfinite(groundElevation_m) && !hasProjected() && latitudeText.empty() &&
           longitudeText.empty();
}

double parseGeographicDegrees(const std::string& textIn) {
    std::istringstream in(textIn);
    std::string token;
    double parts[3] = {0.0, 0.0, 0.0};
    int count = 0;
    bool negative = false;
    while (in >> token) {
        std::string t;
        for (char c : token)
            if (c != '\'' && c != '"') t += c;
        // A degree sign (UTF-8 or Latin-1) ends a number.
        for (const char* sign : {"\xC2\xB0", "\xB0"}) {
            const std::size_t at = t.find(sign);
            if (at != std::string::npos) t.erase(at, std::char_traits<char>::length(sign));
        }
        if (t.empty()) continue;
        double v = 0.0;
        if (parseNumber(t, v) && std::isfinite(v)) {
            if (count == 3) return kNaN;
            parts[count++] = v;
            continue;
        }
        const std::string u = upper(t);
        if (u == "S" || u == "W")
            negative = true;
        else if (u != "N" && u != "E" && u != "DEG" && u != "DEGREES" && u != "DEGREE")
            return kNaN;
    }
    if (count == 0) return kNaN;
    const double sign = parts[0] < 0.0 ? -1.0 : 1.0;
    double degrees = std::abs(parts[0]) + parts[1] / 60.0 + parts[2] / 3600.0;
    // "-111.419 W" is west once, not east.
    if (sign < 0.0 || negative) degrees = -degrees;
    return degrees;
}

WellLocation readWellLocation(const LasHeader& h, const std::string& file,
                              Diagnostics* diagnostics) {
    WellLocation w;
    w.uwi = text(h, {"UWI", "API", "APIN"});
    w.serviceCompany = text(h, {"SRVC", "LCNM", "PCON"});
    if (w.serviceCompany.empty())
        for (const LasItem& v : h.versionItems)
            if (upper(v.mnemonic) == "PROD") w.serviceCompany = v.value;

    // The depth reference: EREF says it outright; otherwise the elevation of
    // the reference that LMF (DREF, DMF) names; otherwise the permanent datum's
    // elevation plus the reference's height above it.
    for (const char* m : {"LMF", "DREF", "DMF"}) {
        if (const LasItem* i = item(h, m)) {
            w.depthReference = i->value;
            break;
        }
    }
    const std::string code = referenceCode(w.depthReference);
    const double epd = metres(h, "EPD", file, diagnostics);
    const double apd = metres(h, "APD", file, diagnostics);
    const double eref = metres(h, "EREF", file, diagnostics);
    if (std::isfinite(eref)) {
        w.referenceElevation_m = eref;
        w.elevationSource = "EREF";
    } else {
        const char* named = code == "KB"   ? "EKB"
                            : code == "DF" ? "EDF"
                            : code == "GL" ? "EGL"
                                           : nullptr;
        const double e = named ? metres(h, named, file, diagnostics) : kNaN;
        if (std::isfinite(e)) {
            w.referenceElevation_m = e;
            w.elevationSource = named;
        } else if (std::isfinite(epd) && std::isfinite(apd)) {
            w.referenceElevation_m = epd + apd;
            w.elevationSource = "EPD + APD";
        }
    }
    if (std::isfinite(w.referenceElevation_m) && std::isfinite(epd) && std::isfinite(apd) &&
        std::abs(w.referenceElevation_m - (epd + apd)) > 0.05 && diagnostics) {
        char buf[200];
        std::snprintf(buf, sizeof buf,
                      "depth reference elevation %.2f m (%s) differs from EPD + APD = %.2f m; "
                      "%.2f m is used",
                      w.referenceElevation_m, w.elevationSource.c_str(), epd + apd,
                      w.referenceElevation_m);
        diagnostics->warn(file, item(h, "APD")->line, buf);
    }
    w.groundElevation_m = metres(h, "EGL", file, diagnostics);
    if (!std::isfinite(w.groundElevation_m)) w.groundElevation_m = metres(h, "GL", file, nullptr);

    static const char* const kProjected[][2] = {{"XWELL", "YWELL"},
                                                {"XCOORD", "YCOORD"},
                                                {"EASTING", "NORTHING"},
                                                {"UTMX", "UTMY"},
                                                {"X", "Y"}};
    for (const auto& pair : kProjected) {
        if (!item(h, pair[0]) || !item(h, pair[1])) continue;
        const double e = metres(h, pair[0], file, diagnostics);
        const double n = metres(h, pair[1], file, diagnostics);
        if (!std::isfinite(e) || !std::isfinite(n)) continue;
        w.easting_m = e;
        w.northing_m = n;
        w.projectedSource = std::string(pair[0]) + ", " + pair[1];
        break;
    }

    auto geographic = [&](std::initializer_list<const char*> names, std::string& textOut,
                          double& degrees, double limit) {
        for (const char* m : names) {
            const LasItem* i = item(h, m);
            if (!i) continue;
            textOut = i->value;
            degrees = parseGeographicDegrees(i->value);
            if (!(std::abs(degrees) <= limit)) {
                degrees = kNaN;
                if (diagnostics)
                    diagnostics->warn(file, i->line,
                                      std::string(m) + " '" + i->value +
                                          "' is not decimal degrees or degrees, minutes and "
                                          "seconds; shown as written");
            }
            return;
        }
    };
    geographic({"LATI", "LAT", "LATITUDE"}, w.latitudeText, w.latitude_deg, 90.0);
    geographic({"LONG", "LON", "LONGITUDE"}, w.longitudeText, w.longitude_deg, 180.0);
    return w;
}

std::string formatWellLocation(const WellLocation& w) {
    if (w.empty()) return {};
    std::string out;
    char buf[256];
    if (!w.uwi.empty()) out += "UWI:       " + w.uwi + "\n";
    if (std::isfinite(w.referenceElevation_m)) {
        std::snprintf(buf, sizeof buf, "depth ref: %s, elevation %.2f m from %s\n",
                      w.depthReference.empty() ? "unnamed" : w.depthReference.c_str(),
                      w.referenceElevation_m, w.elevationSource.c_str());
        out += buf;
    } else if (!w.depthReference.empty()) {
        out += "depth ref: " + w.depthReference + ", elevation not given\n";
    }
    if (std::isfinite(w.groundElevation_m)) {
        std::snprintf(buf, sizeof buf, "ground:    elevation %.2f m\n", w.groundElevation_m);
        out += buf;
    }
    if (w.hasProjected()) {
        std::snprintf(buf, sizeof buf, "map:       easting %.2f m, northing %.2f m (%s)\n",
                      w.easting_m, w.northing_m, w.projectedSource.c_str());
        out += buf;
    }
    if (!w.latitudeText.empty() || !w.longitudeText.empty()) {
        auto degrees = [](double v, const std::string& t) {
            char b[96];
            if (std::isfinite(v))
                std::snprintf(b, sizeof b, "%.6f", v);
            else
                std::snprintf(b, sizeof b, "'%s'", t.c_str());
            return std::string(b);
        };
        out += "lat/long:  " + degrees(w.latitude_deg, w.latitudeText) + ", " +
               degrees(w.longitude_deg, w.longitudeText) + "\n";
    }
    if (std::isfinite(w.referenceElevation_m) || w.hasProjected() || !w.latitudeText.empty())
        out +=
            "placement: by --wellhead E,N,ELEV only (the header's location is shown, not used)\n";
    return out;
}

}  // namespace caliper3d::io
