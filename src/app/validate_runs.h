// Running rayrad itself as a child process, for the validation commands.
#pragma once

#include <string>
#include <vector>

namespace rayrad::app {

/// This very program: /proc/self/exe stays valid even if the file was rebuilt meanwhile.
inline std::string selfExe() { return "/proc/self/exe"; }

/// Runs args (args[0] the program) with stdout and stderr to logPath; the exit code, or
/// -1 when it could not start or did not exit normally. Each child has its own peak memory.
int runChild(const std::vector<std::string>& args, const std::string& logPath);

}  // namespace rayrad::app
