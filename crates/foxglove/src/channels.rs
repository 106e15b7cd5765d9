//! What a topic looks like as a Foxglove channel: its message encoding and its schema.
//!
//! A Foxglove client decodes a channel's messages with the schema it was advertised with,
//! so the hub picks, per topic, the one encoding in which it can give every message of
//! the topic together with a schema the client can parse:
//!
//! - a ROS 1 topic (its definition came as `ros1msg`, from the ROS 1 adapter) is `ros1`
//!   with the `ros1msg` text: messages go as the robot's bytes;
//! - a ROS 2 topic, and any topic whose type the hub's registry knows (the simulator's
//!   and rosbridge publishers' JSON included), is `cdr` with the `ros2msg` text: CDR
//!   messages go as they came, others are converted once per message for every Foxglove
//!   subscriber ([`fleetlink_relay::Message::payload_in`]);
//! - a type nobody defined (a rosbridge client's JSON of a custom type) is `json` without
//!   a schema, its messages as JSON.

use fleetlink_proto::{Encoding, Schema};
use fleetlink_relay::Transcoder;

use crate::protocol::Channel;

/// A topic's channel, without its id.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ChannelForm {
    /// What the messages are sent as.
    pub encoding: Encoding,
    pub schema_name: String,
    pub schema: String,
    pub schema_encoding: Option<&'static str>,
}

impl ChannelForm {
    /// The topic with this schema as a channel.
    pub fn of(schema: &Schema, tc: &dyn Transcoder) -> ChannelForm {
        let with_text = |encoding, schema_encoding, text: &str| ChannelForm {
            encoding,
            schema_name: schema.type_name.clone(),
            schema: text.to_owned(),
            schema_encoding: Some(schema_encoding),
        };
        if !schema.type_name.is_empty() && !schema.text.is_empty() {
            match schema.encoding.as_str() {
                "ros1msg" => return with_text(Encoding::Ros1, "ros1msg", &schema.text),
                "ros2msg" => return with_text(Encoding::Cdr, "ros2msg", &schema.text),
                _ => {}
            }
        }
        if !schema.type_name.is_empty()
            && let Some(known) = tc.schema_for(&schema.type_name)
            && !known.text.is_empty()
        {
            return with_text(Encoding::Cdr, "ros2msg", &known.text);
        }
        ChannelForm {
            encoding: Encoding::Json,
            schema_name: schema.type_name.clone(),
            schema: String::new(),
            schema_encoding: None,
        }
    }

    /// The advertisement of this channel as `id` on `topic`.
    pub fn channel(&self, id: u32, topic: &str) -> Channel {
        Channel {
            id,
            topic: topic.to_owned(),
            encoding: wire_name(self.encoding),
            schema_name: self.schema_name.clone(),
            schema: self.schema.clone(),
            schema_encoding: self.schema_encoding,
        }
    }
}

/// An encoding as the protocol names it.
pub fn wire_name(e: Encoding) -> &'static str {
    match e {
        Encoding::Cdr => "cdr",
        Encoding::Ros1 => "ros1",
        // CBOR has no channel of its own: such messages are sent as JSON.
        Encoding::Json | Encoding::Cbor => "json",
    }
}

/// The encoding a client names for what it publishes or calls with; `None` for one the
/// hub cannot take.
pub fn from_wire_name(name: &str) -> Option<Encoding> {
    Some(match name {
        "cdr" => Encoding::Cdr,
        "ros1" => Encoding::Ros1,
        "json" => Encoding::Json,
        _ => return None,
    })
}

/// The encodings clients may publish and call with (`supportedEncodings`).
pub const CLIENT_ENCODINGS: [&str; 3] = ["json", "cdr", "ros1"];

#[cfg(test)]
mod tests {
    use super::*;
    use fleetlink_relay::GenericTranscoder;
    use fleetlink_relay::transcode::RegistryTranscoder;

    fn schema(type_name: &str, encoding: &str, text: &str) -> Schema {
        Schema {
            type_name: type_name.into(),
            encoding: encoding.into(),
            text: text.into(),
        }
    }

    #[test]
    fn a_ros1_topic_is_a_ros1_channel_with_its_own_definition() {
        let s = schema("sensor_msgs/LaserScan", "ros1msg", "float32 angle_min\n");
        let f = ChannelForm::of(&s, &GenericTranscoder);
        assert_eq!(f.encoding, Encoding::Ros1);
        let c = f.channel(4, "/r1/scan");
        assert_eq!(
            (c.encoding, c.schema_encoding, c.schema.as_str()),
            ("ros1", Some("ros1msg"), "float32 angle_min\n")
        );
    }

    #[test]
    fn a_ros2_topic_is_a_cdr_channel_with_its_own_definition() {
        let s = schema("pkg/msg/Custom", "ros2msg", "int32 a\n");
        let f = ChannelForm::of(&s, &GenericTranscoder);
        assert_eq!(
            (f.encoding, f.schema_encoding, f.schema.as_str()),
            (Encoding::Cdr, Some("ros2msg"), "int32 a\n")
        );
    }

    #[test]
    fn a_json_topic_of_a_known_type_is_cdr_with_the_full_definition_and_dependencies() {
        let tc = RegistryTranscoder::bundled();
        let f = ChannelForm::of(&Schema::named("sensor_msgs/msg/LaserScan"), &tc);
        assert_eq!(f.encoding, Encoding::Cdr);
        assert_eq!(f.schema_encoding, Some("ros2msg"));
        // The header's definition travels with the scan's, as MCAP and Foxglove want it.
        assert!(f.schema.contains("float32[] ranges"), "{}", f.schema);
        assert!(f.schema.contains("MSG: std_msgs/Header"), "{}", f.schema);
    }

    #[test]
    fn an_unknown_type_is_schemaless_json() {
        let f = ChannelForm::of(
            &Schema::named("my_pkg/msg/Nobody"),
            &RegistryTranscoder::bundled(),
        );
        assert_eq!(
            (f.encoding, f.schema.as_str(), f.schema_encoding),
            (Encoding::Json, "", None)
        );
        assert_eq!(f.channel(1, "/x").encoding, "json");
    }

    #[test]
    fn client_encodings_are_the_three_the_router_takes() {
        for name in CLIENT_ENCODINGS {
            let e = from_wire_name(name).expect("known");
            assert_eq!(wire_name(e), name);
        }
        assert_eq!(from_wire_name("protobuf"), None);
    }
}
