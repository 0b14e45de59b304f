#!/usr/bin/env python3
"""Every registered method's curve, open and closed, planar and (where the method takes them) space,
leaves `cagd interpolate` in every format and is read back by an independent reader, then compared
with the curve's own samples (the CSV of the same run, 15 significant digits, in the same parameter t):

- JSON: our reader (`cagd analyze --in c.json` rebuilds the method from the document's points and
  measures its distance from the document's pieces), and the pieces evaluated here by de Casteljau;
- DXF: ezdxf (Debian python3-ezdxf) reads the file, audits it, and evaluates the SPLINE (closed
  curves: the periodic spline, its parameter shifted as its knots say);
- STEP: OpenCASCADE (readers/step_reader.cpp) reads the file and evaluates its edge's curve;
- SVG: headless Chromium loads every drawing in one page; the browser's own path geometry
  (getTotalLength, getPointAtLength) must lie on the curve.

Surfaces (`cagd surface --kind tensor|coons`, `cagd typical-surface`) leave in JSON (the Bézier
patches, evaluated here by de Casteljau in both directions) and STEP (OpenCASCADE evaluates the
face's B-spline surface), each compared with the command's own CSV grid of the same surface.

Tolerances: an exact form must agree to 1e-9 of the data diagonal (the CSV's 15 digits and the
readers' arithmetic); an approximation to the tolerance its document states (1e-6 of the diagonal
of the curve's own samples, larger than the points' where the curve overshoots them) plus that;
the browser's geometry to 2e-4 of the diagonal (it works in single precision, and the reference
polyline of 64 samples per piece is off by about h²κ/8 between samples).
Usage: export_readers_test.py CAGD [STEP_READER]   (an empty STEP_READER: STEP is skipped, said so)
"""
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile

cagd = sys.argv[1]
step_reader = sys.argv[2] if len(sys.argv) > 2 and sys.argv[2] else None
failures = []
checked = {"json": 0, "dxf": 0, "step": 0, "svg": 0, "surface json": 0, "surface step": 0}


def fail(what):
    failures.append(what)
    print("FAIL", what)


def run(*args, stdin=None):
    r = subprocess.run([cagd, *args], capture_output=True, text=True, input=stdin)
    if r.returncode != 0:
        raise RuntimeError(" ".join(args) + ": exit " + str(r.returncode) + ": " + r.stderr.strip())
    return r.stdout


def methods():
    """(name, takes 3-D, takes closed) of every registered method, from --list-methods."""
    out = []
    for line in run("interpolate", "--list-methods").splitlines():
        if line and not line.startswith(" "):
            out.append([line.split()[0], False, False])
        elif line.strip().startswith("claims:"):
            out[-1][1] = "3-D" in line
            out[-1][2] = "open, closed" in line
    return out


def write_points(path, rows):
    with open(path, "w") as f:
        f.write("\n".join(",".join(repr(v) for v in r) for r in rows) + "\n")


def read_csv(path):
    with open(path) as f:
        header = f.readline().strip().split(",")
        rows = [[float(v) for v in line.split(",")] for line in f if line.strip()]
    dim = 3 if "z" in header else 2
    return [r[0] for r in rows], [r[1:1 + dim] for r in rows]


def dist(a, b):
    return math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)))


def bezier_point(control, s):
    pts = [list(p) for p in control]
    for r in range(1, len(pts)):
        for i in range(len(pts) - r):
            pts[i] = [(1 - s) * a + s * b for a, b in zip(pts[i], pts[i + 1])]
    return pts[0]


def json_point(doc, t):
    breaks = doc["breaks"]
    i = max(0, min(len(breaks) - 2, next((k for k in range(len(breaks) - 1) if t < breaks[k + 1]), len(breaks) - 2)))
    return bezier_point(doc["pieces"][i], (t - breaks[i]) / (breaks[i + 1] - breaks[i]))


def surface_point(doc, u, v):
    """S(u, v) of a surface document: the cell holding (u, v), de Casteljau along v, then along u."""
    def cell(breaks, x):
        return max(0, min(len(breaks) - 2, next((k for k in range(len(breaks) - 1) if x < breaks[k + 1]), len(breaks) - 2)))
    ub, vb = doc["u_breaks"], doc["v_breaks"]
    a, b = cell(ub, u), cell(vb, v)
    net = doc["patches"][a + (len(ub) - 1) * b]
    s, t = (u - ub[a]) / (ub[a + 1] - ub[a]), (v - vb[b]) / (vb[b + 1] - vb[b])
    return bezier_point([bezier_point(row, t) for row in net], s)


def check_surface(label, base, grid_csv, parameters):
    """The JSON and STEP files of base against the CSV grid: parameters(row) gives (u, v), the
    columns x, y, z the point."""
    with open(grid_csv) as f:
        header = f.readline().strip().split(",")
        rows = [dict(zip(header, (float(v) for v in line.split(",")))) for line in f if line.strip()]
    uv = [parameters(r) for r in rows]
    xyz = [[r["x"], r["y"], r["z"]] for r in rows]
    tol = 1e-9 * diagonal(xyz)
    with open(base + ".json") as f:
        doc = json.load(f)
    if doc["format"] != "cagd-surface" or not doc["exact"]:
        fail(f"{label}: the JSON is not an exact surface document")
    err = max(dist(surface_point(doc, u, v), x) for (u, v), x in zip(uv, xyz))
    if err > tol:
        fail(f"{label}: JSON patches {err:.3g} from the grid (tolerance {tol:.3g})")
    checked["surface json"] += 1
    if not step_reader:
        return
    r = subprocess.run([step_reader, base + ".step"], input="\n".join(f"{u!r},{v!r}" for u, v in uv) + "\n", capture_output=True, text=True)
    if r.returncode != 0:
        fail(f"{label}: OpenCASCADE does not read the STEP surface: {r.stderr.strip()}")
        return
    lines = r.stdout.split()
    bounds = [float(v) for v in lines[0].split(",")]
    want = [min(u for u, _ in uv), max(u for u, _ in uv), min(v for _, v in uv), max(v for _, v in uv)]
    if max(abs(a - b) for a, b in zip(bounds, want)) > 1e-9 * max(1.0, max(abs(w) for w in want)):
        fail(f"{label}: STEP surface on {bounds}, the grid on {want}")
    got = [[float(v) for v in line.split(",")] for line in lines[1:]]
    err = max(dist(g, x) for g, x in zip(got, xyz))
    if len(got) != len(xyz) or err > tol:
        fail(f"{label}: OpenCASCADE's surface {err:.3g} from the grid (tolerance {tol:.3g})")
    checked["surface step"] += 1


def diagonal(points):
    cols = list(zip(*points))
    return math.sqrt(sum((max(c) - min(c)) ** 2 for c in cols))


open_2d = [(0.0, 5.0), (0.3, 2.5), (1.5, 1.5), (2.3, 1.25), (2.5, 2.5), (3.0, 3.5), (5.0, 3.75), (5.5, 3.3), (5.75, 1.0), (7.0, 1.0)]
closed_2d = [((1.0 if i % 2 == 0 else 1.4) * math.cos(2 * math.pi * i / 8), (1.0 if i % 2 == 0 else 1.4) * math.sin(2 * math.pi * i / 8)) for i in range(8)]
space = [(math.cos(0.7 * i), math.sin(0.7 * i), 0.25 * i) for i in range(9)]

work = tempfile.mkdtemp(prefix="cagd-export-readers-")
try:
    import ezdxf

    write_points(os.path.join(work, "open.csv"), open_2d)
    write_points(os.path.join(work, "closed.csv"), closed_2d)
    write_points(os.path.join(work, "space.csv"), space)
    svgs = []  # (name, svg path, csv samples, diagonal, tolerance, length)
    for name, takes_3d, takes_closed in methods():
        cases = [("open", False)] + ([("closed", True)] if takes_closed else []) + ([("space", False)] if takes_3d else [])
        for data, closed in cases:
            label = f"{name} {data}"
            pts = {"open": open_2d, "closed": closed_2d, "space": space}[data]
            diag = diagonal(pts)
            base = os.path.join(work, f"{name}-{data}")
            common = ["interpolate", "--method", name, "--in", os.path.join(work, data + ".csv"), "--quiet"] + (["--closed"] if closed else [])
            try:
                run(*common, "--out", base + ".csv", "--samples", "64")
                run(*common, "--out", base + ".json")
                run(*common, "--out", base + ".dxf", "--show-points")
                if step_reader:
                    run(*common, "--out", base + ".step")
                if data != "space":
                    run(*common, "--out", base + ".svg", "--comb", "--show-points")
            except RuntimeError as e:
                fail(f"{label}: {e}")
                continue
            ts, xs = read_csv(base + ".csv")
            with open(base + ".json") as f:
                doc = json.load(f)
            exact = doc["exact"]
            # An approximation is held to the tolerance the document states: 1e-6 of the diagonal
            # of the curve's own samples, which exceeds the points' where the curve overshoots them.
            tol = 1e-9 * diag if exact else doc["tolerance"] + 1e-9 * diag
            # JSON: the pieces at the samples' parameters, and cagd analyze's rebuild.
            err = max(dist(json_point(doc, t), x) for t, x in zip(ts, xs))
            if err > tol:
                fail(f"{label}: JSON pieces {err:.3g} from the samples (tolerance {tol:.3g})")
            analysis = dict(line.split(",") for line in run("analyze", "--in", base + ".json").splitlines()[1:])
            rebuilt = float(analysis["rebuilt_max_distance"])
            if rebuilt > tol:
                fail(f"{label}: cagd analyze rebuilds the method {rebuilt:.3g} from the document's pieces (tolerance {tol:.3g})")
            checked["json"] += 1
            # DXF through ezdxf: audit, then the SPLINE evaluated at the samples' parameters.
            dxf = ezdxf.readfile(base + ".dxf")
            auditor = dxf.audit()
            if auditor.has_errors:
                fail(f"{label}: ezdxf's audit finds errors: {[str(e.message) for e in auditor.errors]}")
            splines = dxf.modelspace().query("SPLINE")
            points = dxf.modelspace().query("POINT")
            if len(splines) != 1 or len(points) != len(pts):
                fail(f"{label}: DXF holds {len(splines)} splines and {len(points)} points, expected 1 and {len(pts)}")
            else:
                tool = splines[0].construction_tool()
                # The file's parameter starts where its knots put it: t_min for a clamped spline,
                # shifted for a periodic one (its knots start at 0).
                offset = splines[0].knots[splines[0].dxf.degree] - ts[0]
                err = max(dist(tool.point(t + offset), list(x) + [0.0] * (3 - len(x))) for t, x in zip(ts, xs))
                if err > tol:
                    fail(f"{label}: ezdxf's spline {err:.3g} from the samples (tolerance {tol:.3g})")
                if closed and not (splines[0].closed and splines[0].dxf.flags & 2):
                    fail(f"{label}: the DXF spline of a closed curve is not flagged closed and periodic")
                if closed and min(splines[0].knots) < 0:
                    fail(f"{label}: the periodic DXF spline has negative knots")
            checked["dxf"] += 1
            # STEP through OpenCASCADE.
            if step_reader:
                r = subprocess.run([step_reader, base + ".step"], input="\n".join(repr(t) for t in ts) + "\n", capture_output=True, text=True)
                if r.returncode != 0:
                    fail(f"{label}: OpenCASCADE does not read the STEP file: {r.stderr.strip()}")
                else:
                    lines = r.stdout.split()
                    first, last = (float(v) for v in lines[0].split(","))
                    if abs(first - ts[0]) > 1e-9 * max(1, abs(ts[-1])) or abs(last - ts[-1]) > 1e-9 * max(1, abs(ts[-1])):
                        fail(f"{label}: STEP curve on [{first}, {last}], the samples on [{ts[0]}, {ts[-1]}]")
                    got = [[float(v) for v in line.split(",")] for line in lines[1:]]
                    err = max(dist(g, list(x) + [0.0] * (3 - len(x))) for g, x in zip(got, xs))
                    if len(got) != len(xs) or err > tol:
                        fail(f"{label}: OpenCASCADE's curve {err:.3g} from the samples (tolerance {tol:.3g})")
                checked["step"] += 1
            if data != "space":
                svgs.append((label, base + ".svg", xs, diag, float(analysis["length_integrated"])))

    # Surfaces: each in csv (the reference grid), json and step.
    heights = [(x, y, math.sin(x) * math.cos(0.7 * y) + 0.1 * x * y) for x in (0.0, 0.6, 1.5, 2.0, 3.2) for y in (-1.0, 0.0, 0.8, 2.0)]
    write_points(os.path.join(work, "heights.csv"), heights)
    # Four edges meeting at (0, 0, 0), (3, 0, 0), (0, 2, 1) and (3, 2.3, 0.5), with spans of different lengths.
    edges = {"bottom": [(s, 0.0, 0.3 * s * (3 - s)) for s in (0.0, 1.0, 2.0, 3.0)],
             "left": [(0.0, t, 0.25 * t * t) for t in (0.0, 0.5, 1.2, 2.0)],
             "top": [(0.0, 2.0, 1.0), (1.5, 2.15, 0.8), (3.0, 2.3, 0.5)],
             "right": [(3.0, 0.0, 0.0), (3.0, 0.7, 0.2), (3.0, 1.4, 0.3), (3.0, 2.3, 0.5)]}
    for name, rows in edges.items():
        write_points(os.path.join(work, name + ".csv"), rows)
    surface_cases = [
        ("surface tensor", ["surface", "--kind", "tensor", "--in", os.path.join(work, "heights.csv"), "--samples", "12"], lambda r: (r["x"], r["y"])),
        ("surface coons", ["surface", "--kind", "coons"] + sum((["--" + n, os.path.join(work, n + ".csv")] for n in edges), []) + ["--samples", "12"],
         lambda r: (r["u"], r["v"])),
        ("typical-surface", ["typical-surface", "--n", "9", "--alpha-u", "-0.5", "--alpha-v", "2", "--angle-deg", "20", "--grid", "11"], lambda r: (r["u"], r["v"])),
    ]
    for label, args, parameters in surface_cases:
        base = os.path.join(work, label.replace(" ", "-"))
        try:
            run(*args, "--out", base + ".csv")
            run(*args, "--out", base + ".json")
            if step_reader:
                run(*args, "--out", base + ".step")
        except RuntimeError as e:
            fail(f"{label}: {e}")
            continue
        check_surface(label, base, base + ".csv", parameters)

    # SVG: one page with every drawing; the browser measures each path.
    chromium = shutil.which("chromium")
    if not chromium:
        fail("chromium is not installed (install-deps installs it in the test layer)")
    else:
        page = os.path.join(work, "page.html")
        with open(page, "w") as f:
            f.write("<!DOCTYPE html><html><body>\n")
            for k, (_, path, _, _, _) in enumerate(svgs):
                with open(path) as s:
                    f.write(f'<div id="d{k}">' + s.read().split("?>", 1)[1] + "</div>\n")
            f.write("""<pre id="out"></pre><script>
const result = [];
document.querySelectorAll('div').forEach(div => {
  const p = div.querySelector('path#curve');
  const L = p.getTotalLength();
  const pts = [];
  for (let i = 0; i <= 400; ++i) { const q = p.getPointAtLength(L * i / 400); pts.push([q.x, q.y]); }
  result.push({length: L, points: pts, comb: div.querySelectorAll('g#comb path').length, dots: div.querySelectorAll('g#points circle').length});
});
document.getElementById('out').textContent = JSON.stringify(result);
</script></body></html>""")
        r = subprocess.run([chromium, "--headless", "--no-sandbox", "--disable-gpu", "--dump-dom", "file://" + page], capture_output=True, text=True, timeout=120)
        text = r.stdout
        start = text.find('<pre id="out">')
        if r.returncode != 0 or start < 0:
            fail(f"chromium: exit {r.returncode}: {r.stderr[-500:]}")
        else:
            import html
            result = json.loads(html.unescape(text[start + len('<pre id="out">'):text.index("</pre>", start)]))
            for (label, _, xs, diag, length), got in zip(svgs, result):
                # Distance of each browser point from the polyline of the samples.
                def to_polyline(q):
                    best = float("inf")
                    for a, b in zip(xs, xs[1:]):
                        ab = [b[0] - a[0], b[1] - a[1]]
                        den = ab[0] ** 2 + ab[1] ** 2
                        u = 0.0 if den == 0 else max(0.0, min(1.0, ((q[0] - a[0]) * ab[0] + (q[1] - a[1]) * ab[1]) / den))
                        best = min(best, math.hypot(q[0] - a[0] - u * ab[0], q[1] - a[1] - u * ab[1]))
                    return best
                err = max(to_polyline(q) for q in got["points"][::4])
                if err > 2e-4 * diag:
                    fail(f"{label}: the browser's SVG path is {err:.3g} from the curve (tolerance {2e-4 * diag:.3g})")
                if abs(got["length"] - length) > 1e-3 * length:
                    fail(f"{label}: the browser measures the SVG path {got['length']:.6g} long, the curve is {length:.6g}")
                if got["comb"] != 2 or got["dots"] == 0:
                    fail(f"{label}: the SVG lacks its comb or points ({got['comb']} comb paths, {got['dots']} points)")
                checked["svg"] += 1
finally:
    shutil.rmtree(work, ignore_errors=True)

print("export.readers: read back " + ", ".join(f"{n} {k}" for k, n in checked.items()) + ("" if step_reader else "; STEP skipped: this library has no OpenCASCADE"))
total = sum(checked.values())
print(f"{total - len(failures)} passed, {len(failures)} failed")
sys.exit(1 if failures or total == 0 else 0)
