// Captures the fixtures of the unit tests from a running hub (e.g. `fleetlink demo`):
// the same message of each topic as the hub sends it twice — once as a CBOR binary frame
// (compression "cbor") and once as JSON — matched by header stamp. The tests then check
// that the page's CBOR handling gives what the JSON says, on frames the Rust side made.
//
//   node --experimental-websocket test/capture-fixtures.mjs ws://127.0.0.1:8080/ robot1 [NAME...]
//
// NAMEs (scan, points, odom, markers, video) limit the capture to those fixtures. The video
// fixture is a keyframe of the camera's H.264 stream.
import { writeFileSync } from "node:fs";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";

const [url, robot = "robot1", ...only] = process.argv.slice(2);
if (!url) throw new Error("usage: capture-fixtures.mjs WS_URL [ROBOT] [NAME...]");
const out = join(dirname(fileURLToPath(import.meta.url)), "fixtures");
const all = { scan: `/${robot}/scan`, points: `/${robot}/points`, odom: `/${robot}/odom`, markers: `/${robot}/markers`, video: `/${robot}/camera/video` };
const topics = Object.fromEntries(Object.entries(all).filter(([k]) => !only.length || only.includes(k)));
// A MarkerArray has no header of its own: its markers' stamp identifies it; a
// CompressedVideo its timestamp.
const stampOf = (m) => JSON.stringify(m?.header?.stamp ?? m?.markers?.[0]?.header?.stamp ?? m?.timestamp);
// Whether an H.264 access unit (Annex B) holds an IDR slice: a start code, then NAL type 5.
const idr = (d) => d.some((b, i) => i >= 2 && d[i - 2] === 0 && d[i - 1] === 0 && b === 1 && (d[i + 1] & 0x1f) === 5);

function open(compression, onFrame) {
  const ws = new WebSocket(url);
  ws.binaryType = "arraybuffer";
  ws.onopen = () => {
    for (const t of Object.values(topics)) ws.send(JSON.stringify({ op: "subscribe", topic: t, compression, queue_length: 50 }));
  };
  ws.onmessage = (ev) => onFrame(ev.data);
  return ws;
}

const { decode } = await import("cbor2");
const cbor = new Map(); // `${topic} ${stamp}` -> bytes
const json = new Map();
const done = new Set();
const a = open("cbor", (d) => {
  const b = new Uint8Array(d);
  const m = decode(b);
  if (m.op === "publish" && (m.msg.format !== "h264" || idr(m.msg.data))) cbor.set(`${m.topic} ${stampOf(m.msg)}`, b);
  check();
});
const b = open("none", (d) => {
  const m = JSON.parse(d);
  if (m.op === "publish") json.set(`${m.topic} ${stampOf(m.msg)}`, d);
  check();
});
function check() {
  for (const [name, topic] of Object.entries(topics)) {
    if (done.has(name)) continue;
    for (const [k, bytes] of cbor) {
      if (!k.startsWith(`${topic} `) || !json.has(k)) continue;
      writeFileSync(join(out, `${name}.cbor`), bytes);
      writeFileSync(join(out, `${name}.json`), json.get(k));
      done.add(name);
      console.log(`${name}: ${bytes.length} bytes CBOR, ${json.get(k).length} bytes JSON`);
      break;
    }
  }
  if (done.size === Object.keys(topics).length) {
    a.close();
    b.close();
    process.exit(0);
  }
}
setTimeout(() => {
  console.error(`timeout: captured only ${[...done].join(", ")}`);
  process.exit(1);
}, 15000);
