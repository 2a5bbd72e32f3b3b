// Displays and views of an OpenColorIO config, checked, with their processors
// (tonemap/display_transform.h is the caller's side).
#pragma once

#include <tonemap/image_library.h>

#include <string>

namespace rayrad::image_module {

/// Throws InputError for a config that does not load, or a display or view it does not
/// have (the message lists the ones it has).
tonemap::ResolvedView resolveView(const std::string& configFile, const std::string& embeddedConfig,
                                  const std::string& display, const std::string& view);

}  // namespace rayrad::image_module
