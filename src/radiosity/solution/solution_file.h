// A saved radiosity solution (rayrad solve --save FILE.rrs, render --solution FILE.rrs):
// solve once, render any number of views later. Versioned and checksummed, with the
// fingerprint of what the solution depends on, so a solution is never applied to a scene
// it was not computed for.
#pragma once

#include <radiosity/mesh/patch_mesh.h>
#include <radiosity/solution/solution.h>
#include <scene/scene.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace rayrad::radiosity {

/// What a solution depends on, each part hashed (64-bit FNV-1a) on its own so a mismatch
/// can say which part differs. Cameras, sensors and render settings are not in it.
struct SolutionFingerprint {
    uint64_t geometry = 0;   ///< the premeshed patches: vertex positions, corners, materials
    uint64_t materials = 0;  ///< kind, reflectance, emission, specular, index, sides
    uint64_t lights = 0;     ///< point lights, spots and luminaires (their tables too)
    uint64_t settings = 0;   ///< the radiosity and cluster settings
    /// The emitters with each one's strength divided by its light group's strength: equal
    /// when the scenes differ only by dimming whole groups. Not part of the match above.
    uint64_t lightShapes = 0;
    /// Each light group's strength, in the order of scene::lightGroups ("" the emitters in
    /// no group): Σ luminance(I) × photometric scale over its lights + Σ luminance(L_e)
    /// over its emissive materials. Only ratios of the same group's strength are used.
    std::vector<std::pair<std::string, double>> groupStrengths;
};

/// One light group's part of a solution (the group solved alone), saved so a scene whose
/// groups are dimmed can be rendered from it.
struct GroupSolution {
    std::string group;
    RadiositySolution solution;
};

SolutionFingerprint fingerprintOf(const scene::Scene& scene, const PatchMesh& mesh);

/// The file's bytes: magic "RAYRADSOL", format version, byte-order mark, fingerprint,
/// counts, the per-patch and per-vertex arrays, the solve's statistics, and a checksum of
/// all of it.
std::string encodeSolution(const RadiositySolution& solution, const SolutionFingerprint& fingerprint,
                           size_t vertexCount, const std::vector<GroupSolution>& groups = {});

/// The solution in `bytes` (read from `path`, named in messages). Throws InputError when
/// it is not a rayrad solution, is of another version or byte order, is damaged (the
/// checksum), or was computed for another scene: the message says whether the geometry,
/// the materials, the lights or the settings differ. Lights that differ only by dimming
/// whole light groups are accepted when the file holds the groups' parts: the solution is
/// then Σ_g (S'_g / S_g) part_g, with S the groups' strengths then and now.
/// Throws InputError naming `path` unless the file starts as a solution file does: read
/// before the whole file is (a 10 GB file of something else is refused at once).
void checkSolutionFileStart(const std::string& path);

RadiositySolution decodeSolution(const std::string& bytes, const std::string& path, const SolutionFingerprint& expected,
                                 size_t patchCount, size_t vertexCount);

}  // namespace rayrad::radiosity
