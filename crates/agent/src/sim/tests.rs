//! Simulator behaviour on virtual time: rates, determinism, and message shapes checked
//! against the ROS 2 definitions.

use std::collections::BTreeSet;

use base64::Engine;
use base64::engine::general_purpose::STANDARD as BASE64;
use serde_json::Value;

use super::*;
use crate::config::{ImageSim, LaserScanSim, MarkersSim, OdometrySim, PointCloudSim, PoseSim};

const EPOCH_NS: u64 = 1_700_000_000_123_000_000;

/// Drives `sim` like a well-behaved driver: sleep until `next_due`, poll, for `until`.
fn run(sim: &mut Sim, until: Duration) -> Vec<SimMessage> {
    let mut out = Vec::new();
    loop {
        let due = sim.next_due();
        if due >= until {
            return out;
        }
        let before = out.len();
        sim.poll_into(due, &mut out);
        assert!(out.len() > before, "nothing due at next_due {due:?}");
    }
}

fn parse(msg: &SimMessage) -> Value {
    serde_json::from_slice(&msg.json).expect("valid JSON")
}

/// Field names of a JSON object, sorted.
fn keys(v: &Value) -> BTreeSet<&str> {
    v.as_object()
        .expect("object")
        .keys()
        .map(String::as_str)
        .collect()
}

fn set(names: &[&'static str]) -> BTreeSet<&'static str> {
    names.iter().copied().collect()
}

fn check_header(v: &Value, stamp_ns: u64, frame_id: &str) {
    assert_eq!(keys(v), set(&["stamp", "frame_id"]));
    assert_eq!(keys(&v["stamp"]), set(&["sec", "nanosec"]));
    let sec = v["stamp"]["sec"].as_u64().expect("sec");
    let nanosec = v["stamp"]["nanosec"].as_u64().expect("nanosec");
    assert!(nanosec < 1_000_000_000);
    assert_eq!(sec * 1_000_000_000 + nanosec, stamp_ns);
    assert_eq!(v["frame_id"], frame_id);
}

fn check_quaternion(q: &Value) {
    assert_eq!(keys(q), set(&["x", "y", "z", "w"]));
    let n: f64 = ["x", "y", "z", "w"]
        .iter()
        .map(|k| q[k].as_f64().expect("f64").powi(2))
        .sum();
    assert!((n - 1.0).abs() < 1e-9, "quaternion norm² {n}");
}

fn check_pose(p: &Value) {
    assert_eq!(keys(p), set(&["position", "orientation"]));
    assert_eq!(keys(&p["position"]), set(&["x", "y", "z"]));
    check_quaternion(&p["orientation"]);
}

fn all_sensors() -> Sim {
    Sim::new(&SimConfig::default(), "robot1", EPOCH_NS)
}

#[test]
fn topics_follow_the_config() {
    let sim = all_sensors();
    let names: Vec<_> = sim
        .topics()
        .iter()
        .map(|t| (t.name.as_str(), t.type_name))
        .collect();
    assert_eq!(
        names,
        [
            ("/scan", "sensor_msgs/msg/LaserScan"),
            ("/odom", "nav_msgs/msg/Odometry"),
            ("/pose", "geometry_msgs/msg/PoseStamped"),
            ("/points", "sensor_msgs/msg/PointCloud2"),
            (
                "/camera/image/compressed",
                "sensor_msgs/msg/CompressedImage"
            ),
        ]
    );
    assert_eq!(sim.topics()[1].period, Duration::from_millis(50));
    let none = SimConfig {
        laser_scan: None,
        odometry: None,
        pose: None,
        point_cloud: None,
        image: None,
        markers: None,
        ..SimConfig::default()
    };
    let sim = Sim::new(&none, "r", 0);
    assert!(sim.topics().is_empty());
    assert_eq!(sim.next_due(), Duration::MAX);
}

#[test]
fn rates_over_ten_virtual_seconds() {
    let mut sim = all_sensors();
    let msgs = run(&mut sim, Duration::from_secs(10));
    let mut counts = [0usize; 5];
    for m in &msgs {
        counts[m.topic_index] += 1;
    }
    assert_eq!(counts, [100, 200, 100, 50, 100]);
    assert_eq!(sim.skipped(), 0);
    // Stamps are exactly epoch + k × period, increasing per topic.
    let scans: Vec<u64> = msgs
        .iter()
        .filter(|m| m.topic_index == 0)
        .map(|m| m.stamp_ns)
        .collect();
    assert_eq!(scans[0], EPOCH_NS);
    assert!(scans.windows(2).all(|w| w[1] - w[0] == 100_000_000));
}

#[test]
fn late_driver_gets_the_newest_slot_and_a_skip_count() {
    let cfg = SimConfig {
        odometry: Some(OdometrySim::default()),
        ..no_sensors()
    };
    let mut sim = Sim::new(&cfg, "r", 0);
    assert_eq!(sim.poll(Duration::ZERO).len(), 1);
    let late = sim.poll(Duration::from_millis(1020)); // slots 1..=20 due, 20 is newest
    assert_eq!(late.len(), 1);
    assert_eq!(late[0].stamp_ns, 1_000_000_000);
    assert_eq!(sim.skipped(), 19);
    assert_eq!(sim.next_due(), Duration::from_millis(1050));
    assert!(sim.poll(Duration::from_millis(1049)).is_empty());
}

fn no_sensors() -> SimConfig {
    SimConfig {
        laser_scan: None,
        odometry: None,
        pose: None,
        point_cloud: None,
        image: None,
        markers: None,
        ..SimConfig::default()
    }
}

#[test]
fn deterministic_for_a_seed_and_name() {
    let a = run(&mut all_sensors(), Duration::from_secs(2));
    let b = run(&mut all_sensors(), Duration::from_secs(2));
    assert_eq!(a, b);
    // Same output when polled irregularly (late polls skip slots, but what is produced
    // for a slot does not depend on the polling pattern).
    let mut irregular = all_sensors();
    let mut c = Vec::new();
    for ms in [0, 100, 200, 300] {
        irregular.poll_into(Duration::from_millis(ms), &mut c);
    }
    for m in &c {
        assert!(
            a.contains(m),
            "message for topic {} at {} differs",
            m.topic_index,
            m.stamp_ns
        );
    }
    let other_seed = SimConfig {
        seed: 2,
        ..SimConfig::default()
    };
    let d = run(
        &mut Sim::new(&other_seed, "robot1", EPOCH_NS),
        Duration::from_secs(2),
    );
    assert_ne!(a, d);
    let e = run(
        &mut Sim::new(&SimConfig::default(), "robot2", EPOCH_NS),
        Duration::from_secs(2),
    );
    assert_ne!(a, e);
}

#[test]
fn laser_scan_shape() {
    let cfg = SimConfig {
        laser_scan: Some(LaserScanSim {
            ranges: 360,
            ..LaserScanSim::default()
        }),
        frame_prefix: "r1/".into(),
        ..no_sensors()
    };
    let mut sim = Sim::new(&cfg, "r1", EPOCH_NS);
    for m in run(&mut sim, Duration::from_secs(3)) {
        let v = parse(&m);
        assert_eq!(
            keys(&v),
            set(&[
                "header",
                "angle_min",
                "angle_max",
                "angle_increment",
                "time_increment",
                "scan_time",
                "range_min",
                "range_max",
                "ranges",
                "intensities"
            ])
        );
        check_header(&v["header"], m.stamp_ns, "r1/laser");
        let f = |k: &str| v[k].as_f64().unwrap_or_else(|| panic!("{k} is a number"));
        let ranges = v["ranges"].as_array().expect("ranges");
        assert_eq!(ranges.len(), 360);
        let (min, max, inc) = (f("angle_min"), f("angle_max"), f("angle_increment"));
        assert!((min + std::f64::consts::PI).abs() < 1e-6);
        assert!((min + inc * 359.0 - max).abs() < 1e-4);
        assert!((f("scan_time") - 0.1).abs() < 1e-6);
        assert!((f("time_increment") * 360.0 - 0.1).abs() < 1e-6);
        let (rmin, rmax) = (f("range_min"), f("range_max"));
        for r in ranges {
            let r = r.as_f64().expect("range is a number");
            assert!((rmin..=rmax).contains(&r), "range {r}");
        }
        // Inside a 20 m room nothing is farther than the diagonal.
        assert!(ranges.iter().filter_map(Value::as_f64).all(|r| r < 28.5));
        assert_eq!(v["intensities"].as_array().map(Vec::len), Some(0));
    }
}

#[test]
fn odometry_and_pose_shape() {
    let cfg = SimConfig {
        odometry: Some(OdometrySim::default()),
        pose: Some(PoseSim::default()),
        ..no_sensors()
    };
    let mut sim = Sim::new(&cfg, "r1", EPOCH_NS);
    let msgs = run(&mut sim, Duration::from_secs(5));
    let mut prev: Option<(f64, f64, f64)> = None;
    for m in &msgs {
        let v = parse(m);
        if m.topic_index == 1 {
            assert_eq!(keys(&v), set(&["header", "pose"]));
            check_header(&v["header"], m.stamp_ns, "map");
            check_pose(&v["pose"]);
            continue;
        }
        assert_eq!(
            keys(&v),
            set(&["header", "child_frame_id", "pose", "twist"])
        );
        check_header(&v["header"], m.stamp_ns, "odom");
        assert_eq!(v["child_frame_id"], "base_link");
        assert_eq!(keys(&v["pose"]), set(&["pose", "covariance"]));
        assert_eq!(keys(&v["twist"]), set(&["twist", "covariance"]));
        assert_eq!(v["pose"]["covariance"].as_array().map(Vec::len), Some(36));
        assert_eq!(v["twist"]["covariance"].as_array().map(Vec::len), Some(36));
        check_pose(&v["pose"]["pose"]);
        let twist = &v["twist"]["twist"];
        assert_eq!(keys(twist), set(&["linear", "angular"]));
        assert_eq!(keys(&twist["linear"]), set(&["x", "y", "z"]));
        // Twist agrees with motion: distance travelled ≈ speed × dt.
        let p = &v["pose"]["pose"]["position"];
        let (x, y) = (p["x"].as_f64().expect("x"), p["y"].as_f64().expect("y"));
        let speed = twist["linear"]["x"].as_f64().expect("speed");
        if let Some((px, py, pspeed)) = prev {
            let moved = ((x - px).powi(2) + (y - py).powi(2)).sqrt();
            let expected = 0.5 * (speed + pspeed) * 0.05;
            assert!(
                (moved - expected).abs() < 1e-3,
                "moved {moved}, expected {expected}"
            );
        }
        prev = Some((x, y, speed));
    }
}

#[test]
fn point_cloud_shape_and_data() {
    for points in [10_000, 1_001, 7] {
        let cfg = SimConfig {
            point_cloud: Some(PointCloudSim {
                points,
                ..PointCloudSim::default()
            }),
            ..no_sensors()
        };
        let mut sim = Sim::new(&cfg, "r1", EPOCH_NS);
        let m = sim.generate(0, Duration::from_secs(3));
        let v = parse(&m);
        assert_eq!(
            keys(&v),
            set(&[
                "header",
                "height",
                "width",
                "fields",
                "is_bigendian",
                "point_step",
                "row_step",
                "data",
                "is_dense"
            ])
        );
        check_header(&v["header"], m.stamp_ns, "lidar");
        assert_eq!(v["height"], 1);
        assert_eq!(v["width"], points);
        assert_eq!(v["point_step"], 16);
        assert_eq!(v["row_step"], points * 16);
        assert_eq!(v["is_bigendian"], false);
        assert_eq!(v["is_dense"], true);
        let fields = v["fields"].as_array().expect("fields");
        let expected = [("x", 0), ("y", 4), ("z", 8), ("intensity", 12)];
        assert_eq!(fields.len(), 4);
        for (f, (name, offset)) in fields.iter().zip(expected) {
            assert_eq!(keys(f), set(&["name", "offset", "datatype", "count"]));
            assert_eq!(
                (f["name"].as_str(), f["offset"].as_u64()),
                (Some(name), Some(offset))
            );
            assert_eq!(
                (f["datatype"].as_u64(), f["count"].as_u64()),
                (Some(7), Some(1))
            );
        }
        let data = BASE64
            .decode(v["data"].as_str().expect("data is a string"))
            .expect("base64");
        assert_eq!(data.len(), points as usize * 16);
        // Every point is inside the room and finite; z between floor and ceiling
        // (relative to a sensor 0.4 m up), intensities positive.
        for p in data.chunks_exact(16) {
            let f = |i: usize| f32::from_le_bytes([p[i], p[i + 1], p[i + 2], p[i + 3]]);
            let (x, y, z, intensity) = (f(0), f(4), f(8), f(12));
            assert!(x.is_finite() && y.is_finite() && (x * x + y * y).sqrt() < 28.5);
            assert!((-0.45..=2.65).contains(&z), "z {z}");
            assert!(intensity > 0.0);
        }
    }
}

/// The JPEG in a `CompressedImage` message, decoded: `(width, height, rgb)`.
fn decode_jpeg(msg: &SimMessage) -> (usize, usize, Vec<u8>) {
    use zune_jpeg::zune_core::bytestream::ZCursor;
    let v = parse(msg);
    let data = BASE64
        .decode(v["data"].as_str().expect("string"))
        .expect("base64");
    let mut decoder = zune_jpeg::JpegDecoder::new(ZCursor::new(&data));
    let rgb = decoder.decode().expect("a decodable JPEG");
    let (w, h) = decoder.dimensions().expect("dimensions after decoding");
    assert_eq!(rgb.len(), w * h * 3, "RGB output");
    (w, h, rgb)
}

fn camera_only(image: ImageSim) -> Sim {
    let cfg = SimConfig {
        image: Some(image),
        ..no_sensors()
    };
    Sim::new(&cfg, "r1", EPOCH_NS)
}

#[test]
fn compressed_image_shape() {
    let mut sim = camera_only(ImageSim {
        width: 200,
        height: 100,
        ..ImageSim::default()
    });
    let msgs = run(&mut sim, Duration::from_millis(300));
    assert_eq!(msgs.len(), 3);
    let mut frames = Vec::new();
    for m in &msgs {
        let v = parse(m);
        assert_eq!(keys(&v), set(&["header", "format", "data"]));
        check_header(&v["header"], m.stamp_ns, "camera");
        assert_eq!(v["format"], "jpeg");
        // A real JPEG of the configured size, not bytes behind a JPEG header.
        let (w, h, rgb) = decode_jpeg(m);
        assert_eq!((w, h), (200, 100));
        frames.push(rgb);
    }
    // The robot patrols: its view changes from frame to frame.
    assert_ne!(frames[0], frames[1]);
    assert_ne!(frames[1], frames[2]);
    // The default size.
    let mut sim = camera_only(ImageSim::default());
    let (w, h, _) = decode_jpeg(&sim.generate(0, Duration::ZERO));
    assert_eq!((w, h), (320, 240));
}

/// The picture the robot's camera sends when it stands at `(x, y)` looking along `yaw`.
fn view_from(x: f64, y: f64, yaw: f64) -> (usize, usize, Vec<u8>) {
    let mut sim = camera_only(ImageSim::default());
    sim.motion = Motion::Hold { x, y, yaw };
    decode_jpeg(&sim.generate(0, Duration::ZERO))
}

fn pixel(rgb: &[u8], width: usize, col: usize, row: usize) -> [i32; 3] {
    let at = (row * width + col) * 3;
    [rgb[at], rgb[at + 1], rgb[at + 2]].map(i32::from)
}

fn distance(a: [i32; 3], b: [i32; 3]) -> i32 {
    (0..3).map(|i| (a[i] - b[i]).abs()).sum()
}

/// Mean difference between horizontally adjacent pixels, per channel: a few levels for a
/// picture of surfaces, about 85 for noise.
fn roughness(rgb: &[u8], width: usize) -> f64 {
    let (mut sum, mut n) = (0u64, 0u64);
    for row in rgb.chunks_exact(width * 3) {
        for (a, b) in row.iter().zip(&row[3..]) {
            sum += u64::from(a.abs_diff(*b));
            n += 1;
        }
    }
    sum as f64 / n as f64
}

#[test]
fn camera_sees_the_room_from_the_robot_pose() {
    // From the room's centre looking along +x, the pillar at (4.2, 0) is straight ahead:
    // orange in the middle of the picture, ceiling above, floor below.
    let (w, h, rgb) = view_from(0.0, 0.0, 0.0);
    assert!(
        roughness(&rgb, w) < 12.0,
        "roughness {}",
        roughness(&rgb, w)
    );
    let [r, g, b] = pixel(&rgb, w, w / 2, h / 2);
    assert!(
        r > 140 && r > g + 40 && g > b + 20,
        "pillar ahead: rgb {r},{g},{b}"
    );
    let top = pixel(&rgb, w, w / 2, 2);
    assert!(
        top.iter().all(|&c| c > 180) && top.iter().max().unwrap() - top.iter().min().unwrap() < 25,
        "ceiling overhead: rgb {top:?}"
    );
    let bottom = pixel(&rgb, w, w / 2, h - 3);
    assert!(
        bottom.iter().all(|&c| c < 170) && distance(bottom, top) > 100,
        "floor below: rgb {bottom:?}"
    );
    // Turned to look between the pillars (60°, at the north wall 11.5 m away): no orange
    // in the middle any more, the green of the north wall.
    let (w, h, rgb) = view_from(0.0, 0.0, std::f64::consts::FRAC_PI_3);
    let [r, g, b] = pixel(&rgb, w, w / 2, h / 2);
    assert!(g > r && g > b, "north wall ahead: rgb {r},{g},{b}");
}

#[test]
fn a_wall_fills_more_of_the_picture_as_the_robot_nears_it() {
    // Looking south at the wall y = -10, from 5 m and from 2 m away. In the middle column
    // the wall's colour spans the rows between the ceiling's edge (3 m up) and the top of
    // its skirting board (0.15 m up): (3 - 0.15) m / distance × focal length rows, clipped
    // to the picture.
    let south = -std::f64::consts::FRAC_PI_2;
    let wall_rows = |distance_m: f64| {
        let (w, h, rgb) = view_from(0.5, -10.0 + distance_m, south);
        let middle = pixel(&rgb, w, w / 2, h / 2);
        let rows = (0..h)
            .filter(|&row| distance(pixel(&rgb, w, w / 2, row), middle) < 30)
            .count();
        (rows, h)
    };
    let focal = camera::CameraSpec::new(320, 240, 75).focal();
    let (far, h) = wall_rows(5.0);
    let expected = (3.0 - 0.15) / 5.0 * focal;
    assert!(
        (far as f64 - expected).abs() < 0.08 * expected,
        "wall 5 m away covers {far} rows, expected about {expected:.0}"
    );
    let (near, _) = wall_rows(2.0);
    assert!(
        near > far + 60 && near as f64 > 0.9 * h as f64,
        "wall 2 m away covers {near} rows (from 5 m: {far})"
    );
}

/// Checks `v` against the registry's definition of `type_name`, recursively: exactly the
/// fields the `.msg` has (the registry's rosapi typedefs), and arrays of messages checked
/// element by element.
fn check_fields(v: &Value, type_name: &str, defs: &[Value]) {
    let def = defs
        .iter()
        .find(|d| d["type"] == type_name)
        .unwrap_or_else(|| panic!("no typedef for {type_name}"));
    let names: Vec<&str> = def["fieldnames"]
        .as_array()
        .expect("fieldnames")
        .iter()
        .filter_map(Value::as_str)
        .collect();
    assert_eq!(
        keys(v),
        names.iter().copied().collect::<BTreeSet<_>>(),
        "fields of {type_name}"
    );
    for (i, name) in names.iter().enumerate() {
        let ty = def["fieldtypes"][i].as_str().expect("field type");
        if !ty.contains('/') {
            continue;
        }
        if def["fieldarraylen"][i] == -1 {
            check_fields(&v[*name], ty, defs);
        } else {
            for e in v[*name].as_array().expect("array") {
                check_fields(e, ty, defs);
            }
        }
    }
}

/// The value of a `Marker` constant, from the registry.
fn marker_const(defs: &[Value], name: &str) -> i64 {
    let def = defs
        .iter()
        .find(|d| d["type"] == "visualization_msgs/msg/Marker")
        .expect("Marker typedef");
    let i = def["constnames"]
        .as_array()
        .expect("constnames")
        .iter()
        .position(|c| c == name)
        .unwrap_or_else(|| panic!("no constant {name}"));
    def["constvalues"][i]
        .as_str()
        .expect("value text")
        .parse()
        .expect("integer")
}

fn markers_only() -> Sim {
    let cfg = SimConfig {
        markers: Some(MarkersSim::default()),
        frame_prefix: "r1/".into(),
        ..no_sensors()
    };
    Sim::new(&cfg, "r1", EPOCH_NS)
}

#[test]
fn markers_config_topic_and_rate() {
    assert_eq!(SimConfig::default().markers, None, "markers are opt-in");
    let mut sim = markers_only();
    assert_eq!(sim.topics().len(), 1);
    assert_eq!(sim.topics()[0].name, "/markers");
    assert_eq!(
        sim.topics()[0].type_name,
        "visualization_msgs/msg/MarkerArray"
    );
    assert_eq!(sim.topics()[0].period, Duration::from_secs(1));
    assert_eq!(run(&mut sim, Duration::from_secs(10)).len(), 10);
}

#[test]
fn markers_parse_against_the_registry_type() {
    use fleetlink_proto::{Encoding, Payload, Schema};
    use fleetlink_relay::Transcoder;
    use fleetlink_relay::transcode::RegistryTranscoder;

    let tc = RegistryTranscoder::bundled();
    let defs = tc
        .typedefs("visualization_msgs/msg/MarkerArray")
        .expect("MarkerArray is bundled");
    let schema = Schema::named("visualization_msgs/msg/MarkerArray");
    let mut sim = markers_only();
    for goal in [None, Some((3.0, -2.5))] {
        sim.set_goal_marker(goal);
        let m = sim.generate(0, Duration::from_secs(2));
        let v = parse(&m);
        check_fields(&v, "visualization_msgs/msg/MarkerArray", &defs);
        // The hub's check (wrong types refused) passes, and the message survives CDR.
        let json = Payload::json(m.json.to_vec());
        tc.normalize(&schema, &json).expect("valid MarkerArray");
        let cdr = tc
            .convert(&schema, &json, Encoding::Cdr)
            .expect("JSON → CDR");
        let back: Value = serde_json::from_slice(
            &tc.convert(&schema, &Payload::new(Encoding::Cdr, cdr), Encoding::Json)
                .expect("CDR → JSON"),
        )
        .expect("JSON");
        let list = v["markers"].as_array().expect("markers");
        assert_eq!(back["markers"].as_array().map(Vec::len), Some(list.len()));

        let of = |ns: &str| -> Vec<&Value> { list.iter().filter(|m| m["ns"] == ns).collect() };
        let f = |v: &Value| v.as_f64().expect("number");
        for m in list {
            check_header(&m["header"], m_stamp(&m["header"]), "r1/map");
            assert_eq!(m["header"]["stamp"], v["markers"][0]["header"]["stamp"]);
        }
        // Five pillars: cylinders where the world has them, as wide and tall.
        let pillars = of("pillars");
        assert_eq!(pillars.len(), world::PILLARS.len());
        for (p, (x, y, r)) in pillars.iter().zip(world::PILLARS) {
            assert_eq!(p["type"], marker_const(&defs, "CYLINDER"));
            assert_eq!(p["action"], marker_const(&defs, "ADD"));
            let pos = &p["pose"]["position"];
            assert_eq!((f(&pos["x"]), f(&pos["y"])), (x, y));
            assert_eq!(f(&p["scale"]["x"]), 2.0 * r);
            assert_eq!(f(&p["scale"]["z"]), world::PILLAR_HEIGHT);
            assert!(f(&p["color"]["a"]) > 0.0);
        }
        let ids: BTreeSet<i64> = pillars.iter().filter_map(|p| p["id"].as_i64()).collect();
        assert_eq!(ids.len(), 5, "unique ids in the namespace");
        // The walls: a closed strip around the room.
        let walls = of("walls");
        assert_eq!(walls.len(), 1);
        assert_eq!(walls[0]["type"], marker_const(&defs, "LINE_STRIP"));
        let pts = walls[0]["points"].as_array().expect("points");
        assert_eq!(pts.len(), 5);
        assert_eq!(pts[0], pts[4]);
        for p in pts {
            assert_eq!(f(&p["x"]).abs(), world::HALF_ROOM);
            assert_eq!(f(&p["y"]).abs(), world::HALF_ROOM);
        }
        assert!(f(&walls[0]["scale"]["x"]) > 0.0);
        // The goal: a sphere at the goal, or the sphere deleted.
        let g = of("goal");
        assert_eq!(g.len(), 1);
        assert_eq!(g[0]["type"], marker_const(&defs, "SPHERE"));
        match goal {
            Some((x, y)) => {
                assert_eq!(g[0]["action"], marker_const(&defs, "ADD"));
                let pos = &g[0]["pose"]["position"];
                assert_eq!((f(&pos["x"]), f(&pos["y"])), (x, y));
                assert!(f(&g[0]["scale"]["x"]) > 0.0);
            }
            None => assert_eq!(g[0]["action"], marker_const(&defs, "DELETE")),
        }
    }
}

fn m_stamp(h: &Value) -> u64 {
    h["stamp"]["sec"].as_u64().expect("sec") * 1_000_000_000
        + h["stamp"]["nanosec"].as_u64().expect("nanosec")
}

#[test]
fn markers_are_deterministic_and_follow_the_goal() {
    let a = run(&mut markers_only(), Duration::from_secs(3));
    let b = run(&mut markers_only(), Duration::from_secs(3));
    assert_eq!(a, b);
    let mut sim = markers_only();
    sim.set_goal_marker(Some((1.0, 2.0)));
    let with_goal = sim.generate(0, Duration::from_secs(1));
    sim.set_goal_marker(None);
    let without = sim.generate(0, Duration::from_secs(1));
    assert_ne!(with_goal.json, without.json);
    assert_eq!(without, a[1]);
}

#[test]
fn a_camera_nobody_wants_is_not_rendered_and_its_slots_are_not_counted_late() {
    let mut sim = all_sensors();
    let camera = (0..sim.topics().len())
        .find(|&i| sim.is_costly(i))
        .expect("the camera");
    assert_eq!(
        (0..sim.topics().len())
            .filter(|&i| sim.is_costly(i))
            .count(),
        1,
        "only the camera is costly"
    );
    let mut out = Vec::new();
    for ms in (0..=2000).step_by(10) {
        sim.poll_wanted_into(Duration::from_millis(ms), &mut out, |i| i != camera);
    }
    assert!(!out.is_empty());
    assert!(
        out.iter().all(|m| m.topic_index != camera),
        "the camera was rendered"
    );
    assert_eq!(sim.skipped(), 0, "passed-over slots are not lateness");
    // Wanted again: its next slot is made.
    out.clear();
    sim.poll_wanted_into(Duration::from_millis(2500), &mut out, |_| true);
    assert!(out.iter().any(|m| m.topic_index == camera));
}
