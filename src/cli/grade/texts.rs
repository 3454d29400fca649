//! The words of the feedback pages and of the Markdown that the gradescope and
//! prairielearn formats carry, as English msgids of `po/messages.pot` (listed by
//! [`crate::cli::messages`]), looked up in the grading's language ([`lang`]).
//!
//! JSON keys, the csv and json verdicts and the mistake ids stay English: scripts read them.

use crate::i18n::Lang;

/// The teacher's line on standard error for a group of near-identical submissions (`{}`:
/// their names).
pub const NEAR_IDENTICAL: &str =
    "near-identical (the same tokens once comments are dropped and names and spacing normalized): {}";
/// The page's title (`{}`: the student).
pub const FEEDBACK_TITLE: &str = "Feedback: {}";
/// The verdict line of an answer that agrees (`{}`: the score out of 100).
pub const VERDICT_AGREES: &str = "Verdict: agrees — score {} / 100";
/// The verdict line of an answer that disagrees (`{}`: the score out of 100).
pub const VERDICT_DISAGREES: &str = "Verdict: disagrees — score {} / 100";
/// The verdict line of a submission that could not be checked (`{}`: the score out of 100).
pub const VERDICT_ERROR: &str = "Verdict: error — score {} / 100";
/// A Moodle feedback cell's verdict of an answer that agrees (`{}`: the exercise id, the
/// score out of 100).
pub const CELL_AGREES: &str = "{}: agrees ({}/100)";
/// A Moodle feedback cell's verdict of an answer that disagrees.
pub const CELL_DISAGREES: &str = "{}: disagrees ({}/100)";
/// A Moodle feedback cell's verdict of a submission that could not be checked.
pub const CELL_ERROR: &str = "{}: error ({}/100)";
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
    CELL_AGREES,
    CELL_DISAGREES,
    CELL_ERROR,
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

// The teacher's usage errors: the assignment file, the patterns, the outputs and the
// Moodle files (printed on standard error, in the class's language once it is known).

/// An assignment file's error (`{}`: the file, the error).
pub const ASSIGNMENT_FILE: &str = "assignment {}: {}";
/// A Moodle worksheet's error (`{}`: the file, the error).
pub const WORKSHEET_FILE: &str = "worksheet {}: {}";
/// A `--map` file's error (`{}`: the file, the error).
pub const MAP_FILE: &str = "map {}: {}";
/// A file that is not UTF-8 text.
pub const NOT_UTF8: &str = "not UTF-8 text";
/// An error at a line of a file (`{}`: the line, the error).
pub const AT_LINE: &str = "line {}: {}";
/// What is wrong with an assignment's field (`{}`: the TOML field as written, e.g.
/// `exercise.weight`, and why).
pub const AT_FIELD: &str = "{}: {}";
/// A TOML syntax error at a line (`{}`: the line, the line's text, the parser's message).
pub const AT_LINE_SHOWN: &str = "line {} (`{}`): {}";
/// An assignment with no exercise.
pub const NO_EXERCISE: &str = "no [[exercise]]";
/// An exercise listed twice (`{}`: the id, the line of its first listing).
pub const LISTED_TWICE: &str = "`{}` is already listed at line {}: list each exercise once";
/// A weight that is not a number of points (`{}`: the value).
pub const NOT_POINTS: &str = "{} is not a number of points ≥ 0";
/// A `partial` that is none of its forms (`{}`: the value).
pub const BAD_PARTIAL: &str = "`{}` is not \"cases\", \"none\" or a number 0 to 100";
/// A mistake's credit out of range (`{}`: the value).
pub const BAD_CREDIT: &str = "`{}` is not a credit 0 to 100";
/// A mistake id the catalogue does not have.
pub const NO_SUCH_MISTAKE: &str = "no such mistake in the catalogue";
/// A mistake the exercise's check can never name (`{}`: the exercise, its model, its mistakes).
pub const NOT_MISTAKE_OF: &str = "not a mistake of exercise {} (model {}); its mistakes: {}";
/// Credits for an exercise answered by a number or a letter (`{}`: the exercise).
pub const NO_NAMED_MISTAKES: &str = "exercise {} is answered by a number or a letter: it has no named mistakes";
/// A pair exercise without its vertex pattern (`{}`: the exercise, the option or field).
pub const PAIR_NEEDS_VERTEX: &str =
    "exercise {} is checked as a pair: give {} PATTERN, the pattern of its vertex shader";
/// A vertex pattern for an exercise that takes no vertex shader (`{}`: the option or field,
/// the exercise).
pub const TAKES_NO_VERTEX: &str = "{}: exercise {} takes no vertex shader";
/// `--vertex` without `--files`.
pub const VERTEX_NEEDS_FILES: &str =
    "--vertex picks the vertex shader beside the fragment shader that --files picks: give --files too";
/// An empty pattern.
pub const PATTERN_EMPTY: &str = "an empty pattern matches no file; leave the field out for any fragment shader";
/// A pattern character that is not supported (`{}`: the character).
pub const PATTERN_UNSUPPORTED: &str = "`{}` is not supported (use *, ?, **, / and {a,b})";
/// A pattern that leaves the student's folder.
pub const PATTERN_OUTSIDE: &str =
    "a pattern is a path inside the student's folder: no leading `/`, no `..`, no empty folder";
/// Braces inside braces.
pub const PATTERN_NESTED: &str = "nested braces are not supported";
/// A closing brace without its opening one.
pub const PATTERN_UNOPENED: &str = "a `}` without its `{`";
/// An opening brace without its closing one.
pub const PATTERN_UNCLOSED: &str = "a `{` without its `}`";
/// Neither an exercise nor an assignment.
pub const NO_EXERCISE_GIVEN: &str = "give --exercise ID or --assignment FILE";
/// A worksheet without the Moodle format.
pub const WORKSHEET_WITHOUT_MOODLE: &str =
    "--worksheet is read by --format moodle only: add --format moodle, or leave --worksheet out";
/// The Moodle format without a worksheet.
pub const MOODLE_WITHOUT_WORKSHEET: &str = "--format moodle needs --worksheet FILE.csv";
/// A folder that cannot be created (`{}`: the folder, the system's reason).
pub const CANNOT_CREATE: &str = "cannot create {}: {}";
/// An output path that is not a regular file (`{}`: the path).
pub const OUTPUT_NOT_FILE: &str = "{}: the output is not a regular file";
/// An output path in a missing folder (`{}`: the path, the folder).
pub const OUTPUT_NO_FOLDER: &str = "{}: the output's folder {} does not exist";
/// A feedback folder that cannot be created (`{}`: the folder, the system's reason).
pub const FEEDBACK_CANNOT_CREATE: &str = "--feedback {}: cannot create the folder: {}";
/// A feedback folder where no page can be written (`{}`: the folder, the system's reason).
pub const FEEDBACK_CANNOT_WRITE: &str = "--feedback {}: cannot write there: {}";
/// A worksheet the CSV reader refuses (`{}`: its message).
pub const NOT_CSV: &str = "not a CSV worksheet: {}";
/// A quote never closed (`{}`: the line).
pub const QUOTE_NOT_CLOSED: &str = "line {}: a quote `\"` opens a field that is never closed";
/// An empty worksheet.
pub const WORKSHEET_EMPTY: &str = "empty";
/// A header cell that swallowed the next line (`{}`: the cell's first line).
pub const HEADER_RUNS_ON: &str =
    "line 1: the header cell `{}` runs onto the next line: a quote `\"` is not closed where the cell ends";
/// No identifier column (`{}`: the header's cells, the names looked for).
pub const NO_IDENTIFIER_COLUMN: &str = "no identifier column: the header has {}; looked for {} (download the \
                                        worksheet again from Moodle's \"Download grading worksheet\")";
/// No grade column (`{}`: the header's cells, the names looked for).
pub const NO_GRADE_COLUMN: &str = "no grade column: the header has {}; looked for {} (give --grade-column NAME)";
/// No feedback column (`{}`: the header's cells, the names looked for).
pub const NO_FEEDBACK_COLUMN: &str =
    "no feedback column: the header has {}; looked for {} (give --feedback-column NAME)";
/// A `--map` line that is not `file,identifier` (`{}`: the line).
pub const MAP_LINE: &str = "line {}: expected `file,identifier`";

/// The warning when Gradescope's or PrairieLearn's format is given a class (`{}`: the
/// format, the folder, how many submissions it holds, with their names after `: `).
pub const WARN_ONE_SUBMISSION: &str =
    "warning: --format {} grades one submission (the platform runs lightlab once per student), and {} holds {}";
/// A note of a row on standard error (`{}`: the file, the notes).
pub const NOTE_LINE: &str = "note: {}: {}";
/// A graded student without a worksheet row (`{}`: the student).
pub const WARN_NO_ROW: &str = "warning: no worksheet row for {} (give --map FILE.csv with `file,identifier`)";
/// Nothing graded (`{}`: the folder, the exercises).
pub const WARN_NOTHING: &str = "warning: nothing was graded in {}: no submission found for {}";
/// Nothing graded, and some files were not graded (`{}`: the folder, the exercises).
pub const WARN_NOTHING_SEE: &str =
    "warning: nothing was graded in {}: no submission found for {} (see the files not graded above)";

/// The teacher's texts above, for the translation template.
pub const TEACHER: &[&str] = &[
    ASSIGNMENT_FILE,
    WORKSHEET_FILE,
    MAP_FILE,
    NOT_UTF8,
    AT_LINE,
    AT_FIELD,
    AT_LINE_SHOWN,
    NO_EXERCISE,
    LISTED_TWICE,
    NOT_POINTS,
    BAD_PARTIAL,
    BAD_CREDIT,
    NO_SUCH_MISTAKE,
    NOT_MISTAKE_OF,
    NO_NAMED_MISTAKES,
    PAIR_NEEDS_VERTEX,
    TAKES_NO_VERTEX,
    VERTEX_NEEDS_FILES,
    PATTERN_EMPTY,
    PATTERN_UNSUPPORTED,
    PATTERN_OUTSIDE,
    PATTERN_NESTED,
    PATTERN_UNOPENED,
    PATTERN_UNCLOSED,
    NO_EXERCISE_GIVEN,
    WORKSHEET_WITHOUT_MOODLE,
    MOODLE_WITHOUT_WORKSHEET,
    CANNOT_CREATE,
    OUTPUT_NOT_FILE,
    OUTPUT_NO_FOLDER,
    FEEDBACK_CANNOT_CREATE,
    FEEDBACK_CANNOT_WRITE,
    NOT_CSV,
    QUOTE_NOT_CLOSED,
    WORKSHEET_EMPTY,
    HEADER_RUNS_ON,
    NO_IDENTIFIER_COLUMN,
    NO_GRADE_COLUMN,
    NO_FEEDBACK_COLUMN,
    MAP_LINE,
    WARN_ONE_SUBMISSION,
    NOTE_LINE,
    WARN_NO_ROW,
    WARN_NOTHING,
    WARN_NOTHING_SEE,
];

/// The grading's language: the command line's (`--lang`, else the assignment's `lang`,
/// else `LIGHTLAB_LANG` or the locale; see [`super::run()`]).
pub fn lang() -> Lang {
    crate::i18n::output_lang()
}

/// `msgid` in the grading's language (the command line's, as everywhere), and then each
/// `{}` filled in order: the checker's lookups, so a row's texts and the checker's agree.
pub(crate) use crate::checker::texts::{tr, tr_fill};

/// A Moodle feedback cell's verdict for `exercise`, in the grading's language (the
/// student reads it): `basic-move-light: agrees (100/100)`.
pub fn cell_verdict(exercise: &str, verdict: &str, score: u32) -> String {
    let msgid = by_verdict(verdict, [CELL_AGREES, CELL_DISAGREES, CELL_ERROR]);
    tr_fill(msgid, &[exercise, &score.to_string()])
}

/// The verdict line of a row (`agrees`, `disagrees`, `error`) with its score.
pub fn verdict_line(verdict: &str, score: u32) -> String {
    let msgid = by_verdict(verdict, [VERDICT_AGREES, VERDICT_DISAGREES, VERDICT_ERROR]);
    tr_fill(msgid, &[&score.to_string()])
}

/// The one of `[agrees, disagrees, error]` that names a row's `verdict` (anything but
/// `agrees` and `disagrees` is an error).
fn by_verdict(verdict: &str, [agrees, disagrees, error]: [&'static str; 3]) -> &'static str {
    match verdict {
        "agrees" => agrees,
        "disagrees" => disagrees,
        _ => error,
    }
}
