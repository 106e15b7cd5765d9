#!/usr/bin/env node
// What Foxglove and Lichtblick do with a rosbridge server, done with their own parsers
// (@foxglove/rosmsg, @foxglove/rosmsg2-serialization from npm) against a fleetlink hub:
//
//   1. every bundled type's full definition (`fleetlink msg list --full-texts`) parses, in
//      the ROS 1 and the ROS 2 grammar;
//   2. the Lichtblick flow: /rosapi/topics_and_raw_types -> ROS 2 detected (an
//      rcl_interfaces/msg/Log topic is listed) -> every typedefs_full_text parses -> each
//      simulated topic subscribed with compression cbor-raw and decoded from its CDR bytes
//      with those definitions, field for field equal to the same message as rosbridge JSON;
//   3. /rosout carries the hub's events: an agent refused for a bad token is logged there;
//   4. a client that publishes and subscribes on one connection receives its own message.
//
// Exits 0 when every check passed, 1 naming the failed check. Every wait is bounded.

import { parseArgs } from "node:util";
import { execFileSync } from "node:child_process";
import { parse } from "@foxglove/rosmsg";
import { MessageReader } from "@foxglove/rosmsg2-serialization";
import { decode as cborDecode } from "cbor2";
import WebSocket from "ws";

const TIMEOUT_MS = 10_000;
const { values: args } = parseArgs({
  options: {
    url: { type: "string" },
    bin: { type: "string" },
    robot: { type: "string", default: "robot1" },
  },
});
if (!args.url || !args.bin) {
  console.error("usage: foxglove_check.mjs --url ws://HOST:PORT/?token=T --bin fleetlink [--robot robot1]");
  process.exit(2);
}
const robot = args.robot;

class CheckFailed extends Error {}
function check(cond, what) {
  if (!cond) throw new CheckFailed(what);
}
const ok = (what) => console.log(`  ok: ${what}`);

/** A rosbridge connection that hands out frames (JSON text or CBOR binary) by predicate. */
class Conn {
  constructor(url, protocols) {
    this.ws = new WebSocket(url, protocols);
    this.ws.binaryType = "arraybuffer";
    this.frames = [];
    this.waiters = [];
    this.ws.on("message", (data, isBinary) => {
      const frame = isBinary ? new Uint8Array(data) : JSON.parse(data.toString());
      this.frames.push(frame);
      this.waiters = this.waiters.filter((w) => !w());
    });
  }
  open() {
    return new Promise((resolve, reject) => {
      this.ws.once("open", resolve);
      this.ws.once("error", reject);
    });
  }
  send(obj) {
    this.ws.send(obj instanceof Uint8Array ? obj : JSON.stringify(obj));
  }
  /** The first frame `pred` accepts (removed from the buffer), within the timeout. */
  next(pred, what, ms = TIMEOUT_MS) {
    return new Promise((resolve, reject) => {
      const timer = setTimeout(() => reject(new CheckFailed(`${what}: nothing within ${ms} ms`)), ms);
      const look = () => {
        const i = this.frames.findIndex(pred);
        if (i < 0) return false;
        clearTimeout(timer);
        resolve(this.frames.splice(i, 1)[0]);
        return true;
      };
      if (!look()) this.waiters.push(look);
    });
  }
  async call(service, args = {}) {
    const id = `call-${service}-${Math.random()}`;
    this.send({ op: "call_service", id, service, args });
    const r = await this.next((f) => f.op === "service_response" && f.id === id, `answer of ${service}`);
    check(r.result === true, `${service} failed: ${JSON.stringify(r.values)}`);
    return r.values;
  }
  close() {
    this.ws.close();
  }
}

function checkBundledDefinitions() {
  for (const [dialect, ros2] of [["ros1", false], ["ros2", true]]) {
    const all = JSON.parse(
      execFileSync(args.bin, ["msg", "list", "--full-texts", "--dialect", dialect], {
        maxBuffer: 64 << 20,
      }).toString(),
    );
    const bad = [];
    for (const [type, text] of Object.entries(all)) {
      try {
        parse(text, { ros2 });
      } catch (e) {
        bad.push(`${type}: ${e.message}`);
      }
    }
    check(Object.keys(all).length > 100, `only ${Object.keys(all).length} bundled ${dialect} types listed`);
    check(bad.length === 0, `${bad.length} ${dialect} definitions @foxglove/rosmsg cannot parse:\n${bad.slice(0, 5).join("\n")}`);
    ok(`all ${Object.keys(all).length} bundled types parse with @foxglove/rosmsg (${dialect})`);
  }
}

const sameStamp = (a, b) => a && b && a.sec === b.sec && a.nanosec === b.nanosec;
const b64 = (bytes) => Buffer.from(bytes).toString("base64");

/** Compares a CDR-decoded message with its rosbridge JSON form, returning the first difference. */
function diff(raw, json, path = "") {
  if (raw instanceof Uint8Array || ArrayBuffer.isView(raw)) {
    const arr = Array.from(raw);
    if (typeof json === "string") return b64(raw) === json ? null : `${path}: bytes differ`;
    if (!Array.isArray(json) || json.length !== arr.length) return `${path}: length ${arr.length} vs ${json?.length}`;
    for (let i = 0; i < arr.length; i++) {
      const d = diff(arr[i], json[i], `${path}[${i}]`);
      if (d) return d;
    }
    return null;
  }
  if (Array.isArray(raw)) {
    if (!Array.isArray(json) || json.length !== raw.length) return `${path}: length ${raw.length} vs ${json?.length}`;
    for (let i = 0; i < raw.length; i++) {
      const d = diff(raw[i], json[i], `${path}[${i}]`);
      if (d) return d;
    }
    return null;
  }
  if (raw !== null && typeof raw === "object") {
    for (const k of Object.keys(raw)) {
      const d = diff(raw[k], json?.[k], `${path}.${k}`);
      if (d) return d;
    }
    return null;
  }
  if (typeof raw === "number" && typeof json === "number") {
    return Math.abs(raw - json) <= 1e-6 * Math.max(1, Math.abs(raw)) ? null : `${path}: ${raw} vs ${json}`;
  }
  if (typeof raw === "bigint") return BigInt(json) === raw ? null : `${path}: ${raw} vs ${json}`;
  return raw === json ? null : `${path}: ${JSON.stringify(raw)} vs ${JSON.stringify(json)}`;
}

async function checkLichtblickFlow(c) {
  const v = await c.call("/rosapi/topics_and_raw_types");
  const types = new Map(v.topics.map((t, i) => [t, { type: v.types[i], text: v.typedefs_full_text[i] }]));
  check(v.types.includes("rcl_interfaces/msg/Log"), `no rcl_interfaces/msg/Log among ${v.types.join(", ")}: Lichtblick would not detect ROS 2`);
  check(types.has("/rosout"), "no /rosout topic");
  ok("ROS 2 detected the way Lichtblick does (rcl_interfaces/msg/Log listed, /rosout present)");
  const readers = new Map();
  for (const [topic, { type, text }] of types) {
    if (!text) continue;
    let defs;
    try {
      defs = parse(text, { ros2: true });
    } catch (e) {
      throw new CheckFailed(`typedefs_full_text of ${topic} (${type}) does not parse: ${e.message}\n${text.slice(0, 400)}`);
    }
    readers.set(topic, new MessageReader(defs));
  }
  ok(`typedefs_full_text of all ${readers.size} topics with a definition parse (ros2)`);
  const sim = ["scan", "odom", "pose", "points", "camera/image/compressed"].map((t) => `/${robot}/${t}`);
  // rosbridge keeps one delivery (compression) per topic and connection, so the JSON copy
  // comes on a second connection. It subscribes first and has a message of each topic
  // before the raw subscription is made: the first subscriber of an idle robot topic gets
  // the robot's cached latest message alone, which a later subscriber never sees.
  const j = new Conn(args.url);
  await j.open();
  for (const topic of sim) {
    check(readers.has(topic), `${topic} is not listed with a definition`);
    j.send({ op: "subscribe", topic, id: `json-${topic}`, queue_length: 100 });
  }
  for (const topic of sim) {
    await j.next((f) => !(f instanceof Uint8Array) && f.op === "publish" && f.topic === topic, `a first JSON ${topic} message`);
  }
  for (const topic of sim) {
    c.send({ op: "subscribe", topic, compression: "cbor-raw", id: `raw-${topic}` });
  }
  for (const topic of sim) {
    const isRaw = (f) => f instanceof Uint8Array;
    const rawFrame = await c.next((f) => isRaw(f) && cborDecode(f).topic === topic, `cbor-raw ${topic}`);
    const env = cborDecode(rawFrame);
    check(env.op === "publish" && env.msg && env.msg.bytes, `${topic}: cbor-raw frame without msg.bytes`);
    const decoded = readers.get(topic).readMessage(env.msg.bytes);
    // The JSON copy of the same message: same header stamp (every sim message has a header).
    const json = await j.next(
      (f) => !isRaw(f) && f.op === "publish" && f.topic === topic && sameStamp(f.msg.header?.stamp, decoded.header?.stamp),
      `the JSON copy of the ${topic} message stamped ${JSON.stringify(decoded.header?.stamp)}`,
      15_000,
    );
    const d = diff(decoded, json.msg);
    check(d === null, `${topic}: CDR decoded by @foxglove/rosmsg2-serialization differs from rosbridge JSON at ${d}`);
    c.send({ op: "unsubscribe", topic });
    ok(`${topic}: cbor-raw CDR decoded with the advertised definition equals the JSON message`);
  }
  j.close();
}

/** HELLO of a made-up robot with a bad token, as an agent would send it. */
function helloFrame(robotName, token) {
  const enc = new TextEncoder();
  const varint = (n) => {
    const out = [];
    do {
      let b = n & 0x7f;
      n >>>= 7;
      if (n) b |= 0x80;
      out.push(b);
    } while (n);
    return out;
  };
  const str = (s) => {
    const b = enc.encode(s);
    return [...varint(b.length), ...b];
  };
  const body = [...varint(1), ...str(robotName), ...str(token), ...varint(1000), 0, 0, 0, 0, 0, 0, 0, 0];
  return new Uint8Array([0x01, ...varint(body.length), ...body]);
}

async function checkRosout(c) {
  c.send({ op: "subscribe", topic: "/rosout", id: "rosout" });
  // Give the subscription a moment to be in place before causing the event.
  await c.call("/rosapi/get_time");
  const base = args.url.replace(/\?.*$/, "");
  const agent = new Conn(base, ["fleetlink.v1"]);
  await agent.open();
  agent.send(helloFrame("intruder", "flk_robot_not_a_real_token"));
  const log = await c.next(
    (f) => f.op === "publish" && f.topic === "/rosout" && String(f.msg.msg).includes("intruder"),
    "a /rosout line about the refused agent",
  );
  agent.close();
  check(log.msg.level === 30, `refusal logged at level ${log.msg.level}, expected 30 (WARN)`);
  check(log.msg.name === "fleetlink_hub", `log name ${log.msg.name}`);
  check(typeof log.msg.stamp?.sec === "number", "log without a stamp");
  ok(`/rosout: "${log.msg.msg}"`);
}

async function checkSelfDelivery(c) {
  c.send({ op: "advertise", topic: "/fg_self", type: "std_msgs/msg/String" });
  c.send({ op: "subscribe", topic: "/fg_self", id: "self" });
  c.send({ op: "publish", topic: "/fg_self", msg: { data: "mine" } });
  const m = await c.next((f) => f.op === "publish" && f.topic === "/fg_self", "own message back");
  check(m.msg.data === "mine", `own message ${JSON.stringify(m.msg)}`);
  ok("a client receives its own publish when subscribed");
}

const checks = [
  ["bundled definitions", async () => checkBundledDefinitions()],
  ["lichtblick flow", checkLichtblickFlow],
  ["rosout", checkRosout],
  ["self delivery", checkSelfDelivery],
];
let failed = 0;
for (const [name, fn] of checks) {
  console.log(`-- ${name}`);
  const c = new Conn(args.url);
  try {
    await c.open();
    await fn(c);
  } catch (e) {
    failed++;
    console.log(`FAIL ${name}: ${e instanceof CheckFailed ? e.message : e.stack}`);
  } finally {
    c.close();
  }
}
console.log(failed ? `FAIL foxglove: ${failed} check(s) failed` : "PASS foxglove");
process.exit(failed ? 1 : 0);
