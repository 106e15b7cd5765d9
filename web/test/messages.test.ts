// The page's message handling against frames the hub produced (test/fixtures, captured
// from `fleetlink demo` by capture-fixtures.mjs): each fixture is one message as a CBOR
// binary frame and as JSON, and what the page gets from the CBOR must be what the JSON
// says — typed arrays decoded with the right type, endianness and length, byte strings
// as bytes, and the panels' unpacking (scan points, cloud xyz) consistent with both.
import assert from "node:assert/strict";
import { readFileSync } from "node:fs";
import { join } from "node:path";
import { test } from "node:test";
import { bytesOf, imageKind, inspectable, pose2d, scanPoints, skeleton, unpackCloud } from "../src/messages";
import { decodeFrame } from "../src/rosbridge";

const dir = join(process.cwd(), "test", "fixtures");
const pair = (name: string) => ({
  cbor: decodeFrame(new Uint8Array(readFileSync(join(dir, `${name}.cbor`)))) as any,
  json: JSON.parse(readFileSync(join(dir, `${name}.json`), "utf8")),
});

test("LaserScan: ranges arrive as a Float32Array equal to the JSON numbers", () => {
  const { cbor, json } = pair("scan");
  assert.equal(cbor.op, "publish");
  assert.equal(cbor.topic, json.topic);
  const r = cbor.msg.ranges;
  assert.ok(r instanceof Float32Array, `ranges is ${r?.constructor?.name}`);
  assert.equal(r.length, json.msg.ranges.length);
  json.msg.ranges.forEach((v: number | null, i: number) => assert.ok(v === null ? Number.isNaN(r[i]) || !Number.isFinite(r[i]) : r[i] === Math.fround(v), `ranges[${i}]`));
  assert.equal(cbor.msg.angle_increment, Math.fround(json.msg.angle_increment));
  const fromCbor = scanPoints(cbor.msg), fromJson = scanPoints(json.msg);
  assert.ok(fromCbor.length > 100);
  // JSON carries the float32 angles as shortest decimals, CBOR as the float32 itself:
  // the same points within float32 rounding.
  assert.equal(fromCbor.length, fromJson.length);
  fromCbor.forEach((v, i) => assert.ok(Math.abs(v - fromJson[i]) < 1e-4, `point coordinate ${i}: ${v} vs ${fromJson[i]}`));
  // The simulated room is 20 m across: every point lies inside it, seen from the robot.
  for (let i = 0; i < fromCbor.length; i += 2) assert.ok(Math.hypot(fromCbor[i], fromCbor[i + 1]) < 30);
});

test("PointCloud2: data arrives as bytes equal to the JSON base64, and unpacks to the same points", () => {
  const { cbor, json } = pair("points");
  const data = cbor.msg.data;
  assert.ok(data instanceof Uint8Array, `data is ${data?.constructor?.name}`);
  assert.deepEqual(Buffer.from(data), Buffer.from(json.msg.data, "base64"));
  assert.equal(data.length, cbor.msg.row_step * cbor.msg.height);
  const a = unpackCloud(cbor.msg), b = unpackCloud(json.msg);
  assert.equal(a.count, cbor.msg.width * cbor.msg.height);
  assert.deepEqual(a.positions.subarray(0, a.count * 3), b.positions.subarray(0, b.count * 3));
  let zmin = Infinity, zmax = -Infinity;
  for (let i = 0; i < a.count; i++) {
    const x = a.positions[i * 3], y = a.positions[i * 3 + 1], z = a.positions[i * 3 + 2];
    assert.ok(Math.abs(x) < 25 && Math.abs(y) < 25, `point ${i} (${x}, ${y}) outside the room`);
    zmin = Math.min(zmin, z);
    zmax = Math.max(zmax, z);
  }
  assert.ok(zmax > zmin, "a cloud with height");
  // Reusing buffers gives the same answer and does not reallocate.
  const again = unpackCloud(cbor.msg, a);
  assert.equal(again.positions, a.positions);
});

test("Odometry: the pose and the covariance (float64[36] as a typed array) match the JSON", () => {
  const { cbor, json } = pair("odom");
  const cov = cbor.msg.pose.covariance;
  assert.ok(cov instanceof Float64Array, `covariance is ${cov?.constructor?.name}`);
  assert.deepEqual(Array.from(cov), json.msg.pose.covariance);
  const p = pose2d(cbor.msg)!, q = pose2d(json.msg)!;
  assert.deepEqual(p, q);
  assert.ok(Math.abs(p.x) < 10 && Math.abs(p.y) < 10);
  assert.equal(cbor.msg.header.frame_id, json.msg.header.frame_id);
});

test("bytesOf, imageKind and inspectable on edge cases", () => {
  assert.deepEqual(Array.from(bytesOf("AAEC")), [0, 1, 2]);
  assert.deepEqual(Array.from(bytesOf([3, 4])), [3, 4]);
  assert.equal(imageKind(new Uint8Array([0xff, 0xd8, 0xff, 0xe0])), "jpeg");
  assert.equal(imageKind(new Uint8Array([1, 2, 3, 4])), "unknown");
  const shown = inspectable({ a: new Float32Array(100), b: new Uint8Array(10) }, 4) as any;
  assert.equal(shown.a.length, 5);
  assert.equal(shown.b, "<10 bytes>");
});

test("skeleton: a request built from rosapi typedefs", () => {
  const defs = [
    { type: "std_srvs/srv/SetBool_Request", fieldnames: ["data"], fieldtypes: ["bool"], fieldarraylen: [-1] },
    { type: "x/msg/Goal", fieldnames: ["p", "ids", "name"], fieldtypes: ["geometry_msgs/msg/Point", "int32", "string"], fieldarraylen: [-1, 0, -1] },
    { type: "geometry_msgs/msg/Point", fieldnames: ["x", "y", "z"], fieldtypes: ["float64", "float64", "float64"], fieldarraylen: [-1, -1, -1] },
  ];
  assert.deepEqual(skeleton(defs), { data: false });
  assert.deepEqual(skeleton(defs, "x/msg/Goal"), { p: { x: 0, y: 0, z: 0 }, ids: [], name: "" });
});
