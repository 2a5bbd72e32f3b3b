// Running rayrad itself as a child process, for the validation commands.
#pragma once

#include <string>
#include <vector>

namespace rayrad::app {

/// This very program: /proc/self/exe stays valid even if the file was rebuilt meanwhile.
inline std::string selfExe() { return "/proc/self/exe"; }

/// A bundled file ("scenes/cube/cube.json") wherever rayrad runs from: relative to the
/// working directory if it is there, else installed (<prefix>/share/rayrad/), else in
/// the source tree this binary was built from. The path as given if none has it.
std::string bundledPath(const std::string& relative);

/// Creates `outDir` (and its parents) and returns outDir/results.csv, checked writable;
/// throws InputError or OutputError naming the problem.
std::string prepareResults(const std::string& outDir);

/// Runs args (args[0] the program) with stdout and stderr to logPath; the exit code, or
/// -1 when it could not start or did not exit normally. Each child has its own peak memory.
int runChild(const std::vector<std::string>& args, const std::string& logPath);

}  // namespace rayrad::app
