#!/usr/bin/python3
"""How long the README's commands take: measured, written down, cited (docs/durations.csv).

    measure-durations.py measure [REPO]   clone REPO (default: this repository) into a temporary
                                          folder and time, in that clone, as a new user runs them:
                                          make web, make test, make reproduce, make test again,
                                          and pip install after make test (docs/python.md). The
                                          compiler cache is off (CCACHE_DISABLE=1), so "first use"
                                          compiles everything; packages are already installed
                                          (install-deps.sh's apt-get time depends on the network
                                          and is not measured). Writes docs/durations.csv, then
                                          the sentences below. Takes about an hour on 2 cores.
    measure-durations.py write            rewrite the sentences from docs/durations.csv
    measure-durations.py check            exit 1 unless README.md and docs/reproduction.md hold
                                          the sentence docs/durations.csv gives (ctest
                                          docs.durations)

The sentence stands between <!-- durations:begin --> and <!-- durations:end --> in each file.
"""
import csv
import io
import os
import re
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CSV = os.path.join(ROOT, "docs", "durations.csv")
CITING = ["README.md", os.path.join("docs", "reproduction.md")]
BLOCK = re.compile(r"(<!-- durations:begin -->\n)(.*?)(<!-- durations:end -->)", re.S)

# (step, command run in the clone, what it includes)
STEPS = [
    ("make web", "make web", "first use: the viewer compiled to WebAssembly (Emscripten's own "
     "library cache was warm)"),
    ("make test", "make test", "first use, after make web: set-up, build, ctest, the browser tests"),
    ("make reproduce", "make reproduce", "after make test: every experiment, figure and the benchmark"),
    ("make test again", "make test", "after make reproduce, nothing changed"),
    ("pip install", "/usr/bin/python3 -m venv --system-site-packages venv && "
     "CAGD_BUILD_DIR=$PWD/build venv/bin/pip install --quiet --no-build-isolation .",
     "after make test, reusing build/ (docs/python.md)"),
]


def machine():
    cpu = next((line.split(":", 1)[1].strip() for line in open("/proc/cpuinfo")
                if line.startswith("model name")), "unknown")
    memory_kib = next(int(line.split()[1]) for line in open("/proc/meminfo") if line.startswith("MemTotal"))
    return f"{os.cpu_count()} cores ({cpu}), {memory_kib / 2**20:.0f} GiB"


def measure(repository):
    revision = subprocess.run(["git", "-C", repository, "rev-parse", "--short", "HEAD"],
                              capture_output=True, text=True, check=True).stdout.strip()
    rows = []
    with tempfile.TemporaryDirectory(prefix="cagd-durations-") as work:
        clone = os.path.join(work, "clone")
        subprocess.run(["git", "clone", "-q", repository, clone], check=True)
        environment = dict(os.environ, CCACHE_DISABLE="1")
        for step, command, includes in STEPS:
            load = os.getloadavg()[0]
            started = time.monotonic()
            with open(os.path.join(work, "log.txt"), "a") as log:
                log.write(f"\n=== {step}: {command}\n")
                log.flush()
                process = subprocess.Popen(["bash", "-c", command], cwd=clone, env=environment,
                                           stdout=log, stderr=subprocess.STDOUT)
                samples = []  # the 1-minute load average every 10 s while the step runs
                while process.poll() is None:
                    samples.append(os.getloadavg()[0])
                    time.sleep(10)
            seconds = time.monotonic() - started
            mean_load = sum(samples) / len(samples) if samples else load
            print(f"{step}: {seconds:.0f} s (exit {process.returncode}, load {load:.1f} before, {mean_load:.1f} on average)", flush=True)
            if process.returncode != 0:
                sys.exit(f"measure-durations: '{command}' failed; see {work}/log.txt")
            rows.append((step, f"{seconds:.0f}", f"{load:.1f}", f"{mean_load:.1f}", includes))
    with open(CSV, "w", newline="") as f:
        f.write(f"# Measured by scripts/measure-durations.py on {time.strftime('%Y-%m-%d')} at {revision}, "
                f"on {machine()}, in a fresh clone, compiler cache off.\n"
                "# load_before, load_mean: the 1-minute load average when the step started and while it "
                "ran; the steps use 2 jobs, so a mean above 2 means other work slowed them.\n")
        writer = csv.writer(f, lineterminator="\n")
        writer.writerow(["step", "seconds", "load_before", "load_mean", "includes"])
        writer.writerows(rows)


def minutes(seconds):
    seconds = int(seconds)
    if seconds < 90:
        return f"{seconds} s"
    return f"{seconds / 60:.0f} min"


def sentence():
    text = open(CSV).read()
    header = text.splitlines()[0]
    date, revision, cores = re.search(r"on (\d{4}-\d\d-\d\d) at (\w+), on (\d+) cores", header).groups()
    seconds = {row["step"]: row["seconds"]
               for row in csv.DictReader(io.StringIO("\n".join(l for l in text.splitlines() if not l.startswith("#"))))}
    return (f"How long, measured on {cores} cores ({date}, [docs/durations.csv](docs/durations.csv) "
            f"by `scripts/measure-durations.py`): "
            f"`make test` {minutes(seconds['make test'])} on first use after `make web`'s "
            f"{minutes(seconds['make web'])}, {minutes(seconds['make test again'])} again; "
            f"`make reproduce` {minutes(seconds['make reproduce'])}; "
            f"`pip install` {minutes(seconds['pip install'])} after `make test`.\n")


def cited(path, text):
    # The link is relative to the citing file.
    if path.startswith("docs" + os.sep):
        return text.replace("(docs/durations.csv)", "(durations.csv)")
    return text


def write():
    for path in CITING:
        full = os.path.join(ROOT, path)
        content = open(full).read()
        if not BLOCK.search(content):
            sys.exit(f"measure-durations: {path} has no <!-- durations:begin --> block")
        content = BLOCK.sub(lambda m: m.group(1) + cited(path, sentence()) + m.group(3), content)
        open(full, "w").write(content)


def check():
    wrong = []
    for path in CITING:
        match = BLOCK.search(open(os.path.join(ROOT, path)).read())
        if not match or match.group(2) != cited(path, sentence()):
            wrong.append(f"{path}: {match.group(2).strip() if match else 'no durations block'}")
    if wrong:
        print("These files do not say what docs/durations.csv measured (scripts/measure-durations.py write):")
        print("\n".join(wrong))
        print("expected: " + sentence())
        return 1
    print("README.md and docs/reproduction.md cite docs/durations.csv: " + sentence())
    return 0


if __name__ == "__main__":
    mode = sys.argv[1] if len(sys.argv) > 1 else ""
    if mode == "measure":
        measure(os.path.abspath(sys.argv[2]) if len(sys.argv) > 2 else ROOT)
        write()
    elif mode == "write":
        write()
    elif mode == "check":
        sys.exit(check())
    else:
        sys.exit(__doc__)
