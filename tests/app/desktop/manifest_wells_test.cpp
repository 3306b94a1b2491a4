// A field opened from a batch manifest (caliper3d view --manifest): every row's well with its
// own options, loaded through WellSession with no window, each record showing how far its
// load has got; a row that cannot be opened says its line.
#include "app/manifest_wells.h"

#include <cstdlib>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <QComboBox>
#include <QSignalSpy>
#include <QTreeWidget>
#include <glm/geometric.hpp>

#include "app/desktop/desk_model.h"
#include "app/desktop/warnings_dock.h"
#include "app/desktop/well_session.h"
#include "app/desktop/wells_dock.h"
#include "desktop_test_support.h"

using namespace caliper3d;

namespace {

class ManifestWellsTest : public ::testing::Test {
protected:
    void SetUp() override {
        if (!test::ensureGuiApplication()) GTEST_SKIP() << "no display (run under xvfb-run)";
    }
};

// `caliper3d synth --field 3` into a folder of this test's own, with a manifest of its three
// wells, each with its own bit size, and two rows that cannot be opened (a file that is not
// there, a malformed wellhead).
std::filesystem::path writeField(const std::string& name) {
    const std::filesystem::path dir = test::freshScratchFolder(name);
    const std::string command = std::string(CALIPER3D_BINARY) + " synth --field 3 --length 40 " +
                                "--step 0.1 -o " + dir.string() + "/ > /dev/null";
    if (std::system(command.c_str()) != 0) return {};
    std::ofstream manifest(dir / "field.csv");
    manifest << "file,verb,bit_size,wellhead,options\n"
                "well-000.las,report,8.5in,,--step 1\n"
                "well-001.las,report,9.875in,,\n"
                "# a comment line, not a row\n"
                "well-002.las,report,,,--bit-size 6in\n"
                "missing.las,report,,,\n"
                "well-000.las,report,,\"not,a,wellhead\",\n";
    return dir;
}

TEST_F(ManifestWellsTest, EveryRowBecomesAWellWithItsOwnOptions) {
    const std::filesystem::path dir = writeField("manifest_wells_rows");
    ASSERT_FALSE(dir.empty()) << "synth --field failed";
    app::LoadOptions base;
    base.radialExaggeration = 7.0;  // the command line's, kept under each row's
    const std::vector<app::ManifestWell> wells =
        app::manifestWells(app::readManifest((dir / "field.csv").string()), base);
    ASSERT_EQ(wells.size(), 5u);
    EXPECT_EQ(wells[0].source.path, (dir / "well-000.las").string());
    ASSERT_TRUE(wells[0].options.read.bitSize_mm.has_value());
    EXPECT_NEAR(*wells[0].options.read.bitSize_mm, 215.9, 1e-9);
    EXPECT_NEAR(*wells[1].options.read.bitSize_mm, 250.825, 1e-9);
    EXPECT_NEAR(*wells[2].options.read.bitSize_mm, 152.4, 1e-9);  // from its options cell
    for (const app::ManifestWell& well : wells)
        EXPECT_DOUBLE_EQ(well.options.radialExaggeration, 7.0);
    // report's --step is the batch's, not the window's: noted, not applied.
    EXPECT_EQ(wells[0].ignored, std::vector<std::string>{"--step"});
    for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(wells[i].problem, "") << i;
    // The malformed wellhead: its line (the header is line 1, the comment line 4).
    EXPECT_EQ(wells[4].line, 7u);
    EXPECT_EQ(wells[4].problem.rfind("line 7: --wellhead", 0), 0u) << wells[4].problem;
}

TEST_F(ManifestWellsTest, AFieldLoadsWellByWellWithItsProgressInTheModel) {
    const std::filesystem::path dir = writeField("manifest_wells_load");
    ASSERT_FALSE(dir.empty()) << "synth --field failed";
    std::vector<app::ManifestWell> wells =
        app::manifestWells(app::readManifest((dir / "field.csv").string()), {});
    wells.pop_back();  // the row with a problem: the window names it and opens the others
    app::DeskModel model;
    app::WellsDock dock(model);
    app::WellSession session(model, nullptr);
    // Every fraction a record is given, well by well.
    std::vector<std::vector<double>> fractions(wells.size());
    QObject::connect(&model, &app::DeskModel::wellChanged, [&](int i) {
        if (i >= 0 && std::size_t(i) < fractions.size())
            fractions[std::size_t(i)].push_back(model.well(i).loadFraction);
    });
    session.openWell(wells.front().source, wells.front().options);
    for (std::size_t i = 1; i < wells.size(); ++i)
        session.addWell(wells[i].source, wells[i].options);
    ASSERT_EQ(model.wellCount(), 4);
    EXPECT_TRUE(session.progress().busy);
    ASSERT_TRUE(test::waitUntil([&] { return !session.loading(); }, 120000));
    ASSERT_TRUE(test::waitUntil(
        [&] {
            for (int i = 0; i < 3; ++i)
                if (!model.well(i).analysis) return false;
            return true;
        },
        120000));
    for (int i = 0; i < 3; ++i) {
        SCOPED_TRACE(i);
        const app::DeskWell& well = model.well(i);
        ASSERT_NE(well.geometry, nullptr);
        EXPECT_EQ(well.name, QString("FIELD-00%1").arg(i));
        // Its own bit size, as its row gave it.
        EXPECT_EQ(well.options.read.bitSize_mm, wells[std::size_t(i)].options.read.bitSize_mm);
        EXPECT_DOUBLE_EQ(well.loadFraction, 1.0);
        // Published as it went: never backwards, done at the end.
        const std::vector<double>& seen = fractions[std::size_t(i)];
        ASSERT_FALSE(seen.empty());
        for (std::size_t k = 1; k < seen.size(); ++k) EXPECT_GE(seen[k], seen[k - 1]);
        EXPECT_DOUBLE_EQ(seen.back(), 1.0);
        EXPECT_EQ(dock.tree()->topLevelItem(i)->text(app::WellsDock::State), "loaded");
    }
    // Placed from their headers: 25 m apart.
    const auto head = [&](int i) { return model.well(i).geometry->centre(0); };
    EXPECT_NEAR(glm::length(head(1) - head(0)), 25.0, 0.5);
    // The file that is not there failed, and says so.
    EXPECT_FALSE(model.well(3).error.isEmpty());
    EXPECT_NE(model.well(3).error.indexOf("missing.las"), -1) << model.well(3).error.toStdString();
    EXPECT_EQ(dock.tree()->topLevelItem(3)->text(app::WellsDock::State), "failed");
    EXPECT_FALSE(session.progress().busy);
}

TEST_F(ManifestWellsTest, TheWellsDockSaysHowFarEachLoadHasGot) {
    app::DeskModel model;
    app::WellsDock dock(model);
    app::DeskWell reading;
    reading.name = "A";
    reading.loadFraction = 0.404;
    model.addWell(reading);
    EXPECT_EQ(dock.tree()->topLevelItem(0)->text(app::WellsDock::State), "reading 40%");
    app::DeskWell failed = reading;
    failed.error = "A.las line 3: expected a number";
    model.updateWell(0, failed);
    EXPECT_EQ(dock.tree()->topLevelItem(0)->text(app::WellsDock::State), "failed");
}

TEST_F(ManifestWellsTest, WellsAddedOneByOneGetTheirOwnRowsAndColourBoxes) {
    // A field's wells come one at a time: each is one row more, at the end, whose "Colour by"
    // box speaks for its own well; grouping two as runs of one well puts the run under it.
    app::DeskModel model;
    app::WellsDock dock(model);
    QSignalSpy chosen(&dock, &app::WellsDock::colourChosen);
    const QStringList names{"A", "B", "C"};
    for (int i = 0; i < names.size(); ++i) {
        app::DeskWell well;
        well.name = names[i];
        well.id = 10 + i;
        model.addWell(well);
        ASSERT_EQ(dock.tree()->topLevelItemCount(), i + 1);
        for (int k = 0; k <= i; ++k) {
            ASSERT_EQ(dock.tree()->topLevelItem(k), dock.item(k));
            EXPECT_EQ(dock.item(k)->text(app::WellsDock::Name), names[k]);
        }
    }
    for (int i = 0; i < names.size(); ++i) {
        auto* box =
            qobject_cast<QComboBox*>(dock.tree()->itemWidget(dock.item(i), app::WellsDock::Colour));
        ASSERT_NE(box, nullptr) << i;
        emit box->activated(0);
        ASSERT_EQ(chosen.count(), i + 1);
        EXPECT_EQ(chosen.back().at(0).toInt(), i);
    }
    model.setRunOf(0, 10);
    model.setRunOf(2, 10);
    EXPECT_EQ(dock.tree()->topLevelItemCount(), 2);
    EXPECT_EQ(dock.item(2)->parent(), dock.item(0));
    app::DeskWell later;
    later.name = "D";
    later.id = 13;
    model.addWell(later);
    EXPECT_EQ(dock.tree()->topLevelItemCount(), 3);
    EXPECT_EQ(dock.tree()->topLevelItem(2), dock.item(3));
    EXPECT_EQ(dock.item(2)->parent(), dock.item(0));
}

TEST_F(ManifestWellsTest, TheWarningsDockFollowsEachWellsWarningsAsTheyChange) {
    app::DeskModel model;
    app::WarningsDock dock(model);
    EXPECT_EQ(dock.text(), "No well loaded.");
    app::DeskWell a;
    a.name = "A";
    a.diagnostics.warn("A.las", 7, "a null value in DEVI");
    model.addWell(a);
    app::DeskWell b;
    b.name = "B";
    model.addWell(b);
    EXPECT_NE(dock.text().indexOf("A.las:7"), -1) << dock.text().toStdString();
    const QString before = dock.text();
    // Progress leaves the text; a new warning of B's, or its failure, shows.
    b.loadFraction = 0.5;
    model.updateWell(1, b);
    EXPECT_EQ(dock.text(), before);
    b.diagnostics.warn("B.las", 12, "an arm past the tool's reach");
    model.updateWell(1, b);
    EXPECT_NE(dock.text().indexOf("A.las:7"), -1);
    EXPECT_NE(dock.text().indexOf("B.las:12"), -1) << dock.text().toStdString();
    b.error = "B.las line 40: expected a number";
    model.updateWell(1, b);
    EXPECT_NE(dock.text().indexOf("error: B.las line 40"), -1) << dock.text().toStdString();
    EXPECT_TRUE(dock.windowTitle().startsWith("Warnings (2)")) << dock.windowTitle().toStdString();
}

TEST_F(ManifestWellsTest, CancelStopsAFieldStillLoading) {
    const auto large = test::syntheticLog("example", 4000.0, 0.01);
    app::DeskModel model;
    app::WellSession session(model, nullptr);
    QSignalSpy cancelled(&session, &app::WellSession::loadCancelled);
    session.openWell(QString::fromStdString(large.string()), {});
    session.addWell(QString::fromStdString(large.string()), {});
    session.addWell(QString::fromStdString(large.string()), {});
    ASSERT_TRUE(test::waitUntil([&] { return session.progress().fraction > 0.0; }, 20000));
    EXPECT_TRUE(session.progress().text.startsWith("Loading 3 wells, 0 of 3 done"))
        << session.progress().text.toStdString();
    session.cancelLoading();
    EXPECT_EQ(cancelled.count(), 1);
    EXPECT_EQ(model.wellCount(), 0);
    EXPECT_FALSE(session.progress().busy);
    EXPECT_TRUE(test::waitUntil([&] { return session.retiredLoadsRunning() == 0; }, 10000));
}

}  // namespace
