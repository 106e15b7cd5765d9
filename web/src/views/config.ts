// The robot view's configuration panel (docs/runtime-config.md): the configuration the
// robot runs with (asked of its agent through the hub), the changes in force and who made
// them, and — for an operator who may change it — an editor for a change, applied at once
// by the agent or refused with the error its YAML would give (line and column in the
// change).

import { api, ApiError } from "../api";
import { button, el } from "./dom";

interface ConfigView {
  robot: string;
  online: boolean;
  may_change: boolean;
  effective?: string;
  overlay?: Record<string, unknown>;
  changeable?: string[];
  persisted?: string | null;
  changed_at_ms?: number | null;
  changed_by?: string | null;
  kept?: { overlay: unknown; by: string; at_ms: number } | null;
  changed?: string[];
  unchanged?: boolean;
  error?: string;
}

/** What the panel exposes to the dashboard's test hooks (`window.fleetlink.config`). */
export interface ConfigProbe {
  loaded: boolean;
  mayChange: boolean;
  overlay: unknown;
  result: string;
}

export function configPanel(body: HTMLElement, info: HTMLElement, robot: string, probe: ConfigProbe): () => void {
  const effective = el("pre", "config-effective", "…");
  const changes = el("div", "config-changes");
  const editor = el("textarea", "config-editor");
  editor.rows = 8;
  editor.spellcheck = false;
  editor.placeholder = "topics:\n  /scan: { rate_limit_hz: 2 }";
  const result = el("div", "config-result");
  const apply = button("apply change", "", () => void send());
  const reload = button("reload", "small", () => void load());
  const controls = el("div", "config-controls");
  controls.append(apply, reload);
  const edit = el("div", "config-edit");
  edit.append(el("label", "", "change (YAML or JSON, the agent file's fields; only those listed below may change while it runs)"), editor, controls, result);
  body.append(changes, edit, effective);
  let alive = true;

  function show(v: ConfigView) {
    probe.loaded = true;
    probe.mayChange = v.may_change;
    probe.overlay = v.overlay ?? null;
    effective.textContent = v.effective ?? v.error ?? "";
    const overlay = v.overlay ?? {};
    const n = Object.keys(overlay).length;
    const who = v.changed_by ? ` by ${v.changed_by}${v.changed_at_ms ? `, ${new Date(v.changed_at_ms).toLocaleString()}` : ""}` : "";
    changes.textContent = n ? `changes in force${who}:` : "no changes in force: the robot runs its file's configuration";
    if (n) changes.appendChild(el("pre", "", JSON.stringify(overlay, null, 2)));
    if (v.kept) changes.appendChild(el("div", "info", `the hub keeps them and applies them again when ${robot} reconnects (last by ${v.kept.by})`));
    info.textContent = v.online ? (v.persisted ? ` · kept on the robot in ${v.persisted}` : " · not kept on the robot") : " · offline";
    edit.hidden = !v.may_change;
    apply.disabled = !v.online;
    if (v.changeable) editor.title = `may change while it runs: ${v.changeable.join(", ")}`;
    if (!editor.value && n) editor.value = JSON.stringify(overlay, null, 2);
  }

  async function load() {
    try {
      const v = await api<ConfigView>(`/api/v1/robots/${encodeURIComponent(robot)}/config`);
      if (alive) show(v);
    } catch (e) {
      if (!alive) return;
      probe.loaded = true;
      effective.textContent = `cannot read the configuration: ${(e as Error).message}`;
      edit.hidden = true;
    }
  }

  async function send() {
    apply.disabled = true;
    result.className = "config-result";
    try {
      const v = await api<ConfigView>(`/api/v1/robots/${encodeURIComponent(robot)}/config`, { method: "PUT", body: editor.value });
      const text = v.unchanged ? "nothing changed" : `applied: ${(v.changed ?? []).join(", ")}`;
      result.textContent = text;
      result.classList.add("ok");
      probe.result = text;
      show({ ...v, may_change: true, online: true });
    } catch (e) {
      const text = e instanceof ApiError ? e.message : `${(e as Error).message}`;
      result.textContent = `refused: ${text}`;
      result.classList.add("error");
      probe.result = `refused: ${text}`;
    } finally {
      apply.disabled = false;
    }
  }

  void load();
  return () => {
    alive = false;
  };
}
