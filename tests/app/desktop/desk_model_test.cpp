#include "app/desktop/desk_model.h"

#include <cmath>
#include <memory>
#include <vector>

#include <gtest/gtest.h>
#include <QSignalSpy>

#include "reconstruction/synthetic/synthetic_well.h"

using namespace caliper3d;

namespace {

// A 20 m synthetic well, rows every 0.1 m from 100 m.
app::DeskWell syntheticWell() {
    auto table = std::make_shared<const io::SectionTable>(
        reconstruction::makeSyntheticWell(reconstruction::syntheticProfile("example", 20.0, 0.1)));
    app::DeskWell w;
    w.name = "synthetic";
    w.geometry = std::make_shared<const reconstruction::WellGeometry>(
        table, reconstruction::GeometryOptions{});
    return w;
}

}  // namespace

TEST(DeskModelTest, SnapsTheCurrentDepthToTheNearestRowAndClampsAtTheEnds) {
    app::DeskModel model;
    const int well = model.addWell(syntheticWell());
    const auto& depth = model.well(well).geometry->table().depth_m;
    ASSERT_GT(depth.size(), 10u);
    // The first well with a geometry becomes current at its first row.
    EXPECT_EQ(model.currentWell(), well);
    EXPECT_EQ(model.currentRow(), 0u);
    EXPECT_DOUBLE_EQ(model.currentDepth_m(), depth.front());

    const double step = depth[1] - depth[0];
    model.setCurrentDepth(depth[7] + 0.4 * step);
    EXPECT_EQ(model.currentRow(), 7u);
    model.setCurrentDepth(depth[7] + 0.6 * step);
    EXPECT_EQ(model.currentRow(), 8u);
    EXPECT_DOUBLE_EQ(model.currentDepth_m(), depth[8]);
    model.setCurrentDepth(depth.front() - 50.0);
    EXPECT_EQ(model.currentRow(), 0u);
    model.setCurrentDepth(depth.back() + 50.0);
    EXPECT_EQ(model.currentRow(), depth.size() - 1);
}

TEST(DeskModelTest, SignalsAChangeOnceAndNotForTheSameRow) {
    app::DeskModel model;
    model.addWell(syntheticWell());
    QSignalSpy changed(&model, &app::DeskModel::currentChanged);
    const auto& depth = model.well(0).geometry->table().depth_m;
    model.setCurrentDepth(depth[20]);
    model.setCurrentDepth(depth[20] + 1e-6);  // the same row: no signal
    ASSERT_EQ(changed.count(), 1);
    EXPECT_EQ(changed.at(0).at(0).toInt(), 0);
    EXPECT_DOUBLE_EQ(changed.at(0).at(1).toDouble(), depth[20]);
}

TEST(DeskModelTest, IgnoresWellsWithoutGeometryAndWrapsTheAzimuth) {
    app::DeskModel model;
    app::DeskWell failed;
    failed.name = "bad";
    failed.error = "bad.las:12: expected a number";
    model.addWell(failed);
    EXPECT_EQ(model.currentWell(), -1);
    EXPECT_EQ(model.current(), nullptr);
    EXPECT_TRUE(std::isnan(model.currentDepth_m()));
    model.setCurrent(0, 105.0);  // no geometry: nothing to go to
    EXPECT_EQ(model.currentWell(), -1);

    model.addWell(syntheticWell());
    EXPECT_EQ(model.currentWell(), 1);
    QSignalSpy azimuth(&model, &app::DeskModel::azimuthChanged);
    model.setCurrentAzimuth(-30.0);
    EXPECT_DOUBLE_EQ(model.currentAzimuth_deg(), 330.0);
    model.setCurrentAzimuth(690.0);  // the same direction: no second signal
    EXPECT_EQ(azimuth.count(), 1);

    model.clearWells();
    EXPECT_EQ(model.wellCount(), 0);
    EXPECT_EQ(model.currentWell(), -1);
}

TEST(DeskModelTest, AWellOpensAtItsFirstMeasuredSection) {
    // The first 3 m of the log have no reading (every arm null), as above a real log's first
    // reading: the views open on the first section with one, not on "no data".
    io::SectionTable table =
        reconstruction::makeSyntheticWell(reconstruction::syntheticProfile("example", 20.0, 0.1));
    for (std::size_t row = 0; row < 30; ++row)
        for (int arm = 0; arm < table.armCount; ++arm) table.radii(row)[arm] = std::nan("");
    app::DeskWell w;
    w.name = "late";
    w.geometry = std::make_shared<const reconstruction::WellGeometry>(
        std::make_shared<const io::SectionTable>(std::move(table)),
        reconstruction::GeometryOptions{});
    ASSERT_FALSE(w.geometry->measured(29));
    ASSERT_TRUE(w.geometry->measured(30));
    EXPECT_EQ(app::DeskModel::firstMeasuredRow(*w.geometry), 30u);
    app::DeskModel model;
    model.addWell(w);
    EXPECT_EQ(model.currentWell(), 0);
    EXPECT_EQ(model.currentRow(), 30u);
    EXPECT_DOUBLE_EQ(model.currentDepth_m(), w.geometry->table().depth_m[30]);
    // A well whose geometry comes later (a load) opens there too.
    app::DeskModel loading;
    app::DeskWell pending = w;
    pending.geometry.reset();
    loading.addWell(pending);
    EXPECT_EQ(loading.currentWell(), -1);
    loading.updateWell(0, w);
    EXPECT_EQ(loading.currentRow(), 30u);
}

TEST(DeskModelTest, UntilOneIsChosenTheFirstWellPlacedInOrderIsCurrent) {
    // A field's wells load side by side and are placed in any order: the views open on the
    // first well given, whichever is placed first, until the user chooses one.
    app::DeskModel model;
    app::DeskWell pending = syntheticWell();
    pending.geometry.reset();
    for (int w = 0; w < 3; ++w) model.addWell(pending);
    model.updateWell(1, syntheticWell());
    EXPECT_EQ(model.currentWell(), 1);
    model.updateWell(2, syntheticWell());
    EXPECT_EQ(model.currentWell(), 1);
    model.updateWell(0, syntheticWell());
    EXPECT_EQ(model.currentWell(), 0);
    EXPECT_EQ(model.currentRow(), app::DeskModel::firstMeasuredRow(*model.well(0).geometry));
    // Chosen: a well placed before it no longer takes over.
    app::DeskModel chosen;
    for (int w = 0; w < 3; ++w) chosen.addWell(pending);
    chosen.updateWell(2, syntheticWell());
    chosen.updateWell(1, syntheticWell());
    EXPECT_EQ(chosen.currentWell(), 1);
    chosen.setCurrent(2, 10.0);
    chosen.updateWell(0, syntheticWell());
    EXPECT_EQ(chosen.currentWell(), 2);
    EXPECT_DOUBLE_EQ(chosen.currentDepth_m(), 10.0);
    // The well chosen closed: the first well is current again, and is until the next choice.
    chosen.removeWell(2);
    EXPECT_EQ(chosen.currentWell(), 0);
    chosen.addWell(syntheticWell());
    EXPECT_EQ(chosen.currentWell(), 0);
}
