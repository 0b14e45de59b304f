// The peer protocol, for the adapters written in JavaScript (docs/peers.md): read the requests on
// standard input, answer each with one line on standard output.
//
// A request is a line `curve CONFIGURATION open|closed N D`, then N lines of D coordinates
// separated by spaces. The answer is one line: a cagd-curve document (the library's JSON of exact
// pieces, export/curve_json.hpp) whose pieces are the peer's own, or {"error": "..."} when the peer
// refuses the points or fails. `--version` prints the peer's name and version and exits.
import { execFileSync, spawnSync } from "node:child_process";
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";

// The requests of standard input: [{configuration, closed, points: [[x, y, ...], ...]}].
export function readRequests(text) {
  const lines = text.split("\n");
  const requests = [];
  for (let i = 0; i < lines.length; ) {
    const head = lines[i++].trim();
    if (head === "") continue;
    const f = head.split(/\s+/);
    if (f.length !== 5 || f[0] !== "curve" || (f[2] !== "open" && f[2] !== "closed"))
      throw new Error(`line ${i}: "${head}" is not "curve CONFIGURATION open|closed N D"`);
    const n = Number(f[3]), d = Number(f[4]);
    const points = [];
    for (let k = 0; k < n; ++k) {
      const p = (lines[i++] ?? "").trim().split(/\s+/).map(Number);
      if (p.length !== d || p.some((v) => !Number.isFinite(v))) throw new Error(`line ${i}: not ${d} numbers`);
      points.push(p);
    }
    requests.push({ configuration: f[1], closed: f[2] === "closed", points });
  }
  return requests;
}

// Planar cubic pieces from lines of eight numbers each (x0 y0 x1 y1 x2 y2 x3 y3), as the MetaPost
// and Asymptote adapters have their programs write them.
export function planarCubicsOfLines(text) {
  return text
    .trim()
    .split("\n")
    .map((line) => {
      const v = line.trim().split(/\s+/).map(Number);
      if (v.length !== 8 || v.some((x) => !Number.isFinite(x))) throw new Error(`not a cubic piece: "${line}"`);
      return [0, 2, 4, 6].map((k) => [v[k], v[k + 1]]);
    });
}

// One answer: the document of `pieces` (Bézier control points, cubic unless given longer), with
// breaks 0, 1, 2, … (the span index) unless given. A peer that gives samples only and whose pieces
// approximate its curve says so: `approximation: {maxDistance, tolerance}` (exact: false, the bound).
export function document(peer, request, pieces, { parameter = "uniform (span index)", breaks, approximation } = {}) {
  return JSON.stringify({
    format: "cagd-curve",
    format_version: 1,
    library_version: peer.version,
    registry: "",
    method: { closed: request.closed, name: `${peer.name}:${request.configuration}`, parameter, parameters: {} },
    points: request.points,
    dimension: request.points[0].length,
    degree: pieces.length ? pieces[0].length - 1 : 3,
    exact: !approximation,
    max_distance: approximation?.maxDistance ?? 0,
    tolerance: approximation?.tolerance ?? 0,
    breaks: breaks ?? pieces.map((_, i) => i).concat([pieces.length]),
    pieces,
  });
}

// Runs an adapter: `answer(request)` returns a document line or throws; its message is the error.
// An adapter whose program starts slowly (MetaPost, Asymptote) also gives `answerAll(requests)`,
// which draws every request in one run and returns their lines in order; when that run fails, each
// request is drawn alone by `answer`, so that a request the program rejects fails alone.
export function serve(peer, answer, answerAll) {
  if (process.argv.includes("--version")) {
    process.stdout.write(`${peer.name} ${peer.version}\n`);
    return;
  }
  const requests = readRequests(readFileSync(0, "utf8"));
  const known = (request) => {
    if (!peer.configurations.includes(request.configuration))
      throw new Error(`unknown configuration "${request.configuration}"; ${peer.name} has ${peer.configurations.join(", ")}`);
  };
  const alone = (request) => {
    try {
      known(request);
      return answer(request);
    } catch (e) {
      return JSON.stringify({ error: String(e.message ?? e) });
    }
  };
  let out = null;
  if (answerAll && requests.length > 1) {
    try {
      requests.forEach(known);
      out = answerAll(requests);
      if (out.length !== requests.length) throw new Error(`${out.length} answers to ${requests.length} requests`);
    } catch {
      out = null;
    }
  }
  // One line at a time, each written as it is drawn (writes to a pipe or a file are synchronous
  // here): a batch's answers together may exceed the longest string V8 holds (2^29 characters).
  if (out) for (const line of out) process.stdout.write(line + "\n");
  else for (const request of requests) process.stdout.write(alone(request) + "\n");
}

// Splits the text a batch program wrote into its paths: each path's lines follow a line "path".
export function pathsOfBatch(text, count) {
  const parts = text.split(/^path$/m).slice(1);
  if (parts.length !== count) throw new Error(`the program wrote ${parts.length} paths of ${count}`);
  return parts;
}

// The version of an installed npm package of peers/.
export function packageVersion(name) {
  return JSON.parse(readFileSync(new URL(`./node_modules/${name}/package.json`, import.meta.url), "utf8")).version;
}

// Runs `program` with `args` in a scratch folder holding `files` ({name: text}); returns the text of
// the file `result` it wrote, or throws with the program's last lines. The folder is removed.
export function runInScratch(program, args, files, result) {
  const dir = mkdtempSync(join(tmpdir(), "cagd-peer-"));
  try {
    for (const [name, text] of Object.entries(files)) writeFileSync(join(dir, name), text);
    try {
      execFileSync(program, args, { cwd: dir, stdio: ["ignore", "pipe", "pipe"], maxBuffer: 1 << 30 });
    } catch (e) {
      const said = `${e.stdout ?? ""}${e.stderr ?? ""}`.trim().split("\n").slice(-3).join(" | ");
      throw new Error(`${program} failed (${e.status ?? e.signal ?? e.code}): ${said}`);
    }
    return readFileSync(join(dir, result), "utf8");
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
}

// The first line a program prints for `args` (its version) on standard output or error; null when
// it cannot be run.
export function programVersion(program, args) {
  const r = spawnSync(program, args, { stdio: ["ignore", "pipe", "pipe"] });
  if (r.error || r.status !== 0) return null;
  return `${r.stdout}${r.stderr}`.split("\n")[0].trim();
}
