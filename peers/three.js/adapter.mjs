// three.js as its users call it (pieces.mjs: the drawing, shared with the viewer), run by peers/run.
import * as THREE from "three";
import { document, packageVersion, serve } from "../protocol.mjs";
import { configurations, pieces } from "./pieces.mjs";

const peer = { name: "three.js", version: packageVersion("three"), configurations };

serve(peer, (request) =>
  document(peer, request, pieces(THREE, request.configuration, request.points, request.closed)),
);
