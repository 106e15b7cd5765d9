// Tasking: navigation goals clicked on the map (to the robot's action, with feedback,
// progress and Cancel; else a PoseStamped on a goal topic), the initial pose, and a form
// generated from any service's request type.
//
// What the user may do is learnt from the hub, never from a role name: the `/rosapi`
// listings only name the services and actions the caller may call, an advertise the
// caller may not publish on is answered with a `status` error, and any call the hub
// refuses later disables its control with the hub's own text.

import { skeleton, type Typedef } from "../messages";
import { count, probe } from "../probe";
import { Refused, type Rosbridge } from "../rosbridge";
import { button, el, jsonTree, num } from "./dom";
import type { MapView } from "./map2d";

function disable(ctrl: HTMLButtonElement | HTMLElement, key: string, why: string, note: HTMLElement) {
  if (ctrl instanceof HTMLButtonElement || ctrl instanceof HTMLSelectElement) ctrl.disabled = true;
  ctrl.title = why;
  note.textContent = `Disabled: ${why}`;
  note.className = "why";
  probe.disabled[key] = why;
}

export function taskingPanel(
  root: HTMLElement,
  rb: Rosbridge,
  robot: string,
  map: MapView,
  pose: () => { x: number; y: number; yaw: number } | null,
  cleanups: (() => void)[],
) {
  const ns = `/${robot}/`;
  // --- navigation
  const nav = el("div", "task nav");
  nav.appendChild(el("h3", "", "Navigation goal"));
  const navHelp = el("p", "muted", "Looking for the robot's navigation action…");
  const progress = el("progress") as HTMLProgressElement;
  progress.max = 1;
  progress.value = 0;
  const navState = el("div", "navstate", "");
  const cancel = button("Cancel goal", "danger");
  cancel.disabled = true;
  nav.append(navHelp, progress, navState, cancel);
  // --- initial pose
  const init = el("div", "task init");
  init.appendChild(el("h3", "", "Initial pose"));
  const initBtn = button("Set initial pose: click the map");
  const initNote = el("p", "muted", `publishes geometry_msgs/msg/PoseWithCovarianceStamped on ${ns}initialpose`);
  init.append(initBtn, initNote);
  // --- service form
  const svc = el("div", "task svc");
  svc.appendChild(el("h3", "", "Call a service"));
  const svcSel = el("select");
  const form = el("form", "svcform");
  const svcOut = el("div", "svcout");
  const svcNote = el("p", "muted", "Listing the services you may call…");
  svc.append(svcSel, svcNote, form, svcOut);
  root.append(nav, init, svc);

  let mode: "goal" | "init" = "goal";
  let goal: ReturnType<Rosbridge["sendGoal"]> | null = null;
  let action: { name: string; type: string } | null = null;
  let goalTopicAllowed = false;
  let initAllowed = false;

  map.onClick = async (x, y) => {
    if (mode === "init") {
      mode = "goal";
      initBtn.classList.remove("armed");
      if (!initAllowed) return;
      const yaw = pose()?.yaw ?? 0;
      rb.publish(`${ns}initialpose`, {
        header: { frame_id: "map", stamp: { sec: 0, nanosec: 0 } },
        pose: { pose: { position: { x, y, z: 0 }, orientation: { x: 0, y: 0, z: Math.sin(yaw / 2), w: Math.cos(yaw / 2) } }, covariance: new Array(36).fill(0) },
      }, (why) => disable(initBtn, "initialpose", why, initNote));
      initNote.textContent = `initial pose sent: (${num(x, 2)}, ${num(y, 2)})`;
      return;
    }
    if (action) sendGoal(x, y);
    else if (goalTopicAllowed) {
      map.goal = { x, y };
      map.invalidate();
      rb.publish(`${ns}goal_pose`, {
        header: { frame_id: "map", stamp: { sec: 0, nanosec: 0 } },
        pose: { position: { x, y, z: 0 }, orientation: { x: 0, y: 0, z: 0, w: 1 } },
      }, (why) => disable(nav, "goal", why, navHelp));
      navState.textContent = `goal published on ${ns}goal_pose: (${num(x, 2)}, ${num(y, 2)})`;
    }
  };

  function sendGoal(x: number, y: number) {
    if (!action) return;
    const a = action;
    map.goal = { x, y };
    map.invalidate();
    const p = pose();
    const start = p ? Math.hypot(p.x - x, p.y - y) : 1;
    progress.value = 0;
    navState.textContent = `goal (${num(x, 2)}, ${num(y, 2)}) sent to ${a.name}…`;
    const g = rb.sendGoal(a.name, a.type, { x, y }, (fb) => {
      if (goal !== g) return;
      const d = Number(fb?.distance_remaining);
      probe.feedback.push(d);
      if (probe.feedback.length > 500) probe.feedback.splice(0, 250);
      count("feedback");
      if (Number.isFinite(d)) {
        progress.value = start > 0 ? Math.max(0, Math.min(1, 1 - d / start)) : 1;
        navState.textContent = `driving to (${num(x, 2)}, ${num(y, 2)}): ${num(d, 2)} m to go`;
      }
    });
    goal = g;
    cancel.disabled = false;
    g.result.then(
      (r) => {
        probe.lastResult = r;
        if (goal !== g) return;
        const what = r.status === 4 ? "reached" : r.status === 5 ? "canceled" : r.status === 6 ? "aborted" : `ended (status ${r.status})`;
        const v = r.values ?? {};
        navState.textContent = `goal ${what}${v.x != null ? ` at (${num(v.x, 2)}, ${num(v.y, 2)})` : ""}`;
        if (r.status === 4) progress.value = 1;
        cancel.disabled = true;
        goal = null;
      },
      (e: Error) => {
        if (goal !== g) return;
        goal = null;
        cancel.disabled = true;
        if (e instanceof Refused && /not allowed/.test(e.message)) disable(nav, "navigate", e.message, navHelp);
        else navState.textContent = `goal failed: ${e.message}`;
      },
    );
  }
  cancel.addEventListener("click", () => {
    goal?.cancel();
    navState.textContent += " · cancel requested";
  });
  initBtn.addEventListener("click", () => {
    mode = mode === "init" ? "goal" : "init";
    initBtn.classList.toggle("armed", mode === "init");
  });
  cleanups.push(() => goal?.cancel());

  // What may this caller do? Ask the hub.
  (async () => {
    const [actions, services] = await Promise.all([
      rb.call("/rosapi/action_servers").then((v) => (v.action_servers as string[]) ?? [], () => [] as string[]),
      rb.call("/rosapi/services").then((v) => (v.services as string[]) ?? [], () => [] as string[]),
    ]);
    const mine = actions.filter((a) => a.startsWith(ns));
    const nav2 = mine.find((a) => /navigate/.test(a)) ?? mine[0];
    if (nav2) {
      const type = await rb.call("/rosapi/service_type", { service: nav2 }).then((v) => String(v.type ?? ""), () => "");
      action = { name: nav2, type };
      navHelp.textContent = `Click on the map to send a goal to ${nav2} (${type}).`;
    } else {
      const why = await rb.advertise(`${ns}goal_pose`, "geometry_msgs/msg/PoseStamped");
      if (why) disable(cancel, "navigate", `the hub lists no navigation action you may use on ${robot}, and refused the goal topic: ${why}`, navHelp);
      else {
        goalTopicAllowed = true;
        cleanups.push(() => rb.unadvertise(`${ns}goal_pose`));
        navHelp.textContent = `No navigation action listed for you; clicks publish a PoseStamped on ${ns}goal_pose.`;
      }
    }
    const whyInit = await rb.advertise(`${ns}initialpose`, "geometry_msgs/msg/PoseWithCovarianceStamped");
    if (whyInit) disable(initBtn, "initialpose", whyInit, initNote);
    else {
      initAllowed = true;
      cleanups.push(() => rb.unadvertise(`${ns}initialpose`));
    }
    const own = services.filter((s) => s.startsWith(ns));
    if (own.length === 0) {
      disable(svcSel, "services", `the hub lists no services of ${robot} you may call (/rosapi/services)`, svcNote);
      return;
    }
    for (const s of own) svcSel.appendChild(new Option(s, s));
    svcNote.textContent = "";
    svcSel.addEventListener("change", () => buildForm(svcSel.value));
    buildForm(own[0]);
  })();

  async function buildForm(service: string) {
    form.replaceChildren(el("p", "muted", "loading the request type…"));
    svcOut.replaceChildren();
    let type = "", defs: Typedef[] = [];
    try {
      type = String((await rb.call("/rosapi/service_type", { service })).type);
      defs = (await rb.call("/rosapi/service_request_details", { type })).typedefs ?? [];
    } catch (e) {
      form.replaceChildren(el("p", "why", `cannot read the type of ${service}: ${(e as Error).message}`));
      return;
    }
    const req = skeleton(defs);
    form.replaceChildren(el("div", "muted", `${type} request`));
    const inputs: { path: string[]; input: HTMLInputElement; kind: string }[] = [];
    const walk = (obj: Record<string, unknown>, td: Typedef | undefined, path: string[]) => {
      if (!td) return;
      td.fieldnames.forEach((f, i) => {
        const ft = td.fieldtypes[i];
        const sub = defs.find((d) => d.type === ft);
        if (sub && td.fieldarraylen[i] === -1) return walk(obj[f] as Record<string, unknown>, sub, [...path, f]);
        const label = el("label", "", `${[...path, f].join(".")} (${ft}${td.fieldarraylen[i] >= 0 ? "[]" : ""})`);
        const input = el("input");
        input.name = [...path, f].join(".");
        if (ft === "bool" && td.fieldarraylen[i] === -1) input.type = "checkbox";
        else input.value = JSON.stringify(obj[f]);
        label.appendChild(input);
        form.appendChild(label);
        inputs.push({ path: [...path, f], input, kind: ft === "bool" && td.fieldarraylen[i] === -1 ? "bool" : ft === "string" && td.fieldarraylen[i] === -1 ? "string" : "json" });
      });
    };
    walk(req, defs[0], []);
    if (inputs.length === 0) form.appendChild(el("p", "muted", "(no request fields)"));
    for (const i of inputs) if (i.kind === "string") i.input.value = "";
    const go = button("Call", "primary");
    go.type = "submit";
    form.appendChild(go);
    form.onsubmit = async (ev) => {
      ev.preventDefault();
      const args = structuredClone(req);
      try {
        for (const i of inputs) {
          let o = args as Record<string, unknown>;
          for (const k of i.path.slice(0, -1)) o = o[k] as Record<string, unknown>;
          const k = i.path[i.path.length - 1];
          o[k] = i.kind === "bool" ? i.input.checked : i.kind === "string" ? i.input.value : JSON.parse(i.input.value || "null");
        }
      } catch (e) {
        svcOut.replaceChildren(el("p", "why", `bad value: ${(e as Error).message}`));
        return;
      }
      go.disabled = true;
      svcOut.replaceChildren(el("p", "muted", `calling ${service}…`));
      try {
        const v = await rb.call(service, args, 10);
        probe.lastServiceResponse = { service, ok: true, values: v };
        count("service-response");
        svcOut.replaceChildren(el("div", "ok", "response:"), jsonTree(v));
      } catch (e) {
        probe.lastServiceResponse = { service, ok: false, error: (e as Error).message };
        svcOut.replaceChildren(el("p", "why", `refused or failed: ${(e as Error).message}`));
        if (e instanceof Refused && /not allowed/.test(e.message)) disable(go, `call:${service}`, e.message, svcNote);
      } finally {
        if (!probe.disabled[`call:${service}`]) go.disabled = false;
      }
    };
  }
}
