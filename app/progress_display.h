#pragma once

#include <cstddef>
#include <cstdio>
#include <map>
#include <string>

namespace caliper3d::app {

// Progress of a long run on a terminal: one line on stderr, redrawn in place, with the inputs
// done of the total, those that failed, the time gone and left, and each input under way with
// its own time ("[12/100, 1 failed] 0:42, about 5:50 left | A-3.las report 4 s").
// Silent when stderr is not a terminal (a file, a pipe, a cluster job's log), so logs carry
// only the verbs' own lines.
class ProgressDisplay {
public:
    ProgressDisplay(std::size_t total, std::FILE* stream = stderr);
    ProgressDisplay(std::size_t total, std::FILE* stream, bool enabled);
    ~ProgressDisplay();
    ProgressDisplay(const ProgressDisplay&) = delete;
    ProgressDisplay& operator=(const ProgressDisplay&) = delete;

    bool enabled() const { return m_enabled; }
    // An input (`key`: unique among those under way) began or ended.
    void started(const std::string& key, const std::string& label);
    void finished(const std::string& key, bool ok);
    // Erases the line, so that other text can be printed; the next redraw puts it back.
    void clear();
    // Redraws the line (the times move on).
    void redraw();

private:
    std::FILE* m_stream;
    bool m_enabled;
    std::size_t m_total;
    std::size_t m_done = 0;
    std::size_t m_failed = 0;
    double m_start_s;
    std::map<std::string, std::pair<std::string, double>> m_running;  // key -> label, start
    bool m_drawn = false;
};

// "0:42", "1:02:05".
std::string formatDuration(double seconds);

}  // namespace caliper3d::app
