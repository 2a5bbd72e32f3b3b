// Reading input files with a clear error for everything that is not a readable file of
// a sane size: missing files, directories, devices, loops of symbolic links.
#pragma once

#include <cstddef>
#include <string>

namespace rayrad {

/// What is wrong with `path` as an input ("no such file", "is a directory, not a mesh
/// file", ...), or "" when it names a readable file (or a pipe). `what` says what it
/// should be ("scene file", "mesh file").
std::string inputFileProblem(const std::string& path, const std::string& what);

/// Throws InputError ("path: problem") unless `path` names a readable regular file.
void checkInputFile(const std::string& path, const std::string& what);

/// The whole file (standard input for "-"), after checkInputFile; throws InputError when
/// it is longer than `limitBytes` (checked before reading, and while reading a pipe).
std::string readInputFile(const std::string& path, const std::string& what, size_t limitBytes);

}  // namespace rayrad
