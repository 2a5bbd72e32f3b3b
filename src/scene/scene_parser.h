// Reads a JSON scene file into a SceneDesc. Knows nothing of Embree, OIIO or OCIO.
#pragma once

#include <scene/scene_desc.h>

#include <functional>
#include <string>
#include <vector>

namespace rayrad::scene {

/// Receives each problem found in the input: `place` is a JSON pointer ("/lights/0/
/// intensity_cd") or "line L, column C" for syntax errors.
using ErrorHandler = std::function<void(const std::string& place, const std::string& message)>;

/// A command-line override "radiosity.max_edge=0.25": a dotted path into the JSON and a
/// value (JSON if it parses as JSON, else a string).
struct Override {
    std::string path;
    std::string value;
};

/// Parses `text` (the contents of `fileName`). Every problem goes to `onError`; the
/// default handler throws InputError("file: place: message") at the first one.
/// Overrides are applied to the JSON before it is read, so they are checked the same way.
SceneDesc parseScene(const std::string& text, const std::string& fileName,
                     const std::vector<Override>& overrides = {}, const ErrorHandler& onError = {});

/// Scene files larger than this are refused (geometry that large belongs in mesh files).
constexpr size_t kMaxSceneFileBytes = size_t(256) << 20;
/// The name a scene read from standard input ("-") has in messages.
inline const char* const kStandardInputName = "<stdin>";

/// Reads the file ("-": standard input) and parses it, with the cameras of its glTF mesh
/// files as views (addFileViews); a missing, unreadable or too large file, a directory or
/// a device is an InputError.
SceneDesc loadScene(const std::string& fileName, const std::vector<Override>& overrides = {});

/// Splits "a.b=c" into an Override; throws InputError on a malformed string.
Override parseOverride(const std::string& text);

}  // namespace rayrad::scene
