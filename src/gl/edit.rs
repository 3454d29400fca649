//! Text edits of a GLSL function file, written once: the checker's mistakes rewrite the
//! verified files with them ([`crate::checker::mistakes`]), and a model whose shader is
//! another's with a term added is made from that one's file with them
//! ([`crate::gl::models`], `lighting_maps_emission` from `lighting_maps.glsl`).
//!
//! | symbol | meaning |
//! | --- | --- |
//! | [`Edit`] | `(from, to)`: replace every occurrence of `from` by `to` |
//! | step | alternatives, `&[Edit]`: each that occurs is applied; at least one must |

/// One edit: replace every occurrence of `from` by `to`.
pub type Edit = (&'static str, &'static str);

/// `text` with every step applied: in each step, every alternative that occurs replaces all
/// its occurrences. Errors: the first pattern of the first step that matches nothing.
pub fn apply_steps(steps: &[&[Edit]], text: &str) -> Result<String, &'static str> {
    let mut text = text.to_string();
    for step in steps {
        let mut matched = false;
        for (from, to) in *step {
            if text.contains(from) {
                text = text.replace(from, to);
                matched = true;
            }
        }
        if !matched {
            return Err(step.first().map_or("", |e| e.0));
        }
    }
    Ok(text)
}
