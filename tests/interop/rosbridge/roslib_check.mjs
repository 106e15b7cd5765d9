#!/usr/bin/env node
// rosbridge interop check with roslib (roslibjs, from npm) under Node against a fleetlink
// hub or agent. Same checks as roslibpy_check.py:
//   --mode hub    --url is the hub; topics are /<robot>/scan ...; publishing a
//                 geometry_msgs/msg/Twist on /<robot>/cmd_vel at the hub must reach a
//                 second roslib client subscribed to /cmd_vel on --peer-url (the agent's
//                 local listener).
//   --mode local  --url is the agent's local listener; topics are /scan ...; publishing on
//                 a local topic must reach a roslib client on the hub (--peer-url) under
//                 /<robot>/<topic>.
// roslib 2.x is ESM; under Node 20 (no global WebSocket) its default transport factory
// uses the `ws` package (a dependency of roslib) with binaryType 'arraybuffer', so CBOR
// frames are decoded by roslib itself (cbor2). Exits 0 when every check passed, 1 with a
// message naming the failed check otherwise. Every wait is bounded by a timeout.

import { isDeepStrictEqual, parseArgs } from "node:util";
import { readFileSync } from "node:fs";
import { Ros, Topic, Service } from "roslib";

const TIMEOUT_MS = 10_000;
const PUBLISH_ATTEMPTS = 100;
const PUBLISH_INTERVAL_MS = 100;

const { values: args } = parseArgs({
  options: {
    url: { type: "string" },
    mode: { type: "string" },
    robot: { type: "string", default: "robot1" },
    "peer-url": { type: "string" },
    "scan-ranges": { type: "string", default: "720" },
    points: { type: "string", default: "2000" },
  },
});
if (!args.url || !["hub", "local"].includes(args.mode) || !args["peer-url"]) {
  console.error(
    "usage: roslib_check.mjs --url ws://HOST:PORT/ --mode hub|local --peer-url ws://... [--robot robot1] [--scan-ranges 720] [--points 2000]",
  );
  process.exit(2);
}
const robot = args.robot;
const ns = args.mode === "hub" ? `/${robot}` : "";
const SCAN_RANGES = Number(args["scan-ranges"]);
const POINTS = Number(args.points);

class CheckFailed extends Error {}
function check(cond, what) {
  if (!cond) throw new CheckFailed(what);
}
function ok(what) {
  console.log(`  ok: ${what}`);
}

/** Resolves with fn's result, or rejects naming `what` after `ms`. */
function within(ms, what, fn) {
  return new Promise((resolve, reject) => {
    const timer = setTimeout(
      () => reject(new CheckFailed(`${what}: nothing within ${ms} ms`)),
      ms,
    );
    fn(
      (v) => {
        clearTimeout(timer);
        resolve(v);
      },
      (e) => {
        clearTimeout(timer);
        reject(e instanceof Error ? e : new CheckFailed(`${what}: ${JSON.stringify(e)}`));
      },
    );
  });
}

const clients = [];
async function connect(url) {
  const ros = new Ros({});
  clients.push(ros);
  await within(TIMEOUT_MS, `connect ${url}`, (resolve, reject) => {
    ros.on("connection", () => resolve());
    // Later errors (a frame roslib could not decode, ...) are printed: a check that then
    // times out says why.
    ros.on("error", (e) => {
      console.error(`  roslib error on ${url}: ${e?.message ?? e}`);
      reject(new CheckFailed(`connect ${url}: ${e?.message ?? e}`));
    });
    ros.connect(url).catch(reject);
  });
  return ros;
}

function call(ros, name, request = {}, serviceType = "") {
  const svc = new Service({ ros, name, serviceType });
  return within(TIMEOUT_MS, `call ${name}`, (resolve, reject) =>
    svc.callService(request, resolve, (e) => reject(new CheckFailed(`call ${name} failed: ${e}`))),
  );
}

/** Collects `n` messages from a subscription, then unsubscribes. */
function collect(ros, name, messageType, n, options = {}) {
  const topic = new Topic({ ros, name, messageType, ...options });
  const got = [];
  return within(TIMEOUT_MS, `${n} message(s) on ${name}`, (resolve) => {
    topic.subscribe((m) => {
      got.push(m);
      if (got.length === n) {
        topic.unsubscribe();
        resolve(got);
      }
    });
  }).catch((e) => {
    topic.unsubscribe();
    throw new CheckFailed(`${e.message} (got ${got.length})`);
  });
}

function checkStamp(stamp, what) {
  check(stamp && "sec" in stamp && "nanosec" in stamp, `${what}: header.stamp ${JSON.stringify(stamp)} lacks sec/nanosec`);
  check(stamp.nanosec >= 0 && stamp.nanosec < 1e9, `${what}: nanosec ${stamp.nanosec}`);
  const t = stamp.sec + stamp.nanosec * 1e-9;
  check(Math.abs(t - Date.now() / 1000) < 60, `${what}: stamp ${t} not near now`);
  return t;
}

async function checkTopics(ros) {
  const want = {
    [`${ns}/scan`]: "sensor_msgs/msg/LaserScan",
    [`${ns}/odom`]: "nav_msgs/msg/Odometry",
    [`${ns}/points`]: "sensor_msgs/msg/PointCloud2",
  };
  const res = await within(TIMEOUT_MS, "ros.getTopics()", (resolve, reject) =>
    ros.getTopics(resolve, (e) => reject(new CheckFailed(`ros.getTopics() failed: ${e}`))),
  );
  check(Array.isArray(res.topics) && Array.isArray(res.types), `getTopics: reply ${JSON.stringify(res).slice(0, 200)}`);
  check(res.topics.length === res.types.length, `getTopics: ${res.topics.length} topics, ${res.types.length} types`);
  for (const [t, ty] of Object.entries(want)) {
    const i = res.topics.indexOf(t);
    check(i >= 0, `getTopics lacks ${t}: ${res.topics}`);
    check(res.types[i] === ty, `getTopics: type of ${t} is ${res.types[i]}, want ${ty}`);
  }
  ok(`ros.getTopics() (/rosapi/topics) lists ${Object.entries(want).map(([t, ty]) => `${t}=${ty}`).join(", ")}`);
  const ty = await within(TIMEOUT_MS, "ros.getTopicType()", (resolve, reject) =>
    ros.getTopicType(`${ns}/odom`, resolve, (e) => reject(new CheckFailed(`getTopicType failed: ${e}`))),
  );
  check(ty === "nav_msgs/msg/Odometry", `/rosapi/topic_type ${ns}/odom = ${ty}`);
  ok(`ros.getTopicType(${ns}/odom) = ${ty}`);
}

async function checkGetTime(ros) {
  const res = await call(ros, "/rosapi/get_time", {}, "rosapi/GetTime");
  const t = res.time;
  check(t && Number.isInteger(t.sec) && Number.isInteger(t.nanosec), `/rosapi/get_time: ${JSON.stringify(res)}`);
  check(Math.abs(t.sec + t.nanosec * 1e-9 - Date.now() / 1000) < 60, `/rosapi/get_time ${JSON.stringify(t)} not near now`);
  ok(`/rosapi/get_time = ${t.sec}.${String(t.nanosec).padStart(9, "0")}`);
}

async function checkGraph(ros) {
  const services = await within(TIMEOUT_MS, "ros.getServices()", (resolve, reject) =>
    ros.getServices(resolve, (e) => reject(new CheckFailed(`getServices failed: ${e}`))),
  );
  for (const s of ["/rosapi/topics", "/rosapi/get_time", "/rosapi/topic_type"]) {
    check(Array.isArray(services) && services.includes(s), `/rosapi/services lacks ${s}: ${services}`);
  }
  const nodes = await within(TIMEOUT_MS, "ros.getNodes()", (resolve, reject) =>
    ros.getNodes(resolve, (e) => reject(new CheckFailed(`getNodes failed: ${e}`))),
  );
  check(Array.isArray(nodes) && nodes.length > 0 && nodes.every((n) => typeof n === "string" && n.startsWith("/")), `/rosapi/nodes: ${JSON.stringify(nodes)}`);
  if (args.mode === "hub") check(nodes.includes(`/${robot}`), `/rosapi/nodes at the hub lacks /${robot}: ${nodes}`);
  ok(`ros.getServices() lists the rosapi services; ros.getNodes() = ${JSON.stringify(nodes)}`);
}

async function checkScan(ros) {
  const msgs = await collect(ros, `${ns}/scan`, "sensor_msgs/msg/LaserScan", 3);
  const stamps = [];
  for (const m of msgs) {
    const r = m.ranges;
    check(r.length === SCAN_RANGES, `scan: ${r.length} ranges, want ${SCAN_RANGES}`);
    const { angle_min: amin, angle_max: amax, angle_increment: inc } = m;
    check(inc > 0 && amin < amax, `scan: angles min ${amin} max ${amax} inc ${inc}`);
    check(Math.abs(amin + inc * (r.length - 1) - amax) < 1e-3, `scan: angle_min + inc*(n-1) != angle_max`);
    const bad = Array.from(r).filter((x) => !(typeof x === "number" && x >= m.range_min && x <= m.range_max));
    check(bad.length === 0, `scan: ${bad.length} ranges outside [${m.range_min}, ${m.range_max}]`);
    check(m.header.frame_id.endsWith("laser"), `scan: frame_id ${m.header.frame_id}`);
    stamps.push(checkStamp(m.header.stamp, "scan"));
  }
  check(stamps[0] < stamps[1] && stamps[1] < stamps[2], `scan: stamps not increasing: ${stamps}`);
  ok(`3 LaserScans on ${ns}/scan: ${SCAN_RANGES} ranges, consistent angles, increasing stamps`);
}

async function checkOdom(ros) {
  const [m] = await collect(ros, `${ns}/odom`, "nav_msgs/msg/Odometry", 1);
  check(m.child_frame_id.endsWith("base_link"), `odom: child_frame_id ${m.child_frame_id}`);
  check(m.pose.covariance.length === 36, "odom: pose.covariance length");
  const q = m.pose.pose.orientation;
  const norm = Math.hypot(q.x, q.y, q.z, q.w);
  check(Math.abs(norm - 1) < 1e-3, `odom: orientation not a unit quaternion (${norm})`);
  checkStamp(m.header.stamp, "odom");
  ok(`Odometry on ${ns}/odom: unit quaternion, 6x6 covariances`);
}

async function checkPoints(ros, compression) {
  const [m] = await collect(ros, `${ns}/points`, "sensor_msgs/msg/PointCloud2", 1, { compression });
  let data = m.data;
  let form = "base64";
  if (compression === "cbor" && data instanceof Uint8Array) {
    form = "bytes";
  } else if (compression === "cbor") {
    // rosbridge sends uint8[] as a CBOR byte string (docs/protocol.md §2.2).
    throw new Error(`points (cbor): data is ${Object.prototype.toString.call(data)}, want a Uint8Array from a CBOR byte string`);
  } else {
    check(typeof data === "string", `points (json): data is ${typeof data}, want base64 string`);
    data = Buffer.from(data, "base64");
  }
  check(m.width === POINTS, `points (${compression}): width ${m.width}, want ${POINTS}`);
  check(
    data.length === m.width * m.height * m.point_step && data.length === m.row_step * m.height,
    `points (${compression}): ${data.length} bytes for width ${m.width} x point_step ${m.point_step}`,
  );
  checkStamp(m.header.stamp, `points (${compression})`);
  ok(`PointCloud2 on ${ns}/points (${compression}): data ${data.length} bytes = ${m.width} x ${m.point_step} as ${form}`);
}

/** Resolves once the server answered a request sent after everything before it. */
function barrier(ros) {
  return call(ros, "/rosapi/get_time", {}, "rosapi/GetTime");
}

// A program that publishes and listens on one connection hears itself (as with rosbridge).
async function checkOwnMessages(ros) {
  const name = `/interop_js/self_${args.mode}`;
  const topic = new Topic({ ros, name, messageType: "std_msgs/msg/String" });
  topic.advertise();
  const got = within(TIMEOUT_MS, `own message on ${name}`, (resolve) => topic.subscribe((m) => resolve(m)));
  // A connection's operations are handled in order: once this answer is back, the
  // advertise and the subscription are in place.
  await barrier(ros);
  topic.publish({ data: "self" });
  const m = await got;
  topic.unsubscribe();
  check(m.data === "self", `own message: ${JSON.stringify(m)}`);
  ok(`a client publishing and subscribing ${name} on one connection received its own message`);
}

// A burst of 1,000 small messages reaches a subscriber with the default queue whole.
async function checkBurst(ros) {
  const name = `/interop_js/burst_${args.mode}`;
  const other = await connect(args.url);
  const sub = new Topic({ ros: other, name, messageType: "std_msgs/msg/Int32" });
  const seen = [];
  const all = within(TIMEOUT_MS, `1000 messages of a burst on ${name}`, (resolve) =>
    sub.subscribe((m) => {
      seen.push(m.data);
      if (seen.length === 1000) resolve();
    }),
  ).catch((e) => {
    throw new CheckFailed(`${e.message} (got ${seen.length})`);
  });
  const pub = new Topic({ ros, name, messageType: "std_msgs/msg/Int32" });
  pub.advertise();
  await barrier(other);
  await barrier(ros);
  for (let i = 0; i < 1000; i++) pub.publish({ data: i });
  await all;
  sub.unsubscribe();
  check(seen.every((v, i) => v === i), "burst arrived out of order");
  ok(`a burst of 1000 messages on ${name} arrived whole and in order`);
}

async function checkInvalidOp(ros) {
  const id = "bad-op-1";
  const st = await within(TIMEOUT_MS, "status reply to op 'no_such_op'", (resolve) => {
    ros.once(`status:${id}`, resolve); // roslib routes status frames with an id here
    ros.callOnConnection({ op: "no_such_op", id });
  });
  check(st.level === "error", `invalid op: status level ${st.level}: ${JSON.stringify(st)}`);
  check(String(st.msg).includes("no_such_op"), `invalid op: msg does not name the op: ${JSON.stringify(st)}`);
  ok(`invalid op answered: ${JSON.stringify(st)}`);
  await checkGetTime(ros);
  ok("connection still serves requests after the error");
}

/** Publishes until the subscriber has it; bounded in count and time. */
async function publishUntilReceived(pub, msg, sub, what, pred) {
  let resolveGot;
  const got = new Promise((r) => (resolveGot = r));
  sub.subscribe((m) => {
    if (pred(m)) resolveGot(m);
  });
  pub.advertise();
  try {
    for (let i = 0; i < PUBLISH_ATTEMPTS; i++) {
      pub.publish(msg);
      let timer;
      const tick = new Promise((r) => (timer = setTimeout(() => r(undefined), PUBLISH_INTERVAL_MS)));
      const m = await Promise.race([got, tick]);
      clearTimeout(timer);
      if (m !== undefined) return m;
    }
    throw new CheckFailed(`${what}: nothing after ${PUBLISH_ATTEMPTS} publishes (${(PUBLISH_ATTEMPTS * PUBLISH_INTERVAL_MS) / 1000}s)`);
  } finally {
    pub.unadvertise();
    sub.unsubscribe();
  }
}

async function checkPublishHub(ros) {
  const local = await connect(args["peer-url"]);
  const nonce = Math.floor(Math.random() * 1e6) / 1024; // exactly representable
  const twist = { linear: { x: 0.5, y: -0.25, z: 0 }, angular: { x: 0, y: 0, z: nonce } };
  const sub = new Topic({ ros: local, name: "/cmd_vel", messageType: "geometry_msgs/msg/Twist" });
  const pub = new Topic({ ros, name: `/${robot}/cmd_vel`, messageType: "geometry_msgs/msg/Twist" });
  const got = await publishUntilReceived(pub, twist, sub, "Twist at the robot's local /cmd_vel", (m) => m.angular?.z === nonce);
  check(isDeepStrictEqual(got, twist), `cmd_vel: robot got ${JSON.stringify(got)}, sent ${JSON.stringify(twist)}`);
  ok(`Twist published on /${robot}/cmd_vel at the hub reached local /cmd_vel unchanged`);
  local.close();
}

async function checkPublishLocal(ros) {
  const hub = await connect(args["peer-url"]);
  const text = `hello from roslibjs ${Math.floor(Math.random() * 2 ** 30)}`;
  const sub = new Topic({ ros: hub, name: `/${robot}/interop_js/chatter`, messageType: "std_msgs/msg/String" });
  const pub = new Topic({ ros, name: "/interop_js/chatter", messageType: "std_msgs/msg/String" });
  const got = await publishUntilReceived(pub, { data: text }, sub, `String at the hub on /${robot}/interop_js/chatter`, (m) => m.data === text);
  check(isDeepStrictEqual(got, { data: text }), `chatter: hub got ${JSON.stringify(got)}`);
  ok(`String published locally on /interop_js/chatter reached the hub as /${robot}/interop_js/chatter`);
  hub.close();
}

const ZERO_TIME = { sec: 0, nanosec: 0 };

/** A message with its typed arrays (CBOR's numeric arrays) as plain arrays. */
function plain(v) {
  if (ArrayBuffer.isView(v) && !(v instanceof DataView)) return Array.from(v);
  if (Array.isArray(v)) return v.map(plain);
  if (v && typeof v === "object") return Object.fromEntries(Object.entries(v).map(([k, x]) => [k, plain(x)]));
  return v;
}

// Partial messages reach JSON and CBOR subscribers with the type's defaults filled.
async function checkPartialMessages(ros) {
  const nonce = `partial-${Math.floor(Math.random() * 2 ** 30)}`;
  const cases = [
    {
      name: "/interop_js/goal_id",
      type: "actionlib_msgs/GoalID",
      msg: { id: nonce },
      pred: (m) => isDeepStrictEqual(m, { stamp: { secs: 0, nsecs: 0 }, id: nonce }),
      what: "GoalID with only its id: zero stamp, named as ROS 1 names it (a type only ROS 1 has)",
    },
    {
      name: "/interop_js/trajectory",
      type: "trajectory_msgs/msg/JointTrajectory",
      msg: { joint_names: [nonce], points: [{ positions: [0.5] }, {}] },
      pred: (m) =>
        m.joint_names?.[0] === nonce &&
        isDeepStrictEqual(m.header, { stamp: ZERO_TIME, frame_id: "" }) &&
        isDeepStrictEqual(m.points, [
          { positions: [0.5], velocities: [], accelerations: [], effort: [], time_from_start: ZERO_TIME },
          { positions: [], velocities: [], accelerations: [], effort: [], time_from_start: ZERO_TIME },
        ]),
      what: "JointTrajectory with partial points: every point complete",
    },
    {
      name: "/interop_js/camera_info",
      type: "sensor_msgs/msg/CameraInfo",
      msg: { width: 640, height: 480, header: { frame_id: nonce } },
      pred: (m) =>
        m.header?.frame_id === nonce &&
        m.k?.length === 9 && m.r?.length === 9 && m.p?.length === 12 &&
        [...m.k, ...m.r, ...m.p].every((x) => x === 0) &&
        isDeepStrictEqual(m.d, []) && m.roi?.do_rectify === false,
      what: "CameraInfo with size and frame: fixed arrays of zeros",
    },
  ];
  for (const c of cases) {
    for (const compression of ["none", "cbor"]) {
      const sub = new Topic({ ros, name: c.name, messageType: c.type, compression });
      const pub = new Topic({ ros, name: c.name, messageType: c.type });
      const pred = (m) => c.pred(plain(m));
      const got = await publishUntilReceived(pub, c.msg, sub, `${c.what} (${compression})`, pred);
      check(pred(got), `${c.what} (${compression}): got ${JSON.stringify(plain(got))}`);
    }
    ok(`${c.what}, on JSON and CBOR subscribers of ${c.name}`);
  }
}

// A provider's answer as roslib sends it: roslib 2 sends `values` only when the callback
// returns something truthy, and `result: false` without values otherwise, which
// rosbridge refuses (its caller then waits forever); through fleetlink the caller gets
// the values, or a failure at once.
async function checkProviderAnswers(ros) {
  for (const ret of [true, false, undefined]) {
    const name = `/interop_js/answers_${String(ret)}_${args.mode}`;
    const message = `answered by a callback returning ${String(ret)}`;
    const server = new Service({ ros, name, serviceType: "std_srvs/srv/Trigger" });
    server.advertise((request, response) => {
      response.success = true;
      response.message = message;
      return ret;
    });
    try {
      let got;
      let failure;
      for (let i = 0; i < PUBLISH_ATTEMPTS && got === undefined && failure === undefined; i++) {
        try {
          got = await call(ros, name, {}, "std_srvs/srv/Trigger");
        } catch (e) {
          if (String(e.message).includes("not advertised")) {
            await new Promise((r) => setTimeout(r, PUBLISH_INTERVAL_MS));
          } else if (e instanceof CheckFailed && /answered (result: false|without a response)/.test(String(e.message))) {
            failure = e.message;
          } else {
            throw e;
          }
        }
      }
      if (ret) {
        check(isDeepStrictEqual(got, { success: true, message }), `provider returning ${String(ret)}: the caller got ${JSON.stringify(got)}`);
        ok(`a provider whose callback returns ${String(ret)} answers its caller: ${JSON.stringify(got)}`);
      } else {
        check(failure !== undefined, `provider returning ${String(ret)}: the caller got ${JSON.stringify(got)}, want a failure`);
        ok(`a provider whose callback returns ${String(ret)} (roslib sends no values) fails its caller at once: ${failure}`);
      }
    } finally {
      server.unadvertise();
    }
  }
}

async function main() {
  const version = JSON.parse(readFileSync(new URL("./node_modules/roslib/package.json", import.meta.url))).version;
  console.log(`roslib ${version} (node ${process.version}) -> ${args.url} (${args.mode} mode)`);
  const ros = await connect(args.url);
  ok(`connected to ${args.url}`);
  await checkTopics(ros);
  await checkGetTime(ros);
  await checkGraph(ros);
  await checkScan(ros);
  await checkOdom(ros);
  await checkPoints(ros, "none");
  await checkPoints(ros, "cbor");
  await checkPoints(ros, "png");
  await checkOwnMessages(ros);
  await checkBurst(ros);
  await checkInvalidOp(ros);
  await checkPartialMessages(ros);
  await checkProviderAnswers(ros);
  if (args.mode === "hub") await checkPublishHub(ros);
  else await checkPublishLocal(ros);
}

let code = 0;
try {
  await main();
  console.log(`PASS roslib (${args.mode})`);
} catch (e) {
  console.error(`FAIL roslib (${args.mode}): ${e instanceof CheckFailed ? e.message : e?.stack ?? e}`);
  code = 1;
} finally {
  for (const c of clients) {
    try {
      c.close();
    } catch {}
  }
}
process.exit(code);
