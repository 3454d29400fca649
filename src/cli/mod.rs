//! The command-line subcommands of `lightlab` (feature `book`), one module each.

#[cfg(feature = "gl")]
pub mod check_shader;
#[cfg(feature = "gl")]
pub mod oracle;
