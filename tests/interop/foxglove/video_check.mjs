#!/usr/bin/env node
// A Foxglove client watching a robot's camera video: @foxglove/ws-protocol's
// FoxgloveClient finds the video topic as a channel of `foxglove_msgs/msg/CompressedVideo`
// in CDR (the schema Foxglove's image panel plays), its schema parses with
// @foxglove/rosmsg, it subscribes for --seconds, and every MessageData is read with
// @foxglove/rosmsg2-serialization from the advertised schema: format "h264", the stamp
// set, the first one a keyframe. The access units go to --out (per frame a little-endian
// u32 length, then the bytes) for FFmpeg's decoder to check (video_peer.py decode).
//
// Exits 0 when every check passed, 1 naming the failed one. Every wait is bounded.

import { writeFileSync } from "node:fs";
import { parseArgs } from "node:util";
import foxglove from "@foxglove/ws-protocol";
import { parse } from "@foxglove/rosmsg";
import { MessageReader } from "@foxglove/rosmsg2-serialization";
import WebSocket from "ws";
import { CheckFailed, check, ok, sleep, until } from "./checks.mjs";

const { FoxgloveClient } = foxglove;
const { values: args } = parseArgs({
  options: {
    url: { type: "string" },
    topic: { type: "string" },
    seconds: { type: "string", default: "4" },
    out: { type: "string" },
  },
});
if (!args.url || !args.topic || !args.out) {
  console.error("usage: video_check.mjs --url ws://HOST:PORT/?token=T --topic /robot1/camera/video --out FILE [--seconds S]");
  process.exit(2);
}

/** Whether an Annex B access unit holds an IDR slice (NAL type 5). */
const idr = (au) => au.some((b, i) => i >= 2 && au[i - 2] === 0 && au[i - 1] === 0 && b === 1 && (au[i + 1] & 0x1f) === 5);

const ws = new WebSocket(args.url, ["foxglove.sdk.v1"]);
const client = new FoxgloveClient({ ws });
const channels = new Map();
const messages = [];
client.on("advertise", (chs) => chs.forEach((c) => channels.set(c.id, c)));
client.on("message", (m) => messages.push(m));
try {
  await new Promise((resolve, reject) => {
    ws.once("open", resolve);
    ws.once("error", reject);
  });
  const ch = await until(() => [...channels.values()].find((c) => c.topic === args.topic), `a channel for ${args.topic}`, 10_000);
  check(ch.schemaName === "foxglove_msgs/msg/CompressedVideo" && ch.encoding === "cdr" && ch.schemaEncoding === "ros2msg",
    `${args.topic}: ${ch.schemaName} in ${ch.encoding} (${ch.schemaEncoding}), want foxglove_msgs/msg/CompressedVideo in cdr (ros2msg)`);
  let reader;
  try {
    reader = new MessageReader(parse(ch.schema, { ros2: true }));
  } catch (e) {
    throw new CheckFailed(`${args.topic}: its schema does not parse: ${e.message}`);
  }
  ok(`${args.topic} is a ${ch.schemaName} channel in CDR; its schema parses`);
  client.subscribe(ch.id);
  await until(() => messages.length > 0, `a first video frame on ${args.topic}`, 10_000);
  await sleep(Number(args.seconds) * 1000);
  const frames = messages.map((m) => reader.readMessage(new Uint8Array(m.data.buffer, m.data.byteOffset, m.data.byteLength)));
  check(frames.every((f) => f.format === "h264"), `formats ${[...new Set(frames.map((f) => f.format))]}`);
  check(frames.every((f) => f.timestamp.sec > 1_600_000_000), `stamps ${JSON.stringify(frames[0].timestamp)}`);
  check(idr(frames[0].data), "the first frame given is not a keyframe");
  const parts = [];
  for (const f of frames) {
    const len = Buffer.alloc(4);
    len.writeUInt32LE(f.data.length);
    parts.push(len, Buffer.from(f.data.buffer, f.data.byteOffset, f.data.byteLength));
  }
  writeFileSync(args.out, Buffer.concat(parts));
  const keys = frames.filter((f) => idr(f.data)).length;
  ok(`${frames.length} CompressedVideo frames read from CDR (${keys} keyframes, the first one of them), frame_id "${frames[0].frame_id}"`);
  client.close();
  process.exit(0);
} catch (e) {
  console.log(`FAIL ${e instanceof CheckFailed ? e.message : e?.stack ?? e}`);
  client.close();
  process.exit(1);
}
