#include <app/version.h>

#include <raytrace/embree_scene.h>
#include <scene/mesh_import.h>
#include <tonemap/image_io.h>

namespace rayrad::app {

std::string versionText() {
    return "rayrad " RAYRAD_VERSION "\n" + raytrace::embreeVersion() + ", " + tonemap::libraryVersions() + ", " +
           scene::assimpVersion();
}

}  // namespace rayrad::app
