#!/usr/bin/env python3
"""The folders of src/ depend on each other downwards only (DESIGN.md, Layout): no folder includes
a header of a folder that includes, directly or through others, one of its own. Prints each
folder's dependencies and every cycle; exit 1 if there is one. Usage: check-folder-dependencies.py [ROOT]
"""
import collections
import os
import re
import sys

root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..")
src = os.path.join(root, "src")
deps = collections.defaultdict(set)
for folder, _, files in os.walk(src):
    owner = os.path.relpath(folder, src).split(os.sep)[0]
    for f in files:
        if f.endswith((".cpp", ".hpp", ".in")):
            for used in re.findall(r'#include "cagd/([a-z_]+)/', open(os.path.join(folder, f), encoding="utf-8").read()):
                if used != owner:
                    deps[owner].add(used)


def reaches(start, goal):
    seen, todo = set(), [start]
    while todo:
        for n in deps[todo.pop()]:
            if n == goal:
                return True
            if n not in seen:
                seen.add(n)
                todo.append(n)
    return False


cycles = sorted({tuple(sorted((a, b))) for a in list(deps) for b in deps[a] if reaches(b, a)})
for a in sorted(deps):
    print(f"{a} -> {', '.join(sorted(deps[a]))}")
for a, b in cycles:
    print(f"cycle: {a} and {b} depend on each other")
sys.exit(1 if cycles else 0)
