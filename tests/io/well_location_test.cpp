// Depth reference elevation and well location from the LAS header
// (docs/conventions.md, "Depth reference and well location").
#include "io/well_location.h"

#include <cmath>
#include <fstream>

#include <gtest/gtest.h>

#include "io/log_reader.h"
#include "test_support.h"

using namespace caliper3d::io;

namespace {

WellLocation locationOf(const std::string& header, Diagnostics* diagnostics = nullptr) {
    const std::string text = "~Version\n VERS. 2.0 :\n WRAP. NO :\n" + header +
                             "~Curve\n DEPT.M :\n R1.IN :\n R2.IN :\n R3.IN :\n~A\n1 4 4 4\n";
    return readWellLocation(parseLasHeader(text, "h.las", nullptr), "h.las", diagnostics);
}

TEST(WellLocationTest, StarLogGivesKellyBushingElevationAndLatitudeLongitude) {
    const auto file =
        caliper3d::test::sharedData() / "real" / "1AA072209208W400_WL_0477502_STAR_FIELD.las";
    CALIPER3D_REQUIRE_DATA(file);
    const LogInfo info = describeLog(file.string(), ReadOptions{});
    const WellLocation& w = info.location;
    EXPECT_EQ(w.uwi, "1AA072209208W400");
    EXPECT_EQ(w.serviceCompany, "Baker Hughes");
    EXPECT_EQ(w.depthReference, "K.B.");
    EXPECT_DOUBLE_EQ(w.referenceElevation_m, 440.70);  // EKB, = EPD 438.50 + APD 2.20
    EXPECT_EQ(w.elevationSource, "EKB");
    EXPECT_DOUBLE_EQ(w.groundElevation_m, 438.50);
    EXPECT_DOUBLE_EQ(w.latitude_deg, 57.0175);
    EXPECT_DOUBLE_EQ(w.longitude_deg, -111.419);  // "-111.419 W": west once
    EXPECT_FALSE(w.hasProjected());
    const std::string shown = formatLogInfo(info);
    EXPECT_NE(shown.find("depth ref: K.B., elevation 440.70 m from EKB"), std::string::npos)
        << shown;
    EXPECT_NE(shown.find("lat/long:  57.017500, -111.419000"), std::string::npos) << shown;
    EXPECT_NE(shown.find("UWI:       1AA072209208W400"), std::string::npos) << shown;
}

TEST(WellLocationTest, FmiLogGivesItsReferenceElevationFromEref) {
    const auto file =
        caliper3d::test::sharedData() / "real" / "1AA063409108W400_FMI_SONIC_MAIN.las";
    CALIPER3D_REQUIRE_DATA(file);
    const LogInfo info = describeLog(file.string(), ReadOptions{});
    const WellLocation& w = info.location;
    EXPECT_EQ(w.uwi, "1AA063409108W400");
    EXPECT_EQ(w.serviceCompany, "Schlumberger");
    EXPECT_EQ(w.depthReference, "KB");
    EXPECT_DOUBLE_EQ(w.referenceElevation_m, 449.0);
    EXPECT_EQ(w.elevationSource, "EREF");
    EXPECT_DOUBLE_EQ(w.groundElevation_m, 445.0);
    EXPECT_DOUBLE_EQ(w.latitude_deg, 56.9345);
    EXPECT_DOUBLE_EQ(w.longitude_deg, -111.2054);
    EXPECT_NE(formatLogInfo(info).find("depth ref: KB, elevation 449.00 m from EREF"),
              std::string::npos);
}

TEST(WellLocationTest, ElevationFollowsTheNamedReferenceThenPermanentDatumPlusApd) {
    // LMF names the drill floor: EDF, not EKB.
    EXPECT_DOUBLE_EQ(
        locationOf("~Parameter\n LMF. DF :\n EKB.M 101.0 :\n EDF.M 100.5 :\n").referenceElevation_m,
        100.5);
    // No named elevation: the permanent datum plus the reference's height above it, in feet.
    const WellLocation feet = locationOf("~Parameter\n LMF. KB :\n EPD.F 1000 :\n APD.F 20 :\n");
    EXPECT_NEAR(feet.referenceElevation_m, 1020 * 0.3048, 1e-9);
    EXPECT_EQ(feet.elevationSource, "EPD + APD");
    // Nothing says where the depths are measured from: no elevation.
    EXPECT_TRUE(std::isnan(locationOf("~Parameter\n EKB.M 101.0 :\n").referenceElevation_m));
    // A named elevation that disagrees with EPD + APD is used, and warned about.
    Diagnostics d;
    const WellLocation odd =
        locationOf("~Parameter\n LMF. KB :\n EKB.M 101.0 :\n EPD.M 90 :\n APD.M 10 :\n", &d);
    EXPECT_DOUBLE_EQ(odd.referenceElevation_m, 101.0);
    ASSERT_EQ(d.warningCount, 1u);
    EXPECT_NE(d.warnings[0].message.find("differs from EPD + APD = 100.00 m"), std::string::npos);
}

TEST(WellLocationTest, ProjectedCoordinatesNeedALengthUnit) {
    const WellLocation w = locationOf("~Well\n XWELL.M 512300.5 :\n YWELL.M 6801200.25 :\n");
    EXPECT_TRUE(w.hasProjected());
    EXPECT_DOUBLE_EQ(w.easting_m, 512300.5);
    EXPECT_DOUBLE_EQ(w.northing_m, 6801200.25);
    EXPECT_EQ(w.projectedSource, "XWELL, YWELL");
    // X and Y in degrees are geographic, not a map grid.
    Diagnostics d;
    EXPECT_FALSE(locationOf("~Well\n X.DEG -111.4 :\n Y.DEG 57.0 :\n", &d).hasProjected());
    EXPECT_EQ(d.warningCount, 2u);
}

TEST(WellLocationTest, GeographicDegreesReadHemispheresAndMinutes) {
    EXPECT_DOUBLE_EQ(parseGeographicDegrees("57.0175 N"), 57.0175);
    EXPECT_DOUBLE_EQ(parseGeographicDegrees("56.934500 degrees"), 56.9345);
    EXPECT_DOUBLE_EQ(parseGeographicDegrees("111.419 W"), -111.419);
    EXPECT_DOUBLE_EQ(parseGeographicDegrees("-111.419 W"), -111.419);
    EXPECT_DOUBLE_EQ(parseGeographicDegrees("57 1 3.0 N"), 57.0 + 1.0 / 60.0 + 3.0 / 3600.0);
    EXPECT_DOUBLE_EQ(parseGeographicDegrees("33\xC2\xB0 30' S"), -33.5);
    EXPECT_TRUE(std::isnan(parseGeographicDegrees("unknown")));
}

TEST(WellLocationTest, GeographicDegreesReadSignsQuotesAndHemisphereLetters) {
    const double dms = 60.0 + 30.0 / 60.0 + 15.24 / 3600.0;
    EXPECT_DOUBLE_EQ(parseGeographicDegrees("60\xC2\xB0"
                                            "30'15.24\"N"),
                     dms);
    EXPECT_DOUBLE_EQ(parseGeographicDegrees("60\xC2\xBA 30\xE2\x80\xB2 15.24\xE2\x80\xB3 N"), dms);
    EXPECT_DOUBLE_EQ(parseGeographicDegrees("N60 30 15.24"), dms);
    EXPECT_DOUBLE_EQ(parseGeographicDegrees("S 60 30 15.24"), -dms);
    EXPECT_DOUBLE_EQ(parseGeographicDegrees("2.5W"), -2.5);
    EXPECT_DOUBLE_EQ(parseGeographicDegrees("E002 27 36.9"), 2.0 + 27.0 / 60.0 + 36.9 / 3600.0);
    EXPECT_DOUBLE_EQ(parseGeographicDegrees("-43.2108"), -43.2108);
    // Minutes and seconds are under 60 and unsigned; one hemisphere; at most three numbers.
    EXPECT_TRUE(std::isnan(parseGeographicDegrees("60 75 0 N")));
    EXPECT_TRUE(std::isnan(parseGeographicDegrees("60 -5 N")));
    EXPECT_TRUE(std::isnan(parseGeographicDegrees("N 60 S")));
    EXPECT_TRUE(std::isnan(parseGeographicDegrees("60 1 2 3")));
}

TEST(WellLocationTest, ReadsTheCoordinateSystemDatumEastNorthAndElev) {
    const WellLocation w = locationOf(
        "~Well\n EAST.M 431234.5 :\n NORTH.M 6712345.25 :\n~Parameter\n EPSG. 32631 :\n"
        " GDAT. WGS84 :\n DREF. DF :\n ELEV.FT 100 :\n");
    EXPECT_DOUBLE_EQ(w.easting_m, 431234.5);
    EXPECT_DOUBLE_EQ(w.northing_m, 6712345.25);
    EXPECT_EQ(w.projectedSource, "EAST, NORTH");
    EXPECT_EQ(w.crs, "32631");
    EXPECT_EQ(w.crsSource, "EPSG");
    EXPECT_EQ(w.geodeticDatum, "WGS84");
    EXPECT_DOUBLE_EQ(w.referenceElevation_m, 30.48);  // ELEV, the elevation of DREF's DF
    EXPECT_EQ(w.elevationSource, "ELEV");
    // The item named as the reference: KB 25 m.
    const WellLocation kb = locationOf("~Parameter\n LMF. KB :\n KB.M 25.0 :\n");
    EXPECT_DOUBLE_EQ(kb.referenceElevation_m, 25.0);
    EXPECT_EQ(kb.elevationSource, "KB");
    // ELEV with the permanent datum named and no other reference.
    const WellLocation pdat = locationOf("~Parameter\n PDAT. GL :\n ELEV.M 12.5 :\n");
    EXPECT_DOUBLE_EQ(pdat.referenceElevation_m, 12.5);
    EXPECT_EQ(pdat.depthReference, "GL");
    // ELEV with nothing named is not taken to be the reference's.
    EXPECT_TRUE(std::isnan(locationOf("~Parameter\n ELEV.M 12.5 :\n").referenceElevation_m));
    const std::string shown = formatWellLocation(w);
    EXPECT_NE(shown.find("crs:       32631 (EPSG)"), std::string::npos) << shown;
}

TEST(WellLocationTest, HeaderAloneIsReadFromTheFile) {
    const auto path = caliper3d::test::scratch("header_only.las");
    {
        std::ofstream out(path);
        out << "~Version\n VERS. 2.0 :\n WRAP. NO :\n~Well\n LATI. 57 1 3.0 N :\n"
               " LONG. 111 25 8.4 W :\n~Curve\n DEPT.M :\n R1.IN :\n~A\n1 4\n2 4\n";
    }
    const WellLocation w = readWellLocationOf(path.string(), nullptr);
    EXPECT_DOUBLE_EQ(w.latitude_deg, 57.0175);
    EXPECT_NEAR(w.longitude_deg, -111.419, 1e-12);
    // LAS 3.0: the header ends at ~Log_Data.
    const auto las3 = caliper3d::test::scratch("header_only_3.las");
    {
        std::ofstream out(las3);
        out << "~Version\n VERS. 3.0 :\n WRAP. NO :\n DLM. COMMA :\n~Well\n LATI. 34.5 :\n"
               " LONG. -102.25 :\n GDAT. NAD83 :\n~Log_Definition\n DEPT.M :\n R1.IN :\n"
               "~Log_Data | Log_Definition\n1,4\n2,4\n";
    }
    const WellLocation w3 = readWellLocationOf(las3.string(), nullptr);
    EXPECT_DOUBLE_EQ(w3.latitude_deg, 34.5);
    EXPECT_DOUBLE_EQ(w3.longitude_deg, -102.25);
    EXPECT_EQ(w3.geodeticDatum, "NAD83");
    // Not LAS, or not there: nothing.
    const auto text = caliper3d::test::scratch("header_only.csv");
    { std::ofstream(text) << "DEPT,R1\n1,4\n~A\n"; }
    EXPECT_TRUE(readWellLocationOf(text.string(), nullptr).empty());
    EXPECT_TRUE(readWellLocationOf(path.string() + ".none", nullptr).empty());
}

}  // namespace
