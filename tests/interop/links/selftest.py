#!/usr/bin/env python3
"""Checks the suite's own measurements on made-up records, so a FAIL of the suite is a
measured outcome and not a counting mistake. run.sh runs it first (no root needed)."""

import os
import sys
import tempfile

from harness import Rx, log_time_ns, read_blobs, read_calls, reliable_audit
from links_scenarios import (bulk_rate, first_error, intact_row, offline_row, ok_run, pending_row,
                             recovery, recovery_ratio)

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


def call_records(t_cut, t_dead, t_up, fixed):
    """A caller's log (peers.py caller) at 2 Hz from 10 s before the cut: answered in 2 ms
    before the cut; with `fixed` the calls in flight fail "robot link lost" at `t_dead`,
    those made after it "no_provider" at once, and calls work again from link-up; without,
    nothing made after the cut is answered."""
    lines = []
    for i in range(40):
        sent = t_cut - 10 * S + i * S // 2
        lines.append(f"call {i} {sent}")
        if sent < t_cut:
            lines.append(f"ok {i} {sent + 2 * MS} {{\"success\":true}}")
        elif not fixed:
            continue
        elif sent < t_dead:
            lines.append(f"err {i} {t_dead} robot link lost: robot1 is gone")
        elif sent < t_up:
            lines.append(f"err {i} {sent + MS} no_provider: /robot1/get_status is not offered")
        else:
            lines.append(f"ok {i} {sent + 2 * MS} {{}}")
    with tempfile.NamedTemporaryFile("w", suffix=".calls", delete=False) as f:
        f.write("\n".join(lines) + "\n")
    try:
        return read_calls(f.name)
    finally:
        os.unlink(f.name)


def check_calls():
    t_cut, t_dead, t_up = 100 * S, 102 * S, int(104.2 * S)
    calls = call_records(t_cut, t_dead, t_up, fixed=True)
    assert len(calls) == 40 and calls[3].ok and calls[25].ok is False, calls[:3]
    assert first_error(calls, t_cut, t_up) == t_dead
    row = pending_row("hub", calls, t_cut, t_dead, t_dead + 30 * MS, "the offline listing")
    assert row[3] is True and row[1].startswith("4/4 did"), row
    row = offline_row("hub", calls, t_cut, t_dead, t_up)
    assert row[3] is True and row[1].startswith("4/4 failed"), row  # 102.0 s: in the guard
    first, run = ok_run(calls, t_up)
    assert first.n == 29 and run == 11, (first, run)
    calls[21].answer += S  # one call in flight answered 1 s after the link's death
    assert pending_row("hub", calls, t_cut, t_dead, t_dead, "x")[3] is False
    calls = call_records(t_cut, t_dead, t_up, fixed=False)
    assert first_error(calls, t_cut, t_up) is None
    row = pending_row("hub", calls, t_cut, None, None, "the offline listing")
    assert row[3] is False and "6/6 calls" in row[1], row
    row = offline_row("hub", calls, t_cut, None, t_up)
    assert row[3] is False and row[1].startswith("0/3 failed"), row
    assert ok_run(calls, t_up) == (None, 0)
    t = log_time_ns("2025-11-27T17:48:00.123456Z  WARN fleetlink_agent::uplink: hub link down: x")
    assert t == 1764265680123456000, t


def blob_records(lines):
    with tempfile.NamedTemporaryFile("w", suffix=".sensors", delete=False) as f:
        f.write("\n".join(lines) + "\n")
    try:
        return read_blobs(f.name)
    finally:
        os.unlink(f.name)


def check_blobs():
    """The viewer's copies matched to the publisher's by stamp (peers.py sensors and
    sensorsub logs): one copy with other bytes fails, as does nothing to compare."""
    sent = blob_records([f"cloud {i} {1000 + i} {'ab'[i % 2] * 64} 230400 121000" for i in range(1, 5)]
                        + ["# status {}", "cloud 5 1005 cd"])  # a half-written last line
    assert [b.stamp for b in sent["cloud"]] == [1001, 1002, 1003, 1004] and sent["cloud"][0].zstd1 == 121000
    got = [f"cloud {9000 + i} {1000 + i} {'ab'[i % 2] * 64} 230400" for i in (2, 3)]
    run = {"sent": sent, "got": blob_records(got)}
    row = intact_row("auto", run, "cloud")
    assert row[3] is True and row[1].startswith("2/2 identical (2 received, 4 published)"), row
    run["got"] = blob_records(got + [f"cloud 9004 1004 {'c' * 64} 230400"])
    assert intact_row("auto", run, "cloud")[3] is False, "a copy with other bytes passes"
    run["got"] = blob_records([f"cloud 9009 999 {'a' * 64} 230400"])
    assert intact_row("auto", run, "cloud")[3] is False, "nothing matched passes"


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
    check_calls()
    check_blobs()
    print("selftest: measurement helpers ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
