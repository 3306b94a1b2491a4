// Wellheads from log headers, projected with PROJ. This sits in reconstruction, not io: io
// reads what the header writes (io::WellLocation, text and numbers), and putting wells in one
// field frame is geodesy, like the magnetic declination beside it (path/); io stays free of
// any geodetic library, so its readers and fuzzers link nothing but the standard library.
#include "reconstruction/load/wellhead_placement.h"

#include <proj.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>

#include "io/text.h"
#include "reconstruction/load/load_well.h"

namespace caliper3d::reconstruction {

namespace {

struct PjDelete {
    void operator()(PJ* p) const { proj_destroy(p); }
};
using Pj = std::unique_ptr<PJ, PjDelete>;

// A coordinate reference system PROJ knows, with its metres per unit of the first axis.
struct Crs {
    Pj pj;
    PJ_TYPE type = PJ_TYPE_UNKNOWN;
    double metresPerUnit = 1.0;
};

// One PROJ context a thread, with the systems made in it by name: placements run on the load
// workers and a context is not shared between threads, and making a system reads PROJ's
// database, which a field of a hundred wells would otherwise do several times a well (a
// quarter of a small well's load).
struct Context {
    PJ_CONTEXT* ctx = proj_context_create();
    std::map<std::string, Crs> systems;  // crsOf's, by the text they were made from
    Context() { proj_log_level(ctx, PJ_LOG_NONE); }
    ~Context() {
        systems.clear();  // the systems first: they belong to the context
        proj_context_destroy(ctx);
    }
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;
};

Context& threadContext() {
    thread_local Context context;
    return context;
}

// "32631", "EPSG 32631", "epsg::32631" -> "EPSG:32631"; "UTM zone 31N", "UTM 31 S" -> the
// WGS 84 UTM zone; anything else as written (PROJ reads names, WKT and PROJ strings).
std::string normalisedCrs(const std::string& written) {
    std::string t(io::trim(written));
    const std::string u = io::upper(t);
    std::string digits;
    for (char c : u)
        if (std::isdigit(static_cast<unsigned char>(c))) digits += c;
    std::string letters;
    for (char c : u)
        if (std::isalpha(static_cast<unsigned char>(c))) letters += c;
    if (!digits.empty() && (letters.empty() || letters == "EPSG")) return "EPSG:" + digits;
    if (!digits.empty() && digits.size() <= 2 &&
        (letters == "UTMZONEN" || letters == "UTMZONES" || letters == "UTMN" ||
         letters == "UTMS")) {
        const int zone = std::stoi(digits);
        if (zone >= 1 && zone <= 60)
            return "EPSG:" + std::to_string((letters.back() == 'N' ? 32600 : 32700) + zone);
    }
    return t;
}

// The WGS 84 UTM zone of a point: 6-degree zones from 180 W, north or south of the equator
// (the Norway and Svalbard exceptions are not made: the frame only needs to be one grid).
std::string utmZoneOf(double latitude_deg, double longitude_deg) {
    int zone = static_cast<int>(std::floor((longitude_deg + 180.0) / 6.0)) + 1;
    zone = zone < 1 ? 1 : zone > 60 ? 60 : zone;
    return "EPSG:" + std::to_string((latitude_deg >= 0.0 ? 32600 : 32700) + zone);
}

// The system `text` names (a null pj where PROJ knows none), made once a thread.
const Crs& crsOf(Context& c, const std::string& text) {
    auto [found, made] = c.systems.try_emplace(text);
    Crs& out = found->second;
    if (!made) return out;
    out.pj.reset(proj_create(c.ctx, text.c_str()));
    if (!out.pj) return out;
    out.type = proj_get_type(out.pj.get());
    if (out.type == PJ_TYPE_PROJECTED_CRS) {
        Pj cs(proj_crs_get_coordinate_system(c.ctx, out.pj.get()));
        double factor = 1.0;
        if (cs &&
            proj_cs_get_axis_info(c.ctx, cs.get(), 0, nullptr, nullptr, nullptr, &factor, nullptr,
                                  nullptr, nullptr) &&
            factor > 0.0)
            out.metresPerUnit = factor;
    }
    return out;
}

bool isProjected(const Crs& crs) {
    return crs.pj && crs.type == PJ_TYPE_PROJECTED_CRS;
}

bool isGeographic(const Crs& crs) {
    return crs.pj &&
           (crs.type == PJ_TYPE_GEOGRAPHIC_2D_CRS || crs.type == PJ_TYPE_GEOGRAPHIC_3D_CRS);
}

// The geographic system of a header's latitude and longitude: the datum GDAT names (by its
// common name, else as PROJ reads it), WGS 84 when none; "" when PROJ does not know it.
std::string geographicCrsOf(const io::WellLocation& w, Context& c) {
    std::string letters;
    for (char ch : io::upper(w.geodeticDatum))
        if (std::isalnum(static_cast<unsigned char>(ch))) letters += ch;
    if (letters.empty() || letters == "WGS84") return "EPSG:4326";
    static const char* const kDatums[][2] = {{"NAD83", "EPSG:4269"},      {"NAD27", "EPSG:4267"},
                                             {"ED50", "EPSG:4230"},       {"ETRS89", "EPSG:4258"},
                                             {"GDA94", "EPSG:4283"},      {"GDA2020", "EPSG:7844"},
                                             {"SIRGAS2000", "EPSG:4674"}, {"WGS72", "EPSG:4322"}};
    for (const auto& d : kDatums)
        if (letters == d[0]) return d[1];
    std::string text = normalisedCrs(w.geodeticDatum);
    return isGeographic(crsOf(c, text)) ? text : std::string();
}

// x, y in `from`'s units (longitude, latitude in degrees for a geographic system) to `to`'s
// units; false when PROJ cannot.
bool transform(Context& c, const Crs& from, const Crs& to, double x, double y, double& e,
               double& n) {
    Pj op(proj_create_crs_to_crs_from_pj(c.ctx, from.pj.get(), to.pj.get(), nullptr, nullptr));
    if (!op) return false;
    Pj normalised(proj_normalize_for_visualization(c.ctx, op.get()));  // lon, lat; E, N
    if (!normalised) return false;
    const PJ_COORD r = proj_trans(normalised.get(), PJ_FWD, proj_coord(x, y, 0.0, 0.0));
    if (!std::isfinite(r.xy.x) || !std::isfinite(r.xy.y) || r.xy.x == HUGE_VAL) return false;
    e = r.xy.x;
    n = r.xy.y;
    return true;
}

std::string format(const char* pattern, double a, double b) {
    char buf[160];
    std::snprintf(buf, sizeof buf, pattern, a, b);
    return buf;
}

std::string elevationText(const io::WellLocation& w) {
    if (!std::isfinite(w.referenceElevation_m)) return ", elevation not given";
    char buf[200];
    std::snprintf(buf, sizeof buf, ", elevation %s %.2f m (%s)",
                  w.depthReference.empty() ? "of the depth reference" : w.depthReference.c_str(),
                  w.referenceElevation_m, w.elevationSource.c_str());
    return buf;
}

}  // namespace

std::string fieldFrameOf(const io::WellLocation& w) {
    if (!w.crs.empty()) {
        Context& c = threadContext();
        std::string text = normalisedCrs(w.crs);
        // A geographic system names the datum of the latitude and longitude, not a grid.
        if (!isGeographic(crsOf(c, text))) return text;
    }
    if (std::isfinite(w.latitude_deg) && std::isfinite(w.longitude_deg))
        return utmZoneOf(w.latitude_deg, w.longitude_deg);
    if (w.hasProjected()) return kHeaderGrid;
    return {};
}

std::string describeFrame(const std::string& frame) {
    if (frame == kHeaderGrid) return "the first well's header grid (no coordinate system named)";
    Context& c = threadContext();
    const Crs& crs = crsOf(c, frame);
    if (!crs.pj) return "'" + frame + "'";
    std::string name = proj_get_name(crs.pj.get()) ? proj_get_name(crs.pj.get()) : frame;
    const std::string wgs84Utm = "WGS 84 / UTM zone ";
    if (name.rfind(wgs84Utm, 0) == 0) name = "UTM zone " + name.substr(wgs84Utm.size());
    const char* authority = proj_get_id_auth_name(crs.pj.get(), 0);
    const char* code = proj_get_id_code(crs.pj.get(), 0);
    if (authority && code) name += std::string(" (") + authority + ":" + code + ")";
    return name;
}

WellPlacement placeFromHeader(const io::WellLocation& w, const std::string& frame) {
    WellPlacement out;
    const bool geographic = std::isfinite(w.latitude_deg) && std::isfinite(w.longitude_deg);
    if (!geographic && !w.hasProjected()) {
        out.description = "the header gives no latitude/longitude or map coordinates";
        if (!w.latitudeText.empty() || !w.longitudeText.empty())
            out.description = "the header's latitude/longitude ('" + w.latitudeText + "', '" +
                              w.longitudeText + "') are not both degrees";
        return out;
    }
    if (frame.empty()) {
        out.description = "the first well's header gives no location to place it beside";
        return out;
    }
    Wellhead head;
    head.elevation_m = w.referenceElevation_m;
    if (frame == kHeaderGrid) {
        if (!w.hasProjected() || !w.crs.empty()) {
            out.description =
                "the first well's map coordinates name no coordinate system, so this well's " +
                std::string(w.hasProjected() ? "map coordinates in " + w.crs
                                             : "latitude/longitude") +
                " cannot be put beside them";
            return out;
        }
        head.easting_m = w.easting_m;
        head.northing_m = w.northing_m;
        out.wellhead = head;
        out.description = "from the header's map coordinates (" + w.projectedSource + ") in " +
                          describeFrame(frame) + ": " +
                          format("E %.2f N %.2f", w.easting_m, w.northing_m) + elevationText(w);
        return out;
    }
    Context& c = threadContext();
    const Crs& to = crsOf(c, frame);
    if (!isProjected(to)) {
        out.description = "the field frame '" + frame + "' is not a projected system PROJ knows";
        return out;
    }
    // Map coordinates in a system the header names come first (a surveyed grid position),
    // then latitude and longitude.
    std::string why;
    if (w.hasProjected() && !w.crs.empty()) {
        const std::string text = normalisedCrs(w.crs);
        const Crs& from = crsOf(c, text);
        double e = 0.0, n = 0.0;
        if (!isProjected(from)) {
            why = w.crsSource + " '" + w.crs + "' is not a projected system PROJ knows";
        } else if (transform(c, from, to, w.easting_m / from.metresPerUnit,
                             w.northing_m / from.metresPerUnit, e, n)) {
            head.easting_m = e * to.metresPerUnit;
            head.northing_m = n * to.metresPerUnit;
            out.wellhead = head;
            const std::string source = describeFrame(text);
            const std::string target = describeFrame(frame);
            out.description = "from the header's map coordinates (" + w.projectedSource + ") in " +
                              source + (source == target ? "" : ", into " + target) + ": " +
                              format("E %.2f N %.2f", head.easting_m, head.northing_m) +
                              elevationText(w);
            return out;
        } else {
            why = "PROJ cannot transform " + w.crsSource + " '" + w.crs + "' into " + frame;
        }
    }
    if (geographic) {
        const std::string datum = geographicCrsOf(w, c);
        if (datum.empty()) {
            out.description = "the datum '" + w.geodeticDatum +
                              "' of its latitude/longitude is "
                              "not one PROJ knows";
            return out;
        }
        const Crs& from = crsOf(c, datum);
        double e = 0.0, n = 0.0;
        if (!from.pj || !transform(c, from, to, w.longitude_deg, w.latitude_deg, e, n)) {
            out.description = "PROJ cannot project its latitude/longitude into " + frame;
            return out;
        }
        head.easting_m = e * to.metresPerUnit;
        head.northing_m = n * to.metresPerUnit;
        out.wellhead = head;
        out.description = "from the header's lat/long" +
                          std::string(w.geodeticDatum.empty() ? " (WGS 84: no datum named)"
                                                              : " (" + w.geodeticDatum + ")") +
                          ", " + describeFrame(frame) + ": " +
                          format("E %.2f N %.2f", head.easting_m, head.northing_m) +
                          elevationText(w);
        return out;
    }
    out.description = why.empty() ? "its map coordinates (" + w.projectedSource +
                                        ") name no coordinate system and the field is in " +
                                        describeFrame(frame)
                                  : why;
    return out;
}

double trueNorthGridAzimuth(const std::string& frame, double easting_m, double northing_m) {
    if (frame.empty() || frame == kHeaderGrid) return 0.0;
    Context& c = threadContext();
    const Crs& grid = crsOf(c, frame);
    if (!isProjected(grid)) return 0.0;
    Crs geographic;
    geographic.pj.reset(proj_crs_get_geodetic_crs(c.ctx, grid.pj.get()));
    if (!geographic.pj) return 0.0;
    geographic.type = proj_get_type(geographic.pj.get());
    // The point's latitude and longitude, then a step of 1e-4 degrees (11 m) north of it.
    const double e = easting_m / grid.metresPerUnit, n = northing_m / grid.metresPerUnit;
    double lon = 0, lat = 0, e1 = 0, n1 = 0;
    if (!transform(c, grid, geographic, e, n, lon, lat) ||
        !transform(c, geographic, grid, lon, lat + 1e-4, e1, n1))
        return 0.0;
    return std::atan2(e1 - e, n1 - n) * 180.0 / 3.14159265358979323846;
}

WellPlacement placeWell(const WellSource& source, const Wellhead& origin) {
    WellPlacement out;
    if (source.wellhead) {
        out.wellhead = *source.wellhead;
        char buf[200];
        std::snprintf(buf, sizeof buf, "by --wellhead: E %.2f N %.2f, elevation %.2f m",
                      source.wellhead->easting_m, source.wellhead->northing_m,
                      source.wellhead->elevation_m);
        out.description = buf;
        return out;
    }
    out = placeFromHeader(io::readWellLocationOf(source.path, nullptr), origin.frame);
    if (out.wellhead && !std::isfinite(out.wellhead->elevation_m)) {
        out.wellhead->elevation_m = origin.elevation_m;
        out.description += " (level with the scene origin)";
    }
    return out;
}

}  // namespace caliper3d::reconstruction
