// Writing outputs safely. Every output path is checked before any work; at the end all
// of a run's outputs are written together, each to a temporary file beside its target,
// every write checked and fsynced, then renamed over the target while the old file is
// kept beside it until every rename has succeeded. A failure, or a termination signal,
// removes the temporary files and puts every old file back: all outputs or none.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace rayrad {

/// An output that cannot be written (bad path, full disk, I/O error): exit code 3. The
/// message names the file and the reason.
class OutputError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// The files one run writes.
class OutputFiles {
  public:
    /// Inputs of the run (scene file, mesh files): no output may be one of them.
    void addInput(const std::string& path);

    /// Checks `path` as an output of this run, now, before any work (and removes temporary
    /// files that processes no longer running left beside it); throws OutputError
    /// when it cannot be written: its directory is missing or not writable, it is a
    /// directory, a device or another non-regular file, it is read-only, its name is
    /// longer than the file system allows, or it is an input or another output of the
    /// run. A symbolic link is followed: its target is what gets replaced.
    void add(const std::string& path);

    /// Gives the bytes of an output added before (written at the next commit()).
    void set(const std::string& path, std::string bytes);

    /// Writes every output given since the last commit: all temporary files first, then
    /// the renames. Throws OutputError naming the file; no temporary file is left and
    /// every output already replaced is put back. A termination signal meanwhile does the
    /// same, then ends the process (termination.h). For the tests, the environment
    /// variable RAYRAD_TEST_COMMIT_FAULT injects a fault: "rename:K" (the K-th rename
    /// fails), "signal:write:K" or "signal:rename:K" (SIGTERM after the K-th write or rename).
    void commit();

  private:
    struct Output {
        std::string path;    ///< as the user gave it (for messages)
        std::string target;  ///< the file to replace: symlinks resolved
        std::string bytes;
        bool pending = false;
    };
    Output& find(const std::string& path);

    std::vector<std::string> m_inputs;  ///< resolved paths
    std::vector<Output> m_outputs;
};

/// One output, checked and written as above.
void writeFileAtomically(const std::string& path, const std::string& bytes);

/// Throws OutputError if `path` cannot be an output (the checks of OutputFiles::add
/// that need no other file).
void checkWritable(const std::string& path);

}  // namespace rayrad
