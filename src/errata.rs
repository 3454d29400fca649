//! Every number the tutorials print, recomputed.
