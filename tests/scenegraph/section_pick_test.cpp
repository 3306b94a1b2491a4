// Picking the wall: a known ray on a known synthetic well gives its section, MD and angle and
// the report's row for that section, at every level of detail SoLOD draws there.
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoRayPickAction.h>
#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoSeparator.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec2.hpp>

#include "coin_fixture.h"
#include "io/section_table.h"
#include "reconstruction/analysis/report_writer.h"
#include "reconstruction/analysis/well_analysis.h"
#include "reconstruction/mesh/lod_levels.h"
#include "reconstruction/mesh/lod_tree.h"
#include "reconstruction/section/section_frame.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "reconstruction/well_geometry.h"
#include "scenegraph/node_ref.h"
#include "scenegraph/section_pick.h"
#include "scenegraph/segment_node_builder.h"
#include "scenegraph/well_scene.h"

using namespace caliper3d;

namespace {

// The "ellipse" profile: vertical, a 245.9 x 217.9 mm ellipse with its major axis at azimuth
// 60 around a centred tool, six arms turning 2 degrees per metre; 10 m every 2.5 mm.
constexpr double kLength_m = 10.0;
constexpr double kStep_m = 0.0025;
constexpr double kDmax_mm = 245.9;
constexpr double kDmin_mm = 217.9;
constexpr double kMajorAzimuth_deg = 60.0;

io::SectionTable ellipseWell() {
    return reconstruction::makeSyntheticWell(
        reconstruction::syntheticProfile("ellipse", kLength_m, kStep_m));
}

// Signed difference of two angles, degrees, in (-180, 180].
double angleBetween(double a, double b) {
    double d = std::fmod(a - b, 360.0);
    if (d > 180.0) d -= 360.0;
    if (d <= -180.0) d += 360.0;
    return d;
}

SbVec3f toSb(const glm::dvec3& v) {
    return SbVec3f(static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z));
}

// Scene direction of a horizontal azimuth (the scene is x east, y up, z south).
SbVec3f horizontal(double azimuth_deg) {
    return toSb(reconstruction::toScene(
        {std::cos(glm::radians(azimuth_deg)), std::sin(glm::radians(azimuth_deg)), 0.0}));
}

std::map<std::string, std::string> keyValues(const std::string& text) {
    std::map<std::string, std::string> out;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        const std::size_t eq = line.find('=');
        if (eq != std::string::npos) out[line.substr(0, eq)] = line.substr(eq + 1);
    }
    return out;
}

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> out;
    std::stringstream in(line);
    for (std::string field; std::getline(in, field, ',');) out.push_back(field);
    if (!line.empty() && line.back() == ',') out.emplace_back();
    return out;
}

class SectionPickTest : public CoinTest {
protected:
    void build(io::SectionTable table, double exaggeration = 1.0) {
        reconstruction::GeometryOptions options;
        options.radialExaggeration = exaggeration;
        m_geometry = std::make_shared<const reconstruction::WellGeometry>(
            std::make_shared<const io::SectionTable>(std::move(table)), options);
        m_analysis = reconstruction::analyseWell(*m_geometry, {});
        m_scene = std::make_unique<scenegraph::WellScene>();
        m_scene->buildAllLevels(*m_geometry);
        m_root = scenegraph::makeRef(new SoSeparator);
        m_camera = new SoPerspectiveCamera;
        m_camera->nearDistance = 0.01f;  // as the render roots set it
        m_camera->farDistance = 500.0f;
        m_root->addChild(m_camera);
        m_root->addChild(m_scene->root());
    }

    std::vector<scenegraph::PickableWell> wells() const {
        return {{m_scene.get(), m_geometry.get(), &m_analysis, "ellipse"}};
    }

    // The camera, whose distance chooses every SoLOD's level, at `eye` looking down the
    // hole, north up.
    void placeEye(const SbVec3f& eye) {
        m_camera->position = eye;
        m_camera->pointAt(eye + SbVec3f(0.0f, -10.0f, 0.0f), SbVec3f(0.0f, 0.0f, -1.0f));
    }

    // The tool axis at measured depth md_m (the well is vertical from the wellhead).
    static SbVec3f axisAt(double md_m) { return SbVec3f(0.0f, static_cast<float>(-md_m), 0.0f); }

    // Shoots from the axis at md_m outward at `azimuth_deg`, level with the section.
    std::optional<scenegraph::SectionPick> shoot(double md_m, double azimuth_deg) const {
        return scenegraph::pickSection(m_root.get(), SbViewportRegion(800, 600), axisAt(md_m),
                                       horizontal(azimuth_deg), wells());
    }

    // What every pick of the ellipse well from its axis must give: the section at that MD,
    // the angle shot at, the true radius there, and the report's row for that section.
    void expectKnownAnswer(const scenegraph::SectionPick& pick, double md_m,
                           double azimuth_deg) const {
        const std::vector<double>& depth = m_geometry->table().depth_m;
        ASSERT_LT(pick.wall.row, depth.size());
        EXPECT_EQ(pick.section.md_m, depth[pick.wall.row]);
        EXPECT_LE(std::abs(pick.section.md_m - md_m), kStep_m) << pick.wall.row;
        EXPECT_EQ(pick.segment, static_cast<std::size_t>(md_m));  // 1 m segments
        // In a vertical hole the high side is north: both angles are the azimuth shot at. The
        // ray leaves the axis, so the direction is exact, whatever polygon it meets.
        EXPECT_NEAR(angleBetween(pick.wall.fromHighSide_deg, azimuth_deg), 0.0, 0.05);
        EXPECT_NEAR(angleBetween(pick.wall.azimuth_deg, azimuth_deg), 0.0, 0.05);
        // The true section there: the spline through six pads stays within 2 % of the ellipse
        // (docs/conventions.md, "Section shape").
        const double ellipse =
            reconstruction::ellipseRadius_mm(kDmax_mm, kDmin_mm, azimuth_deg - kMajorAzimuth_deg);
        EXPECT_NEAR(pick.wall.radius_mm, ellipse, 0.02 * ellipse);
        // The report's analysis of that section, field by field and as the report writes it.
        const reconstruction::SectionResult& r = m_analysis.sections[pick.wall.row];
        EXPECT_EQ(pick.section.equivalentDiameter_mm, r.equivalentDiameter_mm);
        EXPECT_EQ(pick.section.dmax_mm, r.dmax_mm);
        EXPECT_EQ(pick.section.dmin_mm, r.dmin_mm);
        EXPECT_EQ(pick.section.majorAzimuth_deg, r.majorAzimuth_deg);
        EXPECT_EQ(pick.section.cls, r.cls);
        EXPECT_NEAR(pick.section.dmax_mm, kDmax_mm, 2.0);
        EXPECT_NEAR(pick.section.dmin_mm, kDmin_mm, 2.0);
        EXPECT_NEAR(pick.section.majorAzimuth_deg, kMajorAzimuth_deg, 2.0);
        EXPECT_NEAR(pick.section.bit_mm, 215.9, 1e-9);
        expectReportRow(pick);
    }

    // formatSectionPick's report columns are the report CSV's line for that section.
    void expectReportRow(const scenegraph::SectionPick& pick) const {
        std::ostringstream csv;
        reconstruction::writeSectionReport(csv, m_analysis);
        std::istringstream lines(csv.str());
        std::string header, row;
        std::getline(lines, header);
        for (std::size_t i = 0; i <= pick.wall.row; ++i) std::getline(lines, row);
        const std::vector<std::string> names = split(header), values = split(row);
        ASSERT_EQ(names.size(), values.size());
        const auto printed = keyValues(scenegraph::formatSectionPick(pick));
        for (std::size_t k = 0; k < names.size(); ++k) {
            ASSERT_EQ(printed.count(names[k]), 1u) << names[k];
            EXPECT_EQ(printed.at(names[k]), values[k]) << names[k];
        }
        EXPECT_EQ(printed.at("section"), std::to_string(pick.wall.row));
        EXPECT_EQ(printed.at("well_name"), "ellipse");
    }

    std::shared_ptr<const reconstruction::WellGeometry> m_geometry;
    reconstruction::WellAnalysis m_analysis;
    std::unique_ptr<scenegraph::WellScene> m_scene;
    scenegraph::NodeRef<SoSeparator> m_root;
    SoPerspectiveCamera* m_camera = nullptr;
};

}  // namespace

TEST_F(SectionPickTest, RayFromTheAxisFindsItsSectionAngleAndReportRowAtEveryLevel) {
    build(ellipseWell());
    const double md = 5.3012;  // between two sections, in segment 5
    const std::size_t segment = 5;
    const reconstruction::SegmentMesh mesh = m_geometry->buildSegment(segment);
    const scenegraph::LodView view;  // the scene's own
    const std::vector<float> switches = scenegraph::lodSwitchDistances(mesh, view);
    ASSERT_EQ(switches.size(), 4u);
    ASSERT_EQ(mesh.parts.size(), 4u);
    const auto row = static_cast<std::size_t>(std::lround(md / kStep_m));
    const reconstruction::DetailPart* part = nullptr;
    for (const reconstruction::DetailPart& p : mesh.parts)
        if (p.firstRow <= row && row <= p.lastRow) part = &p;
    ASSERT_NE(part, nullptr);
    const float partSwitch = scenegraph::partSwitchDistance(*part, mesh.partError_mm, view);
    ASSERT_LT(partSwitch, switches[0]);

    struct Case {
        const char* what;
        SbVec3f eye;
        int level;
        bool reduced;
    };
    const SbVec3f centre(mesh.centre.x, mesh.centre.y, mesh.centre.z);
    // Beside the segment, east of its centre: a distance that draws the level wanted.
    auto beside = [&](float distance) { return centre + SbVec3f(distance, 0.0f, 0.0f); };
    const std::vector<Case> cases = {
        {"level 0, every section (eye at the ray's start)", axisAt(md), 0, false},
        {"level 0, the part's reduced copy", beside((partSwitch + switches[0]) / 2.0f), 0, true},
        {"level 1", beside((switches[0] + switches[1]) / 2.0f), 1, false},
        {"level 2", beside((switches[1] + switches[2]) / 2.0f), 2, false},
        {"level 3 (the pads' polygon)", beside((switches[2] + switches[3]) / 2.0f), 3, false},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.what);
        placeEye(c.eye);
        for (double azimuth : {10.0, 60.0, 135.0, 250.0, 330.0}) {
            SCOPED_TRACE(azimuth);
            const std::optional<scenegraph::SectionPick> pick = shoot(md, azimuth);
            ASSERT_TRUE(pick.has_value());
            EXPECT_EQ(pick->level, c.level);  // SoRayPickAction followed SoLOD's choice
            EXPECT_EQ(pick->inParts, c.level == 0);
            EXPECT_EQ(pick->reducedPart, c.reduced);
            expectKnownAnswer(*pick, md, azimuth);
        }
    }
    // Past the last switch the segment draws nothing (the path line shows the well): there
    // is no wall to pick, as there is none in the picture.
    placeEye(beside(switches[3] * 1.5f));
    EXPECT_FALSE(shoot(md, 135.0).has_value());
}

TEST_F(SectionPickTest, InAnInclinedHoleTheAngleCountsClockwiseFromTheHighSide) {
    // A gauge hole (215.9 mm) held at 40 degrees towards azimuth 120 from the top.
    reconstruction::SyntheticWellSpec spec =
        reconstruction::syntheticProfile("circle", kLength_m, kStep_m);
    spec.initialInclination_deg = 40.0;
    spec.holeAzimuth_deg = 120.0;
    build(reconstruction::makeSyntheticWell(spec));
    const std::size_t row = 1500;  // MD 3.75 m
    const reconstruction::SectionFrame& f = m_geometry->frame(row);
    const reconstruction::PathPoint& p = m_geometry->path()[row];
    ASSERT_NEAR(p.inc_deg, 40.0, 1e-6);
    const reconstruction::Ned highSide = reconstruction::highSide(p.inc_deg, p.azi_deg);
    const reconstruction::Ned right = glm::cross(f.tangent, highSide);  // clockwise, looking down
    const SbVec3f start = toSb(reconstruction::toScene(m_geometry->centre(row)));
    placeEye(start);
    for (double angle : {15.0, 100.0, 200.0, 300.0}) {
        SCOPED_TRACE(angle);
        const reconstruction::Ned d =
            std::cos(glm::radians(angle)) * highSide + std::sin(glm::radians(angle)) * right;
        const std::optional<scenegraph::SectionPick> pick =
            scenegraph::pickSection(m_root.get(), SbViewportRegion(800, 600), start,
                                    toSb(reconstruction::toScene(d)), wells());
        ASSERT_TRUE(pick.has_value());
        EXPECT_LE(std::abs(static_cast<double>(pick->wall.row) - static_cast<double>(row)), 1.0);
        EXPECT_NEAR(angleBetween(pick->wall.fromHighSide_deg, angle), 0.0, 0.05);
        EXPECT_NEAR(pick->wall.radius_mm, 215.9 / 2.0, 0.01);
        expectReportRow(*pick);
    }
}

TEST_F(SectionPickTest, ARayAlongAnArmMeetsThatArmsReading) {
    build(ellipseWell());
    placeEye(axisAt(2.0));
    const double md = 2.0;
    const auto row = static_cast<std::size_t>(std::lround(md / kStep_m));
    const io::SectionTable& table = m_geometry->table();
    for (int arm = 0; arm < table.armCount; ++arm) {
        // Arms go clockwise from arm 1 at P1AZ (docs/conventions.md, "Arms").
        const double azimuth = std::fmod(table.p1az_deg[row] + 60.0 * arm, 360.0);
        const std::optional<scenegraph::SectionPick> pick = shoot(md, azimuth);
        ASSERT_TRUE(pick.has_value()) << arm;
        EXPECT_EQ(pick->wall.row, row);
        EXPECT_NEAR(angleBetween(pick->wall.fromArm1_deg, 60.0 * arm), 0.0, 0.05) << arm;
        // The spline passes through every pad.
        EXPECT_NEAR(pick->wall.radius_mm, table.radii(row)[arm], 0.01) << arm;
    }
}

TEST_F(SectionPickTest, RadialExaggerationDrawsWiderButThePickReportsTheTrueSection) {
    build(ellipseWell());
    placeEye(axisAt(4.4));
    const std::optional<scenegraph::SectionPick> plain = shoot(4.4, 135.0);
    build(ellipseWell(), 20.0);
    placeEye(axisAt(4.4));
    const std::optional<scenegraph::SectionPick> wide = shoot(4.4, 135.0);
    ASSERT_TRUE(plain.has_value());
    ASSERT_TRUE(wide.has_value());
    // A centred ellipse, drawn 20 times as far from the axis...
    const float drawnPlain = glm::length(glm::vec2(plain->point.x, plain->point.z));
    const float drawnWide = glm::length(glm::vec2(wide->point.x, wide->point.z));
    EXPECT_NEAR(drawnWide / drawnPlain, 20.0f, 0.1f);
    // ...is still the same section, angle, true radius and report row.
    EXPECT_EQ(wide->wall.row, plain->wall.row);
    EXPECT_NEAR(wide->wall.fromHighSide_deg, plain->wall.fromHighSide_deg, 1e-3);
    EXPECT_NEAR(wide->wall.radius_mm, plain->wall.radius_mm, 1e-3);
    EXPECT_EQ(wide->section.equivalentDiameter_mm, plain->section.equivalentDiameter_mm);
    expectKnownAnswer(*wide, 4.4, 135.0);
}

TEST_F(SectionPickTest, AnExaggeratedOffCentreSectionIsShrunkBackAboutItsOwnCentre) {
    // The hole centre 15 mm east of the tool: a section is drawn F times larger about the
    // centroid of its area, so the wall a ray from the tool axis meets at 135 degrees is
    // not the true wall at 135 degrees.
    reconstruction::SyntheticWellSpec spec =
        reconstruction::syntheticProfile("ellipse", kLength_m, kStep_m);
    spec.toolOffset_mm = 15.0;
    spec.toolOffsetAzimuth_deg = 90.0;
    const double f = 20.0;
    build(reconstruction::makeSyntheticWell(spec), f);
    placeEye(axisAt(4.4));
    const std::optional<scenegraph::SectionPick> pick = shoot(4.4, 135.0);
    ASSERT_TRUE(pick.has_value());
    const reconstruction::SectionResult& r = m_analysis.sections[pick->wall.row];
    ASSERT_NEAR(r.centreOffset_mm, 15.0, 0.5);
    // The true point the pick names, drawn as the mesh draws it (north, east, metres): the
    // centroid plus F times the way from it. It is where the ray met the wall, to the drawn
    // polygon's sag (a quarter of a millimetre at level 0) times F.
    const double a = glm::radians(pick->wall.azimuth_deg);
    const double c = glm::radians(r.centreOffsetAzimuth_deg);
    const glm::dvec2 truePoint =
        pick->wall.radius_mm / 1000.0 * glm::dvec2(std::cos(a), std::sin(a));
    const glm::dvec2 centroid = r.centreOffset_mm / 1000.0 * glm::dvec2(std::cos(c), std::sin(c));
    const glm::dvec2 drawn = centroid + f * (truePoint - centroid);
    const reconstruction::Ned hit = reconstruction::fromScene(glm::dvec3(pick->point));
    EXPECT_NEAR(drawn.x, hit.x, f * 0.0003);
    EXPECT_NEAR(drawn.y, hit.y, f * 0.0003);
    // Seen from the tool axis the drawn point is at 135 degrees; the true one is not.
    EXPECT_GT(std::abs(angleBetween(pick->wall.azimuth_deg, 135.0)), 2.0);
    // The report's row is the same as without exaggeration.
    build(reconstruction::makeSyntheticWell(spec));
    EXPECT_EQ(pick->section.equivalentDiameter_mm,
              m_analysis.sections[pick->wall.row].equivalentDiameter_mm);
    EXPECT_EQ(pick->section.dmax_mm, m_analysis.sections[pick->wall.row].dmax_mm);
    EXPECT_EQ(pick->section.centreOffset_mm, m_analysis.sections[pick->wall.row].centreOffset_mm);
}

TEST_F(SectionPickTest, PixelPickUsesTheCamerasRayThroughThePixelCentre) {
    build(ellipseWell());
    const double eyeMd = 2.0;
    placeEye(axisAt(eyeMd));  // looking down the hole, north up: east is on the right
    const SbViewportRegion viewport(401, 401);
    // The middle row, 200 pixels right of the centre column: a ray leaning east.
    const SbVec2s pixel(400, 200);
    const std::optional<scenegraph::SectionPick> pick =
        scenegraph::pickSection(m_root.get(), viewport, pixel, wells());
    ASSERT_TRUE(pick.has_value());
    EXPECT_NEAR(angleBetween(pick->wall.fromHighSide_deg, 90.0), 0.0, 0.05);
    // It leans from the axis by tan a = (pixel centre off the middle, normalised) x tan(half
    // the field of view), so it meets a wall of radius R that much deeper: R / tan a (the
    // drawn wall within a millimetre of the true one).
    const double tanA =
        (2.0 * 400.5 / 401.0 - 1.0) * std::tan(m_camera->heightAngle.getValue() / 2.0);
    const double expected = eyeMd + pick->wall.radius_mm / 1000.0 / tanA;
    EXPECT_NEAR(pick->section.md_m, expected, kStep_m + 0.001 / tanA);
    expectReportRow(*pick);
}

TEST_F(SectionPickTest, MissesAndGapsPickNothingAndASectionWithoutDataSaysSo) {
    io::SectionTable table = ellipseWell();
    for (std::size_t i = 0; i < table.rowCount(); ++i)
        if (table.depth_m[i] >= 6.2 - 1e-9 && table.depth_m[i] < 6.4 - 1e-9)
            for (int k = 0; k < table.armCount; ++k) table.radii(i)[k] = std::nan("");
    build(std::move(table));
    placeEye(axisAt(6.3));

    // Outside the hole, looking away from it.
    EXPECT_FALSE(scenegraph::pickSection(m_root.get(), SbViewportRegion(800, 600),
                                         SbVec3f(1.0f, -5.0f, 0.0f), SbVec3f(1.0f, 0.0f, 0.0f),
                                         wells())
                     .has_value());
    // In the gap the wall has no ring: the ray meets only the path line it starts on, which
    // Coin picks and the wall pick passes over.
    SoRayPickAction raw(SbViewportRegion(800, 600));
    raw.setRay(axisAt(6.3), horizontal(45.0), 0.0f);
    raw.setPickAll(TRUE);
    raw.apply(m_root.get());
    EXPECT_GT(raw.getPickedPointList().getLength(), 0);
    EXPECT_FALSE(shoot(6.3, 45.0).has_value());
    // Just above the gap the wall is there, and its section has data.
    const std::optional<scenegraph::SectionPick> edge = shoot(6.197, 45.0);
    ASSERT_TRUE(edge.has_value());
    EXPECT_TRUE(m_geometry->measured(edge->wall.row));
    EXPECT_NE(edge->section.cls, reconstruction::BoreholeClass::NoData);

    // A section without data (as a coarse wall may reach the edge of a gap): no value guessed.
    const auto gapRow = static_cast<std::size_t>(std::lround(6.3 / kStep_m));
    ASSERT_FALSE(m_geometry->measured(gapRow));
    scenegraph::SectionPick inGap;
    inGap.wall = reconstruction::locateWallPoint(*m_geometry, gapRow - 2, gapRow + 2,
                                                 glm::dvec3(0.1, -6.3, 0.0));
    ASSERT_EQ(inGap.wall.row, gapRow);
    inGap.section = m_analysis.sections[gapRow];
    EXPECT_TRUE(std::isnan(inGap.wall.radius_mm));
    const auto printed = keyValues(scenegraph::formatSectionPick(inGap));
    EXPECT_EQ(printed.at("class"), "no_data");
    for (const char* measurement : {"dmin_mm", "dmax_mm", "equivalent_diameter_mm", "ellipticity",
                                    "area_mm2", "radius_mm", "repaired_arms"})
        EXPECT_EQ(printed.at(measurement), "no_data") << measurement;
    EXPECT_EQ(printed.at("md_m"), "6.3000");  // where it is stays known
    EXPECT_EQ(printed.at("bit_mm"), "215.90");
    EXPECT_EQ(printed.at("angle_azimuth_deg"), "90.00");  // east of the axis
}

TEST_F(SectionPickTest, AWellWithoutItsAnalysisIsRefused) {
    build(ellipseWell());
    std::vector<scenegraph::PickableWell> incomplete = wells();
    incomplete[0].analysis = nullptr;
    EXPECT_THROW(scenegraph::pickSection(m_root.get(), SbViewportRegion(800, 600), axisAt(1.0),
                                         horizontal(0.0), incomplete),
                 std::invalid_argument);
}

TEST_F(SectionPickTest, AWellHeldLeanIsPickedOnTheRowsItHoldsWhereverTheTreeDrawsIt) {
    // A 300 m well drawn whole, picked through the geometry of a sample of its rows (a well of
    // a field held lean in the window): from 200 m and 50 m (spans' merged meshes of two depths)
    // and from beside a segment, the row found is a row held, the nearest held to the row the
    // whole well gives.
    const auto whole = std::make_shared<const reconstruction::WellGeometry>(
        std::make_shared<const io::SectionTable>(reconstruction::makeSyntheticWell(
            reconstruction::syntheticProfile("circle", 300.0, 0.01))),
        reconstruction::GeometryOptions{});
    const reconstruction::WellAnalysis analysis = reconstruction::analyseWell(*whole, {});
    std::vector<std::size_t> rows =
        reconstruction::planCoarseMeshes(*whole, reconstruction::kFirstCoarseLevel, {1.0}).rows();
    for (const std::size_t row : reconstruction::everyKthRow(whole->table().rowCount(), 3000))
        rows.push_back(row);
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    const reconstruction::WellGeometry sample = whole->sampled(rows);
    scenegraph::WellScene scene;
    scene.buildAll(*whole);
    m_root = scenegraph::makeRef(new SoSeparator);
    m_camera = new SoPerspectiveCamera;
    m_camera->nearDistance = 0.01f;
    m_camera->farDistance = 5000.0f;
    m_root->addChild(m_camera);
    m_root->addChild(scene.root());
    const std::vector<scenegraph::PickableWell> asWhole{{&scene, whole.get(), &analysis, "circle"}};
    const std::vector<scenegraph::PickableWell> asLean{{&scene, &sample, nullptr, "circle", &rows}};
    const std::vector<double>& depth = whole->table().depth_m;
    for (const float away : {200.0f, 50.0f, 1.5f}) {
        SCOPED_TRACE(away);
        const SbVec3f target = axisAt(150.0);
        const SbVec3f eye = target + SbVec3f(away, 0.0f, 0.0f);
        m_camera->position = eye;
        m_camera->pointAt(target, SbVec3f(0.0f, 1.0f, 0.0f));
        const auto exact = scenegraph::pickSection(m_root.get(), SbViewportRegion(800, 600), eye,
                                                   target - eye, asWhole);
        const auto held = scenegraph::pickSection(m_root.get(), SbViewportRegion(800, 600), eye,
                                                  target - eye, asLean);
        ASSERT_TRUE(exact.has_value());
        ASSERT_TRUE(held.has_value());
        EXPECT_EQ(exact->spanDepth > 0, away > 10.0f);  // a span's merged mesh further away
        EXPECT_EQ(held->spanDepth, exact->spanDepth);
        EXPECT_TRUE(exact->analysed);
        EXPECT_FALSE(held->analysed);
        ASSERT_LT(held->wall.row, rows.size());
        // The held row nearest the whole well's row (the rows between are not held).
        const double md = depth[exact->wall.row];
        const auto next = std::lower_bound(rows.begin(), rows.end(), exact->wall.row);
        double nearest = 1e9;
        for (auto it = next == rows.begin() ? next : next - 1; it != rows.end() && it <= next; ++it)
            nearest = std::min(nearest, std::abs(depth[*it] - md));
        EXPECT_LE(std::abs(depth[rows[held->wall.row]] - md), nearest + 0.011)
            << "whole row " << exact->wall.row << ", held " << rows[held->wall.row];
        EXPECT_EQ(sample.table().depth_m[held->wall.row], depth[rows[held->wall.row]]);
    }
    // A geometry that does not hold as many rows as it says is refused.
    std::vector<std::size_t> fewer(rows.begin(), rows.end() - 1);
    EXPECT_THROW(
        scenegraph::pickSection(m_root.get(), SbViewportRegion(800, 600), axisAt(1.0),
                                horizontal(0.0), {{&scene, &sample, nullptr, "circle", &fewer}}),
        std::invalid_argument);
}
