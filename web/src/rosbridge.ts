// The dashboard's one connection to the hub: rosbridge v2 over the hub's port.
//
// Design choice: every subscription asks for `compression: "cbor"` so large messages
// (clouds, scans, images) arrive as binary CBOR with RFC 8746 typed arrays — no JSON
// parse of a million numbers — and for `queue_length: 1` (latest-only), so a slow page
// always gets the newest message instead of an ever-growing backlog. Replies that the
// hub refuses (a `status` error with the request's id, or `result: false`) reach the
// caller as rejected promises carrying the hub's text: the page shows *that* text to
// explain what is disabled, it never guesses roles.

import { decode } from "cbor2";
import { probe } from "./probe";

// cbor2 (pure JavaScript, no native add-on): maps as objects, RFC 8746 typed arrays as
// TypedArrays, byte strings as Uint8Array, 64-bit integers as numbers while exact.

/** Decodes one binary rosbridge frame (a CBOR map holding the op). */
export function decodeFrame(data: ArrayBuffer | Uint8Array): Record<string, unknown> {
  const bytes = data instanceof Uint8Array ? data : new Uint8Array(data);
  return decode(bytes) as Record<string, unknown>;
}

export interface SubOptions {
  type?: string;
  throttle_rate?: number;
  queue_length?: number;
  regex?: boolean;
  /** JSON for small topics where readability matters more than size. */
  compression?: "cbor" | "none";
}

/** `size` is the frame's length in bytes, for the per-topic bandwidth plots. */
export type Handler = (msg: any, topic: string, receivedAt: number, size: number) => void;

interface Sub {
  topic: string;
  opts: SubOptions;
  handlers: Set<Handler>;
}

export class Refused extends Error {}

type Pending = { resolve: (v: any) => void; reject: (e: Error) => void; timer: number };

export interface GoalHandle {
  id: string;
  result: Promise<{ status: number; values: any; result: boolean }>;
  cancel(): void;
}

export class Rosbridge {
  private ws: WebSocket | null = null;
  private subs = new Map<string, Sub>();
  private pending = new Map<string, Pending>();
  private goals = new Map<string, { onFeedback: (v: any) => void; done: Pending }>();
  private statusWaiters = new Map<string, (msg: string) => void>();
  private nextId = 1;
  private closed = false;
  private retryMs = 500;
  /** Set by the page for the status bar. */
  onState: (state: "connecting" | "open" | "closed", detail?: string) => void = () => {};
  /** Frames received, for the tests and the status bar. */
  framesIn = 0;
  bytesIn = 0;

  constructor(private url: string) {
    this.connect();
  }

  private connect() {
    this.onState("connecting");
    const ws = new WebSocket(this.url);
    ws.binaryType = "arraybuffer";
    this.ws = ws;
    ws.onopen = () => {
      this.retryMs = 500;
      this.onState("open");
      for (const s of this.subs.values()) this.sendSubscribe(s);
    };
    ws.onmessage = (ev) => this.onFrame(ev.data);
    ws.onclose = (ev) => {
      this.onState("closed", ev.reason || `code ${ev.code}`);
      for (const [id, p] of this.pending) {
        clearTimeout(p.timer);
        p.reject(new Error("connection to the hub lost"));
        this.pending.delete(id);
      }
      if (!this.closed) {
        setTimeout(() => this.connect(), this.retryMs);
        this.retryMs = Math.min(this.retryMs * 2, 5000);
      }
    };
  }

  close() {
    this.closed = true;
    this.ws?.close();
  }

  private send(op: Record<string, unknown>) {
    if (this.ws?.readyState === WebSocket.OPEN) this.ws.send(JSON.stringify(op));
  }

  private onFrame(data: string | ArrayBuffer) {
    const now = performance.now();
    this.framesIn++;
    let m: Record<string, any>;
    const size = typeof data === "string" ? data.length : data.byteLength;
    try {
      if (typeof data === "string") {
        this.bytesIn += data.length;
        m = JSON.parse(data);
      } else {
        this.bytesIn += data.byteLength;
        m = decodeFrame(data);
      }
      probe.busyMs.decode += performance.now() - now;
    } catch (e) {
      console.warn("undecodable frame from the hub", e);
      return;
    }
    switch (m.op) {
      case "publish": {
        const topic = String(m.topic);
        for (const s of this.subs.values()) {
          if (s.topic === topic || (s.opts.regex && new RegExp(`^(?:${s.topic})$`).test(topic))) {
            for (const h of s.handlers) {
              try {
                h(m.msg, topic, now, size);
              } catch (e) {
                console.error(`handler for ${topic} failed`, e);
              }
            }
          }
        }
        break;
      }
      case "service_response": {
        const p = this.pending.get(String(m.id));
        if (!p) break;
        this.pending.delete(String(m.id));
        clearTimeout(p.timer);
        if (m.result === false) p.reject(new Refused(typeof m.values === "string" ? m.values : JSON.stringify(m.values)));
        else p.resolve(m.values);
        break;
      }
      case "action_feedback": {
        this.goals.get(String(m.id))?.onFeedback(m.values);
        break;
      }
      case "action_result": {
        const g = this.goals.get(String(m.id));
        if (!g) break;
        this.goals.delete(String(m.id));
        g.done.resolve({ status: m.status, values: m.values, result: m.result });
        break;
      }
      case "status": {
        const id = m.id === undefined ? undefined : String(m.id);
        if (m.level === "error" && id) {
          const p = this.pending.get(id);
          if (p) {
            this.pending.delete(id);
            clearTimeout(p.timer);
            p.reject(new Refused(String(m.msg)));
          }
          const g = this.goals.get(id);
          if (g) {
            this.goals.delete(id);
            g.done.reject(new Refused(String(m.msg)));
          }
          this.statusWaiters.get(id)?.(String(m.msg));
        }
        if (m.level === "error" && !id) console.warn("hub:", m.msg);
        break;
      }
    }
  }

  private sendSubscribe(s: Sub) {
    this.send({
      op: "subscribe",
      id: `sub:${s.topic}`,
      topic: s.topic,
      type: s.opts.type,
      compression: s.opts.compression ?? "cbor",
      queue_length: s.opts.queue_length ?? 1,
      throttle_rate: s.opts.throttle_rate ?? 0,
      regex: s.opts.regex || undefined,
    });
  }

  /** Subscribes (shared per topic); returns the unsubscribe function. */
  subscribe(topic: string, handler: Handler, opts: SubOptions = {}): () => void {
    let s = this.subs.get(topic);
    if (!s) {
      s = { topic, opts, handlers: new Set() };
      this.subs.set(topic, s);
      this.sendSubscribe(s);
    }
    s.handlers.add(handler);
    return () => {
      const cur = this.subs.get(topic);
      if (!cur) return;
      cur.handlers.delete(handler);
      if (cur.handlers.size === 0) {
        this.subs.delete(topic);
        this.send({ op: "unsubscribe", id: `sub:${topic}`, topic });
      }
    };
  }

  /** Calls a service; rejects with the hub's text when refused or failed. */
  call(service: string, args: unknown = {}, timeoutS = 10): Promise<any> {
    const id = `call:${this.nextId++}`;
    return new Promise((resolve, reject) => {
      const timer = window.setTimeout(() => {
        this.pending.delete(id);
        reject(new Error(`${service}: no answer within ${timeoutS + 2} s`));
      }, (timeoutS + 2) * 1000);
      this.pending.set(id, { resolve, reject, timer });
      this.send({ op: "call_service", id, service, args, timeout: timeoutS });
    });
  }

  /**
   * Advertises `topic` and waits briefly for a refusal: the hub answers a refused
   * advertise with a `status` error naming the reason, and says nothing on success.
   * Resolves with `null` when allowed, else with the hub's text.
   */
  advertise(topic: string, type: string, waitMs = 1500): Promise<string | null> {
    const id = `adv:${topic}:${this.nextId++}`;
    return new Promise((resolve) => {
      const timer = window.setTimeout(() => {
        this.statusWaiters.delete(id);
        resolve(null);
      }, waitMs);
      this.statusWaiters.set(id, (msg) => {
        clearTimeout(timer);
        this.statusWaiters.delete(id);
        resolve(msg);
      });
      this.send({ op: "advertise", id, topic, type });
    });
  }

  unadvertise(topic: string) {
    this.send({ op: "unadvertise", topic });
  }

  /** Publishes; `onRefused` gets the hub's text if the publish is refused. */
  publish(topic: string, msg: unknown, onRefused?: (why: string) => void) {
    const id = `pub:${topic}:${this.nextId++}`;
    if (onRefused) {
      this.statusWaiters.set(id, (why) => {
        this.statusWaiters.delete(id);
        onRefused(why);
      });
      setTimeout(() => this.statusWaiters.delete(id), 5000);
    }
    this.send({ op: "publish", id, topic, msg });
  }

  /** Sends an action goal with feedback; `result` settles with the action_result. */
  sendGoal(action: string, actionType: string, args: unknown, onFeedback: (v: any) => void): GoalHandle {
    const id = `goal:${this.nextId++}`;
    const result = new Promise<any>((resolve, reject) => {
      this.goals.set(id, { onFeedback, done: { resolve, reject, timer: 0 } });
    });
    this.send({ op: "send_action_goal", id, action, action_type: actionType, args, feedback: true });
    return { id, result, cancel: () => this.send({ op: "cancel_action_goal", id, action }) };
  }
}
