# Shared by the command-line tests: a scratch directory and a pass/fail counter.
# Usage: source it, call `check NAME COMMAND...`, end with `finish LABEL`.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
passed=0
check() {
    local name="$1"
    shift
    if "$@"; then passed=$((passed + 1)); else echo "FAIL $name"; failures=$((failures + 1)); fi
}
finish() {
    echo "$1: $passed passed, $failures failed"
    [ "$failures" -eq 0 ]
}

# expect CODE NAME EXPECTED_SUBSTRING -- ARGS...: runs $rayrad ARGS; passes when it exits
# with CODE, writes exactly one line on stderr, containing the substring, and leaves no
# file named out* or .out*, nor a temporary .rayrad-* file, in $work.
expect() {
    local code="$1" name="$2" want="$3"
    shift 4
    local err rc lines
    err=$("$rayrad" "$@" 2>&1 >/dev/null)
    rc=$?
    lines=$(printf '%s\n' "$err" | grep -c .)
    if [ "$rc" -ne "$code" ] || [ "$lines" -ne 1 ] || [[ "$err" != *"$want"* ]]; then
        echo "FAIL $name: exit $rc (wanted $code), $lines line(s): $err (wanted: $want)"
        failures=$((failures + 1))
    else
        passed=$((passed + 1))
    fi
    if ls "$work"/out* "$work"/.out* "$work"/.rayrad-* >/dev/null 2>&1; then
        echo "FAIL $name: left output: $(ls -a "$work" | tr '\n' ' ')"
        failures=$((failures + 1))
        rm -f "$work"/out* "$work"/.out* "$work"/.rayrad-*
    fi
}

scene() {  # scene NAME JSON: writes $work/NAME.json
    printf '%s\n' "$2" > "$work/$1.json"
}

# The smallest good scene, in parts: a white box room and a point light in it.
good_materials='"materials": {"white": {"type": "diffuse", "reflectance": 0.5}}'
good_box='"objects": [{"type": "box", "min": [0,0,0], "max": [1,1,1], "facing": "inward", "material": "white"}]'
good_light='"lights": [{"type": "point", "position": [0.5,0.5,0.5], "intensity_cd": 10}]'

# A 2 m courtyard of white walls open to the sky above (materials "white" and "sky", an opening).
court_objects='"objects": [
  {"type": "quad", "material": "white", "vertices": [[0,0,0],[0,0,2],[2,0,2],[2,0,0]]},
  {"type": "quad", "material": "white", "vertices": [[0,0,0],[0,2,0],[0,2,2],[0,0,2]]},
  {"type": "quad", "material": "white", "vertices": [[2,0,0],[2,0,2],[2,2,2],[2,2,0]]},
  {"type": "quad", "material": "white", "vertices": [[0,0,0],[2,0,0],[2,2,0],[0,2,0]]},
  {"type": "quad", "material": "white", "vertices": [[0,0,2],[0,2,2],[2,2,2],[2,0,2]]},
  {"type": "quad", "material": "sky", "vertices": [[0,2,0],[2,2,0],[2,2,2],[0,2,2]]}]'
