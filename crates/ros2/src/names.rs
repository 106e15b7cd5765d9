//! ROS 2 names on DDS, as ROS 2's middlewares spell them.
//!
//! A topic `/scan` is the DDS topic `rt/scan`; a service `/add` is the request topic
//! `rq/addRequest` and the reply topic `rr/addReply`; an action `/nav` is the services
//! `/nav/_action/{send_goal,cancel_goal,get_result}` and the topics
//! `/nav/_action/{feedback,status}`. Types: `pkg/msg/T` is `pkg::msg::dds_::T_`
//! (through the msg crate's [`TypeName`]).

use fleetlink_msg::name::TypeName;

/// What a DDS topic name is in ROS 2 terms.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum DdsName {
    Topic(String),
    Request(String),
    Reply(String),
}

impl DdsName {
    pub fn parse(dds: &str) -> Option<DdsName> {
        let ros = |rest: &str| rest.starts_with('/').then(|| rest.to_owned());
        if let Some(rest) = dds.strip_prefix("rt") {
            return ros(rest).map(DdsName::Topic);
        }
        if let Some(rest) = dds.strip_prefix("rq") {
            return rest
                .strip_suffix("Request")
                .and_then(ros)
                .map(DdsName::Request);
        }
        if let Some(rest) = dds.strip_prefix("rr") {
            return rest.strip_suffix("Reply").and_then(ros).map(DdsName::Reply);
        }
        None
    }
}

pub fn topic(ros: &str) -> String {
    format!("rt{ros}")
}

pub fn request_topic(service: &str) -> String {
    format!("rq{service}Request")
}

pub fn reply_topic(service: &str) -> String {
    format!("rr{service}Reply")
}

/// `pkg::msg::dds_::T_` → `pkg/msg/T`.
pub fn ros_type(dds_type: &str) -> Option<String> {
    fleetlink_msg::name::from_dds_name(dds_type)
        .ok()
        .map(|t| t.to_string())
}

/// `pkg/msg/T` (or `pkg/T`) → `pkg::msg::dds_::T_`.
pub fn dds_type(ros_type: &str) -> Option<String> {
    TypeName::parse(ros_type).ok().map(|t| t.dds_name())
}

/// A service's type from its request part's DDS type: `pkg::srv::dds_::T_Request_` →
/// `pkg/srv/T`.
pub fn service_type(request_dds_type: &str) -> Option<String> {
    ros_type(request_dds_type)?
        .strip_suffix("_Request")
        .map(str::to_owned)
}

/// The parts of an action named `action`.
pub const ACTION_INFIX: &str = "/_action/";

/// `/nav/_action/send_goal` → `/nav`.
pub fn action_of_send_goal(service: &str) -> Option<&str> {
    service.strip_suffix("/_action/send_goal")
}

/// An action's type from its send_goal request's DDS type:
/// `pkg::action::dds_::T_SendGoal_Request_` → `pkg/action/T`.
pub fn action_type(send_goal_dds_type: &str) -> Option<String> {
    ros_type(send_goal_dds_type)?
        .strip_suffix("_SendGoal_Request")
        .map(str::to_owned)
}

/// True for the names ROS 2 hides from topic lists (an action's parts, `_`-prefixed
/// components); they are bridged as parts of their action, never as topics.
pub fn is_hidden(ros: &str) -> bool {
    ros.split('/').any(|c| c.starts_with('_'))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dds_names_read_back_as_ros_names() {
        assert_eq!(
            DdsName::parse("rt/scan"),
            Some(DdsName::Topic("/scan".into()))
        );
        assert_eq!(
            DdsName::parse("rq/a/addRequest"),
            Some(DdsName::Request("/a/add".into()))
        );
        assert_eq!(
            DdsName::parse("rr/addReply"),
            Some(DdsName::Reply("/add".into()))
        );
        assert_eq!(DdsName::parse("rq/add"), None);
        assert_eq!(DdsName::parse("DCPSParticipant"), None);
        assert_eq!(DdsName::parse("rtscan"), None);
        assert_eq!(topic("/scan"), "rt/scan");
        assert_eq!(request_topic("/add"), "rq/addRequest");
        assert_eq!(reply_topic("/add"), "rr/addReply");
    }

    #[test]
    fn types_map_both_ways() {
        assert_eq!(
            dds_type("sensor_msgs/msg/LaserScan").as_deref(),
            Some("sensor_msgs::msg::dds_::LaserScan_")
        );
        assert_eq!(
            dds_type("geometry_msgs/Twist").as_deref(),
            Some("geometry_msgs::msg::dds_::Twist_")
        );
        assert_eq!(
            ros_type("sensor_msgs::msg::dds_::LaserScan_").as_deref(),
            Some("sensor_msgs/msg/LaserScan")
        );
        assert_eq!(
            service_type("example_interfaces::srv::dds_::AddTwoInts_Request_").as_deref(),
            Some("example_interfaces/srv/AddTwoInts")
        );
        assert_eq!(
            action_type("example_interfaces::action::dds_::Fibonacci_SendGoal_Request_").as_deref(),
            Some("example_interfaces/action/Fibonacci")
        );
        assert_eq!(action_of_send_goal("/fib/_action/send_goal"), Some("/fib"));
        assert!(is_hidden("/fib/_action/feedback"));
        assert!(!is_hidden("/scan"));
    }
}
