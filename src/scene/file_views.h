// Views from mesh files: the cameras of a glTF file become named views of the scene, as
// if the scene file listed them in "cameras".
#pragma once

#include <scene/scene_desc.h>

namespace rayrad::scene {

/// For every mesh object read from a .gltf or .glb file, its cameras (placed by the
/// object's transform) appended to desc.views under their names; the first becomes the
/// default view when the scene gives no "camera" or "cameras". Resolution: 480 rows, the
/// file's aspect ratio (4:3 when it gives none). Throws InputError for a camera whose name
/// a view of the scene already has, or "all".
void addFileViews(SceneDesc& desc);

}  // namespace rayrad::scene
