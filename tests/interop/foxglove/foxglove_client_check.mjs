#!/usr/bin/env node
// What Foxglove and Lichtblick do with a Foxglove WebSocket server, done with
// @foxglove/ws-protocol's own FoxgloveClient (npm) against a fleetlink hub, with one
// subprotocol (--subprotocol):
//
//   1. the hub answers with that subprotocol and a serverInfo naming the capabilities it
//      implements (clientPublish, services, parameters) and a sessionId;
//   2. the robot's topics are channels whose schemas parse with @foxglove/rosmsg; the
//      laser scan and the point cloud are subscribed and their MessageData decoded with
//      @foxglove/rosmsg2-serialization from the advertised schema (values sane);
//   3. a geometry_msgs/Twist client-published on /<robot>/cmd_vel (in --publish-encoding)
//      reaches the robot: a rosbridge client on the agent's local listener receives it;
//   4. the robot's /get_status service (std_srvs/srv/Trigger) is called (in
//      --call-encoding) and answers success;
//   5. a hub parameter (--param NAME=JSON, set beforehand) is read with getParameters;
//   6. with --denied-url (a token without rights): no channel, no service, a publish is
//      refused with a status error and does not reach the robot, a call fails.
//
// Exits 0 when every check passed, 1 naming the failed check. Every wait is bounded.

import { parseArgs } from "node:util";
import { isDeepStrictEqual } from "node:util";
import foxglove from "@foxglove/ws-protocol";
import { parse } from "@foxglove/rosmsg";
import { MessageReader, MessageWriter } from "@foxglove/rosmsg2-serialization";
import WebSocket from "ws";
import { CheckFailed, check, ok, sleep, until as waitUntil } from "./checks.mjs";

// A CommonJS package: its named exports come through the default one.
const { FoxgloveClient } = foxglove;

const TIMEOUT_MS = 10_000;
const { values: args } = parseArgs({
  options: {
    url: { type: "string" },
    "denied-url": { type: "string" },
    "local-url": { type: "string" },
    subprotocol: { type: "string", default: "foxglove.websocket.v1" },
    robot: { type: "string", default: "robot1" },
    "scan-ranges": { type: "string", default: "720" },
    points: { type: "string", default: "2000" },
    "publish-encoding": { type: "string", default: "cdr" },
    "call-encoding": { type: "string", default: "json" },
    param: { type: "string" },
  },
});
if (!args.url || !args["local-url"]) {
  console.error("usage: foxglove_client_check.mjs --url ws://HOST:PORT/?token=T --local-url ws://AGENT/ [--denied-url URL] [--subprotocol P] [--param NAME=JSON]");
  process.exit(2);
}
const robot = args.robot;
const scanRanges = Number(args["scan-ranges"]);
const points = Number(args.points);


/** Resolves with `get()` once it is truthy; fails naming `what` after `ms`. */
const until = (get, what, ms = TIMEOUT_MS) => waitUntil(get, what, ms);

/** A FoxgloveClient over `ws` with everything it hears kept for the checks. */
async function connect(url, subprotocol) {
  const ws = new WebSocket(url, [subprotocol]);
  const client = new FoxgloveClient({ ws });
  const seen = {
    ws,
    client,
    serverInfo: undefined,
    channels: new Map(),
    services: new Map(),
    statuses: [],
    messages: [],
    responses: [],
    failures: [],
    parameters: [],
    errors: [],
  };
  client.on("serverInfo", (m) => (seen.serverInfo = m));
  client.on("advertise", (chs) => chs.forEach((c) => seen.channels.set(c.id, c)));
  client.on("unadvertise", (ids) => ids.forEach((id) => seen.channels.delete(id)));
  client.on("advertiseServices", (ss) => ss.forEach((s) => seen.services.set(s.id, s)));
  client.on("unadvertiseServices", (ids) => ids.forEach((id) => seen.services.delete(id)));
  client.on("status", (m) => seen.statuses.push(m));
  client.on("message", (m) => seen.messages.push(m));
  client.on("serviceCallResponse", (m) => seen.responses.push(m));
  client.on("serviceCallFailure", (m) => seen.failures.push(m));
  client.on("parameterValues", (m) => seen.parameters.push(m));
  client.on("error", (e) => seen.errors.push(e));
  await new Promise((resolve, reject) => {
    ws.once("open", resolve);
    ws.once("error", reject);
  });
  return seen;
}

/** A rosbridge JSON client on the robot's local listener, subscribed to /cmd_vel. */
async function localCmdVel(url) {
  const ws = new WebSocket(url);
  const got = [];
  ws.on("message", (data, isBinary) => {
    if (isBinary) return;
    const m = JSON.parse(data.toString());
    if (m.op === "publish" && m.topic === "/cmd_vel") got.push(m.msg);
  });
  await new Promise((resolve, reject) => {
    ws.once("open", resolve);
    ws.once("error", reject);
  });
  ws.send(JSON.stringify({ op: "subscribe", topic: "/cmd_vel", type: "geometry_msgs/msg/Twist" }));
  return { ws, got };
}

function channelOf(seen, topic) {
  return [...seen.channels.values()].find((c) => c.topic === topic);
}

async function checkServerInfo(seen, subprotocol) {
  check(seen.ws.protocol === subprotocol, `the hub chose subprotocol '${seen.ws.protocol}', want '${subprotocol}'`);
  const info = await until(() => seen.serverInfo, "serverInfo");
  for (const cap of ["clientPublish", "services", "parameters"]) {
    check(info.capabilities.includes(cap), `serverInfo capabilities ${JSON.stringify(info.capabilities)} lack ${cap}`);
  }
  check(!info.capabilities.includes("time"), "serverInfo announces 'time', which the hub does not send");
  check(typeof info.sessionId === "string" && info.sessionId.length > 0, "serverInfo has no sessionId");
  check(info.supportedEncodings.includes("cdr") && info.supportedEncodings.includes("json"), `supportedEncodings ${info.supportedEncodings}`);
  ok(`subprotocol ${subprotocol} echoed; serverInfo ${JSON.stringify(info.capabilities)}, session ${info.sessionId}`);
}

async function checkChannels(seen) {
  const want = [`/${robot}/scan`, `/${robot}/points`, `/${robot}/odom`];
  await until(() => want.every((t) => channelOf(seen, t)), `channels for ${want.join(", ")}`);
  let parsed = 0;
  for (const c of seen.channels.values()) {
    if (c.encoding === "json") continue;
    check(c.schema.length > 0, `channel ${c.topic} (${c.encoding}) has an empty schema`);
    const ros2 = c.schemaEncoding === "ros2msg";
    check(ros2 || c.schemaEncoding === "ros1msg", `channel ${c.topic}: schemaEncoding ${c.schemaEncoding}`);
    check((c.encoding === "cdr") === ros2, `channel ${c.topic}: encoding ${c.encoding} with ${c.schemaEncoding}`);
    try {
      parse(c.schema, { ros2 });
    } catch (e) {
      throw new CheckFailed(`channel ${c.topic}: its schema does not parse: ${e.message}`);
    }
    parsed++;
  }
  const scan = channelOf(seen, `/${robot}/scan`);
  check(scan.encoding === "cdr" && scan.schemaName.endsWith("LaserScan"), `scan channel ${JSON.stringify({ ...scan, schema: undefined })}`);
  check(scan.schema.includes("MSG: "), "the scan's schema lacks its dependencies (no MSG: section)");
  ok(`${seen.channels.size} channels; ${parsed} schemas parse with @foxglove/rosmsg`);
}

async function checkSubscribe(seen) {
  const scan = channelOf(seen, `/${robot}/scan`);
  const cloud = channelOf(seen, `/${robot}/points`);
  const scanSub = seen.client.subscribe(scan.id);
  const cloudSub = seen.client.subscribe(cloud.id);
  const first = (sub) => seen.messages.find((m) => m.subscriptionId === sub);
  const scanMsg = await until(() => first(scanSub), "a LaserScan MessageData");
  const cloudMsg = await until(() => first(cloudSub), "a PointCloud2 MessageData", 15_000);
  const decode = (ch, m) => new MessageReader(parse(ch.schema, { ros2: true })).readMessage(new Uint8Array(m.data.buffer, m.data.byteOffset, m.data.byteLength));
  const s = decode(scan, scanMsg);
  check(s.ranges.length === scanRanges, `LaserScan has ${s.ranges.length} ranges, want ${scanRanges}`);
  const finite = Array.from(s.ranges).filter(Number.isFinite);
  check(finite.length > 0 && finite.every((r) => r >= 0), "LaserScan ranges are not finite non-negative numbers");
  check(Number.isFinite(s.angle_min) && s.angle_max > s.angle_min, `LaserScan angles ${s.angle_min}..${s.angle_max}`);
  check(typeof scanMsg.timestamp === "bigint" && scanMsg.timestamp > 1_600_000_000_000_000_000n, `receive timestamp ${scanMsg.timestamp}`);
  ok(`LaserScan decoded from CDR: ${s.ranges.length} ranges, ${finite.length} finite, frame ${s.header.frame_id}`);
  const c = decode(cloud, cloudMsg);
  const n = c.width * c.height;
  check(n === points, `PointCloud2 has ${n} points, want ${points}`);
  check(c.point_step > 0 && c.data.length === c.row_step * c.height, `PointCloud2 data ${c.data.length} bytes, row_step ${c.row_step}`);
  const x = c.fields.find((f) => f.name === "x");
  check(x && c.fields.some((f) => f.name === "y") && c.fields.some((f) => f.name === "z"), "PointCloud2 lacks x/y/z fields");
  const view = new DataView(c.data.buffer, c.data.byteOffset, c.data.byteLength);
  const x0 = view.getFloat32(x.offset, !c.is_bigendian);
  check(Number.isFinite(x0), `the first point's x is ${x0}`);
  ok(`PointCloud2 decoded from CDR: ${n} points of ${c.point_step} bytes, first x ${x0.toFixed(3)}`);
  seen.client.unsubscribe(scanSub);
  seen.client.unsubscribe(cloudSub);
  // A bad subscription is answered with a status error and the session goes on.
  const before = seen.statuses.length;
  seen.ws.send(JSON.stringify({ op: "subscribe", subscriptions: [{ id: 999, channelId: 987654 }] }));
  const st = await until(() => seen.statuses.slice(before).find((m) => m.level === 2), "a status error for an unknown channel");
  check(/987654/.test(st.message), `status for an unknown channel: ${st.message}`);
  seen.ws.send("{ not json");
  await until(() => seen.statuses.slice(before).find((m) => /malformed/i.test(m.message)), "a status error for malformed JSON");
  ok(`errors answered with status and the session goes on: "${st.message}"`);
}

const TWIST_DEF = "geometry_msgs/Vector3 linear\ngeometry_msgs/Vector3 angular\n================================================================================\nMSG: geometry_msgs/Vector3\nfloat64 x\nfloat64 y\nfloat64 z\n";

/** Advertises /<robot>/cmd_vel on `seen` and publishes a Twist with angular.z = nonce
 *  every 100 ms for `ms`; returns the Twist the robot got (or undefined). */
async function publishTwist(seen, local, encoding, nonce, ms) {
  const chan = seen.client.advertise({
    topic: `/${robot}/cmd_vel`,
    encoding,
    schemaName: "geometry_msgs/msg/Twist",
    schema: TWIST_DEF,
    schemaEncoding: "ros2msg",
  });
  const twist = { linear: { x: 0.25, y: 0, z: 0 }, angular: { x: 0, y: 0, z: nonce } };
  const data =
    encoding === "json"
      ? new TextEncoder().encode(JSON.stringify(twist))
      : new MessageWriter(parse(TWIST_DEF, { ros2: true })).writeMessage(twist);
  const end = Date.now() + ms;
  let got;
  while (Date.now() < end && !got) {
    seen.client.sendMessage(chan, data);
    await sleep(100);
    got = local.got.find((m) => m.angular?.z === nonce);
  }
  seen.client.unadvertise(chan);
  return { got, twist };
}

async function checkClientPublish(seen, local) {
  const nonce = Math.round(Math.random() * 1e6) / 1e3 + 1;
  const { got, twist } = await publishTwist(seen, local, args["publish-encoding"], nonce, TIMEOUT_MS);
  check(got, `no Twist with angular.z ${nonce} reached the robot's /cmd_vel`);
  check(isDeepStrictEqual(got, twist), `the robot got ${JSON.stringify(got)}, sent ${JSON.stringify(twist)}`);
  ok(`Twist client-published as ${args["publish-encoding"]} on /${robot}/cmd_vel reached the robot unchanged`);
}

async function checkServiceCall(seen) {
  const name = `/${robot}/get_status`;
  const svc = await until(() => [...seen.services.values()].find((s) => s.name === name), `service ${name} advertised`);
  check(svc.type === "std_srvs/srv/Trigger", `service ${name} type ${svc.type}`);
  const enc = args["call-encoding"];
  const defs = (text) => parse(text, { ros2: true });
  let data;
  if (enc === "json") {
    data = new TextEncoder().encode("{}");
  } else {
    // Trigger's request has no fields: its schema is empty, and still CDR.
    check(svc.request?.encoding === "cdr" && svc.request?.schemaEncoding === "ros2msg", `service ${name} request ${JSON.stringify(svc.request)}`);
    check(/bool success/.test(svc.response?.schema), `service ${name} response schema ${JSON.stringify(svc.response)}`);
    data = new MessageWriter(defs(svc.request.schema)).writeMessage({});
  }
  const callId = 41 + Math.floor(Math.random() * 1000);
  seen.client.sendServiceCallRequest({ serviceId: svc.id, callId, encoding: enc, data });
  const resp = await until(
    () => seen.responses.find((r) => r.callId === callId) || seen.failures.find((f) => f.callId === callId),
    `the answer to call ${callId} of ${name}`,
  );
  check(!("message" in resp) || resp.data, `call of ${name} failed: ${resp.message}`);
  check(resp.serviceId === svc.id && resp.encoding === enc, `answer ${JSON.stringify({ serviceId: resp.serviceId, encoding: resp.encoding })}`);
  const body =
    enc === "json"
      ? JSON.parse(new TextDecoder().decode(resp.data))
      : new MessageReader(defs(svc.response.schema)).readMessage(resp.data);
  check(body.success === true && typeof body.message === "string" && body.message.length > 0, `${name} answered ${JSON.stringify(body)}`);
  ok(`${name} called with a ${enc} request, answered in ${enc}: ${body.message.slice(0, 60)}`);
  // An unknown service id fails the call, by name.
  seen.client.sendServiceCallRequest({ serviceId: 987654, callId: 7, encoding: "json", data: new TextEncoder().encode("{}") });
  const f = await until(() => seen.failures.find((x) => x.callId === 7), "serviceCallFailure for an unknown service");
  check(/987654/.test(f.message), `failure text: ${f.message}`);
  ok(`an unknown service id fails with serviceCallFailure: "${f.message}"`);
}

/** Sets hub parameter `name` to `value` the way a rosbridge client does
 *  (/rosapi/set_param on the hub, no subprotocol), so the Foxglove read has something
 *  to find. */
async function setParamViaRosbridge(url, name, value) {
  const ws = new WebSocket(url);
  await new Promise((resolve, reject) => {
    ws.once("open", resolve);
    ws.once("error", reject);
  });
  const answer = new Promise((resolve) =>
    ws.on("message", (data) => {
      const m = JSON.parse(data.toString());
      if (m.op === "service_response" && m.id === "set") resolve(m);
    }),
  );
  ws.send(JSON.stringify({ op: "call_service", id: "set", service: "/rosapi/set_param", args: { name, value: JSON.stringify(value) } }));
  const r = await Promise.race([answer, sleep(TIMEOUT_MS).then(() => undefined)]);
  ws.close();
  check(r && r.result === true, `set_param ${name} through rosbridge: ${JSON.stringify(r)}`);
}

async function checkParameter(seen) {
  const eq = args.param.indexOf("=");
  const name = args.param.slice(0, eq);
  const value = JSON.parse(args.param.slice(eq + 1));
  await setParamViaRosbridge(args.url, name, value);
  seen.client.getParameters([name], "fleetlink-param");
  const pv = await until(() => seen.parameters.find((p) => p.id === "fleetlink-param"), "parameterValues");
  const got = pv.parameters.find((p) => p.name === name);
  check(got && isDeepStrictEqual(got.value, value), `getParameters ${name}: ${JSON.stringify(pv.parameters)}, want ${JSON.stringify(value)}`);
  ok(`getParameters read ${name} = ${JSON.stringify(got.value)}`);
}

async function checkDenied(url, subprotocol, local) {
  const seen = await connect(url, subprotocol);
  await until(() => seen.serverInfo, "serverInfo (no rights)");
  // Give the hub time to advertise anything it would: nothing may come.
  await sleep(1500);
  check(seen.channels.size === 0, `a token without rights sees channels: ${[...seen.channels.values()].map((c) => c.topic)}`);
  check(seen.services.size === 0, `a token without rights sees services: ${[...seen.services.values()].map((s) => s.name)}`);
  const before = seen.statuses.length;
  const nonce = Math.round(Math.random() * 1e6) / 1e3 + 2000;
  const { got } = await publishTwist(seen, local, "json", nonce, 1500);
  check(!got, "a token without rights published cmd_vel to the robot");
  const refusal = seen.statuses.slice(before).find((m) => m.level === 2 && /cmd_vel/.test(m.message));
  check(refusal, `no status error for a refused advertise: ${JSON.stringify(seen.statuses)}`);
  seen.client.sendServiceCallRequest({ serviceId: 1, callId: 5, encoding: "json", data: new TextEncoder().encode("{}") });
  await until(() => seen.failures.find((f) => f.callId === 5), "serviceCallFailure without rights");
  if (args.param) {
    seen.client.getParameters([args.param.split("=")[0]], "denied");
    const pv = await until(() => seen.parameters.find((p) => p.id === "denied"), "parameterValues without rights");
    check(pv.parameters.length === 0, `a token without rights read ${JSON.stringify(pv.parameters)}`);
  }
  ok(`a token without rights: no channels, no services, publish refused ("${refusal.message}"), calls fail, parameters hidden`);
  seen.ws.close();
}

async function main() {
  const sp = args.subprotocol;
  const local = await localCmdVel(args["local-url"]);
  const seen = await connect(args.url, sp);
  try {
    await checkServerInfo(seen, sp);
    await checkChannels(seen);
    await checkSubscribe(seen);
    await checkClientPublish(seen, local);
    await checkServiceCall(seen);
    if (args.param) await checkParameter(seen);
    check(seen.errors.length === 0, `the client reported errors: ${seen.errors.map(String).join("; ")}`);
    if (args["denied-url"]) await checkDenied(args["denied-url"], sp, local);
  } finally {
    seen.ws.close();
    local.ws.close();
  }
}

main().then(
  () => {
    console.log(`PASS: FoxgloveClient (${args.subprotocol})`);
    process.exit(0);
  },
  (e) => {
    console.error(`FAIL: ${e instanceof CheckFailed ? e.message : e.stack}`);
    process.exit(1);
  },
);
