#include <core/output_file.h>

#include <core/input_error.h>
#include <core/termination.h>

#include <fmt/format.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <climits>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <set>
#include <sys/stat.h>
#include <unistd.h>

namespace rayrad {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& why) {
    throw OutputError(placeMessage(path, "", "cannot write: " + why));
}

const char* kindOf(mode_t mode) {
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISFIFO(mode)) return "a named pipe";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}

/// The file an output path names: its symbolic links followed (relative links resolve
/// against the link's directory). The target need not exist.
fs::path resolveLinks(const std::string& path) {
    fs::path p(path);
    struct stat st {};
    for (int hops = 0; lstat(p.c_str(), &st) == 0 && S_ISLNK(st.st_mode); ++hops) {
        if (hops == 40) fail(path, "a loop of symbolic links");
        std::error_code ec;
        const fs::path to = fs::read_symlink(p, ec);
        if (ec) fail(path, "cannot read the symbolic link: " + ec.message());
        p = to.is_absolute() ? to : p.parent_path() / to;
    }
    return p.lexically_normal();
}

fs::path directoryOf(const fs::path& p) { return p.has_parent_path() ? p.parent_path() : fs::path("."); }

/// The static checks of an output; returns the file to replace.
fs::path checkOutput(const std::string& path) {
    if (path.empty()) throw OutputError("an output file name is empty");
    const fs::path target = resolveLinks(path);
    const std::string name = target.filename().string();
    if (name.empty() || name == "." || name == "..") fail(path, "names a directory, not a file");
    if (path.size() >= PATH_MAX) fail(path, fmt::format("the path is {} bytes long, the limit is {}", path.size(), PATH_MAX - 1));
    const fs::path dir = directoryOf(target);
    struct stat st {};
    if (stat(dir.c_str(), &st) != 0) {
        if (errno == ENOENT) fail(path, "directory '" + dir.string() + "' does not exist");
        fail(path, "directory '" + dir.string() + "': " + std::strerror(errno));
    }
    if (!S_ISDIR(st.st_mode)) fail(path, "'" + dir.string() + "' is not a directory");
    if (access(dir.c_str(), W_OK | X_OK) != 0) fail(path, "directory '" + dir.string() + "' is not writable");
    long nameMax = pathconf(dir.c_str(), _PC_NAME_MAX);
    if (nameMax <= 0) nameMax = NAME_MAX;
    if (static_cast<long>(name.size()) > nameMax)
        fail(path, fmt::format("the file name is {} bytes, longer than the {} its file system allows", name.size(), nameMax));
    if (stat(target.c_str(), &st) == 0) {
        if (S_ISDIR(st.st_mode)) fail(path, "is a directory, not an output file");
        if (!S_ISREG(st.st_mode))
            fail(path, std::string("is ") + kindOf(st.st_mode) +
                           "; rayrad replaces an output file whole, so name a regular file");
        if ((st.st_mode & 0222) == 0) fail(path, "the file exists and is read-only");
    } else if (errno != ENOENT) {
        fail(path, std::strerror(errno));
    }
    return target;
}

/// Identity of a file for "is this the same file": device and inode when it exists,
/// else its absolute path with links resolved.
struct FileId {
    bool exists = false;
    dev_t device = 0;
    ino_t inode = 0;
    std::string path;
    bool operator==(const FileId& o) const {
        return exists && o.exists ? device == o.device && inode == o.inode : path == o.path;
    }
};

FileId identify(const fs::path& p) {
    FileId id;
    struct stat st {};
    if (stat(p.c_str(), &st) == 0) id.exists = true, id.device = st.st_dev, id.inode = st.st_ino;
    std::error_code ec;
    fs::path abs = fs::weakly_canonical(fs::absolute(p, ec), ec);
    id.path = ec ? p.lexically_normal().string() : abs.string();
    return id;
}

/// A temporary name beside `target`, short enough for any file system:
/// ".rayrad-PID-K.tmp" (the new file) or ".rayrad-PID-K.old" (the old one, kept while the
/// outputs are replaced).
fs::path temporaryBeside(const fs::path& target, int k, const char* suffix) {
    return directoryOf(target) / fmt::format(".rayrad-{}-{}.{}", getpid(), k, suffix);
}

/// Writes `bytes` to a new file `tmp` (its mode that of `modeFrom` if that exists),
/// checking every write, fsync and close.
void writeNewFile(const std::string& path, const fs::path& tmp, const fs::path& modeFrom, const std::string& bytes) {
    struct stat st {};
    const bool replacing = stat(modeFrom.c_str(), &st) == 0;
    int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) fail(path, std::string("cannot create a temporary file beside it: ") + std::strerror(errno));
    auto failHere = [&](const char* what) {
        const int e = errno;
        ::close(fd);
        std::remove(tmp.c_str());
        fail(path, std::string(what) + std::strerror(e) + " (the old file, if any, is unchanged)");
    };
    if (replacing && fchmod(fd, st.st_mode & 07777) != 0) failHere("");
    size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            failHere("");
        }
        done += static_cast<size_t>(n);
    }
    if (fsync(fd) != 0) failHere("");
    if (::close(fd) != 0) {
        const int e = errno;
        std::remove(tmp.c_str());
        fail(path, std::string(std::strerror(e)) + " (the old file, if any, is unchanged)");
    }
}

void syncDirectory(const fs::path& dir) {
    int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;
    fsync(fd);  // best effort: the rename is done; some file systems refuse fsync on a directory
    ::close(fd);
}

}  // namespace

void checkWritable(const std::string& path) { checkOutput(path); }

void OutputFiles::addInput(const std::string& path) {
    if (path.empty() || path == "-") return;
    m_inputs.push_back(path);
}

namespace {
/// Removes the temporary files (".rayrad-PID-K.tmp" / ".old") that processes no longer
/// running left in `dir` (killed with SIGKILL, or a machine that went down); each
/// directory once a process.
void removeStaleTemporaries(const fs::path& dir) {
    static std::set<std::string> done;
    std::error_code ec;
    const std::string key = fs::weakly_canonical(fs::absolute(dir, ec), ec).string();
    if (!done.insert(key).second) return;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        long pid = 0;
        int k = 0, used = 0;
        char suffix[4] = {};
        if (std::sscanf(name.c_str(), ".rayrad-%ld-%d.%3[a-z]%n", &pid, &k, suffix, &used) != 3 ||
            used != static_cast<int>(name.size()) || (std::strcmp(suffix, "tmp") != 0 && std::strcmp(suffix, "old") != 0))
            continue;
        if (pid <= 0 || pid == getpid() || ::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;
        std::remove(it->path().c_str());
    }
}
}  // namespace

void OutputFiles::add(const std::string& path) {
    const fs::path target = checkOutput(path);
    removeStaleTemporaries(directoryOf(target));
    const FileId id = identify(target);
    for (const auto& in : m_inputs)
        if (identify(in) == id) fail(path, "it is an input of this run ('" + in + "')");
    for (const auto& o : m_outputs)
        if (identify(o.target) == id)
            fail(path, o.path == path ? "given twice as an output" : "it is the same file as the output '" + o.path + "'");
    m_outputs.push_back({path, target.string(), {}, false});
}

OutputFiles::Output& OutputFiles::find(const std::string& path) {
    for (auto& o : m_outputs)
        if (o.path == path) return o;
    throw std::logic_error("output '" + path + "' was not checked before the work (OutputFiles::add)");
}

void OutputFiles::set(const std::string& path, std::string bytes) {
    Output& o = find(path);
    o.bytes = std::move(bytes);
    o.pending = true;
}

namespace {
/// A fault injected into commit() for the tests (environment variable
/// RAYRAD_TEST_COMMIT_FAULT): "rename:K" — the K-th rename fails (EIO); "signal:write:K" or
/// "signal:rename:K" — SIGTERM is raised after the K-th temporary file is written or the
/// K-th output renamed into place.
struct InjectedFault {
    enum class Kind { None, RenameFails, SignalAfterWrite, SignalAfterRename } kind = Kind::None;
    size_t at = 0;  ///< 1-based
    static InjectedFault fromEnvironment() {
        InjectedFault f;
        const char* text = std::getenv("RAYRAD_TEST_COMMIT_FAULT");
        if (!text) return f;
        const std::string t = text;
        auto number = [&](const std::string& prefix) {
            return t.rfind(prefix, 0) == 0 ? std::strtoul(t.c_str() + prefix.size(), nullptr, 10) : 0ul;
        };
        if (size_t k = number("rename:")) f.kind = Kind::RenameFails, f.at = k;
        if (size_t k = number("signal:write:")) f.kind = Kind::SignalAfterWrite, f.at = k;
        if (size_t k = number("signal:rename:")) f.kind = Kind::SignalAfterRename, f.at = k;
        return f;
    }
    bool is(Kind k, size_t index) const { return kind == k && at == index + 1; }
};

/// Keeps the file at `target` (if there is one) under the name `backup` too: a hard link,
/// or a copy where the file system has none. False when there is no file to keep.
bool keepOld(const std::string& path, const fs::path& target, const fs::path& backup) {
    struct stat st {};
    if (stat(target.c_str(), &st) != 0) return false;
    if (::link(target.c_str(), backup.c_str()) == 0) return true;
    std::error_code ec;
    if (!fs::copy_file(target, backup, ec))
        fail(path, "cannot keep the old file while the outputs are replaced: " + ec.message());
    return true;
}
}  // namespace

void OutputFiles::commit() {
    std::vector<Output*> pending;
    for (auto& o : m_outputs)
        if (o.pending) pending.push_back(&o);
    if (pending.empty()) return;
    // Every name first, so a termination signal can remove whatever of them exists.
    std::vector<std::string> temporaries, backups, cleanup;
    for (size_t i = 0; i < pending.size(); ++i) {
        temporaries.push_back(temporaryBeside(pending[i]->target, static_cast<int>(i), "tmp").string());
        backups.push_back(temporaryBeside(pending[i]->target, static_cast<int>(i), "old").string());
    }
    cleanup.insert(cleanup.end(), temporaries.begin(), temporaries.end());
    cleanup.insert(cleanup.end(), backups.begin(), backups.end());
    TerminationCleanup onSignal(cleanup);
    const InjectedFault fault = InjectedFault::fromEnvironment();
    auto removeAll = [](const std::vector<std::string>& files) {
        for (const auto& f : files) std::remove(f.c_str());
    };
    try {
        for (size_t i = 0; i < pending.size(); ++i) {
            writeNewFile(pending[i]->path, temporaries[i], pending[i]->target, pending[i]->bytes);
            if (fault.is(InjectedFault::Kind::SignalAfterWrite, i)) std::raise(SIGTERM);
        }
    } catch (...) {
        removeAll(temporaries);
        throw;
    }
    // Every file is written and synced: now replace the targets, each old file kept until
    // all are in place. A failed rename, or a termination signal (held back meanwhile),
    // puts every old file back: all outputs or none.
    onSignal.holdSignals();
    std::vector<char> hadOld(pending.size(), 0);
    size_t placed = 0;
    auto undo = [&] {
        for (size_t j = 0; j < placed; ++j) {
            const std::string& target = pending[j]->target;
            if (hadOld[j])
                std::rename(backups[j].c_str(), target.c_str());
            else
                std::remove(target.c_str());
        }
        removeAll(temporaries);
        removeAll(backups);
    };
    for (size_t i = 0; i < pending.size(); ++i) {
        try {
            hadOld[i] = keepOld(pending[i]->path, pending[i]->target, backups[i]);
        } catch (...) {
            undo();
            throw;
        }
        const bool injected = fault.is(InjectedFault::Kind::RenameFails, i);
        if (injected || std::rename(temporaries[i].c_str(), pending[i]->target.c_str()) != 0) {
            const std::string why = injected ? std::strerror(EIO) : std::strerror(errno);
            if (hadOld[i]) std::remove(backups[i].c_str());
            undo();
            fail(pending[i]->path,
                 why + (i > 0 ? fmt::format(" (the {} other output(s) already replaced were put back)", i) : ""));
        }
        ++placed;
        if (fault.is(InjectedFault::Kind::SignalAfterRename, i)) std::raise(SIGTERM);
        if (onSignal.heldSignal() != 0) {
            undo();
            onSignal.releaseSignals();  // ends the process
        }
    }
    for (Output* o : pending) {
        syncDirectory(directoryOf(o->target));
        o->pending = false;
        o->bytes.clear();
        o->bytes.shrink_to_fit();
    }
    removeAll(backups);
}

void writeFileAtomically(const std::string& path, const std::string& bytes) {
    OutputFiles files;
    files.add(path);
    files.set(path, bytes);
    files.commit();
}

}  // namespace rayrad
