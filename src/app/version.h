// `rayrad --version`: rayrad's version and the versions of the libraries it runs with.
#pragma once

#include <string>

namespace rayrad::app {

/// "rayrad 0.1.0\nEmbree 3.13.5, OpenImageIO 2.4.7, OpenColorIO 2.1.2, Assimp 5.2.5".
std::string versionText();

}  // namespace rayrad::app
