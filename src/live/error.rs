//! The one error type of the live figures: every way building a figure, a program, an asset
//! or a generated file can fail, each naming the figure, model, asset or file involved.

/// Why a live figure, program, asset or generated file could not be built.
///
/// Cloneable so that the once-per-process [`super::files`] can hand the same error to every
/// caller.
#[derive(Debug, Clone, thiserror::Error)]
pub enum LiveError {
    /// A figure's spec contradicts itself (points, panels, controls, editor).
    #[error("live figure {id}: {what}")]
    Spec {
        /// The figure id.
        id: &'static str,
        /// What is inconsistent.
        what: String,
    },
    /// Building a figure's programs or reference images failed.
    #[error("live figure {id}: {source}")]
    InFigure {
        /// The figure id.
        id: &'static str,
        /// What failed.
        source: Box<LiveError>,
    },
    /// A mesh or texture name no asset answers to.
    #[error("unknown {kind} '{name}'")]
    UnknownAsset {
        /// `"mesh"` or `"texture"`.
        kind: &'static str,
        /// The name asked for.
        name: String,
    },
    /// A model with no GLSL function file.
    #[error("no function file for model '{0}'")]
    NoFunctionFile(String),
    /// A function file uses something GLSL ES 3.00 does not have.
    #[error("line {line}: '{token}' has no place in a function file shared with GLSL ES")]
    NotEs {
        /// 1-based line in the function file.
        line: usize,
        /// The offending token.
        token: String,
    },
    /// The Blinn swap's anchor text is gone from `basic_lighting.glsl`.
    #[error("basic_lighting.glsl no longer contains '{0}': update the Blinn swap")]
    BlinnSwap(String),
    /// Making a texture, map or framebuffer failed (`what` names it).
    #[error("{what}: {detail}")]
    Asset {
        /// The thing being made.
        what: &'static str,
        /// The underlying error, as text.
        detail: String,
    },
    /// Encoding a reference PNG failed.
    #[error("encoding the reference PNG: {0}")]
    Png(String),
    /// The built figures and [`super::IDS`] disagree.
    #[error("live figures built {built:?}, listed {listed:?}")]
    Ids {
        /// The ids built, in order.
        built: Vec<&'static str>,
        /// The ids listed.
        listed: &'static [&'static str],
    },
    /// The page exercises' data could not be made (the message names the exercise).
    #[error("page exercises: {0}")]
    Exercises(String),
    /// A path [`super::files`] does not make.
    #[error("no live file {0}: update live::artifacts()")]
    NoFile(String),
}
