#!/usr/bin/env node
// permessage-deflate with roslib (roslibjs) under Node (issue 56). roslib's Node
// transport is `ws`, which offers the extension by default, as browsers do.
//
// For each --url (the hub, the agent's local listener): the robot's point cloud (JSON)
// arrives whole (its point count) and compressed (counted where `ws` inflates a
// message), on a connection that negotiated permessage-deflate with
// server_no_context_takeover. Exits 0 when every check passed, 1 naming the failed check.

import { parseArgs } from "node:util";
import { createRequire } from "node:module";
import { Ros, Topic } from "roslib";

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
    url: { type: "string", multiple: true },
    points: { type: "string", default: "2000" },
  },
});
if (!args.url?.length) {
  console.error("usage: deflate_roslib_check.mjs --url ws://HOST:PORT/=/cloud/topic [--url ...] [--points N]");
  process.exit(2);
}
const points = Number(args.points);

class CheckFailed extends Error {}
function check(cond, what) {
  if (!cond) throw new CheckFailed(what);
}
const ok = (what) => console.log(`  ok: ${what}`);

function within(promise, what) {
  return Promise.race([
    promise,
    new Promise((_, reject) => setTimeout(() => reject(new CheckFailed(`timed out waiting for ${what}`)), TIMEOUT_MS)),
  ]);
}

async function checkUrl(url, topic) {
  const ros = new Ros({ url });
  await within(new Promise((resolve, reject) => {
    ros.on("connection", resolve);
    ros.on("error", (e) => reject(new CheckFailed(`connect ${url}: ${e?.message ?? e}`)));
  }), `a connection to ${url}`);
  const ws = ros.transport.socket;
  const ext = ws._extensions?.["permessage-deflate"];
  check(ext, `no permessage-deflate negotiated with ${url}: '${ws.extensions}'`);
  check(ext.params.server_no_context_takeover === true, `no server_no_context_takeover: ${JSON.stringify(ext.params)}`);
  ok(`negotiated ${JSON.stringify(ext.params)}`);
  const before = inflated;
  const cloud = new Topic({ ros, name: topic, messageType: "sensor_msgs/msg/PointCloud2" });
  const m = await within(new Promise((resolve) => cloud.subscribe(resolve)), `a message on ${topic}`);
  cloud.unsubscribe();
  check(m.width * m.height === points, `${topic} has ${m.width * m.height} points, want ${points}`);
  check(inflated > before, `${topic} did not arrive compressed`);
  ok(`${topic}: ${points} points, arrived compressed (${inflated - before} inflated)`);
  ros.close();
}

async function main() {
  for (const u of args.url) {
    const at = u.lastIndexOf("=");
    await checkUrl(u.slice(0, at), u.slice(at + 1));
  }
}

main().then(
  () => process.exit(0),
  (e) => {
    console.error(`FAIL: ${e instanceof CheckFailed ? e.message : e.stack}`);
    process.exit(1);
  },
);
