// MetaPost as its users run it: `mpost -numbersystem=double` on a file of paths
// z0..z1..…..z(n−1) (closed: ..cycle), Hobby's algorithm with MetaPost's defaults (tension 1, curl 1
// at open ends), then each path's control points written out at 17 digits (`decimal`). All the
// requests of a batch are drawn by one run (each alone when that run fails). Configuration: hobby.
// Planar points only; MetaPost reads no exponents, so each coordinate is written as a plain decimal,
// and it refuses magnitudes of 2^52 or more (double mode's largest exactly integral range, where it
// stops reading digits).
import { document, pathsOfBatch, planarCubicsOfLines, programVersion, runInScratch, serve } from "../protocol.mjs";

const version = programVersion("mpost", ["--version"]);
if (!version && !process.argv.includes("--version")) {
  process.stderr.write("metapost: mpost is not installed (scripts/install-deps.sh peers)\n");
  process.exit(3);
}
const peer = { name: "metapost", version: (version ?? "none").replace(/^MetaPost (\S+).*/, "$1"), configurations: ["hobby"] };

// x as a decimal without an exponent, 17 significant digits.
function plainDecimal(x) {
  const [mantissa, exponent] = x.toPrecision(17).split("e");
  if (exponent === undefined) return mantissa;
  const negative = mantissa.startsWith("-");
  const digits = mantissa.replace("-", "").replace(".", "");
  const point = 1 + Number(exponent);  // digits before the decimal point
  const text = point <= 0 ? "0." + "0".repeat(-point) + digits : digits.padEnd(point, "0");
  return (negative ? "-" : "") + text;
}

// The statements that draw one request's path p and write its pieces to pieces.txt.
function drawing(request) {
  if (request.points[0].length !== 2) throw new Error("MetaPost draws planar points only");
  for (const p of request.points)
    for (const v of p)
      if (Math.abs(v) >= 2 ** 52) throw new Error(`MetaPost reads no coordinate of magnitude 2^52 or more (${v})`);
  const path = request.points.map(([x, y]) => `(${plainDecimal(x)},${plainDecimal(y)})`).join("..");
  const coordinate = (f, i) => `decimal xpart ${f} ${i} of p & " " & decimal ypart ${f} ${i} of p`;
  return (
    `p := ${path}${request.closed ? "..cycle" : ""};\n` +
    `write "path" to "pieces.txt";\n` +
    `for i = 0 upto length p - 1:\n` +
    `  write ${coordinate("point", "i")} & " " & ${coordinate("postcontrol", "i")} & " " & ` +
    `${coordinate("precontrol", "(i+1)")} & " " & ${coordinate("point", "(i+1)")} to "pieces.txt";\n` +
    `endfor\n`
  );
}

// One run of mpost drawing `requests`, in order; their answers.
function draw(requests) {
  const program = `path p;\n${requests.map(drawing).join("")}write EOF to "pieces.txt";\nend\n`;
  const text = runInScratch(
    "mpost",
    ["-numbersystem=double", "-interaction=batchmode", "-halt-on-error", "curve.mp"],
    { "curve.mp": program },
    "pieces.txt",
  );
  return pathsOfBatch(text, requests.length).map((lines, k) => document(peer, requests[k], planarCubicsOfLines(lines)));
}

serve(peer, (request) => draw([request])[0], draw);
