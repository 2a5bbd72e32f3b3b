// Triangle meshes, their materials and lights from OBJ/PLY/glTF/... files through assimp.
#pragma once

#include <core/math.h>

#include <array>
#include <string>
#include <vector>

namespace rayrad::scene {

/// A material as the mesh file gives it (OBJ .mtl, glTF), diffuse only.
struct ImportedMaterial {
    std::string name;
    bool hasReflectance = false;
    Rgb reflectance{0.0};        ///< OBJ Kd, glTF baseColorFactor (linear RGB)
    Rgb emission{0.0};           ///< OBJ Ke, glTF emissiveFactor × emissive strength, read as cd/m²
    std::string diffuseTexture;  ///< OBJ map_Kd, glTF baseColorTexture: the image file, relative to the mesh file
    bool twoSided = false;       ///< glTF doubleSided: both sides reflect
    /// glTF KHR_materials_transmission (transmissionFactor ≥ 0.5): clear glass, with the
    /// index of KHR_materials_ior (1.5 by default).
    bool glass = false;
    double ior = 1.5;
    /// glTF polished metal (metallicFactor ≥ 0.5, roughnessFactor ≤ kMirrorRoughness): a
    /// mirror where its triangles are few and lie in one plane (the builder decides).
    bool mirrorLike = false;
};
constexpr double kMirrorRoughness = 0.1;

/// A punctual light of the file (glTF KHR_lights_punctual): point or spot, in candela.
struct ImportedLight {
    std::string name;
    bool isSpot = false;
    Vec3 position{0.0};
    Vec3 direction{0, 0, -1};    ///< spot axis, unit
    Rgb intensity{0.0};          ///< cd per channel (colour × intensity)
    double innerAngleDeg = 0, outerAngleDeg = 45;
};

/// A camera of the file (glTF), in the file's coordinates.
struct ImportedCamera {
    std::string name;
    Vec3 position{0.0};
    Vec3 direction{0, 0, -1}, up{0, 1, 0};  ///< unit: the camera's −z and +y
    bool orthographic = false;
    double yfovDeg = 45;      ///< perspective: the vertical field of view
    double ymag = 1;          ///< orthographic: half the view's height, in the file's units
    double aspectRatio = 0;   ///< width / height; 0 when the file does not say
};

/// Every mesh of the file as one triangle list in the file's coordinates with the node
/// transforms applied. Vertices at identical positions are shared; polygons are
/// triangulated here (not by assimp, whose post-processing can crash on broken files).
struct ImportedMesh {
    std::vector<Vec3> positions;
    std::vector<std::vector<uint32_t>> triangles;
    std::vector<int> triangleMaterial;     ///< index into materials, or −1 (the file gives none)
    /// Texture coordinates of each triangle's corners; shorter than `triangles` (down to
    /// empty) when the last triangles have none.
    std::vector<std::array<glm::dvec2, 3>> triangleUvs;
    std::vector<ImportedMaterial> materials;
    std::vector<ImportedLight> lights;
    std::vector<ImportedCamera> cameras;   ///< glTF's cameras, placed by their nodes
    size_t droppedFaces = 0;               ///< points, lines, faces with bad indices
    /// What the file asks for that rayrad reads otherwise, one line each without the
    /// file's name: of its geometry and lights, and of its materials (a missing .mtl, glTF
    /// material properties; moot when the scene gives the object a material of its own).
    std::vector<std::string> warnings, materialWarnings;
};

/// Reads the file. Throws InputError("<sceneFile>: <where>/file: ...") if it cannot be
/// read or holds nothing usable; never crashes on a malformed file (indices out of range,
/// non-finite coordinates, empty meshes are checked before use).
ImportedMesh importMesh(const std::string& path, const std::string& sceneFile, const std::string& where);

/// "Assimp 5.2.5": the version this build runs with.
std::string assimpVersion();

}  // namespace rayrad::scene
