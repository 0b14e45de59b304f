#!/usr/bin/env python3
"""The library's folders (src/cagd/<concept>/) depend on each other downwards only, and on nothing
outside the library (docs/design.md, "Layers"):

- every `#include "..."` in src/, tests/, python/, bench/, experiments/ and examples/ names a
  tracked file by its path (from src/, or from the including file's own folder);
- no file under src/cagd/ includes the harness (src/repro/), the command (src/cli/), python/,
  bench/ or tests/, nor any header that is not the library's own;
- no library folder includes, directly or through others, a folder that includes it (no cycle);
- each library folder includes only folders below it in LAYERS, the order docs/design.md draws
  (a new folder must be given its place there).

Prints each folder's dependencies and every violation; exit 1 if there is one.
Usage: check-folder-dependencies.py [ROOT]
"""
import collections
import os
import re
import sys

root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), ".."))
src = os.path.join(root, "src")
library = os.path.join(src, "cagd")
include = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.MULTILINE)
problems = []

# The layers, bottom first: a folder may include the folders of the layers below its own, never
# one of its own layer or above. docs/design.md draws the same order.
LAYERS = [
    ["core"],
    ["io", "numeric"],
    ["spline"],
    ["analysis", "fairness", "locality"],
    ["intrinsic", "surface"],
    ["aesthetic", "smoothing"],
    ["export"],
    ["methods"],
    ["compare"],
]
layer_of = {folder: rank for rank, folders in enumerate(LAYERS) for folder in folders}

# Headers the build generates (configure_file): found in the build tree, not in the source tree.
generated = {"cli/compare_panels_script.hpp"}


def sources(top):
    for folder, _, files in os.walk(top):
        for f in sorted(files):
            if f.endswith((".cpp", ".hpp", ".in")):
                yield os.path.join(folder, f)


deps = collections.defaultdict(set)
for top in ("src", "tests", "python", "bench", "experiments", "examples"):
    for path in sources(os.path.join(root, top)):
        rel = os.path.relpath(path, root)
        text = open(path, encoding="utf-8").read()
        in_library = os.path.commonpath([path, library]) == library
        owner = os.path.relpath(path, library).split(os.sep)[0] if in_library else None
        for name in include.findall(text):
            here = os.path.join(os.path.dirname(path), name)
            if not (name in generated or os.path.isfile(os.path.join(src, name)) or os.path.isfile(here)):
                problems.append(f"{rel}: #include \"{name}\" names no file (from src/ or {os.path.dirname(rel)}/)")
            if in_library:
                if not name.startswith("cagd/") and not os.path.isfile(here):
                    problems.append(f"{rel}: the library includes \"{name}\", which is not a library header (src/cagd/)")
                    continue
                used = name.split("/")[1] if name.startswith("cagd/") else owner
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


for a, b in sorted({tuple(sorted((a, b))) for a in list(deps) for b in deps[a] if reaches(b, a)}):
    problems.append(f"cycle: src/cagd/{a} and src/cagd/{b} depend on each other")
for folder in sorted(os.listdir(library)):
    if os.path.isdir(os.path.join(library, folder)) and folder not in layer_of:
        problems.append(f"src/cagd/{folder}/ has no place in LAYERS (scripts/check-folder-dependencies.py)")
for a in sorted(deps):
    for b in sorted(deps[a]):
        if a in layer_of and b in layer_of and layer_of[b] >= layer_of[a]:
            problems.append(f"src/cagd/{a} (layer {layer_of[a]}) includes src/cagd/{b} (layer {layer_of[b]}), not below it")
for a in sorted(deps):
    print(f"{a} -> {', '.join(sorted(deps[a]))}")
for p in problems:
    print(p)
sys.exit(1 if problems else 0)
