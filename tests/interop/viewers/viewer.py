"""The viewers of the viewers suite, each a real client in a process of its own (so the
driver can freeze it with SIGSTOP or cut its link):

  rosbridge  roslibpy subscribing to a topic;
  websockets Python `websockets` (its own background thread answers pings) subscribing
             to a topic as JSON.

Each writes one line per message to --log: `msg <count> <delay_s>`, the delay being the
time since the message's header stamp (the same clock: every namespace shares it), and
`closed <reason>` when its connection ends. Runs until killed.
"""

import argparse
import signal
import sys
import time
import urllib.parse


def open_log(path):
    return open(path, "a", buffering=1, encoding="utf-8")


def delay_of(msg):
    stamp = msg.get("header", {}).get("stamp", {})
    sec = stamp.get("sec", stamp.get("secs", 0))
    nsec = stamp.get("nanosec", stamp.get("nsecs", 0))
    if not sec:
        return 0.0
    return time.time() - (sec + nsec / 1e9)


def run_rosbridge(a, log):
    import roslibpy

    u = urllib.parse.urlparse(a.url)
    token = urllib.parse.parse_qs(u.query).get("token", [None])[0]
    headers = {"Authorization": f"Bearer {token}"} if token else None
    ros = roslibpy.Ros(host=u.hostname, port=u.port, headers=headers)
    ros.on("close", lambda *_: log.write("closed by the server\n"))
    ros.run(timeout=10)
    n = [0]

    def on_msg(m):
        n[0] += 1
        log.write(f"msg {n[0]} {delay_of(m):.3f}\n")

    roslibpy.Topic(ros, a.topic, a.type).subscribe(on_msg)
    while True:
        time.sleep(1)


def run_websockets(a, log):
    import json

    from websockets.sync.client import connect

    # Its own keepalive off: the hub's answer to a client's ping waits behind what the
    # hub queued before it too, and `websockets` would close a slow link itself after
    # 20 s (browsers send no pings). Its background thread still answers the hub's.
    with connect(a.url, max_size=None, open_timeout=10, ping_interval=None) as ws:
        ws.send(json.dumps({"op": "subscribe", "topic": a.topic, "type": a.type}))
        n = 0
        try:
            for frame in ws:
                op = json.loads(frame)
                if op.get("op") != "publish":
                    continue
                n += 1
                log.write(f"msg {n} {delay_of(op['msg']):.3f}\n")
        except Exception as e:  # the connection's end, whatever the library calls it
            log.write(f"closed {type(e).__name__}: {e}\n")
            return
        log.write("closed by the server\n")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("kind", choices=["rosbridge", "websockets"])
    p.add_argument("--url", required=True)
    p.add_argument("--topic", required=True)
    p.add_argument("--type", default="sensor_msgs/msg/PointCloud2")
    p.add_argument("--log", required=True)
    a = p.parse_args()
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(0))
    log = open_log(a.log)
    {"rosbridge": run_rosbridge, "websockets": run_websockets}[a.kind](a, log)


if __name__ == "__main__":
    main()
