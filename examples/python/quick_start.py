"""cagd from Python: interpolate points, evaluate the curve like a scipy spline, measure it, and
compare every method on the same points. Runs from any working directory and writes nothing.
Type-checked with `mypy --strict` (ctest python.types); run with `python3 quick_start.py`."""
import pickle

import numpy as np

import cagd


def main() -> None:
    points = np.array([[0.0, 0.0], [1.0, 0.8], [2.0, 0.2], [3.0, 1.0], [4.0, 0.4]])
    curve = cagd.interpolate(points, "s-spline", m=3)
    print(curve)
    t0, t1 = curve.parameter_range
    t = np.linspace(t0, t1, 5)
    print("positions", curve(t).round(4).tolist())
    print("first derivatives", curve(t, 1).round(4).tolist())
    print("length", round(curve.arc_length(), 6), "bending energy", round(curve.bending_energy(), 6))
    again = pickle.loads(pickle.dumps(curve))
    assert np.array_equal(again(t), curve(t))
    table = cagd.compare(points, methods=["cubic-b", "pseudo-spline", "s-spline-m4"])
    for name, length in zip(table["method"], table["length"]):
        print(f"{name:>16}: length {float(length):.6f}")
    measures = cagd.pseudo_energy(0.3, -0.5)
    print("J(0.3, -0.5) =", round(float(measures["pseudo_energy"]), 6), "version", cagd.__version__)


if __name__ == "__main__":
    main()
