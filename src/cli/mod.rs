//! Command-line subcommands, each an `Args` struct and a `run` function.

pub mod bench;
pub mod render;
