#!/usr/bin/env node
// A Foxglove client (@foxglove/ws-protocol's FoxgloveClient) reading a parameter that a
// deny rule hides from it, by another spelling (tests/interop/security): getParameters
// of --hidden (e.g. "/robot1/secret_param/") must return no value for it, while
// getParameters of --shown returns its value (the control: the path works).
//
// Exits 0 when the hidden parameter stayed hidden and the shown one was read, 1 otherwise.

import { parseArgs } from "node:util";
import foxglove from "@foxglove/ws-protocol";
import WebSocket from "ws";

const { FoxgloveClient } = foxglove;
const TIMEOUT_MS = 10_000;
const { values: args } = parseArgs({
  options: { url: { type: "string" }, hidden: { type: "string" }, shown: { type: "string" } },
});
if (!args.url || !args.hidden || !args.shown) {
  console.error("usage: foxglove_param_attack.mjs --url ws://HOST:PORT/?token=T --hidden NAME --shown NAME");
  process.exit(2);
}
const strip = (n) => n.replace(/^\/?/, "/").replace(/\/+$/, "");

const client = new FoxgloveClient({
  ws: new WebSocket(args.url, [FoxgloveClient.SUPPORTED_SUBPROTOCOL]),
});
const answers = [];
client.on("parameterValues", (m) => answers.push(m));
const opened = new Promise((resolve, reject) => {
  client.on("serverInfo", resolve);
  client.on("error", reject);
});
const until = async (pred, what) => {
  const end = Date.now() + TIMEOUT_MS;
  while (Date.now() < end) {
    const hit = pred();
    if (hit) return hit;
    await new Promise((r) => setTimeout(r, 50));
  }
  throw new Error(`${what}: nothing within ${TIMEOUT_MS} ms`);
};

let failed = false;
try {
  await opened;
  client.getParameters([args.hidden], "hidden");
  client.getParameters([args.shown], "shown");
  const shown = await until(() => answers.find((a) => a.id === "shown"), "the shown parameter");
  const hidden = await until(() => answers.find((a) => a.id === "hidden"), "the hidden parameter's answer");
  const leaked = hidden.parameters.filter((p) => strip(p.name) === strip(args.hidden));
  if (leaked.length) {
    failed = true;
    console.log(`FAIL: getParameters ${args.hidden} returned ${JSON.stringify(leaked)}`);
  } else {
    console.log(`  ok: getParameters ${args.hidden} returned no value`);
  }
  if (!shown.parameters.some((p) => strip(p.name) === strip(args.shown))) {
    failed = true;
    console.log(`FAIL: control: getParameters ${args.shown} returned ${JSON.stringify(shown.parameters)}`);
  } else {
    console.log(`  ok: getParameters ${args.shown} returned its value`);
  }
} catch (e) {
  failed = true;
  console.log(`FAIL: ${e.message}`);
}
client.close();
process.exit(failed ? 1 : 0);
