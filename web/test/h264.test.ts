// The page's reading of H.264 access units (src/h264.ts) against a frame of the demo
// camera's video as the hub sends it (test/fixtures/video.*, a keyframe captured by
// capture-fixtures.mjs) and against hand-made byte streams.
import assert from "node:assert/strict";
import { readFileSync } from "node:fs";
import { join } from "node:path";
import { test } from "node:test";
import { codecString, isKeyframe, nalUnits } from "../src/h264";
import { bytesOf } from "../src/messages";
import { decodeFrame } from "../src/rosbridge";

const dir = join(process.cwd(), "test", "fixtures");

test("CompressedVideo: the keyframe's bytes arrive whole and name a Constrained Baseline stream", () => {
  const cbor = decodeFrame(new Uint8Array(readFileSync(join(dir, "video.cbor")))) as any;
  const json = JSON.parse(readFileSync(join(dir, "video.json"), "utf8"));
  assert.equal(cbor.msg.format, "h264");
  const au = bytesOf(cbor.msg.data);
  assert.ok(au instanceof Uint8Array);
  assert.deepEqual(au, bytesOf(json.msg.data), "CBOR bytes equal the JSON's base64");
  assert.ok(isKeyframe(au));
  const types = [...nalUnits(au)].map((u) => u[0] & 0x1f);
  assert.deepEqual(types.slice(0, 2), [7, 8], "SPS and PPS before the picture");
  assert.ok(types.includes(5));
  // profile_idc 66 (Baseline) with constraint_set1 (Constrained Baseline), as the encoder is set up.
  const codec = codecString(au);
  assert.match(codec ?? "", /^avc1\.42[0-9A-F]{4}$/);
  assert.ok(parseInt(codec!.slice(7, 9), 16) & 0x40, `${codec}: constraint_set1 flag`);
});

test("access units: start codes of three and four bytes, P-frames, no SPS", () => {
  const key = new Uint8Array([0, 0, 0, 1, 0x67, 0x42, 0xc0, 0x1f, 0xaa, 0, 0, 1, 0x68, 0xce, 0, 0, 0, 1, 0x65, 0x88, 0x80]);
  assert.deepEqual([...nalUnits(key)].map((u) => [...u]), [[0x67, 0x42, 0xc0, 0x1f, 0xaa], [0x68, 0xce], [0x65, 0x88, 0x80]]);
  assert.ok(isKeyframe(key));
  assert.equal(codecString(key), "avc1.42C01F");
  const p = new Uint8Array([0, 0, 1, 0x41, 0x9a, 0x00, 0x05]);
  assert.ok(!isKeyframe(p));
  assert.equal(codecString(p), null);
  // An SPS cut short names no codec; bytes with no start code hold no unit.
  assert.equal(codecString(new Uint8Array([0, 0, 1, 0x67, 0x42])), null);
  assert.deepEqual([...nalUnits(new Uint8Array([0x65, 1, 2]))], []);
  assert.ok(!isKeyframe(new Uint8Array(0)));
});
