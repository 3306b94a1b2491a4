#pragma once

// DLIS logs with known answers, built from analytic hole shapes by the test writer
// (support/dlis_writer.h). Every expected value is computed from the same shape the
// fixture is written from, in the units the reader must convert from.

#include <cstddef>
#include <string>
#include <vector>

#include "support/dlis_writer.h"

namespace caliper3d::test::dlis {

inline constexpr double kInch_m = 0.0254;

// The distance from the tool axis to an ellipse centred on it, along a direction
// `fromMajor_deg` from its major axis (semi-axes a >= b).
double ellipseRadius(double a, double b, double fromMajor_deg);
// The distance from the tool axis to a circle of radius `r` whose centre lies `offset` away
// at angle `offsetAngle_deg`, along a direction at `angle_deg` (same frame).
double offsetCircleRadius(double r, double offset, double offsetAngle_deg, double angle_deg);

// (a) A six-arm caliper (RAD1..RAD6 in inches, Schlumberger-style orientation P1AZ, DEVI,
// HAZI in degrees) in an elliptical hole centred on the tool, whose major axis points to
// `majorAzimuth_deg`; the index TDEP in `depthUnits` ("0.1 in": whole tenths of an inch as
// FSINGL, "m" or "ft": FDOUBL); bit size as parameter BS (inches).
struct SixArmShape {
    double top_m = 1000.0;
    std::size_t rows = 600;
    double step_m = 0.1524;  // 6 in
    std::string depthUnits = "0.1 in";
    double bitSize_in = 8.5;
    double major_mm = 245.9, minor_mm = 217.9, majorAzimuth_deg = 60.0;
    double p1az0_deg = 10.0, p1azPerRow_deg = 0.7;  // tool rotation
    double devi_deg = 1.5, hazi_deg = 30.0;
    std::string wellName = "DLIS SIX ARM 1";

    // What the reader must return, row by row (depth in metres, radii in millimetres).
    double depth_m(std::size_t row) const;
    double indexValue(std::size_t row) const;  // in depthUnits
    double p1az_deg(std::size_t row) const;
    double radius_mm(std::size_t row, int arm) const;  // arm 1..6
};
FrameSpec sixArmFrame(const SixArmShape& shape, int radiusCode = FSINGL);
LogicalFileSpec sixArmLog(const SixArmShape& shape);

// (b) A 40-finger caliper: one array channel FING of dimension 40 (mm), a circle of
// `diameter_mm` whose centre lies `offset_mm` from the tool axis towards finger
// `offsetAngle_deg` (clockwise from finger 1); the index DEPT in metres, logged upwards
// (DECREASING), no orientation.
struct FingerShape {
    double top_m = 500.0;
    std::size_t rows = 400;
    double step_m = 0.05;
    double diameter_mm = 177.0;
    double offset_mm = 6.0, offsetAngle_deg = 100.0;
    std::string wellName = "DLIS FORTY FINGER";

    double depth_m(std::size_t row) const;  // file order: deepest first
    double radius_mm(int finger) const;     // the same every row
};
LogicalFileSpec fingerLog(const FingerShape& shape);

// (c) An eight-pad imager (Weatherford CMI style): pad-pair diameters DI15 DI26 DI37 DI48
// (inches) of an ellipse centred on the tool, pad-1 azimuth P1AZ, DEVI, HAZI, and an image
// array IMG of dimension {8, 24} the reader lists but does not read; index DEPTH in feet.
struct PadImagerShape {
    double top_ft = 6000.0;
    std::size_t rows = 300;
    double step_ft = 0.5;
    double major_mm = 230.0, minor_mm = 212.0, majorAzimuth_deg = 135.0;
    double p1az0_deg = 200.0, p1azPerRow_deg = -0.3;
    std::string wellName = "DLIS PAD IMAGER";

    double depth_m(std::size_t row) const;
    double p1az_deg(std::size_t row) const;
    double diameter_mm(std::size_t row, int pair) const;  // pair 1..4: pads k and k + 4
};
LogicalFileSpec padImagerLog(const PadImagerShape& shape);

// (d) Three logical files: a gamma-ray log without calipers, then two six-arm runs over
// different depths (run 1: `first`, run 2: `second`).
std::vector<LogicalFileSpec> twoRunLogs(const SixArmShape& first, const SixArmShape& second);

// (e) A six-arm log whose parameters give the casing (CSGL, CSGS, CSGW, CSGT), the magnetic
// declination (MDEC) and the location (LATI, LONG; depths from LMF = KB at EKB).
struct WellParameters {
    double casingShoe_m = 1020.0;
    double casingSize_in = 9.625;
    double casingWeight_lbPerFt = 47.0;
    std::string casingType = "INTERMEDIATE";
    double declination_deg = 1.5;
    double latitude_deg = 57.25, longitude_deg = 2.125;
    double kellyBushing_m = 25.0;
};
LogicalFileSpec sixArmLogWithParameters(const SixArmShape& shape, const WellParameters& p);

// Every numeric code 1..18 as one channel each (V_FSHORT, V_FSINGL, ...) beside a
// six-arm log, holding `codeValue(code, row)` (values each code holds exactly).
LogicalFileSpec everyCodeLog(const SixArmShape& shape);
double codeValue(int code, std::size_t row);
std::string codeName(int code);

}  // namespace caliper3d::test::dlis
