#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoDrawStyle.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoText2.h>

#include <glm/geometric.hpp>

#include "coin_fixture.h"
#include "reconstruction/section/section_frame.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "reconstruction/well_geometry.h"
#include "scenegraph/node_ref.h"
#include "scenegraph/well_annotations.h"
#include "scenegraph/well_scene.h"

namespace caliper3d::scenegraph {
namespace {

using reconstruction::GeometryOptions;
using reconstruction::WellGeometry;

std::shared_ptr<const io::SectionTable> syntheticLog(const std::string& profile, double length,
                                                     double step, double top = 0.0) {
    const io::SectionTable whole =
        reconstruction::makeSyntheticWell(reconstruction::syntheticProfile(profile, length, step));
    std::size_t first = 0;
    while (whole.depth_m[first] < top - 1e-9) ++first;
    auto table = std::make_shared<io::SectionTable>(whole.rows(first, whole.rowCount()));
    table->source = "/data/logs/" + profile + ".txt";
    return table;
}

glm::vec3 sceneCentre(const WellGeometry& g, std::size_t row) {
    return glm::vec3(reconstruction::toScene(g.centre(row)));
}

TEST(WellAnnotationsTest, TicksEveryHundredMetresOfAKilometreWellLieOnItsPath) {
    // The example profile builds from 333 m to 833 m: the ticks follow the curve.
    const auto log = syntheticLog("example", 1000.0, 0.5);
    GeometryOptions options;
    options.wellheadOffset = {30.0, -20.0, 0.0};
    const WellGeometry g(log, options);
    AnnotationView view;
    view.radialExaggeration = 100.0;
    const std::vector<DepthTick> ticks = depthTicks(g, view);
    ASSERT_EQ(ticks.size(), 10u);  // 100 ... 1000 m; MD 0 carries the name instead
    for (std::size_t i = 0; i < ticks.size(); ++i) {
        const double md = 100.0 * static_cast<double>(i + 1);
        EXPECT_DOUBLE_EQ(ticks[i].md_m, md);
        const std::size_t row = static_cast<std::size_t>(md / 0.5);
        ASSERT_DOUBLE_EQ(log->depth_m[row], md);
        const glm::vec3 expected = sceneCentre(g, row);
        for (int k = 0; k < 3; ++k) EXPECT_FLOAT_EQ(ticks[i].position[k], expected[k]) << md;
        EXPECT_EQ(ticks[i].label, std::to_string(static_cast<int>(md)) + " m");
        // The mark stands off the drawn wall (100 x 0.108 m) by 2.5 % of the 1000 m shown,
        // across the path and the view.
        const glm::vec3 mark = ticks[i].end - ticks[i].position;
        EXPECT_NEAR(glm::length(mark), 100.0 * 0.10795 + 25.0, 1e-3) << md;
        EXPECT_NEAR(glm::dot(mark, view.look), 0.0, 1e-3) << md;
        EXPECT_GE(glm::dot(mark, view.right), 0.0) << md;
    }
}

TEST(WellAnnotationsTest, TicksAboveTheLogLieOnTheTieIn) {
    // A vertical log from 250 m: ticks at 100 and 200 m are on the vertical drop from the
    // wellhead (scene y is up).
    const auto log = syntheticLog("circle", 1000.0, 0.5, 250.0);
    const WellGeometry g(log, GeometryOptions{});
    const std::vector<DepthTick> ticks = depthTicks(g, AnnotationView{});
    ASSERT_EQ(ticks.size(), 10u);
    EXPECT_FLOAT_EQ(ticks[0].position.y, -100.0f);
    EXPECT_FLOAT_EQ(ticks[1].position.y, -200.0f);
    EXPECT_FLOAT_EQ(ticks[0].position.x, 0.0f);
}

TEST(WellAnnotationsTest, AnIntervalGetsItsOwnSpacing) {
    const auto log = syntheticLog("circle", 1000.0, 0.5);
    const WellGeometry g(log, GeometryOptions{});
    AnnotationView view;
    view.top_m = 400.0;
    view.bottom_m = 500.0;
    const std::vector<DepthTick> ticks = depthTicks(g, view);
    ASSERT_EQ(ticks.size(), 11u);  // every 10 m from 400 to 500 m
    EXPECT_DOUBLE_EQ(ticks.front().md_m, 400.0);
    EXPECT_DOUBLE_EQ(ticks.back().md_m, 500.0);
}

TEST(WellAnnotationsTest, LabelsThatWouldOverlapAreLeftOut) {
    const auto log = syntheticLog("circle", 100.0, 0.5);
    const WellGeometry g(log, GeometryOptions{});
    AnnotationView view;
    // Seen end on: every tick lands on the same pixel. Only the name is placed.
    view.toPixels = [](const glm::vec3&) { return std::optional<glm::vec2>(glm::vec2(50, 50)); };
    std::vector<DepthTick> ticks = depthTicks(g, view);
    ASSERT_EQ(ticks.size(), 10u);
    for (const DepthTick& tick : ticks) EXPECT_TRUE(tick.label.empty()) << tick.md_m;
    // Ten metres a 30 px: every label fits.
    view.toPixels = [](const glm::vec3& p) {
        return std::optional<glm::vec2>(glm::vec2(100.0f, -3.0f * p.y + 40.0f));
    };
    ticks = depthTicks(g, view);
    for (const DepthTick& tick : ticks) EXPECT_FALSE(tick.label.empty()) << tick.md_m;
}

// Names counted by where their anchors land in a 200 x 100 picture (x pixels = scene x,
// y pixels = scene y): one named, two left out in view, one left out outside the picture, one
// behind the eye, one well without a name.
TEST(WellAnnotationsTest, NamesLeftOutAreCountedAmongThoseAnchoredInThePicture) {
    PlacedAnnotations placed;
    const auto well = [&placed](const std::string& text, glm::vec3 at, bool hasName = true) {
        AnnotationView view;
        view.width_px = 200;
        view.height_px = 100;
        view.toPixels = [](const glm::vec3& p) -> std::optional<glm::vec2> {
            if (p.z < 0.0f) return std::nullopt;  // behind the eye
            return glm::vec2(p.x, p.y);
        };
        WellLabels labels;
        if (hasName) labels.name = WellName{text, at, at, true, 0.1f, std::nullopt};
        placed.views.push_back(view);
        placed.labels.push_back(labels);
    };
    well("A", {10.0f, 10.0f, 1.0f});
    well("", {150.0f, 90.0f, 1.0f});
    well("", {200.0f, 100.0f, 1.0f});  // on the corner: in
    well("", {250.0f, 50.0f, 1.0f});   // right of the picture
    well("", {50.0f, 50.0f, -1.0f});   // behind the eye
    well("", {50.0f, 50.0f, 1.0f}, false);
    const NamesInView names = namesInView(placed);
    EXPECT_EQ(names.inView, 3u);
    EXPECT_EQ(names.leftOut, 2u);
    EXPECT_EQ(namesLeftOutCaption(names), "2 of 3 names left out: no room");
    EXPECT_EQ(namesLeftOutCaption({1, 1}), "1 of 1 name left out: no room");
    EXPECT_EQ(namesLeftOutCaption({3, 0}), "");
    // Without a projection (a window's labels before its camera rests) nothing is counted.
    for (AnnotationView& view : placed.views) view.toPixels = nullptr;
    EXPECT_EQ(namesInView(placed).inView, 0u);
}

TEST(WellAnnotationsTest, DepthLabelsCarryTheDecimalsTheSpacingNeeds) {
    EXPECT_EQ(depthLabel(500.0, 100.0), "500 m");
    EXPECT_EQ(depthLabel(12.5, 0.5), "12.5 m");
    EXPECT_EQ(depthLabel(0.35, 0.05), "0.35 m");
}

TEST(WellAnnotationsTest, TheWellIsNamedByItsLogElseByItsFile) {
    io::SectionTable table;
    table.source = "/data/logs/star.las";
    EXPECT_EQ(wellLabel(table), "star.las");
    table.wellName = "  SUNCOR LEWIS 7-22-92-8 ";
    EXPECT_EQ(wellLabel(table), "SUNCOR LEWIS 7-22-92-8");
}

class WellAnnotationNodesTest : public CoinTest {};

// The string of the last SoText2 under the node called `name` in `root` (a label's own text
// comes after its outline's copies).
std::string textOf(SoNode* root, const char* name) {
    SoSearchAction byName;
    byName.setName(name);
    byName.setSearchingAll(TRUE);
    byName.apply(root);
    if (!byName.getPath()) return {};
    SoSearchAction text;
    text.setType(SoText2::getClassTypeId());
    text.setInterest(SoSearchAction::LAST);
    text.setSearchingAll(TRUE);
    text.apply(byName.getPath()->getTail());
    if (!text.getPath()) return {};
    return static_cast<SoText2*>(text.getPath()->getTail())->string[0].getString();
}

TEST_F(WellAnnotationNodesTest, TheWellheadLabelIsTheWellsName) {
    auto table = std::make_shared<io::SectionTable>(*syntheticLog("circle", 100.0, 0.5));
    table->wellName = "TEST-7";
    const WellGeometry g(table, GeometryOptions{});
    auto root = makeRef(makeWellAnnotations(g, AnnotationView{}));
    EXPECT_EQ(textOf(root.get(), "well_name"), " TEST-7");  // a space off the marker
}

TEST_F(WellAnnotationNodesTest, AnnotationsTakeNoPartInTheSceneBox) {
    const WellGeometry g(syntheticLog("circle", 100.0, 0.5), GeometryOptions{});
    WellScene scene;
    scene.buildAll(g);
    const SbViewportRegion viewport(640, 480);
    SoGetBoundingBoxAction before(viewport);
    before.apply(scene.root());
    auto annotated = makeRef(new SoSeparator);
    annotated->addChild(scene.root());
    AnnotationView view;
    view.radialExaggeration = 1000.0;  // ticks reach 108 m off the path
    annotated->addChild(makeWellAnnotations(g, view));
    SoGetBoundingBoxAction after(viewport);
    after.apply(annotated.get());
    EXPECT_EQ(before.getBoundingBox().getMin(), after.getBoundingBox().getMin());
    EXPECT_EQ(before.getBoundingBox().getMax(), after.getBoundingBox().getMax());
}

TEST_F(WellAnnotationNodesTest, TheUnloggedPathIsDashedFromTheWellhead) {
    EXPECT_EQ(makeUnloggedPath(WellGeometry(syntheticLog("circle", 100.0, 0.5), {})), nullptr);
    const WellGeometry g(syntheticLog("circle", 100.0, 0.5, 27.0), GeometryOptions{});
    auto path = makeRef(makeUnloggedPath(g));
    ASSERT_TRUE(path);
    SoSearchAction search;
    search.setType(SoDrawStyle::getClassTypeId());
    search.apply(path.get());
    ASSERT_NE(search.getPath(), nullptr);
    EXPECT_NE(static_cast<SoDrawStyle*>(search.getPath()->getTail())->linePattern.getValue(),
              0xFFFF);
}

}  // namespace
}  // namespace caliper3d::scenegraph
