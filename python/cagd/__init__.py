"""cagd — interpolating curves from five Japanese CAGD papers (cagd-repro), from Python.

Every value is computed by the C++ library (the same code as the ``cagd`` command and the
reproduction harness); this package only converts NumPy arrays and names.

Methods::

    methods()                       the registry: name, paper, parameters, presets, claims
    interpolate(points, method, closed=False, **params) -> Curve
    interpolate_result(...)         -> Interpolation (status, message, curve, method's report)

Curves (``Curve``)::

    evaluate(t, derivatives=0)      positions t.shape + (dim,) or jets t.shape + (k + 1, dim)
    c(t, nu=0)                      the nu-th derivative, as scipy's splines
    curvature(t), torsion(t)        signed κ for planar curves, |κ| in space; τ (space)
    arc_length(), area(), bending_energy(), parameter_range, node_parameters, breakpoints()
    span_parameter(t), method_parameter(u)   an interpolant's parameter (the method's own) ↔ span index

The rest of the library::

    compare(points, closed=False, methods=None)   the measures of ``cagd compare`` as arrays
    pseudo_energy(theta0, theta1, method="fast"), segment_measures(...), PseudoEnergyTable
    log_aesthetic_curve, normalized_log_aesthetic_curve, log_aesthetic_space_curve
    typical_curve, space_typical_curve            typical Bézier curves (typical_curves)
    elastic_line, smooth_curve, elastic_space_curve   Hosaka's smoothing (section 6)
    tensor_patch, coons_patch, cartesian_surface      Hosaka's surfaces (eq 27, 28, 30)
    boundary_plate_smoothing,
    boundary_surface, BoundaryConformingSurface.join  synthesis between boundaries, joining (eq 31-43)
    elastic_net_surface, plate_smoothing              Hosaka's surface smoothing (eq 53-58)
    boundary_plate_smoothing, window_smoothing        its methods (ii) and approximation 1 (eq 31, 59, 60)

Errors: a wrong type raises ``TypeError`` naming the argument (complex points, a string for
``closed``); bad values raise ``ValueError`` with the library's message (naming the value and what
is allowed); a failed write (``PseudoEnergyTable.save``) raises ``OSError`` and keeps the old
file. A numerical outcome for valid input — no solution, no convergence (e.g. the
curvature-profile Newton) — raises ``cagd.NoSolution`` (a ``RuntimeError``) from the functions that
return a result; ``interpolate_result`` returns it as a status instead.

Parameters of a method are given as keyword arguments, with ``_`` for ``-`` in their names; they
are checked by the registry exactly as the command line's options are, and errors name them as
Python arguments.

Example (every example in these docstrings runs as a doctest in the package's tests)::

    >>> import numpy as np, cagd
    >>> p = np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0]])
    >>> c = cagd.interpolate(p, "s-spline", m=3, end="bessel")
    >>> c
    <cagd.Curve s-spline through 4 points, open, dim=2, t=[0, 3]>
    >>> c.evaluate(3.0)
    array([3., 1.])
    >>> c.evaluate([0.0, 1.5], derivatives=1).shape
    (2, 2, 2)
    >>> round(c.arc_length(), 6)
    4.45534
"""
# Annotations stay as written (PEP 563), so that help() shows "points: '_npt.ArrayLike'" and not
# numpy's expanded Union of every array-like type.
from __future__ import annotations

from typing import Any, Dict, Iterable, List, Union

import numpy as _np
import numpy.typing as _npt

from ._cagd import (  # noqa: F401  (re-exported)
    __version__,
    BoundaryConformingSurface,
    BoundaryPlateSurface,
    CartesianSurface,
    Curve,
    EdgePatch,
    JoinedSurface,
    TensorPatch,
    boundary_plate_smoothing,
    boundary_surface,
    cartesian_surface,
    coons_patch,
    elastic_net_surface,
    plate_smoothing,
    tensor_patch,
    window_smoothing,
    ExplicitSpline,
    Interpolation,
    NoSolution,
    PseudoEnergyTable,
    elastic_line,
    elastic_space_curve,
    log_aesthetic_curve,
    log_aesthetic_space_curve,
    normalized_log_aesthetic_curve,
    pseudo_energy,
    segment_measures,
    smooth_curve,
    space_typical_curve,
    typical_curve,
    _curve_from_bspline,
    _curve_from_ppoly,
)
from . import _cagd

__all__ = [
    "__version__", "Curve", "ExplicitSpline", "Interpolation", "NoSolution", "PseudoEnergyTable",
    "methods", "interpolate", "interpolate_result", "compare", "peer_curve",
    "pseudo_energy", "segment_measures",
    "log_aesthetic_curve", "normalized_log_aesthetic_curve", "log_aesthetic_space_curve",
    "typical_curve", "space_typical_curve",
    "elastic_line", "smooth_curve", "elastic_space_curve",
    "TensorPatch", "EdgePatch", "CartesianSurface", "tensor_patch", "coons_patch", "cartesian_surface",
    "BoundaryConformingSurface", "JoinedSurface", "boundary_surface",
    "BoundaryPlateSurface", "boundary_plate_smoothing", "window_smoothing",
    "elastic_net_surface", "plate_smoothing",
]


def methods() -> List[Dict[str, Any]]:
    """The registry of interpolation methods, in the order of the tables: a list of dicts with
    name, aliases, paper, source, summary, parameters (name, type, default, domain, help),
    presets (the comparison's configurations) and claims (at the default parameters).

    >>> [m["name"] for m in methods()][:3]
    ['pseudo-spline', 'cubic-a', 'cubic-b']
    >>> sorted(methods()[0])
    ['aliases', 'claims', 'name', 'paper', 'parameters', 'presets', 'source', 'summary']
    """
    return _cagd._methods()


def _points(points: _npt.ArrayLike) -> "_npt.NDArray[_np.float64]":
    raw = _np.asarray(points)
    if _np.iscomplexobj(raw):
        raise TypeError("points: complex numbers are not coordinates; give real (n, 2) or (n, 3) values")
    if raw.dtype.kind not in "biuf":
        raise TypeError(f"points: expected real numbers, got an array of {raw.dtype}")
    a = raw.astype(float)
    if a.ndim != 2 or a.shape[1] not in (2, 3):
        raise ValueError(f"points: expected an (n, 2) or (n, 3) array, got shape {a.shape}")
    return a


def _flag(value: object, name: str) -> bool:
    """A bool argument: True, False (or numpy's bool); anything else is a TypeError, never truthy."""
    if isinstance(value, (bool, _np.bool_)):
        return bool(value)
    raise TypeError(f"{name}: expected True or False, got {value!r}")


def _names(value: Union[None, str, Iterable[str]], name: str) -> List[str]:
    """A list of names; one string is read as one name (never as its characters)."""
    if value is None:
        return []
    if isinstance(value, str):
        return [value]
    names: List[str] = list(value)
    for n in names:
        if not isinstance(n, str):
            raise TypeError(f"{name}: expected names (str), got {n!r}")
    return names


def interpolate_result(points: _npt.ArrayLike, method: str, closed: bool = False, **params: Any) -> Interpolation:
    """The interpolation with its outcome: an ``Interpolation`` whose ``status`` is "ok" (and
    ``curve`` the curve) or the numerical outcome ("no_solution", "no_convergence") with its
    ``message``; ``report`` and ``quantities`` hold what the method reports (e.g. the
    curvature-profile Newton history, the pseudo-spline's table length and area).
    Bad input raises ValueError (a wrong type TypeError).

    >>> import numpy as np
    >>> p = np.array([[0.0, 0.0], [1.0, 0.0], [2.0, 1.0], [3.0, 1.0]])
    >>> r = interpolate_result(p, "curvature-profile")
    >>> r.ok, r.status
    (True, 'ok')
    >>> interpolate_result(p, "s-spline", m=-3)
    Traceback (most recent call last):
    ...
    ValueError: s-spline: m '-3': out of range; allowed: integer in [0, 1000]
    """
    if not isinstance(method, str):
        raise TypeError(f"method: expected a method name (str), got {method!r}")
    return _cagd._interpolate_result(_points(points), method, _flag(closed, "closed"), **params)


def interpolate(points: _npt.ArrayLike, method: str, closed: bool = False, **params: Any) -> Curve:
    """The curve of ``method`` (a name of ``methods()`` or a preset such as "s-spline-m2") through
    ``points`` ((n, 2) or (n, 3)). Raises ValueError for bad input and NoSolution when the method
    finds no curve for valid input.

    >>> import numpy as np
    >>> c = interpolate(np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]]), "cubic-b", closed=True)
    >>> a, b = c.parameter_range
    >>> bool(np.allclose(c.evaluate(a), c.evaluate(b)))
    True
    """
    r = interpolate_result(points, method, closed, **params)
    if r.curve is None:
        raise NoSolution(f"{method}: {r.message}")
    return r.curve


def compare(points: _npt.ArrayLike, closed: bool = False, methods: Union[None, str, Iterable[str]] = None, locality: bool = True, threads: int = 0,
            peers: str = "peers", programs: str = "build/peers") -> Dict[str, Any]:
    """Every method (or the named configurations) on the same planar or space points, measured as
    by ``cagd compare``: a dict of arrays, one entry per configuration (``methods``: a list of
    names, or one name). ``method``, ``status`` ("ok", "not applicable", "refused", "no result",
    "cusp", "loops": a closed curve measured but flagged, its turning number or length beside its
    polygon's in the note, "failed": a defect of the method, its message the note) and ``note`` are lists of str; each measure
    (length, area, pseudo_energy, bending_energy, curvature_sign_changes, max_abs_curvature,
    max_abs_curvature_derivative, overshoot, spans, locality_footprint, seconds, max_abs_torsion,
    shared_seconds) is a ``numpy.ma.MaskedArray``, masked where the measure does not exist (method
    not applicable, no result, a cusp's curvature, an open curve's area; area and
    curvature_sign_changes for space points, max_abs_torsion for planar ones), never NaN.
    ``seconds`` times one construction; ``shared_seconds`` what the configuration's builds share
    and load once before it (the pseudo-spline's tables), timed apart so that neither is charged
    to whichever configuration runs first.

    ``methods`` may name other libraries' configurations as PEER:CONFIGURATION ("gsl:cspline",
    "d3-shape:natural"; docs/methods.md lists them), run by their adapters under the repository's
    ``peers`` folder as ``peer_curve`` runs them and measured as the methods are (``seconds``: the
    adapter's whole run); then only the named registry configurations are compared beside them.
    ValueError for a name the folder's manifest lacks; RuntimeError when a named peer is not
    installed here.

    >>> import numpy as np
    >>> t = compare(np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0]]), methods=["cubic-b", "pseudo-spline"])
    >>> t["method"], t["status"]
    (['cubic-b', 'pseudo-spline'], ['ok', 'ok'])
    >>> t["length"].round(6)
    masked_array(data=[4.423849, 4.493685],
                 mask=[False, False],
           fill_value=1e+20)
    """
    raw = _cagd._compare(_points(points), _flag(closed, "closed"), _names(methods, "methods"), _flag(locality, "locality"), int(threads),
                         str(peers), str(programs))
    out: Dict[str, Any] = {}
    for name, value in raw.items():
        if isinstance(value, tuple):
            values, valid = value
            out[name] = _np.ma.MaskedArray(values, mask=~valid)  # type: ignore[no-untyped-call]  # (numpy.ma has no annotations)
        else:
            out[name] = value
    return out


def peer_curve(points: _npt.ArrayLike, name: str, closed: bool = False, peers: str = "peers",
               programs: str = "build/peers") -> Curve:
    """The curve another library draws through `points`, run as its users run it by its adapter
    under the repository's peers/ folder (docs/peers.md), as `cagd peers` runs it: `name` is
    PEER:CONFIGURATION ("d3-shape:natural", "gsl:cspline", "metapost:hobby"; docs/methods.md lists
    them), `programs` the folder where CMake built the C and C++ adapters. The curve is the peer's
    own exact pieces, and every measure of cagd applies to it; where the peer gives samples only
    (plotutils's tension splines), it is its adapter's approximation of the peer's curve, within
    the bound ``compare`` states in the row's note (docs/peers.md).

    ValueError for a name or a folder that is not one; RuntimeError when the peer is not installed
    here (the message says what is missing); cagd.NoSolution when the peer refuses the points or
    fails on them, with its message.

    From the repository's top, with the peers installed (make benchmark installs them), GSL's
    natural spline over chord length is cubic-b's curve to rounding:

    >>> p = np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0]])
    >>> gsl = cagd.peer_curve(p, "gsl:cspline")  # doctest: +SKIP
    >>> t = np.linspace(0.0, 4.2, 9)
    >>> bool(np.abs(gsl(t) - cagd.interpolate(p, "cubic-b")(t)).max() < 1e-14)  # doctest: +SKIP
    True
    """
    return _cagd._peer_curve(_points(points), name, _flag(closed, "closed"), peers, programs)
