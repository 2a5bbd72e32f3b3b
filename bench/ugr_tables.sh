#!/usr/bin/env bash
# Benchmark: rayrad's CIE 190 UGR tables against the tables DIALux and Relux print for the
# eleven EULUMDAT files of tests/data/ugr (spacing 0.25 H), and against CIE 190's own
# standard-condition table of its example luminaire (sample 11, spacing 1 H): per file the
# largest and the mean difference over the 190 entries, and the CPU seconds a table costs.
# Usage: bench/ugr_tables.sh
set -euo pipefail
cd "$(dirname "$0")/.."
rayrad=build/src/rayrad
[ -x "$rayrad" ] || scripts/build rayrad
data=tests/data/ugr
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

ldt() {  # the file of sample N: the three in tests/data/luminaires, the rest beside the tables
    if [ -f "$data/eulumdatugr_sample_$1.ldt" ]; then echo "$data/eulumdatugr_sample_$1.ldt"
    else echo "tests/data/luminaires/eulumdatugr_sample_$1.ldt"; fi
}
for n in 01 02 03 04 05 06 07 08 09 10 11; do
    /usr/bin/time -f "%U %S" -o "$tmp/time_$n" "$rayrad" info "$(ldt "$n")" --ugr-csv "$tmp/ours_$n.csv" > /dev/null 2>&1
done
"$rayrad" info "$(ldt 11)" --ugr-spacing 1 --ugr-csv "$tmp/ours_11_s1.csv" > /dev/null 2>&1
python3 - "$tmp" "$data" <<'PY'
import sys
tmp, data = sys.argv[1], sys.argv[2]
def values(path, header):
    rows = [l.strip().split(',') for l in open(path) if l.strip()]
    rows = rows[1:] if header else rows
    return [[None if v.startswith('<') or v == '' else float(v) for v in (r[2:] if header else r)] for r in rows]
def compare(ours, ref):
    d = [o - r for orow, rrow in zip(ours, ref) for o, r in zip(orow, rrow) if r is not None and o is not None]
    return len(d), max(abs(x) for x in d), sum(d) / len(d)
print("| file | vs DIALux: entries, largest, mean difference | vs Relux: entries, largest, mean difference | CPU-s a table |")
print("|---|---|---|---|")
worst = {"Dialux": 0, "Relux": 0}
for n in ["01", "02", "03", "04", "05", "06", "07", "08", "09", "10", "11"]:
    ours = values(f"{tmp}/ours_{n}.csv", True)
    cells = []
    for ref in ["Dialux", "Relux"]:
        k, big, mean = compare(ours, values(f"{data}/sample_{n}_{ref}.csv", False))
        worst[ref] = max(worst[ref], big)
        cells.append(f"{k}, {big:.2f}, {mean:+.2f}")
    user, sys_ = open(f"{tmp}/time_{n}").read().split()
    print(f"| sample {n} | {cells[0]} | {cells[1]} | {float(user) + float(sys_):.2f} |")
print(f"\nlargest difference over all files: DIALux {worst['Dialux']:.2f}, Relux {worst['Relux']:.2f} UGR")
k, big, mean = compare(values(f"{tmp}/ours_11_s1.csv", True), values(f"{data}/sample_11_cie190.csv", False))
print(f"CIE 190's standard-condition table of its example luminaire (spacing 1 H): {k} entries, "
      f"largest difference {big:.2f}, mean {mean:+.2f} UGR")
PY
