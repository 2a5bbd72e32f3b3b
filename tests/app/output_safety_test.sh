#!/usr/bin/env bash
# Outputs, results and inputs through the real command line: an output that
# cannot be written is refused before any work (exit 3) or fails cleanly at the end (exit
# 3: no temporary file left, the old file byte-identical); a result that must not be
# handed over is refused (exit 4); bad options and input files are named (exit 2).
set -u
rayrad="$1"
src="$2"
source "$(dirname "$0")/test_lib.sh"

scene good '{"materials": {"white": {"type": "diffuse", "reflectance": 0.5}},
 "objects": [{"type": "box", "min": [0,0,0], "max": [1,1,1], "facing": "inward", "material": "white"}],
 "lights": [{"type": "point", "position": [0.5,0.5,0.5], "intensity_cd": 10}],
 "sensors": [{"name": "s", "position": [0.5,0,0.5], "normal": [0,1,0]}],
 "camera": {"position": [0.5,0.5,0.1], "look_at": [0.5,0.5,1], "resolution": [8,8]}}'
good="$work/good.json"
cp "$good" "$work/good.orig"
same_scene() { cmp -s "$good" "$work/good.orig"; }

# intact NAME FILE: FILE still holds "keep" (the old output survived).
intact() {
    if [ "$(cat "$2" 2>/dev/null)" = keep ]; then passed=$((passed + 1)); else echo "FAIL $1: $2 was changed"; failures=$((failures + 1)); fi
}

# ---- outputs that name an input or each other (exit 3, before any work) -------------
expect 3 "--sensors is the scene" "good.json: cannot write: it is an input of this run" -- solve "$good" --sensors "$good" -q
check "scene unchanged after --sensors scene" same_scene
expect 3 "--report is the scene" "it is an input of this run" -- render "$good" -o "$work/out.png" --report "$good" -q
expect 3 "--convergence is the scene" "it is an input of this run" -- solve "$good" --convergence "$good" -q
check "scene unchanged" same_scene
expect 3 "-o and --report one file" "out.png: cannot write: given twice as an output" -- render "$good" -o "$work/out.png" --report "$work/out.png" -q
expect 3 "two names, one file" "cannot write: it is the same file as the output" -- render "$good" -o "$work/out.png" -o "$work/./out.png" -q
expect 3 "--sensors and --report one file" "given twice as an output" -- solve "$good" --sensors "$work/out.csv" --report "$work/out.csv" -q
ln -s "$good" "$work/link-to-scene.png"
expect 3 "output symlinked to the scene" "it is an input of this run" -- render "$good" -o "$work/link-to-scene.png" -q
check "scene unchanged through a symlink" same_scene
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' > "$work/tri.obj"
scene withmesh "{\"materials\": {\"white\": {\"reflectance\": 0.5}}, \"objects\": [{\"type\": \"mesh\", \"file\": \"tri.obj\", \"material\": \"white\"}], \"lights\": [{\"type\": \"point\", \"position\": [0.3,0.3,1], \"intensity_cd\": 10}]}"
expect 3 "--report is a mesh file" "tri.obj: cannot write: it is an input of this run" -- solve "$work/withmesh.json" --report "$work/tri.obj" -q
cp "$src/tests/data/luminaires/radiance_examp1.ies" "$work/lum.ies"
cp "$work/lum.ies" "$work/lum.orig"
expect 3 "--sensors is a luminaire's file" "lum.ies: cannot write: it is an input of this run" -- solve "$good" -q \
    --set 'lights=[{"type": "luminaire", "file": "lum.ies", "position": [0.5, 0.9, 0.5]}]' --sensors "$work/lum.ies"
check "luminaire file unchanged" cmp -s "$work/lum.ies" "$work/lum.orig"

# ---- paths that cannot be written (exit 3, before any work) --------------------------
mkdir "$work/adir"
expect 3 "output is a directory" "adir: cannot write: is a directory" -- render "$good" -o "$work/adir" -q
expect 3 "output ends in a slash" "adir/: cannot write: names a directory, not a file" -- solve "$good" --sensors "$work/adir/" -q
mkfifo "$work/fifo.csv"
expect 3 "output is a named pipe" "fifo.csv: cannot write: is a named pipe" -- solve "$good" --sensors "$work/fifo.csv" -q
if [ "$(id -u)" -eq 0 ] && mknod "$work/null.csv" c 1 3 2>/dev/null; then
    expect 3 "output is a device" "null.csv: cannot write: is a character device" -- solve "$good" --sensors "$work/null.csv" -q
fi
expect 3 "output is /dev/null" "/dev/null: cannot write: is a character device" -- solve "$good" --sensors /dev/null -q
expect 3 "directory missing" "cannot write: directory '$work/nodir' does not exist" -- render "$good" -o "$work/nodir/out.png" -q
expect 3 "a file used as a directory" "is not a directory" -- render "$good" -o "$good/out.png" -q
echo keep > "$work/readonly.png"; chmod 444 "$work/readonly.png"
expect 3 "read-only output" "readonly.png: cannot write: the file exists and is read-only" -- render "$good" -o "$work/readonly.png" -q
intact "read-only output" "$work/readonly.png"
ln -s nowhere/x.png "$work/dangling.png"
expect 3 "symlink into a missing directory" "dangling.png: cannot write: directory" -- render "$good" -o "$work/dangling.png" -q
ln -s loop-b.png "$work/loop-a.png"; ln -s loop-a.png "$work/loop-b.png"
expect 3 "output is a symlink loop" "loop-a.png: cannot write: a loop of symbolic links" -- render "$good" -o "$work/loop-a.png" -q
expect 3 "unknown image format" "out.tif: unknown image format '.tif'" -- render "$good" -o "$work/out.tif" -q
expect 3 "no extension" "unknown image format ''" -- render "$good" -o "$work/out" -q
long=$(printf 'a%.0s' $(seq 252))
# Refused before the solve: the one line on stderr is the error, not a run's summary.
expect 3 "file name over NAME_MAX" "the file name is 256 bytes, longer than the 255 its file system allows" -- render "$good" -o "$work/$long.png" -q
echo keep > "$work/out.snap01.png"; chmod 444 "$work/out.snap01.png"
expect 3 "read-only snapshot" "out.snap01.png: cannot write: the file exists and is read-only" -- render "$good" -o "$work/out.png" --snapshots 1 -q
chmod 644 "$work/out.snap01.png"; rm -f "$work/out.snap01.png"
echo keep > "$work/keep.png"
expect 3 "one bad output of three: nothing written" "nodir" -- render "$good" -o "$work/keep.png" -o "$work/outa.exr" -o "$work/nodir/b.png" -q
intact "one bad output of three" "$work/keep.png"

# ---- what must work ------------------------------------------------------------------
long=$(printf 'a%.0s' $(seq 251))
if "$rayrad" render "$good" -o "$work/$long.png" -q >/dev/null 2>&1 && [ -s "$work/$long.png" ] && ! ls -a "$work" | grep -q '^\.rayrad-'; then
    passed=$((passed + 1))
else
    echo "FAIL a 255-byte file name"; failures=$((failures + 1))
fi
rm -f "$work/$long.png"
echo keep > "$work/target.png"; ln -s target.png "$work/via-link.png"
if "$rayrad" render "$good" -o "$work/via-link.png" -q >/dev/null 2>&1 && [ -L "$work/via-link.png" ] &&
    [ "$(head -c 4 "$work/target.png" | tail -c 3)" = PNG ]; then
    passed=$((passed + 1))
else
    echo "FAIL a symlinked output: the link must stay and its target be replaced"; failures=$((failures + 1))
fi
chmod 640 "$work/target.png"
"$rayrad" render "$good" -o "$work/target.png" -q >/dev/null 2>&1
if [ "$(stat -c %a "$work/target.png")" = 640 ]; then passed=$((passed + 1)); else echo "FAIL a replaced output keeps its mode"; failures=$((failures + 1)); fi
if "$rayrad" solve - -q < "$good" >/dev/null 2>&1; then passed=$((passed + 1)); else echo "FAIL solve - (scene on stdin)"; failures=$((failures + 1)); fi

# ---- writes that fail at the end (exit 3): nothing half-written, old files intact ----
echo keep > "$work/keep.png"; echo keep > "$work/keep.exr"
err=$(ulimit -f 1; "$rayrad" render "$good" --set 'camera.resolution=[128,128]' -o "$work/keep.png" -o "$work/keep.exr" -o "$work/outnew.exr" -q 2>&1 >/dev/null)
rc=$?
if [ "$rc" -eq 3 ] && [[ "$err" == *"cannot write: File too large"* ]] && [ ! -e "$work/outnew.exr" ] && ! ls -a "$work" | grep -q '^\.rayrad-'; then
    passed=$((passed + 1))
else
    echo "FAIL file size limit: exit $rc: $err"; failures=$((failures + 1))
fi
intact "file size limit, PNG" "$work/keep.png"
intact "file size limit, EXR" "$work/keep.exr"
# A real full disk: a 64 KiB tmpfs, when this machine lets us mount one (root); the JPEG
# path is the one whose library used to exit() on its own.
disk="$work/disk"
mkdir "$disk"
if [ "$(id -u)" -eq 0 ] && mount -t tmpfs -o size=64k tmpfs "$disk" 2>/dev/null; then
    echo keep > "$disk/keep.jpg"
    head -c 60000 /dev/zero > "$disk/filler" 2>/dev/null
    err=$("$rayrad" render "$good" --set 'camera.resolution=[256,256]' -o "$disk/keep.jpg" -q 2>&1 >/dev/null)
    rc=$?
    if [ "$rc" -eq 3 ] && [[ "$err" == *"keep.jpg: cannot write: No space left on device"* ]] && ! ls -a "$disk" | grep -q '^\.rayrad-'; then
        passed=$((passed + 1))
    else
        echo "FAIL full disk: exit $rc: $err ($(ls -a "$disk" | tr '\n' ' '))"; failures=$((failures + 1))
    fi
    intact "full disk" "$disk/keep.jpg"
    umount "$disk"
else
    echo "(full-disk case skipped: cannot mount a tmpfs here; the file-size-limit case covers the write path)"
fi

# ---- results that must not be handed over (exit 4, nothing written) ------------------
echo keep > "$work/keep.exr"
expect 4 "Inf luminance from an absurd intensity" "is a light's intensity or luminance absurdly large? Nothing was written" -- \
    render "$good" --set lights.0.intensity_cd=1e300 -o "$work/keep.exr" -q
intact "Inf luminance" "$work/keep.exr"
scene away '{"materials": {"white": {"reflectance": 0.5}},
 "objects": [{"type": "box", "min": [0,0,0], "max": [1,1,1], "facing": "inward", "material": "white"}],
 "lights": [{"type": "point", "position": [0.5,0.5,0.5], "intensity_cd": 10}],
 "camera": {"position": [0.5,0.5,3], "look_at": [0.5,0.5,9], "resolution": [8,8]}}'
expect 4 "all black: camera looking away" "every pixel of the image is black: no light reaches the camera" -- render "$work/away.json" -o "$work/out.png" -q
if "$rayrad" render "$work/away.json" -o "$work/black.png" --allow-black -q >/dev/null 2>&1 && [ -s "$work/black.png" ]; then
    passed=$((passed + 1))
else
    echo "FAIL --allow-black"; failures=$((failures + 1))
fi
expect 4 "all black: behind a mirror (sph4)" "every pixel of the image is black" -- render "$src/scenes/sphere/sph4.json" -o "$work/out.png" --spp 1 --set 'camera.resolution=[16,12]' -q
expect 4 "exposure maps all to black" "the exposure (-40 stops) maps every pixel of the rendering to black" -- render "$good" -o "$work/out.png" --exposure -40 -q
expect 4 "exposure maps all to white" "maps every pixel of the rendering to white" -- render "$good" -o "$work/out.png" --exposure 40 -q
if "$rayrad" render "$good" -o "$work/dark.exr" --exposure -40 -q >/dev/null 2>&1; then
    passed=$((passed + 1))
else
    echo "FAIL an EXR does not depend on the exposure"; failures=$((failures + 1))
fi

if "$rayrad" solve "$good" -q --set 'sensors=[{"name": "a", "position": [0.5,2,0.5], "normal": [0,1,0]}, {"name": "b", "position": [0.5,3,0.5], "normal": [0,1,0]}]' 2>&1 >/dev/null |
    grep -q "warning: every one of the 2 sensors reads 0 lx"; then
    passed=$((passed + 1))
else
    echo "FAIL every sensor dark: no warning"; failures=$((failures + 1))
fi

# Grid statistics beside the sensor CSV: written with it, and checked with it.
grid_set='sensor_grids=[{"name": "floor", "origin": [0.1,0,0.1], "u": [0.8,0,0], "v": [0,0,0.8], "counts": [3,3], "normal": [0,1,0]}]'
if "$rayrad" solve "$good" -q --set "$grid_set" --sensors "$work/grid.csv" >/dev/null 2>&1 &&
    grep -q '^floor,9,' "$work/grid.grids.csv"; then
    passed=$((passed + 1))
else
    echo "FAIL grid statistics file"; failures=$((failures + 1))
fi
echo keep > "$work/ro.grids.csv"; chmod 444 "$work/ro.grids.csv"
expect 3 "read-only grid summary" "ro.grids.csv: cannot write: the file exists and is read-only" -- solve "$good" -q --set "$grid_set" --sensors "$work/ro.csv"
if [ ! -e "$work/ro.csv" ]; then passed=$((passed + 1)); else echo "FAIL the sensor CSV was written although its summary could not be"; failures=$((failures + 1)); fi

# False-colour pictures: written when asked, checked like every output.
if "$rayrad" render "$good" -q --set "$grid_set" --grid-picture "$work/fc_grid.png" --false-colour "$work/fc_lum.png" -o "$work/fc.png" >/dev/null 2>&1 &&
    [ -s "$work/fc_grid.png" ] && [ -s "$work/fc_lum.png" ]; then
    passed=$((passed + 1))
else
    echo "FAIL false-colour pictures"; failures=$((failures + 1))
fi
expect 2 "--grid-picture without grids" "--grid-picture: the scene has no sensor grid or work plane" -- solve "$good" -q --grid-picture "$work/outg.png"
expect 3 "--false-colour as EXR" "outf.exr: a false-colour picture is a display image: use .png or .jpg" -- render "$good" -q -o "$work/out.png" --false-colour "$work/outf.exr"

# ---- options (exit 2, before any work) -----------------------------------------------
expect 2 "--exposure nan" "--exposure: expected stops between -64 and 64, got nan" -- render "$good" -o "$work/out.png" --exposure nan
expect 2 "--exposure inf" "got inf" -- render "$good" -o "$work/out.png" --exposure inf
expect 2 "--exposure 1e10" "got 1e10" -- render "$good" -o "$work/out.png" --exposure 1e10
expect 2 "--exposure empty" "--exposure: expected \"auto\" or a number" -- render "$good" -o "$work/out.png" --exposure ''
expect 2 "--threads -1" "--threads: Value -1 not in range 0 to 4096" -- solve "$good" --threads -1
expect 2 "--threads huge" "not in range 0 to 4096" -- solve "$good" --threads 99999999999
expect 2 "--seed -1" "--seed: Value -1 not in range" -- render "$good" -o "$work/out.png" --seed -1
expect 2 "--spp 0" "--spp" -- render "$good" -o "$work/out.png" --spp 0
expect 2 "--view not in the config" "--view: unknown view \"Filmic\" for display \"sRGB\" (it has \"Standard\", \"ACES 1.0 SDR-video\" or \"Raw\")" -- render "$good" -o "$work/out.png" --view Filmic
expect 2 "--display not in the config" "--display: unknown display \"Foo\" (the config has \"sRGB\")" -- render "$good" -o "$work/out.png" --display Foo
expect 2 "--ocio-config missing" "cannot load the OpenColorIO config" -- render "$good" -o "$work/out.png" --ocio-config "$work/none.ocio"
expect 2 "--set negative index" "--set lights.-1.intensity_cd: \"-1\" is not an array index" -- solve "$good" --set lights.-1.intensity_cd=5
expect 2 "--set index out of range" "--set lights.7.intensity_cd: index 7 is out of range (size 1)" -- solve "$good" --set lights.7.intensity_cd=5
expect 2 "--set bad value names the option" "--set lights.0.intensity_cd=-5: /lights/0/intensity_cd: expected a positive number, got -5" -- solve "$good" --set lights.0.intensity_cd=-5
expect 2 "--set without =" "--set radiosity.max_edge: expected KEY=VALUE" -- solve "$good" --set radiosity.max_edge
expect 2 "unknown option" "--frobnicate" -- solve "$good" --frobnicate
expect 2 "no subcommand" "A subcommand is required" --
if "$rayrad" --version | grep -q "Embree .*OpenImageIO .*OpenColorIO"; then passed=$((passed + 1)); else echo "FAIL --version"; failures=$((failures + 1)); fi

# ---- input files (exit 2) ------------------------------------------------------------
expect 2 "scene is /dev/zero" "/dev/zero: is a device, not a scene file" -- solve /dev/zero
expect 2 "scene is a directory" "adir: is a directory, not a scene file" -- solve "$work/adir"
ln -s loop-d.json "$work/loop-c.json"; ln -s loop-c.json "$work/loop-d.json"
expect 2 "scene is a symlink loop" "loop-c.json: a loop of symbolic links" -- solve "$work/loop-c.json"
ln -s gone.json "$work/dangling.json"
expect 2 "scene is a dangling symlink" "dangling.json: a symbolic link to a file that does not exist" -- solve "$work/dangling.json"
expect 2 "scene path through a file" "no such file (a part of the path is not a directory)" -- solve "$good/x.json"
truncate -s 300M "$work/huge.json"
expect 2 "scene file of 300 MiB" "huge.json: the file is 300 MiB; more than the limit of 256 MiB for a scene file" -- solve "$work/huge.json"
rm -f "$work/huge.json"
expect 2 "garbage on stdin" "<stdin>: line 2, column 1: invalid JSON" -- solve - <<< '{"materials": '
expect 2 "empty stdin" "<stdin>" -- solve - < /dev/null
scene dupkey '{"materials": {"w": {"reflectance": 0.5}},
 "objects": [{"type": "box", "min": [0,0,0], "max": [1,1,1], "material": "w"}],
 "lights": [{"type": "point", "position": [0.5,0.5,0.5], "intensity_cd": 10, "intensity_cd": 5}]}'
expect 2 "duplicate key" "dupkey.json: line 3, column 78: the key \"intensity_cd\" appears twice in one object (first at line 3, column 58)" -- solve "$work/dupkey.json"
scene dupmat '{"materials": {"w": {"reflectance": 0.5}, "w": {"reflectance": 0.2}}, "objects": [], "lights": []}'
expect 2 "duplicate material" "the key \"w\" appears twice" -- solve "$work/dupmat.json"
sed 's/"materials"/"Materials"/' "$good" > "$work/casekey.json"
expect 2 "key in the wrong case" "casekey.json: /Materials: unknown key (did you mean \"materials\"?)" -- solve "$work/casekey.json"
sed 's/"intensity_cd"/"Intensity_CD"/' "$good" > "$work/casekey2.json"
expect 2 "nested key in the wrong case" "did you mean \"intensity_cd\"?" -- solve "$work/casekey2.json"
expect 2 "spot with direction and look_at" "/lights/0/direction: give either \"direction\" or \"look_at\", not both" -- solve "$good" \
    --set 'lights.0={"type": "spot", "position": [0.5,0.5,0.5], "intensity_cd": 5, "direction": [0,-1,0], "look_at": [0,0,0]}'
expect 2 "resolution with a string" "/camera/resolution: expected [width, height], each from 1 to 16384, got [1280,\"x\"]" -- solve "$good" --set 'camera.resolution=[1280,"x"]'
expect 2 "resolution of three numbers" "got [8,8,8]" -- solve "$good" --set 'camera.resolution=[8,8,8]'
expect 2 "singular matrix" "/objects/0/transform: the transform is singular (determinant 0)" -- solve "$good" \
    --set 'objects.0.transform={"matrix": [1,0,0,0, 0,0,0,0, 0,0,1,0, 0,0,0,1]}'
mkdir "$work/mesh.obj"
scene meshdir "{\"materials\": {\"white\": {\"reflectance\": 0.5}}, \"objects\": [{\"type\": \"mesh\", \"file\": \"mesh.obj\", \"material\": \"white\"}], \"lights\": [{\"type\": \"point\", \"position\": [0.3,0.3,1], \"intensity_cd\": 10}]}"
expect 2 "mesh is a directory" "meshdir.json: /objects/0/file: mesh file '$work/mesh.obj': is a directory, not a mesh file" -- solve "$work/meshdir.json"
scene meshdev "{\"materials\": {\"white\": {\"reflectance\": 0.5}}, \"objects\": [{\"type\": \"mesh\", \"file\": \"/dev/zero\", \"material\": \"white\"}], \"lights\": [{\"type\": \"point\", \"position\": [0.3,0.3,1], \"intensity_cd\": 10}]}"
expect 2 "mesh is /dev/zero" "/objects/0/file: mesh file '/dev/zero': is a device, not a mesh file" -- solve "$work/meshdev.json"
ln -s loop-f.obj "$work/loop-e.obj"; ln -s loop-e.obj "$work/loop-f.obj"
scene meshloop "{\"materials\": {\"white\": {\"reflectance\": 0.5}}, \"objects\": [{\"type\": \"mesh\", \"file\": \"loop-e.obj\", \"material\": \"white\"}], \"lights\": [{\"type\": \"point\", \"position\": [0.3,0.3,1], \"intensity_cd\": 10}]}"
expect 2 "mesh is a symlink loop" "loop-e.obj': a loop of symbolic links" -- solve "$work/meshloop.json"

# ---- validate finds its scenes from anywhere -----------------------------------------
if (cd "$work" && "$rayrad" validate sphere --quick --out vs >/dev/null 2>&1) && [ -s "$work/vs/results.csv" ]; then
    passed=$((passed + 1))
else
    echo "FAIL validate sphere --quick does not run outside the repository"; failures=$((failures + 1))
fi

finish "output safety"
