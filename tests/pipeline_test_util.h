// Pipeline options for tests: no progress output, the given --set overrides.
#pragma once

#include <app/pipeline.h>

#include "scene/scene_test_util.h"

#include <string>
#include <vector>

namespace rayrad::test {

inline app::PipelineOptions quiet(std::vector<scene::Override> overrides = {}) {
    app::PipelineOptions p;
    p.quiet = true;
    p.overrides = std::move(overrides);
    return p;
}

}  // namespace rayrad::test
