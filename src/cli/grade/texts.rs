//! The words of the feedback pages and of the Markdown that the gradescope and
//! prairielearn formats carry, as English msgids of `po/messages.pot` (listed by
//! [`crate::cli::messages`]), looked up in the grading's language ([`lang`]).
//!
//! JSON keys, the csv and json verdicts and the mistake ids stay English: scripts read them.

use crate::i18n::Lang;

/// The teacher's line on standard error for a group of near-identical submissions (`{}`:
/// their names).
pub const NEAR_IDENTICAL: &str = "near-identical (the same tokens once names and spacing are normalized): {}";
/// The page's title (`{}`: the student).
pub const FEEDBACK_TITLE: &str = "Feedback: {}";
/// The verdict line of an answer that agrees (`{}`: the score out of 100).
pub const VERDICT_AGREES: &str = "Verdict: agrees — score {} / 100";
/// The verdict line of an answer that disagrees (`{}`: the score out of 100).
pub const VERDICT_DISAGREES: &str = "Verdict: disagrees — score {} / 100";
/// The verdict line of a submission that could not be checked (`{}`: the score out of 100).
pub const VERDICT_ERROR: &str = "Verdict: error — score {} / 100";
/// The label of the error.
pub const ERROR: &str = "Error:";
/// The label of the named mistake.
pub const MISTAKE: &str = "Mistake:";
/// The label of the hint.
pub const HINT: &str = "Hint:";
/// The label of the counterexample.
pub const A_CASE: &str = "A case where it differs:";
/// The picture's text alternative, and PrairieLearn's image label.
pub const PICTURE_ALT: &str = "your shader, the reference, the difference";
/// The picture's caption.
pub const CAPTION: &str = "Left: your shader; middle: the reference; right: the difference (black: none; red, \
                           yellow, white: up to 0.25 and more), on the Basic lighting scene: a full-screen quad lit \
                           from (1.2, 1, 2).";
/// The picture's caption on Light casters' flashlight scene (spot-light exercises).
pub const CAPTION_SPOT: &str = "Left: your shader; middle: the reference; right: the difference (black: none; red, \
                                yellow, white: up to 0.25 and more), on the Light casters scene: a full-screen quad \
                                under a flashlight at the camera, aimed straight ahead (cut-offs 12.5° and 17.5°).";
/// The label of the reason why a page has no picture (`{}`: the reason).
pub const NO_PICTURE: &str = "No picture: it could not be drawn ({}).";
/// Gradescope's and PrairieLearn's message when the folder holds no submission.
pub const ONE_SUBMISSION_NONE: &str = "No submission was found: hand in one fragment shader (.frag, .glsl or .fs), \
                                       or one vertex and fragment shader pair.";
/// Gradescope's and PrairieLearn's message when the folder holds several submissions
/// (`{}`: their names).
pub const ONE_SUBMISSION_MANY: &str = "Several submissions were found ({}): hand in one fragment shader, or one \
                                       vertex and fragment shader pair, and remove the others.";
/// The hint when the check isolated a term and a light but named no mistake.
pub const HINT_ISOLATED: &str = "Look at the term and the light the check isolated: write down, for one of the \
                                 cases below, what each factor of that term should be, and compare with what your \
                                 shader computes.";
/// The hint for a named mistake with a book page (`{}`: the page).
pub const HINT_READ: &str = "Read the book's section on this mistake ({}) and ask which vector or factor in your \
                             shader plays the role it describes.";
/// The hint for a named mistake without a book page.
pub const HINT_CONVENTIONS: &str = "Compare each vector in your shader with the chapter's conventions (unit \
                                    length, pointing away from the surface).";
/// The hint for a wrong number or letter.
pub const HINT_ANSWER: &str = "Go back to the exercise's statement and to the part of the chapter it \
                                   comes from, and work the answer out again, one step at a time.";
/// The label of a finding that names no mistake (an isolation, or a difference the check
/// could not narrow).
pub const DIFFERENCE: &str = "Where it differs:";
/// The hint of a row whose shader does not compile, run or end.
pub const HINT_ERROR: &str = "Fix the error above first: the check can only judge a shader that compiles and runs.";
/// The files that were not graded (`{}`: their names).
pub const NOT_GRADED: &str = "Not graded (not submissions): {}";
/// PrairieLearn's message when the submission cannot be graded.
pub const PL_UNGRADABLE: &str = "The submission could not be graded: fix the errors below and submit again.";
/// PrairieLearn's message when every answer agrees.
pub const PL_AGREES: &str = "Your shader agrees with the reference.";
/// PrairieLearn's message when some answer disagrees.
pub const PL_DISAGREES: &str = "Your shader disagrees with the reference: see each test.";

/// Every text above, for the translation template.
pub const ALL: &[&str] = &[
    NEAR_IDENTICAL,
    FOLDER_NO_SHADER,
    FOLDER_VERTEX_ALONE,
    FOLDER_SEVERAL_VERTEX,
    FOLDER_SEVERAL_FRAGMENT,
    PATTERN_NO_MATCH,
    PATTERN_SEVERAL,
    PATTERN_NO_MATCH_VERTEX,
    PATTERN_SAME_FILE,
    ENTRY_OUTSIDE,
    ENTRY_OUTSIDE_CLASS,
    ENTRY_SELF_LINK,
    ENTRY_SPECIAL,
    ENTRY_BROKEN,
    FOLDER_UNREADABLE,
    FOUND_TOO_DEEP,
    ROW_DOES_NOT_COMPILE,
    ROW_ONE_ANSWER_FILE,
    ROW_NO_RESULT,
    ROW_UNREADABLE,
    ROW_NOT_RUN,
    FEEDBACK_TITLE,
    VERDICT_AGREES,
    VERDICT_DISAGREES,
    VERDICT_ERROR,
    ERROR,
    MISTAKE,
    HINT,
    A_CASE,
    PICTURE_ALT,
    CAPTION,
    CAPTION_SPOT,
    NO_PICTURE,
    ONE_SUBMISSION_NONE,
    ONE_SUBMISSION_MANY,
    HINT_ISOLATED,
    HINT_READ,
    HINT_CONVENTIONS,
    HINT_ERROR,
    HINT_ANSWER,
    DIFFERENCE,
    NOT_GRADED,
    PL_UNGRADABLE,
    PL_AGREES,
    PL_DISAGREES,
];

/// The error row of a student's folder with no submission in it.
pub const FOLDER_NO_SHADER: &str = "no fragment shader (.frag, .glsl, .fs) or answer file (.txt) in it";
/// A folder with vertex shaders only (their names).
pub const FOLDER_VERTEX_ALONE: &str = "a vertex shader alone ({}): hand in its fragment shader beside it";
/// A folder with several vertex shaders (their names).
pub const FOLDER_SEVERAL_VERTEX: &str = "several vertex shaders ({}): keep one";
/// A folder with several fragment shaders (their names).
pub const FOLDER_SEVERAL_FRAGMENT: &str = "several fragment shaders ({}): keep one fragment shader (a vertex shader \
                                           beside it is recognised by its name, .vert, .vs or vert, vs, vertex in \
                                           the name, or by writing gl_Position), or name the answer with grade's \
                                           --files PATTERN (a LearnOpenGL project's lamp shader: --files '*lighting*')";
/// No file of a student's folder matches the pattern (the pattern).
pub const PATTERN_NO_MATCH: &str = "no file matches `{}`: not handed in";
/// Several files match a pattern: the pattern, the files.
pub const PATTERN_SEVERAL: &str = "several files match `{}` ({}): keep one, or make the pattern name one file";
/// No file of a student's folder matches the vertex shader's pattern (the pattern).
pub const PATTERN_NO_MATCH_VERTEX: &str = "no vertex shader matches `{}`: not handed in";
/// The fragment and the vertex pattern pick the same file (its name).
pub const PATTERN_SAME_FILE: &str = "the fragment and the vertex shader patterns pick the same file ({}): the \
                                     fragment pattern must name another file";

/// A file or folder of a student's that is a symbolic link leading outside the student's
/// own folder (its name inside the folder).
pub const ENTRY_OUTSIDE: &str = "{} is a symbolic link that leads outside the student's folder: refused, not read";
/// A class folder's entry that is a symbolic link leading outside the class folder.
pub const ENTRY_OUTSIDE_CLASS: &str = "a symbolic link that leads outside the class folder: refused, not read";
/// A student's entry that is a symbolic link to the class folder itself.
pub const ENTRY_SELF_LINK: &str = "a symbolic link to the class folder itself: refused, not read";
/// A submission that is a FIFO, a device or a socket (its name).
pub const ENTRY_SPECIAL: &str = "{}: not a regular file (a FIFO, device or socket)";
/// A submission that cannot be opened (its name, the system's reason).
pub const ENTRY_BROKEN: &str = "{} cannot be opened: {}";
/// A folder that cannot be listed (the folder, the system's reason).
pub const FOLDER_UNREADABLE: &str = "cannot read the folder {}: {}";
/// A shader found below the depth where shaders are looked for (the file, the depth).
pub const FOUND_TOO_DEEP: &str = "{} was found deeper than {} folders, where shaders are not looked for: move it up";

/// A shader that does not compile (the driver's log and the lines it points at).
pub const ROW_DOES_NOT_COMPILE: &str = "does not compile: {}";
/// A pair handed in for an exercise answered in a text file (the exercise id).
pub const ROW_ONE_ANSWER_FILE: &str = "exercise {} takes one answer file, not a shader pair";
/// The checking child ended without a result (killed from outside).
pub const ROW_NO_RESULT: &str = "the check ended without a result";
/// The checking child's output could not be read (the reason, its standard error).
pub const ROW_UNREADABLE: &str = "unreadable result of the check ({}): {}";
/// A job that never ran (a lightlab defect).
pub const ROW_NOT_RUN: &str = "the check did not run (internal error)";

/// The grading's language: the command line's (`--lang`, else the assignment's `lang`,
/// else `LIGHTLAB_LANG` or the locale; see [`super::run()`]).
pub fn lang() -> Lang {
    crate::i18n::output_lang()
}

/// `msgid` in the grading's language.
pub fn tr(msgid: &str) -> String {
    crate::i18n::tr(lang(), msgid).into_owned()
}

/// [`tr`], then each `{}` filled in order.
pub fn tr_fill(msgid: &str, args: &[&str]) -> String {
    crate::i18n::catalog::tr_fill(lang(), msgid, args)
}

/// The verdict line of a row (`agrees`, `disagrees`, `error`) with its score.
pub fn verdict_line(verdict: &str, score: u32) -> String {
    let msgid = match verdict {
        "agrees" => VERDICT_AGREES,
        "disagrees" => VERDICT_DISAGREES,
        _ => VERDICT_ERROR,
    };
    tr_fill(msgid, &[&score.to_string()])
}
