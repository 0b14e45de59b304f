// d3-shape as its users call it: d3.line().curve(c) drawn into a recording context, whose
// bezierCurveTo calls are the curve's exact cubic pieces (lineTo: a line, elevated to a cubic).
// Configurations: natural (curveNatural), catmull-rom (curveCatmullRom, α = 0.5, d3's default),
// cardinal (curveCardinal, tension 0), monotone-x (curveMonotoneX); closed curves through the
// Closed factories where d3 has one (catmull-rom, cardinal), its pieces rotated to start at the
// first point. Planar points only.
import * as d3 from "d3-shape";
import { document, lineAsCubic, packageVersion, serve } from "../protocol.mjs";

const peer = {
  name: "d3-shape",
  version: packageVersion("d3-shape"),
  configurations: ["natural", "catmull-rom", "cardinal", "monotone-x"],
};
const factories = {
  natural: [d3.curveNatural, null],
  "catmull-rom": [d3.curveCatmullRom, d3.curveCatmullRomClosed],
  cardinal: [d3.curveCardinal, d3.curveCardinalClosed],
  "monotone-x": [d3.curveMonotoneX, null],
};

serve(peer, (request) => {
  if (request.points[0].length !== 2) throw new Error("d3-shape draws planar points only");
  const factory = factories[request.configuration][request.closed ? 1 : 0];
  if (!factory) throw new Error(`d3-shape has no closed curve of ${request.configuration}`);
  const pieces = [];
  let at = null;
  const context = {
    moveTo(x, y) {
      at = [x, y];
    },
    lineTo(x, y) {
      pieces.push(lineAsCubic(at, [x, y]));
      at = [x, y];
    },
    bezierCurveTo(x1, y1, x2, y2, x, y) {
      pieces.push([at, [x1, y1], [x2, y2], [x, y]]);
      at = [x, y];
    },
    closePath() {},
  };
  d3.line().curve(factory).context(context)(request.points);
  // A closed curve starts at d3's second point: its pieces, rotated, start at the first.
  if (request.closed) pieces.unshift(...pieces.splice(pieces.length - 1, 1));
  return document(peer, request, pieces);
});
