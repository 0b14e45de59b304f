// paper.js's exact cubic pieces, as its users draw them: a Path through the points (closed:
// path.closed = true), then path.smooth({type}); span i is [p_i, p_i + handleOut_i,
// p_{i+1} + handleIn_{i+1}, p_{i+1}], read from the segments' handles. Configurations: continuous,
// asymmetric, catmull-rom, geometric (paper's smoothing types, their default factors). Planar
// points only. Shared by the adapter (Node.js, on paper-core: paper.js without PaperScript) and the
// viewer (the browser, web/site/peers.mjs): `paper` is a PaperScope that has been set up.
export const configurations = ["continuous", "asymmetric", "catmull-rom", "geometric"];

export function pieces(paper, configuration, points, closed) {
  if (!configurations.includes(configuration)) throw new Error(`paper.js has no configuration ${configuration}`);
  if (points[0].length !== 2) throw new Error("paper.js draws planar points only");
  const path = new paper.Path(points.map(([x, y]) => new paper.Point(x, y)));
  path.closed = closed;
  path.smooth({ type: configuration });
  const s = path.segments;
  const out = [];
  const spans = closed ? s.length : s.length - 1;
  for (let i = 0; i < spans; ++i) {
    const a = s[i], b = s[(i + 1) % s.length];
    out.push([
      [a.point.x, a.point.y],
      [a.point.x + a.handleOut.x, a.point.y + a.handleOut.y],
      [b.point.x + b.handleIn.x, b.point.y + b.handleIn.y],
      [b.point.x, b.point.y],
    ]);
  }
  path.remove();
  return out;
}
