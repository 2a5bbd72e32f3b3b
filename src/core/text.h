// Small text helpers shared by the readers and writers.
#pragma once

#include <cctype>
#include <filesystem>
#include <string>

namespace rayrad {

/// ASCII lower case (keys, file extensions).
inline std::string toLower(std::string text) {
    for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

/// A file's extension in lower case, with its dot: "scene.IES" → ".ies", "a" → "".
inline std::string lowerExtension(const std::string& path) {
    return toLower(std::filesystem::path(path).extension().string());
}

}  // namespace rayrad
