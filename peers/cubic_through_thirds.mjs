// The Bézier points of a cubic from its values at the parameters 0, 1/3, 2/3, 1 (exact up to
// rounding): P(1/3) = (8c0 + 12c1 + 6c2 + c3)/27 and P(2/3) = (c0 + 6c1 + 12c2 + 8c3)/27, solved for
// c1, c2. For peers that give positions only (three.js's getPoint, plotutils's samples at tension
// 0). No Node.js imports: the viewer loads it beside the peers' pieces.mjs.
export function cubicThroughThirds(c0, p1, p2, c3) {
  const a = p1.map((v, k) => 27 * v - 8 * c0[k] - c3[k]);
  const b = p2.map((v, k) => 27 * v - c0[k] - 8 * c3[k]);
  return [c0, a.map((v, k) => (2 * v - b[k]) / 18), b.map((v, k) => (2 * v - a[k]) / 18), c3];
}
