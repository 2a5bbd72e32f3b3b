#include <core/stage_report.h>

#include <fmt/format.h>

#include <sys/resource.h>

#include <fstream>
#include <sstream>

namespace rayrad {

size_t peakMemoryBytes() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line)) {
        if (line.rfind("VmHWM:", 0) == 0) {
            std::istringstream s(line.substr(6));
            size_t kb = 0;
            s >> kb;
            return kb * 1024;
        }
    }
    return 0;
}

double processCpuSeconds() {
    rusage u{};
    if (getrusage(RUSAGE_SELF, &u) != 0) return 0.0;
    auto seconds = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); };
    return seconds(u.ru_utime) + seconds(u.ru_stime);
}

void StageReport::begin(const std::string& name) {
    end();
    m_stages.push_back({name, 0.0, 0.0, 0});
    m_start = std::chrono::steady_clock::now();
    m_cpuStart = processCpuSeconds();
    m_running = true;
}

void StageReport::end() {
    if (!m_running) return;
    auto now = std::chrono::steady_clock::now();
    m_stages.back().seconds = std::chrono::duration<double>(now - m_start).count();
    m_stages.back().cpuSeconds = processCpuSeconds() - m_cpuStart;
    m_stages.back().peakBytes = peakMemoryBytes();
    m_running = false;
}

double StageReport::totalSeconds() const {
    double t = 0;
    for (const auto& s : m_stages) t += s.seconds;
    return t;
}

double StageReport::totalCpuSeconds() const {
    double t = 0;
    for (const auto& s : m_stages) t += s.cpuSeconds;
    return t;
}

std::string StageReport::toString() const {
    std::string s = fmt::format("{:<24} {:>10} {:>10} {:>14}\n", "stage", "wall s", "CPU s", "peak MiB");
    for (const auto& st : m_stages)
        s += fmt::format("{:<24} {:>10.3f} {:>10.3f} {:>14.1f}\n", st.name, st.seconds, st.cpuSeconds,
                         st.peakBytes / 1048576.0);
    s += fmt::format("{:<24} {:>10.3f} {:>10.3f} {:>14.1f}\n", "total", totalSeconds(), totalCpuSeconds(),
                     peakMemoryBytes() / 1048576.0);
    return s;
}

}  // namespace rayrad
