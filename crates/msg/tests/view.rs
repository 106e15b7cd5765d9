//! The zero-copy view over CDR messages.

use fleetlink_msg::{CdrView, Dialect, Value, Wire, encode, from_json};
use serde_json::json;

use crate::util::registry;

#[test]
fn view_reads_header_and_borrows_point_cloud_data() {
    let reg = registry();
    let data: Vec<u8> = (0..=255u8).cycle().take(4096).collect();
    let j = json!({
        "header": {"stamp": {"sec": 12, "nanosec": 34}, "frame_id": "velodyne"},
        "height": 1, "width": 256,
        "fields": [{"name": "x", "offset": 0, "datatype": 7, "count": 1}, {"name": "intensity", "offset": 12, "datatype": 7, "count": 1}],
        "point_step": 16, "row_step": 4096,
        "data": data.iter().map(|b| *b as u64).collect::<Vec<_>>(),
        "is_dense": true,
    });
    let v = from_json(&reg, "sensor_msgs/PointCloud2", Dialect::Ros2, &j).expect("valid");
    let cdr = encode(&reg, "sensor_msgs/PointCloud2", Wire::Cdr, &v).expect("encodes");
    let view = CdrView::new(&reg, "sensor_msgs/PointCloud2", &cdr).expect("view");
    let h = view.header().expect("header");
    assert_eq!((h.sec, h.nanosec, h.frame_id), (12, 34, "velodyne"));
    let s = view.primitive_array("data").expect("data");
    assert_eq!(s.bytes, &data[..]);
    assert_eq!(s.len, 4096);
    assert!(
        std::ptr::eq(s.bytes.as_ptr(), cdr[s.offset..].as_ptr()),
        "borrowed, not copied"
    );
    assert_eq!(view.field("width").expect("width"), Value::U32(256));
    assert_eq!(view.field("is_dense").expect("is_dense"), Value::Bool(true));
    assert_eq!(view.len(), cdr.len());
    assert!(view.primitive_array("fields").is_err(), "array of messages");
    assert!(view.field("nope").is_err());
}

#[test]
fn view_gives_laser_ranges_as_raw_little_endian_floats() {
    let reg = registry();
    let v = from_json(
        &reg,
        "sensor_msgs/LaserScan",
        Dialect::Ros2,
        &json!({"ranges": [1.0, 2.5]}),
    )
    .expect("valid");
    let cdr = encode(&reg, "sensor_msgs/LaserScan", Wire::Cdr, &v).expect("encodes");
    let view = CdrView::new(&reg, "sensor_msgs/LaserScan", &cdr).expect("view");
    let r = view.primitive_array("ranges").expect("ranges");
    assert_eq!(r.len, 2);
    assert!(!r.big_endian);
    assert_eq!(
        f32::from_le_bytes(r.bytes[4..8].try_into().expect("4 bytes")),
        2.5
    );
    assert!(view.header().is_ok());
}
