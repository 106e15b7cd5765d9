//! One module per subcommand.

pub mod msg;
pub mod qoi_sim;
