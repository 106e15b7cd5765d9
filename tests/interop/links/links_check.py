#!/usr/bin/env python3
"""Bad-links reliability suite: drives a fleetlink hub and agent in two network namespaces
(made by run.sh) through blackouts, a falling bandwidth, process kills, a slowloris
attack and a dead link with service calls in flight both ways, measures what the link
carries (interest, compression, a data budget), and asserts the outcomes in
docs/benchmarks/log.md ("Bad links").

Runs inside the hub namespace (so the hub is reachable on 127.0.0.1); starts processes in
either namespace with `ip netns exec`. Each scenario is a function returning rows
(figure, measured, target, ok); the driver prints them as one table, writes them to
results.md/results.json in --out, and exits 1 if any row is not ok (or a scenario could
not be run: ERROR). Scenarios: LINKS_SCENARIOS="1 2 3 4 5 6 7 8 9 10 11" (default all).

Thresholds (chosen here, documented in docs/benchmarks/log.md):
  nominal latency  idle, unshaped link, no point cloud: p50 of /probe/fast over 3 s;
                   "back at nominal" = latency <= max(2 x p50, p50 + 50 ms).
  ramp latency     per step, p99 of /probe/fast <= 2 x max(idle p99 at the same rate,
                   floor); floor 15 ms (LINKS_IDLE_P99_FLOOR_MS): on a shared 2-core
                   machine the idle p99 alone ranges 2-25 ms with the load; 2 x a 1 ms
                   baseline would test the OS scheduler.
  ramp delivery    >= 90 % of /probe/fast per step (it is `latest`, so a sender could
                   pass the latency bound by dropping nearly all of it).
  bulk target      80 % of min(offered, link - 0.2 Mbit/s for the probes and pings).
"""

import argparse
import json
import os
import signal
import sys
import time

import links_scenarios as sc
from harness import Failed, Fleet, Net, Procs


def on_term(_sig, _frame):
    # run.sh's timeout: leave through the `finally` that stops every process.
    raise SystemExit(124)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--hub-ns", required=True)
    ap.add_argument("--robot-ns", required=True)
    ap.add_argument("--hub-ip", required=True)
    ap.add_argument("--robot-dev", required=True)
    ap.add_argument("--bin", required=True)
    ap.add_argument("--python", required=True)
    ap.add_argument("--tmp", required=True)
    ap.add_argument("--out", required=True, help="directory for results.md / results.json")
    a = ap.parse_args()
    signal.signal(signal.SIGTERM, on_term)

    net = Net(a.hub_ns, a.robot_ns, a.hub_ip, a.robot_dev)
    procs = Procs(a.tmp)
    fleet = Fleet(net, procs, a.bin, a.python, a.tmp)
    wanted = os.environ.get("LINKS_SCENARIOS", "1 2 3 4 5 6 7 8 9 10 11").split()
    results = {}
    started = time.monotonic()
    try:
        fleet.mint_tokens()
        fleet.start_hub()
        sc.detect_outbox(fleet, os.environ.get("LINKS_OUTBOX", "auto"))
        print(f"hub on port {fleet.hub_port} ({a.hub_ns}); agent outbox: "
              f"{'on' if fleet.outbox else 'off (binary refuses the key)'}", flush=True)
        nominal = sc.baseline(fleet)
        results["0 idle baseline"] = nominal["rows"]
        for key, name, fn in sc.SCENARIOS:
            if key not in wanted:
                continue
            print(f"\n== scenario {key}: {name}", flush=True)
            t0 = time.monotonic()
            rows = run_scenario(key, fn, fleet, nominal)
            missed = timing_misses(rows)
            if missed:
                # Measured again once; the first attempt's misses stay in the table.
                print(f"   timing rows missed their targets ({len(missed)}); scenario {key} "
                      "runs once more", flush=True)
                rows = run_again(key, fn, fleet, nominal) + [
                    (f"first attempt: {fig}", measured, target, None)
                    for fig, measured, target, _ in missed]
            results[f"{key} {name}"] = rows
            print(f"   ({time.monotonic() - t0:.0f} s)", flush=True)
    except Failed as e:
        print(f"ERROR: setup: {e}", file=sys.stderr, flush=True)
        results["setup"] = [("ERROR (harness)", str(e).splitlines()[0], "runs", False)]
    finally:
        procs.stop_all()
    ok = report(results, a.out, fleet, time.monotonic() - started)
    return 0 if ok else 1


# Rows that time the machine as much as fleetlink: a latency percentile, a recovery or a
# close within a deadline, a share delivered while two other suites share the two cores.
# A scenario whose only failed rows are of these runs once more, and its second attempt
# decides; a row of what was delivered (missing, duplicated, reordered, the outage's
# messages) is never measured again, so a loss is never retried away.
TIMING = ("recovery of /probe/fast", "uplink alive after", "/probe/fast latency",
          "/probe/fast delivered", "/robot1/points delivered", "trickling connections closed",
          "kept receiving /probe/fast", "new client during the attack")


def timing_misses(rows):
    """The failed rows, if every one of them is a timing row (else none: not retried)."""
    failed = [r for r in rows if r[3] is False]
    if failed and all(any(t in r[0] for t in TIMING) for r in failed):
        return failed
    return []


def run_scenario(key, fn, fleet, nominal):
    """One scenario's rows; a harness failure is an ERROR row. The link and the processes
    are put back as they were afterwards, whatever happened."""
    try:
        return fn(fleet, nominal)
    except Failed as e:
        print(f"ERROR: scenario {key}: {e}", file=sys.stderr, flush=True)
        return [("ERROR (harness)", str(e).splitlines()[0], "runs", False)]
    finally:
        sc.restore(fleet)


def run_again(key, fn, fleet, nominal):
    """The scenario once more, its peers' logs in a directory of their own (they are named
    by the scenario's tags, and the first attempt's would be counted again)."""
    base = fleet.tmp
    fleet.tmp = os.path.join(base, f"again-{key}")
    os.makedirs(fleet.tmp, exist_ok=True)
    try:
        return run_scenario(key, fn, fleet, nominal)
    finally:
        fleet.tmp = base


def report(results, out, fleet, secs):
    lines = ["| scenario | figure | measured | target | |", "|---|---|---|---|---|"]
    all_ok = True
    for scen, rows in results.items():
        for figure, measured, target, ok in rows:
            mark = "ok" if ok is True else ("info" if ok is None else "FAIL")
            if ok is False:
                all_ok = False
            lines.append(f"| {scen} | {figure} | {measured} | {target} | {mark} |")
    # The machine's load matters: latencies and the agent's pacing react to CPU
    # contention, so a failing run is read next to it.
    with open("/proc/loadavg") as f:
        load = " ".join(f.read().split()[:3])
    head = (f"bad-links suite, {time.strftime('%Y-%m-%d %H:%M:%S')}, {secs:.0f} s, "
            f"outbox {'on' if fleet.outbox else 'off'}, load average {load}, binary {fleet.bin}")
    table = "\n".join(lines)
    print("\n" + head + "\n" + table, flush=True)
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "results.md"), "w") as f:
        f.write(head + "\n\n" + table + "\n")
    with open(os.path.join(out, "results.json"), "w") as f:
        json.dump({"header": head, "results": {k: [list(r) for r in v] for k, v in results.items()}}, f, indent=1)
    print(f"\nresults written to {out}/results.md", flush=True)
    print("PASS: bad-links suite" if all_ok else "FAIL: bad-links suite (see the rows marked FAIL)", flush=True)
    return all_ok


if __name__ == "__main__":
    sys.exit(main())
