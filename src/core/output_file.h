// Writing outputs safely: check early that a path is writable, write to a temporary
// file beside it and rename at the end, so a failure never leaves a half-written file.
#pragma once

#include <functional>
#include <string>

namespace rayrad {

/// Throws InputError when `path` cannot be written (missing or read-only directory,
/// read-only existing file). Call it before long work so the user learns at once.
void checkWritable(const std::string& path);

/// Calls `write(tmpPath)` to write a temporary file in the same directory, then renames
/// it to `path`. If `write` throws, the temporary file is removed and `path` is untouched.
void writeAtomically(const std::string& path, const std::function<void(const std::string&)>& write);

}  // namespace rayrad
