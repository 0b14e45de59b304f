#!/usr/bin/env python3
"""Independent recomputation of the degree-99 LCG and LTG slopes of typical_curves Figs. 3-5 for
the construction and parameters stated in experiments/typical_curves/space_curves.cpp: the
corrected values of reference/typical_curves/space_curves.csv (erratum typical_curves-E13).

Nothing here is shared with the C++ library: 40-digit mpmath arithmetic, R_kappa (x) R_tau as the
rotation by the vector (dtheta_tau, 0, dtheta_kappa) (Rodrigues' formula, not log/exp),
Bernstein derivatives from forward differences evaluated term by term, curvature and torsion
from their definitions, the ordinary least-squares slope.
Run: python3 space_curves_mpmath.py   (about a minute; needs mpmath)
"""
import mpmath as mp

mp.mp.dps = 40
ALPHA, BETA, L, S0, DEGREE, SAMPLES = mp.mpf("1.5"), mp.mpf("1.2"), mp.mpf(1), mp.mpf("0.1"), 99, 400


def turning(slope, sigma):
    # theta = slope sign(slope - 1) sigma^((slope - 1)/slope): the normalised law |slope - 1| sigma^(-1/slope)
    return slope * mp.sign(slope - 1) * sigma ** ((slope - 1) / slope)


def rotation(v):
    angle = mp.sqrt(sum(x * x for x in v))
    k = [x / angle for x in v]
    kx = mp.matrix([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return mp.eye(3) + mp.sin(angle) * kx + (1 - mp.cos(angle)) * kx * kx


def polygon():
    ds = L / DEGREE
    frame, point, pts = mp.eye(3), mp.matrix([0, 0, 0]), [mp.matrix([0, 0, 0])]
    for j in range(DEGREE):
        point = point + ds * frame[:, 0]
        pts.append(point)
        if j + 1 < DEGREE:
            s0, s1 = S0 + j * ds, S0 + (j + 1) * ds
            dk, dt = turning(ALPHA, s1) - turning(ALPHA, s0), turning(BETA, s1) - turning(BETA, s0)
            frame = frame * rotation([dt, 0, dk])
    return pts


def derivatives(pts, t, order):
    out, diff, n = [], list(pts), len(pts) - 1
    for k in range(order + 1):
        d = n - k
        factor = mp.factorial(n) / mp.factorial(d)
        val = mp.matrix([0, 0, 0])
        for i, p in enumerate(diff):
            val += mp.binomial(d, i) * t ** i * (1 - t) ** (d - i) * p
        out.append(factor * val)
        diff = [diff[i + 1] - diff[i] for i in range(len(diff) - 1)]
    return out


def cross(a, b):
    return mp.matrix([a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]])


def dot(a, b):
    return sum(a[i] * b[i] for i in range(3))


def slope(xs, ys):
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


def main():
    pts = polygon()
    lx, ly, tx, ty = [], [], [], []
    for k in range(SAMPLES):
        t = mp.mpf(k) / (SAMPLES - 1)
        d1, d2, d3, d4 = derivatives(pts, t, 4)[1:]
        speed = mp.sqrt(dot(d1, d1))
        c = cross(d1, d2)
        cn = mp.sqrt(dot(c, c))
        kappa = cn / speed ** 3
        dkappa = (dot(c, cross(d1, d3)) / (cn * speed ** 3) - 3 * cn * dot(d1, d2) / speed ** 5) / speed
        den, num = dot(c, c), dot(c, d3)
        tau = num / den
        dtau = ((dot(c, d4) * den - num * 2 * dot(c, cross(d1, d3))) / den ** 2) / speed
        lx.append(-mp.log(kappa)); ly.append(mp.log(abs(kappa / dkappa)))
        tx.append(-mp.log(abs(tau))); ty.append(mp.log(abs(tau / dtau)))
    print("LCG slope, degree 99:", mp.nstr(slope(lx, ly), 12))
    print("LTG slope, degree 99:", mp.nstr(slope(tx, ty), 12))


if __name__ == "__main__":
    main()
