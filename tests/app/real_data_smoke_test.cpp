#include <filesystem>
#include <memory>

#include <gtest/gtest.h>

#include "app/input_options.h"
#include "io/parse_error.h"
#include "reconstruction/well_geometry.h"
#include "test_support.h"

using namespace caliper3d;

// Every real log in the reference data either reads and reconstructs, or is
// refused with a ParseError that names the file: never a crash.
TEST(RealDataSmokeTest, EveryRealLogReadsOrIsRefusedByName) {
    const auto folder = test::sharedData() / "real";
    CALIPER3D_REQUIRE_DATA(folder);
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        if (!entry.is_regular_file()) continue;
        ++files;
        const std::string path = entry.path().string();
        try {
            io::Diagnostics diagnostics;
            auto table = std::make_shared<const io::SectionTable>(
                app::readWellFile(path, app::InputOptions{}, &diagnostics));
            EXPECT_GT(table->rowCount(), 0u) << path;
            reconstruction::WellGeometry geometry(table, reconstruction::GeometryOptions{});
            EXPECT_GT(geometry.segmentCount(), 0u) << path;
        } catch (const io::ParseError& e) {
            EXPECT_EQ(e.file(), path);
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
        }
    }
    EXPECT_GE(files, 3);
}
