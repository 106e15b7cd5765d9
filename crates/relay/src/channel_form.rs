//! What a topic looks like to a typed consumer — a Foxglove client, an MCAP file: the
//! one message encoding in which every message of the topic can be given, with a schema
//! the consumer can parse.
//!
//! - a ROS 1 topic (its definition came as `ros1msg`, from the ROS 1 adapter) is `ros1`
//!   with the `ros1msg` text: messages go as the robot's bytes;
//! - a ROS 2 topic, and any topic whose type the hub's registry knows (the simulator's
//!   and rosbridge publishers' JSON included), is `cdr` with the `ros2msg` text: CDR
//!   messages go as they came, others are converted once per message and shared by every
//!   consumer ([`crate::Message::payload_in`]);
//! - a type nobody defined (a rosbridge client's JSON of a custom type) is `json` without
//!   a schema, its messages as JSON.
//!
//! The names of the encodings are those Foxglove's protocol and MCAP's well-known
//! encodings share.

use fleetlink_proto::{Encoding, Schema};

use crate::Transcoder;

/// A topic's typed form.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ChannelForm {
    /// What the messages are given as.
    pub encoding: Encoding,
    pub schema_name: String,
    /// The full definition with its dependencies; empty for schemaless JSON.
    pub schema: String,
    /// `ros1msg` or `ros2msg`; `None` for schemaless JSON.
    pub schema_encoding: Option<&'static str>,
}

impl ChannelForm {
    /// The form of a topic with this schema.
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
            return match known.encoding.as_str() {
                "ros1msg" => with_text(Encoding::Ros1, "ros1msg", &known.text),
                _ => with_text(Encoding::Cdr, "ros2msg", &known.text),
            };
        }
        ChannelForm {
            encoding: Encoding::Json,
            schema_name: schema.type_name.clone(),
            schema: String::new(),
            schema_encoding: None,
        }
    }
}

/// An encoding as Foxglove's protocol and MCAP name it.
pub fn wire_name(e: Encoding) -> &'static str {
    match e {
        Encoding::Cdr => "cdr",
        Encoding::Ros1 => "ros1",
        // CBOR has no well-known name of its own: such messages are given as JSON.
        Encoding::Json | Encoding::Cbor => "json",
    }
}

/// The encoding a name stands for; `None` for one the hub cannot take.
pub fn from_wire_name(name: &str) -> Option<Encoding> {
    Some(match name {
        "cdr" => Encoding::Cdr,
        "ros1" => Encoding::Ros1,
        "json" => Encoding::Json,
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::GenericTranscoder;
    use crate::transcode::RegistryTranscoder;

    fn schema(type_name: &str, encoding: &str, text: &str) -> Schema {
        Schema {
            type_name: type_name.into(),
            encoding: encoding.into(),
            text: text.into(),
        }
    }

    #[test]
    fn a_ros1_topic_is_ros1_with_its_own_definition() {
        let s = schema("sensor_msgs/LaserScan", "ros1msg", "float32 angle_min\n");
        let f = ChannelForm::of(&s, &GenericTranscoder);
        assert_eq!(
            (f.encoding, f.schema_encoding, f.schema.as_str()),
            (Encoding::Ros1, Some("ros1msg"), "float32 angle_min\n")
        );
    }

    #[test]
    fn a_ros2_topic_is_cdr_with_its_own_definition() {
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
    }

    #[test]
    fn wire_names_round_trip() {
        for e in [Encoding::Cdr, Encoding::Ros1, Encoding::Json] {
            assert_eq!(from_wire_name(wire_name(e)), Some(e));
        }
        assert_eq!(wire_name(Encoding::Cbor), "json");
        assert_eq!(from_wire_name("protobuf"), None);
    }
}
