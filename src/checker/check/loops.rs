//! The loop guard: every loop of a learner's shader also counts its iterations, so a loop
//! that never ends is reported as such instead of being graded.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | cap | [`LOOP_CAP`], loop iterations one fragment (one case) may run in all its loops |
//! | mark | [`LOOP_MARK`], the value a capped case writes to every output channel |
//!
//! Mesa's llvmpipe ends every loop after 65 535 iterations (gallivm's
//! `LP_MAX_TGSI_LOOP_ITERATIONS`) and carries on, so `while (k > 0.0) k += 1.0;` finishes
//! there with some colour that may even agree. On a GPU the same shader hangs. With the
//! guard, `while (c)` becomes `while ((c) && lightlab_loop())` and `for (a; c; b)` becomes
//! `for (a; (c) && lightlab_loop(); b)`, on the same line (an empty `c` is `true`);
//! `lightlab_loop()` counts, and turns false past the cap. The cap is below the driver's
//! limit, so an endless loop meets the cap first, and the case is marked.
//!
//! The page (`book/theme/live/lightlab-gl.js`, `guardLoops`) rewrites the reader's text in
//! the same way, with the same cap and mark, read from the data the crate emits
//! ([`crate::live`]'s `guard`). The learner's text exists only in the page there, so the
//! rewrite is written twice; the numbers are not.

use super::glsl::blank_comments;

/// Loop iterations one case may run in all its loops together. The tutorials' loops run
/// at most 256 times a fragment (the floor-lights256 scene), so no correct shader comes
/// near it; it stays under llvmpipe's 65 535 iterations of one loop (see the module docs),
/// so an endless loop is seen by the guard before the driver ends it silently.
pub const LOOP_CAP: u32 = 60_000;
// gallivm's LP_MAX_TGSI_LOOP_ITERATIONS (65 535), the driver's silent end of one loop.
const _: () = assert!(LOOP_CAP < 65_535, "the cap must stop an endless loop before llvmpipe does");
/// The value a case writes to every output channel when the cap stopped one of its loops
/// (the page's checker looks for it in the alpha of a `vec4` output, or in all three
/// channels of a `vec3` one). A lighting shader writes colours, not −7777.
pub const LOOP_MARK: f32 = -7777.0;

/// The declarations the guarded text needs, on one line (no newline inside, so the
/// caller's `#line` numbering stays right when it adds exactly one line).
#[must_use]
pub fn loop_header() -> String {
    format!(
        "int lightlab_loops = 0; bool lightlab_loop() {{ lightlab_loops++; return lightlab_loops <= {LOOP_CAP}; }}\n"
    )
}

/// `source` with every `for` and `while` condition also counting iterations (see the
/// module docs), and the number of loops rewritten. Comments are skipped; loops inside a
/// `#define` are rewritten too, since they run wherever the macro is used. A loop whose
/// parentheses do not close is left as it is (the driver names the error).
#[must_use]
pub fn guard_loops(source: &str) -> (String, usize) {
    let text = blank_comments(source);
    let bytes = text.as_bytes();
    let mut out = String::with_capacity(source.len() + 64);
    let (mut last, mut loops, mut i) = (0, 0, 0);
    while let Some((keyword_end, is_for)) = next_loop_keyword(bytes, i) {
        i = keyword_end;
        let Some(open) = skip_spaces(bytes, keyword_end).filter(|&k| bytes[k] == b'(') else { continue };
        let Some(close) = closing(bytes, open) else { break };
        let (from, to) = if is_for {
            match top_level_semicolons(bytes, open + 1, close)[..] {
                [a, b] => (a + 1, b),
                _ => continue,
            }
        } else {
            (open + 1, close)
        };
        let condition = &source[from..to];
        let condition = if condition.trim().is_empty() { "true" } else { condition };
        out += &source[last..from];
        out += &format!("({condition}) && lightlab_loop()");
        last = to;
        loops += 1;
        // Nothing inside the parentheses is a loop of its own (hostile text may say so).
        i = close + 1;
    }
    out += &source[last..];
    (out, loops)
}

/// Whether a case's output carries the mark (every channel of the colour).
#[must_use]
pub fn marked(colour: &[f32; 4]) -> bool {
    colour[..3].iter().all(|&c| c == LOOP_MARK)
}

/// The next `for` or `while` keyword (a whole word) at or after `from`: one past its end,
/// and whether it is `for`.
fn next_loop_keyword(b: &[u8], from: usize) -> Option<(usize, bool)> {
    let word = |c: u8| c.is_ascii_alphanumeric() || c == b'_';
    let mut i = from;
    while i < b.len() {
        if word(b[i]) {
            let start = i;
            while i < b.len() && word(b[i]) {
                i += 1;
            }
            match &b[start..i] {
                b"for" => return Some((i, true)),
                b"while" => return Some((i, false)),
                _ => {}
            }
        } else {
            i += 1;
        }
    }
    None
}

/// The first byte at or after `i` that is not white space.
fn skip_spaces(b: &[u8], mut i: usize) -> Option<usize> {
    while i < b.len() && b[i].is_ascii_whitespace() {
        i += 1;
    }
    (i < b.len()).then_some(i)
}

/// The `)` that closes the `(` at `open`.
fn closing(b: &[u8], open: usize) -> Option<usize> {
    let mut depth = 0usize;
    for (k, &c) in b.iter().enumerate().skip(open) {
        match c {
            b'(' => depth += 1,
            b')' => {
                depth -= 1;
                if depth == 0 {
                    return Some(k);
                }
            }
            _ => {}
        }
    }
    None
}

/// The `;` inside `b[from..to]` outside any parentheses.
fn top_level_semicolons(b: &[u8], from: usize, to: usize) -> Vec<usize> {
    let mut depth = 0i32;
    let mut out = Vec::new();
    for (k, &c) in b.iter().enumerate().take(to).skip(from) {
        match c {
            b'(' => depth += 1,
            b')' => depth -= 1,
            b';' if depth == 0 => out.push(k),
            _ => {}
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn while_and_for_conditions_count_iterations_on_the_same_line() {
        let (text, n) = guard_loops("while (k > 0.0) k += 1.0;\nfor (int i = 0; i < 4; i++) { }\n");
        assert_eq!(n, 2);
        assert_eq!(
            text,
            "while ((k > 0.0) && lightlab_loop()) k += 1.0;\nfor (int i = 0;( i < 4) && lightlab_loop(); i++) { }\n"
        );
    }

    #[test]
    fn an_empty_for_condition_becomes_true_and_do_while_is_guarded() {
        let (text, n) = guard_loops("for(;;){}\ndo { x(); } while(f(a, b));");
        assert_eq!(n, 2);
        assert!(text.contains("for(;(true) && lightlab_loop();)"), "{text}");
        assert!(text.contains("while((f(a, b)) && lightlab_loop())"), "{text}");
    }

    #[test]
    fn comments_and_longer_words_are_left_alone() {
        let src = "// while (true)\nfloat fortune = 1.0; /* for (;;) */ int whileX = 2;\n";
        assert_eq!(guard_loops(src), (src.to_string(), 0));
    }

    #[test]
    fn a_loop_in_a_macro_is_guarded_and_an_unclosed_one_is_left() {
        let (text, n) = guard_loops("#define SPIN while (true) {}\nSPIN\n");
        assert_eq!(n, 1);
        assert!(text.starts_with("#define SPIN while ((true) && lightlab_loop()) {}\n"), "{text}");
        let unclosed = "while (a < (b) {";
        assert_eq!(guard_loops(unclosed), (unclosed.to_string(), 0));
    }

    #[test]
    fn the_line_count_stays() {
        let src = "for (int i = 0;\n i < n;\n i++)\n{\n while (\n x) {}\n}\n";
        let (text, n) = guard_loops(src);
        assert_eq!(n, 2);
        assert_eq!(text.lines().count(), src.lines().count());
        assert_eq!(loop_header().matches('\n').count(), 1);
    }

    #[test]
    fn only_a_fully_marked_colour_is_marked() {
        assert!(marked(&[LOOP_MARK, LOOP_MARK, LOOP_MARK, 1.0]));
        assert!(!marked(&[LOOP_MARK, 0.0, LOOP_MARK, 1.0]));
        assert!(!marked(&[0.5, 0.5, 0.5, LOOP_MARK]));
    }

    #[test]
    fn keywords_inside_a_condition_do_not_split_it() {
        // Invalid GLSL, but a learner's file may hold anything: the rewrite must not panic
        // and must keep every byte.
        let src = "while (for (;;)) {} while (x) {}";
        let (text, n) = guard_loops(src);
        assert_eq!(n, 2);
        assert_eq!(text, "while ((for (;;)) && lightlab_loop()) {} while ((x) && lightlab_loop()) {}");
    }
}
