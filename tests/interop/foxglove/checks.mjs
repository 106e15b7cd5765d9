// What the Foxglove suite's Node checks share: a failed check, a bounded wait on a
// condition, and the `ok:` line.

export class CheckFailed extends Error {}

export function check(cond, what) {
  if (!cond) throw new CheckFailed(what);
}

export const ok = (what) => console.log(`  ok: ${what}`);

export const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

// Polls `get` every 20 ms until it returns something truthy (returned), or fails naming
// `what` after `ms`.
export async function until(get, what, ms) {
  const end = Date.now() + ms;
  for (;;) {
    const v = get();
    if (v) return v;
    if (Date.now() > end) throw new CheckFailed(`timed out waiting for ${what}`);
    await sleep(20);
  }
}
