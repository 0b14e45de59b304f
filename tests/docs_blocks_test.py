#!/usr/bin/python3
"""Every command in the docs runs as written (ctest docs.blocks).

Each ```sh and ```python block of README.md and docs/*.md runs in a fresh temporary folder of
its own, as a user runs it from the repository's top: `build` and `reference` there are the build
tree and the repository's reference/, and the user's own files that the examples name
(points.csv, heights.csv, ...) are the ones in tests/data/docs/. HOME is the folder too, so that
nothing outside it changes. A shell block runs under `bash -e -o pipefail`; a Python block runs
with PYTHONPATH=build/python under /usr/bin/python3, as docs/python.md says.

A block or a line that cannot run here carries a visible marker, a comment

    # not run by the docs test: <why>

as the block's first line (the whole block) or at the end of a line (that line). The reason
must not be empty. Every other line runs, and a block passes only if it exits 0.

Usage: docs_blocks_test.py SOURCE_DIR BUILD_DIR [FILE ...]   (files relative to SOURCE_DIR)
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

MARKER = re.compile(r"#.*?not run by the docs test:\s*(.*)$")
FENCE = re.compile(r"^```(\w*)[^\n]*\n(.*?)^```", re.S | re.M)
TIMEOUT_SECONDS = 600


def blocks(path):
    text = open(path, encoding="utf-8").read()
    for match in FENCE.finditer(text):
        language = match.group(1)
        if language in ("sh", "python"):
            yield text.count("\n", 0, match.start()) + 1, language, match.group(2)


def logical_lines(body):
    """Shell lines with their backslash continuations joined."""
    pending = ""
    for line in body.splitlines():
        if line.rstrip().endswith("\\"):
            pending += line.rstrip()[:-1] + " "
            continue
        yield pending + line
        pending = ""
    if pending:
        yield pending


def prepare(folder, source, build):
    os.symlink(build, os.path.join(folder, "build"))
    os.symlink(os.path.join(source, "reference"), os.path.join(folder, "reference"))
    os.symlink(os.path.join(source, "peers"), os.path.join(folder, "peers"))
    fixtures = os.path.join(source, "tests", "data", "docs")
    for name in os.listdir(fixtures):
        shutil.copy(os.path.join(fixtures, name), folder)


def main():
    source, build = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    files = sys.argv[3:] or ["README.md"] + sorted(
        os.path.join("docs", f) for f in os.listdir(os.path.join(source, "docs")) if f.endswith(".md"))
    failures, ran, skipped = [], 0, []
    for relative in files:
        for line_number, language, body in blocks(os.path.join(source, relative)):
            where = f"{relative}:{line_number}"
            first = body.splitlines()[0] if body.strip() else ""
            whole = MARKER.search(first) if first.lstrip().startswith("#") else None
            if whole:
                if not whole.group(1).strip():
                    failures.append(f"{where}: a marker without a reason")
                skipped.append(f"{where} (block): {whole.group(1).strip()}")
                continue
            if language == "sh":
                kept = []
                for line in logical_lines(body):
                    marker = MARKER.search(line)
                    if marker:
                        if not marker.group(1).strip():
                            failures.append(f"{where}: a marker without a reason: {line}")
                        skipped.append(f"{where}: {line.split('#')[0].strip()}: {marker.group(1).strip()}")
                    else:
                        kept.append(line)
                command = ["bash", "-e", "-o", "pipefail", "-c", "\n".join(kept)]
            else:
                command = ["/usr/bin/python3", "-c", body]
            with tempfile.TemporaryDirectory(prefix="cagd-docs-") as folder:
                prepare(folder, source, build)
                environment = dict(os.environ, HOME=folder, PYTHONPATH=os.path.join(build, "python"))
                started = time.monotonic()
                try:
                    result = subprocess.run(command, cwd=folder, env=environment, capture_output=True,
                                            text=True, timeout=TIMEOUT_SECONDS)
                    status, output = result.returncode, result.stdout + result.stderr
                except subprocess.TimeoutExpired:
                    status, output = "timeout", f"no end after {TIMEOUT_SECONDS} s"
                seconds = time.monotonic() - started
            ran += 1
            print(f"{where} [{language}] exit {status} in {seconds:.1f} s", flush=True)
            if status != 0:
                failures.append(f"{where} [{language}] exit {status}:\n{output[-3000:]}")
    print(f"\n{ran} blocks run; not run, each with its marker's reason:")
    for entry in skipped:
        print(f"  {entry}")
    if failures:
        print("\nFAILED:\n" + "\n\n".join(failures))
        return 1
    if ran == 0:
        print("FAILED: no block ran")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
