// Marker handling (src/markers.ts) on a MarkerArray the demo hub sent (the simulator's
// room: five pillars, the walls, the goal deleted while there is none — test/fixtures,
// captured by capture-fixtures.mjs) and on hand-made markers for what the demo lacks.
import assert from "node:assert/strict";
import { readFileSync } from "node:fs";
import { join } from "node:path";
import { test } from "node:test";
import { MarkerStore, type MarkerMsg, shapesOf, tally } from "../src/markers";
import { decodeFrame } from "../src/rosbridge";

const dir = join(process.cwd(), "test", "fixtures");
const cbor = decodeFrame(new Uint8Array(readFileSync(join(dir, "markers.cbor")))) as any;
const json = JSON.parse(readFileSync(join(dir, "markers.json"), "utf8"));
const PILLARS = [[4.2, 0, 0.5], [-4.2, 0, 0.5], [0, 7, 0.8], [2, -7.5, 0.6], [8.8, 6, 0.5]];

test("MarkerArray from the hub: CBOR and JSON carry the same markers", () => {
  assert.equal(cbor.op, "publish");
  assert.match(cbor.topic, /\/markers$/);
  assert.equal(cbor.msg.markers.length, json.msg.markers.length);
  assert.deepEqual(cbor.msg.markers.map((m: MarkerMsg) => [m.ns, m.id, m.type, m.action]), json.msg.markers.map((m: MarkerMsg) => [m.ns, m.id, m.type, m.action]));
  assert.equal(cbor.msg.markers[0].header.frame_id, "map");
});

test("MarkerArray from the hub: five pillars as cylinders, the walls as a strip, no goal", () => {
  for (const msg of [cbor.msg, json.msg]) {
    const store = new MarkerStore();
    store.apply(msg, 0);
    const live = store.live(1);
    const t = tally(live);
    assert.deepEqual(t.byType, { CYLINDER: 5, LINE_STRIP: 1 });
    assert.deepEqual(t.byNs, { pillars: 5, walls: 1 });
    const pillars = live.filter((m) => m.msg.ns === "pillars").map((m) => shapesOf(m.msg));
    pillars.forEach((shapes, i) => {
      assert.equal(shapes.length, 1);
      const s = shapes[0];
      assert.equal(s.kind, "ellipse");
      if (s.kind !== "ellipse") return;
      const [x, y, r] = PILLARS[i];
      assert.ok(Math.abs(s.x - x) < 1e-9 && Math.abs(s.y - y) < 1e-9, `pillar ${i} at (${s.x}, ${s.y})`);
      assert.ok(Math.abs(s.rx - r) < 1e-6 && Math.abs(s.ry - r) < 1e-6, `pillar ${i} radius ${s.rx}`);
      assert.ok(s.outline);
    });
    const walls = shapesOf(live.find((m) => m.msg.ns === "walls")!.msg);
    assert.equal(walls.length, 1);
    assert.equal(walls[0].kind, "polyline");
    if (walls[0].kind === "polyline") {
      assert.equal(walls[0].pts.length, 5);
      assert.deepEqual(walls[0].pts[0], walls[0].pts[4]);
      for (const [x, y] of walls[0].pts) assert.ok(Math.abs(x) === 10 && Math.abs(y) === 10);
      assert.ok(walls[0].width > 0);
    }
  }
});

const marker = (m: MarkerMsg): MarkerMsg => ({
  header: { frame_id: "map" }, ns: "t", id: 0, type: 1, action: 0,
  pose: { position: { x: 0, y: 0, z: 0 }, orientation: { x: 0, y: 0, z: 0, w: 1 } },
  scale: { x: 1, y: 1, z: 1 }, color: { r: 1, g: 0, b: 0, a: 1 }, lifetime: { sec: 0, nanosec: 0 }, points: [], ...m,
});

test("the demo's DELETE of the goal removes a goal sphere; ids are per namespace", () => {
  const store = new MarkerStore();
  store.apply({ markers: [marker({ ns: "goal", id: 0, type: 2 }), marker({ ns: "other", id: 0, type: 2 })] }, 0);
  assert.equal(store.live(0).length, 2);
  store.apply(cbor.msg, 0);
  assert.deepEqual(tally(store.live(0)).byNs, { other: 1, pillars: 5, walls: 1 });
  // Same namespace and id: replaced, not added.
  store.apply(marker({ ns: "pillars", id: 2, type: 1 }), 0);
  assert.deepEqual(tally(store.live(0)).byType, { SPHERE: 1, CYLINDER: 4, CUBE: 1, LINE_STRIP: 1 });
});

test("DELETEALL: all markers, or those of one namespace", () => {
  const store = new MarkerStore();
  store.apply(cbor.msg, 0);
  store.apply(marker({ ns: "x", id: 1 }), 0);
  store.applyOne(marker({ ns: "pillars", action: 3 }), 0);
  assert.deepEqual(tally(store.live(0)).byNs, { walls: 1, x: 1 });
  store.applyOne(marker({ ns: "", action: 3 }), 0);
  assert.equal(store.live(0).length, 0);
});

test("lifetime: a marker expires that long after it arrived; 0 is forever", () => {
  const store = new MarkerStore();
  store.apply(marker({ id: 1, lifetime: { sec: 1, nanosec: 500_000_000 } }), 1000);
  store.apply(marker({ id: 2 }), 1000);
  assert.equal(store.nextExpiry(), 2500);
  assert.equal(store.live(2499).length, 2);
  assert.equal(store.live(2500).length, 1);
  assert.equal(store.nextExpiry(), Infinity);
});

test("shapes of the other types: cube, arrow, line list, points, text", () => {
  const yaw90 = { x: 0, y: 0, z: Math.SQRT1_2, w: Math.SQRT1_2 };
  const cube = shapesOf(marker({ type: 1, pose: { position: { x: 1, y: 2, z: 0 }, orientation: yaw90 }, scale: { x: 2, y: 1, z: 1 } }));
  assert.equal(cube[0].kind, "polygon");
  if (cube[0].kind === "polygon") {
    // 2 m along x rotated by 90°: 2 m along y.
    const ys = cube[0].pts.map((p) => p[1]), xs = cube[0].pts.map((p) => p[0]);
    assert.ok(Math.abs(Math.max(...ys) - Math.min(...ys) - 2) < 1e-9 && Math.abs(Math.max(...xs) - Math.min(...xs) - 1) < 1e-9);
  }
  const arrow = shapesOf(marker({ type: 0, scale: { x: 0.1, y: 0.2, z: 0.3 }, points: [{ x: 0, y: 0, z: 0 }, { x: 2, y: 0, z: 0 }] }));
  assert.equal(arrow[0].kind, "polygon");
  if (arrow[0].kind === "polygon") assert.deepEqual(arrow[0].pts[3], [2, 0]);
  const poseArrow = shapesOf(marker({ type: 0, scale: { x: 1.5, y: 0.1, z: 0.1 } }));
  if (poseArrow[0].kind === "polygon") assert.ok(Math.abs(poseArrow[0].pts[3][0] - 1.5) < 1e-9);
  const list = shapesOf(marker({ type: 5, scale: { x: 0.05, y: 0, z: 0 }, points: [{ x: 0, y: 0 }, { x: 1, y: 0 }, { x: 2, y: 0 }, { x: 3, y: 0 }] }));
  assert.equal(list.length, 2);
  const pts = shapesOf(marker({ type: 8, scale: { x: 0.1, y: 0.1, z: 0 }, points: [{ x: 1, y: 1 }, { x: 2, y: 2 }], colors: [{ r: 0, g: 1, b: 0, a: 1 }, { r: 0, g: 0, b: 1, a: 0.5 }] }));
  assert.equal(pts.length, 2);
  if (pts[1].kind === "square") assert.equal(pts[1].fill, "rgba(0,0,255,0.5)");
  const text = shapesOf(marker({ type: 9, text: "dock", scale: { x: 0, y: 0, z: 0.5 } }));
  assert.deepEqual(text, [{ kind: "text", x: 0, y: 0, height: 0.5, text: "dock", fill: "rgba(255,0,0,1)" }]);
  assert.deepEqual(shapesOf(marker({ type: 10 })), []);
});
