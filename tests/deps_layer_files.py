#!/usr/bin/env python3
"""Every header and library a layer's targets use belongs to a package the layer installs.

Used by deps_layers_test.sh (ctest deps.layers). On this machine every package of every layer is
installed, so a build with another layer's package forbidden to CMake would still find, say,
/usr/include/gtest/gtest.h if a library file included it. This check does not depend on what is
installed: it preprocesses every translation unit of a configured tree (`g++ -M`, no code
generation), reads the link lines of the targets from `ninja -t commands`, and looks up each
system file it finds in dpkg's file lists. A file is allowed when it lies in the source or build
tree or belongs to a package of the layer or to one of their dependencies (apt-cache depends
--recurse). The first file outside is reported with its package.

Usage: deps_layer_files.py TREE SOURCE_DIR LAYER:TARGET[,TARGET...]:PATTERN...
  LAYER   a layer of scripts/install-deps.sh (its packages: install-deps.sh --list LAYER)
  TARGET  a ninja target whose link line is checked (cagd, cagd_python, cagd_cli, ...)
  PATTERN translation units of the layer: compile_commands.json entries whose file contains it
          ('' for all)
"""
import concurrent.futures
import json
import os
import re
import shlex
import subprocess
import sys
import tempfile


def layer_packages(source, layer):
    listed = subprocess.run(["bash", os.path.join(source, "scripts/install-deps.sh"), "--list", layer],
                            check=True, capture_output=True, text=True).stdout.split()
    closure = subprocess.run(["apt-cache", "depends", "--recurse", "--installed", "--no-recommends",
                              "--no-suggests", "--no-conflicts", "--no-breaks", "--no-replaces",
                              "--no-enhances"] + listed, check=True, capture_output=True, text=True).stdout
    names = {line.strip() for line in closure.splitlines() if line and not line.startswith((" ", "<"))}
    return listed, names | set(listed)


def package_files():
    files = {}
    info = "/var/lib/dpkg/info"
    for entry in os.listdir(info):
        if not entry.endswith(".list"):
            continue
        package = entry[:-5].split(":")[0]
        with open(os.path.join(info, entry), encoding="utf-8", errors="replace") as f:
            for line in f:
                path = line.rstrip("\n")
                if path and not os.path.isdir(path):
                    files.setdefault(os.path.realpath(path), set()).add(package)
    return files


def headers(entry, scratch, index):
    """The files one translation unit includes (g++ -M)."""
    args = shlex.split(entry["command"]) if "command" in entry else list(entry["arguments"])
    if "-o" in args:
        i = args.index("-o")
        del args[i:i + 2]
    deps = os.path.join(scratch, f"{index}.d")
    subprocess.run(args + ["-M", "-MF", deps], cwd=entry["directory"], check=True, capture_output=True)
    with open(deps) as f:
        text = f.read().replace("\\\n", " ")
    _, _, listed = text.partition(":")
    return [os.path.realpath(os.path.join(entry["directory"], p)) for p in listed.split()]


def link_inputs(tree, target):
    commands = subprocess.run(["ninja", "-C", tree, "-t", "commands", target], check=True,
                              capture_output=True, text=True).stdout.splitlines()
    files = []
    for line in commands:
        if " -c " in line or " -o " not in line:
            continue   # a compilation, or no output
        for token in shlex.split(line):
            if token.startswith("-Wl,"):
                token = token.split(",")[-1]
            if os.path.isabs(token) and re.search(r"\.(so(\.[0-9.]+)?|a)$", token):
                files.append(os.path.realpath(token))
    return files


def main():
    tree, source = os.path.realpath(sys.argv[1]), os.path.realpath(sys.argv[2])
    specs = [s.split(":", 2) for s in sys.argv[3:]]
    entries = json.load(open(os.path.join(tree, "compile_commands.json")))
    owners = package_files()
    failed = False
    with tempfile.TemporaryDirectory() as scratch, concurrent.futures.ThreadPoolExecutor(os.cpu_count() or 2) as pool:
        jobs = {i: pool.submit(headers, e, scratch, i) for i, e in enumerate(entries)}
        included = {i: job.result() for i, job in jobs.items()}
        for layer, targets, pattern in specs:
            listed, allowed = layer_packages(source, layer)
            used = {}
            for i, e in enumerate(entries):
                if pattern in e["file"]:
                    for h in included[i]:
                        used.setdefault(h, os.path.relpath(e["file"], source if e["file"].startswith(source) else tree))
            for target in targets.split(","):
                for f in link_inputs(tree, target):
                    used.setdefault(f, f"the link of {target}")
            outside = []
            for path, user in sorted(used.items()):
                if path.startswith((source + os.sep, tree + os.sep)):
                    continue
                packages = owners.get(path)
                if packages is None:
                    outside.append(f"{path} (used by {user}) belongs to no Debian package")
                elif not packages & allowed:
                    outside.append(f"{path} (used by {user}) comes from {', '.join(sorted(packages))}")
            system = sum(1 for p in used if not p.startswith((source + os.sep, tree + os.sep)))
            if outside:
                failed = True
                print(f"FAIL: layer {layer} ({' '.join(listed)}) lacks what its targets use:")
                for line in outside[:20]:
                    print("  " + line)
            else:
                print(f"layer {layer}: the {system} system headers and libraries of {targets} "
                      f"come from its {len(listed)} packages and their {len(allowed) - len(listed)} dependencies")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
