// The measures table off the page's thread: compare's measures take tens of milliseconds per
// method at 100 points, so the page draws every frame itself and asks this worker for the table,
// the newest request only (viewer.js coalesces them).
'use strict';
importScripts('cagd.js');
const ready = createCagdModule();
onmessage = async (event) => {
  const module = await ready;
  const request = event.data;
  const r = module.compare(Object.assign({}, request, { measures: true, figure: false, anchor: false, motion: false }));
  postMessage(r.ok ? { id: request.id, ok: true, header: r.header, rows: r.rows, names: r.results.map((x) => x.name) } : { id: request.id, ok: false, message: r.message });
};
