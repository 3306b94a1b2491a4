#include "reconstruction/mesh/wall_colouring.h"

#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "reconstruction/mesh/lod_levels.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "reconstruction/well_geometry.h"

using namespace caliper3d::reconstruction;

namespace {
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
}  // namespace

TEST(ColourMapTest, DivergingIsGreyAtItsCentreBlueBelowAndRedAbove) {
    const std::uint32_t centre = divergingColour(0.5);
    EXPECT_EQ(red(centre), green(centre));
    EXPECT_EQ(green(centre), blue(centre));
    EXPECT_EQ(red(centre), 221);  // 0.865 of full scale: Moreland's neutral
    const std::uint32_t low = divergingColour(0.0), high = divergingColour(1.0);
    EXPECT_GT(blue(low), red(low) + 100);
    EXPECT_GT(red(high), blue(high) + 100);
    EXPECT_EQ(divergingColour(-3.0), low);  // clamped
    EXPECT_EQ(divergingColour(std::nan("")), kNoValueColour);
}

TEST(ColourMapTest, SequentialIsViridisEndToEnd) {
    EXPECT_EQ(sequentialColour(0.0), 0x440154FFu);
    EXPECT_EQ(sequentialColour(0.5), 0x21918CFFu);
    EXPECT_EQ(sequentialColour(1.0), 0xFDE725FFu);
    // Lightness rises along the map (a grey print keeps the order).
    auto luma = [](std::uint32_t c) { return 0.3 * red(c) + 0.59 * green(c) + 0.11 * blue(c); };
    for (int i = 0; i < 10; ++i)
        EXPECT_LT(luma(sequentialColour(i / 10.0)), luma(sequentialColour((i + 1) / 10.0)));
}

TEST(WallColouringTest, DeparturesAreMeasuredFromEachRowsReference) {
    const WallColouring c = WallColouring::departure({100.0f, kNaN}, -25.0, 25.0, {});
    EXPECT_EQ(c.rowCount(), 2u);
    EXPECT_EQ(c.colour(0, 100.0), divergingColour(0.5));  // in gauge: the neutral grey
    EXPECT_EQ(c.colour(0, 125.0), divergingColour(1.0));  // +25 mm: the map's end
    EXPECT_EQ(c.colour(0, 112.5), divergingColour(0.75));
    EXPECT_EQ(c.colour(0, 90.0), divergingColour(0.3));
    EXPECT_EQ(c.colour(1, 100.0), kNoValueColour);  // no reference on that row
    // A range that is not symmetric keeps 0 at the centre, each side scaled on its own.
    const WallColouring skew = WallColouring::departure({100.0f}, -10.0, 40.0, {});
    EXPECT_EQ(skew.colour(0, 90.0), divergingColour(0.0));
    EXPECT_EQ(skew.colour(0, 120.0), divergingColour(0.75));
    EXPECT_EQ(skew.legend().lo, -10.0);
    EXPECT_EQ(skew.legend().hi, 40.0);
}

TEST(WallColouringTest, RowValuesMapOverTheirRangeAndCategoriesTakeTheirColours) {
    const WallColouring c =
        WallColouring::perRow({0.0f, 5.0f, 10.0f, kNaN}, ColourMapKind::Sequential, 0.0, 10.0, {});
    EXPECT_EQ(c.colour(0, 123.0), sequentialColour(0.0));  // the radius plays no part
    EXPECT_EQ(c.colour(1, 0.0), sequentialColour(0.5));
    EXPECT_EQ(c.colour(2, 0.0), sequentialColour(1.0));
    EXPECT_EQ(c.colour(3, 0.0), kNoValueColour);
    ColourLegend legend;
    legend.categories = {{"a", 0x112233FFu}, {"b", 0x445566FFu}};
    const WallColouring k = WallColouring::categories({1.0f, 0.0f, kNaN, 7.0f}, legend);
    EXPECT_EQ(k.colour(0, 0.0), 0x445566FFu);
    EXPECT_EQ(k.colour(1, 0.0), 0x112233FFu);
    EXPECT_EQ(k.colour(2, 0.0), kNoValueColour);
    EXPECT_EQ(k.colour(3, 0.0), kNoValueColour);  // not a category
}

// The colours of some rows only, for a well held by those rows: each row's colour as before,
// by direction too, and the same legend.
TEST(WallColouringTest, AColouringOfSomeRowsColoursEachAsTheWholeDid) {
    ColourLegend legend;
    legend.title = "diameter";
    const WallColouring rows = WallColouring::perRow({0.0f, 2.0f, 5.0f, kNaN, 10.0f},
                                                     ColourMapKind::Sequential, 0.0, 10.0, legend);
    const std::vector<std::size_t> kept{1, 3, 4};
    const WallColouring some = rows.rowsOf(kept);
    ASSERT_EQ(some.rowCount(), 3u);
    EXPECT_EQ(some.legend().title, "diameter");
    for (std::size_t i = 0; i < kept.size(); ++i)
        EXPECT_EQ(some.colour(i, 100.0), rows.colour(kept[i], 100.0)) << i;
    // Per direction: rows 0 and 2 have values round the section (slots 0 and 1), row 1 not.
    DirectionalValues directional;
    directional.bins = 4;
    directional.step = 0.5f;
    directional.slot = {0, -1, 1};
    directional.arm1Angle_deg = {0.0f, 45.0f};
    directional.values = {0, 4, 8, 12, 20, 16, kNoDirectionalValue, 2};
    const WallColouring round = WallColouring::perDirection(
        {1.0f, 3.0f, 9.0f}, directional, ColourMapKind::Sequential, 0.0, 10.0, {});
    const std::vector<std::size_t> ends{0, 2};
    const WallColouring both = round.rowsOf(ends);
    ASSERT_EQ(both.rowCount(), 2u);
    EXPECT_TRUE(both.byDirection());
    for (std::size_t i = 0; i < ends.size(); ++i)
        for (const double angle : {0.0, 30.0, 95.0, 180.0, 250.0, 359.0})
            EXPECT_EQ(both.colour(i, 100.0, angle), round.colour(ends[i], 100.0, angle))
                << i << " at " << angle;
    EXPECT_EQ(round.rowsOf({1}).colour(0, 100.0, 90.0), round.colour(1, 100.0, 90.0));
}

TEST(WallColouringTest, EveryWallPointTakesItsRowsColour) {
    auto table = std::make_shared<const caliper3d::io::SectionTable>(
        makeSyntheticWell(syntheticProfile("circle", 4.0, 0.1)));
    GeometryOptions options;
    options.segmentLength_m = 4.0;
    const WellGeometry plain(table, options);
    // Row r coloured by r itself, over [0, rows - 1].
    std::vector<float> values(table->rowCount());
    for (std::size_t r = 0; r < values.size(); ++r) values[r] = static_cast<float>(r);
    const auto colouring = std::make_shared<const WallColouring>(WallColouring::perRow(
        values, ColourMapKind::Sequential, 0.0, static_cast<double>(values.size() - 1), {}));
    const WellGeometry coloured = plain.restyled(1.0, colouring);
    const Mesh level0 = buildSegmentMesh(coloured, 0).levels.front();
    const std::size_t points = 48;
    ASSERT_EQ(level0.colours.size(), table->rowCount() * points);
    for (std::size_t r = 0; r < table->rowCount(); ++r)
        for (std::size_t j = 0; j < points; ++j)
            ASSERT_EQ(level0.colours[r * points + j], colouring->colour(r, 0.0)) << r;
    // Without a colouring: the departure from bit size, grey for this gauge hole.
    const Mesh grey = buildSegmentMesh(plain, 0).levels.front();
    EXPECT_EQ(grey.colours.front(), departureColour(215.9 / 2, 215.9 / 2));
    EXPECT_EQ(grey.colours.front(), divergingColour(0.5));
}

TEST(WallColouringTest, RestyledGeometrySharesTheTableAndThePath) {
    auto table = std::make_shared<const caliper3d::io::SectionTable>(
        makeSyntheticWell(syntheticProfile("build", 50.0, 0.1)));
    const WellGeometry g(table, GeometryOptions{});
    const WellGeometry styled = g.restyled(30.0, nullptr);
    EXPECT_EQ(&styled.table(), &g.table());  // nothing read again
    EXPECT_EQ(&styled.path(), &g.path());    // nothing placed again
    // Frames come from the shared path and orientation: the same, bit for bit.
    EXPECT_TRUE(styled.frame(7).arm1 == g.frame(7).arm1);
    EXPECT_TRUE(styled.frame(7).tangent == g.frame(7).tangent);
    EXPECT_EQ(styled.options().radialExaggeration, 30.0);
    EXPECT_EQ(g.options().radialExaggeration, 1.0);
    // A colouring of another well's rows is refused.
    const auto wrong = std::make_shared<const WallColouring>(
        WallColouring::departure(std::vector<float>(3, 100.0f), -25.0, 25.0, {}));
    EXPECT_THROW((void)g.restyled(1.0, wrong), std::invalid_argument);
}

// The tool runs 15 mm west of the hole's centre ("offcentre"): drawn 10 times larger, the
// hole stays centred where it is and stays round, every point 10 radii from that centre.
// Scaled about the tool axis instead, its centre would move 135 mm east.
TEST(WallColouringTest, ExaggerationScalesEachSectionAboutItsOwnCentre) {
    auto table = std::make_shared<const caliper3d::io::SectionTable>(
        makeSyntheticWell(syntheticProfile("offcentre", 2.0, 0.1)));
    GeometryOptions options;
    options.segmentLength_m = 2.0;
    const WellGeometry g(table, options);
    const WellGeometry big = g.restyled(10.0, nullptr);
    const Mesh level0 = buildSegmentMesh(big, 0).levels.front();
    const std::size_t points = 48, row = 10;
    const glm::dvec3 axis = toScene(g.centre(row));
    // The hole centre: 15 mm east of the tool axis (the scene's east axis).
    const glm::dvec3 east = toScene(Ned(0.0, 1.0, 0.0)) - toScene(Ned(0.0, 0.0, 0.0));
    const glm::dvec3 centre = axis + 0.015 * east;
    for (std::size_t j = 0; j < points; ++j) {
        const glm::dvec3 p(level0.positions[row * points + j]);
        EXPECT_NEAR(glm::length(p - centre), 10.0 * 0.2159 / 2, 6e-3) << j;
    }
}
