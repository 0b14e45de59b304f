#!/usr/bin/env python3
"""Independent 30-digit recomputation of the Fig. 3 values that the lines and arcs leave to the
free spans (curvature_profile, section 5; reference/curvature_profile/fig3_lines_arcs.csv).

Method, deliberately unlike the library's (no Bézier extraction, no Newton on the whole curve, no
Gauss-Legendre): psi(s) is evaluated by de Boor's algorithm on a clamped degree-2 knot vector,
the integrals of (cos psi, sin psi) by mpmath's tanh-sinh quadrature, and each free block alone is
solved by mpmath.findroot. The lines fix psi on them (the chord direction) and the arcs are forced
by their neighbours (span 4: quarter circle radius 1; span 7: semicircle radius 2, psi from -pi/2 to
pi/2; span 9: quarter circle radius 1 ending with psi = 0), so:
  span 2  (4,1)->(1,3):    one quadratic psi segment, psi from pi to pi/2 (unknowns b1, S)
  span 6  (7,7)->(10,3.5): psi from 0 to -pi/2
  spans 10-12 (15,7)->(17,4.2)->(20,3)->(22,3): psi = 0 at (15,7); segments a, b (span 10), c (span 11),
          d (span 12, a line), simple knots between them (kappa continuous); one free parameter,
          fixed here by pinning one printed segment of span 10 and solving for the other.
Run: python3 fig3_mpmath.py   (about a minute)
"""
from mpmath import mp, mpf, quad, cos, sin, pi, findroot

mp.dps = 30


def bezier2(b, t):
    return b[0] * (1 - t) ** 2 + 2 * b[1] * t * (1 - t) + b[2] * t ** 2


def single_segment(b0, b2, dx, dy, guess):
    def f(b1, S):
        return [S * quad(lambda t: cos(bezier2([b0, b1, b2], t)), [0, 1]) - dx,
                S * quad(lambda t: sin(bezier2([b0, b1, b2], t)), [0, 1]) - dy]
    return findroot(f, guess)


def deboor2(t, c, x):
    k = max(i for i in range(2, len(t) - 3) if t[i] <= x) if x < t[-1] else len(t) - 4
    d = [c[j + k - 2] for j in range(3)]
    for r in (1, 2):
        for j in range(2, r - 1, -1):
            a = (x - t[j + k - 2]) / (t[j + 1 + k - r] - t[j + k - 2])
            d[j] = (1 - a) * d[j - 1] + a * d[j]
    return d[2]


def block_residual(a, b, c, d, B1, B2, B3):
    # de Boor ordinates: psi(15,7) = 0, B1, B2, then the line's three equal ordinates B3.
    B = [mpf(0), B1, B2, B3, B3, B3]
    w = [mpf(0), a, a + b, a + b + c, a + b + c + d]
    t = [w[0]] * 3 + [w[1], w[2], w[3]] + [w[4]] * 3
    def integral(fun, s0, s1, brk):
        return quad(lambda s: fun(deboor2(t, B, s)), [s0] + brk + [s1])
    r = []
    for (s0, s1, brk, dx, dy) in ((w[0], w[2], [w[1]], 2, mpf('-2.8')), (w[2], w[3], [], 3, mpf('-1.2')), (w[3], w[4], [], 2, 0)):
        r += [integral(cos, s0, s1, brk) - dx, integral(sin, s0, s1, brk) - dy]
    return r


if __name__ == "__main__":
    b1, S2 = single_segment(pi, pi / 2, -3, 2, (3 * pi / 4, 4))
    print("span 2 length", mp.nstr(S2, 15))
    b1, S6 = single_segment(mpf(0), -pi / 2, 3, mpf('-3.5'), (-pi / 4, 5))
    print("span 6 length", mp.nstr(S6, 15))
    a = mpf('2.053')
    sol = findroot(lambda b, c, d, B1, B2, B3: block_residual(a, b, c, d, B1, B2, B3), (1.8, 3.4, 2.0, -0.5, -1.7, 0.0))
    print("span 10 second segment given the first = 2.053:", mp.nstr(sol[0], 15))
    print("span 11 length", mp.nstr(sol[1], 15), " span 12 length", mp.nstr(sol[2], 15))
    b = mpf('1.806')
    sol = findroot(lambda a_, c, d, B1, B2, B3: block_residual(a_, b, c, d, B1, B2, B3), (2.05, 3.4, 2.0, -0.5, -1.7, 0.0))
    print("span 10 first segment given the second = 1.806:", mp.nstr(sol[0], 15))
    print("semicircle (span 7) 2*pi =", mp.nstr(2 * pi, 15), " quarter circle (spans 4, 9) pi/2 =", mp.nstr(pi / 2, 15))
