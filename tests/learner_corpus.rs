//! The learner corpus (`tests/data/learner_shaders/`, issue 25 item 5): shaders written in
//! styles unlike the project's own, each with the diagnosis it should get. Every correct
//! shader must agree and every mistaken one disagree; the diagnosis accuracy (exact id and
//! site, id only, wrong, none) is printed per kind and held to a floor that only rises.

use crate::gl_common;

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use lightlab::checker::check::{parse_mapping, Mapping};
use lightlab::checker::diagnose::{check_and_diagnose, Finding, Submission};
use lightlab::checker::mistakes::Mistake;
use lightlab::gl::ModelId;

/// Cases per shader: the corpus's author validated every file at 2000.
const CASES: usize = 2000;

fn corpus() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/learner_shaders")
}

/// One corpus file's header.
struct Entry {
    file: String,
    model: ModelId,
    mapping: Mapping,
    vertex: Option<String>,
    /// `(id, site)` expected, empty for a correct shader.
    expect: Vec<(String, Option<String>)>,
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
    let expect = if line.trim() == "agrees" {
        Vec::new()
    } else {
        line.split('+')
            .map(|m| match m.trim().split_once('@') {
                Some((id, site)) => (id.to_string(), Some(site.to_string())),
                None => (m.trim().to_string(), None),
            })
            .collect()
    };
    Entry { file, model, mapping, vertex, expect }
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
    for path in &paths {
        let e = entry(path);
        let fragment = std::fs::read_to_string(path).unwrap();
        let submission = Submission { fragment: &fragment, vertex: e.vertex.as_deref() };
        let d = match check_and_diagnose(
            &ctx,
            submission,
            e.model,
            &e.mapping,
            CASES,
            lightlab::oracle::cases::DEFAULT_SEED,
        ) {
            Ok(d) => d,
            Err(err) => {
                problems.push(format!("{}: {err}", e.file));
                continue;
            }
        };
        if e.expect.is_empty() {
            if !d.agrees() {
                problems.push(format!("{}: a correct shader disagrees\n{}", e.file, d.format()));
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
            (_, _, true) => "vertex + fragment pair",
            (1, false, false) => "single mistake",
            (1, true, false) => "partial (one site)",
            _ => "two mistakes",
        };
        println!("{}: expected {:?}, named {found:?}: {g:?}", e.file, e.expect);
        *table.entry(kind).or_default().entry(g).or_default() += 1;
    }
    println!("\n| kind | exact | id only | wrong | none |\n| --- | --- | --- | --- | --- |");
    for (kind, row) in &table {
        let n = |g| row.get(&g).copied().unwrap_or(0);
        println!("| {kind} | {} | {} | {} | {} |", n(Grade::Exact), n(Grade::IdOnly), n(Grade::Wrong), n(Grade::None));
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
    let exact = |kind: &str| table.get(kind).and_then(|r| r.get(&Grade::Exact)).copied().unwrap_or(0);
    // Floors: the counts measured when this test was written (see the session notes); they
    // only rise as the diagnosis learns, and a regression fails here.
    for (kind, floor) in FLOORS {
        assert!(exact(kind) >= floor, "{kind}: {} exact, the floor is {floor}", exact(kind));
    }
}

/// Exact diagnoses per kind, as measured on 2026-11-25 with the corpus's 66 files (issue 25's
/// targets are 90 % of single and partial mistakes, 70 % of two at once): single 20 of 24,
/// partial 10 of 12, two mistakes 9 of 10, vertex + fragment pairs 4 of 6.
const FLOORS: [(&str, usize); 4] =
    [("single mistake", 20), ("partial (one site)", 10), ("two mistakes", 9), ("vertex + fragment pair", 4)];
