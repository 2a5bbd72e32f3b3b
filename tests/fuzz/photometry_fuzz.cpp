// libFuzzer target for the photometric files: any byte string is an IES or EULUMDAT file
// (RAYRAD_FUZZ_EXTENSION ".ies" or ".ldt"), parsed and then looked up and integrated as
// `rayrad info` does. A bad file must come back as an InputError. Built by scripts/fuzz.
#include "fuzz_support.h"

#include <scene/photometry.h>

#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    return rayrad::fuzz::onlyInputErrors([&] {
        const std::string name = std::string("fuzz") + RAYRAD_FUZZ_EXTENSION;
        const rayrad::scene::Photometry p = std::string(RAYRAD_FUZZ_EXTENSION) == ".ies"
                                                ? rayrad::scene::parseIes(text, name)
                                                : rayrad::scene::parseLdt(text, name);
        (void)p.integratedFlux();
        (void)p.intensity(33, 217);
        (void)p.peak();
    });
}
