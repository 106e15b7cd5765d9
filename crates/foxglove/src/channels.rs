//! A topic as a Foxglove channel: its typed form ([`ChannelForm`], shared with the
//! hub's MCAP recorder) under this session's channel id.

pub use fleetlink_relay::channel_form::{ChannelForm, from_wire_name, wire_name};

use crate::protocol::Channel;

/// The advertisement of a topic of this form as channel `id` on `topic`.
pub fn advertised(form: &ChannelForm, id: u32, topic: &str) -> Channel {
    Channel {
        id,
        topic: topic.to_owned(),
        encoding: wire_name(form.encoding),
        schema_name: form.schema_name.clone(),
        schema: form.schema.clone(),
        schema_encoding: form.schema_encoding,
    }
}

/// The encodings clients may publish and call with (`supportedEncodings`).
pub const CLIENT_ENCODINGS: [&str; 3] = ["json", "cdr", "ros1"];

#[cfg(test)]
mod tests {
    use super::*;
    use fleetlink_proto::{Encoding, Schema};
    use fleetlink_relay::GenericTranscoder;

    #[test]
    fn a_ros1_topic_is_advertised_as_a_ros1_channel_with_its_own_definition() {
        let s = Schema {
            type_name: "sensor_msgs/LaserScan".into(),
            encoding: "ros1msg".into(),
            text: "float32 angle_min\n".into(),
        };
        let c = advertised(&ChannelForm::of(&s, &GenericTranscoder), 4, "/r1/scan");
        assert_eq!(
            (c.id, c.topic.as_str(), c.encoding, c.schema_encoding),
            (4, "/r1/scan", "ros1", Some("ros1msg"))
        );
        assert_eq!(c.schema, "float32 angle_min\n");
    }

    #[test]
    fn client_encodings_are_the_three_the_router_takes() {
        for name in CLIENT_ENCODINGS {
            let e = from_wire_name(name).expect("known");
            assert_eq!(wire_name(e), name);
        }
        assert_eq!(from_wire_name("protobuf"), None);
        assert_eq!(wire_name(Encoding::Cbor), "json");
    }
}
