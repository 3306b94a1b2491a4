#include "support/dlis_fixtures.h"

#include <cmath>
#include <stdexcept>

namespace caliper3d::test::dlis {

namespace {

constexpr double kPi = 3.14159265358979323846;
double rad(double deg) {
    return deg * kPi / 180.0;
}
double wrap360(double deg) {
    const double w = std::fmod(deg, 360.0);
    return w < 0 ? w + 360.0 : w;
}

}  // namespace

double ellipseRadius(double a, double b, double fromMajor_deg) {
    const double c = std::cos(rad(fromMajor_deg)), s = std::sin(rad(fromMajor_deg));
    return a * b / std::sqrt(b * b * c * c + a * a * s * s);
}

double offsetCircleRadius(double r, double offset, double offsetAngle_deg, double angle_deg) {
    // |t u - c| = r along the unit direction u: t = u.c + sqrt((u.c)^2 - |c|^2 + r^2).
    const double uc = offset * std::cos(rad(angle_deg - offsetAngle_deg));
    return uc + std::sqrt(uc * uc - offset * offset + r * r);
}

// ---- (a) six arms ----
double SixArmShape::depth_m(std::size_t row) const {
    if (depthUnits == "0.1 in") return indexValue(row) * 0.1 * kInch_m;
    if (depthUnits == "ft") return indexValue(row) * 12.0 * kInch_m;
    return indexValue(row);
}

double SixArmShape::indexValue(std::size_t row) const {
    const double md = top_m + step_m * static_cast<double>(row);
    if (depthUnits == "0.1 in") return std::round(md / (0.1 * kInch_m));
    if (depthUnits == "ft") return md / (12.0 * kInch_m);
    if (depthUnits == "m") return md;
    throw std::invalid_argument("six-arm fixture: depth units " + depthUnits);
}

double SixArmShape::p1az_deg(std::size_t row) const {
    return wrap360(p1az0_deg + p1azPerRow_deg * static_cast<double>(row));
}

double SixArmShape::radius_mm(std::size_t row, int arm) const {
    // Arm k points (k - 1) 60 degrees clockwise from arm 1 (docs/conventions.md, "Arms").
    const double azimuth = p1az_deg(row) + 60.0 * (arm - 1);
    return ellipseRadius(major_mm / 2.0, minor_mm / 2.0, azimuth - majorAzimuth_deg);
}

FrameSpec sixArmFrame(const SixArmShape& s, int radiusCode) {
    FrameSpec f;
    f.name = "60B";
    const bool tenths = s.depthUnits == "0.1 in";
    f.channels.push_back({"TDEP", s.depthUnits, "Depth", tenths ? FSINGL : FDOUBL, {1}});
    for (int k = 1; k <= 6; ++k)
        f.channels.push_back({"RAD" + std::to_string(k),
                              "in",
                              "Caliper radius, arm " + std::to_string(k),
                              radiusCode,
                              {1}});
    f.channels.push_back({"P1AZ", "deg", "Pad 1 azimuth", FSINGL, {1}});
    f.channels.push_back({"DEVI", "deg", "Hole deviation", FSINGL, {1}});
    f.channels.push_back({"HAZI", "deg", "Hole azimuth", FSINGL, {1}});
    for (std::size_t row = 0; row < s.rows; ++row) {
        std::vector<double> v = {s.indexValue(row)};
        for (int k = 1; k <= 6; ++k) v.push_back(s.radius_mm(row, k) / 25.4);
        v.push_back(s.p1az_deg(row));
        v.push_back(s.devi_deg);
        v.push_back(s.hazi_deg);
        f.addRow(v);
    }
    return f;
}

LogicalFileSpec sixArmLog(const SixArmShape& s) {
    LogicalFileSpec f;
    f.fileId = "SIX ARM CALIPER";
    f.wellName = s.wellName;
    f.fieldName = "TEST FIELD";
    f.company = "CALIPER3D";
    f.parameters.push_back({"BS", "in", "Bit Size", {s.bitSize_in}, {}, FSINGL});
    f.frames.push_back(sixArmFrame(s));
    return f;
}

// ---- (b) forty fingers ----
double FingerShape::depth_m(std::size_t row) const {
    return top_m + step_m * static_cast<double>(rows - 1 - row);
}

double FingerShape::radius_mm(int finger) const {
    return offsetCircleRadius(diameter_mm / 2.0, offset_mm, offsetAngle_deg, 9.0 * (finger - 1));
}

LogicalFileSpec fingerLog(const FingerShape& s) {
    LogicalFileSpec f;
    f.fileId = "MULTIFINGER";
    f.origin = 200;  // a two-byte UVARI in every name
    f.wellName = s.wellName;
    f.parameters.push_back({"BS", "mm", "Bit Size", {215.9}, {}, FDOUBL});
    FrameSpec frame;
    frame.name = "UP";
    frame.direction = "DECREASING";
    frame.channels.push_back({"DEPT", "m", "Depth", FDOUBL, {1}});
    frame.channels.push_back({"FING", "mm", "Finger radii", FSINGL, {40}});
    frame.channels.push_back({"GR", "gAPI", "Gamma ray", SNORM, {1}});
    for (std::size_t row = 0; row < s.rows; ++row) {
        std::vector<double> v = {s.depth_m(row)};
        for (int k = 1; k <= 40; ++k) v.push_back(s.radius_mm(k));
        v.push_back(static_cast<double>(row % 150));
        frame.addRow(v);
    }
    f.frames.push_back(std::move(frame));
    return f;
}

// ---- (c) pad imager ----
double PadImagerShape::depth_m(std::size_t row) const {
    return (top_ft + step_ft * static_cast<double>(row)) * 12.0 * kInch_m;
}

double PadImagerShape::p1az_deg(std::size_t row) const {
    return wrap360(p1az0_deg + p1azPerRow_deg * static_cast<double>(row));
}

double PadImagerShape::diameter_mm(std::size_t row, int pair) const {
    // Pad k of eight points (k - 1) 45 degrees clockwise from pad 1; pair k joins pads k and
    // k + 4, so its diameter is twice the centred ellipse's radius that way.
    const double azimuth = p1az_deg(row) + 45.0 * (pair - 1);
    return 2.0 * ellipseRadius(major_mm / 2.0, minor_mm / 2.0, azimuth - majorAzimuth_deg);
}

LogicalFileSpec padImagerLog(const PadImagerShape& s) {
    LogicalFileSpec f;
    f.fileId = "CMI IMAGER";
    f.wellName = s.wellName;
    f.company = "CALIPER3D";
    f.parameters.push_back({"BS", "in", "Bit Size", {8.5}, {}, FDOUBL});
    FrameSpec frame;
    frame.name = "CMI";
    frame.channels.push_back({"DEPTH", "ft", "Depth", FDOUBL, {1}});
    for (const char* pair : {"DI15", "DI26", "DI37", "DI48"})
        frame.channels.push_back(
            {pair, "in", std::string("Imager Diameter ") + pair[2] + " - " + pair[3], FSINGL, {1}});
    frame.channels.push_back({"P1AZ", "deg", "Pad 1 azimuth", FDOUBL, {1}});
    frame.channels.push_back({"DEVI", "deg", "Deviation", FSINGL, {1}});
    frame.channels.push_back({"HAZI", "deg", "Hole azimuth", FSINGL, {1}});
    frame.channels.push_back({"IMG", "mS/m", "Pad image", SNORM, {8, 24}});
    for (std::size_t row = 0; row < s.rows; ++row) {
        std::vector<double> v = {s.top_ft + s.step_ft * static_cast<double>(row)};
        for (int k = 1; k <= 4; ++k) v.push_back(s.diameter_mm(row, k) / 25.4);
        v.push_back(s.p1az_deg(row));
        v.push_back(2.0);
        v.push_back(75.0);
        for (int i = 0; i < 8 * 24; ++i) v.push_back(static_cast<double>((i * 7 + row) % 1000));
        frame.addRow(v);
    }
    f.frames.push_back(std::move(frame));
    return f;
}

// ---- (d) runs ----
std::vector<LogicalFileSpec> twoRunLogs(const SixArmShape& first, const SixArmShape& second) {
    LogicalFileSpec gamma;
    gamma.fileId = "GAMMA RAY";
    gamma.wellName = first.wellName;
    FrameSpec g;
    g.name = "GR";
    g.channels.push_back({"DEPT", "m", "Depth", FDOUBL, {1}});
    g.channels.push_back({"GR", "gAPI", "Gamma ray", FSINGL, {1}});
    for (int row = 0; row < 50; ++row) g.addRow({200.0 + 0.5 * row, 40.0 + row});
    gamma.frames.push_back(std::move(g));
    LogicalFileSpec run1 = sixArmLog(first), run2 = sixArmLog(second);
    run1.fileId = "RUN 1";
    run2.fileId = "RUN 2";
    run2.runNumber = 2;
    return {gamma, run1, run2};
}

// ---- (e) parameters ----
LogicalFileSpec sixArmLogWithParameters(const SixArmShape& s, const WellParameters& p) {
    LogicalFileSpec f = sixArmLog(s);
    f.parameters.push_back({"CSGL", "m", "Casing shoe, logger", {p.casingShoe_m}, {}, FDOUBL});
    f.parameters.push_back({"CSGS", "in", "Casing size", {p.casingSize_in}, {}, FSINGL});
    f.parameters.push_back(
        {"CSGW", "lbm/ft", "Casing weight", {p.casingWeight_lbPerFt}, {}, FSINGL});
    f.parameters.push_back({"CSGT", "", "Casing type", {}, {p.casingType}, ASCII});
    f.parameters.push_back(
        {"MDEC", "deg", "Magnetic declination", {p.declination_deg}, {}, FDOUBL});
    f.parameters.push_back({"LATI", "deg", "Latitude", {p.latitude_deg}, {}, FDOUBL});
    f.parameters.push_back({"LONG", "deg", "Longitude", {p.longitude_deg}, {}, FDOUBL});
    f.parameters.push_back({"LMF", "", "Logging measured from", {}, {"KB"}, ASCII});
    f.parameters.push_back(
        {"EKB", "m", "Elevation of kelly bushing", {p.kellyBushing_m}, {}, FDOUBL});
    return f;
}

// ---- every code ----
std::string codeName(int code) {
    static const char* names[] = {"",       "FSHORT", "FSINGL", "FSING1", "FSING2",
                                  "ISINGL", "VSINGL", "FDOUBL", "FDOUB1", "FDOUB2",
                                  "CSINGL", "CDOUBL", "SSHORT", "SNORM",  "SLONG",
                                  "USHORT", "UNORM",  "ULONG",  "UVARI"};
    return code >= 1 && code <= 18 ? names[code] : "code" + std::to_string(code);
}

double codeValue(int code, std::size_t row) {
    const double r = static_cast<double>(row % 97);
    switch (code) {
        case FSHORT:
            return (r - 48.0) * 0.25;  // |M| < 2048 at exponents up to 4: exact
        case SSHORT:
            return r - 48.0;
        case USHORT:
            return r * 2.0;
        case SNORM:
            return (r - 48.0) * 500.0;
        case UNORM:
            return r * 600.0;
        case SLONG:
            return (r - 48.0) * 1.0e7;
        case ULONG:
            return r * 4.0e7;
        case UVARI:
            return r * r * r * 30.0;  // 1, 2 and 4 bytes
        default:                      // the floats: binary fractions every float code holds exactly
            return (r - 48.0) * 1.375 + (r > 90 ? 1.0e6 : 0.0);
    }
}

LogicalFileSpec everyCodeLog(const SixArmShape& s) {
    LogicalFileSpec f = sixArmLog(s);
    FrameSpec& frame = f.frames.front();
    FrameSpec out;
    out.name = frame.name;
    out.channels = frame.channels;
    for (int code = 1; code <= 18; ++code)
        out.channels.push_back({"V_" + codeName(code), "", codeName(code) + " values", code, {1}});
    const std::size_t w = frame.width();
    for (std::size_t row = 0; row < frame.frames(); ++row) {
        std::vector<double> v(frame.values.begin() + static_cast<std::ptrdiff_t>(row * w),
                              frame.values.begin() + static_cast<std::ptrdiff_t>((row + 1) * w));
        for (int code = 1; code <= 18; ++code) v.push_back(codeValue(code, row));
        out.addRow(v);
    }
    frame = std::move(out);
    return f;
}

}  // namespace caliper3d::test::dlis
