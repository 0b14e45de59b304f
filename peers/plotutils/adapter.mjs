// GNU plotutils's `spline` as its users run it: `spline -d 2 -a` on the points, one x y pair per line
// (-a: the abscissa t = 0, 1, 2, … made for them; -d 2: a curve in the plane). Configurations:
//   cubic       spline's defaults: tension 0, boundary condition k = 1 (y''[0] = y''[1] and
//               y''[n] = y''[n−1], parabolic runout);
//   natural     -k 0 (second derivatives zero at the ends);
//   tension-1,  -T 1 and -T 5 (k = 1): splines under tension, y'''' = σ² y'' on every span in each
//   tension-5   coordinate, σ the tension (the manual's equation; the abscissa's spacing is 1).
// Closed: the first point again at the end and -p (periodic; k plays no part, so cubic and natural
// draw the same closed curve). Planar points only.
//
// spline writes samples only (-O d: binary doubles; -s: without t). Each span is recovered from its
// samples by the form its differential equation gives, with s = t − i in [0, 1], y0, y1 its ends:
//   tension 0:  a cubic, so the samples at s = 0, 1/3, 2/3, 1 give its Bézier points (to rounding);
//   tension σ:  y(s) = y0 (1 − s) + y1 s + M0 φ(1 − s) + M1 φ(s),  φ(s) = (sinh σs / sinh σ − s)/σ²,
//               M0, M1 the second derivatives at the ends, solved from the samples at s = 1/4, 3/4;
//               the sample at s = 1/2 checks the form (within kFormCheck D, D the points' bounding-
//               box diagonal), else the request fails saying so.
// A tension span is not a polynomial, so the document is an approximation (exact: false): each span
// cut into K equal sub-pieces (K fixed per configuration, so that the approximation is linear in
// the data: a moved point changes the pieces far away only as much as it changes the curve), each
// the quintic Hermite interpolant of the span's value, first and second derivative at its ends (C2
// joins: curvature continuous and exact at every join). Its error on a sub-piece of width h = 1/K,
// per coordinate, is at most max|y⁽⁶⁾| h⁶/(6! · 2⁶) (the Hermite remainder, |(s − a)³ (s − b)³| ≤ h⁶/64),
// and y⁽⁶⁾ = σ⁴ y'' with y''(s) = M0 sinh σ(1 − s)/sinh σ + M1 sinh σs/sinh σ, each term monotone:
// max_distance is the largest of these bounds over the sub-pieces (the coordinates' in quadrature),
// rounding aside.
import { spawnSync } from "node:child_process";
import { cubicThroughThirds } from "../cubic_through_thirds.mjs";
import { document, programVersion, serve } from "../protocol.mjs";

const version = programVersion("spline", ["--version"]);
if (!version && !process.argv.includes("--version")) {
  process.stderr.write("plotutils: spline is not installed (scripts/install-deps.sh peers)\n");
  process.exit(3);
}
const tensions = { "tension-1": { sigma: 1, pieces: 6 }, "tension-5": { sigma: 5, pieces: 16 } };
const peer = {
  name: "plotutils",
  version: (version ?? "none").replace(/^spline \(GNU plotutils\) (\S+).*/, "$1"),
  configurations: ["cubic", "natural", ...Object.keys(tensions)],
};
const kFormCheck = 1e-10;

// spline's samples of `points`, `per` per span (k from 0 to per · spans), as [x, y] pairs.
function samples(points, per, args) {
  const spans = points.length - 1;
  const run = spawnSync("spline", ["-d", "2", "-a", "-n", String(per * spans), "-s", "-O", "d", ...args], {
    input: points.map(([x, y]) => `${x} ${y}`).join("\n") + "\n",
    maxBuffer: 1 << 30,
  });
  if (run.error || run.status !== 0)
    throw new Error(`spline failed (${run.error?.code ?? run.status}): ${String(run.stderr).trim().split("\n").slice(-2).join(" | ")}`);
  const bytes = Uint8Array.from(run.stdout);
  const v = new Float64Array(bytes.buffer, 0, bytes.length / 8);
  if (v.length !== 2 * (per * spans + 1)) throw new Error(`spline wrote ${v.length / 2} samples, not ${per * spans + 1}`);
  return Array.from({ length: per * spans + 1 }, (_, k) => [v[2 * k], v[2 * k + 1]]);
}

function cubicPieces(S, spans) {
  return Array.from({ length: spans }, (_, i) => cubicThroughThirds(S[3 * i], S[3 * i + 1], S[3 * i + 2], S[3 * i + 3]));
}

// The quintic pieces of the tension spline through the samples S (4 per span), and their bound.
function tensionPieces(S, spans, { sigma, pieces: K }, diagonal) {
  const sh = Math.sinh(sigma), s2 = sigma * sigma;
  const phi = (s) => (Math.sinh(sigma * s) / sh - s) / s2;
  const dphi = (s) => ((sigma * Math.cosh(sigma * s)) / sh - 1) / s2;
  const ddphi = (s) => Math.sinh(sigma * s) / sh;
  const [a, b] = [phi(3 / 4), phi(1 / 4)];  // y(1/4) − line = M0 a + M1 b, y(3/4) − line = M0 b + M1 a
  const det = a * a - b * b;
  const h = 1 / K, remainder = Math.pow(h, 6) / (720 * 64) * s2 * s2;
  const pieces = [];
  let bound = 0;
  for (let i = 0; i < spans; ++i) {
    const y0 = S[4 * i], y1 = S[4 * i + 4];
    const M = [0, 1].map((c) => {
      const r1 = S[4 * i + 1][c] - (0.75 * y0[c] + 0.25 * y1[c]);
      const r3 = S[4 * i + 3][c] - (0.25 * y0[c] + 0.75 * y1[c]);
      return [(a * r1 - b * r3) / det, (a * r3 - b * r1) / det];
    });
    const jet = (s) =>
      [0, 1].map((c) => [
        y0[c] * (1 - s) + y1[c] * s + M[c][0] * phi(1 - s) + M[c][1] * phi(s),
        y1[c] - y0[c] - M[c][0] * dphi(1 - s) + M[c][1] * dphi(s),
        M[c][0] * ddphi(1 - s) + M[c][1] * ddphi(s),
      ]);
    const middle = jet(0.5);
    const off = Math.hypot(middle[0][0] - S[4 * i + 2][0], middle[1][0] - S[4 * i + 2][1]);
    if (!(off <= kFormCheck * diagonal))
      throw new Error(`span ${i}: spline's sample at its middle is ${off} from y'''' = σ² y'' with σ = ${sigma} through the others`);
    for (let j = 0; j < K; ++j) {
      const [s0, s1] = [j * h, j === K - 1 ? 1 : (j + 1) * h];
      const [p, q] = [jet(s0), jet(s1)];
      const point = (f) => [0, 1].map((c) => f(p[c], q[c]));
      pieces.push([
        point((u) => u[0]),
        point((u) => u[0] + (h / 5) * u[1]),
        point((u) => u[0] + ((2 * h) / 5) * u[1] + ((h * h) / 20) * u[2]),
        point((_, v) => v[0] - ((2 * h) / 5) * v[1] + ((h * h) / 20) * v[2]),
        point((_, v) => v[0] - (h / 5) * v[1]),
        point((_, v) => v[0]),
      ]);
      const largest = (c) => Math.abs(M[c][0]) * ddphi(1 - s0) + Math.abs(M[c][1]) * ddphi(s1);
      bound = Math.max(bound, remainder * Math.hypot(largest(0), largest(1)));
    }
  }
  return { pieces, bound, breaks: Array.from({ length: spans * K + 1 }, (_, k) => (k % K === 0 ? k / K : Math.floor(k / K) + (k % K) * h)) };
}

serve(peer, (request) => {
  if (request.points[0].length !== 2) throw new Error("plotutils's spline -d 2 draws planar points only");
  const points = request.closed ? request.points.concat([request.points[0]]) : request.points;
  const spans = points.length - 1;
  const args = request.closed ? ["-p"] : request.configuration === "natural" ? ["-k", "0"] : [];
  const tension = tensions[request.configuration];
  if (!tension) return document(peer, request, cubicPieces(samples(points, 3, args), spans));
  const lo = [0, 1].map((c) => points.reduce((m, p) => Math.min(m, p[c]), Infinity));
  const hi = [0, 1].map((c) => points.reduce((m, p) => Math.max(m, p[c]), -Infinity));
  const diagonal = Math.hypot(hi[0] - lo[0], hi[1] - lo[1]);
  const S = samples(points, 4, ["-T", String(tension.sigma), ...args]);
  const { pieces, bound, breaks } = tensionPieces(S, spans, tension, diagonal);
  return document(peer, request, pieces, { breaks, approximation: { maxDistance: bound, tolerance: 0 } });
});
