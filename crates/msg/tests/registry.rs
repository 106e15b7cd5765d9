//! Registry behaviour: name forms, package directories, full texts, defaults, identities.

use fleetlink_msg::{
    Dialect, InterfaceKind, Registry, TypeName, Wire, decode, default_value, encode, from_dds_name,
    from_json, full_text, md5sum, ros2_dds_name, to_json, type_hash,
};
use serde_json::json;

use crate::util::registry;

#[test]
fn short_long_and_dds_names_resolve_to_the_same_type() {
    let reg = Registry::bundled();
    for name in [
        "geometry_msgs/Point",
        "geometry_msgs/msg/Point",
        "geometry_msgs::msg::dds_::Point_",
    ] {
        assert!(reg.contains(name), "{name}");
        assert_eq!(
            reg.resolve_name(name, Dialect::Ros2)
                .expect("resolves")
                .to_string(),
            "geometry_msgs/msg/Point"
        );
    }
    assert!(!reg.contains("geometry_msgs/Nope"));
    assert!(reg.contains("example_interfaces/srv/AddTwoInts"));
    assert!(
        reg.contains("example_interfaces/AddTwoIntsRequest"),
        "ROS 1 service part name"
    );
}

#[test]
fn dds_names_cover_messages_services_and_action_parts() {
    assert_eq!(
        ros2_dds_name("std_msgs/String").expect("ok"),
        "std_msgs::msg::dds_::String_"
    );
    assert_eq!(
        ros2_dds_name("example_interfaces/srv/AddTwoInts_Request").expect("ok"),
        "example_interfaces::srv::dds_::AddTwoInts_Request_"
    );
    assert_eq!(
        ros2_dds_name("example_interfaces/action/Fibonacci_SendGoal_Response").expect("ok"),
        "example_interfaces::action::dds_::Fibonacci_SendGoal_Response_"
    );
    let n: TypeName =
        from_dds_name("nav2_msgs::action::dds_::NavigateToPose_FeedbackMessage_").expect("parses");
    assert_eq!(
        (n.package(), n.kind(), n.name()),
        (
            "nav2_msgs",
            InterfaceKind::Action,
            "NavigateToPose_FeedbackMessage"
        )
    );
    assert!(from_dds_name("std_msgs::msg::String").is_err());
}

#[test]
fn action_parts_are_registered() {
    let reg = Registry::bundled();
    for part in [
        "Goal",
        "Result",
        "Feedback",
        "SendGoal_Request",
        "SendGoal_Response",
        "GetResult_Request",
        "GetResult_Response",
        "FeedbackMessage",
    ] {
        let name = format!("nav2_msgs/action/NavigateToPose_{part}");
        assert!(reg.layout(&name, Dialect::Ros2).is_ok(), "{name}");
    }
}

#[test]
fn package_directories_add_user_types() {
    let reg = registry();
    assert!(reg.contains("test_msgs/msg/AllTypes"));
    let e = reg
        .add_package_dir("/nonexistent/dir")
        .expect_err("missing dir");
    assert!(e.to_string().contains("/nonexistent/dir"), "{e}");
}

#[test]
fn parse_errors_name_the_type_line_and_column() {
    let reg = Registry::empty();
    let e = reg
        .add_definition(
            "demo_msgs/Bad",
            "int32 ok\nfloat32[<=x] bad\n",
            Dialect::Ros2,
        )
        .expect_err("bad bound");
    assert!(e.to_string().contains("demo_msgs/msg/Bad:2:1:"), "{e}");
}

#[test]
fn missing_json_fields_take_ros2_defaults_or_zero() {
    let reg = registry();
    let v = from_json(
        &reg,
        "test_msgs/AllTypes",
        Dialect::Ros2,
        &json!({"i32": 5}),
    )
    .expect("fills");
    let j = to_json(&v);
    assert_eq!(j["i32"], 5);
    assert_eq!(j["i16"], -7);
    assert_eq!(j["f32"], 1.5);
    assert_eq!(j["s"], "hello");
    assert_eq!(j["si32"], json!([1, 2, 3]));
    assert_eq!(j["fu8"], "AAAA", "fixed uint8[3] of zeros as base64");
    assert_eq!(j["fs"], json!(["", ""]));
    let q =
        to_json(&default_value(&reg, "geometry_msgs/Quaternion", Dialect::Ros2).expect("default"));
    assert_eq!(q["w"], 1.0);
}

#[test]
fn json_conventions_of_rosbridge_are_accepted() {
    let reg = Registry::bundled();
    let v = from_json(
        &reg,
        "std_msgs/Header",
        Dialect::Ros2,
        &json!({"stamp": {"secs": 3, "nsecs": 4}}),
    )
    .expect("secs/nsecs");
    assert_eq!(to_json(&v)["stamp"], json!({"sec": 3, "nanosec": 4}));
    let v = from_json(
        &reg,
        "std_msgs/Header",
        Dialect::Ros1,
        &json!({"seq": 9, "stamp": {"secs": 3, "nsecs": 4}}),
    )
    .expect("ROS 1");
    // Read in the ROS 1 dialect, a time has ROS 1's names (issue 56).
    assert_eq!(
        to_json(&v),
        json!({"seq": 9, "stamp": {"secs": 3, "nsecs": 4}, "frame_id": ""})
    );
    let v = from_json(
        &reg,
        "geometry_msgs/Point",
        Dialect::Ros2,
        &json!({"x": 1, "y": null}),
    )
    .expect("int and null");
    let j = to_json(&v);
    assert_eq!((j["x"].as_f64(), j["y"].is_null()), (Some(1.0), true));
    let v = from_json(
        &reg,
        "sensor_msgs/CompressedImage",
        Dialect::Ros2,
        &json!({"data": [1, 2, 255]}),
    )
    .expect("uint8[] as list");
    assert_eq!(to_json(&v)["data"], "AQL/");
}

#[test]
fn full_texts_register_in_a_fresh_registry_with_the_same_identity() {
    let reg = Registry::bundled();
    for name in reg.message_names() {
        let ty = name.to_string();
        if reg.message(&ty, Dialect::Ros2).is_err() {
            continue;
        }
        for dialect in [Dialect::Ros2, Dialect::Ros1] {
            let text = full_text(&reg, &ty, dialect).expect("full text");
            let fresh = Registry::empty();
            fresh
                .add_full_text(&ty, &text, dialect)
                .unwrap_or_else(|e| panic!("{ty} {dialect:?}: {e}\n{text}"));
            let wire = if dialect == Dialect::Ros2 {
                Wire::Cdr
            } else {
                Wire::Ros1
            };
            let v = default_value(&reg, &ty, dialect).expect("default");
            assert_eq!(
                encode(&fresh, &ty, wire, &v).ok(),
                encode(&reg, &ty, wire, &v).ok(),
                "{ty} {dialect:?}"
            );
            match dialect {
                Dialect::Ros2 => assert_eq!(
                    type_hash(&fresh, &ty).ok(),
                    type_hash(&reg, &ty).ok(),
                    "{ty}"
                ),
                Dialect::Ros1 => {
                    assert_eq!(md5sum(&fresh, &ty).ok(), md5sum(&reg, &ty).ok(), "{ty}")
                }
            }
        }
    }
}

#[test]
fn full_text_has_the_separator_and_dependency_lines_peers_expect() {
    let reg = Registry::bundled();
    let text = full_text(&reg, "geometry_msgs/PoseStamped", Dialect::Ros1).expect("text");
    assert!(
        text.contains(&format!("{}\nMSG: std_msgs/Header\n", "=".repeat(80))),
        "{text}"
    );
    assert!(text.contains("uint32 seq"), "ROS 1 header: {text}");
    let text = reg
        .full_text("geometry_msgs/PoseStamped", Dialect::Ros2)
        .expect("text");
    // Headed as the fields spell them, so @foxglove/rosmsg matches them (Lichtblick).
    assert!(text.contains("MSG: builtin_interfaces/Time\n"), "{text}");
    assert!(text.contains("MSG: std_msgs/Header\n"), "{text}");
    assert!(!text.contains("seq"), "{text}");
}

#[test]
fn run_time_ros2_definitions_override_and_are_shared_by_clones() {
    let reg = Registry::bundled();
    let clone = reg.clone();
    let text = "int32 a\nfleet_msgs/Inner inner\n================================================================================\nMSG: fleet_msgs/Inner\nstring name\n";
    reg.add_full_text("fleet_msgs/msg/Outer", text, Dialect::Ros2)
        .expect("registers");
    let v = from_json(
        &clone,
        "fleet_msgs/Outer",
        Dialect::Ros2,
        &json!({"a": 1, "inner": {"name": "x"}}),
    )
    .expect("clone sees it");
    let cdr = encode(&clone, "fleet_msgs/Outer", Wire::Cdr, &v).expect("encodes");
    assert!(
        decode(&reg, "fleet_msgs/Outer", Wire::Cdr, &cdr)
            .expect("decodes")
            .same_as(&v)
    );
}

#[test]
fn service_md5sum_combines_request_and_response_and_actions_have_none() {
    let reg = Registry::bundled();
    let srv = md5sum(&reg, "std_srvs/srv/SetBool").expect("srv md5");
    assert_eq!(srv.len(), 32);
    assert_ne!(
        srv,
        md5sum(&reg, "std_srvs/SetBool_Request").expect("part md5")
    );
    assert!(md5sum(&reg, "example_interfaces/action/Fibonacci").is_err());
}

#[test]
fn registry_can_be_shared_across_threads() {
    fn shareable<T: Send + Sync + Clone + 'static>(_: &T) {}
    let reg = Registry::bundled();
    shareable(&reg);
    let r2 = reg.clone();
    let handle = std::thread::spawn(move || {
        r2.add_definition("thread_msgs/T", "int8 x\n", Dialect::Ros2)
            .is_ok()
    });
    assert!(handle.join().unwrap_or(false));
    assert!(reg.contains("thread_msgs/T"), "clones share one table");
}

/// Issue 56: the types only ROS 1 has, whose rosbridge clients expect ROS 1's names.
#[test]
fn types_only_ros1_has_are_told_apart() {
    let ros1_only = |n: &str| fleetlink_msg::TypeName::parse(n).unwrap().is_ros1_only();
    for n in [
        "actionlib_msgs/GoalID",
        "actionlib_msgs/msg/GoalStatusArray",
        "actionlib_tutorials/FibonacciActionGoal",
        "my_robot/DockActionResult",
        "my_robot/msg/DockActionFeedback",
        "dynamic_reconfigure/Config",
    ] {
        assert!(ros1_only(n), "{n}");
    }
    for n in [
        "std_msgs/msg/Header",
        "sensor_msgs/PointCloud2",
        "example_interfaces/action/Fibonacci_Goal",
        "nav2_msgs/action/NavigateToPose_FeedbackMessage",
        "my_robot/ActionGoal",
    ] {
        assert!(!ros1_only(n), "{n}");
    }
}
