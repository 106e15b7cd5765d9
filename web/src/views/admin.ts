// Admin: the audit log (filter, page through with the hub's cursor) and the access
// rules. Whether the caller may see them is the hub's answer to the request (403 with
// its reason), shown as is.

import { api } from "../api";
import { button, el } from "./dom";

export function adminView(root: HTMLElement): () => void {
  root.innerHTML = "";
  const wrap = el("div", "admin");
  const auditP = el("section", "panel wide");
  auditP.appendChild(el("h2", "", "Audit log"));
  const filters = el("form", "filters");
  const fields: Record<string, HTMLInputElement | HTMLSelectElement> = {};
  for (const [k, ph] of [["principal", "user:alice"], ["action", "publish"], ["name_regex", "/robot1/.*"]]) {
    const i = el("input");
    i.name = k;
    i.placeholder = `${k} e.g. ${ph}`;
    fields[k] = i;
    filters.appendChild(i);
  }
  const allowed = el("select");
  allowed.name = "allowed";
  for (const [v, t] of [["", "allowed and denied"], ["true", "allowed only"], ["false", "denied only"]]) allowed.appendChild(new Option(t, v));
  fields.allowed = allowed;
  filters.appendChild(allowed);
  const apply = button("Filter", "primary");
  apply.type = "submit";
  filters.appendChild(apply);
  const table = el("table", "audit");
  const pager = el("div", "pager");
  const more = button("Next page →");
  const first = button("⇤ First page");
  const note = el("span", "muted");
  pager.append(first, more, note);
  auditP.append(filters, table, pager);
  const rulesP = el("section", "panel wide");
  rulesP.appendChild(el("h2", "", "Access rules"));
  const rules = el("div");
  rulesP.appendChild(rules);
  wrap.append(auditP, rulesP);
  root.appendChild(wrap);

  const PAGE = 50;
  let cursors: unknown[] = [null];
  let page = 0;

  async function load() {
    const q = new URLSearchParams({ limit: String(PAGE) });
    for (const [k, f] of Object.entries(fields)) if (f.value) q.set(k, f.value);
    const c = cursors[page];
    if (c != null) q.set("cursor", typeof c === "string" ? c : JSON.stringify(c));
    try {
      const r = await api<{ records: any[]; next: unknown }>(`/api/v1/audit?${q}`);
      table.innerHTML = "<thead><tr><th>time</th><th>principal</th><th>client</th><th>action</th><th>name</th><th>size</th><th>allowed</th><th>detail</th></tr></thead>";
      const tb = el("tbody");
      for (const rec of r.records) {
        const tr = el("tr", rec.allowed ? "" : "denied");
        const at = rec.at?.secs != null ? rec.at.secs * 1000 : typeof rec.at === "number" ? (rec.at > 1e12 ? rec.at : rec.at * 1000) : NaN;
        for (const v of [Number.isFinite(at) ? new Date(at).toLocaleString() : JSON.stringify(rec.at), rec.principal, rec.client_ip, rec.action, rec.name, rec.size ?? "", rec.allowed ? "yes" : "no", rec.detail ?? ""]) tr.appendChild(el("td", "", String(v)));
        tb.appendChild(tr);
      }
      table.appendChild(tb);
      cursors = cursors.slice(0, page + 1);
      if (r.next != null) cursors.push(r.next);
      more.disabled = r.next == null;
      first.disabled = page === 0;
      note.textContent = `page ${page + 1} · ${r.records.length} records`;
    } catch (e) {
      table.replaceChildren(el("caption", "why", `The hub refused the audit log: ${(e as Error).message}`));
      more.disabled = first.disabled = true;
    }
  }
  filters.addEventListener("submit", (ev) => {
    ev.preventDefault();
    cursors = [null];
    page = 0;
    load();
  });
  more.addEventListener("click", () => { page++; load(); });
  first.addEventListener("click", () => { page = 0; load(); });
  load();
  api<{ rules: any[] }>("/api/v1/rules").then(
    (r) => {
      const t = el("table", "rules");
      t.innerHTML = "<thead><tr><th>id</th><th>subject</th><th>names</th><th>ops</th><th>effect</th><th>comment</th></tr></thead>";
      const tb = el("tbody");
      for (const x of r.rules) {
        const rule = x.rule ?? x;
        const tr = el("tr");
        // `{user: alice}` reads better as `user:alice`; the words (`anyone`, ...) stay.
        const subject = rule.subject && typeof rule.subject === "object" ? Object.entries(rule.subject).map(([k, v]) => `${k}:${v}`).join(" ") : rule.subject;
        for (const v of [x.id ?? "", subject, rule.names, Array.isArray(rule.ops) ? rule.ops.join(", ") : rule.ops, rule.effect ?? "allow", rule.comment ?? ""]) tr.appendChild(el("td", "", typeof v === "string" || typeof v === "number" ? String(v) : JSON.stringify(v)));
        tb.appendChild(tr);
      }
      t.appendChild(tb);
      rules.replaceChildren(r.rules.length ? t : el("p", "muted", "No rules: only the built-in defaults apply (admin group, robots' own namespaces, anonymous read where enabled)."));
    },
    (e) => rules.replaceChildren(el("p", "why", `The hub refused the rules: ${(e as Error).message}`)),
  );
  return () => {};
}
