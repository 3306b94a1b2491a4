#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "io/parse_error.h"
#include "reconstruction/load/load_well.h"
#include "test_support.h"

using namespace caliper3d;

// Every real log in the reference data either reads and reconstructs, or is
// refused with a ParseError that names the file: never a crash.
TEST(RealDataSmokeTest, EveryRealLogReadsOrIsRefusedByName) {
    CALIPER3D_REQUIRE_DATA(test::sharedData() / "real");
    int files = 0;
    for (const char* folder : {"real", "vendors"}) {
        if (!std::filesystem::exists(test::sharedData() / folder)) continue;
        for (const auto& entry : std::filesystem::directory_iterator(test::sharedData() / folder)) {
            if (!entry.is_regular_file()) continue;
            ++files;
            const std::string path = entry.path().string();
            try {
                const reconstruction::LoadedWell well =
                    reconstruction::loadWell({path, {}, {}, {}}, reconstruction::LoadOptions{});
                EXPECT_GT(well.table->rowCount(), 0u) << path;
                EXPECT_GT(well.geometry->segmentCount(), 0u) << path;
            } catch (const io::ParseError& e) {
                EXPECT_EQ(e.file(), path);
            } catch (const std::invalid_argument& e) {
                EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
            }
        }
    }
    EXPECT_GE(files, 3);
}

namespace {
struct InfoRun {
    int status = -1;
    std::string output;  // stdout and stderr together
};

InfoRun info(const std::string& path) {
    InfoRun r;
    FILE* pipe = popen((std::string(CALIPER3D_BINARY) + " info '" + path + "' 2>&1").c_str(), "r");
    if (!pipe) return r;
    char buffer[4096];
    while (std::fgets(buffer, sizeof buffer, pipe)) r.output += buffer;
    const int raw = pclose(pipe);
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    return r;
}
}  // namespace

// `caliper3d info` on every file of the reference data: exit 0 with a
// description (logs of any kind, surveys), or exit 1 with one line saying
// why, for what is neither a log nor a survey. Never a crash.
TEST(RealDataSmokeTest, InfoDescribesEveryReferenceFile) {
    const auto root = test::sharedData();
    CALIPER3D_REQUIRE_DATA(root / "las_edge_cases");
    int described = 0, refused = 0, withoutCaliper = 0;
    for (const char* folder : {"las_edge_cases", "real", "surveys"}) {
        for (const auto& entry : std::filesystem::directory_iterator(root / folder)) {
            const std::string path = entry.path().string();
            SCOPED_TRACE(path);
            const InfoRun r = info(path);
            const std::string name = entry.path().filename().string();
            if (name == "missing_a_section.las" ||
                name == "missing_well_curves_ascii_section.las" ||
                entry.path().extension() == ".json") {
                EXPECT_EQ(r.status, 1) << r.output;
                EXPECT_EQ(r.output.rfind("caliper3d info: " + path + ":", 0), 0u) << r.output;
                EXPECT_NE(r.output.find(": expected "), std::string::npos) << r.output;
                ++refused;
                continue;
            }
            // A log without caliper curves is described, and fails as every other verb would.
            const bool noCaliper =
                r.output.find("no caliper curve recognised") != std::string::npos;
            EXPECT_EQ(r.status, noCaliper ? 1 : 0) << r.output;
            EXPECT_NE(r.output.find("file:      " + path + "\nformat:    "), std::string::npos)
                << r.output;
            EXPECT_NE(r.output.find("\nwarnings:  "), std::string::npos) << r.output;
            if (noCaliper) {
                EXPECT_NE(r.output.find("caliper:   none recognised"), std::string::npos)
                    << r.output;
                ++withoutCaliper;
            }
            if (std::string(folder) == "surveys") {
                EXPECT_NE(r.output.find("format:    deviation survey"), std::string::npos)
                    << r.output;
            }
            ++described;
        }
    }
    EXPECT_EQ(described, 31);
    EXPECT_EQ(refused, 4);
    EXPECT_GT(withoutCaliper, 0);  // the peers' resistivity and porosity logs
}
