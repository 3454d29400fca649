//! The learner corpus (`tests/data/learner_shaders/`): shaders written in styles unlike the
//! project's own, each with the diagnosis it should get. Every correct shader must agree and
//! every mistaken one disagree; the diagnosis accuracy (exact id and site, id only, wrong,
//! none) is counted per kind, held to a floor that only rises, and written as the book's
//! table `book/data/learner_corpus.md` (included by `book/src/11-verification.md`).
//!
//! The table is this test's output on this project's machine: the test fails when a fresh
//! run differs from the committed file, and `LIGHTLAB_BLESS=1` rewrites it. Its first line
//! names the renderer; on another llvmpipe build (which may round differently) the file is
//! not compared, as `tests/gl_book_report.rs` does for the oracle's table.
//!
//! The run takes `LIGHTLAB_CORPUS_CASES` cases per shader (default 2000, the table's count).
//! At another count the floors and targets still hold, every file's check is timed, and the
//! book's table is not compared. At the command line's default (`lightlab check-shader`
//! runs 100 000 cases):
//! `LIGHTLAB_CORPUS_CASES=100000 cargo test --release --test suite learner_corpus -- --nocapture`.

use crate::gl_common;

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use lightlab::checker::check::{parse_mapping, Mapping};
use lightlab::checker::diagnose::{check_and_diagnose, Finding, Submission};
use lightlab::checker::mistakes::Mistake;
use lightlab::gl::ModelId;

/// Cases per shader of the book's table: the corpus's author validated every file at 2000.
const CASES: usize = 2000;

/// Cases per shader of this run: `LIGHTLAB_CORPUS_CASES`, else [`CASES`].
fn cases() -> usize {
    std::env::var("LIGHTLAB_CORPUS_CASES")
        .map_or(CASES, |v| v.parse().unwrap_or_else(|_| panic!("LIGHTLAB_CORPUS_CASES={v:?} is not a case count")))
}

fn corpus() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/learner_shaders")
}

/// One corpus file's header.
struct Entry {
    file: String,
    model: ModelId,
    mapping: Mapping,
    vertex: Option<String>,
    /// `(id, site)` expected, empty for a correct shader or an isolated one.
    expect: Vec<(String, Option<String>)>,
    /// For a mistake outside the catalogue (`expect: isolated NAME`): the switch the
    /// isolation step should locate alone (`the emission term`).
    isolated: Option<String>,
}

fn header(text: &str, key: &str) -> Option<String> {
    let tag = format!("// {key}:");
    text.lines()
        .find_map(|l| l.trim().strip_prefix(&tag))
        .map(|v| v.split_whitespace().next().unwrap_or("").to_string())
}

fn entry(path: &Path) -> Entry {
    let text = std::fs::read_to_string(path).unwrap();
    let file = path.file_name().unwrap().to_string_lossy().to_string();
    let model: ModelId = header(&text, "model").unwrap_or_else(|| panic!("{file}: no model")).parse().unwrap();
    let beside = |name: String| std::fs::read_to_string(path.with_file_name(name)).unwrap();
    let mapping = header(&text, "uniforms").map_or_else(Mapping::default, |t| parse_mapping(&beside(t)).unwrap());
    let vertex = header(&text, "vertex").map(beside);
    let line = text.lines().find_map(|l| l.trim().strip_prefix("// expect:")).unwrap_or_else(|| panic!("{file}"));
    let isolated = line.trim().strip_prefix("isolated ").map(|name| name.trim().to_string());
    let expect = if line.trim() == "agrees" || isolated.is_some() {
        Vec::new()
    } else {
        line.split('+')
            .map(|m| match m.trim().split_once('@') {
                Some((id, site)) => (id.to_string(), Some(site.to_string())),
                None => (m.trim().to_string(), None),
            })
            .collect()
    };
    Entry { file, model, mapping, vertex, expect, isolated }
}

/// The mistakes a finding names, with their sites.
fn named(f: &Finding) -> Vec<(String, Option<String>)> {
    let mut out = vec![(f.id.clone(), f.site.map(|s| s.name().to_string()))];
    if let Some(second) = &f.second {
        out.extend(named(second));
    }
    out
}

/// Whether `found` is `want` or in its equivalence group (identical outputs, so a checker
/// cannot tell them apart).
fn same_id(found: &str, want: &str) -> bool {
    found == want || Mistake::by_id(want).and_then(|m| m.equivalence()).is_some_and(|e| e.ids.contains(&found))
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Grade {
    Exact,
    IdOnly,
    Wrong,
    None,
}

fn grade(want: &[(String, Option<String>)], found: &[(String, Option<String>)]) -> Grade {
    if found.iter().all(|(id, _)| id == "isolated") {
        return Grade::None;
    }
    let ids = want.len() == found.len() && want.iter().all(|(w, _)| found.iter().any(|(f, _)| same_id(f, w)));
    let sites = want
        .iter()
        .all(|(w, ws)| found.iter().any(|(f, fs)| same_id(f, w) && (ws == fs || ws.is_none() && fs.is_none())));
    match (ids, sites) {
        (true, true) => Grade::Exact,
        (true, false) => Grade::IdOnly,
        _ if want.iter().any(|(w, _)| found.iter().any(|(f, _)| same_id(f, w))) => Grade::IdOnly,
        _ => Grade::Wrong,
    }
}

/// The grade of a mistake outside the catalogue: exact when the isolation step locates
/// `switch` alone (its sentence may go on with the conditions every failing case meets),
/// none when it isolates the difference elsewhere or not at all, wrong when it names a
/// catalogue mistake.
fn grade_isolated(switch: &str, first: Option<&Finding>) -> Grade {
    match first {
        Some(f) if f.id == "isolated" => {
            let located = lightlab::checker::isolation::fill("one", &[switch]);
            let rest = f.title.strip_prefix(&located);
            if rest.is_some_and(|r| r.is_empty() || r.starts_with(',')) {
                Grade::Exact
            } else {
                Grade::None
            }
        }
        Some(_) => Grade::Wrong,
        None => Grade::None,
    }
}

#[test]
fn the_learner_corpus_is_diagnosed() {
    let Some(ctx) = gl_common::context_or_skip() else { return };
    let mut paths: Vec<PathBuf> = std::fs::read_dir(corpus())
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "frag"))
        .collect();
    paths.sort();
    assert!(paths.len() >= 40, "the corpus holds {} shaders", paths.len());
    let mut table: BTreeMap<&str, BTreeMap<Grade, usize>> = BTreeMap::new();
    let mut problems = Vec::new();
    // the correct shaders, and how many of them agree
    let (mut correct, mut agreeing) = (0usize, 0usize);
    let cases = cases();
    for path in &paths {
        let e = entry(path);
        let fragment = std::fs::read_to_string(path).unwrap();
        let submission = Submission { fragment: &fragment, vertex: e.vertex.as_deref() };
        let start = std::time::Instant::now();
        let checked =
            check_and_diagnose(&ctx, submission, e.model, &e.mapping, cases, lightlab::oracle::cases::DEFAULT_SEED);
        let secs = start.elapsed().as_secs_f64();
        let d = match checked {
            Ok(d) => d,
            Err(err) => {
                problems.push(format!("{}: {err}", e.file));
                continue;
            }
        };
        if let Some(name) = &e.isolated {
            if d.agrees() {
                problems.push(format!("{}: a mistaken shader agrees", e.file));
                continue;
            }
            let g = grade_isolated(name, d.diagnosis.first());
            let found = d.diagnosis.first().map(|f| &f.title);
            println!("{secs:5.1} s {}: expected {name} isolated, found {found:?}: {g:?}", e.file);
            *table.entry(KINDS[4]).or_default().entry(g).or_default() += 1;
            continue;
        }
        if e.expect.is_empty() {
            correct += 1;
            println!("{secs:5.1} s {}: agrees: {}", e.file, d.agrees());
            if !d.agrees() {
                problems.push(format!("{}: a correct shader disagrees\n{}", e.file, d.format()));
            } else {
                agreeing += 1;
            }
            continue;
        }
        if d.agrees() {
            problems.push(format!("{}: a mistaken shader agrees", e.file));
            continue;
        }
        let found = d.diagnosis.first().map(named).unwrap_or_default();
        let g = grade(&e.expect, &found);
        let kind = match (e.expect.len(), e.expect[0].1.is_some(), e.vertex.is_some()) {
            (_, _, true) => KINDS[3],
            (1, false, false) => KINDS[0],
            (1, true, false) => KINDS[1],
            _ => KINDS[2],
        };
        println!("{secs:5.1} s {}: expected {:?}, named {found:?}: {g:?}", e.file, e.expect);
        *table.entry(kind).or_default().entry(g).or_default() += 1;
    }
    let info = ctx.info();
    let renderer = format!("{} ({})", info.renderer, info.version);
    let markdown = corpus_markdown(&renderer, paths.len(), cases, (correct, agreeing), &table);
    println!("\n{markdown}");
    assert!(problems.is_empty(), "{}", problems.join("\n"));
    let exact = |kind: &str| table.get(kind).and_then(|r| r.get(&Grade::Exact)).copied().unwrap_or(0);
    // Floors: the counts measured when this test was last raised (see FLOORS); they only
    // rise as the diagnosis learns, and a regression fails here.
    for (kind, floor) in FLOORS {
        assert!(exact(kind) >= floor, "{kind}: {} exact, the floor is {floor}", exact(kind));
    }
    // The targets: the exact mistake and site for 90 % of the single and partial mistakes
    // together, both mistakes for 70 % of the two at once.
    let total = |kind: &str| table.get(kind).map_or(0, |r| r.values().sum::<usize>());
    let (one, one_n) = (exact(KINDS[0]) + exact(KINDS[1]), total(KINDS[0]) + total(KINDS[1]));
    assert!(one * 10 >= one_n * 9, "single and partial: {one} of {one_n} exact, under 90 %");
    assert!(exact(KINDS[2]) * 10 >= total(KINDS[2]) * 7, "two mistakes: under 70 % exact");
    if cases == CASES {
        compare_with_book(&markdown);
    } else {
        println!("not compared with the book's table: {cases} cases per shader, the table's are {CASES}");
    }
}

/// Exact diagnoses per kind, as measured with the corpus's 72 files: every file of each kind
/// (single 26, partial 12, two mistakes 10, vertex + fragment pairs 6, outside the
/// catalogue 2). The targets are 90 % of single and partial mistakes together, 70 % of two
/// at once.
const FLOORS: [(&str, usize); 5] = [
    ("single mistake", 26),
    ("partial (one site)", 12),
    ("two mistakes", 10),
    ("vertex + fragment pair", 6),
    ("outside the catalogue", 2),
];

/// The kinds in the table's order, with the combined row of the single and partial
/// mistakes (the kinds whose target is stated together) after the partial ones. A mistake
/// outside the catalogue is exact when the isolation step locates its term alone.
const KINDS: [&str; 5] =
    ["single mistake", "partial (one site)", "two mistakes", "vertex + fragment pair", "outside the catalogue"];

/// The book's table: a line naming the renderer and the run, the accuracy per kind, and how
/// many of the `correct` shaders are `agreeing`, at `cases` per shader. `share exact` is
/// `exact / shaders`, rounded to a whole percent.
fn corpus_markdown(
    renderer: &str,
    files: usize,
    cases: usize,
    (correct, agreeing): (usize, usize),
    table: &BTreeMap<&str, BTreeMap<Grade, usize>>,
) -> String {
    let mut s = format!(
        "Renderer: {renderer}; {files} shaders, {cases} cases each, seed {:#x}.\n\n",
        lightlab::oracle::cases::DEFAULT_SEED
    );
    s += "| kind | shaders | exact id and site | id only | wrong | none | share exact |\n";
    s += "| --- | ---: | ---: | ---: | ---: | ---: | ---: |\n";
    let count = |kinds: &[&str], g: Grade| -> usize {
        kinds.iter().filter_map(|k| table.get(k)).map(|r| r.get(&g).copied().unwrap_or(0)).sum()
    };
    let mut row = |label: &str, kinds: &[&str]| {
        let n: Vec<usize> = [Grade::Exact, Grade::IdOnly, Grade::Wrong, Grade::None].map(|g| count(kinds, g)).into();
        let total: usize = n.iter().sum();
        let share = if total == 0 { 0.0 } else { 100.0 * n[0] as f64 / total as f64 };
        s += &format!("| {label} | {total} | {} | {} | {} | {} | {share:.0} % |\n", n[0], n[1], n[2], n[3]);
    };
    row(KINDS[0], &KINDS[..1]);
    row(KINDS[1], &KINDS[1..2]);
    row("single and partial together", &KINDS[..2]);
    row(KINDS[2], &KINDS[2..3]);
    row(KINDS[3], &KINDS[3..4]);
    row(KINDS[4], &KINDS[4..]);
    s += &format!("\n| correct shaders | agree |\n| ---: | ---: |\n| {correct} | {agreeing} |\n");
    s
}

/// Compares `fresh` with `book/data/learner_corpus.md` (rewritten first when
/// `LIGHTLAB_BLESS=1`); skipped when the committed file was made on another renderer.
fn compare_with_book(fresh: &str) {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/book/data/learner_corpus.md");
    if std::env::var("LIGHTLAB_BLESS").as_deref() == Ok("1") {
        std::fs::write(path, fresh).unwrap();
    }
    let committed = std::fs::read_to_string(path).expect("book/data/learner_corpus.md is committed");
    let first_line = |s: &str| s.lines().next().unwrap_or("").to_string();
    if first_line(fresh) != first_line(&committed) {
        println!("skipped: {path} was made on {:?}, this is {:?}", first_line(&committed), first_line(fresh));
        return;
    }
    assert!(fresh == committed, "{path} differs from a fresh run; rerun this test with LIGHTLAB_BLESS=1");
}
