//! The exercises in the chapters: the data of the in-page checker
//! (`book/theme/live/lightlab-exercise.js`), one classic script per exercise.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | page exercise | a shader exercise checked against a model with a frame ([`crate::checker::complete`]) and no uniform mapping |
//! | program | a complete fragment shader: the reader's, the reference or a mutant |
//! | case | one row of the model's packed inputs and the group's uniforms ([`crate::exercises::export`]) |
//! | match | two programs within `match_tolerance` on all but `mistake_share` of the defined cases ([`crate::checker::diagnose`]) |
//!
//! Every program the page runs is a complete fragment shader of the same form as the
//! reader's: the reference is the exercise's function file in the model's frame, each
//! mutant the same file with one catalogue mistake applied ([`crate::checker::mistakes`]), so
//! the reader's shader is never rewritten: the page sets each declared `in` and uniform
//! from the case and draws one point per case into a float target.
//!
//! The model's quantities, bound and the mistake texts are taken from
//! [`crate::exercises::export::browser_json`] unchanged; the complete shaders, the chapter
//! placement and the verdict's rule are added here, with the cases the command line checks
//! (`lightlab exercise check ID FILE --cases` [`N_CASES`] `--seed` [`SEED`], the quantities
//! it fixes for the reference fixed: `verdict_json`).

use serde_json::{json, Value};

use super::programs::ES_HEADER;
use crate::checker::check::Mapping;
use crate::checker::{complete, diagnose, isolation, sites};
use crate::exercises::{choice_verdict, export, letter, Check, Exercise, NumberTexts, EXERCISES, GIVEN};
use crate::figures::artifact::Artifact;
use crate::gl::ModelId;
use crate::i18n::catalog::tr_fill;
use crate::i18n::{tr, Lang};
use crate::oracle::cases;

/// Cases per check (the model's case generator splits them into groups). 256 keeps a
/// check under a second on SwiftShader; a mutant differs from the reference on a large
/// share of cases, so a few hundred separate every catalogue mistake.
pub const N_CASES: usize = 256;

/// The in-page time guard's limits (loop cap, chunk budget) are the page's guard,
/// [`super::guard`]: the checker draws the reader's cases in chunks of growing size, waits
/// for the GPU after each, and stops once the cases so far took longer than the budget.
/// Iterations of the slow probe's loop (see `slow_probe`): 4·10⁸, far over the page's
/// [`super::guard::LOOP_CAP`], so the probe stands for an endless loop: the cap stops it on
/// its first case and the check names the loop (in SwiftShader 10⁸ iterations took 15.7 s
/// on this project's 2-core machine under load; uncapped, the probe would hold the page).
pub const SLOW_PROBE_ITERATIONS: u64 = 400_000_000;

/// The time guard's messages. `SLOW_TEXT`'s `{}`: the reader's milliseconds, the first and
/// last case, the reference's milliseconds on the same cases; `LOOP_TEXT`'s: the loop cap
/// and the case.
const SLOW_TEXT: &str = "stopped: your shader took {} ms on cases {}–{}, the reference {} ms: an endless or \
                         very long loop? The check stops here so the page does not freeze; `lightlab exercise \
                         check` runs it under a time limit on the command line";
pub(crate) const LOOP_TEXT: &str =
    "stopped: your shader's loops ran more than {} iterations on case {}: an endless loop? \
                         Every loop in the page stops there so the page does not freeze; fix the loop's \
                         condition and press Check again";
const LOST_TEXT: &str = "the browser stopped the last shader and reset the GPU context (it ran too long: an \
                         endless loop?); fix the loop and press Check again";

/// A slow variant of `reference` for the time guard's self-test: a loop of
/// [`SLOW_PROBE_ITERATIONS`] dependent
/// `sin` calls on the shader's first `vec3` input (so no compiler can fold it) before the
/// end of `main`, kept alive by a test on its result that writes the colour output.
/// `None` when the shader has no `vec3` input or no colour output.
fn slow_probe(reference: &str) -> Option<String> {
    use crate::checker::check::glsl::{self, Storage};
    let parsed = glsl::parse(reference);
    let input = parsed.decls.iter().find(|d| d.storage == Storage::In && d.ty == "vec3" && d.block.is_none())?;
    let output = parsed.decls.iter().find(|d| d.storage == Storage::Out && d.block.is_none())?;
    let end = reference.rfind("\n}")?;
    let loop_text = format!(
        "\n    float ll_slow = 0.0;\n    for (int i = 0; i < {SLOW_PROBE_ITERATIONS}; i++) ll_slow = sin(ll_slow + float(i) * {}.x);\n    \
         if (ll_slow == 12345.678) {}.r += 1.0;",
        input.name, output.name
    );
    Some(format!("{}{loop_text}{}", &reference[..end], &reference[end..]))
}

/// The cases' seed (fixed: the book is byte-identical on every build).
pub const SEED: u64 = 0x6c69_6768_746c_6162;

/// The chapter page an exercise sits on (`02-basic-lighting` for `book/src/02-basic-lighting.md`),
/// by its chapter, or by its model for our own exercises. `None` for exercises no chapter
/// page shows (they stay in the exercises appendix).
pub fn chapter_page(e: &Exercise) -> Option<&'static str> {
    let by_model = |m: Option<ModelId>| match m? {
        ModelId::BasicLighting => Some("02-basic-lighting"),
        ModelId::Materials => Some("03-materials"),
        ModelId::LightingMaps | ModelId::LightingMapsEmission => Some("04-lighting-maps"),
        ModelId::Directional | ModelId::Point | ModelId::Spot => Some("05-light-casters"),
        ModelId::MultipleLights => Some("06-multiple-lights"),
        ModelId::Gouraud
        | ModelId::OpenGLTutorial8
        | ModelId::Ogldev19
        | ModelId::NormalMatrix
        | ModelId::BlinnPhong => None,
    };
    if let Check::Pair { .. } = e.check {
        return Some("12-exercises"); // the pair box sits in the exercises chapter
    }
    crate::exercises::chapter_page_of(e.chapter).or_else(|| by_model(e.model()))
}

/// Whether `e` is checked in the page: a shader exercise of a model with a frame, on a
/// chapter page (an exercise's mapping is exported with it, so the page uses the reader's names).
pub fn in_page(e: &Exercise) -> bool {
    if !matches!(e.check, Check::Shader { .. } | Check::Variant { .. }) {
        return false;
    }
    chapter_page(e).is_some() && reference_of(e).is_some()
}

/// The complete shader the page compares a reader's with: the exercise's function file
/// in its model's frame, or, for a model without a function file (`normal_matrix`), the
/// exercise's own reference solution (on llvmpipe every exercise's solution agrees with its
/// model: `tests/exercises.rs`).
fn reference_of(e: &Exercise) -> Option<String> {
    let model = e.model()?;
    match e.functions() {
        Some(functions) => complete::complete_with(model, &functions),
        None => e.solution_text.map(str::to_string),
    }
}

/// The shader exercises the chapters check in the page, in catalogue order.
pub fn page_exercises() -> Vec<&'static Exercise> {
    EXERCISES.iter().filter(|e| in_page(e)).collect()
}

/// Whether `e` is a numeric or choice exercise on a chapter page (checked in the page
/// without OpenGL).
pub fn answer_in_page(e: &Exercise) -> bool {
    matches!(e.check, Check::Numeric { .. } | Check::Choice { .. }) && chapter_page(e).is_some()
}

/// Whether `e` is a vertex + fragment pair exercise on a chapter page (checked in the page
/// by `lightlab-pair.js` on the data of [`super::pair::pair_json`]).
pub fn pair_in_page(e: &Exercise) -> bool {
    matches!(e.check, Check::Pair { .. }) && chapter_page(e).is_some()
}

/// Every exercise with a box on a chapter page: the shader ones, the pair ones and the
/// answer ones, in catalogue order.
pub fn boxed_exercises() -> Vec<&'static Exercise> {
    EXERCISES.iter().filter(|e| in_page(e) || pair_in_page(e) || answer_in_page(e)).collect()
}

/// The pair box's data for pair exercise `e`: the pair check's data
/// ([`super::pair::pair_json`], [`super::pair::N_PAIR_CASES`] triangles: 169 kB of
/// JSON in the book, less than a single-shader exercise's 200 kB), with the exercise's id,
/// title and starting pair, and `kind: "pair"` for `lightlab-exercise.js`.
// String error: it names the exercise, as `exercise_json`'s.
fn pair_exercise_json(e: &Exercise) -> Result<Value, String> {
    let Check::Pair { model } = e.check else { return Err(format!("exercise {}: not a pair exercise", e.id)) };
    let mut v = super::pair::pair_json(model).map_err(|err| format!("exercise {}: {err}", e.id))?;
    let starter = e.vertex_starter().ok_or_else(|| format!("exercise {}: no starting vertex shader", e.id))?;
    v["kind"] = json!("pair");
    v["id"] = json!(e.id);
    v["title"] = json!(e.title);
    v["starter"] = json!({ "vertex": starter, "fragment": e.starter() });
    Ok(v)
}

/// The checker's JSON for a numeric or choice exercise: the crate's answer and the
/// verdict texts of the command line ([`NumberTexts`] with [`GIVEN`] for the reader's
/// number; one verdict per choice from [`choice_verdict`]). The page only compares.
// String error: joined into the artifact's message by `files`, as `exercise_json`'s.
fn answer_json(e: &Exercise) -> Result<Value, String> {
    match e.check {
        Check::Numeric { answer, tolerance, unit } => {
            let t = NumberTexts::new(tolerance, unit);
            let finding = |f: &crate::exercises::NumberFinding| json!({"id": f.id, "title": f.title, "evidence": f.evidence, "text": f.text().trim_end()});
            Ok(json!({
                "id": e.id, "title": e.title, "kind": "number", "statement": e.statement,
                "answer": answer(), "tolerance": tolerance, "unit": unit, "given": GIVEN,
                "right": t.right.trim_end(), "too_high": finding(&t.too_high), "too_low": finding(&t.too_low),
            }))
        }
        Check::Choice { choices, answer } => {
            let want = answer();
            let verdicts: Vec<Value> = (0..choices.len())
                .map(|k| {
                    let (agrees, diagnosis, text) = choice_verdict(choices, want, k);
                    json!({
                        "letter": letter(k).to_string(), "choice": choices[k], "agrees": agrees,
                        "text": text.trim_end(),
                        "diagnosis": diagnosis.iter().map(|f| json!({"id": f.id, "title": f.title, "evidence": f.evidence})).collect::<Vec<_>>(),
                    })
                })
                .collect();
            Ok(json!({"id": e.id, "title": e.title, "kind": "choice", "statement": e.statement, "choices": verdicts}))
        }
        _ => Err(format!("exercise {}: not a numeric or choice exercise", e.id)),
    }
}

/// An exercise's `--uniforms` mapping for the page: `names`, the model's name (or struct
/// prefix) to the reader's, and `values`, quantities fixed in every case.
fn mapping_json(m: &crate::checker::check::Mapping) -> (Value, Value) {
    let names: serde_json::Map<String, Value> =
        m.names.iter().map(|(user, model)| (model.clone(), json!(user))).collect();
    let values: serde_json::Map<String, Value> = m
        .values
        .iter()
        .map(|(q, v)| (q.clone(), Value::Array(v.iter().map(|x| json!(f64::from(*x))).collect())))
        .collect();
    (Value::Object(names), Value::Object(values))
}

/// The verdict's rule for exercise `e` as `lightlab exercise check ID FILE --cases`
/// [`N_CASES`] `--seed` [`SEED`] applies it, and those cases (with the mapping's `[values]`
/// fixed, as the command line fixes them), for the page:
/// - a shader exercise (`"rule": "f64"`): every defined case within the model's bound of the
///   `f64` reference ([`diagnose::case_fails`]); `expected` holds the reference's values,
///   `fixed` the quantities they were computed with, and `switches` the values of each switch
///   of the isolation step ([`isolation::switched_cases`]);
/// - a variant (`"rule": "reference"`): every defined case within twice the bound of the
///   reference solution drawn on the same GPU; the isolation step compares with that
///   solution drawn with each switch ([`crate::exercises::check`]'s `variant`).
// String error: joined into the artifact's message by `files`, as `exercise_json`'s.
fn verdict_json(e: &Exercise, model: ModelId, mapping: &Mapping) -> Result<(Value, Value), String> {
    let case_model = model.case_model();
    let reference = reference_of(e).ok_or_else(|| format!("exercise {}: no reference", e.id))?;
    let fixed = reference_fixed(case_model, &reference, mapping);
    let groups = cases::generate_cases(case_model, N_CASES, SEED, &fixed)
        .map_err(|err| format!("exercise {}: cases: {err}", e.id))?;
    let cases = json!({ "seed": SEED, "groups": export::groups_json(case_model, &groups) });
    let verdict = match e.check {
        Check::Variant { .. } => json!({ "rule": "reference", "bound": 2.0 * case_model.bound, "isolate": true }),
        _ => {
            let switches: serde_json::Map<String, Value> = isolation::switched_cases(case_model, &groups)
                .into_iter()
                .map(|s| (s.name, export::expected_json(case_model, &s.groups)))
                .collect();
            json!({
                "rule": "f64", "bound": case_model.bound, "isolate": true,
                "fixed": fixed.iter().map(|(name, _)| name).collect::<Vec<_>>(),
                "expected": export::expected_json(case_model, &groups), "switches": switches,
            })
        }
    };
    Ok((verdict, cases))
}

/// The quantities the command line fixes when it checks `reference` (`crate::checker::check`'s
/// policy): the mapping's `[values]`, and each per-case quantity with a chapter value that
/// the shader does not declare (it hard-codes it). Declared names are read from the text:
/// a uniform or `in` of a struct type declares `name.field` for each field. The page
/// computes the same set for the reader's shader and uses the `f64` values emitted for this
/// set only when its own set is the same.
fn reference_fixed(model: &cases::CaseModel, reference: &str, mapping: &Mapping) -> Vec<(&'static str, [f32; 3])> {
    use crate::checker::check::glsl::{parse, Storage};
    use crate::gl::layout::Slot;
    let parsed = parse(reference);
    let mut declared = std::collections::BTreeSet::new();
    for d in parsed.decls.iter().filter(|d| matches!(d.storage, Storage::Uniform | Storage::In)) {
        match parsed.structs.get(&d.ty) {
            Some(fields) => declared.extend(fields.iter().map(|f| format!("{}.{}", d.name, f.name))),
            None => {
                declared.insert(d.name.clone());
            }
        }
    }
    let mut fixed = Vec::new();
    for q in model.quantities {
        if let Some(v) = mapping.values.get(q.name) {
            fixed.push((q.name, *v));
        } else if let (Some(v), Slot::Case { .. }, false) = (q.default, q.slot, declared.contains(q.name)) {
            fixed.push((q.name, v));
        }
    }
    fixed
}

/// The mistakes whose mutants in one site the page leaves out: their output there is
/// undefined in GLSL (ES 3.00 §8.2: `pow(x, y)` is undefined for x < 0), so it depends on the
/// driver. llvmpipe gives NaN and the command line names `specular-no-clamp` in the
/// spotlight only; in Chromium's SwiftShader the same mutant differs from the reference on
/// too few cases and the page isolated it instead (the parity test,
/// `tests/browser.rs::the_page_and_the_command_line_give_the_same_verdicts`). The
/// whole-shader mutant stays: both name it.
const NOT_IN_ONE_SITE_IN_THE_PAGE: &[&str] = crate::checker::mistakes::POW_OF_NEGATIVE;

/// Whether the page carries `mutant` (see [`NOT_IN_ONE_SITE_IN_THE_PAGE`]).
fn in_the_page(mutant: &sites::Mutant) -> bool {
    mutant.site.is_none() || !NOT_IN_ONE_SITE_IN_THE_PAGE.contains(&mutant.mistake.id)
}

/// The checker's JSON for exercise `e` (see the module docs), given the export document.
// String error: joined into the artifact's message by `files`, which names the exercise.
fn exercise_json(e: &Exercise, doc: &Value) -> Result<Value, String> {
    let model = e.model().ok_or_else(|| format!("exercise {}: no model", e.id))?;
    let functions = e.functions().unwrap_or_default();
    let reference = reference_of(e).ok_or_else(|| format!("exercise {}: model {model} has no frame", e.id))?;
    let m = doc["models"].get(model.name()).ok_or_else(|| format!("exercise {}: model {model} not exported", e.id))?;
    let base_squashed = diagnose::squashed(&functions);
    let mut mutants = Vec::new();
    for (mutant, mutated) in sites::mutants(model, &functions).into_iter().filter(|(m, _)| in_the_page(m)) {
        let Some(shader) = complete::complete_with(model, &mutated) else { continue };
        let entry = doc["mistakes"]
            .as_array()
            .and_then(|a| a.iter().find(|x| x["id"] == mutant.mistake.id))
            .ok_or_else(|| format!("mistake {} not exported", mutant.mistake.id))?;
        let mut entry = entry.clone();
        entry["shader"] = json!(shader);
        let steps = mutant.mistake.steps_for(model).unwrap_or_default();
        entry["signs"] = signs_json(&diagnose::text_signs(steps.iter().copied(), &base_squashed));
        if let Some(site) = mutant.site {
            // the page names the site as the command line does (Finding::of_mutant)
            let eq = mutant.equivalence();
            let label = mutant.label();
            entry["site"] = json!(site.name());
            entry["site_phrase"] = json!(site.phrase());
            entry["title_en"] = json!(mutant.title());
            entry["equivalent"] = json!(eq.map_or(Vec::new(), |e| e.ids.iter().filter(|id| **id != label).collect()));
            entry["equivalence_reason"] = json!(eq.map_or("", |e| e.reason));
        }
        mutants.push(entry);
    }
    // the exercise's change left out (a variant's): tried after the mutants, as on the command line
    let mut candidates = Vec::new();
    for part in crate::exercises::change::parts(e) {
        let Some(shader) = complete::complete_with(model, &part.functions) else { continue };
        let reversed: Vec<&[(&str, &str)]> = part.reversed.iter().map(Vec::as_slice).collect();
        let english = part.finding(e, &|s: &str| s.to_owned());
        candidates.push(json!({
            "id": part.id,
            "title": part.title.0,
            "title_args": part.title.1,
            "title_en": english.title,
            "hints": part.hints,
            "hint_args": [[e.title], [e.statement]],
            "edits": part.edits.iter().map(|(to, from)| [to.trim(), from.trim()]).collect::<Vec<_>>(),
            "text": crate::exercises::change::EDIT,
            "why": "", "link": "", "equivalent": [], "equivalence_reason": "",
            "optional": part.optional,
            "shader": shader,
            "signs": signs_json(&diagnose::text_signs(reversed, &base_squashed)),
        }));
    }
    let mapping = match e.check {
        Check::Shader { mapping, .. } | Check::Variant { mapping, .. } => mapping,
        _ => "",
    };
    let mapping =
        crate::checker::check::parse_mapping(mapping).map_err(|err| format!("exercise {}: mapping: {err}", e.id))?;
    let (names, values) = mapping_json(&mapping);
    let (verdict, cases) = verdict_json(e, model, &mapping)?;
    let (from, to) = isolation::ISOLATION_PROBE;
    let uniform_names: Vec<&str> =
        m["cases"]["groups"][0]["uniforms"].as_object().map_or(Vec::new(), |u| u.keys().map(String::as_str).collect());
    let case_model = model.case_model();
    let probe = match (functions.contains(from), isolation::probe_expectation(case_model, &uniform_names)) {
        (true, Some(expect)) => complete::complete_with(model, &functions.replace(from, to))
            .map_or(Value::Null, |shader| json!({ "shader": shader, "expect": expect })),
        _ => Value::Null,
    };
    Ok(json!({
        "id": e.id,
        "title": e.title,
        "model": model.name(),
        "isolation": doc["isolation"],
        "switches": m["switches"],
        "flag_labels": m["flag_labels"],
        "probe": probe,
        "names": names,
        "values": values,
        "rules": {
            "forbid": mapping.forbid,
            "require": mapping.require,
            "forbidden_text": crate::checker::check::RULE_FORBIDDEN,
            "required_text": crate::checker::check::RULE_REQUIRED,
        },
        "slow_probe": slow_probe(&reference),
        "time_limits": { "slow_text": SLOW_TEXT, "loop_text": LOOP_TEXT, "lost_text": LOST_TEXT },
        "never_read_text": crate::checker::texts::NOTE_NEVER_READ,
        "guard": super::guard::guard_json(),
        "starter": e.starter(),
        "solution": e.solution(),
        "reference": reference,
        "es_header": ES_HEADER,
        "mistake_share": doc["mistake_share"],
        "bound": m["bound"],
        "match_tolerance": m["match_tolerance"],
        "n_inputs": m["n_inputs"],
        "quantities": m["quantities"],
        "cases": cases,
        "verdict": verdict,
        "mutants": mutants,
        "candidates": candidates,
    }))
}

/// The text signs of a mutant ([`diagnose::text_signs`]) as the page reads them:
/// `[{edit: [text], base: [text]}]`, one per step.
fn signs_json(signs: &[diagnose::StepSigns]) -> Value {
    Value::Array(signs.iter().map(|s| json!({ "edit": s.edit, "base": s.base })).collect())
}

/// The exercise box's link to the appendix (English msgid).
pub const LINK_WITH_SOLUTION: &str = "statement and solution";
/// The same link in a book without solutions (English msgid; `lightlab book --no-solutions`
/// rewrites the box's link, `crate::book::solutions`).
pub const LINK_STATEMENT: &str = "statement";

fn html_escape(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

/// The markup a chapter includes for exercise `e`, in `lang`: a box the checker fills
/// (editor, "Check", result) and the data script. No blank lines, so Markdown keeps one HTML
/// block.
fn exercise_html(e: &Exercise, lang: Lang) -> String {
    let title = html_escape(&tr_fill(lang, "Exercise: {}", &[&tr(lang, e.title)]));
    let link = html_escape(&tr(lang, LINK_WITH_SOLUTION));
    let command = html_escape(&tr(lang, "on the command line:"));
    let status = html_escape(&tr(lang, "(the in-page check needs JavaScript and WebGL2)"));
    let texts = if lang.is_translation() { super::TEXTS_SCRIPT } else { "" };
    let files = if pair_in_page(e) { "FRAG --vertex VERT" } else { "FILE" };
    format!(
        "<div class=\"lightlab-exercise\" id=\"exercise-{id}\" data-exercise=\"{id}\">\n\
         <p><strong>{title}</strong> (<a href=\"12-exercises.html#{id}\">{link}</a>; \
         {command} <code>lightlab exercise check {id} {files}</code>)</p>\n\
         <p class=\"lightlab-status\">{status}</p>\n\
         {texts}<script src=\"generated/live/exercise-{id}.js\"></script>\n</div>\n",
        id = e.id,
    )
}

/// The exercises chapter's "your progress" list, in `lang`: every page exercise, linked to its
/// box on its chapter; `lightlab-learner.js` marks those this browser saw pass (it reads the
/// passes from localStorage and writes only its own words, with `textContent`).
fn progress_html(lang: Lang) -> String {
    let heading = html_escape(&tr(lang, "Your progress on this browser"));
    let status = html_escape(&tr(lang, "(the list needs JavaScript and the browser's storage)"));
    let mut s =
        format!("<div class=\"lightlab-progress\">\n<p><strong>{heading}</strong> <small>{status}</small></p>\n<ul>\n");
    for e in boxed_exercises() {
        let page = chapter_page(e).unwrap_or("12-exercises");
        let title = html_escape(&tr(lang, e.title));
        s += &format!(
            "<li data-exercise=\"{id}\"><a href=\"{page}.html#exercise-{id}\">{title}</a> \
             <span class=\"lightlab-progress-mark\"></span></li>\n",
            id = e.id
        );
    }
    s += "</ul>\n";
    if lang.is_translation() {
        s += super::TEXTS_SCRIPT;
    }
    s + "</div>\n"
}

/// Each page exercise with the checker's data (see the module docs), built once per process.
// String error: it names the exercise.
pub fn page_data() -> Result<&'static [(&'static Exercise, Value)], String> {
    static DATA: std::sync::OnceLock<Result<Vec<(&'static Exercise, Value)>, String>> = std::sync::OnceLock::new();
    DATA.get_or_init(|| {
        let doc = export::browser_json(N_CASES, SEED);
        boxed_exercises()
            .into_iter()
            .map(|e| {
                let data = if in_page(e) {
                    exercise_json(e, &doc)?
                } else if pair_in_page(e) {
                    pair_exercise_json(e)?
                } else {
                    answer_json(e)?
                };
                Ok((e, data))
            })
            .collect()
    })
    .as_ref()
    .map(Vec::as_slice)
    .map_err(Clone::clone)
}

/// The data script of every page exercise, `live/exercise-<id>.js` (language-neutral: its
/// texts are msgids, translated in the page by `texts.js`).
pub fn files() -> Result<Vec<(String, Vec<u8>)>, String> {
    let mut out = Vec::new();
    for (e, data) in page_data()? {
        let js = format!(
            "(window.LIGHTLAB_EXERCISE_DATA = window.LIGHTLAB_EXERCISE_DATA || {{}})[{}] = {};\n",
            json!(e.id),
            data
        );
        out.push((format!("live/exercise-{}.js", e.id), js.into_bytes()));
    }
    Ok(out)
}

/// The page exercises' files as book artifacts: the data scripts (one run builds the export
/// once) and each box's markup in every language.
pub fn artifacts() -> Vec<Artifact> {
    let boxed = boxed_exercises();
    let paths: Vec<String> = boxed.iter().map(|e| format!("live/exercise-{}.js", e.id)).collect();
    let mut all = vec![Artifact::many(paths, || files().map(|f| f.into_iter().map(|(_, b)| b).collect::<Vec<_>>()))];
    let markup: Vec<String> = boxed.iter().map(|e| format!("live/exercise-{}.html", e.id)).collect();
    all.extend(Artifact::localized(markup, move |lang| {
        Ok::<_, String>(boxed_exercises().iter().map(|e| exercise_html(e, lang).into_bytes()).collect())
    }));
    all.extend(Artifact::localized(vec!["live/progress.html".into()], |lang| {
        Ok::<_, String>(vec![progress_html(lang).into_bytes()])
    }));
    all
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_page_exercise_has_a_reference_and_mutants() {
        // one data script per boxed exercise, and its markup in each language
        assert_eq!(files().unwrap().len(), boxed_exercises().len());
        let localized: Vec<String> =
            artifacts().iter().filter(|a| a.lang().is_some()).flat_map(|a| a.paths().to_vec()).collect();
        let boxes = localized.iter().filter(|p| p.contains("live/exercise-")).count();
        assert_eq!(boxes, Lang::ALL.len() * boxed_exercises().len());
        // and the exercises chapter's progress list, in each language, names every box
        assert_eq!(localized.iter().filter(|p| p.ends_with("live/progress.html")).count(), Lang::ALL.len());
        let progress = progress_html(Lang::En);
        for e in boxed_exercises() {
            assert!(
                progress.contains(&format!("<li data-exercise=\"{}\">", e.id)),
                "{} not in the progress list",
                e.id
            );
        }
        assert!(page_exercises().len() >= 5, "page exercises: {}", page_exercises().len());
        let doc = export::browser_json(N_CASES, SEED);
        for e in page_exercises() {
            let v = exercise_json(e, &doc).unwrap();
            let model = e.model().unwrap();
            let functions = e.functions().unwrap_or_default();
            let applicable = sites::mutants(model, &functions).iter().filter(|(m, _)| in_the_page(m)).count();
            // every catalogue mistake that rewrites the exercise's file is a mutant on the page;
            // only the models the catalogue does not cover have fewer than two
            assert_eq!(v["mutants"].as_array().unwrap().len(), applicable, "{}", e.id);
            let uncovered = [ModelId::Ogldev19, ModelId::OpenGLTutorial8, ModelId::NormalMatrix].contains(&model);
            assert!(applicable >= 2 || uncovered, "{}: fewer than two mutants", e.id);
            assert!(v["reference"].as_str().unwrap().starts_with("#version 330 core"));
        }
    }

    /// The answer exercises carry the crate's answer and the command line's texts: the
    /// page's texts for a right and a wrong answer are those `check_exercise` prints.
    #[test]
    fn answer_exercises_carry_the_command_lines_texts() {
        let answers: Vec<&Exercise> = boxed_exercises().into_iter().filter(|e| answer_in_page(e)).collect();
        assert!(answers.len() >= 5, "{}", answers.len());
        for e in answers {
            let v = answer_json(e).unwrap();
            match e.check {
                Check::Numeric { answer, tolerance, .. } => {
                    let want = answer();
                    let cli = crate::exercises::check_exercise(None, e, &format!("{want}"), &Default::default(), 1, 0)
                        .unwrap();
                    assert!(cli.agrees);
                    assert_eq!(v["right"].as_str().unwrap().replace(GIVEN, &want.to_string()), cli.text.trim_end());
                    let high = want + 2.0 * tolerance + 1.0;
                    let cli = crate::exercises::check_exercise(None, e, &format!("{high}"), &Default::default(), 1, 0)
                        .unwrap();
                    assert_eq!(cli.diagnosis[0].id, v["too_high"]["id"].as_str().unwrap());
                    assert_eq!(
                        cli.diagnosis[0].evidence,
                        v["too_high"]["evidence"].as_str().unwrap().replace(GIVEN, &high.to_string())
                    );
                }
                Check::Choice { choices, answer } => {
                    for k in 0..choices.len() {
                        let cli = crate::exercises::check_exercise(
                            None,
                            e,
                            &letter(k).to_string(),
                            &Default::default(),
                            1,
                            0,
                        )
                        .unwrap();
                        assert_eq!(v["choices"][k]["text"].as_str().unwrap(), cli.text.trim_end());
                        assert_eq!(v["choices"][k]["agrees"].as_bool().unwrap(), k == answer());
                    }
                }
                _ => unreachable!(),
            }
        }
    }

    /// Each page exercise is included once, on its chapter's page, and every exercise
    /// include names a page exercise (a stale include would fail the book build).
    #[test]
    fn chapters_include_exactly_the_page_exercises() {
        let src = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("book/src");
        let mut included = Vec::new();
        for entry in std::fs::read_dir(&src).unwrap().flatten() {
            let name = entry.file_name().to_string_lossy().into_owned();
            let Some(page) = name.strip_suffix(".md") else { continue };
            let text = std::fs::read_to_string(entry.path()).unwrap();
            for line in text.lines() {
                if let Some(id) =
                    line.strip_prefix("{{#include generated/live/exercise-").and_then(|r| r.strip_suffix(".html}}"))
                {
                    included.push((id.to_string(), page.to_string()));
                }
            }
        }
        included.sort();
        let mut expected: Vec<(String, String)> =
            boxed_exercises().iter().map(|e| (e.id.to_string(), chapter_page(e).unwrap().to_string())).collect();
        expected.sort();
        assert_eq!(included, expected);
    }
}
