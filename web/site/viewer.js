// The viewer page: points placed and dragged on a canvas, every chosen configuration of the
// registry drawn over them with its curvature comb (one common scale) and its κ(s) profile, the
// comparison's measures, the locality view, the exports, and the whole state in the URL hash.
// All mathematics is the library's (cagd.js, from web/bindings/viewer_module.cpp); this file draws.
// The JavaScript peers (d3-shape, paper.js, three.js) draw their curves in the page as their users
// call them (peers.mjs); the library measures and samples their pieces as it does a method's.
'use strict';

(function () {
  const viewer = {
    ready: null,          // resolves when the module is loaded and the first frame drawn
    module: null,
    registry: null,
    peers: { list: [], draw: null, reason: '' },  // the JavaScript peers (peers.mjs), once loaded
    state: null,
    result: null,         // the last comparison
    measures: null,       // the last measures table from the worker: {id, header, rows, names}
    frames: [],           // the last frames' times in ms: {total, compare, draw, points, methods}
    errors: [],           // messages shown to the user
  };
  window.cagdViewer = viewer;

  // The points of the example: a quarter-turn with an inflection, as a designer might place them.
  const EXAMPLE = [[0, 0], [1.2, 1.6], [3, 2.2], [4.6, 1.4], [5.6, -0.4], [7.2, -1], [8.8, 0.2]];
  // Shown at first: the papers' methods and one peer of each kind.
  const DEFAULT_SHOWN = ['pseudo-spline-approx', 'cubic-b', 's-spline-m2', 'b2-spline-m2', 'hosaka-c2-chord', 'curvature-profile', 'spiro', 'boost-pchip'];
  const MARGIN = 36;            // px around the fitted points
  const PICK_RADIUS = 9;        // px: a click this close to a point picks it
  const MOTION_FLOOR = 1e-9;    // span motion ÷ diagonal below this is rounding (compare's locality tolerance)
  const FRAME_HISTORY = 240;
  // ms: during a drag the measures are computed when the point has rested this long, or is
  // released; not on every frame, where the worker's work (0.2–0.3 s for ten methods at 100 points)
  // would contend with the frames for the machine's cores.
  const MEASURES_PAUSE = 150;

  const $ = (id) => document.getElementById(id);
  const canvas = $('curves'), profileCanvas = $('profile');
  const ctx = canvas.getContext('2d'), pctx = profileCanvas.getContext('2d');
  let view = { cx: 0, cy: 0, scale: 1 };
  let dragging = -1, pendingFrame = false, pendingMotion = false, hoverS = null;
  // The measures worker: one request at a time, the newest waiting (older ones are dropped).
  let worker = null, workerBusy = false, workerNext = null, requestId = 0, settledWaiters = [];
  let pauseTimer = null;  // the measures' request waiting for the dragged point to rest

  // ---- state and the URL hash -------------------------------------------------------------
  // Every name the page can show: the registry's configurations, then the peers' "peer:configuration".
  function knownNames() {
    return new Set(viewer.registry.configurations.map((c) => c.name).concat(viewer.peers.list.map((p) => p.name)));
  }
  const isPeer = (name) => viewer.peers.list.some((p) => p.name === name);

  function defaultState() {
    const known = knownNames();
    return {
      points: EXAMPLE.map((p) => p.slice()),
      closed: false,
      shown: DEFAULT_SHOWN.filter((n) => known.has(n)).map((name) => ({ name, parameters: {} })),
      comb: true,
      locality: false,
      perSpan: 16,
    };
  }

  // The hash holds the state as JSON; numbers in JavaScript's shortest round-trip form, so a link
  // reopens the same doubles and therefore the same curves.
  function encodeState(s) {
    const shown = s.shown.map((c) => (Object.keys(c.parameters).length ? [c.name, c.parameters] : c.name));
    return '#' + encodeURIComponent(JSON.stringify({ v: 1, points: s.points, closed: s.closed, shown, comb: s.comb, locality: s.locality, perSpan: s.perSpan }));
  }

  // A link is refused whole, with a message naming what is wrong, when it is longer than
  // MAX_LINK_BYTES or holds more than MAX_LINK_POINTS points (checked before it is parsed: below
  // them the page answers within 2 s), is not a JSON object, or holds a point that is not two finite
  // numbers (named, never dropped); the example is shown instead.
  const MAX_LINK_POINTS = 2000, MAX_LINK_BYTES = 256 * 1024;
  function decodeState(hash) {
    if (!hash || hash.length < 2) return null;
    const refuse = (why) => {
      report('the link ' + why + '; the example is shown');
      return null;
    };
    if (hash.length > MAX_LINK_BYTES) return refuse(`is ${hash.length} characters long, more than the ${MAX_LINK_BYTES} a link may hold (at most ${MAX_LINK_POINTS} points)`);
    let o;
    try {
      o = JSON.parse(decodeURIComponent(hash.slice(1)));
    } catch (e) {
      return refuse('is not readable JSON (' + e.message + ')');
    }
    if (o === null || typeof o !== 'object' || Array.isArray(o))
      return refuse('must hold a JSON object of the viewer\'s state, not ' + (o === null ? 'null' : Array.isArray(o) ? 'an array' : 'a ' + typeof o + ' (' + JSON.stringify(o).slice(0, 40) + ')'));
    if (o.points !== undefined && !Array.isArray(o.points)) return refuse('holds "points" that are not an array');
    const points = o.points || [];
    if (points.length > MAX_LINK_POINTS) return refuse(`holds ${points.length} points, more than the ${MAX_LINK_POINTS} a link may hold`);
    const bad = points.findIndex((p) => !(Array.isArray(p) && p.length === 2 && p.every((v) => typeof v === 'number' && Number.isFinite(v))));
    if (bad >= 0) return refuse(`holds point ${bad + 1} as ${JSON.stringify(points[bad])}, not two finite numbers`);
    const known = knownNames();
    const shown = [];
    for (const entry of Array.isArray(o.shown) ? o.shown : []) {
      const name = Array.isArray(entry) ? entry[0] : entry;
      const parameters = Array.isArray(entry) && entry[1] && typeof entry[1] === 'object' ? entry[1] : {};
      if (known.has(name)) shown.push({ name, parameters: Object.fromEntries(Object.entries(parameters).map(([k, v]) => [k, String(v)])) });
      else report('the link names an unknown method "' + name + '"; it is left out');
    }
    const perSpan = Number.isInteger(o.perSpan) && o.perSpan >= 2 && o.perSpan <= 64 ? o.perSpan : 16;
    return { points, closed: !!o.closed, shown, comb: o.comb !== false, locality: !!o.locality, perSpan };
  }

  function saveHash() {
    const h = encodeState(viewer.state);
    if (location.hash !== h) history.replaceState(null, '', h);
  }

  // A message for the user: on its own line, which the frames' status does not overwrite; it
  // stays until the user acts (a click, a key, a change of a control).
  function report(message) {
    viewer.errors.push(message);
    $('notice').textContent = message;
  }
  for (const type of ['pointerdown', 'keydown', 'change'])
    document.addEventListener(type, () => { $('notice').textContent = ''; }, { capture: true });

  // ---- colours: one per configuration, fixed by its place in the registry ------------------
  function colour(name, alpha) {
    const i = configIndex(name);
    const hue = (i * 137.508) % 360;  // the golden angle: neighbours far apart, no repeats
    return alpha === undefined ? `hsl(${hue.toFixed(1)} 70% 40%)` : `hsl(${hue.toFixed(1)} 70% 40% / ${alpha})`;
  }

  // ---- view transform ----------------------------------------------------------------------
  function fitView() {
    const pts = viewer.state.points;
    if (pts.length === 0) {
      view = { cx: 0, cy: 0, scale: 50 };
      return;
    }
    let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
    for (const [x, y] of pts) {
      x0 = Math.min(x0, x); x1 = Math.max(x1, x); y0 = Math.min(y0, y); y1 = Math.max(y1, y);
    }
    const w = Math.max(x1 - x0, 1e-9), h = Math.max(y1 - y0, 1e-9);
    // Room for the curves' overshoot and the combs: a fifth of the size on every side.
    const sx = (canvas.width - 2 * MARGIN) / (w * 1.4), sy = (canvas.height - 2 * MARGIN) / (h * 1.4);
    view = { cx: (x0 + x1) / 2, cy: (y0 + y1) / 2, scale: pts.length === 1 ? 50 : Math.min(sx, sy) };
  }
  const toScreen = (x, y) => [canvas.width / 2 + (x - view.cx) * view.scale, canvas.height / 2 - (y - view.cy) * view.scale];
  const toWorld = (px, py) => [view.cx + (px - canvas.width / 2) / view.scale, view.cy - (py - canvas.height / 2) / view.scale];

  function canvasPosition(event) {
    const r = canvas.getBoundingClientRect();
    return [(event.clientX - r.left) * canvas.width / r.width, (event.clientY - r.top) * canvas.height / r.height];
  }

  function pick(px, py) {
    let best = -1, bestD = PICK_RADIUS;
    viewer.state.points.forEach(([x, y], i) => {
      const [sx, sy] = toScreen(x, y);
      const d = Math.hypot(sx - px, sy - py);
      if (d <= bestD) { best = i; bestD = d; }
    });
    return best;
  }

  // ---- computing ---------------------------------------------------------------------------
  // Samples per span: the state's, but no more than one per SCREEN_STEP pixels of the median
  // chord on screen (a span of 100 points on this canvas is some ten pixels long: sixteen samples
  // there only cost time to compute and draw).
  const SCREEN_STEP = 3;
  function samplesPerSpan() {
    const s = viewer.state, n = s.points.length;
    if (n < 3) return s.perSpan;
    const chords = [];
    for (let i = 0; i + 1 < n; ++i) chords.push(Math.hypot(s.points[i + 1][0] - s.points[i][0], s.points[i + 1][1] - s.points[i][1]) * view.scale);
    chords.sort((a, b) => a - b);
    return Math.max(2, Math.min(s.perSpan, Math.ceil(chords[chords.length >> 1] / SCREEN_STEP)));
  }

  // The shown configurations of the registry, and the shown peers' curves drawn on the points (each
  // its pieces or its error), as the library's compare takes them.
  function shownParts() {
    const s = viewer.state;
    return {
      configurations: s.shown.filter((c) => !isPeer(c.name)),
      peers: s.shown.filter((c) => isPeer(c.name)).map((c) => viewer.peers.draw(c.name, s.points, s.closed)),
    };
  }

  function compute(options) {
    const s = viewer.state;
    if (s.points.length < 2 || s.shown.length === 0) return null;
    viewer.perSpan = samplesPerSpan();
    const r = viewer.module.compare({
      points: s.points.flat(), closed: s.closed, ...shownParts(), perSpan: viewer.perSpan,
      anchor: !!(options && options.anchor), motion: !!(options && options.motion),
      continuation: !!(options && options.drag),
    });
    if (!r.ok) {
      report(r.message);
      return null;
    }
    return r;
  }

  function update(options) {
    const t0 = performance.now();
    const r = compute(options);
    const t1 = performance.now();
    viewer.result = r;
    draw();
    const t2 = performance.now();
    const frame = { total: t2 - t0, compare: t1 - t0, draw: t2 - t1, points: viewer.state.points.length, methods: viewer.state.shown.length };
    viewer.frames.push(frame);
    if (viewer.frames.length > FRAME_HISTORY) viewer.frames.shift();
    const failing = r ? r.results.filter((x) => x.status !== 'ok').length : 0;
    $('status').textContent = `${frame.points} points, ${frame.methods} methods: frame ${frame.total.toFixed(1)} ms (library ${frame.compare.toFixed(1)} ms, drawing ${frame.draw.toFixed(1)} ms)` +
      (failing ? `; ${failing} without a curve (see the list)` : '') + (r && r.combScale > 0 ? `; comb: 1 unit of κ = ${fmt(r.combScale)} units of length` : '');
    saveHash();
    renderMethodNotes();
    if (options && (options.drag || options.anchor)) measuresAtPause();
    else requestMeasures();
    return r;
  }

  // ---- the measures, from the worker -------------------------------------------------------
  // A drag frame: the table is marked as behind the curves until the point rests or is released.
  function measuresAtPause() {
    $('measures').classList.add('stale');
    clearTimeout(pauseTimer);
    pauseTimer = setTimeout(requestMeasures, MEASURES_PAUSE);
  }

  function requestMeasures() {
    clearTimeout(pauseTimer);
    pauseTimer = null;
    const s = viewer.state;
    if (s.points.length < 2 || s.shown.length === 0) {
      viewer.measures = null;
      renderMeasures();
      return;
    }
    $('measures').classList.add('stale');
    workerNext = { id: ++requestId, points: s.points.flat(), closed: s.closed, ...shownParts() };
    pumpWorker();
  }

  function pumpWorker() {
    if (workerBusy || !workerNext) {
      if (!workerBusy && !workerNext) settledWaiters.splice(0).forEach((f) => f(viewer.measures));
      return;
    }
    workerBusy = true;
    worker.postMessage(workerNext);
    workerNext = null;
  }

  function onMeasures(event) {
    workerBusy = false;
    const m = event.data;
    if (!m.ok) report('measures: ' + m.message);
    else if (!viewer.measures || m.id > viewer.measures.id) {
      viewer.measures = m;
      renderMeasures();
    }
    pumpWorker();
  }
  // How many measures requests were made (for the tests: a drag's frames make none).
  viewer.measuresRequests = () => requestId;
  // Resolves when the table shows the current points (for the tests); a request waiting for a
  // pause is made now.
  viewer.measuresSettled = () => new Promise((resolve) => {
    if (pauseTimer !== null) requestMeasures();
    settledWaiters.push(resolve);
    pumpWorker();
  });

  function scheduleUpdate(motion) {
    pendingMotion = pendingMotion || motion;
    if (pendingFrame) return;
    pendingFrame = true;
    requestAnimationFrame(() => {
      pendingFrame = false;
      const m = pendingMotion;
      pendingMotion = false;
      update({ motion: m, drag: true });  // a drag frame: the iterative methods continue from the last frame
    });
  }

  // ---- drawing -----------------------------------------------------------------------------
  const fmt = (v) => (Math.abs(v) >= 1e-3 && Math.abs(v) < 1e4) || v === 0 ? String(+v.toPrecision(4)) : v.toExponential(3);

  function polyline(c, xy, stride, start, count) {
    c.beginPath();
    for (let k = 0; k < count; ++k) {
      const [sx, sy] = toScreen(xy[(start + k) * stride], xy[(start + k) * stride + 1]);
      if (k === 0) c.moveTo(sx, sy); else c.lineTo(sx, sy);
    }
    c.stroke();
  }

  function draw() {
    const s = viewer.state, r = viewer.result;
    ctx.clearRect(0, 0, canvas.width, canvas.height);
    ctx.lineJoin = 'round';
    if (r) {
      for (const m of r.results) {
        if (m.status !== 'ok' && m.status !== 'cusp' && m.status !== 'loops') continue;  // a flagged loop is drawn, its note says why
        const n = m.curve.length / 2;
        if (s.comb && m.comb.length) {
          ctx.strokeStyle = colour(m.name, 0.35);
          ctx.lineWidth = 1;
          ctx.beginPath();
          for (let k = 0; k < m.comb.length; k += 4) {
            const [a, b] = toScreen(m.comb[k], m.comb[k + 1]), [c, d] = toScreen(m.comb[k + 2], m.comb[k + 3]);
            ctx.moveTo(a, b); ctx.lineTo(c, d);
          }
          ctx.stroke();
          ctx.strokeStyle = colour(m.name, 0.6);
          ctx.beginPath();
          for (let k = 0; k < m.comb.length; k += 4) {
            const [c, d] = toScreen(m.comb[k + 2], m.comb[k + 3]);
            if (k === 0) ctx.moveTo(c, d); else ctx.lineTo(c, d);
          }
          ctx.stroke();
        }
        if (s.locality && m.motion) {
          // A span shaded by how far it moved since the drag began: darker is farther (log scale,
          // from compare's locality tolerance 1e-9 of the diagonal up to the whole diagonal).
          // Eight shades, one path each.
          const per = viewer.perSpan, levels = new Map();
          for (let k = 0; k < m.motion.length; ++k) {
            if (!(m.motion[k] > MOTION_FLOOR)) continue;
            const level = Math.min(7, Math.floor(8 * (Math.log10(m.motion[k]) + 9) / 9));
            if (!levels.has(level)) levels.set(level, []);
            levels.get(level).push(k);
          }
          ctx.lineWidth = 9;
          for (const [level, spans] of levels) {
            ctx.strokeStyle = colour(m.name, 0.12 + 0.63 * (level + 1) / 8);
            ctx.beginPath();
            for (const k of spans) {
              for (let j = 0; j <= per && k * per + j < n; ++j) {
                const [sx, sy] = toScreen(m.curve[2 * (k * per + j)], m.curve[2 * (k * per + j) + 1]);
                if (j === 0) ctx.moveTo(sx, sy); else ctx.lineTo(sx, sy);
              }
            }
            ctx.stroke();
          }
        }
        ctx.strokeStyle = colour(m.name);
        ctx.lineWidth = 2;
        polyline(ctx, m.curve, 2, 0, n);
      }
    }
    // The data points above the curves; the dragged one filled.
    s.points.forEach(([x, y], i) => {
      const [sx, sy] = toScreen(x, y);
      ctx.beginPath();
      ctx.arc(sx, sy, 4.5, 0, 2 * Math.PI);
      ctx.fillStyle = i === dragging ? '#000' : '#fff';
      ctx.fill();
      ctx.strokeStyle = '#000';
      ctx.lineWidth = 1.5;
      ctx.stroke();
    });
    drawHoverMarkers();
    drawProfiles();
  }

  // The κ(s) strip: every method's curvature against its own arc length, on one κ axis.
  function profileRange() {
    const r = viewer.result;
    let sMax = 0, kAbs = [];
    for (const m of r ? r.results : []) {
      for (let k = 0; k < m.profile.length; k += 2) {
        sMax = Math.max(sMax, m.profile[k]);
        kAbs.push(Math.abs(m.profile[k + 1]));
      }
    }
    kAbs.sort((a, b) => a - b);
    // The axis shows up to twice the 95th percentile of |κ| (a spike is clipped, not flattening the rest).
    const p95 = kAbs.length ? kAbs[Math.min(kAbs.length - 1, Math.floor(0.95 * kAbs.length))] : 1;
    const kMax = Math.min(kAbs.length ? kAbs[kAbs.length - 1] : 1, 2 * p95) || 1;
    return { sMax: sMax || 1, kMax };
  }

  function drawProfiles() {
    const r = viewer.result, W = profileCanvas.width, H = profileCanvas.height, L = 48, R = 8, T = 8, B = 20;
    pctx.clearRect(0, 0, W, H);
    pctx.font = '11px sans-serif';
    pctx.fillStyle = '#444';
    if (!r) {
      pctx.fillText('κ(s): place at least two points and choose a method', L, H / 2);
      return;
    }
    const { sMax, kMax } = profileRange();
    const X = (sv) => L + (W - L - R) * sv / sMax, Y = (kv) => T + (H - T - B) * (1 - (kv + kMax) / (2 * kMax));
    pctx.strokeStyle = '#bbb';
    pctx.lineWidth = 1;
    pctx.beginPath(); pctx.moveTo(L, Y(0)); pctx.lineTo(W - R, Y(0)); pctx.moveTo(L, T); pctx.lineTo(L, H - B); pctx.stroke();
    pctx.fillText(`κ ${fmt(kMax)}`, 2, T + 8);
    pctx.fillText(`${fmt(-kMax)}`, 2, H - B);
    pctx.fillText('0', L - 12, Y(0) + 4);
    pctx.fillText(`arc length s (0 … ${fmt(sMax)})`, W / 2 - 50, H - 4);
    pctx.save();
    pctx.beginPath(); pctx.rect(L, T, W - L - R, H - T - B); pctx.clip();
    for (const m of r.results) {
      if (!m.profile.length) continue;
      pctx.strokeStyle = colour(m.name);
      pctx.lineWidth = 1.5;
      pctx.beginPath();
      for (let k = 0; k < m.profile.length; k += 2) {
        const x = X(m.profile[k]), y = Y(Math.max(-2 * kMax, Math.min(2 * kMax, m.profile[k + 1])));
        if (k === 0) pctx.moveTo(x, y); else pctx.lineTo(x, y);
      }
      pctx.stroke();
    }
    if (hoverS !== null) {
      pctx.strokeStyle = '#000';
      pctx.beginPath(); pctx.moveTo(X(hoverS), T); pctx.lineTo(X(hoverS), H - B); pctx.stroke();
    }
    pctx.restore();
  }

  // Hover on the strip: at arc length s, each method's curve point (the profile sample nearest s,
  // mapped to its curve sample: profiles hold perSpan + 1 samples per span, curves perSpan).
  function hoverSamples() {
    const r = viewer.result, out = [];
    if (!r || hoverS === null) return out;
    const per = viewer.perSpan;
    for (const m of r.results) {
      if (!m.profile.length) continue;
      let best = 0;
      for (let k = 0; k < m.profile.length; k += 2) if (Math.abs(m.profile[k] - hoverS) < Math.abs(m.profile[best] - hoverS)) best = k;
      const i = best / 2, span = Math.floor(i / (per + 1)), j = i % (per + 1);
      const c = Math.min(span * per + j, m.curve.length / 2 - 1);
      out.push({ name: m.name, x: m.curve[2 * c], y: m.curve[2 * c + 1], kappa: m.profile[best + 1] });
    }
    return out;
  }

  function drawHoverMarkers() {
    const marks = hoverSamples();
    for (const h of marks) {
      const [sx, sy] = toScreen(h.x, h.y);
      ctx.beginPath();
      ctx.arc(sx, sy, 6, 0, 2 * Math.PI);
      ctx.strokeStyle = colour(h.name);
      ctx.lineWidth = 2;
      ctx.stroke();
    }
    $('hover').textContent = marks.length ? `s = ${fmt(hoverS)}: ` + marks.map((h) => `${h.name} κ = ${fmt(h.kappa)}`).join(', ') : '';
  }

  // ---- the measures table and the method list ------------------------------------------------
  function renderMeasures() {
    const r = viewer.measures, table = $('measures');
    table.textContent = '';
    if (pauseTimer === null && !workerNext && !workerBusy) table.classList.remove('stale');
    if (!r) return;
    const head = table.insertRow();
    for (const h of r.header) {
      const th = document.createElement('th');
      th.textContent = h;
      head.appendChild(th);
    }
    r.rows.forEach((row, i) => {
      const tr = table.insertRow();
      row.forEach((cell, k) => {
        const td = tr.insertCell();
        td.textContent = cell;
        if (k === 0) td.style.color = colour(r.names[i]);
      });
    });
  }

  function shownEntry(name) { return viewer.state.shown.find((c) => c.name === name); }

  // The list's item of a configuration or peer `name`: its box (shown or not), colour and name,
  // `title` on hover; the caller appends what follows the label.
  function methodItem(name, title) {
    const li = document.createElement('li');
    li.dataset.name = name;
    const label = document.createElement('label');
    const box = document.createElement('input');
    box.type = 'checkbox';
    box.checked = !!shownEntry(name);
    box.addEventListener('change', () => {
      if (box.checked) viewer.state.shown.push({ name, parameters: {} });
      else viewer.state.shown = viewer.state.shown.filter((e) => e.name !== name);
      viewer.state.shown.sort((a, b) => configIndex(a.name) - configIndex(b.name));
      renderMethods();
      update();
    });
    const swatch = document.createElement('span');
    swatch.className = 'swatch';
    swatch.style.background = colour(name);
    label.append(box, swatch, name);
    label.title = title;
    li.appendChild(label);
    return li;
  }

  function renderMethods() {
    const list = $('methods');
    list.textContent = '';
    const methods = new Map(viewer.registry.methods.map((m) => [m.name, m]));
    for (const c of viewer.registry.configurations) {
      const m = methods.get(c.method);
      const li = methodItem(c.name, `${m.summary} [${m.paper}, ${m.source}]`);
      const entry = shownEntry(c.name);
      // Parameters a browser can set on planar points (no files: a table file is the command's
      // and Python's; none of those the registry marks as for 3-D points only).
      const settable = m.parameters.filter((p) => p.type !== 'text' && !p.spaceOnly);
      if (entry && settable.length) {
        const box2 = document.createElement('div');
        box2.className = 'parameters';
        for (const p of settable) {
          const row = document.createElement('label');
          row.title = p.help;
          const current = entry.parameters[p.name] ?? c.values[p.name] ?? p.default;
          let input;
          if (p.type === 'choice') {
            input = document.createElement('select');
            for (const choice of p.choices) input.add(new Option(choice, choice, false, choice === current));
          } else {
            input = document.createElement('input');
            input.type = p.type === 'vector' ? 'text' : 'number';
            if (p.type === 'integer') input.step = '1';
            if (p.type !== 'vector' && Number.isFinite(p.lower)) input.min = p.lower;
            if (p.type !== 'vector' && Number.isFinite(p.upper)) input.max = p.upper;
            input.value = current;
          }
          input.dataset.parameter = p.name;
          input.addEventListener('change', () => {
            if (input.value === (c.values[p.name] ?? p.default)) delete entry.parameters[p.name];
            else entry.parameters[p.name] = input.value;
            update();
          });
          row.append(p.name, input);
          box2.appendChild(row);
        }
        li.appendChild(box2);
      }
      const note = document.createElement('div');
      note.className = 'note';
      li.appendChild(note);
      list.appendChild(li);
    }
    // The peers, drawn in this page by their own libraries.
    const heading = document.createElement('li');
    heading.className = 'group';
    heading.textContent = viewer.peers.list.length ? 'Other libraries, run in this page as their users call them'
      : `Other libraries: not loaded (${viewer.peers.reason})`;
    list.appendChild(heading);
    for (const p of viewer.peers.list) {
      const li = methodItem(p.name, `${p.library}, as its users call it (the drawing its adapter under peers/${p.peer}/ runs)`);
      const note = document.createElement('div');
      note.className = 'note';
      li.appendChild(note);
      list.appendChild(li);
    }
    renderExportChoices();
  }

  // The place of a name in the list: the registry's configurations, then the peers.
  function configIndex(name) {
    const i = viewer.registry.configurations.findIndex((c) => c.name === name);
    if (i >= 0) return i;
    const k = viewer.peers.list.findIndex((p) => p.name === name);
    return k < 0 ? -1 : viewer.registry.configurations.length + k;
  }

  function renderMethodNotes() {
    const r = viewer.result;
    for (const li of $('methods').children) {
      const note = li.querySelector('.note');
      if (!note) continue;  // a group's heading
      const m = r ? r.results.find((x) => x.name === li.dataset.name) : null;
      note.textContent = m && m.status !== 'ok' ? `${m.status}: ${m.note}` : '';
    }
  }

  function renderExportChoices() {
    const sel = $('export-method'), previous = sel.value;
    sel.textContent = '';
    for (const c of viewer.state.shown) sel.add(new Option(c.name, c.name, false, c.name === previous));
    const fsel = $('export-format');
    if (!fsel.options.length) for (const f of viewer.registry.formats) fsel.add(new Option(f, f));
  }

  // ---- exports -------------------------------------------------------------------------------
  // The text of one shown method's curve in a format, written by the library's writer.
  viewer.exportText = function (name, format) {
    const s = viewer.state;
    const request = { points: s.points.flat(), closed: s.closed, format, comb: s.comb };
    // A peer's curve: its pieces as the page's peer draws them (or its error), in their own parameter.
    if (isPeer(name)) return viewer.module.exportCurve({ ...request, ...viewer.peers.draw(name, s.points, s.closed) });
    const entry = shownEntry(name) || { name, parameters: {} };
    return viewer.module.exportCurve({ ...request, name, parameters: entry.parameters });
  };

  function download() {
    const name = $('export-method').value, format = $('export-format').value;
    if (!name) {
      $('export-message').textContent = 'choose a shown method first';
      return;
    }
    const r = viewer.exportText(name, format);
    if (!r.ok) {
      $('export-message').textContent = r.message;
      return;
    }
    const mime = { svg: 'image/svg+xml', json: 'application/json', csv: 'text/csv', dxf: 'application/dxf' }[format] || 'text/plain';
    const a = document.createElement('a');
    a.href = URL.createObjectURL(new Blob([r.text], { type: mime }));
    a.download = `${name}.${format}`;
    document.body.appendChild(a);
    a.click();
    a.remove();
    setTimeout(() => URL.revokeObjectURL(a.href), 1000);
    $('export-message').textContent = `${a.download}: ${r.text.length} bytes`;
  }

  // ---- CSV points ----------------------------------------------------------------------------
  // Read by the library's own point reader (the cagd command's: header, BOM, CRLF, and an error
  // naming the source and line of anything that does not parse).
  viewer.parseCsv = function (text, source = 'pasted points') {
    const r = viewer.module.readPoints(text, source);
    if (!r.ok) throw new Error(r.message);
    return r.points;
  };

  function usePoints(points) {
    viewer.state.points = points;
    fitView();
    update();
  }

  // ---- events --------------------------------------------------------------------------------
  function bind() {
    canvas.addEventListener('contextmenu', (e) => e.preventDefault());
    canvas.addEventListener('mousedown', (e) => {
      const [px, py] = canvasPosition(e);
      const i = pick(px, py);
      if (e.button === 2 || (e.button === 0 && e.altKey)) {
        if (i >= 0) {
          viewer.state.points.splice(i, 1);
          update();
        }
        return;
      }
      if (e.button !== 0) return;
      if (i >= 0) {
        dragging = i;
        update({ anchor: true, motion: viewer.state.locality });
        return;
      }
      viewer.state.points.push(toWorld(px, py));
      update();
    });
    window.addEventListener('mousemove', (e) => {
      if (dragging < 0) return;
      const [px, py] = canvasPosition(e);
      viewer.state.points[dragging] = toWorld(px, py);
      scheduleUpdate(viewer.state.locality);
    });
    window.addEventListener('mouseup', () => {
      if (dragging < 0) return;
      dragging = -1;
      update({ motion: viewer.state.locality });
    });
    profileCanvas.addEventListener('mousemove', (e) => {
      if (!viewer.result) return;
      const r = profileCanvas.getBoundingClientRect();
      const x = (e.clientX - r.left) * profileCanvas.width / r.width;
      hoverS = Math.max(0, Math.min(1, (x - 48) / (profileCanvas.width - 56))) * profileRange().sMax;
      draw();
    });
    profileCanvas.addEventListener('mouseleave', () => {
      hoverS = null;
      draw();
    });
    $('closed').addEventListener('change', (e) => { viewer.state.closed = e.target.checked; update(); });
    $('comb').addEventListener('change', (e) => { viewer.state.comb = e.target.checked; update(); });
    $('locality').addEventListener('change', (e) => { viewer.state.locality = e.target.checked; update(); });
    $('per-span').addEventListener('change', (e) => {
      const v = Number(e.target.value);
      if (Number.isInteger(v) && v >= 2 && v <= 64) viewer.state.perSpan = v;
      else e.target.value = viewer.state.perSpan;
      update();
    });
    $('fit').addEventListener('click', () => { fitView(); draw(); });
    $('clear').addEventListener('click', () => usePoints([]));
    $('example').addEventListener('click', () => usePoints(EXAMPLE.map((p) => p.slice())));
    $('all-methods').addEventListener('click', () => {
      viewer.state.shown = viewer.registry.configurations.map((c) => c.name).concat(viewer.peers.list.map((p) => p.name))
        .map((name) => shownEntry(name) || { name, parameters: {} });
      renderMethods();
      update();
    });
    $('no-methods').addEventListener('click', () => { viewer.state.shown = []; renderMethods(); update(); });
    $('load-csv').addEventListener('click', () => {
      try {
        usePoints(viewer.parseCsv($('csv').value));
      } catch (e) {
        report(e.message);
      }
    });
    $('csv-file').addEventListener('change', async (e) => {
      const f = e.target.files[0];
      if (!f) return;
      try {
        usePoints(viewer.parseCsv(await f.text(), f.name));
      } catch (err) {
        report(err.message);
      }
    });
    $('export').addEventListener('click', download);
    window.addEventListener('hashchange', () => {
      const s = decodeState(location.hash);
      if (s) applyState(s);
    });
  }

  function applyState(s) {
    viewer.state = s;
    $('closed').checked = s.closed;
    $('comb').checked = s.comb;
    $('locality').checked = s.locality;
    $('per-span').value = s.perSpan;
    renderMethods();
    fitView();
    return update();
  }
  // For the tests and the console: set the whole state (as the hash holds it) and redraw.
  viewer.setState = (s) => applyState(Object.assign(defaultState(), s));
  // One frame of a drag, as the mouse makes it (for the tests' frame timing): point i moves to p;
  // the first frame of a drag also keeps the curves as the locality view's anchor.
  viewer.redrawMoving = (i, p) => {
    if (viewer.movingPoint !== i) {
      viewer.movingPoint = i;
      update({ anchor: true, motion: viewer.state.locality });
    }
    viewer.state.points[i] = p;
    return update({ motion: viewer.state.locality, drag: true });
  };
  // A data point's position in the page's CSS pixels (for a test's real mouse drag).
  viewer.pagePosition = (i) => {
    const [sx, sy] = toScreen(...viewer.state.points[i]);
    const r = canvas.getBoundingClientRect();
    return { x: r.left + sx * r.width / canvas.width, y: r.top + sy * r.height / canvas.height };
  };

  viewer.ready = createCagdModule().then(async (module) => {
    viewer.module = module;
    viewer.registry = module.registry();
    try {
      viewer.peers = { ...(await (await import('./peers.mjs')).loadPeers()), reason: '' };
    } catch (e) {
      viewer.peers = { list: [], draw: null, reason: e.message };
      report('the JavaScript peers did not load: ' + e.message);
    }
    worker = new Worker('measures-worker.js');
    worker.onmessage = onMeasures;
    worker.onerror = (e) => report('the measures worker failed: ' + e.message);
    bind();
    const fromHash = decodeState(location.hash);
    applyState(fromHash || defaultState());
    return viewer;
  }, (e) => {
    report('the WebAssembly module did not load: ' + e);
    throw e;
  });
})();
