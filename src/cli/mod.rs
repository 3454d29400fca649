//! The `lightlab` command line's subcommands, each as a library module so the
//! binary stays a thin dispatcher and tests can call the logic directly.
//!
//! | subcommand | module |
//! | --- | --- |
//! | `lightlab shade` | [`shade`] |
//! | `lightlab render` | [`render`] |
//! | `lightlab bench` | [`bench`](mod@bench) |
//! | `lightlab check-shader` (feature `gl`) | `check_shader` |
//! | `lightlab oracle` (feature `gl`) | `oracle` |
//! | `lightlab exercise` (feature `gl`) | `exercise` |
//! | `lightlab grade` (feature `gl`) | `grade` |
//! | `lightlab study` | [`study`] |

pub mod bench;
pub mod render;
pub mod shade;
pub mod study;

#[cfg(feature = "gl")]
pub mod check_shader;
#[cfg(feature = "gl")]
pub mod exercise;
#[cfg(feature = "gl")]
pub mod grade;
#[cfg(feature = "gl")]
pub mod oracle;
