// The dashboard in real headless Chromium (Debian's package, driven by puppeteer-core)
// against `fleetlink demo`: fleet view, robot panels (the camera's H.264 video decoded with
// WebCodecs; its JPEG for a viewer without), the marker layer (the simulator's pillars,
// walls and goal as visualization_msgs markers), navigation goal + cancel, a service form
// call, the recordings page's black-box form, and a viewer without publish rights.
// Screenshots of each view go to --shots. Exits non-zero when any check failed.
//
//   node dashboard_check.mjs --url http://127.0.0.1:PORT/ --user U --password P --viewer-token V --shots DIR
import { mkdirSync } from "node:fs";
import { createRequire } from "node:module";
import { dirname, join } from "node:path";
import { fileURLToPath, pathToFileURL } from "node:url";
import { parseArgs } from "node:util";

// puppeteer-core is one of the dashboard's dev packages (web/node_modules).
const web = join(dirname(fileURLToPath(import.meta.url)), "..", "..", "..", "web");
const puppeteer = (await import(pathToFileURL(createRequire(join(web, "package.json")).resolve("puppeteer-core")).href)).default;

const { values: o } = parseArgs({
  options: {
    url: { type: "string" }, user: { type: "string" }, password: { type: "string" }, "viewer-token": { type: "string" },
    shots: { type: "string" }, robot: { type: "string", default: "robot1" },
    browser: { type: "string", default: "/usr/bin/chromium" },
    "offline-robot": { type: "string" }, "offline-pid": { type: "string" },
    "pull-robot": { type: "string" },
  },
});
mkdirSync(o.shots, { recursive: true });
const robot = o.robot;
const failures = [];
let step = "start";
const ok = (what) => console.log(`ok   ${what}`);
const fail = (what) => { console.log(`FAIL ${what}`); failures.push(what); };
const check = (cond, what) => (cond ? ok(what) : fail(what));
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

/** Polls `fn` in the page until it returns truthy (bounded); returns the value or null. */
async function until(page, fn, arg, ms, what) {
  try {
    const h = await page.waitForFunction(fn, { timeout: ms, polling: 100 }, arg);
    return await h.jsonValue();
  } catch {
    fail(`${what} (not within ${ms} ms)`);
    return null;
  }
}

const browser = await puppeteer.launch({
  executablePath: o.browser,
  headless: true,
  args: ["--no-sandbox", "--enable-unsafe-swiftshader", "--use-angle=swiftshader", "--ignore-gpu-blocklist", "--window-size=1500,1000"],
  defaultViewport: { width: 1500, height: 1000 },
});
const shot = async (page, name, fullPage = false) => {
  const f = join(o.shots, `${name}.png`);
  await page.screenshot({ path: f, fullPage });
  console.log(`     screenshot ${f}`);
};

async function signIn(page, token, user, password) {
  await page.click("#signin");
  if (token) await page.type("#login-form input[name=token]", token);
  else {
    await page.type("#login-form input[name=user]", user);
    await page.type("#login-form input[name=password]", password);
  }
  await page.click("#login-form button[type=submit]");
  await page.waitForFunction(() => document.querySelector("#who")?.textContent?.includes("signed in"), { timeout: 5000 });
}

try {
  const page = await browser.newPage();
  const errors = [];
  page.on("pageerror", (e) => errors.push(String(e)));
  page.on("console", (m) => { if (m.type() === "error") errors.push(m.text()); });

  // --- served by the hub: the page and its assets, nothing from elsewhere
  step = "load";
  const external = [];
  page.on("request", (r) => { if (!r.url().startsWith(o.url) && !r.url().startsWith("ws://") && !r.url().startsWith("blob:") && !r.url().startsWith("data:")) external.push(r.url()); });
  const resp = await page.goto(o.url, { waitUntil: "load" });
  check(resp.status() === 200 && resp.headers()["content-type"]?.startsWith("text/html"), "GET / serves the dashboard (text/html)");

  // --- fleet view: three robots, all moving, within 5 s
  step = "fleet";
  const t0 = Date.now();
  const first = await until(page, () => { const p = window.fleetlink?.poses ?? {}; return ["robot1", "robot2", "robot3"].every((r) => p[r]) && JSON.parse(JSON.stringify(p)); }, null, 5000, "fleet view: poses of robot1..3");
  if (first) {
    const moved = await until(page, (f) => {
      const p = window.fleetlink.poses;
      return Object.keys(f).every((r) => Math.hypot(p[r].x - f[r].x, p[r].y - f[r].y) > 0.1) && true;
    }, first, Math.max(500, 5000 - (Date.now() - t0)), "fleet view: all three robots move");
    if (moved) ok(`fleet view: 3 robots on the map and moving after ${Date.now() - t0} ms`);
  }
  const cards = await page.$$eval(".robot.online", (e) => e.map((x) => x.dataset.robot));
  check(["robot1", "robot2", "robot3"].every((r) => cards.includes(r)), `fleet list shows the demo's robots online (${cards.join(", ")})`);
  const rtt = await page.$eval(".robot.online dl", (e) => e.textContent);
  check(/RTT/.test(rtt) && /msg\/s/.test(rtt), "fleet list shows RTT and msg/s");
  // A robot whose agent stops: greyed in the list and on the map, with when it went.
  if (o["offline-robot"]) {
    const gone = o["offline-robot"];
    await until(page, (r) => window.fleetlink.poses[r], gone, 5000, `${gone} on the map`);
    process.kill(Number(o["offline-pid"]), "SIGTERM");
    const text = await until(page, (r) => { const c = document.querySelector(`.robot.offline[data-robot=${r}]`); return c && c.textContent; }, gone, 8000, `${gone} shown offline`);
    if (text) check(/gone/.test(text), `${gone} greyed as offline: "${text.slice(0, 60)}"`);
  }
  await sleep(800); // trails of a few seconds in the picture
  await shot(page, "1-fleet");

  // --- sign in with user + password: a session token, kept in sessionStorage only
  step = "signin";
  await signIn(page, null, o.user, o.password);
  const who = await page.$eval("#who", (e) => e.textContent);
  check(who.includes(`user:${o.user}`), `signed in with a password: "${who}"`);
  const stored = await page.evaluate(() => ({ s: sessionStorage.getItem("fleetlink.token"), l: Object.keys(localStorage).filter((k) => /token/.test(k)), c: document.cookie }));
  check(stored.s && stored.l.length === 0 && !stored.c, "session token kept in sessionStorage, not localStorage or a cookie");
  const session = stored.s;

  // --- robot view: panels update
  step = "robot";
  await page.waitForSelector(`.robot[data-robot=${robot}]`, { timeout: 5000 });
  await page.click(`.robot[data-robot=${robot}]`);
  await until(page, () => ["scan", "cloud", "camera", "odom", "inspector"].every((k) => window.fleetlink.frames[k] > 0), null, 8000, "robot view: every panel got a frame");
  const f1 = await page.evaluate(() => ({ ...window.fleetlink.frames }));
  await sleep(2000);
  const f2 = await page.evaluate(() => ({ ...window.fleetlink.frames }));
  for (const k of ["scan", "cloud", "cloud-rendered", "camera", "odom", "pose", "inspector"]) {
    const d = (f2[k] ?? 0) - (f1[k] ?? 0);
    check(d > 0, `robot view: ${k} panel updating (${d} frames in 2 s)`);
  }
  const inspected = await page.$eval(".inspector select", (e) => e.value);
  console.log(`     the inspector shows ${inspected}`);
  // Chromium offers permessage-deflate: the hub negotiated it with the page's rosbridge
  // connection (issue 56), so the panels above were fed compressed messages.
  const deflated = await page.evaluate(async (t) => {
    const r = await fetch("/api/v1/clients", { headers: { Authorization: `Bearer ${t}` } });
    return (await r.json()).clients.filter((c) => c.kind === "rosbridge").map((c) => c.deflate);
  }, session);
  check(deflated.includes(true), `robot view: the page's rosbridge connection negotiated permessage-deflate (${JSON.stringify(deflated)})`);
  const insp = await page.$eval(".inspector .tree", (e) => e.textContent);
  check(insp.length > 20 && !/waiting/.test(insp), "inspector shows a message tree");
  // robot1's mirror in the link panel, with the offload rule it applies.
  if (robot === "robot1") {
    const mirror = await until(page, () => {
      const h = [...document.querySelectorAll(".robot-grid section h2")].find((e) => e.textContent.startsWith("Link quality"));
      const info = h?.querySelector(".info");
      return info && /mirror robot1_mirror/.test(info.textContent) ? { text: info.textContent, rule: info.title } : null;
    }, null, 5000, "robot view: the link panel shows robot1's mirror");
    if (mirror) check(/mirror robot1_mirror reads \d+ topics?, /.test(mirror.text) && /capacity_bps/.test(mirror.rule), `robot view: the mirror and its offload signal: "${mirror.text.trim()}" (${mirror.rule})`);
  }
  // The configuration panel: what the robot runs with, and a change applied at once or
  // refused with the YAML's error text (docs/runtime-config.md).
  step = "config";
  const cfg = await until(page, () => window.fleetlink.config.loaded && window.fleetlink.config.mayChange && document.querySelector(".config .config-effective")?.textContent, null, 8000, "robot view: the configuration panel loaded");
  if (cfg) check(cfg.includes(`name: ${robot}`), `configuration panel: the robot's effective configuration (${cfg.length} characters)`);
  const applyChange = async (text) => {
    await page.evaluate((t) => { const e = document.querySelector(".config .config-editor"); e.value = t; window.fleetlink.config.result = ""; }, text);
    await page.evaluate(() => [...document.querySelectorAll(".config button")].find((b) => b.textContent === "apply change").click());
    return until(page, () => window.fleetlink.config.result, null, 10000, "the change's outcome");
  };
  const applied = await applyChange("topics:\n  /odom: { rate_limit_hz: 2 }\n");
  check(applied === "applied: topics", `configuration panel: a change applied (${applied})`);
  const inForce = await page.evaluate(() => JSON.stringify(window.fleetlink.config.overlay));
  check(/"rate_limit_hz":2/.test(inForce), `configuration panel: the change in force ${inForce}`);
  const seen = errors.length;
  const refused = await applyChange("topics:\n  /odom: { rate_limit_hz: 0 }\n");
  // The browser logs the refusal's 400 answer as a failed resource: expected here.
  errors.splice(seen, errors.length - seen, ...errors.slice(seen).filter((e) => !/status of 400/.test(e)));
  check(/^refused: change:2:\d+: topics\["\/odom"\]\.rate_limit_hz: /.test(refused ?? ""), `configuration panel: an invalid change refused with the YAML's text (${refused})`);
  await shot(page, "6-config", true);
  // Undone by removing what the change set (a change merges per entry: `topics: {}` changes nothing).
  const undone = await applyChange("remove:\n  topics: [/odom]\n");
  check(undone === "applied: topics", `configuration panel: the change undone (${undone})`);
  const cloudInfo = await page.$eval(".robot-grid section:nth-child(4) .info", (e) => e.textContent);
  check(/points/.test(cloudInfo), `point cloud panel: ${cloudInfo}`);
  // The camera panel plays the robot's H.264 video with WebCodecs: Chromium decoded it at
  // the demo's size, and the canvas shows the simulator's room (light walls and floor,
  // dark pillars), not a black or flat picture.
  const vid = await until(page, () => {
    const v = window.fleetlink.video, cv = document.querySelector("canvas.camera.video");
    if (!cv || v.decoded < 10) return null;
    const d = cv.getContext("2d").getImageData(0, 0, cv.width, cv.height).data;
    let s = 0, s2 = 0, n = 0;
    for (let i = 0; i < d.length; i += 16) { const y = (d[i] + d[i + 1] + d[i + 2]) / 3; s += y; s2 += y * y; n++; }
    const info = cv.closest("section").querySelector("h2 .info").textContent;
    return { ...v, canvas: `${cv.width}x${cv.height}`, mean: s / n, sd: Math.sqrt(Math.max(0, s2 / n - (s / n) ** 2)), info };
  }, null, 8000, "camera panel: ten video frames decoded");
  if (vid) {
    check(vid.topic === `/${robot}/camera/video` && /^avc1\.42/.test(vid.codec) && !vid.fallback && vid.errors === 0,
      `camera panel: ${vid.topic} played with WebCodecs as ${vid.codec} (${vid.decoded} frames, ${vid.errors} errors${vid.fallback ? `, fell back: ${vid.fallback}` : ""})`);
    check(vid.width === 640 && vid.height === 480 && vid.canvas === "640x480", `camera panel: video frames of ${vid.width}x${vid.height} on a ${vid.canvas} canvas`);
    check(vid.mean > 30 && vid.sd > 10, `camera panel: the canvas shows a picture (mean level ${vid.mean.toFixed(0)}, spread ${vid.sd.toFixed(0)})`);
    check(/fps/.test(vid.info) && /B\/s/.test(vid.info), `camera panel: frame rate and bytes per second shown ("${vid.info}")`);
  }
  // Signing in replaced the connection: the status shows the new one, not the old one's close.
  const connText = await until(page, () => document.querySelector("#conn")?.textContent === "connected" && "connected", null, 3000, "status bar: connected after sign-in");
  if (connText) ok("status bar: connected after sign-in");
  await shot(page, "2-robot", true);

  // --- markers: the simulator's MarkerArray drawn on the map (five pillars, the walls)
  step = "markers";
  const mk = await until(page, () => { const m = window.fleetlink.markers; return m.byNs.pillars === 5 && m.byNs.walls === 1 && JSON.parse(JSON.stringify(m)); }, null, 5000, "markers: pillars and walls on the map");
  if (mk) {
    check(mk.byType.CYLINDER === 5 && mk.byType.LINE_STRIP === 1 && !mk.byNs.goal, `markers: ${JSON.stringify(mk.byType)} drawn, ${mk.shapes} shapes, no goal yet`);
    check((await page.evaluate(() => window.fleetlink.frames.markers)) > 0, "markers: MarkerArray frames received");
  }
  // The map's pixels where a pillar is: the pillar's colour, not the floor's.
  const px = await page.evaluate(() => {
    const cv = document.querySelector("#robot-map");
    const [x, y] = window.fleetlink.mapToScreen(0, 7); // the 0.8 m pillar
    const d = devicePixelRatio || 1;
    const p = cv.getContext("2d").getImageData(Math.round(x * d), Math.round(y * d), 1, 1).data;
    return [p[0], p[1], p[2]];
  });
  check(px[2] > 120 && px[0] > 100, `markers: a pillar is painted at (0, 7) on the map (rgb ${px.join(",")})`);
  await (await page.$("#robot-map")).screenshot({ path: join(o.shots, "2b-markers.png") });
  console.log(`     screenshot ${join(o.shots, "2b-markers.png")}`);

  // --- navigation goal clicked on the map: the robot drives there, feedback shown
  step = "navigate";
  await until(page, () => /Click on the map/.test(document.querySelector(".task.nav")?.textContent ?? ""), null, 5000, "navigation action found");
  const clickAt = async (x, y) => {
    const [px, py] = await page.evaluate((x, y) => window.fleetlink.mapToScreen(x, y), x, y);
    const box = await (await page.$("#robot-map")).boundingBox();
    await page.mouse.click(box.x + px, box.y + py);
  };
  const p0 = await page.evaluate((r) => window.fleetlink.poses[r], robot);
  // 1.5 m towards the room's centre: a short, clear drive.
  const toC = Math.hypot(p0.x, p0.y) || 1;
  const goal = { x: p0.x - (1.5 * p0.x) / toC, y: p0.y - (1.5 * p0.y) / toC };
  await clickAt(goal.x, goal.y);
  await until(page, () => window.fleetlink.feedback.length > 0 && /m to go/.test(document.querySelector(".navstate").textContent), null, 4000, "navigation feedback shown");
  if (await until(page, () => window.fleetlink.markers.byNs.goal === 1 && window.fleetlink.markers.byType.SPHERE === 1, null, 3000, "markers: the goal sphere while navigating")) ok("markers: goal sphere drawn while navigating");
  await shot(page, "3-navigating");
  const reached = await until(page, (a) => { const r = window.fleetlink.lastResult; const p = window.fleetlink.poses[a.robot]; return r && r.status === 4 && Math.hypot(p.x - a.goal.x, p.y - a.goal.y) < 0.25 && { r, p }; }, { robot, goal }, 12000, "navigation goal reached");
  if (reached) ok(`goal (${goal.x.toFixed(2)}, ${goal.y.toFixed(2)}) reached: pose (${reached.p.x.toFixed(2)}, ${reached.p.y.toFixed(2)}), result ${JSON.stringify(reached.r.values)}`);
  const navText = await page.$eval(".navstate", (e) => e.textContent);
  check(/reached/.test(navText), `navigation state says: ${navText}`);
  const gone = await until(page, () => !window.fleetlink.markers.byNs.goal && window.fleetlink.markers.byNs.pillars === 5, null, 3000, "markers: the goal sphere deleted once reached");
  if (gone) ok("markers: goal sphere removed by the simulator's DELETE");

  // Cancel: a far goal, then Cancel mid-way; the robot stops.
  step = "cancel";
  await page.evaluate(() => { window.fleetlink.lastResult = null; window.fleetlink.feedback.length = 0; });
  const far = { x: goal.x > 0 ? goal.x - 4 : goal.x + 4, y: goal.y };
  await clickAt(far.x, far.y);
  await until(page, () => window.fleetlink.feedback.length > 2, null, 4000, "feedback for the far goal");
  await page.click(".task.nav button.danger");
  const canceled = await until(page, () => window.fleetlink.lastResult?.status === 5 && window.fleetlink.lastResult, null, 6000, "Cancel ends the goal (status 5)");
  if (canceled) ok("Cancel: goal ended canceled");
  const c1 = await page.evaluate((r) => window.fleetlink.poses[r], robot);
  await sleep(1500);
  const c2 = await page.evaluate((r) => window.fleetlink.poses[r], robot);
  const drift = Math.hypot(c2.x - c1.x, c2.y - c1.y);
  check(drift < 0.05 && Math.hypot(c2.x - far.x, c2.y - far.y) > 0.5, `after Cancel the robot stands still (moved ${drift.toFixed(3)} m in 1.5 s, short of the goal)`);
  await shot(page, "4-canceled");

  // --- a service form call returns a result
  step = "service";
  await until(page, () => document.querySelectorAll(".task.svc select option").length > 0, null, 5000, "services listed");
  await page.select(".task.svc select", `/${robot}/get_status`);
  await until(page, () => document.querySelector(".svcform button[type=submit]"), null, 5000, "service form generated");
  await page.click(".svcform button[type=submit]");
  const sr = await until(page, () => window.fleetlink.lastServiceResponse, null, 5000, "service response");
  let status = null;
  try { status = JSON.parse(sr?.values?.message); } catch { /* checked below */ }
  check(sr?.ok && sr.values.success === true && status && "mode" in status && "x" in status, `get_status via the form: ${sr?.values?.message}`);
  // SetBool form (a bool checkbox): patrol again, true.
  await page.select(".task.svc select", `/${robot}/set_mode`);
  await until(page, () => document.querySelector(".svcform input[name=data]"), null, 5000, "SetBool form generated");
  await page.click(".svcform input[name=data]");
  await page.evaluate(() => (window.fleetlink.lastServiceResponse = null));
  await page.click(".svcform button[type=submit]");
  const sm = await until(page, () => window.fleetlink.lastServiceResponse, null, 5000, "set_mode response");
  check(sm?.ok && sm.values.success === true, `set_mode(true) via the form: ${JSON.stringify(sm?.values)}`);
  await shot(page, "5-service", true);

  // --- admin: audit log and rules
  step = "admin";
  await page.goto(`${o.url}#/admin`);
  await until(page, () => document.querySelectorAll("table.audit tbody tr").length > 0, null, 5000, "audit log rows");
  await until(page, () => /user:viewer/.test(document.querySelector("table.rules")?.textContent ?? ""), null, 5000, "rules listed");
  await shot(page, "6-admin", true);
  // Paging with the hub's cursor, and a filter.
  const firstRow = await page.$eval("table.audit tbody tr", (e) => e.textContent);
  await page.click(".pager button:nth-child(2)");
  const paged = await until(page, (f) => /page 2/.test(document.querySelector(".pager").textContent) && document.querySelector("table.audit tbody tr")?.textContent !== f, firstRow, 5000, "audit log page 2");
  if (paged) ok("audit log: next page shows older records");
  await page.type(".filters input[name=action]", "login");
  await page.click(".filters button[type=submit]");
  const logins = await until(page, () => { const rows = [...document.querySelectorAll("table.audit tbody tr")]; return /page 1/.test(document.querySelector(".pager").textContent) && rows.length > 0 && rows.every((r) => r.children[3].textContent === "login") && rows.map((r) => r.children[1].textContent); }, null, 5000, "audit log filtered by action");
  if (logins) check(logins.includes(`user:${o.user}`), `audit filter action=login: ${logins.join(", ")}`);
  // --- recordings: the black-box form is there, its robot select filled from the hub's
  // robots (the form only: the demo's robots keep no black box to fetch from).
  step = "recordings";
  await page.goto(`${o.url}#/recordings`);
  const bbRobots = await until(page, () => {
    const f = document.querySelector("#blackbox-form");
    const names = [...(f?.querySelectorAll("select[name=robot] option") ?? [])].map((x) => x.value);
    return ["robot1", "robot2", "robot3"].every((r) => names.includes(r)) && names;
  }, null, 5000, "recordings: black-box form with the robots in its select");
  if (bbRobots) {
    const form = await page.$eval("#blackbox-form", (f) => ({
      last: f.querySelector("input[name=last_s]")?.value,
      topics: !!f.querySelector("input[name=topics]"),
      name: !!f.querySelector("input[name=name]"),
      button: f.querySelector("button[type=submit]")?.textContent,
    }));
    check(form.last === "60" && form.topics && form.name && form.button === "Fetch black box",
      `recordings: black-box form (robots ${bbRobots.join(", ")}; ${JSON.stringify(form)})`);
  }
  await shot(page, "6b-recordings");
  // --- a pull topic (the robot sends /markers only when asked): its button in the topic
  // table asks the hub (POST …/topics/markers/pull), which asks the robot for one message
  // and shows it.
  if (o["pull-robot"]) {
    step = "pull";
    const pr = o["pull-robot"];
    await page.goto(`${o.url}#/robot/${pr}`);
    const ready = await until(page, () => !!([...document.querySelectorAll("table.topics tbody tr")].find((tr) => /\/markers \(pull\)/.test(tr.children[0].textContent)))?.querySelector("button"), null, 10000, `${pr}: /markers listed as a pull topic with its button`);
    if (ready) {
      ok(`${pr}: /markers listed "(pull)" with a pull button`);
      await page.evaluate(() => ([...document.querySelectorAll("table.topics tbody tr")].find((tr) => /\/markers \(pull\)/.test(tr.children[0].textContent))).querySelector("button").click());
      const shown = await until(page, () => { const t = ([...document.querySelectorAll("table.topics tbody tr")].find((tr) => /\/markers \(pull\)/.test(tr.children[0].textContent)))?.querySelector(".pulled")?.textContent ?? ""; return t.length > 20 && t; }, null, 10000, `${pr}: the pulled message shown`);
      if (shown) check(/markers/.test(shown) && !/pull failed/.test(shown), `pull button: one MarkerArray pulled from ${pr} and shown (${shown.slice(0, 60)}…)`);
      await shot(page, "7-pull", true);
    }
  }
  check(errors.length === 0, `no page errors (${errors.slice(0, 3).join(" | ")})`);
  // Sign out ends the session at the hub: the token no longer opens the API.
  step = "signout";
  await page.click("#signout");
  await page.waitForFunction(() => /anonymous/.test(document.querySelector("#who").textContent), { timeout: 5000 });
  const after = await page.evaluate(async (t) => ({ kept: sessionStorage.getItem("fleetlink.token"), status: (await fetch("/api/v1/robots", { headers: { Authorization: `Bearer ${t}` } })).status }), session);
  check(after.kept === null && after.status === 401, `sign out: token forgotten and refused by the hub afterwards (HTTP ${after.status})`);
  check(external.length === 0, `no request outside the hub (${external.slice(0, 3).join(", ")})`);
  await page.close();

  // --- a viewer without publish rights: tasking disabled with the hub's reason, and a
  // forged publish (straight on the page's rosbridge connection) refused by the hub.
  step = "viewer";
  const ctx = await browser.createBrowserContext();
  const v = await ctx.newPage();
  // This viewer's browser has no WebCodecs: its camera panel falls back to the JPEG topic.
  await v.evaluateOnNewDocument(() => { delete window.VideoDecoder; });
  await v.goto(o.url);
  await signIn(v, o["viewer-token"]);
  await v.goto(`${o.url}#/robot/${robot}`);
  const dis = await until(v, () => { const d = window.fleetlink.disabled; return d.estop && d.initialpose && d.services && d.navigate && { ...d }; }, null, 10000, "viewer: tasking disabled");
  if (dis) ok(`viewer sees tasking disabled: ${JSON.stringify(dis).slice(0, 300)}`);
  const btns = await v.evaluate(() => ({ estop: document.querySelector("#estop").disabled, init: [...document.querySelectorAll(".task.init button")].every((b) => b.disabled), svc: document.querySelector(".task.svc select").disabled }));
  check(btns.estop && btns.init && btns.svc, `viewer: e-stop, initial pose and service controls disabled ${JSON.stringify(btns)}`);
  check(/not allowed/.test(dis?.estop ?? ""), "viewer: the reason is the hub's refusal text");
  await until(v, () => window.fleetlink.frames.scan > 0, null, 5000, "viewer still sees the robot's data");
  // The camera panel shows the simulator's picture of its room: a JPEG the browser
  // decoded, at the demo's size, not the grey-level view of undecodable bytes.
  const cam = await until(v, () => {
    const img = document.querySelector("img.camera");
    const note = img?.parentElement?.parentElement?.querySelector("p.muted")?.textContent ?? "";
    return img && img.style.display !== "none" && img.complete && img.naturalWidth > 0 && { w: img.naturalWidth, h: img.naturalHeight, note };
  }, null, 5000, "viewer without WebCodecs: a decoded camera picture");
  if (cam) {
    check(cam.w === 640 && cam.h === 480 && !/not a decodable/.test(cam.note), `viewer without WebCodecs: a decoded ${cam.w}x${cam.h} JPEG picture`);
    check(/no WebCodecs/.test(cam.note), `viewer without WebCodecs: the panel says why it shows JPEG ("${cam.note}")`);
  }
  const viewerCfg = await until(v, () => window.fleetlink.config.loaded && { may: window.fleetlink.config.mayChange, hidden: document.querySelector(".config .config-edit")?.hidden }, null, 8000, "viewer: the configuration panel loaded");
  if (viewerCfg) check(!viewerCfg.may && viewerCfg.hidden, `viewer: the configuration is shown without its editor ${JSON.stringify(viewerCfg)}`);

  await shot(v, "7-viewer");
  const forged = await v.evaluate((r) => new Promise((resolve) => {
    window.fleetlinkRosbridge.publish(`/${r}/cmd_vel`, { linear: { x: 1, y: 0, z: 0 }, angular: { x: 0, y: 0, z: 0 } }, (why) => resolve(why));
    setTimeout(() => resolve(null), 3000);
  }), robot);
  check(/not allowed/.test(forged ?? ""), `viewer: forged publish refused by the hub: ${forged}`);
  await ctx.close();
} catch (e) {
  fail(`${step}: ${e?.stack ?? e}`);
} finally {
  await browser.close();
}
console.log(failures.length ? `dashboard checks: ${failures.length} failure(s)` : "dashboard checks: all passed");
process.exit(failures.length ? 1 : 0);
