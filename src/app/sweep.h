// rayrad sweep: a parameter grid over a scene, expanded into independent jobs (one rayrad
// command line each) for GNU parallel or a Slurm job array to run.
#pragma once

#include <string>
#include <vector>

namespace rayrad::app {

struct SweepOptions {
    std::string scene;
    std::vector<std::string> vary;  ///< "KEY=V1,V2,...": --set values to take in turn
    std::string command = "solve";  ///< the rayrad subcommand and its options; {job} → the job's number
    std::string jobsFile;           ///< one command line per job; a CSV of the jobs' values beside it (.csv)
    std::string rayrad;             ///< the rayrad to run (default: this program's absolute path)
};

/// The values of one --vary: "a.b=1,2,[3,4]" → {"a.b", {"1", "2", "[3,4]"}} (commas inside
/// brackets or quotes do not split). Throws InputError for a malformed one.
std::pair<std::string, std::vector<std::string>> parseVary(const std::string& text);

/// Every combination of the values (the last --vary changing fastest), each checked by
/// reading the scene with its --set values, then the jobs file and its CSV written
/// together. Throws InputError naming the job and value a scene refuses.
int writeSweep(const SweepOptions& options);

/// `word` quoted for a POSIX shell when it needs to be.
std::string shellQuote(const std::string& word);

}  // namespace rayrad::app
