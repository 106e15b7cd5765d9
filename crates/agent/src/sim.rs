//! Simulated robot data.
