// The fleet view: every robot the caller may see on one map (pose topics, latest-only),
// and a side list from `/api/v1/robots` + `/api/v1/topics` polled once a second: online
// or gone since when, last seen, RTT, goodput, messages/s, drops by reason, clock
// offset, capacity share. Offline robots stay on the map, greyed, where they were last.

import { api, type RobotInfo, type TopicInfo } from "../api";
import { pose2d } from "../messages";
import { count, probe } from "../probe";
import type { Rosbridge } from "../rosbridge";
import { colourFor, MapView } from "./map2d";
import { ago, bps, el, num } from "./dom";

export interface PoseSource {
  topic: string;
  type: string;
}

/** The topic that says where a robot is: a map-frame pose first, else odometry. */
export function poseTopic(robot: string, topics: TopicInfo[]): PoseSource | null {
  const own = topics.filter((t) => t.name.startsWith(`/${robot}/`));
  const pick = (type: string) => own.find((t) => t.type === type);
  const t = pick("geometry_msgs/msg/PoseStamped") ?? pick("nav_msgs/msg/Odometry") ?? pick("geometry_msgs/msg/PoseWithCovarianceStamped");
  return t ? { topic: t.name, type: t.type } : null;
}

/** Sum of one robot's topics' rates and drops, from `/api/v1/topics`. */
function topicTotals(robot: string, topics: TopicInfo[]) {
  let rate = 0, bw = 0;
  const drops: Record<string, number> = {};
  for (const t of topics) {
    if (!t.name.startsWith(`/${robot}/`)) continue;
    rate += t.rate_hz;
    bw += t.bandwidth_bps;
    for (const [k, v] of Object.entries(t.drops ?? {})) if (v) drops[k] = (drops[k] ?? 0) + v;
  }
  return { rate, bw, drops };
}

export function fleetView(root: HTMLElement, rb: Rosbridge, open: (robot: string) => void): () => void {
  root.innerHTML = "";
  const layout = el("div", "fleet");
  const mapBox = el("div", "panel mapbox");
  mapBox.appendChild(el("h2", "", "Fleet map"));
  const side = el("div", "panel side");
  side.appendChild(el("h2", "", "Robots"));
  const list = el("div", "robotlist");
  side.appendChild(list);
  layout.append(mapBox, side);
  root.appendChild(layout);
  const map = new MapView(mapBox);
  map.onClick = (x, y) => {
    // Clicking near a robot opens it.
    let best: string | null = null, bestD = 1.2;
    for (const r of map.robots.values()) {
      if (!r.pose) continue;
      const d = Math.hypot(r.pose.x - x, r.pose.y - y);
      if (d < bestD) { best = r.name; bestD = d; }
    }
    if (best) open(best);
  };
  const subs = new Map<string, () => void>();
  const colours = new Map<string, string>();
  let stopped = false;

  async function refresh() {
    let robots: RobotInfo[] = [], topics: TopicInfo[] = [];
    try {
      [{ robots }, { topics }] = await Promise.all([
        api<{ robots: RobotInfo[] }>("/api/v1/robots"),
        api<{ topics: TopicInfo[] }>("/api/v1/topics"),
      ]);
    } catch (e) {
      list.textContent = `cannot list robots: ${(e as Error).message}`;
      return;
    }
    if (stopped) return;
    robots.sort((a, b) => a.name.localeCompare(b.name, undefined, { numeric: true }));
    robots.forEach((r) => {
      if (!colours.has(r.name)) colours.set(r.name, colourFor(colours.size));
    });
    for (const r of robots) {
      const src = poseTopic(r.name, topics);
      const key = src?.topic;
      if (r.online && src && !subs.has(key!)) {
        const colour = colours.get(r.name)!;
        subs.set(key!, rb.subscribe(src.topic, (msg) => {
          const p = pose2d(msg);
          if (!p) return;
          map.setPose(r.name, p, colour);
          probe.poses[r.name] = { ...p, at: Date.now() };
          count("fleet-pose");
        }, { type: src.type, throttle_rate: 100, queue_length: 1, compression: "none" }));
      }
      const m = map.robots.get(r.name);
      if (m && m.online !== r.online) {
        m.online = r.online;
        map.invalidate();
      }
    }
    renderList(robots, topics);
  }

  function renderList(robots: RobotInfo[], topics: TopicInfo[]) {
    list.innerHTML = "";
    if (robots.length === 0) list.appendChild(el("p", "muted", "No robots visible to you yet."));
    for (const r of robots) {
      const t = topicTotals(r.name, topics);
      const card = el("div", `robot ${r.online ? "online" : "offline"}`);
      card.dataset.robot = r.name;
      const head = el("div", "robot-head");
      const dot = el("span", "dot");
      dot.style.background = r.online ? colours.get(r.name)! : "#56606a";
      head.append(dot, el("b", "", r.name), el("span", r.online ? "badge ok" : "badge off", r.online ? "online" : `offline · gone ${ago(r.last_seen_ms)}`));
      card.appendChild(head);
      const kv = el("dl", "kv");
      const row = (k: string, v: string, title = "") => {
        const dt = el("dt", "", k), dd = el("dd", "", v);
        if (title) dd.title = title;
        kv.append(dt, dd);
      };
      if (r.hub) row("hub", r.hub, "connected to this other hub of the federation");
      else row("last seen", ago(r.last_seen_ms));
      if (r.online && !r.hub) {
        row("RTT", r.rtt_ms != null ? `${num(r.rtt_ms)} ms` : "–");
        row("goodput", bps(r.link_rate_bps), "what the robot's link delivered (its link report)");
        row("msg/s", num(t.rate), `${bps(t.bw)} over ${r.topics.length} topics`);
        const drops = Object.entries(t.drops);
        row("drops", drops.length ? drops.map(([k, v]) => `${k} ${v}`).join(", ") : "none");
        row("clock offset", r.clock_offset_ms != null ? `${num(r.clock_offset_ms)} ms` : "–");
        row("share", r.share_bps ? bps(r.share_bps) : "unlimited", "capacity share of the robot's site");
      }
      card.appendChild(kv);
      card.addEventListener("click", () => open(r.name));
      list.appendChild(card);
    }
  }

  refresh();
  const timer = window.setInterval(refresh, 1000);
  return () => {
    stopped = true;
    clearInterval(timer);
    for (const u of subs.values()) u();
    map.destroy();
  };
}
