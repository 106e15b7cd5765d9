"""TLS interop check: Python's own TLS stack and roslibpy against a fleetlink hub on wss://.

1. https://ADDR/healthz with only the test CA trusted (ssl module): the hub's
   certificate chain and its 127.0.0.1 SAN verify.
2. roslibpy over wss://, the hub's certificate verified against the test CA (roslibpy's
   default Twisted context does not verify, so the connector is given one that does),
   the operator token in the Authorization header: /rosapi/topics lists the robot's
   topic, and a message of the robot's simulated odometry arrives.

Exits non-zero with a FAIL line on the first problem. Every wait is bounded.
"""

import argparse
import ssl
import sys
import threading
import urllib.request

import roslibpy
import roslibpy.comm.comm_autobahn as comm
from autobahn.twisted.websocket import connectWS
from twisted.internet import ssl as tssl

TIMEOUT = 15


def fail(msg):
    print(f"FAIL: {msg}", file=sys.stderr)
    sys.exit(1)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--addr", required=True, help="HOST:PORT of the hub")
    ap.add_argument("--ca", required=True, help="CA certificate (PEM) the hub's chains to")
    ap.add_argument("--token", required=True)
    ap.add_argument("--robot", required=True)
    a = ap.parse_args()
    host, port = a.addr.rsplit(":", 1)

    ctx = ssl.create_default_context(cafile=a.ca)
    with urllib.request.urlopen(f"https://{a.addr}/healthz", context=ctx, timeout=TIMEOUT) as r:
        if r.status != 200:
            fail(f"/healthz over https: {r.status}")
    print("ok: https /healthz verified against the test CA")

    with open(a.ca, "rb") as f:
        trust = tssl.Certificate.loadPEM(f.read())
    options = tssl.optionsForClientTLS("localhost", trustRoot=trust)
    comm.connectWS = lambda factory: connectWS(factory, contextFactory=options)

    ros = roslibpy.Ros(host=host, port=int(port), is_secure=True,
                       headers={"Authorization": f"Bearer {a.token}"})
    try:
        ros.run(timeout=TIMEOUT)
    except Exception as e:
        fail(f"roslibpy wss connect: {e}")
    if not ros.is_connected:
        fail("roslibpy wss: not connected")
    print("ok: roslibpy connected over wss://")

    want = f"/{a.robot}/odom"
    try:
        topics = ros.get_topics()  # blocking; roslibpy bounds it with its rosapi timeout
    except Exception as e:
        fail(f"/rosapi/topics over wss: {e}")
    if want not in topics:
        fail(f"/rosapi/topics over wss does not list {want}: {topics}")
    print(f"ok: /rosapi/topics lists {want}")

    got = threading.Event()
    sub = roslibpy.Topic(ros, want, "nav_msgs/msg/Odometry")
    sub.subscribe(lambda m: got.set())
    if not got.wait(TIMEOUT):
        fail(f"no message on {want} over wss within {TIMEOUT} s")
    sub.unsubscribe()
    print(f"ok: received {want} over wss://")
    ros.close()


if __name__ == "__main__":
    main()
