#!/usr/bin/env node
// A Foxglove viewer for the viewers suite: @foxglove/ws-protocol's FoxgloveClient (the
// Foxglove suite's node packages) subscribing to one topic's channel. Writes
// `msg <count>` per message and `closed` when the connection ends; runs until killed.
//
// Usage: foxglove_viewer.mjs --url ws://HOST:PORT/?token=T --topic /robot1/points
//        --packages DIR (a directory whose node_modules has @foxglove/ws-protocol and ws)

import { appendFileSync } from "node:fs";
import { createRequire } from "node:module";
import { join } from "node:path";
import { parseArgs } from "node:util";

const { values: args } = parseArgs({
  options: {
    url: { type: "string" },
    topic: { type: "string" },
    packages: { type: "string" },
    log: { type: "string" },
  },
});
const require = createRequire(join(args.packages, "package.json"));
const { FoxgloveClient } = require("@foxglove/ws-protocol");
const WebSocket = require("ws");

const log = (line) => appendFileSync(args.log, `${line}\n`);
const client = new FoxgloveClient({
  ws: new WebSocket(args.url, [FoxgloveClient.SUPPORTED_SUBPROTOCOL]),
});
let count = 0;
client.on("advertise", (channels) => {
  for (const c of channels) {
    if (c.topic === args.topic) client.subscribe(c.id);
  }
});
client.on("message", () => {
  count += 1;
  log(`msg ${count}`);
});
client.on("close", () => log("closed"));
client.on("error", (e) => log(`error ${e?.message ?? e}`));
