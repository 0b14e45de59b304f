// bezier-spline (npm) as its users call it: new BezierSpline(knots), whose `curves` are the
// spline's exact cubic Bézier pieces, one per span (its README: a G2 continuous spline of cubic
// Bézier curves, for graphics). Configuration: g2. Open curves, of any dimension it is given.
import BezierSpline from "bezier-spline";
import { document, packageVersion, serve } from "../protocol.mjs";

const peer = { name: "bezier-spline", version: packageVersion("bezier-spline"), configurations: ["g2"] };

serve(peer, (request) => {
  if (request.closed) throw new Error("bezier-spline draws open curves only");
  const spline = new BezierSpline(request.points);
  return document(peer, request, spline.curves.map((c) => [0, 1, 2, 3].map((k) => Array.from(c[k]))));
});
