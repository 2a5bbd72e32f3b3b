#!/usr/bin/env python3
"""Draws which module of src/ includes which (radiosity by sub-stage folder): an arrow A → B
when A includes B and no chain of other arrows already leads from A to B (the transitive
reduction: the layers, without the arrows they imply), labelled with how many include lines
it stands for; and the longest chain of includes between files.

    scripts/dev/include_graph.py > includes.dot
    scripts/dev/include_graph.py --png docs/images/includes.png   (needs graphviz's dot)

tests/layering_test.cpp checks the same rules on every build; this only draws them.
"""
import argparse
import collections
import functools
import pathlib
import re
import subprocess
import sys

SRC = pathlib.Path(__file__).resolve().parents[2] / "src"
INCLUDE = re.compile(r'^\s*#\s*include\s*<([a-z_]+/[^>]+\.h)>', re.M)


def module_of(relative):
    parts = relative.split("/")
    if parts[0] == "radiosity" and len(parts) > 2:
        return "/".join(parts[:2])
    return parts[0]


def read_sources():
    files = {}
    for path in sorted(SRC.rglob("*")):
        if path.suffix in (".h", ".cpp"):
            relative = path.relative_to(SRC).as_posix()
            files[relative] = [h for h in INCLUDE.findall(path.read_text()) if (SRC / h).exists()]
    return files


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--png", help="render the drawing to this PNG with dot")
    args = parser.parse_args()
    files = read_sources()

    edges = collections.Counter()
    for f, includes in files.items():
        for h in includes:
            a, b = module_of(f), module_of(h)
            if a != b:
                edges[(a, b)] += 1

    # Transitive reduction: drop A → B when B is reachable from A through another module.
    succ = collections.defaultdict(set)
    for a, b in edges:
        succ[a].add(b)

    def reachable(start, skip):
        seen, todo = set(), [m for m in succ[start] if m != skip]
        while todo:
            m = todo.pop()
            if m not in seen:
                seen.add(m)
                todo.extend(succ[m])
        return seen

    edges = collections.Counter({(a, b): n for (a, b), n in edges.items() if b not in reachable(a, b)})

    @functools.lru_cache(maxsize=None)
    def depth(f):  # the longest chain of includes below f (no cycles: layering_test)
        return 1 + max((depth(h) for h in files[f]), default=0)

    deepest = max(files, key=depth)
    lines = ["digraph includes {", "  rankdir=BT; node [shape=box, fontname=Helvetica, fontsize=11];",
             f'  label="arrows: A includes B (include lines), arrows implied by others left out; longest chain {depth(deepest)} files, from {deepest}";',
             "  fontname=Helvetica; fontsize=10;",
             '  subgraph cluster_radiosity { label="radiosity"; style=rounded;']
    for m in sorted({module_of(f) for f in files}):
        if m.startswith("radiosity"):
            name = "front door" if m == "radiosity" else m.split("/")[1]
            lines.append(f'    "{m}" [label="{name}"];')
    lines.append("  }")
    for (a, b), n in sorted(edges.items()):
        lines.append(f'  "{a}" -> "{b}" [label="{n}", fontsize=9];')
    lines.append("}")
    dot = "\n".join(lines) + "\n"
    if args.png:
        subprocess.run(["dot", "-Tpng", "-Gdpi=80", "-o", args.png], input=dot.encode(), check=True)
        print(f"wrote {args.png}; longest chain {depth(deepest)} files, from {deepest}", file=sys.stderr)
    else:
        sys.stdout.write(dot)


if __name__ == "__main__":
    main()
