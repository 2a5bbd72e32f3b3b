#!/usr/bin/env bash
# rayrad validate luminaire end to end, from a scratch directory (it finds the bundled
# files): every file within its bounds, the table and results.csv written.
set -u
rayrad="$1"
src="$2"
source "$(dirname "$0")/test_lib.sh"
(cd "$work" && "$rayrad" validate luminaire --out out > stdout.txt 2>&1)
rc=$?
check "exit 0" test "$rc" -eq 0
check "all within" grep -q "all within" "$work/stdout.txt"
check "eleven result rows" test "$(tail -n +2 "$work/out/results.csv" | wc -l)" -eq 11
[ "$failures" -eq 0 ] || cat "$work/stdout.txt"
finish "validate luminaire"
