//! Checking a learner's shader: run it on llvmpipe against a model's `f64` reference
//! (`lightlab check-shader`, the exercises, `lightlab grade`), and when it disagrees, name
//! the mistake.
//!
//! The work comes in two stages, and the files follow them:
//!
//! | stage | module | what it holds |
//! | --- | --- | --- |
//! | check: does the shader agree? | [`check`] | the run of one fragment shader: `glsl` (the scanner), `mapping` (the `--uniforms` file and name matching), `rewrite` (the shader turned into a batch body), `loops` (the loop guard), `characters` (pasted characters), `report` (the comparison), `pair` (a vertex + fragment pair on triangles) |
//! | diagnose: which mistake? | [`diagnose`] | the steps of the diagnosis and its verdict sentences |
//! | | [`mistakes`] | the mistake catalogue, each mistake a rewrite of the function files |
//! | | [`sites`] | a catalogue mistake applied inside one function only |
//! | | [`outputs`] | the function files and their mutants run on a check's cases, two runs compared |
//! | | [`two_mistakes`] | two mutants at once |
//! | | [`isolation`] | no mutant matches: terms and lights switched off to say where the difference lives |
//! | | [`verdict`] | the rule on one case, and one entry of a diagnosis |
//! | | [`hints`] | three hints per mistake |
//! | | [`texts`] | the checker's sentences as msgids, looked up in the reader's language |
//! | | [`complete`] | complete fragment shaders built from the function files (a starter, a mutant to show) |
//!
//! `check/` keeps its own directory because it is a unit: it is all `check-shader` needs to
//! give a verdict, and its files are steps of one run (scanned, mapped, rewritten, run,
//! compared). The diagnosis files sit beside it, one per concept, because each is used on
//! its own as well: the live pages and the exercises take the catalogue, the sites and the
//! isolation's hints without running a check.
//!
//! The checker runs on [`crate::gl`] (context, batches, layouts, the tutorials' GLSL) and
//! draws its cases, bounds and error statistics from [`crate::oracle`]; neither depends on
//! it.

pub mod check;
pub mod complete;
pub mod diagnose;
pub mod hints;
pub mod isolation;
pub mod mistakes;
pub mod outputs;
pub mod sites;
pub mod texts;
pub mod two_mistakes;
pub mod verdict;
