//! Fuzzing `lightlab shade` lines: no input panics, and every rejected line gets an
//! error that names a field and says what is wrong.
//!
//! Four generators, each from a fixed seed:
//! - valid cases of every model, mutated (bytes flipped, cut, spliced, keys repeated,
//!   values swapped for hostile ones);
//! - valid cases with every number replaced by one of any magnitude;
//! - objects built from every field name `shade` knows, with values of any JSON type;
//! - arbitrary text.
//!
//! CI runs a fixed slice (`DEFAULT_CASES` per generator). For a long run set
//! `LIGHTLAB_FUZZ_CASES` (cases per generator) and optionally `LIGHTLAB_FUZZ_SEED`:
//!
//! ```text
//! LIGHTLAB_FUZZ_CASES=100000 cargo test --release --test suite cli_shade_fuzz:: -- --nocapture
//! ```
//!
//! Each test prints how many lines it ran and how many were accepted.
#![cfg(feature = "book")]

use std::sync::atomic::{AtomicUsize, Ordering};

use lightlab::cli::shade::{process, shade_line};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed, TestRunner};

/// Cases per generator in CI.
const DEFAULT_CASES: u32 = 2_000;

fn cases() -> u32 {
    std::env::var("LIGHTLAB_FUZZ_CASES").ok().and_then(|s| s.parse().ok()).unwrap_or(DEFAULT_CASES)
}

fn runner(salt: u64) -> TestRunner {
    let seed = std::env::var("LIGHTLAB_FUZZ_SEED").ok().and_then(|s| s.parse().ok()).unwrap_or(20_261_122u64);
    TestRunner::new(Config {
        cases: cases(),
        rng_seed: RngSeed::Fixed(seed ^ salt),
        failure_persistence: None,
        // Shrinking a panic is what we want; other rejections do not occur.
        ..Config::default()
    })
}

/// One valid line of each model, the seeds of the mutations.
const VALID: [&str; 6] = [
    r#"{"model": "learnopengl", "frag_pos": [0, 0, 0], "normal": [0, 0, 1], "view_pos": [0, 0, 3], "material": {"ambient": [1, 0.5, 0.31], "diffuse": [1, 0.5, 0.31], "specular": [0.5, 0.5, 0.5], "shininess": 32}, "lights": [{"kind": "directional", "direction": [-0.2, -1, -0.3], "ambient": [0.05, 0.05, 0.05], "diffuse": [0.4, 0.4, 0.4], "specular": [0.5, 0.5, 0.5]}, {"kind": "point", "position": [0.7, 0.2, 2], "constant": 1, "linear": 0.09, "quadratic": 0.032, "ambient": [0.05, 0.05, 0.05], "diffuse": [0.8, 0.8, 0.8], "specular": [1, 1, 1]}, {"kind": "spot", "position": [0, 0, 3], "direction": [0, 0, -1], "cut_off_deg": 12.5, "outer_cut_off_deg": 15, "constant": 1, "linear": 0.09, "quadratic": 0.032, "ambient": [0, 0, 0], "diffuse": [1, 1, 1], "specular": [1, 1, 1]}]}"#,
    r#"{"model": "blinn-phong", "frag_pos": [0, 0, 0], "normal": [0, 0, 2], "view_pos": [0, 0, 3], "material": {"name": "emerald"}, "lights": [{"kind": "point", "position": [1.2, 1, 2], "constant": 1, "linear": 0.09, "quadratic": 0.032, "ambient": [0.2, 0.2, 0.2], "diffuse": [0.5, 0.5, 0.5], "specular": [1, 1, 1]}]}"#,
    r#"{"model": "opengl-tutorial", "frag_pos": [0, 0, 0], "normal": [0, 0, 1], "view_pos": [0, 0, 3], "light_pos": [4, 4, 4], "diffuse": [1, 0.5, 0.31], "light_power": 50, "exponent": 5}"#,
    r#"{"model": "ogldev", "frag_pos": [0, 0, 0], "normal": [0, 0, -1], "view_pos": [0, 0, -3], "direction": [0, 0, 1], "texture_color": [1, 0.5, 0.31], "specular_power": 32}"#,
    r#"{"model": "basic_lighting", "FragPos": [0.5, 0, 0.5], "Normal": [0, 0, 1], "viewPos": [0, 0, 3], "lightPos": [1.2, 1, 2], "lightColor": [1, 1, 1], "objectColor": [1, 0.5, 0.31], "ambientStrength": 0.1, "specularStrength": 0.5, "shininess": 32}"#,
    r#"{"frag_pos": [0, 0, 0], "normal": [0, 0, 1], "view_pos": [0, 0, 3], "material": {"name": "jade"}, "lights": []}"#,
];

/// Every key `shade` reads, in any model or light.
const KEYS: [&str; 46] = [
    "model",
    "frag_pos",
    "normal",
    "view_pos",
    "material",
    "lights",
    "name",
    "ambient",
    "diffuse",
    "specular",
    "shininess",
    "kind",
    "direction",
    "position",
    "constant",
    "linear",
    "quadratic",
    "cut_off_deg",
    "outer_cut_off_deg",
    "light_pos",
    "light_color",
    "light_power",
    "ambient_factor",
    "exponent",
    "color",
    "ambient_intensity",
    "diffuse_intensity",
    "specular_intensity",
    "specular_power",
    "texture_color",
    "FragPos",
    "Normal",
    "viewPos",
    "lightPos",
    "lightColor",
    "objectColor",
    "ambientStrength",
    "specularStrength",
    "learnopengl",
    "blinn-phong",
    "opengl-tutorial",
    "ogldev",
    "basic_lighting",
    "directional",
    "point",
    "spot",
];

/// Hostile values and fragments spliced into lines.
const HOSTILE: [&str; 24] = [
    "null",
    "true",
    "[]",
    "{}",
    "[0, 0, 0, 0]",
    "[0, 0]",
    "[0, 0, 0]",
    "[1e39, 0, 0]",
    "1e308",
    "-1e400",
    "1e-400",
    "-0",
    "0",
    "-1",
    "90.0000001",
    "NaN",
    "\"\\u0000\"",
    "\"\\ud800\"",
    "[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[",
    "\"emerald\"",
    "{\"name\": \"gold\", \"name\": \"jade\"}",
    "18446744073709551616",
    "0.000000000000000000000000000000000000000000001",
    "[1, 2, 3]",
];

#[derive(Clone, Debug)]
enum Mutation {
    FlipByte(usize, u8),
    Cut(usize, usize),
    Splice(usize, &'static str),
    QuoteKeyHere(usize, &'static str, &'static str),
    Truncate(usize),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    let at = any::<usize>();
    prop_oneof![
        (at, any::<u8>()).prop_map(|(i, b)| Mutation::FlipByte(i, b)),
        (at, 1usize..40).prop_map(|(i, n)| Mutation::Cut(i, n)),
        (at, prop::sample::select(&HOSTILE[..])).prop_map(|(i, s)| Mutation::Splice(i, s)),
        (at, prop::sample::select(&KEYS[..]), prop::sample::select(&HOSTILE[..]))
            .prop_map(|(i, k, v)| Mutation::QuoteKeyHere(i, k, v)),
        at.prop_map(Mutation::Truncate),
    ]
}

/// Apply `m` to `line` at a char boundary (positions are taken modulo the length).
fn apply(line: &mut Vec<u8>, m: &Mutation) {
    let len = line.len().max(1);
    match *m {
        Mutation::FlipByte(i, b) => {
            if !line.is_empty() {
                line[i % len] = b;
            }
        }
        Mutation::Cut(i, n) => {
            let start = i % len;
            let end = (start + n).min(line.len());
            line.drain(start.min(line.len())..end);
        }
        Mutation::Splice(i, s) => {
            let at = i % len;
            line.splice(at..at, s.bytes());
        }
        Mutation::QuoteKeyHere(i, k, v) => {
            // After any `{` or `,` found from position i: insert `"k": v,`, which often
            // repeats a key or puts a hostile value under a known one.
            let at = (i % len..line.len()).find(|&j| line[j] == b'{' || line[j] == b',').map_or(line.len(), |j| j + 1);
            let text = format!("\"{k}\": {v}, ");
            line.splice(at..at, text.bytes());
        }
        Mutation::Truncate(i) => line.truncate(i % len),
    }
}

/// Any JSON value built from the known keys and hostile leaves.
fn json_value() -> impl Strategy<Value = String> {
    let leaf = prop_oneof![
        prop::sample::select(&HOSTILE[..]).prop_map(str::to_string),
        prop::sample::select(&KEYS[..]).prop_map(|k| format!("\"{k}\"")),
        any::<f64>().prop_map(|x| if x.is_finite() { format!("{x:e}") } else { "0".to_string() }),
        (any::<f32>(), any::<f32>(), any::<f32>()).prop_map(|(a, b, c)| {
            let f = |x: f32| if x.is_finite() { format!("{x}") } else { "1".to_string() };
            format!("[{}, {}, {}]", f(a), f(b), f(c))
        }),
    ];
    leaf.prop_recursive(3, 24, 6, |inner| {
        prop_oneof![
            prop::collection::vec(inner.clone(), 0..4).prop_map(|v| format!("[{}]", v.join(", "))),
            prop::collection::vec((prop::sample::select(&KEYS[..]), inner), 0..8).prop_map(|kv| {
                let body: Vec<String> = kv.iter().map(|(k, v)| format!("\"{k}\": {v}")).collect();
                format!("{{{}}}", body.join(", "))
            }),
        ]
    })
}

/// Check one line: no panic (the harness catches one and fails), and a rejected line
/// names a field and a reason. Returns whether the line was accepted.
fn check(line: &str) -> Result<bool, TestCaseError> {
    match shade_line(line) {
        Ok(out) => {
            prop_assert!(out.rgb.is_finite() && out.rgb_f64.is_finite(), "accepted a non-finite result: {line}");
            let json: serde_json::Value = serde_json::from_str(&out.to_json(1))
                .map_err(|e| TestCaseError::fail(format!("output is not JSON ({e}) for {line}")))?;
            prop_assert!(json.get("rgb").is_some());
            Ok(true)
        }
        Err(e) => {
            prop_assert!(!e.field.is_empty() && !e.reason.is_empty(), "empty error {e:?} for {line}");
            let json: serde_json::Value =
                serde_json::from_str(&e.to_json(1)).map_err(|err| TestCaseError::fail(format!("{err}")))?;
            prop_assert_eq!(json["field"].as_str(), Some(e.field.as_str()));
            Ok(false)
        }
    }
}

fn report(name: &str, ran: &AtomicUsize, accepted: &AtomicUsize) {
    println!("{name}: {} lines, {} accepted, 0 panics", ran.load(Ordering::Relaxed), accepted.load(Ordering::Relaxed));
}

#[test]
fn mutated_valid_lines_never_panic() {
    let (ran, accepted) = (AtomicUsize::new(0), AtomicUsize::new(0));
    let strategy = (prop::sample::select(&VALID[..]), prop::collection::vec(mutation(), 1..3));
    runner(1)
        .run(&strategy, |(line, mutations)| {
            let mut bytes = line.as_bytes().to_vec();
            for m in &mutations {
                apply(&mut bytes, m);
            }
            ran.fetch_add(1, Ordering::Relaxed);
            // Invalid UTF-8 is handled by `process` before `shade_line`; check both paths.
            let Ok(text) = std::str::from_utf8(&bytes) else {
                let mut out = Vec::new();
                let ok = process(&bytes[..], &mut out, "fuzz").map_err(|e| TestCaseError::fail(e.to_string()))?;
                prop_assert!(!ok && String::from_utf8_lossy(&out).contains("not valid UTF-8"));
                return Ok(());
            };
            if check(text)? {
                accepted.fetch_add(1, Ordering::Relaxed);
            }
            Ok(())
        })
        .expect("no mutated line panics or gives an empty error");
    report("mutated valid lines", &ran, &accepted);
}

/// `line` split around its number literals: the text pieces, one more than the numbers.
fn split_numbers(line: &str) -> Vec<&str> {
    let bytes = line.as_bytes();
    let mut pieces = Vec::new();
    let (mut start, mut i) = (0, 0);
    while i < bytes.len() {
        let after_separator = i > 0 && matches!(bytes[i - 1], b' ' | b'[' | b',' | b':');
        if after_separator && (bytes[i].is_ascii_digit() || bytes[i] == b'-') {
            pieces.push(&line[start..i]);
            while i < bytes.len() && matches!(bytes[i], b'0'..=b'9' | b'-' | b'+' | b'.' | b'e' | b'E') {
                i += 1;
            }
            start = i;
        } else {
            i += 1;
        }
    }
    pieces.push(&line[start..]);
    pieces
}

/// A number of any magnitude: zero, tiny, ordinary, huge, beyond f32, negative.
fn number() -> impl Strategy<Value = String> {
    prop_oneof![
        Just("0".to_string()),
        Just("-0".to_string()),
        (-2.0f64..2.0).prop_map(|x| format!("{x}")),
        (-100.0f64..100.0).prop_map(|x| format!("{x}")),
        any::<f32>().prop_filter_map("finite", |x| x.is_finite().then(|| format!("{x:e}"))),
        (-320i32..320).prop_map(|e| format!("1e{e}")),
        (-50i32..50).prop_map(|e| format!("-3.5e{e}")),
    ]
}

#[test]
fn valid_structure_with_any_numbers_never_panics() {
    // Every number of a valid line replaced: the evaluation paths (normalize, pow,
    // attenuation, spot cone) meet zero, denormal, huge and negative values.
    let (ran, accepted) = (AtomicUsize::new(0), AtomicUsize::new(0));
    let templates: Vec<Vec<&str>> = VALID.iter().map(|l| split_numbers(l)).collect();
    let strategy = (0..templates.len()).prop_flat_map(|t| (Just(t), prop::collection::vec(number(), 64)));
    runner(5)
        .run(&strategy, |(t, numbers)| {
            let pieces = &templates[t];
            let mut line = String::from(pieces[0]);
            for (piece, n) in pieces[1..].iter().zip(numbers.iter().cycle()) {
                line.push_str(n);
                line.push_str(piece);
            }
            ran.fetch_add(1, Ordering::Relaxed);
            if check(&line)? {
                accepted.fetch_add(1, Ordering::Relaxed);
            }
            Ok(())
        })
        .expect("no number panics");
    report("valid structure, any numbers", &ran, &accepted);
}

#[test]
fn objects_of_known_keys_never_panic() {
    let (ran, accepted) = (AtomicUsize::new(0), AtomicUsize::new(0));
    let model = prop::sample::select(vec!["learnopengl", "blinn-phong", "opengl-tutorial", "ogldev", "basic_lighting"]);
    let strategy = (model, prop::collection::vec((prop::sample::select(&KEYS[..]), json_value()), 0..10));
    runner(2)
        .run(&strategy, |(model, fields)| {
            let body: Vec<String> = fields.iter().map(|(k, v)| format!("\"{k}\": {v}")).collect();
            let line = format!("{{\"model\": \"{model}\", {}}}", body.join(", "));
            ran.fetch_add(1, Ordering::Relaxed);
            if check(&line)? {
                accepted.fetch_add(1, Ordering::Relaxed);
            }
            Ok(())
        })
        .expect("no object panics or gives an empty error");
    report("objects of known keys", &ran, &accepted);
}

#[test]
fn arbitrary_text_never_panics() {
    let (ran, accepted) = (AtomicUsize::new(0), AtomicUsize::new(0));
    runner(3)
        .run(&"\\PC{0,200}", |text| {
            ran.fetch_add(1, Ordering::Relaxed);
            if check(&text)? {
                accepted.fetch_add(1, Ordering::Relaxed);
            }
            Ok(())
        })
        .expect("no text panics");
    report("arbitrary text", &ran, &accepted);
}

#[test]
fn a_batch_answers_every_line_in_order() {
    // `process` over many fuzzed lines at once: one output line per non-blank,
    // non-comment input line, numbered as the input.
    let mut runner = runner(4);
    let (ran, batches) = (AtomicUsize::new(0), AtomicUsize::new(0));
    let strategy = prop::collection::vec(json_value(), 1..50);
    runner
        .run(&strategy, |values| {
            ran.fetch_add(values.len(), Ordering::Relaxed);
            batches.fetch_add(1, Ordering::Relaxed);
            let input: String = values.iter().map(|v| format!("{}\n", v.replace('\n', " "))).collect();
            let mut out = Vec::new();
            process(input.as_bytes(), &mut out, "fuzz").map_err(|e| TestCaseError::fail(e.to_string()))?;
            let numbers: Vec<u64> = String::from_utf8_lossy(&out)
                .lines()
                .map(|l| {
                    serde_json::from_str::<serde_json::Value>(l).ok().and_then(|v| v["line"].as_u64()).unwrap_or(0)
                })
                .collect();
            let want: Vec<u64> = (1..=values.len() as u64)
                .filter(|&i| {
                    let t = values[i as usize - 1].trim();
                    !t.is_empty() && !t.starts_with('#')
                })
                .collect();
            prop_assert_eq!(numbers, want);
            Ok(())
        })
        .expect("every line answered");
    println!("batches: {} lines in {} batches, 0 panics", ran.load(Ordering::Relaxed), batches.load(Ordering::Relaxed));
}
