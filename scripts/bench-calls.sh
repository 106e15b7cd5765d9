#!/usr/bin/env bash
# Service round trips through a real hub and agent (separate processes, loopback):
# starts both from the release binary, then runs `fleetlink bench calls` with their pids
# so the report has the servers' CPU per call and memory. Extra arguments go to the bench
# (e.g. --callers 1,50 --calls 20000 --soak 100000).
#
#   cargo build --release -p fleetlink && scripts/bench-calls.sh --soak 100000
set -euo pipefail
. "$(dirname "$0")/bench-lib.sh"
bench_init calls

robot=robot1
robot_token="$("$bin" admin --data-dir "$tmp/hub" token robot "$robot")"
op_token="$("$bin" admin --data-dir "$tmp/hub" token operator bench --group admin)"
"$bin" hub --listen 127.0.0.1:0 --data-dir "$tmp/hub" >"$tmp/hub.log" 2>&1 &
pids+=($!)
hub_pid=$!
for _ in $(seq 100); do
    hub_addr="$(sed -nE 's/^fleetlink hub listening on ([0-9.:]+)$/\1/p' "$tmp/hub.log")"
    [ -n "$hub_addr" ] && break
    sleep 0.1
done
[ -n "${hub_addr:-}" ] || { cat "$tmp/hub.log" >&2; exit 1; }
cat >"$tmp/agent.yaml" <<EOF
hub: ws://$hub_addr/
name: $robot
token: $robot_token
EOF
"$bin" agent --config "$tmp/agent.yaml" --local-listen 127.0.0.1:0 >"$tmp/agent.log" 2>&1 &
pids+=($!)
agent_pid=$!
for _ in $(seq 100); do
    local_addr="$(sed -nE 's#^  local rosbridge: ws://([0-9.:]+)/$#\1#p' "$tmp/agent.log")"
    [ -n "$local_addr" ] && break
    sleep 0.1
done
[ -n "${local_addr:-}" ] || { cat "$tmp/agent.log" >&2; exit 1; }
echo "hub $hub_addr (pid $hub_pid), agent $robot local ws://$local_addr/ (pid $agent_pid); $(nproc) cores"
"$bin" bench calls --hub "ws://$hub_addr/" --token "$op_token" --local "ws://$local_addr/" \
    --robot "$robot" --hub-pid "$hub_pid" --agent-pid "$agent_pid" "$@"
