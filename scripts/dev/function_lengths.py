#!/usr/bin/env python3
"""Lists the functions in src/ longer than a number of lines (default 80), longest first.

    scripts/dev/function_lengths.py [--over N]

A function is a body that opens after a parameter list at namespace or class level; lambdas
inside it count toward it. Lines are counted from the signature's first line to the closing
brace. A heuristic (comments and string literals are skipped, macros are not expanded), good
enough to keep the code readable, not a parser.
"""
import argparse
import pathlib
import re

SRC = pathlib.Path(__file__).resolve().parents[2] / "src"
CONTROL = re.compile(r'\b(if|for|while|switch|catch|return|else|do)\b\s*\(?')


def strip(text):
    """Comments and string/char literals blanked out, line structure kept."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            i = n if j < 0 else j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append("\n" * text.count("\n", i, j))
            i = j
        elif text.startswith('R"', i):
            m = re.match(r'R"([^(]*)\(', text[i:])
            end = text.find(")" + m.group(1) + '"', i) + len(m.group(1)) + 2
            out.append('""' + "\n" * text.count("\n", i, end))
            i = end
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out.append(c + c)
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


def functions(path):
    lines = strip(path.read_text()).split("\n")
    depth, starts, found = 0, [], []
    kinds = []  # per open brace: "function", "scope" (namespace, class) or "block"
    for number, line in enumerate(lines, 1):
        for k, c in enumerate(line):
            if c == "{":
                head = line[:k].strip()
                back = number - 1
                while not head and back > 0:  # the brace on a line of its own
                    back -= 1
                    head = lines[back].strip()
                inside_function = "function" in kinds
                if inside_function:
                    kinds.append("block")
                elif re.search(r'\b(namespace|class|struct|enum|union)\b', head) and ")" not in head.split("{")[-1]:
                    kinds.append("scope")
                elif head.endswith(")") or re.search(r'\)\s*(const|override|noexcept|final|->.*|:.*)?\s*$', head) \
                        and not CONTROL.match(head):
                    # the signature's first line: back to the line after the previous ; } or {
                    first = number
                    while first > 1 and not re.search(r'[;{}]\s*$|^\s*(public|private|protected):|^\s*template',
                                                       lines[first - 2]) and lines[first - 2].strip():
                        first -= 1
                    kinds.append("function")
                    starts.append((first, head))
                else:
                    kinds.append("block")
            elif c == "}" and kinds:
                kind = kinds.pop()
                if kind == "function":
                    first, head = starts.pop()
                    found.append((number - first + 1, first, head))
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--over", type=int, default=80)
    args = parser.parse_args()
    rows = []
    for path in sorted(SRC.rglob("*")):
        if path.suffix in (".h", ".cpp"):
            for length, first, head in functions(path):
                if length > args.over:
                    rows.append((length, f"{path.relative_to(SRC)}:{first}", head[:90]))
    for length, where, head in sorted(rows, reverse=True):
        print(f"{length:5d}  {where:45s} {head}")


if __name__ == "__main__":
    main()
