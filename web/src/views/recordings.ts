// Recordings: MCAP recordings on the hub (`/api/v1/recordings`): the list with each
// recording's figures and files (downloaded with the session's token), a form to start
// one, a form to fetch a slice of a robot's black box (`/api/v1/recordings/blackbox`),
// and stop / remove. Whether the caller may do each is the hub's answer (403 with its
// reason), shown as is. The list is read again every 2 s, which is also how a fetch's
// progress moves: the hub keeps the figures, the page only shows them.

import { api, type RobotInfo } from "../api";
import { session } from "../session";
import { ago, button, el } from "./dom";

interface FileInfo { name: string; bytes: number; messages: number; dropped: number }
/** How far a black-box fetch is (the hub's `BlackBoxFetch`). */
interface BlackBox {
  robot: string;
  range: { last_s?: number; from_ns?: number; to_ns?: number; topics: string[] };
  /** Known once the robot has cut the slice. */
  size?: number;
  received: number;
  sha256?: string;
  calls: number;
  resumed: number;
  refused: number;
  /** What the fetch waits for, in words, while it waits. */
  waiting?: string;
}
interface Recording {
  id: string;
  spec: { topics: string[]; name?: string; duration_s?: number };
  state: "recording" | "fetching" | "stopped" | "interrupted" | "failed";
  started_by: string;
  started_at_ms: number;
  stopped_at_ms?: number;
  messages: number;
  bytes: number;
  dropped: number;
  refused: number;
  files: FileInfo[];
  error?: string;
  blackbox?: BlackBox;
}

function size(b: number): string {
  const units = ["B", "kB", "MB", "GB", "TB"];
  let x = b, i = 0;
  while (x >= 1000 && i < units.length - 1) { x /= 1000; i++; }
  return `${x.toFixed(x >= 100 || i === 0 ? 0 : 1)} ${units[i]}`;
}

/** Space-separated words of a text field (topics, patterns). */
function words(s: string): string[] {
  return s.split(/\s+/).filter(Boolean);
}

/** What a black-box slice covers, for its row: "black box of robot1, last 60 s: /scan". */
function sliceText(bb: BlackBox): string {
  const r = bb.range;
  const when = r.last_s != null ? `last ${r.last_s} s`
    : r.from_ns != null ? `from ${new Date(r.from_ns / 1e6).toLocaleString()}${r.to_ns != null ? ` to ${new Date(r.to_ns / 1e6).toLocaleString()}` : ""}`
    : "";
  const topics = r.topics.length ? r.topics.join(" ") : "every topic it keeps";
  return `black box of ${bb.robot}${when ? `, ${when}` : ""}: ${topics}`;
}

/** The state cell; a fetch in progress also shows how far it is and what it waits for. */
function stateCell(rec: Recording): HTMLTableCellElement {
  const td = el("td", "", rec.error ? `${rec.state}: ${rec.error}` : rec.state);
  const bb = rec.blackbox;
  if (rec.state !== "fetching" || !bb) return td;
  if (bb.size != null) {
    // Floor, so that 100% means the whole slice is in, not 99.6% of it.
    const pct = bb.size > 0 ? Math.floor((bb.received * 100) / bb.size) : 100;
    const bar = el("progress");
    bar.max = Math.max(bb.size, 1);
    bar.value = Math.min(bb.received, bar.max);
    td.append(bar, el("div", "", `${pct}% · ${size(bb.received)} of ${size(bb.size)}`));
  } else if (bb.received > 0) {
    td.append(el("div", "", `${size(bb.received)} received`));
  }
  if (bb.waiting) td.append(el("div", "why", bb.waiting));
  if (bb.resumed > 0) td.append(el("div", "muted", `resumed ${bb.resumed}×`));
  return td;
}

export function recordingsView(root: HTMLElement): () => void {
  root.innerHTML = "";
  const panel = el("section", "panel wide");
  panel.appendChild(el("h2", "", "Recordings"));
  const form = el("form", "filters");
  form.id = "record-form";
  const topics = el("input");
  topics.name = "topics";
  topics.placeholder = "topics, e.g. /robot1/.* /robot2/scan";
  topics.size = 40;
  const duration = el("input");
  duration.name = "duration";
  duration.placeholder = "duration in s (empty: until stopped)";
  const start = button("Start recording", "primary");
  start.type = "submit";
  const status = el("span", "muted");
  status.id = "record-status";
  form.append(topics, duration, start, status);

  // A slice of what a robot kept in its ring buffer, asked for after the fact.
  const bbForm = el("form", "filters");
  bbForm.id = "blackbox-form";
  const robotSel = el("select");
  robotSel.name = "robot";
  robotSel.title = "the robot whose black box to read (an offline one is waited for)";
  const lastS = el("input");
  lastS.name = "last_s";
  lastS.type = "number";
  // Any value: the hub takes fractions and names what it refuses, which the browser's
  // own validation would hide behind a tooltip.
  lastS.step = "any";
  lastS.value = "60";
  lastS.style.width = "6em";
  const lastLabel = el("label", "muted", "last ");
  lastLabel.append(lastS, " s");
  const bbTopics = el("input");
  bbTopics.name = "topics";
  bbTopics.placeholder = "the robot's own topics, e.g. /scan /odom (empty: all)";
  bbTopics.size = 40;
  const bbName = el("input");
  bbName.name = "name";
  bbName.placeholder = "name (optional)";
  const fetchBtn = button("Fetch black box", "primary");
  fetchBtn.type = "submit";
  const bbStatus = el("span", "muted");
  bbStatus.id = "blackbox-status";
  bbForm.append(robotSel, lastLabel, bbTopics, bbName, fetchBtn, bbStatus);

  const table = el("table", "recordings");
  table.id = "recordings";
  panel.append(form, bbForm, table);
  root.appendChild(panel);

  async function load() {
    try {
      const r = await api<{ recordings: Recording[] }>("/api/v1/recordings");
      table.innerHTML = "<thead><tr><th>id</th><th>state</th><th>topics</th><th>started</th><th>by</th><th>messages</th><th>size</th><th>dropped</th><th>files</th><th></th></tr></thead>";
      const tb = el("tbody");
      for (const rec of r.recordings) {
        const tr = el("tr", rec.blackbox ? `${rec.state} blackbox` : rec.state);
        tr.dataset.id = rec.id;
        tr.append(el("td", "", rec.id), stateCell(rec));
        // A slice's topics are the robot's own names, meaningless without the robot.
        tr.append(el("td", "", rec.blackbox ? sliceText(rec.blackbox) : rec.spec.topics.join(" ")));
        for (const v of [ago(rec.started_at_ms), rec.started_by, String(rec.messages), size(rec.bytes), String(rec.dropped)]) tr.appendChild(el("td", "", v));
        const files = el("td");
        for (const f of rec.files) {
          const a = el("a", "", f.name);
          const q = session.token() ? `?token=${encodeURIComponent(session.token()!)}` : "";
          a.href = `/api/v1/recordings/${encodeURIComponent(rec.id)}/files/${encodeURIComponent(f.name)}${q}`;
          a.download = f.name;
          a.title = `${f.messages} messages, ${size(f.bytes)}`;
          files.append(a, " ");
        }
        tr.appendChild(files);
        const acts = el("td");
        // Stopping a fetch gives up on the rest of the slice (it ends `failed`).
        if (rec.state === "recording" || rec.state === "fetching") acts.appendChild(button("Stop", "", () => act(`/api/v1/recordings/${encodeURIComponent(rec.id)}/stop`, "POST")));
        else acts.appendChild(button("Remove", "", () => confirm(`Delete ${rec.id} and its files?`) && act(`/api/v1/recordings/${encodeURIComponent(rec.id)}`, "DELETE")));
        tr.appendChild(acts);
        tb.appendChild(tr);
      }
      table.appendChild(tb);
      if (!r.recordings.length) table.appendChild(el("caption", "muted", "No recordings yet."));
    } catch (e) {
      table.replaceChildren(el("caption", "why", `The hub refused the recordings: ${(e as Error).message}`));
    }
  }

  // The robots the caller may see, offline ones too (a fetch waits for its robot).
  let listed = "";
  async function loadRobots() {
    let robots: RobotInfo[];
    try {
      ({ robots } = await api<{ robots: RobotInfo[] }>("/api/v1/robots"));
    } catch (e) {
      listed = "";
      const o = el("option", "", `cannot list robots: ${(e as Error).message}`);
      o.value = "";
      robotSel.replaceChildren(o);
      return;
    }
    robots.sort((a, b) => a.name.localeCompare(b.name, undefined, { numeric: true }));
    const labels = robots.map((r) => (r.online ? r.name : `${r.name} (offline)`));
    // Rebuilding the options closes the list under the operator's pointer: only on change.
    if (labels.join("\n") === listed && robots.length) return;
    listed = labels.join("\n");
    const keep = robotSel.value;
    const opts = robots.map((r, i) => {
      const o = el("option", "", labels[i]);
      o.value = r.name;
      return o;
    });
    if (!opts.length) {
      const o = el("option", "", "no robots known");
      o.value = "";
      opts.push(o);
    }
    robotSel.replaceChildren(...opts);
    if (robots.some((r) => r.name === keep)) robotSel.value = keep;
  }

  // Every change to the recordings goes through here: the hub's answer (or its refusal,
  // word for word) lands in `out`, and the list is read again either way.
  async function send(out: HTMLElement, path: string, method: string, body?: unknown, done?: (r: Recording) => string) {
    try {
      const init: RequestInit = body === undefined ? { method } : { method, body: JSON.stringify(body) };
      const r = await api<Recording>(path, init);
      out.textContent = done ? done(r) : "";
    } catch (e) {
      out.textContent = `refused: ${(e as Error).message}`;
    }
    load();
  }

  const act = (path: string, method: string) => send(status, path, method);

  form.addEventListener("submit", (ev) => {
    ev.preventDefault();
    const body: Record<string, unknown> = { topics: words(topics.value) };
    if (duration.value.trim()) body.duration_s = Number(duration.value);
    send(status, "/api/v1/recordings", "POST", body, (r) => `started ${r.id}`);
  });

  bbForm.addEventListener("submit", (ev) => {
    ev.preventDefault();
    const body: Record<string, unknown> = { robot: robotSel.value, topics: words(bbTopics.value) };
    // Left out when empty so that the hub says what it needs, rather than a NaN.
    if (lastS.value.trim()) body.last_s = Number(lastS.value);
    if (bbName.value.trim()) body.name = bbName.value.trim();
    send(bbStatus, "/api/v1/recordings/blackbox", "POST", body, (r) => `fetching ${r.id}`);
  });

  load();
  loadRobots();
  const timer = setInterval(load, 2000);
  // Robots come and go far less often than a fetch's figures move.
  const robotsTimer = setInterval(loadRobots, 10000);
  return () => {
    clearInterval(timer);
    clearInterval(robotsTimer);
  };
}
