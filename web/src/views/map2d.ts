// A top-down 2D map on a canvas: a metre grid, robots as arrows with their heading,
// trails of the last minute, optional scan points and a goal marker. One drawing per
// animation frame at most, however many poses arrive (the data only updates state).
//
// The view fits the room (±10 m by default) and grows to keep every robot in sight;
// clicks are reported in map coordinates so tasking can turn them into goals.

import type { Pose2D } from "../messages";

export interface MapRobot {
  name: string;
  pose: Pose2D | null;
  trail: { x: number; y: number; t: number }[];
  online: boolean;
  colour: string;
}

const TRAIL_MS = 60_000;
const PALETTE = ["#2f80ed", "#eb5757", "#27ae60", "#f2994a", "#9b51e0", "#56ccf2", "#bb6bd9", "#219653"];

export function colourFor(i: number): string {
  return PALETTE[i % PALETTE.length];
}

export class MapView {
  readonly canvas = document.createElement("canvas");
  robots = new Map<string, MapRobot>();
  /** Scan points in map coordinates (interleaved x,y), drawn under the robots. */
  scan: Float32Array | null = null;
  goal: { x: number; y: number } | null = null;
  selected: string | null = null;
  onClick: ((x: number, y: number, ev: MouseEvent) => void) | null = null;
  // Half the side of the square in view, metres: the 20 m room and a margin, to start.
  private half = 11;
  private dirty = true;
  private raf = 0;
  private ro: ResizeObserver;

  constructor(parent: HTMLElement) {
    this.canvas.className = "map";
    parent.appendChild(this.canvas);
    this.ro = new ResizeObserver(() => this.invalidate());
    this.ro.observe(this.canvas);
    this.canvas.addEventListener("click", (ev) => {
      if (!this.onClick) return;
      const [x, y] = this.toWorld(ev.offsetX, ev.offsetY);
      this.onClick(x, y, ev);
    });
    const loop = () => {
      if (this.dirty) this.draw();
      this.raf = requestAnimationFrame(loop);
    };
    this.raf = requestAnimationFrame(loop);
  }

  destroy() {
    cancelAnimationFrame(this.raf);
    this.ro.disconnect();
    this.canvas.remove();
  }

  invalidate() {
    this.dirty = true;
  }

  /** Records a robot's pose (and extends its trail). */
  setPose(name: string, pose: Pose2D, colour: string) {
    let r = this.robots.get(name);
    if (!r) {
      r = { name, pose: null, trail: [], online: true, colour };
      this.robots.set(name, r);
    }
    const now = performance.now();
    r.pose = pose;
    const last = r.trail[r.trail.length - 1];
    if (!last || Math.hypot(last.x - pose.x, last.y - pose.y) > 0.05 || now - last.t > 500) {
      r.trail.push({ x: pose.x, y: pose.y, t: now });
    }
    while (r.trail.length && now - r.trail[0].t > TRAIL_MS) r.trail.shift();
    const reach = Math.max(Math.abs(pose.x), Math.abs(pose.y)) + 1;
    if (reach > this.half) this.half = Math.ceil(reach);
    this.invalidate();
  }

  private geometry() {
    const dpr = window.devicePixelRatio || 1;
    const w = this.canvas.clientWidth, h = this.canvas.clientHeight;
    const scale = Math.min(w, h) / (2 * this.half);
    return { dpr, w, h, scale, cx: w / 2, cy: h / 2 };
  }

  toWorld(px: number, py: number): [number, number] {
    const g = this.geometry();
    return [(px - g.cx) / g.scale, -(py - g.cy) / g.scale];
  }

  toScreen(x: number, y: number): [number, number] {
    const g = this.geometry();
    return [g.cx + x * g.scale, g.cy - y * g.scale];
  }

  private draw() {
    this.dirty = false;
    const g = this.geometry();
    if (g.w === 0 || g.h === 0) return;
    if (this.canvas.width !== Math.round(g.w * g.dpr) || this.canvas.height !== Math.round(g.h * g.dpr)) {
      this.canvas.width = Math.round(g.w * g.dpr);
      this.canvas.height = Math.round(g.h * g.dpr);
    }
    const c = this.canvas.getContext("2d")!;
    c.setTransform(g.dpr, 0, 0, g.dpr, 0, 0);
    c.fillStyle = "#0f1720";
    c.fillRect(0, 0, g.w, g.h);
    const S = (x: number, y: number) => [g.cx + x * g.scale, g.cy - y * g.scale] as const;
    // Metre grid, 5 m lines stronger, axes at the origin.
    for (let i = -this.half; i <= this.half; i++) {
      c.strokeStyle = i === 0 ? "#3b4a5a" : i % 5 === 0 ? "#24313e" : "#18222c";
      c.lineWidth = 1;
      const [x0, y0] = S(i, -this.half), [x1, y1] = S(i, this.half);
      c.beginPath(); c.moveTo(x0, y0); c.lineTo(x1, y1); c.stroke();
      const [a0, b0] = S(-this.half, i), [a1, b1] = S(this.half, i);
      c.beginPath(); c.moveTo(a0, b0); c.lineTo(a1, b1); c.stroke();
    }
    c.fillStyle = "#5b6b7b";
    c.font = "11px sans-serif";
    c.fillText(`1 m grid · ${2 * this.half} m across`, 8, g.h - 8);
    if (this.scan) {
      c.fillStyle = "#f2c94c";
      for (let i = 0; i < this.scan.length; i += 2) {
        const [x, y] = S(this.scan[i], this.scan[i + 1]);
        c.fillRect(x - 1, y - 1, 2, 2);
      }
    }
    if (this.goal) {
      const [x, y] = S(this.goal.x, this.goal.y);
      c.strokeStyle = "#6fcf97";
      c.lineWidth = 2;
      c.beginPath(); c.arc(x, y, 9, 0, Math.PI * 2); c.stroke();
      c.beginPath(); c.moveTo(x - 13, y); c.lineTo(x + 13, y); c.moveTo(x, y - 13); c.lineTo(x, y + 13); c.stroke();
    }
    for (const r of this.robots.values()) {
      const colour = r.online ? r.colour : "#56606a";
      if (r.trail.length > 1) {
        c.strokeStyle = colour;
        c.globalAlpha = 0.55;
        c.lineWidth = 2;
        c.beginPath();
        r.trail.forEach((p, i) => {
          const [x, y] = S(p.x, p.y);
          if (i === 0) c.moveTo(x, y);
          else c.lineTo(x, y);
        });
        c.stroke();
        c.globalAlpha = 1;
      }
      if (!r.pose) continue;
      const [x, y] = S(r.pose.x, r.pose.y);
      const size = Math.max(9, g.scale * 0.45);
      c.save();
      c.translate(x, y);
      c.rotate(-r.pose.yaw);
      c.fillStyle = colour;
      c.strokeStyle = r.name === this.selected ? "#ffffff" : "#0b1016";
      c.lineWidth = 2;
      c.beginPath();
      c.moveTo(size, 0);
      c.lineTo(-size * 0.7, size * 0.6);
      c.lineTo(-size * 0.4, 0);
      c.lineTo(-size * 0.7, -size * 0.6);
      c.closePath();
      c.fill();
      c.stroke();
      c.restore();
      c.fillStyle = r.online ? "#e0e6ec" : "#7b8690";
      c.font = "12px sans-serif";
      c.fillText(r.online ? r.name : `${r.name} (offline)`, x + size + 3, y - size * 0.5);
    }
  }
}
