//! ROS interface model: parser, registry and dynamic codecs (see issue 4).
