#!/usr/bin/env python3
"""The installed headers and the C++ examples of docs/cpp.md, as an outside project meets them.

Usage: installed_headers_test.py PREFIX SOURCE_DIR

1. Every header under PREFIX/include/cagd compiles alone (-fsyntax-only) with the flags that
   pkg-config gives for the installed cagd: a header that includes one the install left out, or
   that leans on an include it does not make itself, fails here.
2. Every ```cpp block of docs/cpp.md builds (compiled and linked) against the install. A block
   without an #include continues the block before it (the docs split one example into steps). The
   blocks' #include lines go to the top of the program, the rest into main(), after a preamble
   that defines the names the prose gives them: `points` and `moved_points` (a cagd::PointList).

Exit 0 when all compile; otherwise each failure is printed with the compiler's first lines.
"""
import os
import re
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

PREAMBLE_INCLUDES = ["<cagd/core/points.hpp>", "<numbers>", "<string>", "<vector>"]
PREAMBLE_BODY = """    cagd::PointList points(6, 2);   // the points the prose of docs/cpp.md calls `points`
    points << 0, 0, 1, 0.5, 2, 0, 3, 1, 4, 0.2, 5, 1;
    cagd::PointList moved_points = points;
    moved_points(2, 1) += 0.01;
"""


def compiler():
    return os.environ.get("CXX", "c++")


def pkg_config(prefix, *what):
    env = dict(os.environ, PKG_CONFIG_PATH=os.path.join(prefix, "lib", "pkgconfig"))
    out = subprocess.run(["pkg-config", *what, "cagd"], env=env, check=True, capture_output=True, text=True).stdout
    return out.split()


def snippets(markdown):
    """The programs of the ```cpp blocks: (first line number, includes, body)."""
    blocks, current, start = [], None, 0
    for number, line in enumerate(markdown.splitlines(), 1):
        if current is None and line.strip() == "```cpp":
            current, start = [], number + 1
        elif current is not None and line.strip() == "```":
            blocks.append((start, current))
            current = None
        elif current is not None:
            current.append(line)
    programs = []
    for start, lines in blocks:
        includes = [l for l in lines if l.startswith("#include")]
        body = [l for l in lines if not l.startswith("#include")]
        if not includes and programs:   # a continuation of the block before
            programs[-1][2].extend(body)
        else:
            programs.append((start, includes, body))
    return programs


def run(command):
    done = subprocess.run(command, capture_output=True, text=True)
    return done.returncode, (done.stdout + done.stderr)


def main():
    if len(sys.argv) != 3:
        print(__doc__.split("\n\n")[1], file=sys.stderr)
        return 2
    prefix, source = sys.argv[1], sys.argv[2]
    cflags = pkg_config(prefix, "--cflags")
    libs = pkg_config(prefix, "--libs")
    include_root = os.path.join(prefix, "include")
    headers = sorted(os.path.relpath(os.path.join(d, f), include_root)
                     for d, _, files in os.walk(os.path.join(include_root, "cagd")) for f in files if f.endswith(".hpp"))
    if len(headers) < 50:
        print(f"FAIL: only {len(headers)} headers installed under {include_root}/cagd")
        return 1
    failures = []
    with tempfile.TemporaryDirectory() as work, ThreadPoolExecutor(max_workers=2) as pool:
        def header_job(h):
            unit = os.path.join(work, re.sub(r"[^A-Za-z0-9]", "_", h) + ".cpp")
            with open(unit, "w") as f:
                f.write(f"#include <{h}>\n")
            return h, run([compiler(), "-fsyntax-only", *cflags, unit])

        def snippet_job(program):
            start, includes, body = program
            unit = os.path.join(work, f"cpp_md_line_{start}.cpp")
            with open(unit, "w") as f:
                for i in PREAMBLE_INCLUDES + [l.split(None, 1)[1] for l in includes]:
                    f.write(f"#include {i}\n")
                f.write("int main() {\n" + PREAMBLE_BODY + "\n".join("    " + l for l in body) + "\n}\n")
            return f"docs/cpp.md block at line {start}", run([compiler(), "-O0", *cflags, unit, "-o", unit + ".out", *libs])

        with open(os.path.join(source, "docs", "cpp.md"), encoding="utf-8") as f:
            programs = snippets(f.read())
        if len(programs) < 5:
            print(f"FAIL: found only {len(programs)} C++ programs in docs/cpp.md")
            return 1
        results = list(pool.map(header_job, headers)) + list(pool.map(snippet_job, programs))
    for name, (code, text) in results:
        if code != 0:
            failures.append(name)
            print(f"FAIL: {name} does not compile against the install:")
            print("\n".join(text.splitlines()[:12]))
    print(f"{len(headers)} installed headers compiled alone, {len(programs)} docs/cpp.md programs built; "
          f"{len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
