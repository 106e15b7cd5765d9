"""The robot's ROS 1 side of the ros1 interop suite (run with Debian's /usr/bin/python3).

Modes:
  graph OUT   the robot's node /robot_graph: publishes /scan (LaserScan), /points
              (PointCloud2, 100k points), /custom (fltest_msgs/Custom, a type that exists
              only in the suite's temporary package) and /chatter; subscribes /cmd_vel and
              /chatter; serves /set_enabled (std_srvs/SetBool) and /add_two_ints
              (example_interfaces/AddTwoInts). Writes what it received to OUT (JSON) every
              0.2 s.
  after       a node started after roscore restarted: publishes /after_restart.
  oneshot     a node subscribed to /oneshot before the hub publishes it once: exit 0
              when that single message arrived.
  wrongtype   a node that subscribes /cmd_vel with the wrong type (std_msgs/String) for
              3 s: the agent must refuse it and keep serving the right subscribers.
  camera S    a camera driver: /camera/image_raw, sensor_msgs/Image 640x480 rgb8 at
              15 Hz for S seconds, the test scene of the video suite
              (tests/interop/video/video_peer.py scene(), a function of the stamp).

Every published value is a pure function of its index, so the hub side checks equality
without talking to this process (expected values: hub_peer.py builds the same ones).
"""
import json
import os
import struct
import sys
import threading

import rospy
from geometry_msgs.msg import Twist
from sensor_msgs.msg import LaserScan, PointCloud2, PointField
from std_msgs.msg import String
from std_srvs.srv import SetBool, SetBoolResponse

ONESHOT = "only once"  # the hub's single message on /<robot>/oneshot (hub_peer.py)

POINTS = 100_000


def scan_msg():
    m = LaserScan()
    m.header.frame_id = "laser"
    m.header.stamp = rospy.Time(1700000000, 250)
    m.angle_min, m.angle_max, m.angle_increment = -1.5, 1.5, 3.0 / 359
    m.range_min, m.range_max = 0.1, 30.0
    m.ranges = [1.0 + 0.25 * (i % 40) for i in range(360)]
    m.intensities = [float(i % 7) for i in range(360)]
    return m


def cloud_msg():
    m = PointCloud2()
    m.header.frame_id = "lidar"
    m.height, m.width = 1, POINTS
    m.fields = [PointField(n, 4 * i, PointField.FLOAT32, 1) for i, n in enumerate("xyz")]
    m.is_bigendian, m.point_step, m.row_step, m.is_dense = False, 12, 12 * POINTS, True
    m.data = b"".join(struct.pack("<fff", i * 0.5, -i * 0.25, 2.0) for i in range(POINTS))
    return m


def custom_msg(n):
    from fltest_msgs.msg import Custom, Inner

    m = Custom()
    m.label = f"custom-{n}"
    m.values = [n, -n, 7]
    m.stamp = rospy.Time(12, 34)
    m.inner = Inner(weight=0.5, ok=True)
    m.more = [Inner(weight=1.5, ok=False), Inner(weight=2.5, ok=True)]
    return m


def graph(out_path):
    from example_interfaces.srv import AddTwoInts, AddTwoIntsResponse

    rospy.init_node("robot_graph", disable_signals=True)
    got = {"cmd_vel": [], "chatter": {}, "set_enabled": []}
    lock = threading.Lock()

    def on_cmd(m):
        with lock:
            got["cmd_vel"].append(m.linear.x)

    def on_chatter(m):
        with lock:
            got["chatter"][m.data] = got["chatter"].get(m.data, 0) + 1

    def on_set(req):
        with lock:
            got["set_enabled"].append(req.data)
        return SetBoolResponse(success=req.data, message=f"enabled={req.data}")

    rospy.Subscriber("/cmd_vel", Twist, on_cmd)
    rospy.Subscriber("/chatter", String, on_chatter)
    rospy.Service("/set_enabled", SetBool, on_set)
    rospy.Service("/add_two_ints", AddTwoInts, lambda r: AddTwoIntsResponse(sum=r.a + r.b))
    scan = rospy.Publisher("/scan", LaserScan, queue_size=5)
    cloud = rospy.Publisher("/points", PointCloud2, queue_size=2)
    custom = rospy.Publisher("/custom", __import__("fltest_msgs.msg", fromlist=["Custom"]).Custom, queue_size=5)
    chatter = rospy.Publisher("/chatter", String, queue_size=50)
    scan_m, cloud_m = scan_msg(), cloud_msg()
    print("graph ready", flush=True)
    rate = rospy.Rate(5)
    n = 0
    while not rospy.is_shutdown():
        n += 1
        scan.publish(scan_m)
        custom.publish(custom_msg(n))
        chatter.publish(String(data=f"robot-{n}"))
        if n % 3 == 0:
            cloud.publish(cloud_m)
        with lock:
            text = json.dumps(got)
        tmp = out_path + ".tmp"
        with open(tmp, "w") as f:
            f.write(text)
        os.replace(tmp, out_path)
        rate.sleep()


def after():
    rospy.init_node("after_restart", disable_signals=True)
    pub = rospy.Publisher("/after_restart", String, queue_size=5)
    print("after ready", flush=True)
    rate = rospy.Rate(5)
    n = 0
    while not rospy.is_shutdown():
        n += 1
        pub.publish(String(data=f"after-{n}"))
        rate.sleep()


def oneshot():
    """A node waiting for /oneshot, which the hub publishes once, later: it must get
    that one message, although the agent registers the publication only when the
    message comes and a ROS 1 subscriber connects only after the master tells it."""
    rospy.init_node("oneshot_listener", disable_signals=True)
    got, arrived = [], threading.Event()
    rospy.Subscriber("/oneshot", String, lambda m: (got.append(m.data), arrived.set()))
    print("oneshot ready", flush=True)
    arrived.wait(20)
    if got[:1] != [ONESHOT]:
        print(f"FAIL: /oneshot: got {got}, want [{ONESHOT!r}]", flush=True)
        sys.exit(1)
    print(f"ok: a rospy subscriber waiting for /oneshot got the hub's single message {ONESHOT!r}", flush=True)


IDLE_POINTS = 50_000  # 16 bytes each: an 800 kB cloud at 10 Hz


def idle_cloud():
    """A lidar driver nobody at the hub watches: /idle_points, an 800 kB PointCloud2 at
    10 Hz. The agent should stop reading it (its connection to this node closes)."""
    rospy.init_node("idle_cloud", disable_signals=True)
    pub = rospy.Publisher("/idle_points", PointCloud2, queue_size=2)
    m = PointCloud2()
    m.header.frame_id = "lidar"
    m.height, m.width = 1, IDLE_POINTS
    m.fields = [PointField(n, 4 * i, PointField.FLOAT32, 1) for i, n in enumerate(["x", "y", "z", "intensity"])]
    m.is_bigendian, m.point_step, m.row_step, m.is_dense = False, 16, 16 * IDLE_POINTS, True
    m.data = b"".join(struct.pack("<ffff", (i % 500) * 0.02, (i // 500) * 0.02, 1.0, 7.0) for i in range(IDLE_POINTS))
    print("idle_cloud ready", flush=True)
    rate = rospy.Rate(10)
    while not rospy.is_shutdown():
        m.header.stamp = rospy.Time.now()
        pub.publish(m)
        rate.sleep()


def camera(seconds):
    """The video suite's scene, built without numpy (Debian's rospy Python has none):
    the gradient once, then the moving box pasted row by row into a copy per frame."""
    from sensor_msgs.msg import Image
    w, h = 640, 480
    base = bytearray(w * h * 3)
    row = bytearray(w * 3)
    for x in range(w):
        row[3 * x] = x * 255 // w
        row[3 * x + 2] = 96
    for y in range(h):
        row[1::3] = bytes([y * 255 // h]) * w
        base[y * w * 3:(y + 1) * w * 3] = row
    box = bytes((250, 250, 240)) * 96
    rospy.init_node("camera", disable_signals=True)
    pub = rospy.Publisher("/camera/image_raw", Image, queue_size=2)
    m = Image(height=h, width=w, encoding="rgb8", is_bigendian=0, step=w * 3)
    m.header.frame_id = "camera"
    print("camera ready", flush=True)
    rate = rospy.Rate(15)
    end = rospy.Time.now() + rospy.Duration(seconds)
    n = 0
    while not rospy.is_shutdown() and rospy.Time.now() < end:
        stamp = rospy.Time.now()
        t = (stamp.to_nsec() // 1_000_000) % 4000
        bx = t * (w - 96) // 4000
        img = bytearray(base)
        for y in range(160, 320):
            at = (y * w + bx) * 3
            img[at:at + 96 * 3] = box
        m.header.stamp = stamp
        m.data = bytes(img)
        pub.publish(m)
        n += 1
        rate.sleep()
    print(f"camera published {n}", flush=True)


def connected_to(node, topic, peer):
    """Whether `node`'s bus (its slave API's getBusInfo, as `rosnode info` reads it) has a
    connection on `topic` with `peer`. Prints yes/no."""
    import xmlrpc.client
    import rosgraph
    api = rosgraph.Master("/probe").lookupNode(node)
    code, _, info = xmlrpc.client.ServerProxy(api).getBusInfo("/probe")
    hit = code == 1 and any(c[1] == peer and c[4] == topic for c in info)
    print("yes" if hit else "no", flush=True)


def wrongtype():
    rospy.init_node("wrong_type", disable_signals=True)
    rospy.Subscriber("/cmd_vel", String, lambda m: print(f"unexpected: {m}", flush=True))
    print("wrongtype ready", flush=True)
    rospy.sleep(3.0)


if __name__ == "__main__":
    if sys.argv[1] == "graph":
        graph(sys.argv[2])
    elif sys.argv[1] == "after":
        after()
    elif sys.argv[1] == "oneshot":
        oneshot()
    elif sys.argv[1] == "wrongtype":
        wrongtype()
    elif sys.argv[1] == "camera":
        camera(float(sys.argv[2]))
    elif sys.argv[1] == "idle_cloud":
        idle_cloud()
    elif sys.argv[1] == "connected":
        connected_to(sys.argv[2], sys.argv[3], sys.argv[4])
    else:
        sys.exit(f"unknown mode {sys.argv[1]}")
