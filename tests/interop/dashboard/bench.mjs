// Dashboard performance in headless Chromium: the robot view of a robot publishing a
// large point cloud. Samples once a second: animation frames (the page's render loop),
// clouds shown, the age of each cloud when shown (header stamp → the frame that drew it),
// the JS heap. Prints one JSON object.
//
//   node bench.mjs --url http://HUB/ --token T --robot robot4 --seconds 60 --minutes 10
import { createRequire } from "node:module";
import { dirname, join } from "node:path";
import { fileURLToPath, pathToFileURL } from "node:url";
import { parseArgs } from "node:util";

const web = join(dirname(fileURLToPath(import.meta.url)), "..", "..", "..", "web");
const puppeteer = (await import(pathToFileURL(createRequire(join(web, "package.json")).resolve("puppeteer-core")).href)).default;
const { values: o } = parseArgs({
  options: {
    url: { type: "string" }, token: { type: "string" }, robot: { type: "string", default: "robot4" },
    seconds: { type: "string", default: "60" }, minutes: { type: "string", default: "10" },
    shot: { type: "string" },
  },
});
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));
const pct = (a, p) => { const s = [...a].sort((x, y) => x - y); return s.length ? s[Math.min(s.length - 1, Math.floor((p / 100) * s.length))] : null; };

const browser = await puppeteer.launch({
  executablePath: "/usr/bin/chromium",
  headless: true,
  args: ["--no-sandbox", "--enable-unsafe-swiftshader", "--use-angle=swiftshader", "--ignore-gpu-blocklist", "--enable-precise-memory-info"],
  defaultViewport: { width: 1500, height: 1000 },
});
try {
  const page = await browser.newPage();
  await page.evaluateOnNewDocument((t) => { sessionStorage.setItem("fleetlink.token", t); sessionStorage.setItem("fleetlink.principal", "bench"); }, o.token);
  await page.goto(`${o.url}#/robot/${o.robot}`);
  await page.waitForFunction(() => (window.fleetlink?.frames?.["cloud-rendered"] ?? 0) > 5, { timeout: 30000 });
  // The heap after a full garbage collection, so garbage not yet collected is not counted.
  const cdp = await page.createCDPSession();
  const heap = async () => { await cdp.send("HeapProfiler.collectGarbage"); return (await page.metrics()).JSHeapUsedSize; };
  const read = () => page.evaluate(() => ({ busy: { ...window.fleetlink.busyMs }, renders: window.fleetlink.renders, shown: window.fleetlink.frames["cloud-rendered"] ?? 0, ages: window.fleetlink.cloudAgesMs.splice(0), points: document.querySelector(".robot-grid section:nth-child(4) .info")?.textContent }));
  const start = Date.now();
  await read(); // drop the warm-up ages
  const a = await read();
  await sleep(Number(o.seconds) * 1000);
  const b = await read();
  const secs = (Date.now() - start) / 1000;
  const out = {
    seconds: Number(secs.toFixed(1)),
    frames_per_s: Number(((b.renders - a.renders) / secs).toFixed(1)),
    clouds_shown_per_s: Number(((b.shown - a.shown) / secs).toFixed(2)),
    cloud_age_ms: { p50: pct(b.ages, 50), p99: pct(b.ages, 99), n: b.ages.length },
    panel: b.points,
    // Share of wall time the page's main thread spent on each (summed ms / elapsed ms).
    busy_share: Object.fromEntries(Object.keys(b.busy).map((k) => [k, Number(((b.busy[k] - a.busy[k]) / (secs * 1000)).toFixed(3))])),
  };
  if (o.shot) await page.screenshot({ path: o.shot });
  const minutes = Number(o.minutes);
  if (minutes > 0) {
    // Memory: after 1 minute and after `minutes`, the page left running.
    const wait = async (m) => { const left = start + m * 60000 - Date.now(); if (left > 0) await sleep(left); };
    // One sample a minute shows a trend, not just two points.
    out.heap_bytes_by_minute = {};
    for (let m = 1; m <= minutes; m++) {
      await wait(m);
      out.heap_bytes_by_minute[m] = await heap();
    }
    out.heap_growth = Number((out.heap_bytes_by_minute[minutes] / out.heap_bytes_by_minute[1] - 1).toFixed(3));
    const c = await read();
    out.cloud_age_ms_last_minutes = { p50: pct(c.ages, 50), p99: pct(c.ages, 99), n: c.ages.length };
  }
  console.log(JSON.stringify(out));
} finally {
  await browser.close();
}
