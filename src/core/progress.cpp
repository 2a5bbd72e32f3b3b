#include <core/progress.h>

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <unistd.h>

namespace rayrad {

Progress::Progress(std::string label, bool quiet)
    : m_label(std::move(label)), m_enabled(!quiet && isatty(fileno(stderr))) {}

Progress::~Progress() { finish(); }

void Progress::update(double fraction, const std::string& detail) {
    if (!m_enabled) return;
    std::lock_guard<std::mutex> lock(m_mutex);
    auto now = std::chrono::steady_clock::now();
    if (m_shown && now - m_last < std::chrono::milliseconds(200)) return;
    m_last = now;
    m_shown = true;
    fraction = std::clamp(fraction, 0.0, 1.0);
    fmt::print(stderr, "\r\033[K{}: {:5.1f}% {}", m_label, 100.0 * fraction, detail);
    std::fflush(stderr);
}

void Progress::finish() {
    if (!m_enabled) return;
    std::lock_guard<std::mutex> lock(m_mutex);
    if (!m_shown) return;
    fmt::print(stderr, "\r\033[K");
    std::fflush(stderr);
    m_shown = false;
}

}  // namespace rayrad
