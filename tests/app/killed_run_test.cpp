// A run killed while it writes leaves the previous output as it was (io/atomic_output.h): the
// caliper3d binary in a process of its own, as a user or a batch scheduler runs it, stopped while
// its temporary file exists.
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "cli_run.h"
#include "io/atomic_output.h"
#include "test_support.h"

namespace fs = std::filesystem;
using caliper3d::test::runCaliper3d;
using caliper3d::test::scratch;

namespace {

std::string readBytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

// Starts the caliper3d binary with `args` (no shell: the pid is the program's), its output to
// `logPath`.
pid_t startCaliper3d(const std::vector<std::string>& args, const fs::path& logPath) {
    std::vector<std::string> all = {CALIPER3D_BINARY};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& arg : all) argv.push_back(arg.data());
    argv.push_back(nullptr);
    const pid_t pid = fork();
    if (pid != 0) return pid;
    const int log = open(logPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (log < 0 || dup2(log, STDOUT_FILENO) < 0 || dup2(log, STDERR_FILENO) < 0) _exit(126);
    execv(argv[0], argv.data());
    _exit(127);
}

// The temporary that process `pid` writes for `target`, if there is one now.
std::optional<fs::path> temporaryOf(const fs::path& target, pid_t pid) {
    const std::string name = target.filename().string();
    const std::string prefix = name + "." + std::to_string(pid) + "-";
    std::error_code error;
    for (fs::directory_iterator it(target.parent_path(), error), end; !error && it != end;
         it.increment(error)) {
        const std::string candidate = it->path().filename().string();
        if (candidate.rfind(prefix, 0) == 0 && caliper3d::io::isTemporaryOf(candidate, name))
            return it->path();
    }
    return std::nullopt;
}

enum class Caught { Writing, Ended, TimedOut };

// Waits until process `pid` writes `target` through a temporary holding at least `bytes`, then
// stops it (SIGSTOP) with that temporary still there: from then on the process cannot rename it
// over the target, however the scheduler ran it. Ended: the process ended first (`status`
// says how), or renamed its temporary before it was stopped (it is then ended here). This waits
// for events, not for a length of time; the time limit only catches a hung run.
Caught stopWhileWriting(pid_t pid, const fs::path& target, std::uintmax_t bytes, int& status) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(5);
    while (std::chrono::steady_clock::now() < deadline) {
        if (waitpid(pid, &status, WNOHANG) == pid) return Caught::Ended;
        const std::optional<fs::path> temporary = temporaryOf(target, pid);
        std::error_code error;
        if (temporary && fs::file_size(*temporary, error) >= bytes && !error) {
            kill(pid, SIGSTOP);
            // Stopped (waitpid WUNTRACED), or ended in between.
            if (waitpid(pid, &status, WUNTRACED) == pid && !WIFSTOPPED(status))
                return Caught::Ended;
            if (fs::exists(*temporary)) return Caught::Writing;
            kill(pid, SIGKILL);  // renamed in between: it has done what this test cannot use
            waitpid(pid, &status, 0);
            return Caught::Ended;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
    return Caught::TimedOut;
}

// A synthetic well of `length_m` metres (kept between runs: the long ones take a while).
fs::path syntheticWell(int length_m) {
    const fs::path log = scratch("killed_run_" + std::to_string(length_m) + "m.las");
    if (!fs::exists(log)) {
        const auto made = runCaliper3d("synth -o " + log.string() + " --length " +
                                       std::to_string(length_m) + " --step 0.05");
        EXPECT_EQ(made.status, 0) << made.output;
    }
    return log;
}

struct KilledRun {
    bool caught = false;  // stopped while writing, then signalled
    int status = 0;       // how it ended
    pid_t pid = 0;
    std::string log;  // what it printed
};

// Runs `verb` over wells of growing length until one is caught writing `target` (a short well
// may be written before the test sees its temporary), then sends it `signal` while stopped.
// A run that ended replaced `target` as it should: `previous` is put back before the next, so
// the run caught is always writing over `previous` (on a slow machine the 2 km well's report
// used to end first and stand in for it).
KilledRun killWhileWriting(const std::string& verb, const fs::path& target, std::uintmax_t bytes,
                           int signal, const std::string& previous) {
    KilledRun run;
    for (const int length_m : {2000, 8000, 32000}) {
        const fs::path well = syntheticWell(length_m);
        const fs::path logPath = scratch("killed_run_" + verb + ".log");
        run.pid = startCaliper3d({verb, well.string(), "-o", target.string()}, logPath);
        const Caught caught = stopWhileWriting(run.pid, target, bytes, run.status);
        run.log = readBytes(logPath);
        if (caught == Caught::TimedOut) {
            ADD_FAILURE() << "caliper3d " << verb << " on a " << length_m
                          << " m well neither wrote " << target << " nor ended in 5 minutes:\n"
                          << run.log;
            return run;
        }
        if (caught == Caught::Writing) {
            kill(run.pid, signal);
            kill(run.pid, SIGCONT);  // a stopped process takes its SIGTERM once continued
            waitpid(run.pid, &run.status, 0);
            run.caught = true;
            return run;
        }
        std::ofstream(target, std::ios::binary | std::ios::trunc) << previous;
    }
    ADD_FAILURE() << "caliper3d " << verb << " wrote " << target
                  << " without a temporary file the test could catch, even from a 32 km well "
                     "(it should write TARGET.PID-N.tmp and rename it):\n"
                  << run.log;
    return run;
}

// The previous good output, written by a short run of the same verb.
std::string writeGoodOutput(const std::string& verb, const fs::path& target) {
    fs::remove(target);
    caliper3d::io::removeTemporaries(target.string());
    const auto good =
        runCaliper3d(verb + " " + syntheticWell(50).string() + " -o " + target.string());
    EXPECT_EQ(good.status, 0) << good.output;
    const std::string bytes = readBytes(target);
    EXPECT_FALSE(bytes.empty());
    return bytes;
}

}  // namespace

TEST(KilledRunTest, AReportKilledWhileWritingLeavesThePreviousReport) {
    const fs::path target = scratch("killed_report.csv");
    const std::string good = writeGoodOutput("report", target);
    // At least one buffer of rows written: the report is under way, not done.
    const KilledRun run = killWhileWriting("report", target, 1, SIGKILL, good);
    ASSERT_TRUE(run.caught);
    ASSERT_TRUE(WIFSIGNALED(run.status) && WTERMSIG(run.status) == SIGKILL) << run.log;
    EXPECT_TRUE(readBytes(target) == good) << "the previous report was replaced";
    // SIGKILL leaves no chance to clean up: the temporary stays beside the intact report.
    EXPECT_EQ(caliper3d::io::removeTemporaries(target.string(), run.pid), 1U);
}

TEST(KilledRunTest, AReportStoppedBySigtermLeavesThePreviousReportAndNoTemporary) {
    const fs::path target = scratch("terminated_report.csv");
    const std::string good = writeGoodOutput("report", target);
    const KilledRun run = killWhileWriting("report", target, 1, SIGTERM, good);
    ASSERT_TRUE(run.caught);
    ASSERT_TRUE(WIFSIGNALED(run.status) && WTERMSIG(run.status) == SIGTERM) << run.log;
    EXPECT_TRUE(readBytes(target) == good) << "the previous report was replaced";
    EXPECT_EQ(caliper3d::io::removeTemporaries(target.string(), run.pid), 0U);
}

TEST(KilledRunTest, AnExportKilledWhileWritingLeavesThePreviousScene) {
    const fs::path target = scratch("killed_export.iv");
    const std::string good = writeGoodOutput("export", target);
    // The scene is serialised before its bytes reach the file: the temporary is empty all that
    // while (where the output itself used to be truncated to nothing).
    const KilledRun run = killWhileWriting("export", target, 0, SIGKILL, good);
    ASSERT_TRUE(run.caught);
    ASSERT_TRUE(WIFSIGNALED(run.status) && WTERMSIG(run.status) == SIGKILL) << run.log;
    EXPECT_TRUE(readBytes(target) == good) << "the previous scene was replaced";
    EXPECT_EQ(caliper3d::io::removeTemporaries(target.string(), run.pid), 1U);
}
