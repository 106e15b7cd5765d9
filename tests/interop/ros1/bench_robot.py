"""The robot side of the ROS 1 bridging benchmark (scripts/bench-ros1.sh runs it with
Debian's /usr/bin/python3, where rospy lives).

  publish   a rospy node writing sensor_msgs/PointCloud2 on /points at --hz, --points
            points of 16 bytes (x, y, z, intensity), until --seconds pass or SIGTERM;
            header.stamp = the wall clock just before publish(). The cloud's bytes are
            built once, as a driver reuses its buffer; rospy serializes each message in
            publish(). At the end it prints how long publish() took after the stamp.
  sub       a rospy subscriber on the robot: the latency floor (no bridge at all).

Latency figures are printed as one JSON line: {"n", "p50_ms", "p99_ms", "max_ms"}.
"""
import argparse
import json
import signal
import sys
import time

import rospy
from sensor_msgs.msg import PointCloud2, PointField


def summary(lat):
    lat = sorted(lat)
    if not lat:
        return {"n": 0}
    pick = lambda q: round(lat[min(len(lat) - 1, int(q * len(lat)))] * 1000, 2)
    return {"n": len(lat), "p50_ms": pick(0.5), "p99_ms": pick(0.99), "max_ms": round(lat[-1] * 1000, 2)}


def publish(args):
    rospy.init_node("bench_points", disable_signals=True)
    pub = rospy.Publisher("/points", PointCloud2, queue_size=10)
    msg = PointCloud2()
    msg.header.frame_id = "lidar"
    msg.height, msg.width = 1, args.points
    msg.fields = [PointField(n, 4 * i, PointField.FLOAT32, 1) for i, n in enumerate(["x", "y", "z", "intensity"])]
    msg.is_bigendian, msg.point_step, msg.row_step, msg.is_dense = False, 16, 16 * args.points, True
    msg.data = bytes(range(256)) * (args.points * 16 // 256) + bytes(args.points * 16 % 256)
    # SIGTERM ends the run early (the bench stops it when its clients are done).
    stop = []
    signal.signal(signal.SIGTERM, lambda *_: stop.append(1))
    print("publish ready", flush=True)
    period = 1.0 / args.hz
    end = time.time() + args.seconds
    nxt = time.time()
    sent = 0
    took = []
    while time.time() < end and not stop and not rospy.is_shutdown():
        msg.header.seq = sent
        msg.header.stamp = rospy.Time.now()
        pub.publish(msg)
        # Serializing and queueing after the stamp: inside every latency below, and the
        # publisher's doing, not a bridge's.
        took.append(time.time() - msg.header.stamp.to_sec())
        sent += 1
        nxt += period
        time.sleep(max(0.0, nxt - time.time()))
    print(json.dumps({"sent": sent, "publish": summary(took[5:])}), flush=True)


def sub(args):
    lat = []
    rospy.init_node("bench_floor", disable_signals=True)
    rospy.Subscriber("/points", PointCloud2, lambda m: lat.append(time.time() - m.header.stamp.to_sec()))
    print("sub ready", flush=True)
    time.sleep(args.seconds)
    print(json.dumps(summary(list(lat)[args.skip:])), flush=True)


def main():
    p = argparse.ArgumentParser()
    sub_p = p.add_subparsers(dest="mode", required=True)
    a = sub_p.add_parser("publish")
    a.add_argument("--points", type=int, default=65536)
    a.add_argument("--hz", type=float, default=10)
    a.add_argument("--seconds", type=float, default=30)
    a = sub_p.add_parser("sub")
    a.add_argument("--seconds", type=float, default=30)
    a.add_argument("--skip", type=int, default=5, help="first messages left out (warm-up)")
    args = p.parse_args()
    publish(args) if args.mode == "publish" else sub(args)


if __name__ == "__main__":
    sys.exit(main())
