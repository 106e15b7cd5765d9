// The hub's REST API (`/api/v1/*`), authenticated with the session's token when there
// is one (anonymous otherwise: the demo hub lets loopback clients read).

import { session } from "./session";

export class ApiError extends Error {
  constructor(public status: number, message: string) {
    super(message);
  }
}

export async function api<T = any>(path: string, init: RequestInit = {}): Promise<T> {
  const headers = new Headers(init.headers);
  const token = session.token();
  if (token) headers.set("Authorization", `Bearer ${token}`);
  if (init.body) headers.set("Content-Type", "application/json");
  const r = await fetch(path, { ...init, headers, cache: "no-store" });
  const text = await r.text();
  let body: any = null;
  try {
    body = text ? JSON.parse(text) : null;
  } catch {
    body = text;
  }
  if (!r.ok) throw new ApiError(r.status, (body && body.error) || text || `HTTP ${r.status}`);
  return body as T;
}

export interface RobotInfo {
  name: string;
  online: boolean;
  namespace: string;
  connected_at_ms?: number;
  last_seen_ms?: number;
  rtt_ms?: number;
  latency_ms?: number;
  link_rate_bps?: number;
  share_bps?: number | null;
  demand_bps?: number;
  clock_offset_ms?: number | null;
  topics: string[];
  /** The hub it is connected to, when that is another hub of a federation. */
  hub?: string;
  /** The robot's data budget as its agent last reported it (absent: none). Bytes per
   * second and per day on the wire; `thinned`: topics it holds back now. */
  budget?: { max_bps: number | null; day_bytes: number | null; used_bytes: number; use_bps: number; thinned: string[] } | null;
  /** What the robot may send now, bytes/s, as its agent last reported it. */
  capacity_bps?: number | null;
  /** When the robot's link rate was last measured with data on it (Unix ms, hub clock),
   * and how many seconds ago: an idle link is not probed, so its estimate ages. */
  link_measured_at_ms?: number | null;
  link_estimate_age_s?: number | null;
  /** Mirrors of the robot beside offloaded nodes (docs/mirror.md): the robot topics each
   * reads now, their bytes/s over the robot's link, and the offload signal (`fits`: the
   * link carries them; null while the capacity is not known). */
  mirrors?: { name: string; connected_at_ms: number; reads: string[]; inputs_bps: number; offload: { rule: string; fits: boolean | null } }[];
}

export interface TopicInfo {
  name: string;
  type: string;
  rate_hz: number;
  bandwidth_bps: number;
  messages: number;
  bytes: number;
  last_message_ms: number | null;
  drops?: Record<string, number>;
  /** What the robot lost of the topic before its link, by reason (its agent's report). */
  robot_drops?: Record<string, number>;
  /** A robot's topic nobody wants is held back on the robot: `idle`; `pull`: sent only
   * when asked (POST /api/v1/robots/{robot}/topics/{topic}/pull). */
  state?: "flowing" | "idle" | "pull";
  /** Over the robot's link (absent for topics that do not come over one): the bytes as
   * carried (compressed where it paid), payload bytes over link bytes, link bytes/s. */
  link_bytes?: number | null;
  compression_ratio?: number | null;
  link_bandwidth_bps?: number | null;
  /** Held back by its robot's data budget now (thinned or paused). */
  thinned?: boolean;
  /** A robot's topic: what its publishers offer on the robot (Hz), and what its link
   * should deliver of that, given the link's capacity, the message sizes and the
   * robot's other topics (docs/qos.md, receive-rate prediction). */
  offered_rate_hz?: number | null;
  predicted_rate_hz?: number | null;
}
