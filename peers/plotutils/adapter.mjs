// GNU plotutils's `spline` as its users run it: `spline -d 2 -a` on the points, one x y pair per line
// (-a: the abscissa t = 0, 1, 2, … made for them; -d 2: a curve in the plane), a cubic spline
// (tension 0). Configurations: cubic, spline's defaults (boundary condition k = 1: y''[0] = y''[1] and
// y''[n] = y''[n−1], parabolic runout); natural, with -k 0 (second derivatives zero at the ends).
// Closed: the first point again at the end and -p (periodic; k plays no part, so both
// configurations draw the same closed curve). spline writes samples only; its curve at
// tension 0 is a cubic in t on each span, so samples at t = i, i + 1/3, i + 2/3, i + 1 (-n 3 spans,
// written in binary doubles with -O d, -s without t) give each span's Bézier points exactly up to
// rounding, as the three.js adapter does with getPoint. Planar points only.
// Its tension splines (-T > 0) are not polynomial on a span, so four samples do not give them:
// they are not among the configurations.
import { spawnSync } from "node:child_process";
import { document, programVersion, serve } from "../protocol.mjs";

const version = programVersion("spline", ["--version"]);
if (!version && !process.argv.includes("--version")) {
  process.stderr.write("plotutils: spline is not installed (scripts/install-deps.sh peers)\n");
  process.exit(3);
}
const peer = {
  name: "plotutils",
  version: (version ?? "none").replace(/^spline \(GNU plotutils\) (\S+).*/, "$1"),
  configurations: ["cubic", "natural"],
};

serve(peer, (request) => {
  if (request.points[0].length !== 2) throw new Error("plotutils's spline -d 2 draws planar points only");
  const points = request.closed ? request.points.concat([request.points[0]]) : request.points;
  const spans = points.length - 1;
  const args = ["-d", "2", "-a", "-n", String(3 * spans), "-s", "-O", "d"];
  if (request.closed) args.push("-p");
  else if (request.configuration === "natural") args.push("-k", "0");
  const run = spawnSync("spline", args, {
    input: points.map(([x, y]) => `${x} ${y}`).join("\n") + "\n",
    maxBuffer: 1 << 30,
  });
  if (run.error || run.status !== 0)
    throw new Error(`spline failed (${run.error?.code ?? run.status}): ${String(run.stderr).trim().split("\n").slice(-2).join(" | ")}`);
  const bytes = Uint8Array.from(run.stdout);
  const v = new Float64Array(bytes.buffer, 0, bytes.length / 8);
  if (v.length !== 2 * (3 * spans + 1)) throw new Error(`spline wrote ${v.length / 2} samples, not ${3 * spans + 1}`);
  const sample = (k) => [v[2 * k], v[2 * k + 1]];
  const pieces = [];
  for (let i = 0; i < spans; ++i) {
    const [c0, p1, p2, c3] = [0, 1, 2, 3].map((k) => sample(3 * i + k));
    // P(1/3) = (8c0 + 12c1 + 6c2 + c3)/27, P(2/3) = (c0 + 6c1 + 12c2 + 8c3)/27, solved for c1, c2.
    const a = p1.map((x, k) => 27 * x - 8 * c0[k] - c3[k]);
    const b = p2.map((x, k) => 27 * x - c0[k] - 8 * c3[k]);
    pieces.push([c0, a.map((x, k) => (2 * x - b[k]) / 18), b.map((x, k) => (2 * x - a[k]) / 18), c3]);
  }
  return document(peer, request, pieces);
});
