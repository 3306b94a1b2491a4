// Wellheads from log headers, projected into one field frame with PROJ
// (reconstruction/load/wellhead_placement.h). The truth is GeographicLib's transverse
// Mercator (Krüger's series to sixth order, a different implementation from PROJ's).
#include "reconstruction/load/wellhead_placement.h"

#include <GeographicLib/UTMUPS.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "io/las_writer.h"
#include "reconstruction/load/load_well.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "test_support.h"

namespace caliper3d::reconstruction {
namespace {

// A short synthetic log written by our own LAS writer with these ~Parameter items.
std::string writeWell(const std::string& name, const std::vector<io::LasParameter>& items) {
    const auto path = test::scratch(name);
    io::LasWriteOptions las;
    las.wellName = name;
    las.parameters = items;
    io::writeLasFile(path.string(), makeSyntheticWell(syntheticProfile("circle", 10.0, 0.5)), las);
    return path.string();
}

// Easting and northing of a point in UTM zone `zone` (north), from GeographicLib.
void utm(double lat, double lon, int zone, double& e, double& n) {
    int z = 0;
    bool north = false;
    GeographicLib::UTMUPS::Forward(lat, lon, z, north, e, n, zone);
}

// A grid offset (metres east, north) turned to true north at a point whose meridian
// convergence (GeographicLib: the bearing of grid north from true north) is `gamma_deg`.
Ned trueOffset(double de, double dn, double down, double gamma_deg) {
    const double g = gamma_deg * 3.14159265358979323846 / 180.0;
    // True azimuth = grid azimuth + gamma.
    return {dn * std::cos(g) - de * std::sin(g), de * std::cos(g) + dn * std::sin(g), down};
}

WellPlacement placedFile(const std::string& path) {
    const io::WellLocation w = io::readWellLocationOf(path, nullptr);
    return placeFromHeader(w, fieldFrameOf(w));
}

TEST(WellheadPlacementTest, LatitudeLongitudeInEveryNotationLandWithinHalfAMetreOfUtm) {
    // One point, 60 30' 15.24" N, 2 27' 36.9" E (UTM zone 31N), written five ways.
    const double lat = 60.0 + 30.0 / 60.0 + 15.24 / 3600.0;
    const double lon = 2.0 + 27.0 / 60.0 + 36.9 / 3600.0;
    double e = 0, n = 0;
    utm(lat, lon, 31, e, n);
    const char* const notations[][2] = {
        {"60.50423333 N", "2.46025000 E"},
        {"60.50423333", "2.46025000"},
        {"60 30 15.24 N", "2 27 36.90 E"},
        {"60\xC2\xB0"
         "30'15.24\"N",
         "2\xC2\xB0"
         "27'36.90\"E"},
        {"N60 30 15.24", "E002 27 36.9"},
    };
    int k = 0;
    for (const auto& t : notations) {
        const std::string file = writeWell("wellhead_notation_" + std::to_string(k++) + ".las",
                                           {{"LATI", "", t[0], ""},
                                            {"LONG", "", t[1], ""},
                                            {"LMF", "", "KB", ""},
                                            {"EKB", "M", "31.5", ""}});
        const WellPlacement p = placedFile(file);
        ASSERT_TRUE(p.wellhead) << t[0] << ": " << p.description;
        EXPECT_NEAR(p.wellhead->easting_m, e, 0.5) << t[0];
        EXPECT_NEAR(p.wellhead->northing_m, n, 0.5) << t[0];
        EXPECT_DOUBLE_EQ(p.wellhead->elevation_m, 31.5);
        EXPECT_NE(p.description.find("UTM zone 31N (EPSG:32631)"), std::string::npos)
            << p.description;
        EXPECT_NE(p.description.find("elevation KB 31.50 m (EKB)"), std::string::npos)
            << p.description;
    }
}

TEST(WellheadPlacementTest, SouthernAndWesternHemispheresTakeTheirZone) {
    // Rio de Janeiro's Christ the Redeemer, 22 57' 5" S, 43 12' 39" W: UTM zone 23S.
    const double lat = -(22.0 + 57.0 / 60.0 + 5.0 / 3600.0);
    const double lon = -(43.0 + 12.0 / 60.0 + 39.0 / 3600.0);
    int zone = 0;
    bool north = true;
    double e = 0, n = 0;
    GeographicLib::UTMUPS::Forward(lat, lon, zone, north, e, n);
    ASSERT_EQ(zone, 23);
    ASSERT_FALSE(north);
    for (const auto& t :
         std::vector<std::pair<std::string, std::string>>{{"22 57 5 S", "43 12 39 W"},
                                                          {"-22.95138889", "-43.21083333"},
                                                          {"S 22 57 05", "W 43 12 39"}}) {
        const std::string file = writeWell("wellhead_south.las", {{"LAT", "", t.first, ""},
                                                                  {"LON", "", t.second, ""},
                                                                  {"DREF", "", "DF", ""},
                                                                  {"ELEV", "FT", "2300", ""}});
        const io::WellLocation w = io::readWellLocationOf(file, nullptr);
        EXPECT_EQ(fieldFrameOf(w), "EPSG:32723") << t.first;
        const WellPlacement p = placeFromHeader(w, fieldFrameOf(w));
        ASSERT_TRUE(p.wellhead) << p.description;
        EXPECT_NEAR(p.wellhead->easting_m, e, 0.5) << t.first;
        EXPECT_NEAR(p.wellhead->northing_m, n, 0.5) << t.first;
        EXPECT_NEAR(p.wellhead->elevation_m, 2300 * 0.3048, 1e-9);  // ELEV, in feet
    }
}

TEST(WellheadPlacementTest, MapCoordinatesInANamedSystemAreTransformedIntoTheField) {
    // The field: a well at 60.5 N 2.9 E (zone 31N). The second well's header gives UTM zone 32N
    // coordinates (EPSG 32632) of 60.51 N 3.05 E: they land on that point's zone 31N place.
    const std::string first = writeWell(
        "wellhead_field_first.las",
        {{"LATI", "DEG", "60.5", ""}, {"LONG", "DEG", "2.9", ""}, {"EREF", "M", "20", ""}});
    double e32 = 0, n32 = 0, e31 = 0, n31 = 0, e0 = 0, n0 = 0;
    int zone = 0;
    bool north = false;
    GeographicLib::UTMUPS::Forward(60.51, 3.05, zone, north, e32, n32, 32);
    utm(60.51, 3.05, 31, e31, n31);
    utm(60.5, 2.9, 31, e0, n0);
    char x[40], y[40];
    std::snprintf(x, sizeof x, "%.3f", e32);
    std::snprintf(y, sizeof y, "%.3f", n32);
    const std::string second = writeWell("wellhead_field_epsg.las", {{"X", "M", x, ""},
                                                                     {"Y", "M", y, ""},
                                                                     {"EPSG", "", "32632", ""},
                                                                     {"EREF", "M", "22.5", ""}});
    const WellPlacement own = placedFile(second);  // alone, in its own grid: as written
    ASSERT_TRUE(own.wellhead) << own.description;
    EXPECT_NEAR(own.wellhead->easting_m, e32, 0.001);
    const Wellhead origin = sceneOrigin({{first, {}, {}, {}}, {second, {}, {}, {}}});
    EXPECT_EQ(origin.frame, "EPSG:32631");
    EXPECT_NEAR(origin.easting_m, e0, 0.5);
    EXPECT_NEAR(origin.northing_m, n0, 0.5);
    const WellPlacement p = placeWell({second, {}, {}, {}}, origin);
    ASSERT_TRUE(p.wellhead) << p.description;
    EXPECT_NEAR(p.wellhead->easting_m, e31, 0.5);
    EXPECT_NEAR(p.wellhead->northing_m, n31, 0.5);
    EXPECT_NE(p.description.find("UTM zone 32N (EPSG:32632), into UTM zone 31N (EPSG:32631)"),
              std::string::npos)
        << p.description;
}

TEST(WellheadPlacementTest, WellsPlacedOnSeveralThreadsAtOnceLandWhereTheyLandOneByOne) {
    // Each thread keeps its own PROJ context and the systems it has made: the same wells
    // placed by four threads at once, each several times over (the second time from the
    // systems it already holds), land exactly where they land placed one by one, and every
    // place is within half a metre of GeographicLib's.
    struct Case {
        std::string file;
        double e = 0.0, n = 0.0;
    };
    std::vector<Case> cases;
    for (int k = 0; k < 6; ++k) {
        const double lat = 60.2 + 0.05 * k, lon = 2.5 + 0.1 * k;
        Case c;
        utm(lat, lon, 31, c.e, c.n);
        char la[32], lo[32];
        std::snprintf(la, sizeof la, "%.8f", lat);
        std::snprintf(lo, sizeof lo, "%.8f", lon);
        c.file = writeWell("wellhead_threads_" + std::to_string(k) + ".las",
                           {{"LATI", "DEG", la, ""}, {"LONG", "DEG", lo, ""}});
        cases.push_back(c);
    }
    std::vector<WellSource> sources;
    for (const Case& c : cases) sources.push_back({c.file, {}, {}, {}});
    const Wellhead origin = sceneOrigin(sources);
    ASSERT_EQ(origin.frame, "EPSG:32631");
    std::vector<WellPlacement> alone;
    for (const WellSource& source : sources) alone.push_back(placeWell(source, origin));
    constexpr int kThreads = 4, kRounds = 3;
    std::vector<std::vector<WellPlacement>> placed(kThreads);
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t)
        threads.emplace_back([&, t] {
            for (int round = 0; round < kRounds; ++round)
                for (std::size_t k = 0; k < sources.size(); ++k)
                    placed[static_cast<std::size_t>(t)].push_back(placeWell(
                        sources[(k + static_cast<std::size_t>(t)) % sources.size()], origin));
        });
    for (std::thread& t : threads) t.join();
    for (int t = 0; t < kThreads; ++t)
        for (std::size_t i = 0; i < placed[static_cast<std::size_t>(t)].size(); ++i) {
            const std::size_t k = (i + static_cast<std::size_t>(t)) % sources.size();
            const WellPlacement& p = placed[static_cast<std::size_t>(t)][i];
            ASSERT_TRUE(p.wellhead) << p.description;
            ASSERT_TRUE(alone[k].wellhead) << alone[k].description;
            EXPECT_EQ(p.wellhead->easting_m, alone[k].wellhead->easting_m);
            EXPECT_EQ(p.wellhead->northing_m, alone[k].wellhead->northing_m);
            EXPECT_EQ(p.description, alone[k].description);
            // In the field frame: the first well's UTM zone.
            EXPECT_NEAR(p.wellhead->easting_m, cases[k].e, 0.5);
            EXPECT_NEAR(p.wellhead->northing_m, cases[k].n, 0.5);
        }
}

TEST(WellheadPlacementTest, TwoWellsOpenedTogetherSitAtTheirRelativeOffsets) {
    const std::string a = writeWell("wellhead_pair_a.las", {{"LATI", "", "57 1 3.0 N", ""},
                                                            {"LONG", "", "111 25 8.4 W", ""},
                                                            {"LMF", "", "K.B.", ""},
                                                            {"EKB", "M", "440.7", ""}});
    const std::string b = writeWell(
        "wellhead_pair_b.las",
        {{"LATI", "", "57.0210 N", ""}, {"LONG", "", "-111.4102", ""}, {"EREF", "M", "452.2", ""}});
    double ea = 0, na = 0, eb = 0, nb = 0, gamma = 0, k = 0;
    int zone = 0;
    bool north = false;
    GeographicLib::UTMUPS::Forward(57.0175, -111.419, zone, north, ea, na, gamma, k, 12);
    utm(57.0210, -111.4102, 12, eb, nb);
    const Ned truth = trueOffset(eb - ea, nb - na, 440.7 - 452.2, gamma);
    const std::vector<WellSource> wells = {{a, {}, {}, {}}, {b, {}, {}, {}}};
    const Wellhead origin = sceneOrigin(wells);
    EXPECT_EQ(origin.frame, "EPSG:32612");
    io::Diagnostics d;
    const GeometryOptions ga = wellGeometryOptions(wells[0], LoadOptions{}, origin, &d);
    const GeometryOptions gb = wellGeometryOptions(wells[1], LoadOptions{}, origin, &d);
    EXPECT_EQ(d.warningCount, 0u);
    EXPECT_EQ(ga.wellheadOffset, Ned(0.0));
    EXPECT_NEAR(origin.trueNorthGridAzimuth_deg, -gamma, 1e-5);
    EXPECT_NEAR(gb.wellheadOffset.x, truth.x, 0.5);   // north
    EXPECT_NEAR(gb.wellheadOffset.y, truth.y, 0.5);   // east
    EXPECT_NEAR(gb.wellheadOffset.z, truth.z, 1e-9);  // b's reference is higher
    // And against the meridian arc: 0.0035 degrees of latitude at 57.019 N are 389.76 m
    // (M = a (1 - e^2) / (1 - e^2 sin^2 phi)^1.5 on WGS 84); the grid's scale factor there,
    // 0.9996, takes 0.16 m off.
    EXPECT_NEAR(gb.wellheadOffset.x, 389.76, 0.5);
    // Loaded, the second well's path starts at its head.
    const LoadedWell loaded = loadWell(wells[1], LoadOptions{}, origin);
    EXPECT_EQ(loaded.geometry->options().wellheadOffset, gb.wellheadOffset);
}

TEST(WellheadPlacementTest, WellheadOptionOverridesTheHeader) {
    const std::string a =
        writeWell("wellhead_override_a.las",
                  {{"LATI", "", "60.5", ""}, {"LONG", "", "2.9", ""}, {"EREF", "M", "20", ""}});
    const std::string b =
        writeWell("wellhead_override_b.las",
                  {{"LATI", "", "60.6", ""}, {"LONG", "", "2.9", ""}, {"EREF", "M", "30", ""}});
    // --wellhead on the first: the origin is where it says, in the frame of its header.
    const Wellhead given{600000.0, 6710000.0, 10.0, ""};
    const std::vector<WellSource> wells = {{a, {}, given, {}}, {b, {}, {}, {}}};
    const Wellhead origin = sceneOrigin(wells);
    EXPECT_EQ(origin.easting_m, 600000.0);
    EXPECT_EQ(origin.elevation_m, 10.0);
    EXPECT_EQ(origin.frame, "EPSG:32631");
    double eb = 0, nb = 0, lat = 0, lon = 0, gamma = 0, k = 0;
    utm(60.6, 2.9, 31, eb, nb);
    GeographicLib::UTMUPS::Reverse(31, true, 600000.0, 6710000.0, lat, lon, gamma, k);
    const Ned truth = trueOffset(eb - 600000.0, nb - 6710000.0, 10.0 - 30.0, gamma);
    const GeometryOptions gb = wellGeometryOptions(wells[1], LoadOptions{}, origin, nullptr);
    EXPECT_NEAR(gb.wellheadOffset.x, truth.x, 0.5);
    EXPECT_NEAR(gb.wellheadOffset.y, truth.y, 0.5);
    EXPECT_DOUBLE_EQ(gb.wellheadOffset.z, 10.0 - 30.0);
    // --wellhead on the second: its header is not read.
    const WellSource placedByOption{b, {}, Wellhead{600010.0, 6710020.0, 12.0, ""}, {}};
    const GeometryOptions g = wellGeometryOptions(placedByOption, LoadOptions{}, origin, nullptr);
    const Ned byOption = trueOffset(10.0, 20.0, -2.0, gamma);
    EXPECT_NEAR(g.wellheadOffset.x, byOption.x, 1e-3);
    EXPECT_NEAR(g.wellheadOffset.y, byOption.y, 1e-3);
    EXPECT_DOUBLE_EQ(g.wellheadOffset.z, -2.0);
    EXPECT_EQ(placeWell(placedByOption, origin).description,
              "by --wellhead: E 600010.00 N 6710020.00, elevation 12.00 m");
}

TEST(WellheadPlacementTest, AFileWithoutCoordinatesOpensAtTheOriginAndSaysWhy) {
    const std::string bare = writeWell("wellhead_bare.las", {{"LMF", "", "KB", ""}});
    const std::vector<WellSource> alone = {{bare, {}, {}, {}}};
    const Wellhead origin = sceneOrigin(alone);
    EXPECT_EQ(origin, Wellhead{});
    const WellPlacement p = placeWell(alone[0], origin);
    EXPECT_FALSE(p.wellhead);
    EXPECT_EQ(p.description, "the header gives no latitude/longitude or map coordinates");
    io::Diagnostics quiet;
    EXPECT_EQ(wellGeometryOptions(alone[0], LoadOptions{}, origin, &quiet).wellheadOffset,
              Ned(0.0));
    EXPECT_EQ(quiet.warningCount, 0u);  // alone, nothing is misplaced
    // In a field placed from headers, it is drawn at the first head, with a warning.
    const std::string placed =
        writeWell("wellhead_field_head.las", {{"LATI", "", "60.5", ""}, {"LONG", "", "2.9", ""}});
    const std::vector<WellSource> field = {{placed, {}, {}, {}}, {bare, {}, {}, {}}};
    io::Diagnostics d;
    const Wellhead fieldOrigin = sceneOrigin(field);
    EXPECT_EQ(fieldOrigin.elevation_m, 0.0);  // its elevation not given
    EXPECT_EQ(wellGeometryOptions(field[1], LoadOptions{}, fieldOrigin, &d).wellheadOffset,
              Ned(0.0));
    ASSERT_EQ(d.warningCount, 1u);
    EXPECT_NE(d.warnings[0].message.find("not placed in the field (the header gives no "
                                         "latitude/longitude or map coordinates)"),
              std::string::npos)
        << d.warnings[0].message;
    // A well after a first one without coordinates is not placed either: nothing to place it
    // beside.
    const WellPlacement after = placeWell({placed, {}, {}, {}}, origin);
    EXPECT_FALSE(after.wellhead);
    EXPECT_EQ(after.description, "the first well's header gives no location to place it beside");
}

TEST(WellheadPlacementTest, UnnamedGridsAndUnknownSystemsAreNotGuessed) {
    // Map coordinates that name no system: the first well's grid, shared by the next one's
    // unnamed coordinates but not by latitude and longitude.
    const std::string a =
        writeWell("wellhead_grid_a.las", {{"XWELL", "M", "1000", ""}, {"YWELL", "M", "2000", ""}});
    const std::string b =
        writeWell("wellhead_grid_b.las", {{"XWELL", "M", "1030", ""}, {"YWELL", "M", "1960", ""}});
    const std::string c =
        writeWell("wellhead_grid_c.las", {{"LATI", "", "60.5", ""}, {"LONG", "", "2.9", ""}});
    const Wellhead origin = sceneOrigin({{a, {}, {}, {}}});
    EXPECT_EQ(origin.frame, kHeaderGrid);
    const WellPlacement pb = placeWell({b, {}, {}, {}}, origin);
    ASSERT_TRUE(pb.wellhead);
    EXPECT_EQ(wellheadOffset(*pb.wellhead, origin), Ned(-40.0, 30.0, 0.0));
    EXPECT_FALSE(placeWell({c, {}, {}, {}}, origin).wellhead);
    // A system PROJ does not know places nothing, and says so.
    const std::string odd = writeWell(
        "wellhead_odd.las",
        {{"XWELL", "M", "1000", ""}, {"YWELL", "M", "2000", ""}, {"CRS", "", "NOT A SYSTEM", ""}});
    const WellPlacement p = placedFile(odd);
    EXPECT_FALSE(p.wellhead);
    EXPECT_NE(p.description.find("'NOT A SYSTEM'"), std::string::npos) << p.description;
}

}  // namespace
}  // namespace caliper3d::reconstruction
