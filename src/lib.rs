//! lightlab
