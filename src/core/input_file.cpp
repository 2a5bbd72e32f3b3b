#include <core/input_file.h>

#include <core/input_error.h>

#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sys/stat.h>
#include <unistd.h>

namespace rayrad {

namespace {

/// A Git LFS pointer is a few lines of text, about 130 bytes.
constexpr long kLfsPointerMaxBytes = 1024;

std::string sizeText(double bytes) {
    return bytes >= 1 << 20 ? fmt::format("{:.0f} MiB", bytes / (1 << 20)) : fmt::format("{:.0f} bytes", bytes);
}

[[noreturn]] void tooLarge(const std::string& path, const std::string& what, const std::string& size, size_t limit) {
    throw InputError(placeMessage(path, "", fmt::format("the {} is {}; more than the limit of {} for a {}", what == "standard input" ? "input" : "file", size,
                                                        sizeText(static_cast<double>(limit)), what)));
}

/// Reads a stream to its end, at most `limit` bytes.
std::string readBounded(std::istream& in, const std::string& path, const std::string& what, size_t limit) {
    std::string text;
    char buffer[1 << 16];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
        text.append(buffer, static_cast<size_t>(in.gcount()));
        if (text.size() > limit) tooLarge(path, what, "larger", limit);
    }
    if (in.bad()) throw InputError(placeMessage(path, "", "cannot read the " + what));
    return text;
}

}  // namespace

std::string inputFileProblem(const std::string& path, const std::string& what) {
    if (path.empty()) return "the " + what + " name is empty";
    struct stat st {};
    if (stat(path.c_str(), &st) != 0) {
        const int e = errno;
        if (e == ENOENT) {
            struct stat link {};
            if (lstat(path.c_str(), &link) == 0) return "a symbolic link to a file that does not exist";
            return "no such file";
        }
        if (e == ELOOP) return "a loop of symbolic links";
        if (e == ENOTDIR) return "no such file (a part of the path is not a directory)";
        return std::string("cannot open the ") + what + ": " + std::strerror(e);
    }
    if (S_ISDIR(st.st_mode)) return "is a directory, not a " + what;
    if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode)) return "is a device, not a " + what;
    if (!S_ISREG(st.st_mode) && !S_ISFIFO(st.st_mode)) return "is not a regular file, so not a " + what;
    if (access(path.c_str(), R_OK) != 0) return std::string("cannot open the ") + what + " for reading: " + std::strerror(errno);
    if (S_ISREG(st.st_mode) && st.st_size < kLfsPointerMaxBytes) {
        std::ifstream in(path, std::ios::binary);
        std::string head(static_cast<size_t>(st.st_size), '\0');
        if (in.read(head.data(), st.st_size) && isGitLfsPointer(head)) return kGitLfsPointerProblem;
    }
    return "";
}

const char* const kGitLfsPointerProblem =
    "is a Git LFS pointer, not the file itself (the repository was cloned without Git LFS): fetch the file with "
    "'git lfs pull'";

bool isGitLfsPointer(std::string_view text) {
    constexpr std::string_view signature = "version https://git-lfs.github.com/spec/";
    return text.size() < kLfsPointerMaxBytes && text.substr(0, signature.size()) == signature;
}

void checkInputFile(const std::string& path, const std::string& what) {
    const std::string problem = inputFileProblem(path, what);
    if (!problem.empty()) throw InputError(placeMessage(path, "", problem));
}

std::string readInputFile(const std::string& path, const std::string& what, size_t limitBytes) {
    if (path == "-") return readBounded(std::cin, "standard input", "standard input", limitBytes);
    checkInputFile(path, what);
    struct stat st {};
    if (stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) && static_cast<size_t>(st.st_size) > limitBytes)
        tooLarge(path, what, sizeText(static_cast<double>(st.st_size)), limitBytes);
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(placeMessage(path, "", "cannot open the " + what + " for reading"));
    return readBounded(in, path, what, limitBytes);
}

}  // namespace rayrad
