#include <core/termination.h>

#include <atomic>
#include <csignal>
#include <unistd.h>

namespace rayrad {

namespace {
/// The registered files (null: none). Read by the handler, which may run in any thread.
std::atomic<const std::vector<std::string>*> g_files{nullptr};
std::atomic<bool> g_holding{false};
volatile std::sig_atomic_t g_held = 0;

constexpr int kSignals[] = {SIGTERM, SIGINT, SIGHUP};

/// Removes the registered files (unlink is async-signal-safe) and ends the process with
/// the signal's default action.
void removeFilesAndEnd(int signal) {
    if (const auto* files = g_files.load())
        for (const std::string& f : *files) ::unlink(f.c_str());
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

extern "C" void onTermination(int signal) {
    if (g_holding.load()) {
        g_held = signal;
        return;
    }
    removeFilesAndEnd(signal);
}
}  // namespace

void installTerminationCleanup() {
    struct sigaction action {};
    action.sa_handler = onTermination;
    sigemptyset(&action.sa_mask);
    for (int s : kSignals) sigaddset(&action.sa_mask, s);
    for (int s : kSignals) {
        struct sigaction old {};
        // A signal ignored by whoever started rayrad (nohup) stays ignored.
        if (sigaction(s, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
        sigaction(s, &action, nullptr);
    }
}

TerminationCleanup::TerminationCleanup(const std::vector<std::string>& paths) { g_files.store(&paths); }

TerminationCleanup::~TerminationCleanup() {
    releaseSignals();
    g_files.store(nullptr);
}

void TerminationCleanup::holdSignals() { g_holding.store(true); }

int TerminationCleanup::heldSignal() const { return g_held; }

void TerminationCleanup::releaseSignals() {
    if (!g_holding.exchange(false)) return;
    if (const int signal = g_held) {
        g_held = 0;
        removeFilesAndEnd(signal);
    }
}

}  // namespace rayrad
