//! The `lightlab` command line's subcommands, each as a library module so the
//! binary stays a thin dispatcher and tests can call the logic directly.
//!
//! | subcommand | module |
//! | --- | --- |
//! | `lightlab shade` | [`shade`] |
//! | `lightlab render` | [`render`] |
//! | `lightlab bench` | [`bench`] |
//! | `lightlab study` | [`study`] |

pub mod bench;
pub mod render;
pub mod shade;
pub mod study;
