#!/usr/bin/env bash
# rayrad validate cube --quick end to end: every run succeeds, the tables and plots are
# written, and the default configuration's gathered indirect error is within 1 % at A, B, C.
set -u
rayrad="$1"
src="$2"
source "$(dirname "$0")/test_lib.sh"
"$rayrad" validate cube --quick --scene "$src/scenes/cube/cube.json" --out "$work" > "$work/stdout.txt" 2>&1
rc=$?
check "exit 0" test "$rc" -eq 0
check "tables printed" grep -q "### Cluster sweep at 4800 triangles" "$work/stdout.txt"
check "mesh plot" test -s "$work/error_vs_time_mesh.png"
check "cluster plot" test -s "$work/error_vs_time_clusters.png"
check "12 result rows" test "$(tail -n +2 "$work/results.csv" | wc -l)" -eq 12
# results.csv: A/B/C gather errors are columns 14, 17, 20.
row=$(grep '^clusters,1 %,4800,' "$work/results.csv")
for col in 14 17 20; do
    err=$(echo "$row" | cut -d, -f$col)
    check "gathered error column $col = $err within 1%" awk -v e="$err" 'BEGIN { exit !(e > -1 && e < 1) }'
done
[ "$failures" -eq 0 ] || cat "$work/stdout.txt"
finish "validate --quick"
