#include "io/atomic_output.h"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace caliper3d::io {

namespace fs = std::filesystem;

namespace {

// The temporaries alive in this process, for a signal handler to remove. A handler may call
// only async-signal-safe functions (unlink, raise) and read only what needs no lock, so each
// path sits in a fixed slot whose state is one lock-free atomic: the handler unlinks the slots
// it finds live, and a slot is filled before it is marked live.
constexpr int kSlots = 64;
constexpr std::size_t kPathBytes = 4096;
enum SlotState : int { kFree, kFilling, kLive };
struct Slot {
    std::atomic<int> state{kFree};
    pid_t owner = 0;  // a forked child inherits the slots: it removes only its own temporaries
    char path[kPathBytes];
};
Slot g_slots[kSlots];
static_assert(std::atomic<int>::is_always_lock_free, "a signal handler reads the slot states");

extern "C" void removeTemporariesAndEnd(int signal) {
    const int savedErrno = errno;
    const pid_t self = getpid();
    for (Slot& slot : g_slots)
        if (slot.state.load(std::memory_order_acquire) == kLive && slot.owner == self)
            unlink(slot.path);
    errno = savedErrno;
    // SA_RESETHAND has put the default action back: raised again, the signal ends the process
    // as it would have without us (once this handler returns and unblocks it).
    raise(signal);
}

// Installs the handler for the signals that ask a run to stop, once, and only where the
// program left them at their default action (an ignored SIGINT of a background job stays
// ignored; a program's own handler stays its own).
void installSignalHandlers() {
    static std::once_flag once;
    std::call_once(once, [] {
        for (const int signal : {SIGINT, SIGTERM, SIGHUP}) {
            struct sigaction current {};
            if (sigaction(signal, nullptr, &current) != 0 || current.sa_handler != SIG_DFL)
                continue;
            struct sigaction action {};
            action.sa_handler = &removeTemporariesAndEnd;
            sigemptyset(&action.sa_mask);
            action.sa_flags = SA_RESETHAND;
            sigaction(signal, &action, nullptr);
        }
    });
}

// A slot holding `path`, or -1 when all are taken or the path is too long (the temporary is
// then only removed by its writer, as after a SIGKILL).
int registerTemporary(const std::string& path) {
    if (path.size() >= kPathBytes) return -1;
    installSignalHandlers();
    for (int i = 0; i < kSlots; ++i) {
        int expected = kFree;
        if (!g_slots[i].state.compare_exchange_strong(expected, kFilling)) continue;
        g_slots[i].owner = getpid();
        std::memcpy(g_slots[i].path, path.c_str(), path.size() + 1);
        g_slots[i].state.store(kLive, std::memory_order_release);
        return i;
    }
    return -1;
}

void releaseTemporary(int slot) {
    if (slot >= 0) g_slots[slot].state.store(kFree, std::memory_order_release);
}

std::string reason(int error) {
    return std::generic_category().message(error);
}

// Writes the file's data to disk before the rename makes it the target: otherwise a power cut
// just after the rename can leave an empty target (the rename reached the disk, the data not).
bool syncFile(const std::string& path) {
    const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return false;
    const bool synced = fsync(fd) == 0;
    return close(fd) == 0 && synced;
}

// The rename itself reaches the disk with its folder; best effort (some file systems refuse).
void syncFolder(const std::string& file) {
    const fs::path folder = fs::path(file).parent_path();
    const int fd = open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;
    fsync(fd);
    close(fd);
}

std::atomic<unsigned> g_sequence{0};

}  // namespace

AtomicOutput::AtomicOutput(std::string target)
    : m_target(std::move(target)), m_finalPath(m_target) {
    struct stat linkInfo {};
    struct stat info {};
    const bool exists = stat(m_target.c_str(), &info) == 0;
    if (exists && !S_ISREG(info.st_mode) && !S_ISDIR(info.st_mode)) {
        m_direct = true;
        m_path = m_target;
        return;
    }
    if (exists && lstat(m_target.c_str(), &linkInfo) == 0 && S_ISLNK(linkInfo.st_mode)) {
        std::error_code error;
        const fs::path resolved = fs::canonical(m_target, error);
        if (!error) m_finalPath = resolved.string();
    }
    m_path = m_finalPath + "." + std::to_string(static_cast<long>(getpid())) + "-" +
             std::to_string(g_sequence.fetch_add(1)) + ".tmp";
    m_slot = registerTemporary(m_path);
}

AtomicOutput::~AtomicOutput() {
    if (!m_committed) discard();
    releaseTemporary(m_slot);
}

std::ostream& AtomicOutput::stream() {
    if (m_stream.is_open()) return m_stream;
    errno = 0;
    m_stream.open(m_path, std::ios::binary | std::ios::trunc);
    if (!m_stream)
        throw std::runtime_error(m_target + ": cannot open for writing" +
                                 (errno ? " (" + reason(errno) + ")" : std::string()));
    return m_stream;
}

void AtomicOutput::commit() {
    if (m_committed) return;
    if (m_stream.is_open()) {
        m_stream.close();
        if (!m_stream) {
            discard();
            throw std::runtime_error(m_target + ": write failed (disk full?)");
        }
    }
    if (m_direct) {
        m_committed = true;
        return;
    }
    struct stat info {};
    if (stat(m_path.c_str(), &info) != 0) {
        // The writer never made the file (or a signal handler of ours removed it).
        const int error = errno;
        throw std::runtime_error(m_target + ": nothing was written (" + reason(error) + ")");
    }
    if (!syncFile(m_path)) {
        const int error = errno;
        discard();
        throw std::runtime_error(m_target + ": write failed (" + reason(error) + ")");
    }
    // A replaced file keeps its permissions; a new one gets the umask's, as before.
    struct stat old {};
    if (stat(m_finalPath.c_str(), &old) == 0 && S_ISREG(old.st_mode))
        chmod(m_path.c_str(), old.st_mode & 07777);
    if (std::rename(m_path.c_str(), m_finalPath.c_str()) != 0) {
        const int error = errno;
        discard();
        throw std::runtime_error(m_target + ": cannot replace the file (" + reason(error) + ")");
    }
    m_committed = true;
    releaseTemporary(m_slot);
    m_slot = -1;
    syncFolder(m_finalPath);
}

void AtomicOutput::discard() noexcept {
    if (m_stream.is_open()) m_stream.close();
    if (!m_direct) unlink(m_path.c_str());
}

bool isTemporaryOf(const std::string& fileName, const std::string& targetFileName) {
    // TARGET "." PID "-" N ".tmp"
    const std::string tail = ".tmp";
    if (fileName.size() < targetFileName.size() + 1 + 1 + 1 + 1 + tail.size()) return false;
    if (fileName.compare(0, targetFileName.size(), targetFileName) != 0) return false;
    if (fileName[targetFileName.size()] != '.') return false;
    if (fileName.compare(fileName.size() - tail.size(), tail.size(), tail) != 0) return false;
    const std::string middle = fileName.substr(
        targetFileName.size() + 1, fileName.size() - targetFileName.size() - 1 - tail.size());
    const std::size_t dash = middle.find('-');
    if (dash == 0 || dash == std::string::npos || dash + 1 == middle.size()) return false;
    for (std::size_t i = 0; i < middle.size(); ++i)
        if (i != dash && (middle[i] < '0' || middle[i] > '9')) return false;
    return true;
}

std::size_t removeTemporaries(const std::string& target, long pid) {
    const fs::path path(target);
    const fs::path folder = path.parent_path().empty() ? fs::path(".") : path.parent_path();
    const std::string name = path.filename().string();
    const std::string pidPrefix = name + "." + std::to_string(pid) + "-";
    std::size_t removed = 0;
    std::error_code error;
    for (fs::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
        const std::string candidate = it->path().filename().string();
        if (!isTemporaryOf(candidate, name)) continue;
        if (pid != 0 && candidate.compare(0, pidPrefix.size(), pidPrefix) != 0) continue;
        std::error_code gone;
        if (fs::remove(it->path(), gone)) ++removed;
    }
    return removed;
}

}  // namespace caliper3d::io
