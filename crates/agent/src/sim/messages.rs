//! The five message types in rosbridge JSON (ROS 2 field names; `uint8[]` as base64).
//!
//! Design: typed `Serialize` structs mirror the ROS 2 definitions field by field, so a
//! wrong field name is a compile-time diff against the `.msg`, not a typo in a string.
//! Large arrays (cloud points, camera pictures, scan ranges) are written into buffers
//! owned by [`Scratch`] and reused between messages; the only per-message allocation of
//! size is the JSON output, which is handed out as `Bytes` (and the JPEG encoder's working
//! strip of 16 rows, which it allocates itself).

use base64::Engine;
use base64::engine::general_purpose::STANDARD as BASE64;
use serde::Serialize;

use super::camera::{self, CameraSpec};
use super::world::{self, Noise, RobotState, Surface};

#[derive(Serialize)]
pub(crate) struct Time {
    sec: i32,
    nanosec: u32,
}

impl Time {
    pub(crate) fn from_ns(ns: u64) -> Self {
        // ROS 2 Time is int32 seconds: saturate rather than wrap in 2038.
        let sec = i32::try_from(ns / 1_000_000_000).unwrap_or(i32::MAX);
        Self {
            sec,
            nanosec: (ns % 1_000_000_000) as u32,
        }
    }
}

#[derive(Serialize)]
pub(crate) struct Header<'a> {
    stamp: Time,
    frame_id: &'a str,
}

impl<'a> Header<'a> {
    pub(crate) fn new(stamp_ns: u64, frame_id: &'a str) -> Self {
        Self {
            stamp: Time::from_ns(stamp_ns),
            frame_id,
        }
    }
}

#[derive(Serialize)]
struct Point {
    x: f64,
    y: f64,
    z: f64,
}

#[derive(Serialize)]
struct Quaternion {
    x: f64,
    y: f64,
    z: f64,
    w: f64,
}

#[derive(Serialize)]
struct Pose {
    position: Point,
    orientation: Quaternion,
}

impl Pose {
    fn planar(x: f64, y: f64, yaw: f64) -> Self {
        let (s, c) = (yaw / 2.0).sin_cos();
        Self {
            position: Point { x, y, z: 0.0 },
            orientation: Quaternion {
                x: 0.0,
                y: 0.0,
                z: s,
                w: c,
            },
        }
    }
}

#[derive(Serialize)]
struct Vector3 {
    x: f64,
    y: f64,
    z: f64,
}

#[derive(Serialize)]
struct Twist {
    linear: Vector3,
    angular: Vector3,
}

#[derive(Serialize)]
struct PoseWithCovariance {
    pose: Pose,
    #[serde(serialize_with = "as_slice")]
    covariance: [f64; 36],
}

#[derive(Serialize)]
struct TwistWithCovariance {
    twist: Twist,
    #[serde(serialize_with = "as_slice")]
    covariance: [f64; 36],
}

/// serde implements `Serialize` for arrays only up to 32 elements.
fn as_slice<S: serde::Serializer>(m: &[f64; 36], s: S) -> Result<S::Ok, S::Error> {
    m.as_slice().serialize(s)
}

/// `nav_msgs/msg/Odometry`.
#[derive(Serialize)]
struct Odometry<'a> {
    header: Header<'a>,
    child_frame_id: &'a str,
    pose: PoseWithCovariance,
    twist: TwistWithCovariance,
}

/// `geometry_msgs/msg/PoseStamped`.
#[derive(Serialize)]
struct PoseStamped<'a> {
    header: Header<'a>,
    pose: Pose,
}

/// `sensor_msgs/msg/LaserScan`.
#[derive(Serialize)]
struct LaserScan<'a> {
    header: Header<'a>,
    angle_min: f32,
    angle_max: f32,
    angle_increment: f32,
    time_increment: f32,
    scan_time: f32,
    range_min: f32,
    range_max: f32,
    ranges: &'a [f32],
    intensities: &'a [f32],
}

/// `sensor_msgs/msg/PointField`.
#[derive(Serialize)]
struct PointField {
    name: &'static str,
    offset: u32,
    datatype: u8,
    count: u32,
}

/// `sensor_msgs/msg/PointCloud2`.
#[derive(Serialize)]
struct PointCloud2<'a> {
    header: Header<'a>,
    height: u32,
    width: u32,
    fields: [PointField; 4],
    is_bigendian: bool,
    point_step: u32,
    row_step: u32,
    data: &'a str,
    is_dense: bool,
}

/// `sensor_msgs/msg/CompressedImage`.
#[derive(Serialize)]
struct CompressedImage<'a> {
    header: Header<'a>,
    format: &'a str,
    data: &'a str,
}

/// Reused buffers, so steady-state generation does not allocate per point or per beam.
#[derive(Debug, Default)]
pub(crate) struct Scratch {
    ranges: Vec<f32>,
    /// Cloud points, or the camera's JPEG.
    binary: Vec<u8>,
    /// The camera's picture before encoding.
    canvas: camera::Canvas,
    base64: String,
}

fn to_json<T: Serialize>(msg: &T, capacity: usize) -> Vec<u8> {
    let mut out = Vec::with_capacity(capacity);
    // Serializing these structs into a Vec cannot fail: no maps with non-string keys,
    // no I/O. Non-finite floats become `null`, which the generators avoid.
    if let Err(e) = serde_json::to_writer(&mut out, msg) {
        unreachable!("serializing a simulated message failed: {e}");
    }
    out
}

pub(crate) const SCAN_RANGE_MIN: f32 = 0.12;
pub(crate) const SCAN_RANGE_MAX: f32 = 30.0;
/// Laser mounted 0.15 m ahead of the robot's centre.
const LASER_X: f64 = 0.15;

pub(crate) fn laser_scan(
    scratch: &mut Scratch,
    state: &RobotState,
    beams: u32,
    scan_time: f32,
    noise: &mut Noise,
    header: Header<'_>,
) -> Vec<u8> {
    let n = beams.max(1);
    let increment = std::f64::consts::TAU / f64::from(n);
    let angle_min = -std::f64::consts::PI;
    let (sy, cy) = state.yaw.sin_cos();
    let (ox, oy) = (state.x + LASER_X * cy, state.y + LASER_X * sy);
    scratch.ranges.clear();
    scratch.ranges.extend((0..n).map(|i| {
        let (dy, dx) = (state.yaw + angle_min + f64::from(i) * increment).sin_cos();
        let r = world::range_2d(ox, oy, dx, dy) + noise.normal(0.01);
        (r as f32).clamp(SCAN_RANGE_MIN, SCAN_RANGE_MAX)
    }));
    let msg = LaserScan {
        header,
        angle_min: angle_min as f32,
        angle_max: (angle_min + f64::from(n - 1) * increment) as f32,
        angle_increment: increment as f32,
        time_increment: scan_time / n as f32,
        scan_time,
        range_min: SCAN_RANGE_MIN,
        range_max: SCAN_RANGE_MAX,
        ranges: &scratch.ranges,
        intensities: &[],
    };
    to_json(&msg, 256 + 10 * n as usize)
}

/// Diagonal 6×6 covariance (row-major, x y z roll pitch yaw).
fn diagonal(d: [f64; 6]) -> [f64; 36] {
    let mut m = [0.0; 36];
    for (i, v) in d.into_iter().enumerate() {
        m[i * 7] = v;
    }
    m
}

pub(crate) fn odometry(state: &RobotState, header: Header<'_>, child_frame_id: &str) -> Vec<u8> {
    let msg = Odometry {
        header,
        child_frame_id,
        pose: PoseWithCovariance {
            pose: Pose::planar(state.x, state.y, state.yaw),
            covariance: diagonal([0.01, 0.01, 1e-6, 1e-6, 1e-6, 0.03]),
        },
        twist: TwistWithCovariance {
            twist: Twist {
                linear: Vector3 {
                    x: state.speed,
                    y: 0.0,
                    z: 0.0,
                },
                angular: Vector3 {
                    x: 0.0,
                    y: 0.0,
                    z: state.yaw_rate,
                },
            },
            covariance: diagonal([0.005, 0.005, 1e-6, 1e-6, 1e-6, 0.01]),
        },
    };
    to_json(&msg, 1024)
}

pub(crate) fn pose_stamped(state: &RobotState, header: Header<'_>) -> Vec<u8> {
    to_json(
        &PoseStamped {
            header,
            pose: Pose::planar(state.x, state.y, state.yaw),
        },
        256,
    )
}

/// x, y, z, intensity: four float32, little-endian.
pub(crate) const POINT_STEP: u32 = 16;
/// `sensor_msgs/msg/PointField` FLOAT32.
pub(crate) const FLOAT32: u8 = 7;
/// 3D lidar: rings between ±15° elevation, mounted 0.4 m above the floor.
const LIDAR_RINGS: u32 = 16;
const LIDAR_HEIGHT: f64 = 0.4;
const LIDAR_FOV: f64 = 30.0 * std::f64::consts::PI / 180.0;

pub(crate) fn point_cloud(
    scratch: &mut Scratch,
    state: &RobotState,
    points: u32,
    noise: &mut Noise,
    header: Header<'_>,
) -> Vec<u8> {
    let rings = LIDAR_RINGS.min(points.max(1));
    let columns = points.div_ceil(rings).max(1);
    let mut elevations = [(0.0, 1.0); LIDAR_RINGS as usize];
    for (r, e) in elevations.iter_mut().enumerate().take(rings as usize) {
        let angle = if rings == 1 {
            0.0
        } else {
            -LIDAR_FOV / 2.0 + LIDAR_FOV * r as f64 / f64::from(rings - 1)
        };
        *e = angle.sin_cos();
    }
    let bin = &mut scratch.binary;
    bin.clear();
    bin.reserve(points as usize * POINT_STEP as usize);
    let column_step = std::f64::consts::TAU / f64::from(columns);
    'columns: for c in 0..columns {
        let azimuth = f64::from(c) * column_step;
        let (sa, ca) = azimuth.sin_cos();
        let (dy, dx) = (state.yaw + azimuth).sin_cos();
        for &(sin_el, cos_el) in &elevations[..rings as usize] {
            if bin.len() >= points as usize * POINT_STEP as usize {
                break 'columns;
            }
            let (range, surface) =
                world::range_3d(state.x, state.y, LIDAR_HEIGHT, dx, dy, (sin_el, cos_el));
            let range = range + noise.normal(0.01);
            let reflectivity = match surface {
                Surface::Wall => 100.0,
                Surface::Pillar => 220.0,
                Surface::Floor => 30.0,
                Surface::Ceiling => 60.0,
            };
            let horizontal = range * cos_el;
            for v in [
                horizontal * ca,
                horizontal * sa,
                range * sin_el,
                reflectivity / (1.0 + 0.05 * range),
            ] {
                bin.extend_from_slice(&(v as f32).to_le_bytes());
            }
        }
    }
    let width = points;
    scratch.base64.clear();
    BASE64.encode_string(&scratch.binary, &mut scratch.base64);
    let field = |name, offset| PointField {
        name,
        offset,
        datatype: FLOAT32,
        count: 1,
    };
    let msg = PointCloud2 {
        header,
        height: 1,
        width,
        fields: [
            field("x", 0),
            field("y", 4),
            field("z", 8),
            field("intensity", 12),
        ],
        is_bigendian: false,
        point_step: POINT_STEP,
        row_step: width * POINT_STEP,
        data: &scratch.base64,
        is_dense: true,
    };
    to_json(&msg, scratch.base64.len() + 512)
}

/// A picture of the room from the robot's pose ([`camera`]), JPEG-encoded.
pub(crate) fn compressed_image(
    scratch: &mut Scratch,
    state: &RobotState,
    spec: CameraSpec,
    header: Header<'_>,
) -> Vec<u8> {
    camera::render(&mut scratch.canvas, spec, state);
    camera::encode(&scratch.canvas.rgb, spec, &mut scratch.binary);
    scratch.base64.clear();
    BASE64.encode_string(&scratch.binary, &mut scratch.base64);
    let msg = CompressedImage {
        header,
        format: "jpeg",
        data: &scratch.base64,
    };
    to_json(&msg, scratch.base64.len() + 256)
}

/// `std_msgs/msg/ColorRGBA`.
#[derive(Serialize, Clone, Copy)]
struct ColorRgba {
    r: f32,
    g: f32,
    b: f32,
    a: f32,
}

/// `builtin_interfaces/msg/Duration`.
#[derive(Serialize)]
struct RosDuration {
    sec: i32,
    nanosec: u32,
}

/// `visualization_msgs/msg/MeshFile`.
#[derive(Serialize)]
struct MeshFile {
    filename: &'static str,
    data: &'static str,
}

/// `visualization_msgs/msg/UVCoordinate` (never sent: the list is always empty).
#[derive(Serialize)]
struct UvCoordinate {
    u: f32,
    v: f32,
}

/// `visualization_msgs/msg/Marker`, every field (the unused texture and mesh ones empty).
#[derive(Serialize)]
struct Marker<'a> {
    header: Header<'a>,
    ns: &'static str,
    id: i32,
    #[serde(rename = "type")]
    kind: i32,
    action: i32,
    pose: Pose,
    scale: Vector3,
    color: ColorRgba,
    lifetime: RosDuration,
    frame_locked: bool,
    points: Vec<Point>,
    colors: Vec<ColorRgba>,
    texture_resource: &'static str,
    texture: CompressedImage<'a>,
    uv_coordinates: Vec<UvCoordinate>,
    text: &'static str,
    mesh_resource: &'static str,
    mesh_file: MeshFile,
    mesh_use_embedded_materials: bool,
}

/// `visualization_msgs/msg/MarkerArray`.
#[derive(Serialize)]
struct MarkerArray<'a> {
    markers: Vec<Marker<'a>>,
}

/// `visualization_msgs/msg/Marker` type and action constants.
pub(crate) mod marker {
    pub(crate) const SPHERE: i32 = 2;
    pub(crate) const CYLINDER: i32 = 3;
    pub(crate) const LINE_STRIP: i32 = 4;
    pub(crate) const ADD: i32 = 0;
    pub(crate) const DELETE: i32 = 2;
}

/// Goal sphere diameter, m.
const GOAL_DIAMETER: f64 = 0.4;
/// Wall line width, m.
const WALL_WIDTH: f64 = 0.1;

impl<'a> Marker<'a> {
    fn new(stamp_ns: u64, frame_id: &'a str, ns: &'static str, id: i32, kind: i32) -> Self {
        Self {
            header: Header::new(stamp_ns, frame_id),
            ns,
            id,
            kind,
            action: marker::ADD,
            pose: Pose::planar(0.0, 0.0, 0.0),
            scale: Vector3 {
                x: 1.0,
                y: 1.0,
                z: 1.0,
            },
            color: ColorRgba {
                r: 1.0,
                g: 1.0,
                b: 1.0,
                a: 1.0,
            },
            lifetime: RosDuration { sec: 0, nanosec: 0 },
            frame_locked: false,
            points: Vec::new(),
            colors: Vec::new(),
            texture_resource: "",
            texture: CompressedImage {
                header: Header::new(0, ""),
                format: "",
                data: "",
            },
            uv_coordinates: Vec::new(),
            text: "",
            mesh_resource: "",
            mesh_file: MeshFile {
                filename: "",
                data: "",
            },
            mesh_use_embedded_materials: false,
        }
    }
}

/// The room as markers, in the pose's frame: one `CYLINDER` per pillar (namespace
/// `pillars`, ids 0..), the walls as one closed `LINE_STRIP` (`walls`/0), and the
/// navigation goal as a `SPHERE` (`goal`/0) — or, with no goal, a `DELETE` of it, so a
/// viewer drops the sphere of a goal that ended.
pub(crate) fn markers(stamp_ns: u64, frame_id: &str, goal: Option<(f64, f64)>) -> Vec<u8> {
    let mut list = Vec::with_capacity(world::PILLARS.len() + 2);
    for (i, &(x, y, r)) in world::PILLARS.iter().enumerate() {
        let mut m = Marker::new(stamp_ns, frame_id, "pillars", i as i32, marker::CYLINDER);
        m.pose.position = Point {
            x,
            y,
            z: world::PILLAR_HEIGHT / 2.0,
        };
        m.scale = Vector3 {
            x: 2.0 * r,
            y: 2.0 * r,
            z: world::PILLAR_HEIGHT,
        };
        m.color = ColorRgba {
            r: 0.55,
            g: 0.6,
            b: 0.7,
            a: 1.0,
        };
        list.push(m);
    }
    let mut walls = Marker::new(stamp_ns, frame_id, "walls", 0, marker::LINE_STRIP);
    let h = world::HALF_ROOM;
    walls.points = [(-h, -h), (h, -h), (h, h), (-h, h), (-h, -h)]
        .into_iter()
        .map(|(x, y)| Point { x, y, z: 0.0 })
        .collect();
    walls.scale = Vector3 {
        x: WALL_WIDTH,
        y: 0.0,
        z: 0.0,
    };
    walls.color = ColorRgba {
        r: 0.85,
        g: 0.85,
        b: 0.9,
        a: 1.0,
    };
    list.push(walls);
    let mut g = Marker::new(stamp_ns, frame_id, "goal", 0, marker::SPHERE);
    match goal {
        Some((x, y)) => {
            g.pose.position = Point {
                x,
                y,
                z: GOAL_DIAMETER / 2.0,
            };
            g.scale = Vector3 {
                x: GOAL_DIAMETER,
                y: GOAL_DIAMETER,
                z: GOAL_DIAMETER,
            };
            g.color = ColorRgba {
                r: 0.44,
                g: 0.81,
                b: 0.59,
                a: 0.9,
            };
        }
        None => g.action = marker::DELETE,
    }
    list.push(g);
    to_json(&MarkerArray { markers: list }, 8192)
}
