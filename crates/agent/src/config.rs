//! Agent configuration (YAML).
