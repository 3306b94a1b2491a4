#include "app/desktop/open_well_dialog.h"

#include <cmath>
#include <fstream>

#include <gtest/gtest.h>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QTableWidget>

#include "desk_test_support.h"
#include "io/column_text_writer.h"
#include "io/las_writer.h"
#include "reconstruction/synthetic/synthetic_well.h"

using namespace caliper3d;

namespace {

io::SectionTable syntheticTable(double bitSize_mm) {
    io::SectionTable table =
        reconstruction::makeSyntheticWell(reconstruction::syntheticProfile("example", 20.0, 0.1));
    table.bitSize_mm.assign(std::isfinite(bitSize_mm) ? table.rowCount() : 0, bitSize_mm);
    return table;
}

// The window of the bundled example draws at x50 with its 8.5 in bit size.
app::LoadOptions exampleLook() {
    app::LoadOptions look;
    look.read.bitSize_mm = 215.9;
    look.radialExaggeration = 50.0;
    return look;
}

QString curveRole(const QTableWidget& curves, const QString& mnemonic) {
    for (int row = 0; row < curves.rowCount(); ++row)
        if (curves.item(row, 0)->text() == mnemonic) return curves.item(row, 2)->text();
    return {};
}

}  // namespace

TEST(OpenWellDialogTest, PrefillsWhatTheExampleColumnTextHolds) {
    CALIPER3D_REQUIRE_GUI();
    const io::SectionTable table = syntheticTable(io::kNaN);
    const auto path = test::scratch("dialog_example.txt");
    io::writeColumnTextFile(path.string(), table);
    app::OpenWellDialog dialog(QString::fromStdString(path.string()), exampleLook());

    ASSERT_TRUE(dialog.acceptable()) << dialog.errorText().toStdString();
    ASSERT_NE(dialog.info(), nullptr);
    EXPECT_NE(dialog.info()->format.find("column text"), std::string::npos);
    EXPECT_EQ(dialog.info()->rows, table.rowCount());
    EXPECT_EQ(dialog.info()->arms, table.armCount);
    EXPECT_NEAR(dialog.info()->top_m, table.depth_m.front(), 1e-6);
    EXPECT_NEAR(dialog.info()->bottom_m, table.depth_m.back(), 1e-6);
    EXPECT_TRUE(std::isnan(dialog.info()->bitSize_mm));
    const auto* summary = dialog.findChild<QLabel*>("summary");
    EXPECT_TRUE(summary->text().contains("Bit size in the log: none in the log"))
        << summary->text().toStdString();
    EXPECT_TRUE(dialog.findChild<QLineEdit*>("bitSize")->placeholderText().startsWith("none"));
    const auto* curves = dialog.findChild<QTableWidget*>("curves");
    EXPECT_EQ(curves->rowCount(), static_cast<int>(dialog.info()->curves.size()));
    EXPECT_EQ(curveRole(*curves, "R1"), "radius");
    // Nothing of the example's options but the look.
    EXPECT_FALSE(dialog.request().options.read.bitSize_mm);
    EXPECT_EQ(dialog.request().options.radialExaggeration, 50.0);
}

TEST(OpenWellDialogTest, PrefillsALasFilesOwnBitSizeAndNameAndMapsAnOverride) {
    CALIPER3D_REQUIRE_GUI();
    const io::SectionTable table = syntheticTable(156.0);
    const auto path = test::scratch("dialog_star.las");
    io::LasWriteOptions las;
    las.wellName = "LEWIS 7-22";
    io::writeLasFile(path.string(), table, las);
    app::OpenWellDialog dialog(QString::fromStdString(path.string()), exampleLook());

    ASSERT_TRUE(dialog.acceptable()) << dialog.errorText().toStdString();
    EXPECT_EQ(dialog.info()->format, "LAS 2.0");
    EXPECT_EQ(dialog.info()->wellName, "LEWIS 7-22");
    EXPECT_NEAR(dialog.info()->bitSize_mm, 156.0, 1e-9);
    EXPECT_TRUE(dialog.findChild<QLineEdit*>("bitSize")->placeholderText().contains("156.0 mm"));
    EXPECT_EQ(curveRole(*dialog.findChild<QTableWidget*>("curves"), "BS"), "bit size");
    // The log's own bit size stands unless one is typed: the example's never comes in.
    EXPECT_FALSE(dialog.request().options.read.bitSize_mm);

    dialog.findChild<QLineEdit*>("bitSize")->setText("6.5in");
    auto* radius = dialog.findChild<QComboBox*>("radiusUnit");
    radius->setCurrentIndex(radius->findData("mm"));
    dialog.describe();
    ASSERT_TRUE(dialog.acceptable()) << dialog.errorText().toStdString();
    ASSERT_TRUE(dialog.request().options.read.bitSize_mm);
    EXPECT_NEAR(*dialog.request().options.read.bitSize_mm, 165.1, 1e-9);
    EXPECT_EQ(dialog.request().options.read.radiusUnit, io::LengthUnit::Millimetre);
    EXPECT_NEAR(dialog.info()->bitSize_mm, 156.0, 1e-9) << "the log's, shown beside the override";
    EXPECT_EQ(dialog.choices().options.at("bit-size"), "6.5in");
    EXPECT_EQ(dialog.choices().options.at("radius-unit"), "mm");
}

TEST(OpenWellDialogTest, ACurveThatIsNotThereDisablesOkAndSaysWhich) {
    CALIPER3D_REQUIRE_GUI();
    const auto path = test::scratch("dialog_roles.las");
    io::writeLasFile(path.string(), syntheticTable(156.0));
    app::OpenWellDialog dialog(QString::fromStdString(path.string()), {});
    ASSERT_TRUE(dialog.acceptable());
    dialog.findChild<QLineEdit*>("radii")->setText("R1,R2,NOPE");
    dialog.describe();
    EXPECT_FALSE(dialog.acceptable());
    EXPECT_TRUE(dialog.errorText().contains("NOPE")) << dialog.errorText().toStdString();
    dialog.findChild<QLineEdit*>("radii")->setText("");
    dialog.findChild<QLineEdit*>("wellhead")->setText("1,2");
    dialog.describe();
    EXPECT_FALSE(dialog.acceptable());
    EXPECT_TRUE(dialog.errorText().contains("--wellhead")) << dialog.errorText().toStdString();
    dialog.findChild<QLineEdit*>("wellhead")->setText("512300,6801200,25.5");
    dialog.describe();
    EXPECT_TRUE(dialog.acceptable()) << dialog.errorText().toStdString();
    ASSERT_TRUE(dialog.request().wells.front().wellhead);
    EXPECT_EQ(dialog.request().wells.front().wellhead->northing_m, 6801200.0);
}

TEST(OpenWellDialogTest, ABadFileDisablesOkNamingTheFileAndLine) {
    CALIPER3D_REQUIRE_GUI();
    const io::SectionTable table = syntheticTable(io::kNaN);
    const auto path = test::scratch("dialog_bad.txt");
    io::writeColumnTextFile(path.string(), table);
    {
        std::ofstream out(path, std::ios::app);
        out << "999.0 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15\n";
    }
    std::size_t lines = 0;
    {
        std::ifstream in(path);
        std::string line;
        while (std::getline(in, line)) ++lines;
    }
    app::OpenWellDialog dialog(QString::fromStdString(path.string()), {});
    EXPECT_FALSE(dialog.acceptable());
    const std::string where = path.string() + ":" + std::to_string(lines);
    EXPECT_TRUE(dialog.errorText().startsWith(QString::fromStdString(where)))
        << dialog.errorText().toStdString() << " (expected " << where << ")";
    EXPECT_EQ(dialog.info(), nullptr);
}

TEST(OpenWellDialogTest, PrefillsTheRealStarLog) {
    CALIPER3D_REQUIRE_GUI();
    const auto path = test::sharedData() / "real" / "1AA072209208W400_WL_0477502_STAR_FIELD.las";
    CALIPER3D_REQUIRE_DATA(path);
    app::OpenWellDialog dialog(QString::fromStdString(path.string()), exampleLook());
    ASSERT_TRUE(dialog.acceptable()) << dialog.errorText().toStdString();
    // `caliper3d info` on it: 2114 sections, six RAD*QH radii, a 156 mm bit.
    EXPECT_EQ(dialog.info()->rows, 2114u);
    EXPECT_EQ(dialog.info()->arms, 6);
    EXPECT_NEAR(dialog.info()->bitSize_mm, 156.0, 0.05);
    EXPECT_FALSE(dialog.request().options.read.bitSize_mm) << "the example's 8.5 in came in";
}

TEST(OpenWellDialogTest, StartsFromARecentFilesChoicesAndGivesThemBack) {
    CALIPER3D_REQUIRE_GUI();
    const auto path = test::scratch("dialog_recent.txt");
    io::writeColumnTextFile(path.string(), syntheticTable(io::kNaN));
    const QString file = QString::fromStdString(path.string());
    const app::OpenChoices recent{
        file, {{"bit-size", "6.5in"}, {"depth-unit", "ft"}, {"arms", "6"}, {"nulls", "declared"}}};
    app::OpenWellDialog dialog(file, {}, nullptr, recent);
    EXPECT_EQ(dialog.findChild<QLineEdit*>("bitSize")->text(), "6.5in");
    EXPECT_EQ(dialog.findChild<QComboBox*>("depthUnit")->currentData().toString(), "ft");
    EXPECT_EQ(dialog.findChild<QComboBox*>("radiusUnit")->currentData().toString(), "");
    // Every field the table gives the dialog, and an option without a field kept as it was.
    EXPECT_EQ(dialog.choices().options, recent.options);
    ASSERT_TRUE(dialog.request().options.read.bitSize_mm);
    EXPECT_NEAR(*dialog.request().options.read.bitSize_mm, 165.1, 1e-9);
    EXPECT_EQ(dialog.request().options.read.nullPolicy, io::NullPolicy::Declared);
}
