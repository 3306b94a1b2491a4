// io::AtomicOutput: the target is replaced whole on commit, or left as it was.
#include "io/atomic_output.h"

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "test_support.h"

using caliper3d::io::AtomicOutput;
using caliper3d::io::isTemporaryOf;
using caliper3d::io::removeTemporaries;
namespace fs = std::filesystem;

namespace {

// A folder of its own for each test, so that "no temporary left" can look at all of it.
fs::path freshFolder(const std::string& name) {
    return caliper3d::test::freshScratchFolder("atomic_output/" + name);
}

std::string readText(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

void writeText(const fs::path& file, const std::string& text) {
    std::ofstream(file, std::ios::binary) << text;
}

// The names in `folder`, other than `keep`.
std::vector<std::string> othersIn(const fs::path& folder, const std::string& keep) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder))
        if (entry.path().filename() != keep) names.push_back(entry.path().filename().string());
    return names;
}

}  // namespace

TEST(AtomicOutputTest, CommitReplacesTheTargetAndLeavesNoTemporary) {
    const fs::path folder = freshFolder("commit");
    const fs::path target = folder / "report.csv";
    writeText(target, "old\n");
    {
        AtomicOutput out(target.string());
        out.stream() << "new\n";
        out.stream().flush();
        // Until the commit the target is the old file, the new one a temporary beside it.
        EXPECT_EQ(readText(target), "old\n");
        EXPECT_NE(out.path(), target.string());
        EXPECT_EQ(fs::path(out.path()).parent_path(), folder);
        EXPECT_TRUE(isTemporaryOf(fs::path(out.path()).filename().string(), "report.csv"))
            << out.path();
        EXPECT_EQ(readText(out.path()), "new\n");
        out.commit();
        EXPECT_TRUE(out.committed());
    }
    EXPECT_EQ(readText(target), "new\n");
    EXPECT_TRUE(othersIn(folder, "report.csv").empty());
}

TEST(AtomicOutputTest, AnExceptionBeforeCommitLeavesTheOldTargetAndNoTemporary) {
    const fs::path folder = freshFolder("exception");
    const fs::path target = folder / "scene.iv";
    writeText(target, "the last good scene\n");
    try {
        AtomicOutput out(target.string());
        out.stream() << "half a scene";
        out.stream().flush();
        throw std::runtime_error("the writer failed");
    } catch (const std::runtime_error&) {
    }
    EXPECT_EQ(readText(target), "the last good scene\n");
    EXPECT_TRUE(othersIn(folder, "scene.iv").empty());
}

TEST(AtomicOutputTest, NoCommitLeavesNoFileWhereThereWasNone) {
    const fs::path folder = freshFolder("new");
    {
        AtomicOutput out((folder / "new.csv").string());
        out.stream() << "unfinished";
    }
    EXPECT_TRUE(fs::is_empty(folder));
}

TEST(AtomicOutputTest, AFolderThatIsNotThereGivesAnErrorNamingTheFile) {
    const fs::path folder = freshFolder("missing");
    const std::string target = (folder / "no such folder" / "out.csv").string();
    AtomicOutput out(target);
    try {
        out.stream() << "x";
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind(target + ": ", 0), 0U) << message;
        EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;
    }
    EXPECT_TRUE(fs::is_empty(folder));
}

TEST(AtomicOutputTest, APathALibraryWritesIsRenamedOnCommit) {
    const fs::path folder = freshFolder("library");
    const fs::path target = folder / "well.glb";
    writeText(target, "old");
    AtomicOutput out(target.string());
    writeText(out.path(), "written by a library that opens its own file");
    EXPECT_EQ(readText(target), "old");
    out.commit();
    EXPECT_EQ(readText(target), "written by a library that opens its own file");
    EXPECT_TRUE(othersIn(folder, "well.glb").empty());
}

TEST(AtomicOutputTest, ACommitWithNothingWrittenIsAnErrorAndKeepsTheTarget) {
    const fs::path folder = freshFolder("nothing");
    const fs::path target = folder / "picture.png";
    writeText(target, "old");
    AtomicOutput out(target.string());
    try {
        out.commit();
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()).rfind(target.string() + ": ", 0), 0U) << e.what();
    }
    EXPECT_FALSE(out.committed());
    EXPECT_EQ(readText(target), "old");
}

TEST(AtomicOutputTest, AWriteErrorIsReportedNamingTheFile) {
    // /dev/full takes no byte: a device, so written directly (nothing to keep, nothing renamed).
    if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
    AtomicOutput out("/dev/full");
    EXPECT_EQ(out.path(), "/dev/full");
    out.stream() << std::string(1 << 16, 'x');
    try {
        out.commit();
        FAIL() << "no error";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()).rfind("/dev/full: write failed", 0), 0U) << e.what();
    }
    EXPECT_TRUE(fs::is_character_file("/dev/full"));
}

TEST(AtomicOutputTest, ADeviceIsWrittenDirectlyAndNeverReplaced) {
    AtomicOutput out("/dev/null");
    EXPECT_EQ(out.path(), "/dev/null");
    out.stream() << "discarded\n";
    out.commit();
    EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

TEST(AtomicOutputTest, ASymbolicLinkKeepsPointingAtTheNewFile) {
    const fs::path folder = freshFolder("link");
    writeText(folder / "real.csv", "old");
    fs::create_symlink("real.csv", folder / "link.csv");
    AtomicOutput out((folder / "link.csv").string());
    out.stream() << "new";
    out.commit();
    EXPECT_TRUE(fs::is_symlink(folder / "link.csv"));
    EXPECT_EQ(readText(folder / "real.csv"), "new");
}

TEST(AtomicOutputTest, AReplacedFileKeepsItsPermissions) {
    const fs::path folder = freshFolder("mode");
    const fs::path target = folder / "shared.csv";
    writeText(target, "old");
    ASSERT_EQ(chmod(target.c_str(), 0640), 0);
    AtomicOutput out(target.string());
    out.stream() << "new";
    out.commit();
    struct stat info {};
    ASSERT_EQ(stat(target.c_str(), &info), 0);
    EXPECT_EQ(info.st_mode & 07777, 0640U);
}

TEST(AtomicOutputTest, TemporaryNamesAreRecognisedAndRemovedByProcess) {
    EXPECT_TRUE(isTemporaryOf("a.csv.123-0.tmp", "a.csv"));
    EXPECT_TRUE(isTemporaryOf("a.csv.9-17.tmp", "a.csv"));
    EXPECT_FALSE(isTemporaryOf("a.csv", "a.csv"));
    EXPECT_FALSE(isTemporaryOf("a.csv.tmp", "a.csv"));
    EXPECT_FALSE(isTemporaryOf("a.csv.123.tmp", "a.csv"));
    EXPECT_FALSE(isTemporaryOf("a.csv.x-0.tmp", "a.csv"));
    EXPECT_FALSE(isTemporaryOf("a.csv.123-.tmp", "a.csv"));
    EXPECT_FALSE(isTemporaryOf("b.csv.123-0.tmp", "a.csv"));
    EXPECT_FALSE(isTemporaryOf("a.csv.123-0.tmpx", "a.csv"));

    const fs::path folder = freshFolder("leftovers");
    for (const char* name :
         {"a.csv", "a.csv.123-0.tmp", "a.csv.123-4.tmp", "a.csv.77-0.tmp", "ab.csv.123-0.tmp"})
        writeText(folder / name, "x");
    EXPECT_EQ(removeTemporaries((folder / "a.csv").string(), 123), 2U);
    EXPECT_TRUE(fs::exists(folder / "a.csv.77-0.tmp"));
    EXPECT_TRUE(fs::exists(folder / "ab.csv.123-0.tmp"));
    EXPECT_TRUE(fs::exists(folder / "a.csv"));
    EXPECT_EQ(removeTemporaries((folder / "a.csv").string()), 1U);
    EXPECT_FALSE(fs::exists(folder / "a.csv.77-0.tmp"));
}

TEST(AtomicOutputTest, SigtermRemovesTheTemporaryAndKeepsTheTarget) {
    const fs::path folder = freshFolder("sigterm");
    const fs::path target = folder / "report.csv";
    writeText(target, "old\n");
    int ready[2];
    ASSERT_EQ(pipe(ready), 0);
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
        close(ready[0]);
        AtomicOutput out(target.string());
        out.stream() << "half a report";
        out.stream().flush();
        const char byte = 1;
        if (write(ready[1], &byte, 1) != 1) _exit(3);
        for (;;) pause();  // ended by the signal
    }
    close(ready[1]);
    char byte = 0;
    ASSERT_EQ(read(ready[0], &byte, 1), 1);  // the temporary is written
    close(ready[0]);
    EXPECT_EQ(othersIn(folder, "report.csv").size(), 1U);
    ASSERT_EQ(kill(pid, SIGTERM), 0);
    int status = 0;
    ASSERT_EQ(waitpid(pid, &status, 0), pid);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << status;
    EXPECT_EQ(readText(target), "old\n");
    EXPECT_TRUE(othersIn(folder, "report.csv").empty());
}
