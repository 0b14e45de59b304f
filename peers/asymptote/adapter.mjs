// Asymptote as its users run it: `asy` on a file of paths z0..z1..…..z(n−1) (closed: ..cycle),
// Hobby's algorithm in double precision with Asymptote's defaults (tension 1, curl 1 at open ends),
// then each path's control points written out at 17 digits (format("%.17g")). All the requests of a
// batch are drawn by one run (each alone when that run fails). Configuration: hobby. Planar points
// only (Asymptote's 3-D paths are a module of their own).
import { document, pathsOfBatch, planarCubicsOfLines, programVersion, runInScratch, serve } from "../protocol.mjs";

const version = programVersion("asy", ["--version"]);
if (!version && !process.argv.includes("--version")) {
  process.stderr.write("asymptote: asy is not installed (scripts/install-deps.sh peers)\n");
  process.exit(3);
}
const peer = { name: "asymptote", version: (version ?? "none").replace(/^Asymptote version (\S+).*/, "$1"), configurations: ["hobby"] };

// The statements that draw one request's path p and write its pieces to f.
function drawing(request) {
  if (request.points[0].length !== 2) throw new Error("Asymptote's planar paths take planar points only");
  const path = request.points.map(([x, y]) => `(${x.toPrecision(17)},${y.toPrecision(17)})`).join("..");
  const g = (z) => `format("%.17g", ${z}.x) + " " + format("%.17g", ${z}.y)`;
  return (
    `p = ${path}${request.closed ? "..cycle" : ""};\n` +
    `write(f, "path", endl);\n` +
    `for (int i = 0; i < length(p); ++i) {\n` +
    `  pair a = point(p, i), b = postcontrol(p, i), c = precontrol(p, i + 1), d = point(p, i + 1);\n` +
    `  write(f, ${g("a")} + " " + ${g("b")} + " " + ${g("c")} + " " + ${g("d")}, endl);\n` +
    `}\n`
  );
}

// One run of asy drawing `requests`, in order; their answers.
function draw(requests) {
  const program = `path p;\nfile f = output("pieces.txt");\n${requests.map(drawing).join("")}close(f);\n`;
  const text = runInScratch("asy", ["-noV", "-offscreen", "curve.asy"], { "curve.asy": program }, "pieces.txt");
  return pathsOfBatch(text, requests.length).map((lines, k) => document(peer, requests[k], planarCubicsOfLines(lines)));
}

serve(peer, (request) => draw([request])[0], draw);
