// Recordings: MCAP recordings on the hub (`/api/v1/recordings`): the list with each
// recording's figures and files (downloaded with the session's token), a form to start
// one, and stop / remove. Whether the caller may do each is the hub's answer (403 with
// its reason), shown as is.

import { api } from "../api";
import { session } from "../session";
import { ago, button, el } from "./dom";

interface FileInfo { name: string; bytes: number; messages: number; dropped: number }
interface Recording {
  id: string;
  spec: { topics: string[]; name?: string; duration_s?: number };
  state: "recording" | "stopped" | "interrupted" | "failed";
  started_by: string;
  started_at_ms: number;
  stopped_at_ms?: number;
  messages: number;
  bytes: number;
  dropped: number;
  refused: number;
  files: FileInfo[];
  error?: string;
}

function size(b: number): string {
  const units = ["B", "kB", "MB", "GB", "TB"];
  let x = b, i = 0;
  while (x >= 1000 && i < units.length - 1) { x /= 1000; i++; }
  return `${x.toFixed(x >= 100 || i === 0 ? 0 : 1)} ${units[i]}`;
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
  const table = el("table", "recordings");
  table.id = "recordings";
  panel.append(form, table);
  root.appendChild(panel);

  async function load() {
    try {
      const r = await api<{ recordings: Recording[] }>("/api/v1/recordings");
      table.innerHTML = "<thead><tr><th>id</th><th>state</th><th>topics</th><th>started</th><th>by</th><th>messages</th><th>size</th><th>dropped</th><th>files</th><th></th></tr></thead>";
      const tb = el("tbody");
      for (const rec of r.recordings) {
        const tr = el("tr", rec.state);
        tr.dataset.id = rec.id;
        const state = rec.error ? `${rec.state}: ${rec.error}` : rec.state;
        for (const v of [rec.id, state, rec.spec.topics.join(" "), ago(rec.started_at_ms), rec.started_by, String(rec.messages), size(rec.bytes), String(rec.dropped)]) tr.appendChild(el("td", "", v));
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
        if (rec.state === "recording") acts.appendChild(button("Stop", "", () => act(`/api/v1/recordings/${encodeURIComponent(rec.id)}/stop`, "POST")));
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

  async function act(path: string, method: string) {
    try {
      await api(path, { method });
      status.textContent = "";
    } catch (e) {
      status.textContent = `refused: ${(e as Error).message}`;
    }
    load();
  }

  form.addEventListener("submit", async (ev) => {
    ev.preventDefault();
    const body: Record<string, unknown> = { topics: topics.value.split(/\s+/).filter(Boolean) };
    if (duration.value.trim()) body.duration_s = Number(duration.value);
    try {
      const r = await api<Recording>("/api/v1/recordings", { method: "POST", body: JSON.stringify(body) });
      status.textContent = `started ${r.id}`;
    } catch (e) {
      status.textContent = `refused: ${(e as Error).message}`;
    }
    load();
  });

  load();
  const timer = setInterval(load, 2000);
  return () => clearInterval(timer);
}
