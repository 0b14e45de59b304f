// paper.js as its users call it: a Path through the points (closed: path.closed = true), then
// path.smooth({type}); its exact cubic pieces are read from the segments' handles: span i is
// [p_i, p_i + handleOut_i, p_{i+1} + handleIn_{i+1}, p_{i+1}]. Run on paper-core (paper.js without
// PaperScript, the build for Node.js). Configurations: continuous, asymmetric, catmull-rom,
// geometric (paper's smoothing types, their default factors). Planar points only.
import { createRequire } from "node:module";
import { document, serve } from "../protocol.mjs";

const paper = createRequire(import.meta.url)("paper/dist/paper-core.js");
paper.setup(new paper.Size(1, 1));
const peer = {
  name: "paper.js",
  version: paper.version,
  configurations: ["continuous", "asymmetric", "catmull-rom", "geometric"],
};

serve(peer, (request) => {
  if (request.points[0].length !== 2) throw new Error("paper.js draws planar points only");
  const path = new paper.Path(request.points.map(([x, y]) => new paper.Point(x, y)));
  path.closed = request.closed;
  path.smooth({ type: request.configuration });
  const s = path.segments;
  const pieces = [];
  const spans = request.closed ? s.length : s.length - 1;
  for (let i = 0; i < spans; ++i) {
    const a = s[i], b = s[(i + 1) % s.length];
    pieces.push([
      [a.point.x, a.point.y],
      [a.point.x + a.handleOut.x, a.point.y + a.handleOut.y],
      [b.point.x + b.handleIn.x, b.point.y + b.handleIn.y],
      [b.point.x, b.point.y],
    ]);
  }
  path.remove();
  return document(peer, request, pieces);
});
