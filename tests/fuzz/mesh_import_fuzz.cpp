// libFuzzer target for the mesh importers: any byte string is a mesh file of the format
// RAYRAD_FUZZ_EXTENSION names (".obj", ".ply", ".gltf", ".glb"). It is written to a file
// and read the way a scene's "mesh" object reads it. A bad file must come back as an
// InputError; any other exception, a crash, a hang or a sanitizer report is a finding.
// Built by scripts/fuzz.
#include "fuzz_support.h"

#include <scene/mesh_import.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const std::string path = "/tmp/rayrad-fuzz-" + std::to_string(getpid()) + RAYRAD_FUZZ_EXTENSION;
    FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) std::abort();
    if (size > 0 && std::fwrite(data, 1, size, f) != size) std::abort();
    std::fclose(f);
    return rayrad::fuzz::onlyInputErrors([&] {
        rayrad::scene::ImportedMesh mesh = rayrad::scene::importMesh(path, "fuzz.json", "/objects/0");
        (void)mesh;
    });
}
