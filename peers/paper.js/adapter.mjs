// paper.js as its users call it (pieces.mjs: the drawing, shared with the viewer), on paper-core
// (paper.js without PaperScript, the build for Node.js), run by peers/run.
import { createRequire } from "node:module";
import { document, serve } from "../protocol.mjs";
import { configurations, pieces } from "./pieces.mjs";

const paper = createRequire(import.meta.url)("paper/dist/paper-core.js");
paper.setup(new paper.Size(1, 1));
const peer = { name: "paper.js", version: paper.version, configurations };

serve(peer, (request) =>
  document(peer, request, pieces(paper, request.configuration, request.points, request.closed)),
);
