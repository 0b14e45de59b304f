// three.js's cubic pieces, as its users draw them: new THREE.CatmullRomCurve3(points, closed,
// curveType), read through getPoint. Each span of a CatmullRomCurve3 is a cubic in its local
// parameter w ∈ [0, 1] (three's CubicPoly), so four evaluations per span, at w = 0, 1/3, 2/3, 1,
// give its Bézier points exactly up to rounding (the curve's parameter t = (i + w)/spans is
// rounded once). Configurations: centripetal, chordal, uniform (three's "catmullrom", tension
// 0.5); open and closed, planar or in space. Shared by the adapter (Node.js) and the viewer (the
// browser, web/site/peers.mjs): `THREE` is the three module either loaded.
import { cubicThroughThirds } from "../cubic_through_thirds.mjs";

export const configurations = ["centripetal", "chordal", "uniform"];
const curveTypes = { centripetal: "centripetal", chordal: "chordal", uniform: "catmullrom" };

export function pieces(THREE, configuration, points, closed) {
  if (!curveTypes[configuration]) throw new Error(`three.js has no configuration ${configuration}`);
  const d = points[0].length;
  const curve = new THREE.CatmullRomCurve3(
    points.map((p) => new THREE.Vector3(p[0], p[1], d === 3 ? p[2] : 0)),
    closed,
    curveTypes[configuration],
  );
  const spans = closed ? points.length : points.length - 1;
  const at = (t) => {
    const v = curve.getPoint(Math.min(t, 1));
    return [v.x, v.y, v.z].slice(0, d);
  };
  const out = [];
  for (let i = 0; i < spans; ++i) {
    out.push(cubicThroughThirds(...[0, 1, 2, 3].map((k) => at((i + k / 3) / spans))));
  }
  return out;
}
