#pragma once

#include <cstddef>
#include <fstream>
#include <ostream>
#include <string>

namespace caliper3d::io {

// An output file written whole or not at all. Everything goes to a temporary file beside the
// target (the same folder, so that the last step is one atomic rename), which commit() flushes to
// disk and renames over the target; if the writing ends any other way (an exception, an early
// return) the destructor removes the temporary. A reader of the target, or a run that is killed,
// finds the previous file or the new one, never part of one.
//
// The temporary is named "TARGET.PID-N.tmp". SIGINT, SIGTERM and SIGHUP remove the temporaries
// of the process before it ends as the signal says (where nothing else handles those signals);
// a SIGKILL leaves its temporary beside the intact target (removeTemporaries clears it).
//
// A target that exists but is not a regular file (/dev/null, a pipe, a terminal) is written
// directly: it holds nothing to keep, and a rename would replace it. A symbolic link to a file
// is followed: the file it names is replaced, the link kept.
class AtomicOutput {
public:
    explicit AtomicOutput(std::string target);
    ~AtomicOutput();
    AtomicOutput(const AtomicOutput&) = delete;
    AtomicOutput& operator=(const AtomicOutput&) = delete;

    // The file named by the caller: what error messages name.
    const std::string& target() const { return m_target; }
    // Where to write: the temporary (the target itself when written directly). For a library
    // that opens a path on its own; the caller's writer must have closed it before commit().
    const std::string& path() const { return m_path; }
    // A binary stream on path(), opened on the first call. Throws std::runtime_error naming the
    // target when the file cannot be made.
    std::ostream& stream();
    // Closes the stream (when one was opened), flushes the file to disk and renames it over the
    // target. Throws std::runtime_error naming the target when any of it fails; the temporary
    // is removed then and the target left as it was.
    void commit();
    bool committed() const { return m_committed; }

private:
    void discard() noexcept;

    std::string m_target;     // as the caller named it
    std::string m_finalPath;  // what the rename replaces: the target, its link followed
    std::string m_path;       // what is written
    std::ofstream m_stream;
    bool m_direct = false;
    bool m_committed = false;
    int m_slot = -1;  // its place among the temporaries removed on a signal; -1: none
};

// Whether `fileName` is a temporary that an AtomicOutput of `targetFileName` makes (names
// without their folder): "TARGET.PID-N.tmp".
bool isTemporaryOf(const std::string& fileName, const std::string& targetFileName);

// Removes the temporaries that process `pid` left beside `target` (a process killed before it
// could remove them); returns how many. A pid of 0 removes those of any process.
std::size_t removeTemporaries(const std::string& target, long pid = 0);

}  // namespace caliper3d::io
