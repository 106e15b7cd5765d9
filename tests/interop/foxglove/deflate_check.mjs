#!/usr/bin/env node
// permessage-deflate with Foxglove's own client (issue 56): FoxgloveClient
// (@foxglove/ws-protocol) over `ws` with perMessageDeflate, against a fleetlink hub.
//
// Two deflate clients subscribe to the robot's point cloud: each must get it compressed
// (RSV1, counted where `ws` inflates a message), decode it from CDR with the right point
// count, and see its own subscription id (the per-subscriber header travels in front of
// the body compressed once for both). A third client without deflate gets the same
// content uncompressed. The hub's client listing says which connection negotiated it.
// Exits 0 when every check passed, 1 naming the failed check. Every wait is bounded.

import { parseArgs } from "node:util";
import { createRequire } from "node:module";
import foxglove from "@foxglove/ws-protocol";
import { parse } from "@foxglove/rosmsg";
import { MessageReader } from "@foxglove/rosmsg2-serialization";
import WebSocket from "ws";
import { CheckFailed, check, ok, sleep, until as waitUntil } from "./checks.mjs";

const { FoxgloveClient } = foxglove;
const require = createRequire(import.meta.url);
// The module `ws` itself loads (same file, same instance): counts inflated messages.
const PerMessageDeflate = require(new URL("./node_modules/ws/lib/permessage-deflate.js", import.meta.url).pathname);
let inflated = 0;
const decompress = PerMessageDeflate.prototype.decompress;
PerMessageDeflate.prototype.decompress = function (data, fin, cb) {
  if (fin) inflated++;
  return decompress.call(this, data, fin, cb);
};

const TIMEOUT_MS = 15_000;
const { values: args } = parseArgs({
  options: {
    url: { type: "string" },
    api: { type: "string" },
    token: { type: "string" },
    robot: { type: "string", default: "robot1" },
    points: { type: "string", default: "1000" },
  },
});
if (!args.url || !args.api || !args.token) {
  console.error("usage: deflate_check.mjs --url ws://HOST:PORT/?token=T --api http://HOST:PORT --token T [--robot robot1] [--points N]");
  process.exit(2);
}
const points = Number(args.points);

const until = (get, what, ms = TIMEOUT_MS) => waitUntil(get, what, ms);

async function connect(perMessageDeflate) {
  const ws = new WebSocket(args.url, [FoxgloveClient.SUPPORTED_SUBPROTOCOL], { perMessageDeflate });
  const client = new FoxgloveClient({ ws });
  const seen = { ws, client, channels: new Map(), messages: [] };
  client.on("advertise", (chs) => chs.forEach((c) => seen.channels.set(c.id, c)));
  client.on("message", (m) => seen.messages.push(m));
  await new Promise((resolve, reject) => {
    ws.once("open", resolve);
    ws.once("error", reject);
  });
  return seen;
}

async function cloudOf(seen) {
  const topic = `/${args.robot}/points`;
  const ch = await until(() => [...seen.channels.values()].find((c) => c.topic === topic), `channel ${topic}`);
  const sub = seen.client.subscribe(ch.id);
  const m = await until(() => seen.messages.find((x) => x.subscriptionId === sub), `a PointCloud2 on subscription ${sub}`);
  const c = new MessageReader(parse(ch.schema, { ros2: true })).readMessage(
    new Uint8Array(m.data.buffer, m.data.byteOffset, m.data.byteLength),
  );
  check(c.width * c.height === points, `PointCloud2 has ${c.width * c.height} points, want ${points}`);
  check(c.data.length === c.row_step * c.height, `PointCloud2 data ${c.data.length} bytes, row_step ${c.row_step}`);
  return { sub, bytes: m.data.byteLength };
}

async function main() {
  const a = await connect(true);
  const b = await connect(true);
  // Subscription ids differ per client: b subscribes to something else first.
  const ext = a.ws._extensions?.["permessage-deflate"];
  check(a.ws.extensions.includes("permessage-deflate") && ext, `no permessage-deflate negotiated: '${a.ws.extensions}'`);
  check(ext.params.server_no_context_takeover === true, `the hub did not answer server_no_context_takeover: ${JSON.stringify(ext.params)}`);
  ok(`negotiated ${JSON.stringify(ext.params)}`);
  const before = inflated;
  const [ca, cb] = await Promise.all([cloudOf(a), cloudOf(b)]);
  check(inflated - before >= 2, `only ${inflated - before} compressed messages arrived`);
  ok(`two deflate clients decoded the cloud (${points} points, ${ca.bytes} bytes) from compressed messages on subscriptions ${ca.sub} and ${cb.sub}`);
  const plain = await connect(false);
  check(!plain.ws.extensions.includes("permessage-deflate"), `deflate negotiated although not offered: ${plain.ws.extensions}`);
  const cp = await cloudOf(plain);
  ok(`a client without deflate decoded the same cloud (${cp.bytes} bytes) uncompressed`);
  const res = await fetch(`${args.api}/api/v1/clients`, { headers: { Authorization: `Bearer ${args.token}` } });
  const listed = (await res.json()).clients.filter((c) => c.kind === "foxglove");
  const on = listed.filter((c) => c.deflate).length;
  check(on === 2 && listed.length === 3, `the hub lists ${on} of ${listed.length} Foxglove clients with deflate, want 2 of 3`);
  ok("the hub's client listing shows deflate on the two that negotiated it");
  for (const s of [a, b, plain]) s.client.close();
}

main().then(
  () => process.exit(0),
  (e) => {
    console.error(`FAIL: ${e instanceof CheckFailed ? e.message : e.stack}`);
    process.exit(1);
  },
);
