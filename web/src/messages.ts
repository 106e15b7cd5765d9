// Turning decoded rosbridge messages into what the panels draw. Pure functions, no DOM,
// unit-tested against frames the hub produced (test/fixtures, see test/messages.test.ts).
//
// With `compression: "cbor"` the hub sends numeric arrays as RFC 8746 typed arrays and
// `uint8[]` as byte strings, so `ranges` is already a Float32Array and a cloud's `data`
// a Uint8Array; with JSON they are number arrays and a base64 string. Both are accepted
// here so the inspector and the tests can feed either.

export type Numbers = ArrayLike<number>;

/** `uint8[]` as bytes, whether it came as a CBOR byte string, a JSON base64 text or numbers. */
export function bytesOf(v: unknown): Uint8Array {
  if (v instanceof Uint8Array) return v;
  if (ArrayBuffer.isView(v)) return new Uint8Array(v.buffer, v.byteOffset, v.byteLength);
  if (typeof v === "string") {
    const bin = atob(v);
    const out = new Uint8Array(bin.length);
    for (let i = 0; i < bin.length; i++) out[i] = bin.charCodeAt(i);
    return out;
  }
  if (Array.isArray(v)) return Uint8Array.from(v as number[]);
  return new Uint8Array(0);
}

/** Header stamp in milliseconds since the epoch (ROS 2 `sec`/`nanosec`, ROS 1 `secs`/`nsecs`). */
export function stampMs(header: any): number | null {
  const s = header?.stamp;
  if (!s) return null;
  const sec = s.sec ?? s.secs;
  const ns = s.nanosec ?? s.nsecs ?? 0;
  return typeof sec === "number" ? sec * 1000 + ns / 1e6 : null;
}

/** Yaw (rad) of a quaternion. */
export function yawOf(q: { x: number; y: number; z: number; w: number }): number {
  return Math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z));
}

export interface Pose2D {
  x: number;
  y: number;
  yaw: number;
}

/** The 2D pose of a `PoseStamped`, `Odometry` or `Pose`/`PoseWithCovariance`-carrying message. */
export function pose2d(msg: any): Pose2D | null {
  let p = msg?.pose;
  if (p?.pose) p = p.pose; // Odometry / PoseWithCovariance(Stamped)
  if (!p?.position || !p?.orientation) return null;
  return { x: p.position.x, y: p.position.y, yaw: yawOf(p.orientation) };
}

/** LaserScan → points in the sensor frame, as interleaved x,y (NaN/out-of-range skipped). */
export function scanPoints(msg: any): Float32Array {
  const ranges: Numbers = msg.ranges ?? [];
  const out = new Float32Array(ranges.length * 2);
  let n = 0;
  for (let i = 0; i < ranges.length; i++) {
    const r = ranges[i];
    if (!(r >= msg.range_min && r <= msg.range_max)) continue;
    const a = msg.angle_min + i * msg.angle_increment;
    out[n++] = r * Math.cos(a);
    out[n++] = r * Math.sin(a);
  }
  return out.subarray(0, n);
}

/** sensor_msgs/PointField datatypes: size in bytes and DataView getter. */
const FIELD_TYPES: Record<number, [number, (dv: DataView, o: number, le: boolean) => number]> = {
  1: [1, (d, o) => d.getInt8(o)],
  2: [1, (d, o) => d.getUint8(o)],
  3: [2, (d, o, le) => d.getInt16(o, le)],
  4: [2, (d, o, le) => d.getUint16(o, le)],
  5: [4, (d, o, le) => d.getInt32(o, le)],
  6: [4, (d, o, le) => d.getUint32(o, le)],
  7: [4, (d, o, le) => d.getFloat32(o, le)],
  8: [8, (d, o, le) => d.getFloat64(o, le)],
};

export interface Cloud {
  /** Interleaved x,y,z of the finite points. */
  positions: Float32Array;
  /** Per point: the `intensity` field when present, else NaN. */
  intensity: Float32Array;
  count: number;
}

/**
 * PointCloud2 → positions (and intensity when there is such a field). `into` lets the
 * caller reuse buffers between frames so a 10 Hz 100k-point cloud allocates nothing.
 */
export function unpackCloud(msg: any, into?: Cloud): Cloud {
  const data = bytesOf(msg.data);
  const total = (msg.width ?? 0) * (msg.height ?? 1);
  const step: number = msg.point_step;
  const le = !msg.is_bigendian;
  const field = (name: string) => (msg.fields as any[]).find((f) => f.name === name);
  const fx = field("x"), fy = field("y"), fz = field("z"), fi = field("intensity");
  if (!fx || !fy || !fz || !step) throw new Error("PointCloud2 without x, y, z fields");
  const positions = into && into.positions.length >= total * 3 ? into.positions : new Float32Array(total * 3);
  const intensity = into && into.intensity.length >= total ? into.intensity : new Float32Array(total);
  const dv = new DataView(data.buffer, data.byteOffset, data.byteLength);
  const fast = le && fx.datatype === 7 && fy.datatype === 7 && fz.datatype === 7;
  const gx = FIELD_TYPES[fx.datatype][1], gy = FIELD_TYPES[fy.datatype][1], gz = FIELD_TYPES[fz.datatype][1];
  const gi = fi ? FIELD_TYPES[fi.datatype]?.[1] : undefined;
  const rows = msg.height ?? 1, cols = msg.width ?? 0, rowStep = msg.row_step || cols * step;
  let n = 0;
  for (let r = 0; r < rows; r++) {
    for (let c = 0; c < cols; c++) {
      const o = r * rowStep + c * step;
      if (o + step > data.byteLength) break;
      const x = fast ? dv.getFloat32(o + fx.offset, true) : gx(dv, o + fx.offset, le);
      const y = fast ? dv.getFloat32(o + fy.offset, true) : gy(dv, o + fy.offset, le);
      const z = fast ? dv.getFloat32(o + fz.offset, true) : gz(dv, o + fz.offset, le);
      if (!Number.isFinite(x) || !Number.isFinite(y) || !Number.isFinite(z)) continue;
      positions[n * 3] = x;
      positions[n * 3 + 1] = y;
      positions[n * 3 + 2] = z;
      intensity[n] = gi ? gi(dv, o + fi.offset, le) : NaN;
      n++;
    }
  }
  return { positions, intensity, count: n };
}

/** What a CompressedImage's bytes are: a decodable format by magic number, or not. */
export function imageKind(data: Uint8Array): "jpeg" | "png" | "unknown" {
  if (data.length > 3 && data[0] === 0xff && data[1] === 0xd8 && data[2] === 0xff) return "jpeg";
  if (data.length > 8 && data[0] === 0x89 && data[1] === 0x50 && data[2] === 0x4e && data[3] === 0x47) return "png";
  return "unknown";
}

/** A JSON-safe copy for the inspector: typed arrays and byte strings summarised, not expanded. */
export function inspectable(v: unknown, maxItems = 64): unknown {
  if (v instanceof Uint8Array) return `<${v.length} bytes>`;
  if (ArrayBuffer.isView(v)) {
    const a = Array.from((v as unknown as Numbers) as ArrayLike<number>).slice(0, maxItems);
    const total = (v as unknown as { length: number }).length;
    return total > maxItems ? [...a, `… ${total - maxItems} more (${v.constructor.name})`] : a;
  }
  if (Array.isArray(v)) {
    const a = v.slice(0, maxItems).map((x) => inspectable(x, maxItems));
    return v.length > maxItems ? [...a, `… ${v.length - maxItems} more`] : a;
  }
  if (v && typeof v === "object") {
    const o: Record<string, unknown> = {};
    for (const [k, x] of Object.entries(v)) o[k] = inspectable(x, maxItems);
    return o;
  }
  return v;
}

/**
 * A skeleton message (JSON) for a type from `/rosapi/*_details` typedefs: what the
 * service form starts from. Typedefs are `{type, fieldnames, fieldtypes, fieldarraylen,
 * examples}` as rosapi gives them.
 */
export interface Typedef {
  type: string;
  fieldnames: string[];
  fieldtypes: string[];
  fieldarraylen: number[];
  examples?: string[];
}

const PRIMITIVE_DEFAULT: Record<string, unknown> = {
  bool: false, string: "", float32: 0, float64: 0, int8: 0, uint8: 0, int16: 0, uint16: 0,
  int32: 0, uint32: 0, int64: 0, uint64: 0, byte: 0, char: 0, time: { sec: 0, nanosec: 0 },
  duration: { sec: 0, nanosec: 0 },
};

export function skeleton(typedefs: Typedef[], type?: string): Record<string, unknown> {
  const root = type ? typedefs.find((t) => t.type === type) : typedefs[0];
  const build = (td: Typedef | undefined, depth: number): Record<string, unknown> => {
    const out: Record<string, unknown> = {};
    if (!td || depth > 16) return out;
    td.fieldnames.forEach((name, i) => {
      const ft = td.fieldtypes[i];
      const len = td.fieldarraylen?.[i] ?? -1;
      const one = ft in PRIMITIVE_DEFAULT ? PRIMITIVE_DEFAULT[ft] : build(typedefs.find((t) => t.type === ft), depth + 1);
      out[name] = len === -1 ? one : len === 0 ? [] : Array.from({ length: len }, () => one);
    });
    return out;
  };
  return build(root, 0);
}
