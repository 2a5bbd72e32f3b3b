// Stanford PLY meshes (ASCII, binary little and big endian), read by rayrad itself: the
// file is checked as it is read, so a broken or hostile file gives a clear error.
#pragma once

#include <core/math.h>

#include <string>
#include <vector>

namespace rayrad::scene {

/// The vertices (x, y, z) and faces (vertex_indices or vertex_index lists) of a PLY
/// file; other elements and properties are skipped.
struct PlyMesh {
    std::vector<Vec3> positions;
    std::vector<std::vector<uint32_t>> faces;  ///< as written: 3 or more indices, unchecked
};

/// Reads `path`. Throws std::runtime_error with the reason and where in the file
/// ("header line 4: ...", "face 17: ..."); allocates nothing the file's size cannot
/// back (a header claiming 4·10⁹ vertices in a 200-byte file is an error, not bad_alloc).
PlyMesh readPly(const std::string& path);

}  // namespace rayrad::scene
