// Tiny DOM and formatting helpers shared by the views.

export function el<K extends keyof HTMLElementTagNameMap>(tag: K, cls = "", text?: string): HTMLElementTagNameMap[K] {
  const e = document.createElement(tag);
  if (cls) e.className = cls;
  if (text !== undefined) e.textContent = text;
  return e;
}

export function num(v: number | null | undefined, digits = 1): string {
  if (v == null || !Number.isFinite(v)) return "–";
  return Math.abs(v) >= 100 ? v.toFixed(0) : v.toFixed(digits);
}

/** A rate in bytes per second (the hub's `*_bps` fields are bytes, not bits). */
export function bps(v: number | null | undefined): string {
  if (v == null || !Number.isFinite(v) || v <= 0) return "–";
  const units = ["B/s", "kB/s", "MB/s", "GB/s"];
  let x = v, i = 0;
  while (x >= 1000 && i < units.length - 1) { x /= 1000; i++; }
  return `${x.toFixed(x >= 100 ? 0 : 1)} ${units[i]}`;
}

export function ago(ms: number | null | undefined): string {
  if (!ms) return "never";
  const s = Math.max(0, (Date.now() - ms) / 1000);
  if (s < 2) return "just now";
  if (s < 90) return `${s.toFixed(0)} s ago`;
  if (s < 5400) return `${(s / 60).toFixed(0)} min ago`;
  return new Date(ms).toLocaleString();
}

export function button(text: string, cls = "", onClick?: (ev: MouseEvent) => void): HTMLButtonElement {
  const b = el("button", cls, text);
  if (onClick) b.addEventListener("click", onClick);
  return b;
}

/** A collapsible JSON tree (objects and arrays fold; long arrays are summarised upstream). */
export function jsonTree(v: unknown, name = "", depth = 0): HTMLElement {
  if (v !== null && typeof v === "object") {
    const d = el("details");
    if (depth < 2) d.open = true;
    const entries = Object.entries(v as object);
    d.appendChild(el("summary", "", `${name}${name ? ": " : ""}${Array.isArray(v) ? `[${entries.length}]` : `{${entries.length}}`}`));
    for (const [k, x] of entries) d.appendChild(jsonTree(x, k, depth + 1));
    return d;
  }
  const line = el("div", "leaf");
  line.appendChild(el("span", "key", name ? `${name}: ` : ""));
  line.appendChild(el("span", `val ${typeof v}`, JSON.stringify(v) ?? String(v)));
  return line;
}
