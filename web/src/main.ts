// The dashboard's shell: the connection to the hub, sign-in/out, the e-stop, and the
// router between views (`#/` fleet, `#/robot/<name>`, `#/recordings`, `#/admin`).

import { api, ApiError } from "./api";
import { probe } from "./probe";
import { Rosbridge } from "./rosbridge";
import { session } from "./session";
import { adminView } from "./views/admin";
import { recordingsView } from "./views/recordings";

import { fleetView } from "./views/fleet";
import { robotView } from "./views/robot";

const $ = <T extends HTMLElement>(id: string) => document.getElementById(id) as T;
const main = $("main");
const conn = $("conn");
const who = $("who");
const signInBtn = $<HTMLButtonElement>("signin");
const signOutBtn = $<HTMLButtonElement>("signout");
const estop = $<HTMLButtonElement>("estop");
const estopNote = $("estop-note");
const dialog = $<HTMLDialogElement>("login");

/** E-stop target, configurable (kept in localStorage: it is not a secret). */
function estopConfig(): { topic: string; type: string } {
  try {
    const c = JSON.parse(localStorage.getItem("fleetlink.estop") ?? "null");
    if (c?.topic && c?.type) return c;
  } catch {
    /* default below */
  }
  return { topic: "/fleet/estop", type: "std_msgs/msg/Bool" };
}

let rb: Rosbridge;
let leave: () => void = () => {};

function connect() {
  rb?.close();
  rb = new Rosbridge(session.wsUrl());
  (globalThis as any).fleetlinkRosbridge = rb;
  rb.onState = (s, d) => {
    conn.textContent = s === "open" ? "connected" : s === "connecting" ? "connecting…" : `disconnected (${d}), retrying`;
    conn.className = `conn ${s}`;
    if (s === "open") probeEstop();
  };
  const p = session.principal();
  who.textContent = p === "token" ? "signed in with a token" : p ? `signed in as ${p}` : "anonymous (read-only where the hub allows)";
  signInBtn.hidden = !!p;
  signOutBtn.hidden = !p;
}

async function probeEstop() {
  const c = estopConfig();
  const why = await rb.advertise(c.topic, c.type);
  estop.disabled = !!why;
  estop.title = why ? `Disabled: ${why}` : `publishes ${c.type} {data: true} on ${c.topic}`;
  estopNote.textContent = why ? `e-stop disabled: ${why}` : `→ ${c.topic}`;
  if (why) probe.disabled.estop = why;
  else delete probe.disabled.estop;
}

estop.addEventListener("click", () => {
  const c = estopConfig();
  const msg = c.type.endsWith("/Bool") ? { data: true } : {};
  // Repeated a few times: a lost frame must not mean a robot that keeps driving.
  for (let i = 0; i < 3; i++) setTimeout(() => rb.publish(c.topic, msg, (why) => (estopNote.textContent = `e-stop refused: ${why}`)), i * 100);
  estopNote.textContent = `e-stop sent on ${c.topic} at ${new Date().toLocaleTimeString()}`;
});

function route() {
  leave();
  const h = location.hash.replace(/^#\/?/, "");
  document.querySelectorAll("nav a").forEach((a) => a.classList.toggle("active", (a as HTMLAnchorElement).hash === `#/${h.split("/")[0]}`));
  main.classList.remove("offline");
  if (h.startsWith("robot/")) leave = robotView(main, rb, decodeURIComponent(h.slice(6)));
  else if (h === "admin") leave = adminView(main);
  else if (h === "recordings") leave = recordingsView(main);
  else leave = fleetView(main, rb, (name) => (location.hash = `#/robot/${encodeURIComponent(name)}`));
}

// --- sign-in: user/password → session token from the hub, or a token pasted as is.
signInBtn.addEventListener("click", () => dialog.showModal());
$("login-cancel").addEventListener("click", () => dialog.close());
$<HTMLFormElement>("login-form").addEventListener("submit", async (ev) => {
  ev.preventDefault();
  const f = ev.target as HTMLFormElement;
  const user = (f.elements.namedItem("user") as HTMLInputElement).value;
  const password = (f.elements.namedItem("password") as HTMLInputElement).value;
  const token = (f.elements.namedItem("token") as HTMLInputElement).value.trim();
  const err = $("login-error");
  err.textContent = "";
  try {
    if (token) {
      // Ask the hub whether it takes the token before keeping it.
      const r = await fetch("/api/v1/robots", { headers: { Authorization: `Bearer ${token}` } });
      if (!r.ok) throw new ApiError(r.status, (await r.json().catch(() => null))?.error ?? `HTTP ${r.status}`);
      session.set(token, "token");
    } else {
      const r = await api<{ token: string; principal: string }>("/api/v1/login", { method: "POST", body: JSON.stringify({ user, password }) });
      session.set(r.token, r.principal);
    }
    f.reset();
    dialog.close();
    connect();
    route();
  } catch (e) {
    err.textContent = `sign-in refused: ${(e as Error).message}`;
  }
});
signOutBtn.addEventListener("click", async () => {
  // A login session ends at the hub; a pasted long-lived token is only forgotten here.
  if (session.principal() !== "token") await api("/api/v1/logout", { method: "POST" }).catch(() => {});
  session.clear();
  connect();
  route();
});

window.addEventListener("hashchange", route);
connect();
route();
// The one render counter the benchmarks read: animation frames the page got.
const tick = () => {
  probe.renders++;
  requestAnimationFrame(tick);
};
requestAnimationFrame(tick);

