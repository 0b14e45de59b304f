// The JavaScript peers in the browser, as their users call them: d3-shape, paper.js and three.js,
// their npm packages (peers/package-lock.json) copied into the site at build time (peers/lib/), and
// each peer's drawing the very module its Node.js adapter runs (peers/<peer>/pieces.mjs, copied
// beside them). viewer.js draws a shown peer's curve here and hands its cubic pieces to the
// library (cagd.js: compare's peers), which measures and samples them as `cagd compare --peers`
// does. bezier-spline, the fourth JavaScript peer, is a CommonJS package and runs in Node.js only.
import * as d3Shape from './peers/d3-shape/pieces.mjs';
import * as paperJs from './peers/paper.js/pieces.mjs';
import * as threeJs from './peers/three.js/pieces.mjs';

// A classic script (the UMD builds of d3 and paper.js define globals), loaded once.
function script(src) {
  return new Promise((resolve, reject) => {
    const s = document.createElement('script');
    s.src = src;
    s.onload = resolve;
    s.onerror = () => reject(new Error(`${src} did not load`));
    document.head.appendChild(s);
  });
}

// The peers: [{name: "peer:configuration", peer, library}], and draw(name, points, closed) ->
// {name, pieces: [x0, y0, x1, y1, x2, y2, x3, y3, …]} or {name, error}.
export async function loadPeers() {
  await script('peers/lib/d3-path.js');
  await script('peers/lib/d3-shape.js');
  await script('peers/lib/paper-core.js');
  const THREE = await import('./peers/lib/three.module.js');
  const paper = globalThis.paper;
  paper.setup(new paper.Size(1, 1));
  const peers = [
    { peer: 'd3-shape', library: 'd3-shape (npm, ISC)', lib: globalThis.d3, module: d3Shape },
    { peer: 'paper.js', library: `paper.js ${paper.version} (npm paper, MIT)`, lib: paper, module: paperJs },
    { peer: 'three.js', library: `three.js r${THREE.REVISION} (npm three, MIT)`, lib: THREE, module: threeJs },
  ];
  const list = [], byName = new Map();
  for (const p of peers)
    for (const c of p.module.configurations) {
      const name = `${p.peer}:${c}`;
      list.push({ name, peer: p.peer, configuration: c, library: p.library });
      byName.set(name, { ...p, configuration: c });
    }
  function draw(name, points, closed) {
    const p = byName.get(name);
    if (!p) return { name, error: `no peer configuration ${name} in this page` };
    try {
      const pieces = p.module.pieces(p.lib, p.configuration, points, closed);
      return pieces.length ? { name, pieces: pieces.flat(2) } : { name, error: `${p.peer} drew no piece` };
    } catch (e) {
      return { name, error: e.message };
    }
  }
  return { list, draw };
}
