#include "app/progress_display.h"

#include <cmath>

#include <sys/ioctl.h>
#include <unistd.h>

#include "app/input_summary.h"

namespace caliper3d::app {

std::string formatDuration(double seconds) {
    const long total = std::lround(std::max(0.0, seconds));
    char text[32];
    if (total >= 3600)
        std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", total / 3600, total / 60 % 60,
                      total % 60);
    else
        std::snprintf(text, sizeof text, "%ld:%02ld", total / 60, total % 60);
    return text;
}

ProgressDisplay::ProgressDisplay(std::size_t total, std::FILE* stream)
    : ProgressDisplay(total, stream, isatty(fileno(stream)) != 0) {}

ProgressDisplay::ProgressDisplay(std::size_t total, std::FILE* stream, bool enabled)
    : m_stream(stream), m_enabled(enabled), m_total(total), m_start_s(steadySeconds()) {}

ProgressDisplay::~ProgressDisplay() {
    clear();
}

void ProgressDisplay::started(const std::string& key, const std::string& label) {
    m_running[key] = {label, steadySeconds()};
    redraw();
}

void ProgressDisplay::finished(const std::string& key, bool ok) {
    m_running.erase(key);
    ++m_done;
    m_failed += ok ? 0 : 1;
    redraw();
}

void ProgressDisplay::clear() {
    if (!m_enabled || !m_drawn) return;
    std::fputs("\r\033[K", m_stream);
    std::fflush(m_stream);
    m_drawn = false;
}

void ProgressDisplay::redraw() {
    if (!m_enabled) return;
    const double now = steadySeconds();
    const double elapsed = now - m_start_s;
    std::string line = "[" + std::to_string(m_done) + "/" + std::to_string(m_total);
    if (m_failed > 0) line += ", " + std::to_string(m_failed) + " failed";
    line += "] " + formatDuration(elapsed);
    if (m_done > 0 && m_done < m_total)
        line += ", about " +
                formatDuration(elapsed / static_cast<double>(m_done) *
                               static_cast<double>(m_total - m_done)) +
                " left";
    for (const auto& [key, running] : m_running)
        line += " | " + running.first + " " + formatDuration(now - running.second);
    winsize size{};
    const int fd = fileno(m_stream);
    const std::size_t width = ioctl(fd, TIOCGWINSZ, &size) == 0 && size.ws_col > 0
                                  ? static_cast<std::size_t>(size.ws_col)
                                  : std::size_t{80};
    if (line.size() >= width) line.resize(width - 1);  // one line, never wrapped
    std::fputs(("\r\033[K" + line).c_str(), m_stream);
    std::fflush(m_stream);
    m_drawn = true;
}

}  // namespace caliper3d::app
