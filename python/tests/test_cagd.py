"""The Python module against the C++ library on the papers' data (make test, ctest python.module).

The C++ values come from two places: the program python_reference_values (the same computations
written in C++, 17 digits) and the `cagd` command. Both must agree with the module to 1e-12
(relative, with an absolute floor of 1e-12 times the data's scale): the module converts, it does
not compute. Environment (set by ctest): CAGD_SOURCE_DIR, CAGD_REFERENCE_VALUES, CAGD_CLI.
"""
import csv
import io
import json
import math
import os
import pickle
import shutil
import subprocess
import sys

import numpy as np
import pytest

import cagd

ROOT = os.environ.get("CAGD_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
TABLE1 = os.path.join(ROOT, "reference", "pseudo_energy", "data", "table1.csv")
FRACTIONS = [0.0, 0.1, 0.37, 0.5, 0.93, 1.0]
TOL = 1e-12


def table1():
    return np.loadtxt(TABLE1, delimiter=",", comments="#", skiprows=3)


def lifted(points):
    """Table 1 in 3-D: z = (x - y)/4, exact in binary floating point (as the C++ side)."""
    return np.column_stack([points, (points[:, 0] - points[:, 1]) / 4.0])


@pytest.fixture(scope="module")
def cpp():
    exe = os.environ.get("CAGD_REFERENCE_VALUES")
    if not exe:
        pytest.fail("CAGD_REFERENCE_VALUES is not set (run through ctest)")
    out = subprocess.run([exe, ROOT], check=True, capture_output=True, text=True).stdout
    values = {}
    for line in out.splitlines():
        key, value = line.rsplit(" ", 1)
        values[key] = float(value)
    assert len(values) > 1000, "the C++ side wrote too few values"
    return values


def close(ours, theirs, scale=1.0):
    if math.isnan(ours) or math.isnan(theirs):  # undefined (torsion at a straight point) on both sides
        return math.isnan(ours) and math.isnan(theirs)
    return abs(ours - theirs) <= TOL * max(abs(theirs), scale)


def curve_values(key, c):
    """The same values as curve_values() in reference_values.cpp."""
    out = {key + ".length": c.arc_length(), key + ".bending_energy": c.bending_energy()}
    if c.dimension == 2:
        out[key + ".area"] = c.area()
    t0, t1 = c.parameter_range
    ts = np.array([t0 + f * (t1 - t0) for f in FRACTIONS])
    jets = c.evaluate(ts, derivatives=2)
    kappa = c.curvature(ts)
    tau = c.torsion(ts) if c.dimension == 3 else None
    for f in range(len(FRACTIONS)):
        for r in range(3):
            for d in range(c.dimension):
                out[f"{key}.jet{f}.{r}.{d}"] = jets[f, r, d]
        out[f"{key}.curvature{f}"] = kappa[f]
        if tau is not None:
            out[f"{key}.torsion{f}"] = tau[f]
    return out


def check_all(values, cpp, scale):
    assert values
    bad = [(k, v, cpp[k]) for k, v in values.items() if not close(v, cpp[k], scale)]
    assert not bad, f"{len(bad)} of {len(values)} values differ from C++, e.g. {bad[:3]}"


def test_every_method_open_closed_2d_3d_equals_cpp(cpp):
    plane = table1()
    checked = 0
    for m in cagd.methods():
        claims = m["claims"]
        for closed in (False, True):
            if closed and not claims["supports_closed"]:
                continue
            for dim in (2, 3):
                if dim > claims["max_dimension"]:
                    continue
                key = f"{m['name']}.{'closed' if closed else 'open'}.{dim}d"
                r = cagd.interpolate_result(plane if dim == 2 else lifted(plane), m["name"], closed=closed)
                assert float(r.ok) == cpp[key + ".ok"], key
                if r.ok:
                    check_all(curve_values(key, r.curve), cpp, scale=10.0)
                    checked += 1
    # Every method builds at least its open planar curve on Table 1.
    assert checked >= len(cagd.methods())


def test_pseudo_energy_equals_cpp(cpp):
    for i, (t0, t1) in enumerate([(0.3, 0.7), (-1.2, 2.5), (2.9, -0.4)]):
        e = cagd.pseudo_energy(t0, t1)
        key = f"pseudo_energy.{i}"
        for name, field in [("J", "pseudo_energy"), ("r0", "r0"), ("r1", "r1"), ("length", "length"), ("area", "area")]:
            assert close(e[field], cpp[f"{key}.{name}"]), (key, name)


def test_aesthetic_and_typical_curves_equal_cpp(cpp):
    check_all(curve_values("lac", cagd.normalized_log_aesthetic_curve(-1.0, 2.0)), cpp, scale=1.0)
    typical = cagd.typical_curve(-1.0, 2.0, 9, kind="constant-rotation")
    check_all(curve_values("typical", typical["curve"]), cpp, scale=1.0)
    assert typical["control_points"].shape == (10, 2)


def test_elastic_line_equals_cpp(cpp):
    plane = table1()
    spline, second = cagd.elastic_line(np.arange(len(plane), dtype=float), plane[:, 1], 0.1)
    values = {f"elastic_line.y{i}": y for i, y in enumerate(spline.values[:, 0])}
    check_all(values, cpp, scale=1.0)
    assert second.shape == (len(plane), 1) and second[0, 0] == 0.0 and second[-1, 0] == 0.0


def test_compare_equals_cpp(cpp):
    r = cagd.compare(table1(), threads=1)
    checked = 0
    for i, name in enumerate(r["method"]):
        if r["length"].mask[i]:
            assert r["status"][i] != "ok"
            continue
        assert close(r["length"][i], cpp[f"compare.{name}.length"], 10.0)
        assert close(r["pseudo_energy"][i], cpp[f"compare.{name}.pseudo_energy"], 10.0)
        if not r["bending_energy"].mask[i]:
            assert close(r["bending_energy"][i], cpp[f"compare.{name}.bending_energy"], 10.0)
        checked += 1
    assert checked >= 15
    # An open curve has no enclosed area: masked, never NaN.
    assert r["area"].mask.all()
    assert not any(np.isnan(r[k].data).any() for k in r if isinstance(r[k], np.ma.MaskedArray))
    assert r["max_abs_torsion"].mask.all()


def test_compare_on_space_points():
    t = np.linspace(0.0, 2.0 * np.pi, 24, endpoint=False)
    knot = np.c_[np.sin(t) + 2 * np.sin(2 * t), np.cos(t) - 2 * np.cos(2 * t), -np.sin(3 * t)]
    r = cagd.compare(knot, closed=True, methods=["pseudo-spline-approx", "cubic-b", "curvature-profile"], threads=1)
    assert r["status"] == ["ok", "ok", "not applicable"]
    # the shared tables' load is timed apart from the construction; none for a method not applied
    assert list(r["shared_seconds"].mask) == [False, False, True] and r["shared_seconds"][0] >= 0.0
    assert list(r["seconds"].mask) == [False, False, True] and r["seconds"][1] > 0.0
    assert r["area"].mask.all() and r["curvature_sign_changes"].mask.all()
    assert not r["max_abs_torsion"].mask[0] and r["max_abs_torsion"][0] > 0.0
    # the table's torsion is the largest |τ| of the curve at the same samples (128 per span)
    c = cagd.interpolate(knot, "cubic-b", closed=True)
    br = c.breakpoints()
    u = np.concatenate([np.linspace(br[k], br[k + 1], 129) for k in range(len(br) - 1)])
    assert r["max_abs_torsion"][1] == pytest.approx(np.max(np.abs(c.torsion(u))), rel=1e-9)


def cli_quantities(*args):
    out = subprocess.run([os.environ["CAGD_CLI"], *args], check=True, capture_output=True, text=True).stdout
    return {row["quantity"]: row["value"] for row in csv.DictReader(io.StringIO(out))}


@pytest.mark.parametrize("method", ["pseudo-spline", "cubic-b", "s-spline", "hosaka", "boost-makima"])
def test_length_and_area_equal_the_command(method):
    # `cagd analyze --in` prints 12 significant digits: agreement to that print.
    q = cli_quantities("analyze", "--in", TABLE1, "--method", method)
    c = cagd.interpolate(table1(), method)
    assert float(q["length_integrated"]) == pytest.approx(c.arc_length(), rel=1e-11)
    assert float(q["area_integrated"]) == pytest.approx(c.area(), rel=1e-11)


def test_methods_are_the_registry_of_the_command():
    listing = subprocess.run([os.environ["CAGD_CLI"], "interpolate", "--list-methods"], check=True, capture_output=True, text=True).stdout
    names = [line.split()[0] for line in listing.splitlines() if line and not line[0].isspace()]
    assert [m["name"] for m in cagd.methods()] == names
    s = next(m for m in cagd.methods() if m["name"] == "s-spline")
    assert "m" in [p["name"] for p in s["parameters"]]
    assert "s-spline-m2" in s["presets"]


def test_evaluate_is_vectorised_and_shaped():
    c = cagd.interpolate(table1(), "cubic-b")
    t = np.linspace(*c.parameter_range, 101)
    pos = c.evaluate(t)
    jets = c.evaluate(t, derivatives=3)
    assert pos.shape == (101, 2) and jets.shape == (101, 4, 2)
    assert np.array_equal(jets[:, 0, :], pos)
    assert np.array_equal(c.evaluate(float(t[7])), pos[7])
    assert c.evaluate(0.5, derivatives=1).shape == (2, 2)
    # The curve interpolates: positions at the node parameters are the data points.
    assert np.allclose(c.evaluate(c.node_parameters), table1(), rtol=0, atol=1e-12)
    # Derivatives against central differences of the positions, away from the nodes (the
    # derivative in u jumps there by the change of dτ/du).
    h = 1e-6
    inner = t[:-1] + 0.0537
    fd = (c.evaluate(inner + h) - c.evaluate(inner - h)) / (2 * h)
    assert np.allclose(fd, c.evaluate(inner, derivatives=1)[:, 1, :], atol=1e-6)
    # A closed curve returns to its start.
    closed = cagd.interpolate(table1(), "cubic-b", closed=True)
    a, b = closed.parameter_range
    assert np.allclose(closed.evaluate(a), closed.evaluate(b), atol=1e-12)


def test_long_arrays_are_evaluated_on_every_core_with_the_same_result():
    # From 2^16 parameters on, evaluate and the other vectorised functions split the array over the
    # cores (python/bindings.hpp); every value is the one a short, serial call gives, bit for bit.
    c = cagd.interpolate(table1(), "pseudo-spline")
    t = np.linspace(*c.parameter_range, 200003)
    jets = c.evaluate(t, derivatives=2)
    serial = np.concatenate([c.evaluate(t[i:i + 50000], derivatives=2) for i in range(0, t.size, 50000)])
    assert np.array_equal(jets, serial)
    assert np.array_equal(c.curvature(t), np.concatenate([c.curvature(t[i:i + 50000]) for i in range(0, t.size, 50000)]))
    # A bad parameter deep in a long array is reported as a serial loop would report the first one.
    bad = t.copy()
    bad[150001], bad[190000] = 1e9, 2e9
    with pytest.raises(ValueError, match=r"^t = 1000000000 outside"):
        c.evaluate(bad)


def test_bad_input_is_value_error_with_the_library_message():
    p = table1()
    with pytest.raises(ValueError, match="unknown method 'nope'"):
        cagd.interpolate(p, "nope")
    bad = p.copy()
    bad[3, 1] = float("nan")
    with pytest.raises(ValueError, match=r"point 4 \(row 3\) coordinate y is nan"):
        cagd.interpolate(bad, "cubic-b")
    with pytest.raises(ValueError, match="out of range"):
        cagd.interpolate(p, "s-spline", m=-3)
    with pytest.raises(ValueError, match=r"\(n, 2\) or \(n, 3\)"):
        cagd.interpolate(np.zeros((4, 4)), "cubic-b")
    c = cagd.interpolate(p, "cubic-b")
    with pytest.raises(ValueError, match="outside"):
        c.evaluate(1e9)
    with pytest.raises(ValueError):
        cagd.pseudo_energy(4.0, 0.5)  # outside [-π, π]
    with pytest.raises(ValueError):
        cagd.interpolate(lifted(p), "curvature-profile")  # a planar method given 3-D points


def test_numerical_outcome_is_no_solution_or_a_status():
    # Line, arc, line through these points is impossible (curvature_profile; the C++ test
    # InconsistentArcIsNoSolutionNotAWrongCurve).
    p = np.array([[0.0, 0.0], [1.0, 0.0], [2.0, 1.0], [3.0, 1.0]])
    r = cagd.interpolate_result(p, "curvature-profile", spans="line,arc,line")
    assert not r.ok and r.status == "no_solution" and r.curve is None and r.message
    with pytest.raises(cagd.NoSolution, match="inconsistent"):
        cagd.interpolate(p, "curvature-profile", spans="line,arc,line")
    assert issubclass(cagd.NoSolution, RuntimeError)
    with pytest.raises(cagd.NoSolution, match="undefined node"):
        cagd.pseudo_energy(0.0, 0.0)


def test_curvature_profile_reports_its_newton_history():
    x = np.arange(0.0, 8.0)
    r = cagd.interpolate_result(np.column_stack([x, np.sin(x)]), "curvature-profile")
    assert r.ok
    keys = [k for k, _ in r.report]
    assert "unknowns" in keys and any(k.startswith("newton_") for k in keys)


def test_pseudo_spline_quantities_and_table_lookup():
    r = cagd.interpolate_result(table1(), "pseudo-spline")
    assert "length" in " ".join(r.quantities)
    table = cagd.PseudoEnergyTable.build(n=36, threads=2)
    v = table.lookup(0.3, 0.7)
    assert set(v) >= {"pseudo_energy", "r0", "r1", "length", "area", "type"}
    assert len(table.nodes) == 36
    # The paper's 10° table interpolates J to about 1 % here (a property, not equality).
    assert v["pseudo_energy"] == pytest.approx(cagd.pseudo_energy(0.3, 0.7)["pseudo_energy"], rel=0.02)
    assert table.node(3, 4)["pseudo_energy"] > 0
    with pytest.raises(ValueError):
        table.node(36, 0)


def test_table_save_reports_a_failed_write_and_keeps_the_old_file(tmp_path):
    table = cagd.PseudoEnergyTable.build(n=8, threads=2)
    with pytest.raises(OSError, match="No space left on device"):
        table.save("/dev/full")
    path = tmp_path / "table.txt"
    path.write_text("old\n")
    with pytest.raises(ValueError, match="is a directory"):
        table.save(str(tmp_path))
    table.save(str(path))
    assert path.read_text().startswith("# cagd pseudo_energy table format")
    assert [p.name for p in tmp_path.iterdir()] == ["table.txt"], "no temporary file is left"
    # A link keeps pointing where it did (its target is replaced); a loop of links is a ValueError.
    link = tmp_path / "link.txt"
    link.symlink_to(path)
    table.save(str(link))
    assert link.is_symlink() and os.readlink(link) == str(path)
    loop = tmp_path / "loop"
    loop.symlink_to(loop)
    with pytest.raises(ValueError, match="loop"):
        table.save(str(loop))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["link.txt", "loop", "table.txt"], "nothing else is made"
    loaded, built = cagd.PseudoEnergyTable.load(str(link)).node(2, 3), table.node(2, 3)
    assert all(loaded[k] == built[k] for k in ("pseudo_energy", "r0", "r1", "length", "type")), "what was saved loads back bit for bit"


def test_a_damaged_or_hostile_table_is_a_value_error_naming_the_file(tmp_path):
    good = tmp_path / "table.txt"
    cagd.PseudoEnergyTable.build(n=8, threads=2).save(str(good))
    lines = good.read_text().splitlines(keepends=True)
    row = next(k for k, line in enumerate(lines) if not line.startswith("#") and any(c in "123456789" for c in line))
    flipped = lines[row].replace("1", "2", 1) if "1" in lines[row] else lines[row].replace("2", "3", 1)
    damaged = tmp_path / "damaged.txt"
    damaged.write_text("".join(lines[:row] + [flipped] + lines[row + 1:]))
    with pytest.raises(ValueError, match=r"damaged\.txt.*checksum"):
        cagd.PseudoEnergyTable.load(str(damaged))
    truncated = tmp_path / "truncated.txt"
    truncated.write_text("".join(lines[: len(lines) // 2]))
    with pytest.raises(ValueError, match=r"truncated\.txt"):
        cagd.PseudoEnergyTable.load(str(truncated))


def _fnv1a64(data):
    """The table files' checksum (FNV-1a, 64 bits), written here independently of the library."""
    h = 14695981039346656037
    for byte in data:
        h = ((h ^ byte) * 1099511628211) & 0xFFFFFFFFFFFFFFFF
    return h


def test_a_huge_declared_grid_is_refused_within_512_mb(tmp_path):
    # In a child interpreter whose address space is limited: the refusal comes before any allocation.
    huge = tmp_path / "huge.txt"
    content = b"# cagd pseudo_energy table format 7 grid 6000 placement periodic method fast\nx\n"
    huge.write_bytes(content + f"# checksum fnv1a64 {_fnv1a64(content):016x}\n".encode())
    code = (
        "import resource, sys\n"
        "resource.setrlimit(resource.RLIMIT_AS, (512 << 20, 512 << 20))\n"
        "import cagd\n"
        "try:\n"
        "    cagd.PseudoEnergyTable.load(sys.argv[1])\n"
        "except ValueError as e:\n"
        "    print('ValueError:', e)\n"
    )
    env = dict(os.environ)
    out = subprocess.run([sys.executable, "-c", code, str(huge)], capture_output=True, text=True, env=env, timeout=60)
    assert out.returncode == 0, out.stderr
    assert out.stdout.startswith("ValueError:") and "6000" in out.stdout, out.stdout


def test_space_curves_have_torsion():
    helix = np.array([[math.cos(0.5 * k), math.sin(0.5 * k), 0.1 * k] for k in range(12)])
    c = cagd.interpolate(helix, "hosaka")
    tau = c.torsion(np.linspace(*c.parameter_range, 9)[2:-2])
    assert (tau > 0).all()  # a right-handed helix
    lac = cagd.log_aesthetic_space_curve(1.5, 1.2, 1.0)
    assert lac.dimension == 3
    s = cagd.space_typical_curve(1.5, 1.2, 1.0, 8)
    assert s["control_points"].shape == (9, 3)


def test_smoothing():
    p = table1()
    spline = cagd.smooth_curve(p, 0.0)  # λ = 0: interpolation
    assert np.allclose(spline.values, p, atol=1e-12)
    x = np.arange(8.0)
    a = np.column_stack([np.sin(x), np.cos(x)])
    curve, energy = cagd.elastic_space_curve(x, a, 0.05)
    assert curve.dimension == 3 and energy > 0


def test_arguments_of_the_wrong_type_are_type_errors_naming_them():
    p = table1()
    with pytest.raises(TypeError, match="points: complex"):
        cagd.interpolate(p + 0j, "cubic-b")
    with pytest.raises(TypeError, match="points: expected real numbers"):
        cagd.interpolate([["a", "b"], ["c", "d"]], "cubic-b")
    with pytest.raises(TypeError, match="closed: expected True or False"):
        cagd.interpolate(p, "cubic-b", closed="no")
    with pytest.raises(TypeError, match="method: expected a method name"):
        cagd.interpolate(p, 3)
    # One name where a list is expected is one name, not its characters.
    table = cagd.compare(p, methods="cubic-b")
    assert table["method"] == ["cubic-b"]


def _documented_objects():
    """The package, every public name and every method and property of the public classes."""
    yield "cagd", cagd
    for name in cagd.__all__:
        obj = getattr(cagd, name)
        yield name, obj
        if isinstance(obj, type):
            for attr, member in vars(obj).items():
                if not attr.startswith("_"):
                    yield f"{name}.{attr}", member


def test_every_docstring_example_runs():
    import doctest

    parser, runner = doctest.DocTestParser(), doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    examples = 0
    for name, obj in _documented_objects():
        doc = getattr(obj, "__doc__", None)
        if not doc or ">>>" not in doc:
            continue
        test = parser.get_doctest(doc, {"cagd": cagd, "np": np} | vars(cagd), name, None, 0)
        examples += len(test.examples)
        runner.run(test)
    result = runner.summarize(verbose=False)
    assert result.failed == 0, f"{result.failed} docstring example(s) failed (printed above)"
    assert examples >= 25, f"only {examples} docstring examples found"


def test_scalars_of_every_kind_give_scalar_shaped_results():
    c = cagd.interpolate(table1(), "cubic-b")
    expected = c.evaluate(0.5)
    for t in (np.float32(0.5), np.float64(0.5), np.array(0.5), 0.5):
        assert c.evaluate(t).shape == (2,) and np.array_equal(c.evaluate(t), expected)
        assert c.evaluate(t, derivatives=2).shape == (3, 2)
        assert isinstance(c.curvature(t), float)
    assert c.evaluate(np.int64(1)).shape == (2,) and c.evaluate(np.uint8(1)).shape == (2,)
    grid = np.full((2, 3), 0.5)
    assert c.evaluate(grid).shape == (2, 3, 2) and c.evaluate(grid, derivatives=1).shape == (2, 3, 2, 2)
    assert c.curvature(grid).shape == (2, 3)
    for bad in (0.5 + 1j, "0.5", None, True, [0.5, "a"]):
        with pytest.raises(TypeError, match="^t: expected real numbers"):
            c.evaluate(bad)
    with pytest.raises(ValueError, match="derivatives = 17; allowed 0..16"):
        c.evaluate(0.5, derivatives=17)


def test_no_nan_and_sizes_are_limited_before_allocating():
    with pytest.raises(ValueError, match=r"r0 = 1e\+100; allowed \(0, 1e60\]"):
        cagd.segment_measures(0.5, -0.3, 1e100, 1e100)
    d = cagd.segment_measures(0.5, -0.3, 1e60, 1e60)
    assert all(math.isfinite(v) for v in d.values() if isinstance(v, float))
    x = np.arange(3.0)
    with pytest.raises(ValueError, match="subdivisions = 1000000 gives 2000000 pieces for 3 points; at most 20000"):
        cagd.elastic_space_curve(x, np.column_stack([x, x]), 1.0, subdivisions=10**6)
    with pytest.raises(TypeError, match="^x: expected real numbers"):
        cagd.elastic_line(x + 1j, x, 1.0)


def test_messages_name_python_arguments_not_options_or_cpp_names():
    p = table1()
    for call in (lambda: cagd.interpolate(p, "s-spline", m=10**9), lambda: cagd.interpolate(p, "s-spline", start_tangnt=1.0),
                 lambda: cagd.interpolate(p, "cubic-b").evaluate(1e9), lambda: cagd.elastic_line([0.0, 0.0], [1.0, 2.0], 1.0)):
        with pytest.raises(ValueError) as e:
            call()
        assert "::" not in str(e.value) and "--" not in str(e.value), str(e.value)
    with pytest.raises(ValueError, match="start_tangnt is not a parameter of s-spline .*start_tangent"):
        cagd.interpolate(p, "s-spline", start_tangnt=1.0)
    # A leading C++ function name says nothing to a Python caller: the message starts with the matter.
    with pytest.raises(ValueError, match="^unknown method 's-spline-m3'"):
        cagd.compare(p, methods=["s-spline-m3"])
    with pytest.raises(ValueError, match=r"^x must increase strictly"):
        cagd.elastic_line([0.0, 0.0], [1.0, 2.0], 1.0)
    with pytest.raises(ValueError, match=r"^t = 1000000000 outside \[0, "):
        cagd.interpolate(p, "cubic-b").evaluate(1e9)



def test_version_is_the_projects():
    text = open(os.path.join(ROOT, "CMakeLists.txt"), encoding="utf-8").read()
    import re

    assert cagd.__version__ == re.search(r"project\(\s*cagd_repro\s+VERSION\s+([0-9.]+)", text).group(1)


def test_a_curve_is_called_like_a_scipy_spline():
    c = cagd.interpolate(table1(), "cubic-b")
    t = np.linspace(*c.parameter_range, 7).reshape(7, 1)
    jets = c.evaluate(t, derivatives=2)
    assert np.array_equal(c(t), c.evaluate(t)) and c(t).shape == (7, 1, 2)
    assert np.array_equal(c(t, 1), jets[..., 1, :]) and np.array_equal(c(t, nu=2), jets[..., 2, :])
    assert c(0.5, 1).shape == (2,)
    with pytest.raises(ValueError, match="derivatives = -1"):
        c(0.5, -1)


def test_repr_names_the_method_the_points_and_closedness():
    assert repr(cagd.interpolate(table1(), "s-spline")) == "<cagd.Curve s-spline through 13 points, open, dim=2, t=[0, 12]>"
    closed = cagd.interpolate(table1(), "cubic-b", closed=True)
    assert closed.closed and repr(closed).startswith("<cagd.Curve cubic-b through 13 points, closed, dim=2")
    assert repr(cagd.normalized_log_aesthetic_curve(-0.5, 1.0)).startswith("<cagd.Curve log-aesthetic, dim=2")


def test_every_kind_of_curve_pickles_to_the_same_curve():
    import pickle

    x = np.arange(5.0)
    curves = {
        "interpolate": cagd.interpolate(lifted(table1()), "s-spline", closed=True, m=3, end="natural"),
        "normalized_log_aesthetic_curve": cagd.normalized_log_aesthetic_curve(-0.5, 1.0),
        "log_aesthetic_curve": cagd.log_aesthetic_curve(1.5, c0=2.0, start=(1.0, -1.0)),
        "log_aesthetic_space_curve": cagd.log_aesthetic_space_curve(1.5, 1.2, 1.0, start=0.1),
        "typical_curve": cagd.typical_curve(-0.5, 1.0, 12, kind="scale-one")["curve"],
        "space_typical_curve": cagd.space_typical_curve(1.5, 1.2, 1.0, 9, start=0.1)["curve"],
        "elastic_space_curve": cagd.elastic_space_curve(x, np.column_stack([np.sin(x), np.cos(x)]), 0.1, subdivisions=2)[0],
    }
    for name, c in curves.items():
        again = pickle.loads(pickle.dumps(c))
        t = np.linspace(*c.parameter_range, 11)
        assert np.array_equal(again.evaluate(t, derivatives=2), c.evaluate(t, derivatives=2)), name
        assert repr(again) == repr(c) and again.method == c.method, name


def test_curves_run_in_their_methods_parameter_and_cubic_b_is_scipys_natural_spline():
    from scipy.interpolate import CubicSpline

    p = table1()
    chords = np.linalg.norm(np.diff(p, axis=0), axis=1)
    tau = np.concatenate([[0.0], np.cumsum(chords)])
    c = cagd.interpolate(p, "cubic-b")
    assert np.allclose(c.node_parameters, tau, rtol=0, atol=1e-12), "cubic-b states the chord-length parameter"
    ref = CubicSpline(tau, p, bc_type="natural")
    t = np.linspace(0.0, tau[-1], 501)
    for nu in range(4):
        assert np.max(np.abs(c(t, nu) - ref(t, nu))) <= 1e-12 * max(1.0, np.max(np.abs(ref(t, nu)))), f"derivative {nu}"
    # Closed: the periodic spline through the points and the first again.
    q = np.vstack([p, p[:1]])
    tau_c = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(q, axis=0), axis=1))])
    cc = cagd.interpolate(p, "cubic-b", closed=True)
    ref_c = CubicSpline(tau_c, q, bc_type="periodic")
    t = np.linspace(0.0, tau_c[-1], 501)
    for nu in range(4):
        # The third derivative is a step function: at the closing point scipy reads the first piece, we the last.
        tt = t if nu < 3 else t[:-1]
        assert np.max(np.abs(cc(tt, nu) - ref_c(tt, nu))) <= 1e-12 * max(1.0, np.max(np.abs(ref_c(tt, nu)))), f"closed, derivative {nu}"
    # The span parameter stays available: u = k at data point k.
    assert np.allclose(c.span_parameter(c.node_parameters), np.arange(len(p)), atol=1e-12)
    assert np.allclose(c.method_parameter(np.arange(len(p))), tau, atol=1e-12)
    # Arc length for the curvature-profile spline: each span's τ-length is its length.
    cp = cagd.interpolate(p[:6], "curvature-profile")
    assert abs(cp.node_parameters[-1] - cp.arc_length()) <= 1e-9 * cp.arc_length()
    with pytest.raises(ValueError, match="only an interpolant"):
        cagd.normalized_log_aesthetic_curve(-0.5, 1.0).span_parameter(0.5)


def test_scipy_curves_come_in_exactly_and_ours_go_out_to_scipy():
    from scipy.interpolate import CubicSpline, PPoly, make_interp_spline, splev, splprep

    p = table1()
    tau = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(p, axis=0), axis=1))])
    ours = cagd.interpolate(p, "cubic-b")
    t = np.linspace(0.0, tau[-1], 401)
    # CubicSpline natural is cubic-b: measured through from_ppoly, the same curve and measures.
    natural = cagd.Curve.from_ppoly(CubicSpline(tau, p, bc_type="natural"))
    for nu in range(3):
        assert np.max(np.abs(natural(t, nu) - ours(t, nu))) <= 1e-12 * max(1.0, np.max(np.abs(ours(t, nu))))
    assert abs(natural.arc_length() - ours.arc_length()) <= 1e-12 * ours.arc_length()
    assert np.max(np.abs(natural.curvature(t) - ours.curvature(t))) <= 1e-10 * np.max(np.abs(ours.curvature(t)))
    # Not-a-knot, periodic, quintic interpolation and splprep: each equals scipy's own evaluation.
    q = np.vstack([p, p[:1]])
    tau_c = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(q, axis=0), axis=1))])
    for name, spline, ts in [
        ("not-a-knot", CubicSpline(tau, p), t),
        ("periodic", CubicSpline(tau_c, q, bc_type="periodic"), np.linspace(0.0, tau_c[-1], 401)),
        ("quintic", make_interp_spline(tau, p, k=5), t),
    ]:
        c = cagd.Curve.from_ppoly(spline) if hasattr(spline, "x") else cagd.Curve.from_bspline(spline)
        for nu in range(3):
            ref = spline(ts, nu)
            assert np.max(np.abs(c(ts, nu) - ref)) <= 1e-11 * max(1.0, np.max(np.abs(ref))), f"{name}, derivative {nu}"
    tck, u = splprep(p.T, s=0)
    c = cagd.Curve.from_bspline(tck)
    uu = np.linspace(0.0, 1.0, 301)
    assert np.max(np.abs(c(uu) - np.array(splev(uu, tck)).T)) <= 1e-12 * np.max(np.abs(p))
    assert np.max(np.abs(c(u) - p)) <= 1e-12 * np.max(np.abs(p))
    # Ours to scipy: the quartic S-spline as a PPoly, and the pickled scipy curve again.
    s_spline = cagd.interpolate(p, "s-spline")
    pp = PPoly(*s_spline.to_ppoly())
    ts = np.linspace(*s_spline.parameter_range, 401)
    assert pp.c.shape[0] == 5 and np.max(np.abs(pp(ts) - s_spline(ts))) <= 1e-12 * np.max(np.abs(p))
    import pickle

    assert np.array_equal(pickle.loads(pickle.dumps(natural))(t), natural(t))
    with pytest.raises(ValueError, match="shape"):
        cagd.Curve.from_ppoly((np.zeros((4, 3)), np.arange(4.0)))


def test_bridges_share_one_degree_limit_accurate_at_it_and_refuse_beyond():
    """from_bspline and from_ppoly take degrees up to 31 (the curve document's limit), accurate to
    1e-10 of the coefficients there; beyond it, and for arguments of the wrong type or range, a
    ValueError or TypeError naming the argument, never pybind11's cast error."""
    from scipy.interpolate import BSpline, PPoly
    import pickle

    rng = np.random.default_rng(5)
    k = 31
    b = BSpline(np.r_[[0.0] * (k + 1), [1.0] * (k + 1)], rng.uniform(-1, 1, (k + 1, 2)), k)
    u = np.linspace(0, 1, 601)
    assert np.max(np.abs(cagd.Curve.from_bspline(b)(u) - b(u))) <= 1e-10
    c = rng.uniform(-1, 1, (k + 1, 3, 2))
    x = np.array([0.0, 1.0, 2.0, 3.0])
    for i in range(2):  # continuous: each piece starts where the previous ends
        c[k, i + 1] = sum(c[m, i] * (x[i + 1] - x[i]) ** (k - m) for m in range(k + 1))
    pp = PPoly(c, x)
    u = np.linspace(0, 3, 601)
    assert np.max(np.abs(cagd.Curve.from_ppoly(pp)(u) - pp(u))) <= 1e-10 * np.max(np.abs(c))
    t = np.r_[[0.0] * 4, [1.0] * 4]
    with pytest.raises(ValueError, match=r"k = 40 is outside \[0, 31\]"):
        cagd.Curve.from_bspline((np.r_[[0.0] * 41, [1.0] * 41], np.zeros((41, 2)), 40))
    with pytest.raises(ValueError, match=r"k = 1099511627776 is outside"):
        cagd.Curve.from_bspline((t, np.zeros((4, 2)), 2**40))
    with pytest.raises(TypeError, match="k: expected an integer, got str"):
        cagd.Curve.from_bspline((t, np.zeros((4, 2)), "3"))
    with pytest.raises(ValueError, match="c: PPoly coefficients of degree 1000"):
        cagd.Curve.from_ppoly((np.zeros((1001, 1, 2)), np.array([0.0, 1.0])))
    curve = cagd.interpolate(np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]]), "cubic-b")
    with pytest.raises(ValueError, match="cagd.methods made a list, not a cagd.Curve"):
        cagd.Curve.__new__(cagd.Curve).__setstate__(("methods", (), {}, None))
    with pytest.raises(ValueError, match="not a cagd.Curve's pickle"):
        cagd.Curve.__new__(cagd.Curve).__setstate__(("no_such_function", (), {}, None))
    assert pickle.loads(pickle.dumps(curve))(0.5).tolist() == curve(0.5).tolist()


def test_surfaces_equal_cpp(cpp):
    gx, gy = np.array([0.0, 1.0, 2.5, 3.0, 4.2]), np.array([0.0, 0.5, 1.5, 2.0])
    z = np.array([[math.sin(x) * math.cos(y) + 0.1 * a * b for b, y in enumerate(gy)] for a, x in enumerate(gx)])
    surfaces = {"cartesian": cagd.cartesian_surface(gx, gy, z), "net": cagd.elastic_net_surface(gx, gy, z, 0.05),
                "plate": cagd.plate_smoothing(gx, gy, z, 0.05), "boundary_plate": cagd.boundary_plate_smoothing(gx, gy, z, 0.05, energy="no_twist", m=2)}
    at = np.array([[0.0, 0.0], [0.7, 1.1], [2.5, 0.5], [3.9, 1.95], [4.2, 2.0]])
    for name, s in surfaces.items():
        for a in (0, 1):
            for b in (0, 1):
                values = s.evaluate(at[:, 0], at[:, 1], a=a, b=b)  # vectorised over the points
                for k in range(len(at)):
                    assert close(values[k], cpp[f"surface.{name}.{k}.{a}{b}"]), (name, k, a, b)
    bottom = np.array([[0, 0, 0], [1, 0, 0.3], [2, 0, 0.1], [3, 0, 0]], float)
    left = np.array([[0, 0, 0], [0, 1, 0.5], [0, 2, 0]], float)
    top = np.array([[0, 2, 0], [1, 2.2, 0.4], [2, 2.1, 0.2], [3, 2, 0]], float)
    right = np.array([[3, 0, 0], [3, 1, -0.5], [3, 2, 0]], float)
    coons = cagd.coons_patch(bottom, left, top, right)
    corners = np.array([[[[[math.sin(1.0 + k + 2 * l + 3 * i + 5 * j + 7 * d) for d in range(3)] for j in range(2)] for i in range(2)] for l in range(2)] for k in range(2)])
    tensor = cagd.tensor_patch(corners)
    uv = np.array([[0.0, 0.0], [0.3, 0.8], [0.5, 0.5], [1.0, 0.25]])
    for name, p in {"coons": coons, "tensor": tensor}.items():
        for a in (0, 1):
            for b in (0, 1):
                values = p.evaluate(uv[:, 0], uv[:, 1], a=a, b=b)
                assert values.shape == (4, 3)
                for k in range(4):
                    for d in range(3):
                        assert close(values[k, d], cpp[f"surface.{name}.{k}.{a}{b}.{d}"]), (name, k, a, b, d)
    ex, ey = 0.5 * np.arange(6), np.arange(5.0)
    ez = np.array([[math.cos(x) + 0.05 * a * b * b for b in range(5)] for a, x in enumerate(ex)])
    window = cagd.window_smoothing(ex, ey, ez, 0.3)
    for k in range(3):
        for a in (0, 1):
            for b in (0, 1):
                assert close(float(window.evaluate(0.3 + 0.8 * k, 0.7 + 1.1 * k, a=a, b=b)), cpp[f"surface.window.{k}.{a}{b}"]), ("window", k, a, b)
    # Boundary-conforming synthesis (m = 2) and joining beyond x0 = 2.
    x = 0.5 * np.arange(5)
    lower = np.column_stack([x, 0.2 * np.sin(x), 0.1 * x * x])
    upper = np.column_stack([x, 1.5 + 0.3 * x, 1.0 - 0.2 * x])
    strip = cagd.boundary_surface(lower, upper, [0.3, -0.1], [-0.2, 0.05], m=2)
    y0, y1 = strip.y_range(2.0)
    far = np.column_stack([y0 + (y1 - y0) * np.arange(4) / 3.0, 3.0 + 0.1 * np.arange(4), 0.5 - 0.1 * np.arange(4)])
    joined = strip.join(2.0, far, [0.2, 0.0])
    for name, s, at in (("strip", strip, [(0.3, 0.5), (1.0, 1.2), (1.7, 0.9), (2.0, 1.4)]), ("joined", joined, [(2.0, 0.5), (2.4, 1.0), (2.9, 1.6)])):
        at = np.array(at)
        for a in (0, 1):
            for b in (0, 1):
                values = s.evaluate(at[:, 0], at[:, 1], a=a, b=b)
                for k in range(len(at)):
                    assert close(values[k], cpp[f"surface.{name}.{k}.{a}{b}"]), (name, k, a, b)
    # Grids broadcast as numpy does: a (3, 1) column against a (4,) row gives (3, 4) points.
    grid = coons.evaluate(np.linspace(0, 1, 3)[:, None], np.linspace(0, 1, 4))
    assert grid.shape == (3, 4, 3) and np.allclose(grid[:, 0], coons.evaluate(np.linspace(0, 1, 3), 0.0))
    assert surfaces["cartesian"].evaluate(np.array([[0.7]]), 1.1).shape == (1, 1)
    with pytest.raises(ValueError, match="corners: expected shape"):
        cagd.tensor_patch(np.zeros((2, 2, 2, 3, 3)))
    with pytest.raises(ValueError, match="energy = 'stiff'"):
        cagd.plate_smoothing(gx, gy, z, 0.05, energy="stiff")
    with pytest.raises(TypeError, match="^u: expected real numbers"):
        coons.evaluate("a", 0.5)


def test_every_public_function_and_class_has_an_example_and_every_member_a_docstring():
    missing_example, missing_doc = [], []
    for name in cagd.__all__:
        obj = getattr(cagd, name)
        if name in ("__version__", "NoSolution"):
            assert (obj.__doc__ or "") != "", name
            continue
        if ">>>" not in (obj.__doc__ or "") and not (isinstance(obj, type) and "(its example)" in obj.__doc__ or "(their examples)" in (obj.__doc__ or "")):
            missing_example.append(name)
        if isinstance(obj, type):
            for attr, member in vars(obj).items():
                doc = (getattr(member, "__doc__", None) or "").strip()
                if doc.startswith(attr + "("):  # pybind11 puts the signature first: the text follows it
                    doc = doc.split("\n", 1)[1].strip() if "\n" in doc else ""
                if not attr.startswith("_") and len(doc) < 10:
                    missing_doc.append(f"{name}.{attr}")
    assert not missing_example, f"no example in the docstring of {missing_example}"
    assert not missing_doc, f"no docstring: {missing_doc}"


def test_at_arc_length_inverts_the_arc_length():
    lac = cagd.normalized_log_aesthetic_curve(-0.5, 1.0)  # its parameter is arc length
    s = np.linspace(0.0, 1.0, 7)
    assert np.allclose(lac.at_arc_length(s), s, atol=1e-12)
    c = cagd.interpolate(table1(), "hosaka")
    t = c.at_arc_length(np.array([[0.25], [0.5]]) * c.arc_length())
    assert t.shape == (2, 1) and 0.0 < t[0, 0] < t[1, 0] < c.parameter_range[1]
    with pytest.raises(ValueError, match="the curve's length"):
        c.at_arc_length(2 * c.arc_length())


def end_of_range_walk(n, seed, max_turn):
    """n points of a walk of unit steps, each turning by an angle uniform in [-max_turn, max_turn]
    (pi: a uniformly random direction)."""
    heading = np.cumsum(np.random.default_rng(seed).uniform(-max_turn, max_turn, n - 1))
    steps = np.column_stack([np.cos(heading), np.sin(heading)])
    return np.vstack([[0.0, 0.0], np.cumsum(steps, axis=0)])


# The Newton methods take walks that turn by at most 1.2 rad a step, where their curves exist (as
# tests/methods/test_end_of_range.cpp): on hairpins they end in no_convergence after many steps.
NEWTON_METHODS = {"curvature-profile", "spiro"}


@pytest.mark.parametrize("n", [10, 1000, 100000])
def test_every_configuration_evaluates_at_both_ends_of_its_parameter_range(n):
    # evaluate() works at both ends of parameter_range and gives the first and last point there
    # (closed: the first point again), for every configuration (presets, else the method).
    configurations = [(preset, m["name"], m["claims"]) for m in cagd.methods() for preset in (m["presets"] or [m["name"]])]
    checked = 0
    for name, method, claims in configurations:
        count = min(n, claims["max_points"]) if claims["max_points"] > 0 else n
        p = end_of_range_walk(count, 7, 1.2 if method in NEWTON_METHODS else math.pi)
        extent = float(np.linalg.norm(p.max(axis=0) - p.min(axis=0)))
        for closed in (False, True):
            if closed and not claims["supports_closed"]:
                continue
            r = cagd.interpolate_result(p, name, closed=closed)
            if not r.ok:
                assert r.message, f"{name} closed={closed}: a numerical outcome says why"
                continue
            a, b = r.curve.parameter_range
            ends = r.curve.evaluate(np.array([a, b]))
            assert np.all(np.isfinite(ends)), name
            last = p[0] if closed else p[-1]
            assert np.linalg.norm(ends[0] - p[0]) <= 1e-8 * extent, f"{name} closed={closed} at t = {a!r}"
            assert np.linalg.norm(ends[1] - last) <= 1e-8 * extent, f"{name} closed={closed} at t = {b!r}"
            checked += 1
    assert checked >= len(cagd.methods())


def test_a_parameter_of_the_wrong_python_type_is_a_type_error_naming_it():
    p = table1()
    with pytest.raises(TypeError, match=r"^m: expected an integer, got str '2'"):
        cagd.interpolate(p, "s-spline", m="2")
    with pytest.raises(TypeError, match=r"^m_vector: expected a str, got list"):
        cagd.interpolate(p, "s-spline", m_vector=["2", "3"])
    # The right types still work, numpy's numbers included.
    assert cagd.interpolate(p, "s-spline", m=np.int64(2)).dimension == 2


def test_help_shows_readable_signatures():
    import inspect
    text = str(inspect.signature(cagd.interpolate))
    assert "Union[" not in text and len(text) < 120, text
    assert text.startswith("(points: '_npt.ArrayLike', method: 'str'"), text


def test_torsion_is_nan_where_undefined_at_natural_ends():
    t = 0.7 * np.arange(9)
    helix = np.column_stack([np.cos(t), np.sin(t), 0.21 * np.arange(9)])
    c = cagd.interpolate(helix, "cubic-b")
    a, b = c.parameter_range
    tau = c.torsion(np.array([a, 0.5 * (a + b), b]))
    assert math.isnan(tau[0]) and math.isnan(tau[2]), tau
    assert abs(tau[1] - 0.3 / 1.09) < 0.05, tau


def test_peer_curve_runs_an_adapter_and_names_every_failure():
    # The launcher of tests/data/peers (a shell script speaking the peer protocol): "echoer" draws
    # the polygon through the points, refuses configuration "refuse"; "absent" is not installed.
    peers = os.path.join(ROOT, "tests", "data", "peers")
    p = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 1.0]])
    c = cagd.peer_curve(p, "echoer:a", peers=peers)
    assert c.parameter_range == (0.0, 2.0)
    assert np.array_equal(c(np.array([0.0, 1.0, 2.0])), p)
    assert np.allclose(c(0.5), [0.5, 1.0], rtol=0, atol=1e-15)
    closed = cagd.peer_curve(p, "echoer:a", closed=True, peers=peers)
    assert closed.parameter_range == (0.0, 3.0) and np.array_equal(closed(3.0), p[0])
    assert np.array_equal(pickle.loads(pickle.dumps(c))(0.5), c(0.5))
    with pytest.raises(cagd.NoSolution, match="echoer:refuse: refused by the test peer"):
        cagd.peer_curve(p, "echoer:refuse", peers=peers)
    with pytest.raises(RuntimeError, match="absent: not installed here"):
        cagd.peer_curve(p, "absent:a", peers=peers)
    with pytest.raises(ValueError, match="name: \"echoer\" is not PEER:CONFIGURATION"):
        cagd.peer_curve(p, "echoer", peers=peers)
    with pytest.raises(ValueError, match="peers: "):
        cagd.peer_curve(p, "echoer:a", peers=os.path.join(ROOT, "tests"))
    with pytest.raises(ValueError, match="no peer"):
        cagd.peer_curve(p, "nobody:a", peers=os.path.join(ROOT, "peers"))
    with pytest.raises(TypeError, match="closed"):
        cagd.peer_curve(p, "echoer:a", closed="yes", peers=peers)
    with pytest.raises(ValueError, match="is not a name"):
        cagd.peer_curve(p, "echoer:two words", peers=peers)


def test_compare_measures_peers_beside_the_methods():
    # The test launcher's echoer draws the polygon: its length is the polygon's, it bends nowhere, and
    # moving the middle point moves the two spans beside it; its "refuse" configuration has no curve.
    peers = os.path.join(ROOT, "tests", "data", "peers")
    p = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 1.0], [4.0, 3.0], [6.0, 0.0]])
    t = cagd.compare(p, methods=["cubic-b", "echoer:polygon"], peers=peers)
    assert t["method"] == ["cubic-b", "echoer:polygon"]
    assert t["status"] == ["ok", "ok"]
    perimeter = float(np.sum(np.linalg.norm(np.diff(p, axis=0), axis=1)))
    assert abs(t["length"][1] - perimeter) <= 1e-12 * perimeter
    assert t["bending_energy"][1] == 0.0
    assert t["locality_footprint"][1] == 2
    assert list(np.ma.getmaskarray(t["shared_seconds"])) == [False, True]  # a peer shares no tables
    # A peer that gives samples only: its pieces approximate its curve, and the note gives the bound.
    approximate = cagd.compare(p, methods=["echoer:approximate"], peers=peers)
    assert approximate["status"] == ["ok"]
    assert approximate["note"] == [
        "its pieces approximate echoer:approximate's curve within 0.25 (the peer gives samples only)"]
    refused = cagd.compare(p, methods=["echoer:refuse"], peers=peers)
    assert refused["status"] == ["no result"]
    assert refused["note"] == ["echoer: refused by the test peer"]
    with pytest.raises(RuntimeError, match="absent: not installed here"):
        cagd.compare(p, methods=["absent:a"], peers=peers)
    with pytest.raises(ValueError, match="nobody:x"):
        cagd.compare(p, methods=["nobody:x"], peers=peers)
    with pytest.raises(ValueError, match="peers: "):
        cagd.compare(p, methods=["echoer:polygon"], peers=os.path.join(ROOT, "tests"))


def _bezier_values(pieces, breaks, t):
    # The pieces (K, degree + 1, 2) on their breaks, evaluated at the parameters t (de Casteljau).
    k = np.clip(np.searchsorted(breaks, t, side="right") - 1, 0, len(pieces) - 1)
    u = ((t - breaks[k]) / (breaks[k + 1] - breaks[k]))[:, None]
    b = pieces[k].copy()
    for r in range(b.shape[1] - 1, 0, -1):
        b = (1 - u[:, :, None]) * b[:, :r] + u[:, :, None] * b[:, 1:r + 1]
    return b[:, 0]


@pytest.mark.skipif(not (shutil.which("spline") and shutil.which("node")),
                    reason="plotutils's spline or Node.js is not installed (scripts/install-deps.sh peers)")
def test_plotutils_pieces_lie_within_their_bound_of_splines_own_samples():
    # The plotutils adapter recovers each span from spline's samples at quarters (thirds at tension
    # 0) and, for a spline under tension, writes quintic Hermite pieces with a bound (docs/peers.md).
    # spline's own samples at 1/240 of every span, run here directly, lie within that bound of the
    # pieces (the bound is a remainder estimate, so it must hold everywhere), and the cubic's pieces
    # are spline's curve to rounding.
    rng = np.random.default_rng(7)
    for trial in range(6):
        n, closed = int(rng.integers(3, 12)), trial % 2 == 1
        p = rng.uniform(-5.0, 5.0, (n, 2))
        q = np.vstack([p, p[:1]]) if closed else p
        spans, per = len(q) - 1, 240
        diagonal = float(np.linalg.norm(p.max(axis=0) - p.min(axis=0)))
        for configuration, args in [("cubic", []), ("tension-1", ["-T", "1"]), ("tension-5", ["-T", "5"])]:
            request = f"curve {configuration} {'closed' if closed else 'open'} {n} 2\n" + "".join(
                f"{x!r} {y!r}\n" for x, y in p)
            # The adapter itself (it needs no npm package, so peers/run's check of peers/node_modules,
            # absent before make benchmark, does not apply).
            answer = subprocess.run(["node", os.path.join(ROOT, "peers", "plotutils", "adapter.mjs")],
                                    input=request.encode(), capture_output=True, check=True).stdout
            document = json.loads(answer)
            assert "error" not in document, document
            dense = subprocess.run(["spline", "-d", "2", "-a", "-n", str(per * spans), "-s", "-O", "d", *args]
                                   + (["-p"] if closed else []),
                                   input="".join(f"{x!r} {y!r}\n" for x, y in q).encode(),
                                   capture_output=True, check=True).stdout
            samples = np.frombuffer(dense, dtype=np.float64).reshape(-1, 2)
            t = np.arange(per * spans + 1) / per
            ours = _bezier_values(np.array(document["pieces"]), np.array(document["breaks"]), t)
            error = float(np.linalg.norm(ours - samples, axis=1).max())
            if configuration == "cubic":
                assert document["exact"] and error <= 1e-13 * diagonal, (configuration, error)
            else:
                assert not document["exact"]
                bound = document["max_distance"]
                assert 0.0 < bound <= 1e-8 * diagonal, (configuration, bound, diagonal)
                assert error <= bound + 1e-13 * diagonal, (configuration, error, bound)
                assert error >= 0.01 * bound, (configuration, error, bound)  # not a loose bound
