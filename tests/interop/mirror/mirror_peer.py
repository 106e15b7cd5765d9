"""ROS 2 nodes (Cyclone DDS, ROS 2 names and CDR) on both sides of a mirror, and a look
at the hub's topic listing. Modes:

  robot-listen OUT SECS   the robot's graph: a reader of /map (nav_msgs/OccupancyGrid);
                          prints "ready", writes what it got to OUT as JSON.
  cloud-nodes OUT SECS    the cloud's graph: two nodes (participants) reading /scan
                          (sensor_msgs/LaserScan), the first also publishing /map every
                          200 ms; ends when both have 20 scans (or SECS pass) and writes
                          OUT as JSON.
  hub-topic URL TOKEN NAME  prints the hub's entry for topic NAME (GET /api/v1/topics)
                          as JSON, or null.
"""
import dataclasses
import json
import os
import sys
import threading
import time
import urllib.request

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "ros2"))

from cyclonedds.idl import IdlStruct  # noqa: E402
from cyclonedds.idl.types import float32, float64, int8, sequence, uint32  # noqa: E402

import ros2_dds as D  # noqa: E402
import ros2_types as T  # noqa: E402


@dataclasses.dataclass
class Point(IdlStruct, typename=T.dds_name("geometry_msgs/msg/Point")):
    x: float64
    y: float64
    z: float64


@dataclasses.dataclass
class Quaternion(IdlStruct, typename=T.dds_name("geometry_msgs/msg/Quaternion")):
    x: float64
    y: float64
    z: float64
    w: float64


@dataclasses.dataclass
class Pose(IdlStruct, typename=T.dds_name("geometry_msgs/msg/Pose")):
    position: Point
    orientation: Quaternion


@dataclasses.dataclass
class MapMetaData(IdlStruct, typename=T.dds_name("nav_msgs/msg/MapMetaData")):
    map_load_time: T.Time
    resolution: float32
    width: uint32
    height: uint32
    origin: Pose


@dataclasses.dataclass
class OccupancyGrid(IdlStruct, typename=T.dds_name("nav_msgs/msg/OccupancyGrid")):
    header: T.Header
    info: MapMetaData
    data: sequence[int8]


WIDTH, HEIGHT = 16, 8


def a_map(n):
    """The cloud node's map number n: a WIDTH x HEIGHT grid, cell i = (i + n) % 100."""
    return OccupancyGrid(
        header=T.Header(stamp=D.now(), frame_id="map"),
        info=MapMetaData(
            map_load_time=D.now(), resolution=0.05, width=WIDTH, height=HEIGHT,
            origin=Pose(position=Point(x=-1.0, y=-2.0, z=0.0),
                        orientation=Quaternion(x=0.0, y=0.0, z=0.0, w=1.0)),
        ),
        data=[(i + n) % 100 for i in range(WIDTH * HEIGHT)],
    )


def robot_listen(out, secs):
    node = D.Node()
    got = []
    lock = threading.Lock()

    def on_map(m):
        with lock:
            got.append({"width": m.info.width, "height": m.info.height, "frame": m.header.frame_id,
                        "resolution": round(m.info.resolution, 4), "origin_y": m.info.origin.position.y,
                        "data": list(m.data)})

    node.reader(D.topic_name("/map"), OccupancyGrid, on_map)
    print("ready", flush=True)
    deadline = time.monotonic() + secs
    while time.monotonic() < deadline and not os.path.exists(out + ".stop"):
        time.sleep(0.1)
    with lock:
        json.dump({"maps": got}, open(out, "w"))


def cloud_nodes(out, secs):
    scans = [[], []]
    lock = threading.Lock()
    nodes = [D.Node(), D.Node()]
    for i, node in enumerate(nodes):
        def on_scan(s, i=i):
            with lock:
                scans[i].append(len(s.ranges))
        node.reader(D.topic_name("/scan"), T.LaserScan, on_scan)
    maps = nodes[0].writer(D.topic_name("/map"), OccupancyGrid)
    print("ready", flush=True)
    deadline = time.monotonic() + secs
    n = 0
    while time.monotonic() < deadline:
        maps.write(a_map(n))
        n += 1
        with lock:
            if min(len(s) for s in scans) >= 20:
                break
        time.sleep(0.2)
    with lock:
        json.dump({"scans": [len(s) for s in scans], "ranges": [sorted(set(s)) for s in scans],
                   "maps_sent": n}, open(out, "w"))


def hub_topic(url, token, name):
    req = urllib.request.Request(f"{url}/api/v1/topics", headers={"Authorization": f"Bearer {token}"})
    with urllib.request.urlopen(req, timeout=5) as r:
        topics = json.load(r)["topics"]
    print(json.dumps(next((t for t in topics if t["name"] == name), None)))


if __name__ == "__main__":
    mode, args = sys.argv[1], sys.argv[2:]
    if mode == "robot-listen":
        robot_listen(args[0], float(args[1]))
    elif mode == "cloud-nodes":
        cloud_nodes(args[0], float(args[1]))
    elif mode == "hub-topic":
        hub_topic(*args)
    else:
        sys.exit(f"unknown mode {mode}")
