#!/usr/bin/env python3
"""Checks the suite's own measurements on made-up records, so a FAIL of the suite is a
measured outcome and not a counting mistake. run.sh runs it first (no root needed)."""

import sys

from harness import Rx, reliable_audit
from links_scenarios import bulk_rate, recovery, recovery_ratio

S = 1_000_000_000
MS = 1_000_000


def fast_records(t_up, stall_until, n=300):
    """50 Hz /probe/fast from 2 s before link-up; nothing gets through until
    `stall_until`, when the backlog arrives at once; 1 ms latency after that."""
    out = []
    for i in range(n):
        sent = t_up - 2 * S + i * 20 * MS
        recv = sent + MS if sent >= stall_until else stall_until
        out.append(Rx("fast", recv, i, sent))
    return out


def main():
    t_up = 100 * S
    rx = fast_records(t_up, t_up + 3 * S)
    rec = recovery(rx, t_up, 51, rx[-1].sent)
    assert rec is not None and abs(rec - 3.0) < 0.03, f"recovery after a 3 s stall: {rec}"
    cut = [r for r in rx if r.sent < t_up + S]  # stalled for good: nothing sent later arrives
    assert recovery(cut, t_up, 51, rx[-1].sent) is None, "a stalled uplink counts as recovered"
    rx = fast_records(t_up, 0)
    rec = recovery(rx, t_up, 51, rx[-1].sent)
    assert rec is not None and rec < 0.03, f"recovery of an unbroken link: {rec}"

    assert recovery_ratio(3.0, 0.2, 30) == (15.0, False)
    assert recovery_ratio(None, 0.5, 30) == (60.0, True), "a direct client that never recovered"
    assert recovery_ratio(1.0, 0.0, 30) == (50.0, False), "fleetlink's 0 s is floored at one period"
    assert recovery_ratio(1.0, None, 30) == (None, False)

    a = reliable_audit([1, 2, 3, 4, 5], [Rx("reliable", 0, s, 0) for s in (1, 3, 2, 3, 5)])
    assert (a["missing"], a["duplicated"], a["reordered"]) == (1, 1, 1), a
    a = reliable_audit([1, 2, 3], [Rx("reliable", 0, s, 0) for s in (1, 2, 3)])
    assert (a["missing"], a["duplicated"], a["reordered"]) == (0, 0, 0), a

    clouds = [(int(i * 0.4 * S), 213_000) for i in range(30)]  # 4.26 Mbit/s, steady
    got = bulk_rate(clouds, int(2.1 * S), 7 * S, 3.0)
    assert abs(got - 4.26) < 0.01, f"steady bulk rate: {got}"
    got = bulk_rate(clouds[:12], int(2.1 * S), 7 * S, 3.0)  # stops at 4.4 s
    assert got < 3.0, f"a bulk flow that stops mid-step still meets its target: {got}"
    assert bulk_rate([], 0, S, 3.0) == 0.0
    print("selftest: measurement helpers ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
