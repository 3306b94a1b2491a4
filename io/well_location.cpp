#include "io/well_location.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <exception>
#include <fstream>
#include <sstream>
#include <string_view>

#include "io/dlis/dlis_reader.h"
#include "io/dlis/dlis_stream.h"
#include "io/number_parsing.h"
#include "io/parse_error.h"
#include "io/stream/mapped_file.h"
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

// The depth reference and its elevation (docs/conventions.md, "Depth reference, tie-in and
// well location"), with a warning where it disagrees with EPD + APD.
void readDepthReference(const LasHeader& h, WellLocation& w, const std::string& file,
                        Diagnostics* diagnostics) {
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
        // The named reference's elevation item, or the item named as the reference itself
        // ("KB.M 25.0"); then ELEV, the elevation of whatever reference LMF (DREF, DMF) or
        // PDAT names.
        static const char* const kKb[] = {"EKB", "KB", nullptr};
        static const char* const kDf[] = {"EDF", "DF", nullptr};
        static const char* const kGl[] = {"EGL", nullptr};
        const char* const* named = code == "KB"   ? kKb
                                   : code == "DF" ? kDf
                                   : code == "GL" ? kGl
                                                  : nullptr;
        for (const char* const* m = named; m && *m && !std::isfinite(w.referenceElevation_m); ++m) {
            const double e = metres(h, *m, file, diagnostics);
            if (!std::isfinite(e)) continue;
            w.referenceElevation_m = e;
            w.elevationSource = *m;
        }
        if (!std::isfinite(w.referenceElevation_m) && (!code.empty() || item(h, "PDAT"))) {
            const double e = metres(h, "ELEV", file, diagnostics);
            if (std::isfinite(e)) {
                w.referenceElevation_m = e;
                w.elevationSource = "ELEV";
                if (w.depthReference.empty())
                    if (const LasItem* pdat = item(h, "PDAT")) w.depthReference = pdat->value;
            }
        }
        if (!std::isfinite(w.referenceElevation_m) && std::isfinite(epd) && std::isfinite(apd)) {
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
}

}  // namespace

bool WellLocation::hasProjected() const {
    return std::isfinite(easting_m) && std::isfinite(northing_m);
}

bool WellLocation::empty() const {
    return uwi.empty() && depthReference.empty() && !std::isfinite(referenceElevation_m) &&
           !std::isfinite(groundElevation_m) && !hasProjected() && latitudeText.empty() &&
           longitudeText.empty() && crs.empty();
}

double parseGeographicDegrees(const std::string& textIn) {
    // Degree, minute and second signs separate numbers, as blanks do: the degree sign and the
    // masculine ordinal often written for it (UTF-8 or Latin-1), primes and quotes.
    std::string spaced;
    for (std::size_t k = 0; k < textIn.size(); ++k) {
        const unsigned char c = static_cast<unsigned char>(textIn[k]);
        const std::string_view rest(textIn.data() + k, textIn.size() - k);
        std::size_t skip = 0;
        for (const char* sign : {"\xC2\xB0", "\xC2\xBA", "\xE2\x80\xB2", "\xE2\x80\xB3"})
            if (rest.substr(0, std::char_traits<char>::length(sign)) == sign)
                skip = std::char_traits<char>::length(sign);
        if (skip > 0) {
            spaced += ' ';
            k += skip - 1;
            continue;
        }
        if (c == 0xB0 || c == 0xBA || c == '\'' || c == '"' || c == ',') {
            spaced += ' ';
            continue;
        }
        // A hemisphere letter next to a number ("57.5N", "W111") is a word of its own.
        const char u = static_cast<char>(std::toupper(c));
        if (u == 'N' || u == 'S' || u == 'E' || u == 'W') {
            const bool afterDigit =
                k > 0 &&
                (std::isdigit(static_cast<unsigned char>(textIn[k - 1])) || textIn[k - 1] == '.');
            const bool beforeDigit =
                k + 1 < textIn.size() && (std::isdigit(static_cast<unsigned char>(textIn[k + 1])) ||
                                          textIn[k + 1] == '-' || textIn[k + 1] == '.');
            if (afterDigit || beforeDigit) {
                spaced += ' ';
                spaced += u;
                spaced += ' ';
                continue;
            }
        }
        spaced += static_cast<char>(c);
    }
    std::istringstream in(spaced);
    std::string t;
    double parts[3] = {0.0, 0.0, 0.0};
    int count = 0;
    bool negative = false;
    int hemispheres = 0;
    while (in >> t) {
        double v = 0.0;
        if (parseNumber(t, v) && std::isfinite(v)) {
            if (count == 3) return kNaN;
            // Only the degrees carry a sign; minutes and seconds are under 60.
            if (count > 0 && (v < 0.0 || v >= 60.0)) return kNaN;
            parts[count++] = v;
            continue;
        }
        const std::string u = upper(t);
        if (u == "S" || u == "W" || u == "N" || u == "E") {
            if (++hemispheres > 1) return kNaN;
            negative = u == "S" || u == "W";
        } else if (u != "DEG" && u != "DEGREES" && u != "DEGREE") {
            return kNaN;
        }
    }
    if (count == 0) return kNaN;
    const double sign = parts[0] < 0.0 ? -1.0 : 1.0;
    double degrees = std::abs(parts[0]) + parts[1] / 60.0 + parts[2] / 3600.0;
    // "-111.419 W" is west once, not east.
    if (sign < 0.0 || negative) degrees = -degrees;
    return degrees;
}

WellLocation readWellLocationOf(const std::string& path, Diagnostics* diagnostics) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return {};
    {
        // DLIS: the parameters of its first logical file that gives a place.
        std::string start(512, '\0');
        in.read(start.data(), static_cast<std::streamsize>(start.size()));
        start.resize(static_cast<std::size_t>(in.gcount()));
        if (dlis::looksLikeDlis(start)) {
            try {
                const MappedFile file(path);
                return readDlisWellLocation(file.bytes(), path, diagnostics);
            } catch (const ParseError&) {
                return {};  // the log's own read says what is wrong
            }
        }
        in.clear();
        in.seekg(0);
    }
    // The header ends at the first log data section (~A, LAS 3's ~Log_Data); read blocks
    // until its title line (a header is a few kilobytes; the 4 MB bound keeps a file that is
    // not LAS from being read whole).
    std::string text;
    char block[65536];
    std::size_t end = std::string::npos;
    std::size_t lineStart = 0;  // the first line not yet looked at
    while (end == std::string::npos && text.size() < (std::size_t{4} << 20)) {
        in.read(block, sizeof block);
        const auto got = static_cast<std::size_t>(in.gcount());
        text.append(block, got);
        const bool last = got < sizeof block;
        while (end == std::string::npos) {
            const std::size_t nl = text.find('\n', lineStart);
            if (nl == std::string::npos && !last) break;  // the line goes on in the next block
            const std::size_t stop = nl == std::string::npos ? text.size() : nl;
            const std::string_view line =
                trim(std::string_view(text).substr(lineStart, stop - lineStart));
            if (!line.empty() && line.front() == '~' && isLasDataTitle(line)) end = lineStart;
            if (nl == std::string::npos) break;
            lineStart = nl + 1;
        }
        if (last) break;
    }
    if (end == std::string::npos) return {};
    text.resize(end);
    const std::string_view head = trim(text);
    if (head.empty() || head.front() != '~') return {};  // not LAS text (DLIS, column text)
    try {
        return readWellLocation(parseLasHeader(text, path, nullptr), path, diagnostics);
    } catch (const std::exception&) {
        return {};  // the reader says what is wrong with the header when the log is read
    }
}

WellLocation readWellLocation(const LasHeader& h, const std::string& file,
                              Diagnostics* diagnostics) {
    WellLocation w;
    w.uwi = text(h, {"UWI", "API", "APIN"});
    w.serviceCompany = text(h, {"SRVC", "LCNM", "PCON"});
    if (w.serviceCompany.empty())
        for (const LasItem& v : h.versionItems)
            if (upper(v.mnemonic) == "PROD") w.serviceCompany = v.value;

    readDepthReference(h, w, file, diagnostics);
    w.groundElevation_m = metres(h, "EGL", file, diagnostics);
    if (!std::isfinite(w.groundElevation_m)) w.groundElevation_m = metres(h, "GL", file, nullptr);

    static const char* const kProjected[][2] = {{"XWELL", "YWELL"},      {"XCOORD", "YCOORD"},
                                                {"EASTING", "NORTHING"}, {"UTMX", "UTMY"},
                                                {"EAST", "NORTH"},       {"X", "Y"}};
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
    for (const char* m : {"PROJ", "EPSG", "CRS", "HZCS"})
        if (const LasItem* i = item(h, m)) {
            w.crs = i->value;
            w.crsSource = m;
            break;
        }
    w.geodeticDatum = text(h, {"GDAT", "DATUM"});
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
    if (!w.crs.empty()) out += "crs:       " + w.crs + " (" + w.crsSource + ")\n";
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
               degrees(w.longitude_deg, w.longitudeText) +
               (w.geodeticDatum.empty() ? "" : " (" + w.geodeticDatum + ")") + "\n";
    }
    return out;
}

}  // namespace caliper3d::io
