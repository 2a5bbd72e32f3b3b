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
