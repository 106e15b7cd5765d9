// The robot view: panels chosen from the robot's topics by type (LaserScan 2D,
// PointCloud2 3D, the camera's video or CompressedImage (camera.ts), Odometry/Pose path
// on the map), a generic inspector
// for any topic, per-topic sparklines (rate and bandwidth from the hub, latency measured
// here), the link quality over the last minutes, and the tasking panel.
//
// Heavy topics are subscribed with CBOR and `queue_length: 1`: if this page is slower
// than the robot, the hub drops the older messages for us and we draw the newest.

import { api, type RobotInfo, type TopicInfo } from "../api";
import { inspectable, pose2d, scanPoints, stampMs } from "../messages";
import { MarkerStore } from "../markers";
import { count, probe } from "../probe";
import type { Rosbridge } from "../rosbridge";
import { Chart, Series, Sparkline } from "./charts";
import { cameraPanel } from "./camera";
import { CloudView } from "./cloud3d";
import { configPanel } from "./config";
import { ago, bps, button, el, jsonTree, num } from "./dom";
import { poseTopic } from "./fleet";
import { MapView } from "./map2d";
import { taskingPanel } from "./tasking";

function panel(parent: HTMLElement, title: string, cls = ""): { box: HTMLElement; body: HTMLElement; info: HTMLElement } {
  const box = el("section", `panel ${cls}`);
  const head = el("h2", "", title);
  const info = el("span", "info");
  head.appendChild(info);
  const body = el("div", "body");
  box.append(head, body);
  parent.appendChild(box);
  return { box, body, info };
}

/** Per-topic latency measured in the page: receive time minus the header stamp. */
class TopicClock {
  n = 0;
  lastLatency = NaN;
  note(msg: any) {
    this.n++;
    const s = stampMs(msg?.header);
    if (s != null) this.lastLatency = Date.now() - s;
  }
}

export function robotView(root: HTMLElement, rb: Rosbridge, name: string): () => void {
  root.innerHTML = "";
  const cleanups: (() => void)[] = [];
  const clocks = new Map<string, TopicClock>();
  const clock = (t: string) => {
    let c = clocks.get(t);
    if (!c) clocks.set(t, (c = new TopicClock()));
    return c;
  };
  const head = el("div", "robot-title");
  head.append(el("a", "back", "← fleet"), el("h1", "", name), el("span", "badge", "…"));
  (head.firstChild as HTMLAnchorElement).href = "#/";
  root.appendChild(head);
  const badge = head.lastChild as HTMLElement;
  const grid = el("div", "robot-grid");
  root.appendChild(grid);

  // Map + tasking come first: they are what an operator acts on.
  const mapP = panel(grid, "Map (odometry path, scan, markers, goal)", "wide");
  const map = new MapView(mapP.body);
  map.selected = name;
  map.canvas.id = "robot-map";
  probe.mapToScreen = (x, y) => map.toScreen(x, y);
  cleanups.push(() => map.destroy(), () => (probe.mapToScreen = null));
  const taskP = panel(grid, "Tasking", "tasking");
  const scanP = panel(grid, "Laser scan");
  const cloudP = panel(grid, "Point cloud (3D)");
  const camP = panel(grid, "Camera");
  const topicsP = panel(grid, "Topics", "full");
  const inspP = panel(grid, "Inspector", "inspector");
  const linkP = panel(grid, "Link quality (last 5 minutes)", "wide");
  const configP = panel(grid, "Configuration", "full config");
  probe.config = { loaded: false, mayChange: false, overlay: null, result: "" };
  cleanups.push(configPanel(configP.body, configP.info, name, probe.config));

  let pose: { x: number; y: number; yaw: number } | null = null;
  let started = false;

  function start(topics: TopicInfo[]) {
    started = true;
    const own = topics.filter((t) => t.name.startsWith(`/${name}/`));
    const byType = (ty: string) => own.filter((t) => t.type === ty);
    const colour = "#2f80ed";

    // Pose / odometry → the map and its path.
    const src = poseTopic(name, topics);
    const odom = byType("nav_msgs/msg/Odometry")[0];
    for (const t of [src, odom && { topic: odom.name, type: odom.type }]) {
      if (!t) continue;
      cleanups.push(rb.subscribe(t.topic, (msg) => {
        clock(t.topic).note(msg);
        if (t.topic === odom?.name) count("odom");
        if (t.topic !== src?.topic) return;
        const p = pose2d(msg);
        if (!p) return;
        pose = p;
        map.setPose(name, p, colour);
        probe.poses[name] = { ...p, at: Date.now() };
        count("pose");
      }, { type: t.type, throttle_rate: 50, queue_length: 1, compression: "none" }));
    }
    if (!src) mapP.info.textContent = "no pose or odometry topic";

    // visualization_msgs markers → the map, one store per topic. Not latest-only: a
    // dropped DELETE would leave a marker behind, so a short queue instead.
    const markerTopics = [...byType("visualization_msgs/msg/MarkerArray"), ...byType("visualization_msgs/msg/Marker")];
    for (const t of markerTopics) {
      const store = new MarkerStore();
      map.markers.push(store);
      cleanups.push(rb.subscribe(t.name, (msg) => {
        clock(t.name).note(Array.isArray(msg?.markers) ? msg.markers[0] : msg);
        store.apply(msg, performance.now());
        map.invalidate();
        count("markers");
      }, { type: t.type, queue_length: 10 }));
    }
    if (src) mapP.info.textContent = `${src.topic}${markerTopics.length ? ` · markers: ${markerTopics.map((t) => t.name).join(", ")}` : ""}`;

    // LaserScan → its own 2D panel and, placed at the robot's pose, the map.
    const scan = byType("sensor_msgs/msg/LaserScan")[0];
    if (scan) {
      const cv = el("canvas", "scan");
      scanP.body.appendChild(cv);
      let latest: Float32Array | null = null, rmax = 10, dirty = false;
      cleanups.push(rb.subscribe(scan.name, (msg) => {
        clock(scan.name).note(msg);
        latest = scanPoints(msg);
        rmax = msg.range_max || rmax;
        dirty = true;
        count("scan");
        if (pose) {
          const c = Math.cos(pose.yaw), s = Math.sin(pose.yaw), w = new Float32Array(latest.length);
          for (let i = 0; i < latest.length; i += 2) {
            w[i] = pose.x + c * latest[i] - s * latest[i + 1];
            w[i + 1] = pose.y + s * latest[i] + c * latest[i + 1];
          }
          map.scan = w;
          map.invalidate();
        }
      }, { type: scan.type, queue_length: 1 }));
      let raf = 0;
      const draw = () => {
        raf = requestAnimationFrame(draw);
        if (!dirty || !latest) return;
        dirty = false;
        const dpr = devicePixelRatio || 1, w = cv.clientWidth, h = cv.clientHeight;
        cv.width = w * dpr; cv.height = h * dpr;
        const g = cv.getContext("2d")!;
        g.setTransform(dpr, 0, 0, dpr, 0, 0);
        g.fillStyle = "#0b1016"; g.fillRect(0, 0, w, h);
        const k = Math.min(w, h) / 2 / Math.min(rmax, 15);
        g.strokeStyle = "#1f2a35";
        for (let r = 2; r <= 14; r += 2) { g.beginPath(); g.arc(w / 2, h / 2, r * k, 0, 7); g.stroke(); }
        g.fillStyle = "#f2c94c";
        // Robot frame: x forward drawn up.
        for (let i = 0; i < latest.length; i += 2) g.fillRect(w / 2 - latest[i + 1] * k - 1, h / 2 - latest[i] * k - 1, 2, 2);
        g.fillStyle = "#2f80ed";
        g.beginPath(); g.moveTo(w / 2, h / 2 - 10); g.lineTo(w / 2 - 6, h / 2 + 6); g.lineTo(w / 2 + 6, h / 2 + 6); g.fill();
        scanP.info.textContent = `${scan.name} · ${latest.length / 2} points · 2 m rings`;
      };
      raf = requestAnimationFrame(draw);
      cleanups.push(() => cancelAnimationFrame(raf));
    } else scanP.body.appendChild(el("p", "muted", "This robot publishes no LaserScan."));

    // PointCloud2 → three.js.
    const cloudT = byType("sensor_msgs/msg/PointCloud2")[0];
    if (cloudT) {
      const view = new CloudView(cloudP.body);
      const sel = el("select");
      for (const o of ["height", "intensity"]) sel.appendChild(new Option(`colour by ${o}`, o));
      sel.addEventListener("change", () => (view.colourBy = sel.value as never));
      cloudP.box.querySelector("h2")!.appendChild(sel);
      // Age of the cloud on screen: from its header stamp (the robot's clock) to the
      // frame that showed it.
      view.onShown = (stamp) => {
        if (stamp != null) probe.cloudAgesMs.push(Date.now() - stamp);
        if (probe.cloudAgesMs.length > 2000) probe.cloudAgesMs.splice(0, 1000);
        count("cloud-rendered");
      };
      cleanups.push(rb.subscribe(cloudT.name, (msg) => {
        clock(cloudT.name).note(msg);
        const n = view.show(msg);
        count("cloud");
        cloudP.info.textContent = `${cloudT.name} · ${n.toLocaleString()} points`;
      }, { type: cloudT.type, queue_length: 1 }));
      cleanups.push(() => view.destroy());
    } else cloudP.body.appendChild(el("p", "muted", "This robot publishes no PointCloud2."));

    // Camera: the video topic played with WebCodecs, or the JPEG topic.
    const cameraTopics = cameraPanel(camP, rb, own, cleanups, (t, msg) => clock(t).note(msg));

    // Inspector: any topic, JSON tree, rate and latency.
    const sel = el("select");
    const tree = el("div", "tree");
    inspP.body.append(sel, tree);
    const shown = new Set([scan?.name, cloudT?.name, src?.topic, ...markerTopics.map((t) => t.name), ...cameraTopics]);
    // Start on a live topic the other panels do not show (odometry, in the demo).
    const firstOther = own.find((t) => !shown.has(t.name) && t.rate_hz > 0) ?? own.find((t) => !shown.has(t.name)) ?? own[0];
    for (const t of own) sel.appendChild(new Option(`${t.name} (${t.type})`, t.name));
    if (firstOther) sel.value = firstOther.name;
    let unsubInsp: (() => void) | null = null, last: any = null, lastAt = 0, n = 0, t0 = performance.now();
    const inspect = () => {
      unsubInsp?.();
      const t = own.find((x) => x.name === sel.value);
      if (!t) return;
      n = 0; t0 = performance.now(); last = null;
      tree.textContent = "waiting for a message…";
      unsubInsp = rb.subscribe(t.name, (msg, _topic, at) => {
        clock(t.name).note(msg);
        last = msg; lastAt = at; n++;
        count("inspector");
      }, { type: t.type, queue_length: 1, throttle_rate: 200 });
    };
    sel.addEventListener("change", inspect);
    inspect();
    const inspTimer = window.setInterval(() => {
      if (!last) return;
      const rate = n / ((performance.now() - t0) / 1000);
      const lat = clock(sel.value).lastLatency;
      inspP.info.textContent = `${num(rate)} msg/s shown · latency ${num(lat, 0)} ms · ${Math.round(performance.now() - lastAt)} ms ago`;
      tree.replaceChildren(jsonTree(inspectable(last), sel.value));
    }, 1000);
    cleanups.push(() => { clearInterval(inspTimer); unsubInsp?.(); });

    taskingPanel(taskP.body, rb, name, map, () => pose, cleanups);
  }

  // Topic table with sparklines and the link chart, from the REST API once a second.
  const table = el("table", "topics");
  table.innerHTML = "<thead><tr><th>topic</th><th>type</th><th>rate (hub)</th><th>bandwidth (hub)</th><th>latency (here)</th><th>drops</th></tr></thead>";
  const tbody = el("tbody");
  table.appendChild(tbody);
  topicsP.body.appendChild(table);
  const rows = new Map<string, { name: HTMLElement; cell: HTMLElement; pull: HTMLButtonElement | null; rate: Sparkline; bw: Sparkline; lat: Sparkline; s: [Series, Series, Series]; drops: HTMLElement }>();
  const link = new Series(3, 300);
  const linkChart = new Chart(linkP.body, link, [
    { label: "RTT ms", colour: "#f2994a", scale: "ms" },
    { label: "latency ms", colour: "#eb5757", scale: "ms" },
    { label: "link MB/s", colour: "#27ae60", scale: "r" },
  ], Math.max(400, linkP.body.clientWidth || 900), 180);
  cleanups.push(() => linkChart.destroy());

  async function refresh() {
    let robots: RobotInfo[], topics: TopicInfo[];
    try {
      [{ robots }, { topics }] = await Promise.all([
        api<{ robots: RobotInfo[] }>("/api/v1/robots"),
        api<{ topics: TopicInfo[] }>("/api/v1/topics"),
      ]);
    } catch (e) {
      badge.textContent = `cannot read the hub: ${(e as Error).message}`;
      return;
    }
    const me = robots.find((r) => r.name === name);
    badge.textContent = !me ? "not visible to you" : me.online ? "online" : "offline";
    badge.className = `badge ${me?.online ? "ok" : "off"}`;
    root.classList.toggle("offline", !!me && !me.online);
    if (!started && me?.online) start(topics);
    const now = Date.now() / 1000;
    if (me?.online) link.push(now, me.rtt_ms ?? null, me.latency_ms ?? null, me.link_rate_bps != null ? me.link_rate_bps / 1e6 : null);
    // The data budget: what it allows, what the link uses, which topics give way.
    const b = me?.budget;
    const limits = b ? [b.max_bps != null ? `${bps(b.max_bps)}` : "", b.day_bytes != null ? `${num(b.day_bytes / 1e6, 0)} MB/day` : ""].filter((x) => x) : [];
    linkP.info.textContent = b
      ? ` · budget ${limits.join(" and ")}: using ${bps(b.use_bps)}${b.thinned.length ? `, thinning ${b.thinned.length} topic${b.thinned.length > 1 ? "s" : ""}` : ""}`
      : "";
    // An idle link is not probed: say how old its capacity estimate is.
    const age = me?.link_estimate_age_s;
    if (me?.online && age != null && age >= 10) {
      linkP.info.textContent += ` · capacity ${me.capacity_bps ? bps(me.capacity_bps) : "not known"}, measured ${ago(Date.now() - age * 1000)} (idle since)`;
    } else if (me?.online && age == null) {
      linkP.info.textContent += " · link capacity not measured with data yet";
    }
    // Its mirrors in the cloud, and whether the link carries what their nodes read.
    const mirrors = me?.mirrors ?? [];
    linkP.info.textContent += mirrors
      .map((m) => {
        const of = me?.capacity_bps ? ` of ${bps(me.capacity_bps)}` : "";
        const verdict = m.offload.fits === null ? "link capacity not known yet" : m.offload.fits ? "fits the link: offload" : "does not fit the link";
        return ` · mirror ${m.name} reads ${m.reads.length} topic${m.reads.length === 1 ? "" : "s"}, ${bps(m.inputs_bps)}${of}: ${verdict}`;
      })
      .join("");
    linkP.info.title = mirrors.length ? mirrors[0].offload.rule : "";
    linkChart.update();
    for (const t of topics.filter((x) => x.name.startsWith(`/${name}/`))) {
      let r = rows.get(t.name);
      if (!r) {
        const tr = el("tr");
        const cells = Array.from({ length: 6 }, () => el("td"));
        const label = el("span", "", t.name);
        cells[0].append(label);
        cells[1].textContent = t.type;
        tr.append(...cells);
        tbody.appendChild(tr);
        const s: [Series, Series, Series] = [new Series(1, 120), new Series(1, 120), new Series(1, 120)];
        r = { name: label, cell: cells[0], pull: null, rate: new Sparkline(cells[2], s[0], "#2f80ed"), bw: new Sparkline(cells[3], s[1], "#27ae60"), lat: new Sparkline(cells[4], s[2], "#eb5757"), s, drops: cells[5] };
        rows.set(t.name, r);
      }
      // Held back on the robot while nobody watches; opening a panel makes it flow. A pull
      // topic comes only when asked: one message per press of its button.
      const state = t.state === "idle" || t.state === "pull" ? t.state : t.thinned ? "thinned" : "";
      r.name.textContent = state ? `${t.name} (${state})` : t.name;
      r.name.title =
        t.state === "idle" ? "nobody is subscribed: the robot holds this topic back"
        : t.state === "pull" ? "sent only when asked: one message per pull"
        : t.thinned ? "the robot's data budget holds this topic back (lowest priorities first)" : "";
      if (t.state === "pull" && !r.pull) {
        const out = el("div", "pulled");
        const topic = t.name;
        const b = button("pull", "small", async () => {
          b.disabled = true;
          try {
            const local = topic.slice(name.length + 2);
            const v = await api<{ msg: unknown }>(`/api/v1/robots/${encodeURIComponent(name)}/topics/${local}/pull`, { method: "POST" });
            out.replaceChildren(jsonTree(v.msg, topic));
          } catch (e) {
            out.textContent = `pull failed: ${(e as Error).message}`;
          } finally {
            b.disabled = false;
          }
        });
        r.cell.append(" ", b, out);
        r.pull = b;
      }
      const lat = clocks.get(t.name)?.lastLatency ?? NaN;
      r.s[0].push(now, t.rate_hz);
      r.s[1].push(now, t.bandwidth_bps);
      r.s[2].push(now, Number.isFinite(lat) ? lat : null);
      // Beside the measured rate: what the robot offers and what its link can deliver of
      // it, when the link cannot carry everything.
      const offered = t.offered_rate_hz, predicted = t.predicted_rate_hz;
      const short = offered != null && predicted != null && predicted < offered * 0.98;
      r.rate.update(short
        ? `${num(t.rate_hz)} Hz · link carries ~${num(predicted)} of ${num(offered)} offered`
        : `${num(t.rate_hz)} Hz`);
      r.cell.parentElement?.children[2]?.setAttribute("title", offered == null ? ""
        : `offered on the robot: ${num(offered)} Hz` + (predicted == null ? "" : `; predicted over its link: ${num(predicted)} Hz`));
      // What the robot's link carries, where compression makes it less than the payloads.
      const ratio = t.compression_ratio ?? 1;
      r.bw.update(ratio >= 1.05 && t.link_bandwidth_bps != null
        ? `${bps(t.bandwidth_bps)} · link ${bps(t.link_bandwidth_bps)} (${num(ratio, 1)}×)`
        : bps(t.bandwidth_bps));
      r.lat.update(Number.isFinite(lat) ? `${num(lat, 0)} ms` : "not subscribed");
      const d = Object.entries(t.drops ?? {}).filter(([, v]) => v).map(([k, v]) => `${k} ${v}`);
      const rd = Object.entries(t.robot_drops ?? {}).filter(([, v]) => v).map(([k, v]) => `${k} ${v}`);
      r.drops.textContent = [...d, ...(rd.length ? [`on the robot: ${rd.join(", ")}`] : [])].join("; ") || "0";
    }
  }
  refresh();
  const timer = window.setInterval(refresh, 1000);
  cleanups.push(() => clearInterval(timer), () => rows.forEach((r) => { r.rate.destroy(); r.bw.destroy(); r.lat.destroy(); }));
  return () => cleanups.forEach((c) => c());
}

