#include <core/output_file.h>

#include <core/input_error.h>

#include <fmt/format.h>

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
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

/// A temporary name beside `target`, short enough for any file system: ".rayrad-PID-K.tmp".
fs::path temporaryBeside(const fs::path& target, int k) {
    return directoryOf(target) / fmt::format(".rayrad-{}-{}.tmp", getpid(), k);
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

void OutputFiles::add(const std::string& path) {
    const fs::path target = checkOutput(path);
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

void OutputFiles::commit() {
    std::vector<Output*> pending;
    for (auto& o : m_outputs)
        if (o.pending) pending.push_back(&o);
    std::vector<fs::path> temporaries;
    auto removeTemporaries = [&] {
        for (const auto& t : temporaries) std::remove(t.c_str());
    };
    try {
        for (Output* o : pending) {
            temporaries.push_back(temporaryBeside(o->target, static_cast<int>(temporaries.size())));
            writeNewFile(o->path, temporaries.back(), o->target, o->bytes);
        }
    } catch (...) {
        removeTemporaries();
        throw;
    }
    // Every file is written and synced: now replace the targets.
    for (size_t i = 0; i < pending.size(); ++i) {
        if (std::rename(temporaries[i].c_str(), pending[i]->target.c_str()) != 0) {
            const std::string why = std::strerror(errno);
            for (size_t j = i; j < pending.size(); ++j) std::remove(temporaries[j].c_str());
            fail(pending[i]->path, why + (i > 0 ? fmt::format(" ({} other output(s) were already written)", i) : ""));
        }
        syncDirectory(directoryOf(pending[i]->target));
        pending[i]->pending = false;
        pending[i]->bytes.clear();
        pending[i]->bytes.shrink_to_fit();
    }
}

void writeFileAtomically(const std::string& path, const std::string& bytes) {
    OutputFiles files;
    files.add(path);
    files.set(path, bytes);
    files.commit();
}

}  // namespace rayrad
