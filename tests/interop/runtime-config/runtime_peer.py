"""The robot's ROS 2 graph and the hub's clients for the runtime configuration suite.
Modes:

  publish TOPIC...        a Cyclone DDS node writing std_msgs/String on each ROS topic at
                          10 Hz (ROS 2 names and CDR), and serving /add_two_ints
                          (example_interfaces, rmw_cyclonedds's request/reply topics);
                          prints "ready", runs until killed.
  count URL SECS TOPIC... a roslibpy client of the hub at URL (token in its query)
                          subscribing to each hub topic; once the first of them delivers
                          (at most 30 s), counts for SECS and prints {topic: msg/s} as JSON.
  listen TOPIC SECS       a Cyclone DDS reader of std_msgs/String on the ROS topic for
                          SECS (printing "ready" first): prints how many it got.
  send URL TOPIC SECS     a roslibpy publisher of std_msgs/String on the hub topic, 10 Hz
                          for SECS.
  call URL SERVICE        a roslibpy call of the hub's AddTwoInts service SERVICE with
                          {a: 2, b: 40}: prints the sum, or "failed: WHY".
  api METHOD URL TOKEN [FILE]  an HTTP request (FILE's bytes as its body); prints the
                          status on the first line and the JSON answer on the second.
"""
import json
import os
import sys
import threading
import time
import urllib.error
import urllib.parse
import urllib.request

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "ros2"))


def publish(topics):
    import ros2_dds as D
    import ros2_types as T

    node = D.Node()
    D.ServiceServer(node, "/add_two_ints", T.AddTwoIntsRequest, T.AddTwoIntsResponse,
                    lambda req, reply: reply(sum=req.a + req.b))
    writers = [(t, node.writer(D.topic_name(t), T.String)) for t in topics]
    print("ready", flush=True)
    n = 0
    while True:
        for t, w in writers:
            w.write(T.String(data=f"{t} {n}"))
        n += 1
        time.sleep(0.1)


def count(url, secs, topics):
    import roslibpy

    u = urllib.parse.urlparse(url)
    token = urllib.parse.parse_qs(u.query).get("token", [None])[0]
    ros = roslibpy.Ros(host=u.hostname, port=u.port, headers={"Authorization": f"Bearer {token}"})
    ros.run(timeout=10)
    lock = threading.Lock()
    counts = {t: 0 for t in topics}
    first = threading.Event()

    def on(t):
        def cb(_msg):
            with lock:
                counts[t] += 1
            first.set()

        return cb

    subs = []
    for t in topics:
        s = roslibpy.Topic(ros, t, "std_msgs/String")
        s.subscribe(on(t))
        subs.append(s)
    if not first.wait(30):
        print(json.dumps({t: 0.0 for t in topics}))
        ros.terminate()
        return
    time.sleep(1.0)  # the other topics' readers start too
    with lock:
        start = dict(counts)
    t0 = time.monotonic()
    time.sleep(secs)
    with lock:
        end = dict(counts)
    dt = time.monotonic() - t0
    print(json.dumps({t: round((end[t] - start[t]) / dt, 1) for t in topics}))
    for s in subs:
        s.unsubscribe()
    ros.terminate()


def listen(topic, secs):
    import ros2_dds as D
    import ros2_types as T

    node = D.Node()
    got = [0]
    lock = threading.Lock()

    def on(_s):
        with lock:
            got[0] += 1

    node.reader(D.topic_name(topic), T.String, on)
    print("ready", flush=True)
    time.sleep(secs)
    with lock:
        print(got[0], flush=True)


def send(url, topic, secs):
    import roslibpy

    u = urllib.parse.urlparse(url)
    token = urllib.parse.parse_qs(u.query).get("token", [None])[0]
    ros = roslibpy.Ros(host=u.hostname, port=u.port, headers={"Authorization": f"Bearer {token}"})
    ros.run(timeout=10)
    pub = roslibpy.Topic(ros, topic, "std_msgs/String")
    end = time.monotonic() + secs
    n = 0
    while time.monotonic() < end:
        pub.publish(roslibpy.Message({"data": f"down {n}"}))
        n += 1
        time.sleep(0.1)
    ros.terminate()


def call(url, service):
    import roslibpy

    u = urllib.parse.urlparse(url)
    token = urllib.parse.parse_qs(u.query).get("token", [None])[0]
    ros = roslibpy.Ros(host=u.hostname, port=u.port, headers={"Authorization": f"Bearer {token}"})
    ros.run(timeout=10)
    svc = roslibpy.Service(ros, service, "example_interfaces/srv/AddTwoInts")
    try:
        res = dict(svc.call(roslibpy.ServiceRequest({"a": 2, "b": 40}), timeout=5))
        print(res.get("sum"))
    except Exception as e:  # roslibpy raises for a failed call; say why
        print(f"failed: {e}")
    ros.terminate()


def api(method, url, token, body_file=None):
    body = open(body_file, "rb").read() if body_file else None
    req = urllib.request.Request(url, data=body, method=method)
    req.add_header("Authorization", f"Bearer {token}")
    try:
        with urllib.request.urlopen(req, timeout=20) as r:
            status, text = r.status, r.read()
    except urllib.error.HTTPError as e:
        status, text = e.code, e.read()
    print(status)
    print(json.dumps(json.loads(text or b"null")))


if __name__ == "__main__":
    mode, args = sys.argv[1], sys.argv[2:]
    if mode == "publish":
        publish(args)
    elif mode == "count":
        count(args[0], float(args[1]), args[2:])
    elif mode == "listen":
        listen(args[0], float(args[1]))
    elif mode == "send":
        send(args[0], args[1], float(args[2]))
    elif mode == "call":
        call(*args)
    elif mode == "api":
        api(*args)
    else:
        sys.exit(f"unknown mode {mode}")
