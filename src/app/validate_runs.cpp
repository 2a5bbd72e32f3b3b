#include <app/validate_runs.h>

#include <core/input_error.h>
#include <core/output_file.h>

#include <filesystem>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace rayrad::app {

int runChild(const std::vector<std::string>& args, const std::string& logPath) {
    std::vector<char*> argv;
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, logPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    pid_t pid;
    int rc = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (rc != 0) return -1;
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string bundledPath(const std::string& relative) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path exeDir = fs::read_symlink("/proc/self/exe", ec).parent_path();
    const fs::path candidates[] = {relative, exeDir / "../share/rayrad" / relative, fs::path(RAYRAD_SOURCE_DIR) / relative};
    for (const auto& c : candidates)
        if (fs::exists(c, ec)) return c.lexically_normal().string();
    return relative;
}

std::string prepareResults(const std::string& outDir) {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::create_directories(outDir, ec);
    if (ec) throw InputError(placeMessage(outDir, "", "cannot create the output directory: " + ec.message()));
    const std::string csvPath = (fs::path(outDir) / "results.csv").string();
    checkWritable(csvPath);
    return csvPath;
}

}  // namespace rayrad::app
