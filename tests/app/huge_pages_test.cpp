#include "app/huge_pages.h"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "cli_run.h"
#include "test_support.h"

using caliper3d::app::HugePageContext;
using caliper3d::app::hugePageTunables;
using caliper3d::app::kHugePagesFrom_bytes;

namespace {

constexpr std::uintmax_t kMiB = std::uintmax_t{1} << 20;

HugePageContext fieldOf(std::uintmax_t bytes) {
    HugePageContext context;
    context.thpMode = "always [madvise] never\n";
    context.inputBytes = bytes;
    context.threshold = kHugePagesFrom_bytes;
    return context;
}

// How many times the dynamic linker started the program for `arguments` (glibc's LD_DEBUG
// statistics, once a start), and what it wrote on stdout. `name`: the scratch file its
// stderr goes to, a test's own (ctest runs the tests side by side).
struct Started {
    int starts = 0;
    std::string output;
};
Started startsOf(const std::string& name, const std::string& environment,
                 const std::string& arguments) {
    const std::string err = caliper3d::test::scratch(name + "_err.txt").string();
    const std::string command = "env " + environment + " LD_DEBUG=statistics " +
                                std::string(CALIPER3D_BINARY) + " " + arguments + " 2>" + err;
    Started out;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return out;
    char buffer[4096];
    while (std::fgets(buffer, sizeof buffer, pipe)) out.output += buffer;
    pclose(pipe);
    std::ifstream log(err);
    for (std::string line; std::getline(log, line);)
        if (line.find("total startup time") != std::string::npos) ++out.starts;
    return out;
}

bool givenOnRequest() {
    std::ifstream mode("/sys/kernel/mm/transparent_hugepage/enabled");
    std::stringstream text;
    text << mode.rdbuf();
    return text.str().find("[madvise]") != std::string::npos;
}

}  // namespace

TEST(HugePagesTest, AskedForFromTheThresholdWhereTheKernelGivesThemOnRequest) {
    EXPECT_FALSE(hugePageTunables(fieldOf(63 * kMiB)));
    EXPECT_EQ(hugePageTunables(fieldOf(64 * kMiB)), "glibc.malloc.hugetlb=1");
    // Added to the user's own tunables.
    HugePageContext theirs = fieldOf(200 * kMiB);
    theirs.tunables = "glibc.malloc.arena_max=2";
    EXPECT_EQ(hugePageTunables(theirs), "glibc.malloc.arena_max=2:glibc.malloc.hugetlb=1");
    // Never a second time, nor against the user's choice.
    theirs.tunables = "glibc.malloc.hugetlb=0";
    EXPECT_FALSE(hugePageTunables(theirs));
    // Every process has them already, or none can.
    HugePageContext kernel = fieldOf(200 * kMiB);
    kernel.thpMode = "[always] madvise never\n";
    EXPECT_FALSE(hugePageTunables(kernel));
    kernel.thpMode = "always madvise [never]\n";
    EXPECT_FALSE(hugePageTunables(kernel));
    kernel.thpMode = "";  // no such file
    EXPECT_FALSE(hugePageTunables(kernel));
    // CALIPER3D_HUGE_PAGES: "always" whatever the input; "0" (or the restart's "1") never.
    HugePageContext set = fieldOf(10 * kMiB);
    set.setting = "always";
    EXPECT_TRUE(hugePageTunables(set));
    set.inputBytes = 200 * kMiB;
    for (const char* no : {"0", "1", "no"}) {
        set.setting = no;
        EXPECT_FALSE(hugePageTunables(set)) << no;
    }
    // The window of one well: only when told "always".
    HugePageContext window = fieldOf(200 * kMiB);
    window.window = true;
    window.files = 1;
    EXPECT_FALSE(hugePageTunables(window));
    window.setting = "always";
    EXPECT_TRUE(hugePageTunables(window));
    // The window of a field: from the threshold, as the verbs.
    window.setting.clear();
    window.files = 2;
    EXPECT_TRUE(hugePageTunables(window));
    window.inputBytes = 63 * kMiB;
    EXPECT_FALSE(hugePageTunables(window));
    // batch: from no input at all.
    HugePageContext batch = fieldOf(0);
    batch.threshold = 0;
    EXPECT_TRUE(hugePageTunables(batch));
}

TEST(HugePagesTest, ACommandAskingForThemStartsOnceMoreWithTheSameResult) {
    if (!givenOnRequest()) GTEST_SKIP() << "transparent huge pages are not given on request here";
    const std::string log = caliper3d::test::scratch("huge_pages.txt").string();
    ASSERT_EQ(caliper3d::test::runCaliper3d("synth -o " + log + " --length 20 --step 0.1").status,
              0);
    const std::string arguments = "info '" + log + "'";
    const Started asked = startsOf("huge_pages_asked", "CALIPER3D_HUGE_PAGES=always", arguments);
    const Started no = startsOf("huge_pages_no", "CALIPER3D_HUGE_PAGES=0", arguments);
    const Started theirs =
        startsOf("huge_pages_theirs",
                 "CALIPER3D_HUGE_PAGES=always GLIBC_TUNABLES=glibc.malloc.hugetlb=0", arguments);
    const Started small =
        startsOf("huge_pages_small", "-u CALIPER3D_HUGE_PAGES", arguments);  // far below 64 MiB
    EXPECT_EQ(asked.starts, 2);
    EXPECT_EQ(no.starts, 1);
    EXPECT_EQ(theirs.starts, 1);
    EXPECT_EQ(small.starts, 1);
    EXPECT_NE(no.output.find("201"), std::string::npos) << no.output;  // its rows
    EXPECT_EQ(asked.output, no.output);
}

TEST(HugePagesTest, BatchAsksForThemWhateverItsManifest) {
    if (!givenOnRequest()) GTEST_SKIP() << "transparent huge pages are not given on request here";
    const std::string log = caliper3d::test::scratch("huge_pages_batch.txt").string();
    ASSERT_EQ(caliper3d::test::runCaliper3d("synth -o " + log + " --length 20 --step 0.1").status,
              0);
    const std::string manifest = caliper3d::test::scratch("huge_pages_batch.csv").string();
    std::ofstream(manifest) << "file,verb\n" << log << ",report\n";
    const std::string out = caliper3d::test::scratch("huge_pages_batch_out").string();
    const std::string arguments = "batch '" + manifest + "' -o '" + out + "/'";
    EXPECT_EQ(startsOf("huge_pages_batch_asked", "-u CALIPER3D_HUGE_PAGES", arguments).starts, 2);
    EXPECT_EQ(startsOf("huge_pages_batch_no", "CALIPER3D_HUGE_PAGES=0", arguments).starts, 1);
}
