// Small live plots on uPlot: a fixed-length ring of samples per series, redrawn at most
// once a second, so a plot costs the same after ten minutes as after one.

import uPlot from "uplot";

export class Series {
  readonly t: number[] = [];
  /** `null` marks a gap (uPlot skips it; NaN would spoil the axis range). */
  readonly ys: (number | null)[][];
  constructor(n: number, private keep: number) {
    this.ys = Array.from({ length: n }, () => []);
  }
  push(t: number, ...v: (number | null)[]) {
    this.t.push(t);
    v.forEach((x, i) => this.ys[i].push(x != null && Number.isFinite(x) ? x : null));
    if (this.t.length > this.keep) {
      this.t.shift();
      for (const y of this.ys) y.shift();
    }
  }
}

/** A sparkline: no axes, one series, the last value written beside it. */
export class Sparkline {
  private plot: uPlot;
  readonly label = document.createElement("span");
  constructor(parent: HTMLElement, private s: Series, colour: string, width = 120, height = 28) {
    const wrap = document.createElement("span");
    wrap.className = "spark";
    parent.appendChild(wrap);
    this.plot = new uPlot(
      {
        width, height, cursor: { show: false }, legend: { show: false }, select: { show: false } as never,
        axes: [{ show: false }, { show: false }],
        scales: { x: { time: false }, y: { range: (_u, min, max) => [Math.min(0, min), max > 0 ? max * 1.1 : 1] } },
        series: [{}, { stroke: colour, width: 1.5, fill: colour + "33", points: { show: false } }],
      },
      [[], []],
      wrap,
    );
    wrap.appendChild(this.label);
  }
  update(text: string) {
    this.plot.setData([this.s.t, this.s.ys[0]] as never);
    this.label.textContent = text;
  }
  destroy() {
    this.plot.destroy();
  }
}

/** A plot with axes and a legend, several series, for the link quality panel. */
export class Chart {
  private plot: uPlot;
  constructor(parent: HTMLElement, private s: Series, names: { label: string; colour: string; scale?: string }[], width: number, height: number) {
    this.plot = new uPlot(
      {
        width, height,
        scales: { x: { time: true } },
        axes: [{ stroke: "#8a96a3", grid: { stroke: "#1f2a35" } }, { stroke: "#8a96a3", grid: { stroke: "#1f2a35" }, scale: names[0].scale }, ...(names.some((n) => n.scale === "r") ? [{ side: 1, scale: "r", stroke: "#8a96a3", grid: { show: false } }] : [])],
        series: [{}, ...names.map((n) => ({ label: n.label, stroke: n.colour, width: 1.5, scale: n.scale, points: { show: false } }))],
      },
      [[], ...names.map(() => [])] as never,
      parent,
    );
  }
  update() {
    this.plot.setData([this.s.t, ...this.s.ys] as never);
  }
  destroy() {
    this.plot.destroy();
  }
}
