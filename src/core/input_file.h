// Reading input files with a clear error for everything that is not a readable file of
// a sane size: missing files, directories, devices, loops of symbolic links.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace rayrad {

/// What is wrong with `path` as an input ("no such file", "is a directory, not a mesh
/// file", a Git LFS pointer instead of the file, ...), or "" when it names a readable file
/// (or a pipe). `what` says what it should be ("scene file", "mesh file").
std::string inputFileProblem(const std::string& path, const std::string& what);

/// True when `text` (a file's first bytes, or all of it) is a Git LFS pointer: the small
/// text file a repository cloned without Git LFS holds in place of a mesh, a buffer or an
/// image ("version https://git-lfs.github.com/spec/v1", the object's hash and size).
bool isGitLfsPointer(std::string_view text);

/// What inputFileProblem says of a Git LFS pointer.
extern const char* const kGitLfsPointerProblem;

/// Throws InputError ("path: problem") unless `path` names a readable regular file.
void checkInputFile(const std::string& path, const std::string& what);

/// The whole file (standard input for "-"), after checkInputFile; throws InputError when
/// it is longer than `limitBytes` (checked before reading, and while reading a pipe).
std::string readInputFile(const std::string& path, const std::string& what, size_t limitBytes);

}  // namespace rayrad
