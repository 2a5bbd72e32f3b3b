// libFuzzer target for the scene reader: any byte string is a scene file. Bad input must
// come back as an InputError (a clear message, exit code 2 in the tool); any other
// exception, a crash, or a sanitizer report is a finding. Built by scripts/fuzz.
#include "fuzz_support.h"

#include <scene/scene.h>
#include <scene/scene_parser.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string text(reinterpret_cast<const char*>(data), size);
    return rayrad::fuzz::onlyInputErrors([&] {
        rayrad::scene::Scene scene = rayrad::scene::buildScene(rayrad::scene::parseScene(text, "fuzz.json", {}));
        (void)scene;
    });
}
