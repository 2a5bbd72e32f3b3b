#!/usr/bin/env bash
# Bad input through the real command line: exit code 2 (3 for outputs), exactly one line
# on stderr that names the file and the place, and no output file created or damaged.
# Outputs and results have their own catalogue: output_safety_test.sh.
set -u
rayrad="$1"
src="$2"
source "$(dirname "$0")/test_lib.sh"

good_camera='"camera": {"position": [0.5,0.5,0.1], "look_at": [0.5,0.5,1], "resolution": [8,8]}'

scene malformed '{ "materials": { "white": { "reflectance": 0.5, } } }'
expect 2 "malformed JSON" "$work/malformed.json: line 1, column" -- solve "$work/malformed.json"

scene unknown_material "{$good_materials, \"objects\": [{\"type\": \"box\", \"min\": [0,0,0], \"max\": [1,1,1], \"material\": \"whte\"}], $good_light}"
expect 2 "unknown material" "unknown_material.json: /objects/0/material: unknown material \"whte\" (did you mean \"white\"?)" -- solve "$work/unknown_material.json"

scene negative "{$good_materials, $good_box, \"lights\": [{\"type\": \"point\", \"position\": [0.5,0.5,0.5], \"intensity_cd\": -5}]}"
expect 2 "negative intensity" "negative.json: /lights/0/intensity_cd: expected a positive number, got -5" -- solve "$work/negative.json"

scene reflectance "{\"materials\": {\"white\": {\"reflectance\": 1.0}}, $good_box, $good_light}"
expect 2 "reflectance >= 1" "reflectance.json: /materials/white/reflectance: expected values in [0, 0.999]" -- solve "$work/reflectance.json"

scene mesh "{$good_materials, \"objects\": [{\"type\": \"mesh\", \"file\": \"missing.obj\", \"material\": \"white\"}], $good_light}"
expect 2 "missing mesh" "mesh.json: /objects/0/file: mesh file" -- solve "$work/mesh.json"

mirror_materials='"materials": {"white": {"reflectance": 0.5}, "m": {"type": "mirror", "specular_reflectance": 0.9}}'
scene curved_mirror "{$mirror_materials, \"objects\": [{\"type\": \"sphere\", \"material\": \"m\"}], $good_light}"
expect 2 "curved mirror" "curved_mirror.json: /objects/0/material: a mirror must be a quad, polygon or box" -- solve "$work/curved_mirror.json"
scene mirror_type "{\"materials\": {\"white\": {\"type\": \"mirorr\"}}, $good_box, $good_light}"
expect 2 "material type typo" "mirror_type.json: /materials/white/type: unknown material type \"mirorr\" (did you mean \"mirror\"?)" -- solve "$work/mirror_type.json"
scene mirror_ks "{\"materials\": {\"white\": {\"reflectance\": 0.5}, \"m\": {\"type\": \"mirror\", \"specular_reflectance\": 1.5}}, $good_box, $good_light}"
expect 2 "mirror Ks > 1" "mirror_ks.json: /materials/m/specular_reflectance: expected values in [0, 1]" -- solve "$work/mirror_ks.json"

expect 2 "missing scene" "$work/nothere.json: no such file" -- solve "$work/nothere.json"

scene good "{$good_materials, $good_box, $good_light, $good_camera}"
expect 3 "unwritable output" "$work/no/such/dir/out.png: cannot write: directory" -- render "$work/good.json" -o "$work/no/such/dir/out.png"
expect 3 "unknown image format" "$work/out.bmp: unknown image format" -- render "$work/good.json" -o "$work/out.bmp"
expect 3 "unwritable csv" "$work/nodir/out.csv: cannot write" -- solve "$work/good.json" --sensors "$work/nodir/out.csv"
expect 2 "bad --set" "/radiosity/max_egde: unknown key (did you mean \"max_edge\"?)" -- solve "$work/good.json" --set radiosity.max_egde=1
expect 2 "--set with slashes" "--set radiosity/max_edge=1: keys are separated by dots: did you mean radiosity.max_edge=1?" -- solve "$work/good.json" --set radiosity/max_edge=1
expect 2 "bad --exposure" "--exposure: expected \"auto\" or a number" -- render "$work/good.json" -o "$work/out.png" --exposure bright
# Tone reproduction and white balance: named before any work.
expect 2 "unknown --tonemap" "--tonemap: expected exposure, tumblin-rushmeier, ward or reinhard, got \"aces\"" -- render "$work/good.json" -o "$work/out.png" --tonemap aces
expect 2 "--exposure with ward" "--exposure: sets the exposure operator's scale" -- render "$work/good.json" -o "$work/out.png" --tonemap ward --exposure 2
expect 2 "--key nan" "--key: expected a number from 0.0001 to 10, got nan" -- render "$work/good.json" -o "$work/out.png" --tonemap reinhard --key nan
expect 2 "--display-max inf" "--display-max: expected a number" -- render "$work/good.json" -o "$work/out.png" --tonemap ward --display-max inf
expect 2 "bad --white-balance" "--white-balance: expected none, a colour temperature" -- render "$work/good.json" -o "$work/out.png" --white-balance warm
expect 2 "--white-balance 500K" "--white-balance: expected a colour temperature from 1667 to 25000 K" -- render "$work/good.json" -o "$work/out.png" --white-balance 500K
expect 2 "white-balance region outside" "--white-balance: the region 4,4 8×8 is not inside the 8×8 image" -- render "$work/good.json" -o "$work/out.png" --white-balance region:4,4,8,8
scene nocamera "{$good_materials, $good_box, $good_light}"
expect 2 "render without camera" "nocamera.json: /camera: rendering needs a camera" -- render "$work/nocamera.json" -o "$work/out.png"

# An existing output survives a failed run untouched.

# The catalogue: one line each naming the file (and the place), exit 2.
cat_case() {  # cat_case NAME WANT JSON
    scene "$1" "$3"
    expect 2 "$1" "$1.json: $2" -- solve "$work/$1.json"
}
cat_case empty_file "" ''
cat_case not_object "" '[1, 2, 3]'
cat_case truncated "line 2" '{"materials": {'
cat_case trailing_garbage "" '{} xyz'
cat_case empty_scene "" '{}'
cat_case no_objects "" "{$good_materials, $good_light}"
cat_case objects_not_array "/objects" "{$good_materials, \"objects\": 5, $good_light}"
cat_case unknown_top_key "/lihgts" "{$good_materials, $good_box, $good_light, \"lihgts\": []}"
cat_case unknown_object_key '/objects/0/mni: unknown key (did you mean "min"? it is required)' "{$good_materials, \"objects\": [{\"type\": \"box\", \"mni\": [0,0,0], \"max\": [1,1,1], \"material\": \"white\"}], $good_light}"
cat_case unknown_light_key '/lights/0/positon: unknown key (did you mean "position"? it is required)' "{$good_materials, $good_box, \"lights\": [{\"type\": \"point\", \"positon\": [0.5,0.5,0.5], \"intensity_cd\": 10}]}"
cat_case unknown_optional_key '/objects/0/facnig: unknown key (did you mean "facing"?)' "{$good_materials, \"objects\": [{\"type\": \"box\", \"min\": [0,0,0], \"max\": [1,1,1], \"facnig\": \"inward\", \"material\": \"white\"}], $good_light}"
cat_case unknown_object_type "/objects/0/type" "{$good_materials, \"objects\": [{\"type\": \"bx\", \"material\": \"white\"}], $good_light}"
cat_case unknown_light_type "/lights/0/type" "{$good_materials, $good_box, \"lights\": [{\"type\": \"pont\", \"position\": [0.5,0.5,0.5], \"intensity_cd\": 10}]}"
cat_case string_for_number "/lights/0/intensity_cd" "{$good_materials, $good_box, \"lights\": [{\"type\": \"point\", \"position\": [0.5,0.5,0.5], \"intensity_cd\": \"ten\"}]}"
cat_case nan_value "" "{$good_materials, $good_box, \"lights\": [{\"type\": \"point\", \"position\": [0.5,NaN,0.5], \"intensity_cd\": 10}]}"
cat_case huge_value "line 1, column" "{$good_materials, $good_box, \"lights\": [{\"type\": \"point\", \"position\": [0.5,1e999,0.5], \"intensity_cd\": 10}]}"
cat_case short_vector "/lights/0/position" "{$good_materials, $good_box, \"lights\": [{\"type\": \"point\", \"position\": [0.5,0.5], \"intensity_cd\": 10}]}"
cat_case negative_reflectance "/materials/white/reflectance" "{\"materials\": {\"white\": {\"reflectance\": -0.1}}, $good_box, $good_light}"
cat_case rgb_reflectance_one "/materials/white/reflectance" "{\"materials\": {\"white\": {\"reflectance\": [0.5, 1.0, 0.2]}}, $good_box, $good_light}"
cat_case zero_intensity "/lights/0/intensity_cd" "{$good_materials, $good_box, \"lights\": [{\"type\": \"point\", \"position\": [0.5,0.5,0.5], \"intensity_cd\": 0}]}"
cat_case spot_angles "/lights/0" "{$good_materials, $good_box, \"lights\": [{\"type\": \"spot\", \"position\": [0.5,0.5,0.5], \"look_at\": [0.5,0,0.5], \"intensity_cd\": 10, \"inner_angle_deg\": 40, \"outer_angle_deg\": 20}]}"
cat_case degenerate_box "/objects/0" "{$good_materials, \"objects\": [{\"type\": \"box\", \"min\": [0,0,0], \"max\": [1,0,1], \"material\": \"white\"}], $good_light}"
cat_case degenerate_quad "/objects/0" "{$good_materials, \"objects\": [{\"type\": \"quad\", \"vertices\": [[0,0,0],[1,0,0],[2,0,0],[3,0,0]], \"material\": \"white\"}], $good_light}"
cat_case zero_radius "/objects/0/radius" "{$good_materials, \"objects\": [{\"type\": \"sphere\", \"radius\": 0, \"material\": \"white\"}], $good_light}"
cat_case zero_scale "/objects/0/transform/scale" "{$good_materials, \"objects\": [{\"type\": \"box\", \"min\": [0,0,0], \"max\": [1,1,1], \"material\": \"white\", \"transform\": {\"scale\": [1,0,1]}}], $good_light}"
cat_case absurd_resolution "/camera/resolution" "{$good_materials, $good_box, $good_light, \"camera\": {\"position\": [0.5,0.5,0.1], \"look_at\": [0.5,0.5,1], \"resolution\": [100000000, 100000000]}}"
cat_case zero_resolution "/camera/resolution" "{$good_materials, $good_box, $good_light, \"camera\": {\"position\": [0.5,0.5,0.1], \"look_at\": [0.5,0.5,1], \"resolution\": [0, 8]}}"
cat_case camera_look_at_self "/camera" "{$good_materials, $good_box, $good_light, \"camera\": {\"position\": [0.5,0.5,0.5], \"look_at\": [0.5,0.5,0.5], \"resolution\": [8, 8]}}"
cat_case sensor_zero_normal "/sensors/0/normal" "{$good_materials, $good_box, $good_light, \"sensors\": [{\"name\": \"s\", \"position\": [0.5,0,0.5], \"normal\": [0,0,0]}]}"
cat_case bad_stop_unshot "/radiosity/stop_unshot" "{$good_materials, $good_box, $good_light, \"radiosity\": {\"stop_unshot\": 2}}"
cat_case bad_spp "/render/spp" "{$good_materials, $good_box, $good_light, \"render\": {\"spp\": -1}}"
cat_case bad_ior "/materials/g/ior" "{\"materials\": {\"white\": {\"reflectance\": 0.5}, \"g\": {\"type\": \"glass\", \"ior\": 0.5}}, $good_box, $good_light}"
printf 'v 0 0 0\nv 1 0 0\nf 1 2 7\n' > "$work/broken.obj"
cat_case broken_mesh "/objects/0" "{$good_materials, \"objects\": [{\"type\": \"mesh\", \"file\": \"broken.obj\", \"material\": \"white\"}], $good_light}"
printf 'v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n' > "$work/flat.obj"
cat_case zero_area_mesh "/objects/0" "{$good_materials, \"objects\": [{\"type\": \"mesh\", \"file\": \"flat.obj\", \"material\": \"white\"}], $good_light}"
printf 'v 0 0 0\n' > "$work/unreadable.obj"; chmod 000 "$work/unreadable.obj"
if [ "$(id -u)" -ne 0 ]; then
    cat_case unreadable_mesh "/objects/0/file" "{$good_materials, \"objects\": [{\"type\": \"mesh\", \"file\": \"unreadable.obj\", \"material\": \"white\"}], $good_light}"
fi
cat_case back_without_two_sided "/materials/white/back_reflectance" "{\"materials\": {\"white\": {\"reflectance\": 0.5, \"back_reflectance\": 0.2}}, $good_box, $good_light}"
cat_case bad_max_seconds "/radiosity/max_seconds" "{$good_materials, $good_box, $good_light, \"radiosity\": {\"max_seconds\": -1}}"
# Meshes: a PLY without materials needs one; broken and hostile PLY files name the problem.
printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n' > "$work/tri.ply"
cat_case mesh_without_material "/objects/0/material" "{$good_materials, \"objects\": [{\"type\": \"mesh\", \"file\": \"tri.ply\"}], $good_light}"
printf 'ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty float x\nproperty float y\nproperty float z\nend_header\nxyz' > "$work/huge.ply"
scene ply_huge_count "{$good_materials, \"objects\": [{\"type\": \"mesh\", \"file\": \"huge.ply\", \"material\": \"white\"}], $good_light}"
expect 2 "PLY claiming 4e9 vertices" "huge.ply': element 'vertex' claims 4000000000 records, more than the 3 bytes left" -- solve "$work/ply_huge_count.json"
{ printf 'ply\nformat binary_little_endian 1.0\n'; head -c 600 /dev/zero | tr '\0' '\377'; } > "$work/garbage.ply"
scene ply_garbage "{$good_materials, \"objects\": [{\"type\": \"mesh\", \"file\": \"garbage.ply\", \"material\": \"white\"}], $good_light}"
expect 2 "PLY with garbage after its header" "ply_garbage.json: /objects/0/file: mesh '$work/garbage.ply': header line 3" -- solve "$work/ply_garbage.json"
# glTF, read by tinygltf and checked by rayrad: the first input is the one that
# made assimp read past its buffer under the fuzzer.
mesh_case() {  # mesh_case NAME FILE WANT: a scene whose mesh is FILE (in $work)
    scene "$1" "{$good_materials, \"objects\": [{\"type\": \"mesh\", \"file\": \"$2\", \"material\": \"white\"}], $good_light}"
    expect 2 "$1" "$1.json: /objects/0/file: mesh '$work/$2': $3" -- solve "$work/$1.json"
}
printf 'glT": {"versioindexarrayn"aaaaaaaaaaaaaaaaaaaaaaaaaaaaa{"aa' > "$work/notjson.gltf"
mesh_case gltf_not_json notjson.gltf "not a valid glTF 2.0 file"
tri_buffer='"buffers": [{"byteLength": 44, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIAAAA="}], "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}]'
gltf() {  # gltf FILE ACCESSORS: a one-triangle glTF with the given accessors
    printf '%s\n' "{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [{\"mesh\": 0}], \"meshes\": [{\"primitives\": [{\"attributes\": {\"POSITION\": 0}, \"indices\": 1}]}], $tri_buffer, \"accessors\": $2}" > "$work/$1"
}
gltf long.gltf '[{"bufferView": 0, "componentType": 5126, "count": 300, "type": "VEC3"}, {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}]'
mesh_case gltf_accessor_too_long long.gltf "mesh 0 POSITION (accessor 0): 300 elements reach past the end of its buffer view"
gltf offset.gltf '[{"bufferView": 0, "byteOffset": 4000000000, "componentType": 5126, "count": 3, "type": "VEC3"}, {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}]'
mesh_case gltf_accessor_offset offset.gltf "mesh 0 POSITION (accessor 0): 3 elements reach past the end of its buffer view"
gltf intpos.gltf '[{"bufferView": 0, "componentType": 5125, "count": 3, "type": "VEC3"}, {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}]'
mesh_case gltf_int_positions intpos.gltf "mesh 0: POSITION must be float"
gltf noaccessor.gltf '[{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}]'
mesh_case gltf_missing_accessor noaccessor.gltf "not a valid glTF 2.0 file: primitive indices accessor out of bounds"
gltf badindex.gltf '[{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}, {"bufferView": 1, "componentType": 5126, "count": 1, "type": "SCALAR"}]'
mesh_case gltf_float_indices badindex.gltf "mesh 0: indices must be unsigned integers"
printf 'glTF\001\000\000\000\014\000\000\000' > "$work/v1.glb"
mesh_case glb_version_1 v1.glb "not a valid glTF 2.0 file"
printf '%s\n' '{"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"children": [0]}]}' > "$work/cycle.gltf"
mesh_case gltf_node_cycle cycle.gltf "the node hierarchy is deeper than 256 levels (a cycle?)"
# A PLY element without properties that claims 2.7e15 records (found by the fuzzer: it
# looped over the empty records).
cp "$src/tests/fuzz/seeds/ply/regression_empty_element.ply" "$work/empty_element.ply"
scene ply_empty_element "{$good_materials, \"objects\": [{\"type\": \"mesh\", \"file\": \"empty_element.ply\", \"material\": \"white\"}], $good_light}"
expect 2 "PLY element without properties" "ply_empty_element.json: /objects/0/file: mesh '$work/empty_element.ply' has no triangles" -- solve "$work/ply_empty_element.json"
mkdir -p "$work/adir.json"
expect 2 "scene is a directory" "adir.json" -- solve "$work/adir.json"

# Absurd sizes: an error naming the setting, before anything is allocated.
scene tiny_edge "{$good_materials, $good_box, $good_light, \"radiosity\": {\"max_edge\": 1e-5}}"
# Under a 1 GB address-space limit: a premesher that began the 1.2e11 patches would fail
# with another message (out of memory) instead of naming the setting.
within_1gb() { (ulimit -v 1000000 && exec "$unlimited" "$@"); }
unlimited="$rayrad"; rayrad=within_1gb
expect 2 "max_edge 1e-5" "tiny_edge.json: /radiosity/max_edge: premeshing to 1e-05 m edges would make about 1.2e+11 patches" -- solve "$work/tiny_edge.json"
rayrad="$unlimited"
scene tiny_voxel "{$good_materials, $good_box, $good_light, \"clusters\": {\"voxel_size\": 1e-12}}"
expect 2 "voxel_size 1e-12" "tiny_voxel.json: /clusters/voxel_size: a cluster voxel of 1e-12 m makes 1e+12 voxels" -- solve "$work/tiny_voxel.json"
scene small_voxel "{$good_materials, $good_box, $good_light, \"clusters\": {\"voxel_size\": 1e-6}, \"radiosity\": {\"max_edge\": 0.25}}"
if "$rayrad" info "$work/small_voxel.json" 2>&1 | grep -q "warning: /clusters/voxel_size: a cluster voxel of 1e-06 m is smaller than the patches"; then
    passed=$((passed + 1))
else
    echo "FAIL voxel_size 1e-6: no warning from info"; failures=$((failures + 1))
fi

# A million sensors: the warning with the gather's estimate comes before any work — it is
# the first line the solve writes (its summary follows the solve) — and the solve is
# stopped once it has appeared.
scene million_sensors "{$good_materials, $good_box, $good_light, \"sensor_grids\": [{\"name\": \"g\", \"origin\": [0.01,0.01,0.5], \"u\": [0.98,0,0], \"v\": [0,0.98,0], \"counts\": [1000, 1000]}]}"
"$rayrad" solve "$work/million_sensors.json" > /dev/null 2> "$work/million.txt" &
million=$!
while kill -0 "$million" 2> /dev/null && ! grep -q "^warning" "$work/million.txt"; do sleep 0.1; done
kill "$million" 2> /dev/null; wait "$million" 2> /dev/null
if head -n 1 "$work/million.txt" | grep -q "/sensors: 1000000 sensors: the final gather will take at least 17 CPU-minutes"; then
    passed=$((passed + 1))
else
    echo "FAIL a million sensors: the estimate is not the first line"; head -n 3 "$work/million.txt"; failures=$((failures + 1))
fi

# Walkthroughs, export, sweeps and textures.
good_camera='"camera": {"position": [0.5,0.5,0.9], "look_at": [0.5,0.5,0], "resolution": [8, 8]}'
good_path='"camera_path": {"frames": 3, "resolution": [8, 8], "keyframes": [{"position": [0.5,0.5,0.9], "look_at": [0.5,0.5,0]}, {"position": [0.4,0.5,0.8], "look_at": [0.5,0.4,0]}]}'
scene walk "{$good_materials, $good_box, $good_light, $good_camera, $good_path}"
expect 2 "frames beyond the path" "frame 3 is beyond the path's 3 frames" -- render "$work/walk.json" --frames 0:3 -o "$work/out.png"
expect 2 "frames malformed" "expected all, K or A:B" -- render "$work/walk.json" --frames 1:x -o "$work/out.png"
expect 3 "frames into a missing directory" "out.0000.png: cannot write: directory" -- render "$work/walk.json" --frames all -o "$work/nowhere/out.png"
scene still "{$good_materials, $good_box, $good_light, \"camera_path\": {\"frames\": 3, \"keyframes\": [{\"position\": [0.5,0.5,0.9], \"look_at\": [0.5,0.5,0]}, {\"position\": [0.5,0.5,0.9], \"look_at\": [0.5,0.5,0]}]}}"
expect 2 "a path that does not move" "still.json: /camera_path: the keyframes do not move" -- render "$work/still.json" --frames all -o "$work/out.png"
expect 2 "export to another format" "the lit mesh is written as binary glTF" -- export "$work/walk.json" -o "$work/out.obj"
expect 3 "export into a missing directory" "cannot write: directory" -- export "$work/walk.json" -o "$work/nowhere/out.glb"
expect 2 "sweep without a value" "an empty value in" -- sweep "$work/walk.json" --vary radiosity.max_edge=0.5,,0.25 --jobs "$work/out.txt"
expect 2 "sweep value the scene refuses" "job 1 (0.5,-3)" -- sweep "$work/walk.json" --vary radiosity.max_edge=0.5 --vary lights.0.intensity_cd=10,-3 --jobs "$work/out.txt"
expect 2 "sweep with --set in the command" "give the values to vary with --vary" -- sweep "$work/walk.json" --vary radiosity.max_edge=0.5 --run "solve --set render.spp=2" --jobs "$work/out.txt"
scene texture_dir "{\"materials\": {\"white\": {\"texture\": \"$work\"}}, $good_box, $good_light}"
expect 2 "a texture that is a directory" "texture_dir.json: /materials/white/texture: $work: is a directory, not a texture image" -- solve "$work/texture_dir.json"
printf 'not a png' > "$work/fake.png"
scene texture_fake "{\"materials\": {\"white\": {\"texture\": \"fake.png\"}}, $good_box, $good_light}"
expect 2 "a texture that is not an image" "fake.png: not a texture image OpenImageIO can read" -- solve "$work/texture_fake.json"
scene texture_sphere "{\"materials\": {\"white\": {\"texture\": \"fake.png\"}}, \"objects\": [{\"type\": \"sphere\", \"center\": [0,0,0], \"radius\": 1, \"material\": \"white\"}], $good_light}"
expect 2 "a textured sphere" "not onto a polygon or a sphere" -- solve "$work/texture_sphere.json"
scene smoothing "{$good_materials, $good_box, $good_light, \"render\": {\"smoothing_angle_deg\": 95}}"
expect 2 "smoothing angle out of range" "/render/smoothing_angle_deg: expected an angle in [0, 90)" -- solve "$work/smoothing.json"

echo keep > "$work/keep.png"
"$rayrad" render "$work/negative.json" -o "$work/keep.png" >/dev/null 2>&1
if [ "$(cat "$work/keep.png")" != keep ]; then echo "FAIL existing output was overwritten"; failures=$((failures + 1)); else passed=$((passed + 1)); fi

finish "bad input"
