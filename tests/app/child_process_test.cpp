// app::forkChild and describeEnd: a well's process that crashes ends alone, and says how.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>

#include <gtest/gtest.h>

#include "app/child_process.h"
#include "test_support.h"

using caliper3d::app::describeEnd;
using caliper3d::app::forkChild;
using caliper3d::test::scratch;

namespace {
std::string readText(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}
}  // namespace

TEST(ChildProcessTest, TheChildsOutputGoesToItsFilesAndItsStatusComesBack) {
    const auto out = scratch("child_out.txt"), err = scratch("child_err.txt");
    const pid_t pid = forkChild(
        [] {
            std::printf("to stdout\n");
            std::fprintf(stderr, "to stderr\n");
            return 3;
        },
        out.string(), err.string());
    int status = 0;
    ASSERT_EQ(waitpid(pid, &status, 0), pid);
    EXPECT_EQ(describeEnd(status), "exit status 3");
    EXPECT_EQ(readText(out), "to stdout\n");
    EXPECT_EQ(readText(err), "to stderr\n");
}

TEST(ChildProcessTest, ACrashEndsTheChildAloneAndIsNamed) {
    const auto out = scratch("child_crash_out.txt"), err = scratch("child_crash_err.txt");
    const pid_t pid = forkChild(
        [] {
            // abort(): under AddressSanitizer a SIGSEGV becomes a report and exit status 1.
            std::abort();
            return 0;
        },
        out.string(), err.string());
    int status = 0;
    ASSERT_EQ(waitpid(pid, &status, 0), pid);
    EXPECT_EQ(describeEnd(status).rfind("stopped by signal 6 (", 0), 0U) << describeEnd(status);
    const pid_t fine = forkChild([] { return 0; }, out.string(), err.string());
    ASSERT_EQ(waitpid(fine, &status, 0), fine);
    EXPECT_EQ(describeEnd(status), "");
}
