// d3-shape's exact cubic pieces, as its users draw them: d3.line().curve(c) drawn into a recording
// context, whose bezierCurveTo calls are the pieces (lineTo: a line, elevated to a cubic).
// Configurations: natural (curveNatural), catmull-rom (curveCatmullRom, α = 0.5, d3's default),
// cardinal (curveCardinal, tension 0), monotone-x (curveMonotoneX); closed curves through the
// Closed factories where d3 has one (catmull-rom, cardinal), the pieces rotated to start at the
// first point. Planar points only. Shared by the adapter (Node.js, adapter.mjs) and the viewer
// (the browser, web/site/peers.mjs): `d3` is the d3-shape module either loaded.
export const configurations = ["natural", "catmull-rom", "cardinal", "monotone-x"];

// The cubic Bézier pieces of a line segment (a degree-elevated line: d3's lineTo).
function lineAsCubic(a, b) {
  return [a, a.map((v, k) => v + (b[k] - v) / 3), a.map((v, k) => v + (2 * (b[k] - v)) / 3), b];
}

// The pieces through `points` ([[x, y], …]); throws with the reason when d3 draws no such curve.
export function pieces(d3, configuration, points, closed) {
  const factories = {
    natural: [d3.curveNatural, null],
    "catmull-rom": [d3.curveCatmullRom, d3.curveCatmullRomClosed],
    cardinal: [d3.curveCardinal, d3.curveCardinalClosed],
    "monotone-x": [d3.curveMonotoneX, null],
  };
  if (!factories[configuration]) throw new Error(`d3-shape has no configuration ${configuration}`);
  if (points[0].length !== 2) throw new Error("d3-shape draws planar points only");
  const factory = factories[configuration][closed ? 1 : 0];
  if (!factory) throw new Error(`d3-shape has no closed curve of ${configuration}`);
  const out = [];
  let at = null;
  const context = {
    moveTo(x, y) {
      at = [x, y];
    },
    lineTo(x, y) {
      out.push(lineAsCubic(at, [x, y]));
      at = [x, y];
    },
    bezierCurveTo(x1, y1, x2, y2, x, y) {
      out.push([at, [x1, y1], [x2, y2], [x, y]]);
      at = [x, y];
    },
    closePath() {},
  };
  d3.line().curve(factory).context(context)(points);
  // A closed curve starts at d3's second point: its pieces, rotated, start at the first.
  if (closed) out.unshift(...out.splice(out.length - 1, 1));
  return out;
}
