#!/usr/bin/env node
// Services and actions through fleetlink, driven by roslib (roslibjs, npm) under Node.
// Same arguments as calls_check.py; the checks:
//   set_mode       the operator calls /<robot>/set_mode with Service.callService;
//                  /<robot>/get_status shows mode active
//   js_service     a Node client at the hub advertises /cloud/js_add_two_ints
//                  (Service.advertise); a second Node connection at the hub and a Node
//                  program on the robot's local listener call it
//   nav_action     Action.sendGoal to /<robot>/navigate_to_pose: feedback, then the result
//   js_action      a Node client advertises the action /cloud/js_fibonacci (Action.advertise,
//                  sendFeedback + setSucceeded); a second Node client's sendGoal gets the
//                  feedback and the result; a goal cancelled with cancelGoal reaches the
//                  server's cancel callback, which answers setCanceled; unadvertise
//                  removes it from /rosapi/action_servers
// roslib is loaded from tests/interop/rosbridge/node_modules (scripts/setup.d/20-node-packages.sh).
// Prints `ok <check>` or `FAIL <check>: why`; exits 1 if any failed. Every wait is bounded.

import { isDeepStrictEqual, parseArgs } from "node:util";
import { readFileSync } from "node:fs";

const TIMEOUT_MS = 10_000;
const LIST_WAIT_MS = 10_000;
const SPEED = 0.5; // m/s, the simulated robot's navigation speed (spec)
const NAV_TYPE = "fleetlink_sim/action/NavigateTo";
const ADD = "/cloud/js_add_two_ints";
const ADD_TYPE = "example_interfaces/srv/AddTwoInts";
const FIB = "/cloud/js_fibonacci";
const FIB_TYPE = "example_interfaces/action/Fibonacci";

const { values: args } = parseArgs({
  options: {
    "hub-url": { type: "string" },
    "local-url": { type: "string" },
    robot: { type: "string", default: "robot1" },
    // Accepted for the same command line as calls_check.py; the ACL and audit checks
    // run there.
    "viewer-url": { type: "string" },
    api: { type: "string" },
    "op-token": { type: "string" },
    "op-name": { type: "string" },
    "viewer-name": { type: "string" },
  },
});
if (!args["hub-url"] || !args["local-url"]) {
  console.error("usage: calls_check.mjs --hub-url ws://HUB/?token=T --local-url ws://HOST:PORT/ [--robot robot1] [...]");
  process.exit(2);
}
const robot = args.robot;

// roslib lives in the rosbridge suite's node_modules; import its ESM entry point by path.
const pkgDir = new URL("../rosbridge/node_modules/roslib/", import.meta.url);
let ROSLIB, version;
try {
  const pkg = JSON.parse(readFileSync(new URL("package.json", pkgDir)));
  version = pkg.version;
  ROSLIB = await import(new URL(pkg.exports?.["."]?.import ?? pkg.module, pkgDir).href);
} catch (e) {
  console.error(`FAIL: cannot load roslib from ${pkgDir.pathname} (run scripts/setup.d/20-node-packages.sh): ${e?.message ?? e}`);
  process.exit(1);
}
const { Ros, Service, Action } = ROSLIB;

class CheckFailed extends Error {}
function check(cond, what) {
  if (!cond) throw new CheckFailed(what);
}
function note(what) {
  console.log(`    ${what}`);
}
function short(v, n = 300) {
  const s = typeof v === "string" ? v : JSON.stringify(v);
  return s === undefined ? String(v) : s.length <= n ? s : `${s.slice(0, n)}...`;
}
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

/** Resolves with fn's result, or rejects naming `what` after `ms`. */
function within(ms, what, fn) {
  return new Promise((resolve, reject) => {
    const timer = setTimeout(() => reject(new CheckFailed(`${what}: nothing within ${ms} ms`)), ms);
    fn(
      (v) => {
        clearTimeout(timer);
        resolve(v);
      },
      (e) => {
        clearTimeout(timer);
        reject(e instanceof Error ? e : new CheckFailed(`${what}: ${short(e)}`));
      },
    );
  });
}

const clients = [];
async function connect(url, what) {
  const ros = new Ros({});
  clients.push(ros);
  await within(TIMEOUT_MS, `connect ${what}`, (resolve, reject) => {
    ros.on("connection", () => resolve());
    // Later errors (a frame roslib could not decode, ...) are printed: a check that then
    // times out says why.
    ros.on("error", (e) => {
      console.error(`    roslib error on ${what}: ${e?.message ?? e}`);
      reject(new CheckFailed(`connect ${what}: ${e?.message ?? e}`));
    });
    ros.connect(url).catch(reject);
  });
  return ros;
}

/** The values of a successful call; CheckFailed naming the failure text otherwise. */
function call(ros, name, request = {}, serviceType = "") {
  const svc = new Service({ ros, name, serviceType });
  return within(TIMEOUT_MS, `call ${name} ${short(request)}`, (resolve, reject) =>
    svc.callService(request, resolve, (e) => reject(new CheckFailed(`call ${name} ${short(request)}: result false: ${short(e)}`))),
  );
}

async function callUntilOk(ros, name, request, ms, what) {
  const deadline = Date.now() + ms;
  let last;
  while (Date.now() < deadline) {
    try {
      return await call(ros, name, request);
    } catch (e) {
      last = e.message;
    }
    await sleep(200);
  }
  throw new CheckFailed(`${what}: no successful call to ${name} within ${ms} ms; last: ${last}`);
}

function listing(ros, method, what) {
  return within(TIMEOUT_MS, what, (resolve, reject) =>
    ros[method](resolve, (e) => reject(new CheckFailed(`${what} failed: ${short(e)}`))),
  );
}

/** Polls ros.getServices()/getActionServers() until `name` is (or is no longer) listed. */
async function waitListed(ros, method, name, present = true) {
  const deadline = Date.now() + LIST_WAIT_MS;
  for (;;) {
    const names = await listing(ros, method, `ros.${method}()`);
    check(Array.isArray(names), `ros.${method}(): ${short(names)}, want a list`);
    if (names.includes(name) === present) return;
    if (Date.now() > deadline) {
      throw new CheckFailed(`${name} ${present ? "not listed" : "still listed"} by ros.${method}() after ${LIST_WAIT_MS} ms: ${short(names)}`);
    }
    await sleep(100);
  }
}

async function robotStatus(op) {
  const name = `/${robot}/get_status`;
  const v = await call(op, name, {}, "std_srvs/srv/Trigger");
  check(v?.success === true, `${name}: success is ${v?.success}: ${short(v)}`);
  let st;
  try {
    st = JSON.parse(v.message);
  } catch (e) {
    throw new CheckFailed(`${name}: message is not JSON text (${e.message}): ${short(v)}`);
  }
  for (const k of ["mode", "x", "y"]) check(st && k in st, `${name}: status lacks '${k}': ${short(st)}`);
  check(Number.isFinite(st.x) && Number.isFinite(st.y), `${name}: x/y not numbers: ${short(st)}`);
  return st;
}

function towardsOrigin(x, y, dist) {
  const d = Math.hypot(x, y);
  const [ux, uy] = d > 1.5 ? [-x / d, -y / d] : [1, 0];
  const r = (v) => Math.round(v * 1000) / 1000;
  return [r(x + dist * ux), r(y + dist * uy)];
}

async function checkSetMode(op) {
  const name = `/${robot}/set_mode`;
  const v = await call(op, name, { data: true }, "std_srvs/srv/SetBool");
  check(v?.success === true, `${name} {data: true}: success is ${v?.success}: ${short(v)}`);
  check(typeof v.message === "string" && v.message.trim() !== "", `${name} {data: true}: empty or missing message: ${short(v)}`);
  const st = await robotStatus(op);
  check(st.mode === "active", `after ${name} {data: true} (answered ${short(v.message)}), get_status mode is ${short(st.mode)}, want 'active'`);
  return `${name} {data: true} -> ${short(v.message)}; get_status mode ${st.mode} at (${st.x.toFixed(2)}, ${st.y.toFixed(2)})`;
}

async function checkJsService() {
  const provider = await connect(args["hub-url"], "Node provider (hub)");
  const svc = new Service({ ros: provider, name: ADD, serviceType: ADD_TYPE });
  let answered = 0;
  await svc.advertise((req, resp) => {
    resp.sum = req.a + req.b;
    answered += 1;
    return true;
  });
  const caller = await connect(args["hub-url"], "Node caller (hub)");
  await waitListed(caller, "getServices", ADD);
  const v = await call(caller, ADD, { a: 20, b: 22 }, ADD_TYPE);
  check(isDeepStrictEqual(v, { sum: 42 }), `hub caller: ${ADD} {a: 20, b: 22} answered ${short(v)}, want {sum: 42}`);
  const local = await connect(args["local-url"], "Node program on the robot (local listener)");
  const w = await callUntilOk(local, ADD, { a: -5, b: 3000 }, LIST_WAIT_MS, `local program calling ${ADD} through the agent`);
  check(isDeepStrictEqual(w, { sum: 2995 }), `local program: ${ADD} {a: -5, b: 3000} answered ${short(w)}, want {sum: 2995}`);
  check(answered >= 2, `the provider's callback ran ${answered} times for 2 successful calls`);
  await svc.unadvertise();
  await waitListed(caller, "getServices", ADD, false);
  provider.close();
  caller.close();
  local.close();
  return `${ADD} advertised by a Node client answered a Node hub client (42) and a local Node program (2995); gone after unadvertise`;
}

async function checkNavAction(op) {
  const name = `/${robot}/navigate_to_pose`;
  const st = await robotStatus(op);
  const dist = 1.0;
  const [gx, gy] = towardsOrigin(st.x, st.y, dist);
  const nav = new Action({ ros: op, name, actionType: NAV_TYPE });
  const feedback = [];
  const t0 = Date.now();
  const result = await within(Math.round((dist / SPEED) * 3000 + 8000), `result of ${name} to (${gx}, ${gy})`, (resolve, reject) => {
    nav.sendGoal(
      { x: gx, y: gy },
      resolve,
      (f) => feedback.push(f),
      (e) => reject(new CheckFailed(`${name} to (${gx}, ${gy}) failed (roslib: result false or status not SUCCEEDED): ${short(e)}`)),
    );
  });
  const secs = (Date.now() - t0) / 1000;
  check(result?.reached === true, `${name}: result ${short(result)}, want reached: true`);
  check(
    Number.isFinite(result.x) && Number.isFinite(result.y) && Math.hypot(result.x - gx, result.y - gy) < 0.5,
    `${name}: result at (${result.x}, ${result.y}), want within 0.5 m of (${gx}, ${gy})`,
  );
  check(feedback.length >= 2, `${name}: ${feedback.length} feedback message(s) before the result, want >= 2: ${short(feedback)}`);
  const dr = feedback.map((f) => f?.distance_remaining);
  check(dr.every((d) => Number.isFinite(d) && d >= 0 && d <= dist + 1), `${name}: feedback distance_remaining ${short(dr)}, want numbers in [0, ${dist + 1}]`);
  check(dr[dr.length - 1] < dr[0], `${name}: distance_remaining did not decrease: ${short(dr)}`);
  return `${name} to (${gx}, ${gy}): ${feedback.length} feedbacks (${dr[0].toFixed(2)} -> ${dr[dr.length - 1].toFixed(2)} m), SUCCEEDED in ${secs.toFixed(1)} s at (${result.x.toFixed(2)}, ${result.y.toFixed(2)})`;
}

async function checkJsAction(op) {
  const serverRos = await connect(args["hub-url"], "Node action server (hub)");
  const server = new Action({ ros: serverRos, name: FIB, actionType: FIB_TYPE });
  const goals = []; // {goal, id} as the server saw them
  const cancels = []; // ids given to the cancel callback
  const running = new Map(); // id -> {timer, seq}
  server.advertise(
    (goal, id) => {
      goals.push({ goal, id });
      const order = Number(goal?.order);
      const job = { seq: [0, 1], timer: null };
      running.set(id, job);
      job.timer = setInterval(() => {
        if (!(order >= 1) || job.seq.length > order) {
          clearInterval(job.timer);
          running.delete(id);
          server.setSucceeded(id, { sequence: job.seq.slice(0, Math.max(order, 0) + 1) });
          return;
        }
        job.seq.push(job.seq[job.seq.length - 1] + job.seq[job.seq.length - 2]);
        server.sendFeedback(id, { sequence: [...job.seq] });
      }, 100);
    },
    (id) => {
      cancels.push(id);
      const job = running.get(id);
      if (job) {
        clearInterval(job.timer);
        running.delete(id);
        server.setCanceled(id, { sequence: job.seq });
      }
    },
  );
  try {
    const clientRos = await connect(args["hub-url"], "Node action client (hub)");
    await waitListed(clientRos, "getActionServers", FIB);
    const client = new Action({ ros: clientRos, name: FIB, actionType: FIB_TYPE });
    // 1. To success, with feedback.
    const feedback = [];
    const result = await within(TIMEOUT_MS, `result of ${FIB} {order: 5}`, (resolve, reject) => {
      client.sendGoal({ order: 5 }, resolve, (f) => feedback.push(f), (e) => reject(new CheckFailed(`${FIB} {order: 5} failed: ${short(e)}`)));
    });
    check(goals.length === 1 && isDeepStrictEqual(goals[0].goal, { order: 5 }), `the action server got goals ${short(goals)}, want one {order: 5}`);
    check(isDeepStrictEqual(result, { sequence: [0, 1, 1, 2, 3, 5] }), `${FIB} {order: 5}: result ${short(result)}, want {sequence: [0,1,1,2,3,5]}`);
    // The server sent 4 feedbacks ([0,1,1] ... [0,1,1,2,3,5]); each must arrive intact
    // and before the result.
    const want = [0, 1, 1, 2, 3, 5];
    check(
      feedback.length >= 2 &&
        feedback.every((f, i) => Array.isArray(f?.sequence) && isDeepStrictEqual(f.sequence, want.slice(0, f.sequence.length)) && (i === 0 || f.sequence.length > feedback[i - 1].sequence.length)),
      `${FIB} {order: 5}: feedback ${short(feedback)}, want >= 2 of the 4 sent, in order ([0,1,1] ... [0,1,1,2,3,5])`,
    );
    // 2. Cancelled after the first feedback: the server's cancel callback answers setCanceled.
    let goalId;
    let cancelled = false;
    const t0 = Date.now();
    const outcome = await within(TIMEOUT_MS, `end of the cancelled ${FIB} {order: 60} goal`, (resolve) => {
      goalId = client.sendGoal(
        { order: 60 },
        (v) => resolve({ kind: "result", v }),
        () => {
          if (!cancelled) {
            cancelled = true;
            client.cancelGoal(goalId);
          }
        },
        (e) => resolve({ kind: "failed", e }),
      );
    });
    const secs = (Date.now() - t0) / 1000;
    check(cancelled, `${FIB} {order: 60}: ended without any feedback: ${short(outcome)}`);
    check(goals.length === 2, `the action server got ${goals.length} goals, want 2: ${short(goals)}`);
    check(
      cancels.length === 1 && cancels[0] === goals[1].id,
      `the server's cancel callback got ids ${short(cancels)}, want exactly the second goal's id ${short(goals[1].id)}`,
    );
    // roslib: an action_result with result true and status CANCELED goes to the failed
    // callback as the string "GoalError: Action was canceled: <values as JSON>".
    check(
      outcome.kind === "failed" && String(outcome.e).includes("Action was canceled"),
      `${FIB} cancelled: roslib reported ${short(outcome)}, want the failed callback with "Action was canceled..." (status 5)`,
    );
    server.unadvertise();
    await waitListed(clientRos, "getActionServers", FIB, false);
    clientRos.close();
    note(`result ${short(result)} after ${feedback.length} feedbacks; cancel -> ${short(String(outcome.e), 120)} in ${secs.toFixed(2)} s`);
    return `${FIB} served by a Node Action: feedback + setSucceeded reached the Node client; cancelGoal -> cancel callback -> setCanceled`;
  } finally {
    for (const job of running.values()) clearInterval(job.timer);
    serverRos.close();
  }
}

async function main() {
  console.log(`roslib ${version} (node ${process.version}) -> hub ${new URL(args["hub-url"]).host}, local ${args["local-url"]}, robot ${robot}`);
  const failed = [];
  let op;
  try {
    op = await connect(args["hub-url"], "admin operator (hub)");
  } catch (e) {
    console.log(`FAIL connect: ${e.message}`);
    return 1;
  }
  const checks = [
    ["set_mode", () => checkSetMode(op)],
    ["js_service", () => checkJsService()],
    ["nav_action", () => checkNavAction(op)],
    ["js_action", () => checkJsAction(op)],
  ];
  for (const [name, fn] of checks) {
    console.log(`-- ${name}`);
    const t0 = Date.now();
    try {
      const detail = await fn();
      console.log(`ok ${name} (${((Date.now() - t0) / 1000).toFixed(1)} s): ${detail}`);
    } catch (e) {
      failed.push(name);
      console.log(`FAIL ${name}: ${e instanceof CheckFailed ? e.message : e?.stack ?? e}`);
    }
  }
  if (failed.length) {
    console.log(`FAIL calls (roslib): ${failed.length} check(s) failed: ${failed.join(", ")}`);
    return 1;
  }
  console.log("PASS calls (roslib)");
  return 0;
}

let code = 1;
try {
  code = await main();
} catch (e) {
  console.log(`FAIL calls (roslib): ${e?.stack ?? e}`);
} finally {
  for (const c of clients) {
    try {
      c.close();
    } catch {}
  }
}
process.exit(code);
