// visualization_msgs markers: the state a marker topic builds up (ADD/MODIFY replaces the
// marker with the same namespace and id, DELETE removes it, DELETEALL removes all of the
// topic's markers — or only those of its namespace when one is given — and a non-zero
// lifetime expires a marker that long after it arrived), and how each marker looks from
// above, in map coordinates. Pure: no DOM, unit-tested on a frame from the demo hub.
//
// Markers are placed in the frame the robot's pose uses (the page has no TF): a marker
// in that frame — the simulator publishes the room in it — lines up with the robot.

import { yawOf } from "./messages";

export const MARKER_TYPES = [
  "ARROW", "CUBE", "SPHERE", "CYLINDER", "LINE_STRIP", "LINE_LIST", "CUBE_LIST", "SPHERE_LIST",
  "POINTS", "TEXT_VIEW_FACING", "MESH_RESOURCE", "TRIANGLE_LIST",
] as const;
export const ADD = 0, DELETE = 2, DELETEALL = 3;

export interface Rgba { r: number; g: number; b: number; a: number }
interface Xyz { x: number; y: number; z: number }

/** One marker as it arrived (rosbridge JSON or CBOR: the same field names). */
export interface MarkerMsg {
  header?: { frame_id?: string };
  ns?: string;
  id?: number;
  type?: number;
  action?: number;
  pose?: { position?: Partial<Xyz>; orientation?: { x: number; y: number; z: number; w: number } };
  scale?: Partial<Xyz>;
  color?: Partial<Rgba>;
  lifetime?: { sec?: number; nanosec?: number; secs?: number; nsecs?: number };
  points?: ArrayLike<Partial<Xyz>>;
  colors?: ArrayLike<Partial<Rgba>>;
  text?: string;
}

export interface StoredMarker {
  msg: MarkerMsg;
  /** Page time (ms) after which it is gone; Infinity for lifetime 0. */
  expires: number;
}

const key = (ns: string, id: number) => `${ns}\u0000${id}`;

function lifetimeMs(l: MarkerMsg["lifetime"]): number {
  if (!l) return 0;
  return (l.sec ?? l.secs ?? 0) * 1000 + (l.nanosec ?? l.nsecs ?? 0) / 1e6;
}

/** The markers of one topic. */
export class MarkerStore {
  readonly markers = new Map<string, StoredMarker>();

  /** Applies a `Marker` or a `MarkerArray` message received at page time `now` (ms). */
  apply(msg: any, now: number) {
    if (Array.isArray(msg?.markers)) for (const m of msg.markers) this.applyOne(m, now);
    else if (msg && typeof msg === "object") this.applyOne(msg, now);
  }

  applyOne(m: MarkerMsg, now: number) {
    const ns = m.ns ?? "", id = m.id ?? 0, action = m.action ?? ADD;
    if (action === DELETEALL) {
      if (!ns) this.markers.clear();
      else for (const [k, s] of this.markers) if ((s.msg.ns ?? "") === ns) this.markers.delete(k);
    } else if (action === DELETE) {
      this.markers.delete(key(ns, id));
    } else if (action === ADD || action === 1) {
      // ADD and MODIFY (both 0; 1 is ROS 1's deprecated MODIFY). Other actions are ignored.
      const life = lifetimeMs(m.lifetime);
      this.markers.set(key(ns, id), { msg: m, expires: life > 0 ? now + life : Infinity });
    }
  }

  /** Drops expired markers; returns the live ones. */
  live(now: number): StoredMarker[] {
    const out: StoredMarker[] = [];
    for (const [k, s] of this.markers) {
      if (s.expires <= now) this.markers.delete(k);
      else out.push(s);
    }
    return out;
  }

  /** The next expiry (ms page time), to redraw when a marker runs out. */
  nextExpiry(): number {
    let t = Infinity;
    for (const s of this.markers.values()) t = Math.min(t, s.expires);
    return t;
  }
}

/** A marker colour as CSS. */
export function css(c: Partial<Rgba> | undefined, fallback?: Partial<Rgba>): string {
  const k = c ?? fallback ?? {};
  const ch = (v: number | undefined) => Math.round(Math.min(1, Math.max(0, v ?? 0)) * 255);
  return `rgba(${ch(k.r)},${ch(k.g)},${ch(k.b)},${Math.min(1, Math.max(0, k.a ?? 1))})`;
}

/** What to draw, in map coordinates (metres), for one marker. */
export type Shape =
  | { kind: "polygon"; pts: [number, number][]; fill: string }
  | { kind: "ellipse"; x: number; y: number; rx: number; ry: number; yaw: number; fill: string; outline: boolean }
  | { kind: "polyline"; pts: [number, number][]; width: number; stroke: string }
  | { kind: "square"; x: number; y: number; w: number; h: number; fill: string }
  | { kind: "text"; x: number; y: number; height: number; text: string; fill: string };

/** A marker seen from above: a list of shapes (empty for what cannot be drawn in 2D). */
export function shapesOf(m: MarkerMsg): Shape[] {
  const p = m.pose?.position ?? {}, q = m.pose?.orientation;
  const px = p.x ?? 0, py = p.y ?? 0;
  const yaw = q ? yawOf(q) : 0, c = Math.cos(yaw), s = Math.sin(yaw);
  const sx = m.scale?.x ?? 0, sy = m.scale?.y ?? 0, sz = m.scale?.z ?? 0;
  const colour = css(m.color);
  // A point of the marker's own frame → the map.
  const T = (x: number, y: number): [number, number] => [px + c * x - s * y, py + s * x + c * y];
  const points = Array.from(m.points ?? [], (v) => T(v.x ?? 0, v.y ?? 0));
  const colourAt = (i: number) => (m.colors && m.colors.length > i ? css(m.colors[i]) : colour);
  const out: Shape[] = [];
  switch (m.type) {
    case 0: { // ARROW: from points[0] to points[1] (shaft diameter x, head diameter y, head length z), else along the pose's x axis (length x, width y)
      let a: [number, number], b: [number, number], shaft: number, head: number, headLen: number;
      if (points.length >= 2) {
        [a, b] = points;
        shaft = sx; head = sy || 2 * sx; headLen = sz || Math.hypot(b[0] - a[0], b[1] - a[1]) * 0.3;
      } else {
        a = T(0, 0); b = T(sx, 0);
        shaft = sy; head = 2 * sy; headLen = sx * 0.23;
      }
      const len = Math.hypot(b[0] - a[0], b[1] - a[1]);
      if (!(len > 0)) break;
      const ux = (b[0] - a[0]) / len, uy = (b[1] - a[1]) / len, nx = -uy, ny = ux;
      headLen = Math.min(headLen, len);
      const h0: [number, number] = [b[0] - ux * headLen, b[1] - uy * headLen];
      const w = shaft / 2, hw = head / 2;
      out.push({ kind: "polygon", fill: colour, pts: [
        [a[0] + nx * w, a[1] + ny * w], [h0[0] + nx * w, h0[1] + ny * w], [h0[0] + nx * hw, h0[1] + ny * hw],
        b, [h0[0] - nx * hw, h0[1] - ny * hw], [h0[0] - nx * w, h0[1] - ny * w], [a[0] - nx * w, a[1] - ny * w],
      ] });
      break;
    }
    case 1: // CUBE: its footprint
      out.push({ kind: "polygon", fill: colour, pts: [T(-sx / 2, -sy / 2), T(sx / 2, -sy / 2), T(sx / 2, sy / 2), T(-sx / 2, sy / 2)] });
      break;
    case 2: // SPHERE
    case 3: // CYLINDER: its footprint, outlined so neighbours stay apart
      out.push({ kind: "ellipse", x: px, y: py, rx: sx / 2, ry: sy / 2, yaw, fill: colour, outline: m.type === 3 });
      break;
    case 4: // LINE_STRIP (width scale.x)
    case 5: { // LINE_LIST: pairs
      const step = m.type === 4 ? 1 : 2;
      for (let i = 0; i + 1 < points.length; i += step) {
        out.push({ kind: "polyline", pts: [points[i], points[i + 1]], width: sx, stroke: colourAt(i) });
      }
      // One path when the strip has one colour: joins drawn properly.
      if (m.type === 4 && !(m.colors && m.colors.length) && points.length > 1) {
        out.length = 0;
        out.push({ kind: "polyline", pts: points, width: sx, stroke: colour });
      }
      break;
    }
    case 6: // CUBE_LIST
    case 8: // POINTS (width x, height y)
      points.forEach(([x, y], i) => out.push({ kind: "square", x, y, w: sx, h: m.type === 8 ? sy || sx : sy, fill: colourAt(i) }));
      break;
    case 7: // SPHERE_LIST
      points.forEach(([x, y], i) => out.push({ kind: "ellipse", x, y, rx: sx / 2, ry: sy / 2, yaw: 0, fill: colourAt(i), outline: false }));
      break;
    case 9: // TEXT_VIEW_FACING: scale.z is the height of a capital letter
      if (m.text) out.push({ kind: "text", x: px, y: py, height: sz, text: m.text, fill: colour });
      break;
    case 11: // TRIANGLE_LIST
      for (let i = 0; i + 2 < points.length; i += 3) out.push({ kind: "polygon", pts: [points[i], points[i + 1], points[i + 2]], fill: colourAt(i) });
      break;
    default: // MESH_RESOURCE and unknown types: nothing to draw from above
      break;
  }
  return out;
}

/** Per type name and per namespace, how many markers a list holds (for the probe and the panel). */
export function tally(list: StoredMarker[]): { byType: Record<string, number>; byNs: Record<string, number> } {
  const byType: Record<string, number> = {}, byNs: Record<string, number> = {};
  for (const { msg } of list) {
    const t = MARKER_TYPES[msg.type ?? -1] ?? `type ${msg.type}`;
    byType[t] = (byType[t] ?? 0) + 1;
    const ns = msg.ns ?? "";
    byNs[ns] = (byNs[ns] ?? 0) + 1;
  }
  return { byType, byNs };
}
