// Who the page is signed in as. The token lives in sessionStorage only (gone with the
// tab), never in localStorage or a cookie.

const KEY = "fleetlink.token";
const WHO = "fleetlink.principal";

export const session = {
  token(): string | null {
    return sessionStorage.getItem(KEY);
  },
  principal(): string | null {
    return sessionStorage.getItem(WHO);
  },
  set(token: string, principal: string) {
    sessionStorage.setItem(KEY, token);
    sessionStorage.setItem(WHO, principal);
  },
  clear() {
    sessionStorage.removeItem(KEY);
    sessionStorage.removeItem(WHO);
  },
  /** The rosbridge URL on the page's own origin: the hub serves both on one port. */
  wsUrl(): string {
    const proto = location.protocol === "https:" ? "wss:" : "ws:";
    const t = this.token();
    return `${proto}//${location.host}/${t ? `?token=${encodeURIComponent(t)}` : ""}`;
  },
};
