//! Issue 56: a type only ROS 1 has (actionlib's) gets ROS 1's field names when the hub
//! completes a rosbridge client's message, as rosbridge on ROS 1 would; a ROS 2 type
//! keeps ROS 2's; a ROS 1 time crossing into CDR keeps its value.

use fleetlink_proto::{Encoding, Payload, Schema};
use fleetlink_relay::transcode::{NormalizeCache, RegistryTranscoder, Transcoder};
use serde_json::{Value, json};

fn normalized(t: &RegistryTranscoder, schema: &Schema, msg: Value) -> Value {
    let out = t
        .normalize_cached(
            schema,
            Payload::json(msg.to_string().into_bytes()),
            &mut NormalizeCache::default(),
        )
        .expect("fits its type");
    serde_json::from_slice(&out.bytes).expect("JSON")
}

#[test]
fn a_partial_goal_id_gets_ros1_names() {
    let t = RegistryTranscoder::bundled();
    // What roslibpy's `Goal.cancel()` publishes, on a topic a rosbridge client advertised.
    let advertised = Schema::named("actionlib_msgs/GoalID");
    assert_eq!(
        normalized(&t, &advertised, json!({"id": "g1"})),
        json!({"stamp": {"secs": 0, "nsecs": 0}, "id": "g1"})
    );
    // ROS 2's names in, ROS 1's out.
    assert_eq!(
        normalized(
            &t,
            &advertised,
            json!({"id": "g2", "stamp": {"sec": 5, "nanosec": 6}})
        ),
        json!({"stamp": {"secs": 5, "nsecs": 6}, "id": "g2"})
    );
    // A status array's header gets ROS 1's `seq`.
    let status = Schema::named("actionlib_msgs/GoalStatusArray");
    let out = normalized(&t, &status, json!({"status_list": []}));
    assert_eq!(
        out["header"],
        json!({"seq": 0, "stamp": {"secs": 0, "nsecs": 0}, "frame_id": ""})
    );
}

#[test]
fn a_ros2_type_keeps_ros2_names() {
    let t = RegistryTranscoder::bundled();
    let header = Schema::named("std_msgs/msg/Header");
    assert_eq!(
        normalized(&t, &header, json!({"frame_id": "map"})),
        json!({"stamp": {"sec": 0, "nanosec": 0}, "frame_id": "map"})
    );
    // A ROS 2 robot's actionlib_msgs topic (declared as ROS 2's) stays ROS 2.
    let ros2 = Schema {
        type_name: "actionlib_msgs/msg/GoalID".into(),
        encoding: "ros2msg".into(),
        text: String::new(),
    };
    assert_eq!(
        normalized(&t, &ros2, json!({"id": "g3"})),
        json!({"stamp": {"sec": 0, "nanosec": 0}, "id": "g3"})
    );
}

#[test]
fn a_ros1_time_keeps_its_value_in_cdr() {
    let t = RegistryTranscoder::bundled();
    let schema = Schema::named("actionlib_msgs/GoalID");
    let json = Payload::json(br#"{"stamp": {"secs": 7, "nsecs": 8}, "id": "g4"}"#.to_vec());
    let cdr = t.convert(&schema, &json, Encoding::Cdr).expect("to CDR");
    let ros2 = Schema {
        type_name: "actionlib_msgs/msg/GoalID".into(),
        encoding: "ros2msg".into(),
        text: String::new(),
    };
    let back = t
        .convert(&ros2, &Payload::new(Encoding::Cdr, cdr), Encoding::Json)
        .expect("back to JSON");
    let back: Value = serde_json::from_slice(&back).unwrap();
    assert_eq!(back, json!({"stamp": {"sec": 7, "nanosec": 8}, "id": "g4"}));
}

/// A rosbridge client's `advertise` names the type only: the router fills in the
/// registry's definition, a ROS 1 one for a type only ROS 1 has, so the topic is read
/// with ROS 1's names.
#[test]
fn an_advertised_ros1_type_gets_a_ros1_schema() {
    let t = RegistryTranscoder::bundled();
    let filled = t.schema_for("actionlib_msgs/GoalID").expect("bundled");
    assert_eq!(filled.encoding, "ros1msg");
    assert_eq!(
        normalized(&t, &filled, json!({"id": "g5"})),
        json!({"stamp": {"secs": 0, "nsecs": 0}, "id": "g5"})
    );
    assert_eq!(
        t.schema_for("std_msgs/msg/Header").unwrap().encoding,
        "ros2msg"
    );
}
