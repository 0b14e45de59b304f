// d3-shape as its users call it (pieces.mjs: the drawing, shared with the viewer), run by peers/run.
import * as d3 from "d3-shape";
import { document, packageVersion, serve } from "../protocol.mjs";
import { configurations, pieces } from "./pieces.mjs";

const peer = { name: "d3-shape", version: packageVersion("d3-shape"), configurations };

serve(peer, (request) =>
  document(peer, request, pieces(d3, request.configuration, request.points, request.closed)),
);
