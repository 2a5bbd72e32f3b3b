// glTF 2.0 meshes (.gltf with embedded or external buffers, .glb), parsed by tinygltf
// (Debian libtinygltf-dev) and then checked by rayrad before any value is used: every
// accessor's range against its buffer, every index against its vertices, the node tree's
// depth and size. Assimp is not used for glTF: on malformed .gltf files it falls back to
// sniffing every other format, and one of those reads past its buffer (found by
// scripts/fuzz).
#pragma once

#include <scene/mesh_import.h>

#include <string>

namespace rayrad::scene {

/// Reads `path`: the triangles of the default scene's nodes (triangle lists, strips and
/// fans; points and lines are counted as dropped), with the node transforms applied;
/// materials (baseColorFactor, emissiveFactor × KHR_materials_emissive_strength, the
/// base colour texture's name) and KHR_lights_punctual point and spot lights (candela).
/// Throws InputError(errorPrefix + reason) for a file that cannot be used.
ImportedMesh readGltf(const std::string& path, const std::string& errorPrefix);

}  // namespace rayrad::scene
