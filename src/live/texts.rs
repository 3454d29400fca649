//! The words of the live figures and exercises in the reader's language.
//!
//! The page data (`generated/live/<id>.js`, `exercise-<id>.js`) stays English: its texts are
//! msgids. A translated page loads one more script, `generated/<code>/live/texts.js`, which
//! sets `window.LIGHTLAB_TEXTS` to `{english: translation}` for every text the page can
//! show; `book/theme/live/lightlab-i18n.js` looks them up (`T('…')`, `TF('… {} …', [args])`).
//! The dictionary holds:
//! - the JavaScript's own words: every `T('…')` and `TF('…'` literal of the vendored scripts
//!   ([`script_msgids`]);
//! - the page data's texts: the strings under the keys in [`DISPLAY_KEYS`] (titles,
//!   statements, labels, the mistakes' titles and explanations, the isolation sentences).
//!
//! Each goes through [`crate::i18n::tr`], so the template records them when the English
//! dictionary is generated (see `crate::book::drawn_words`).

use std::collections::BTreeSet;

use serde_json::{json, Map, Value};

use crate::i18n::{tr, Lang};

/// The vendored scripts whose `T('…')` and `TF('…'` literals are page words.
pub const SCRIPTS: [(&str, &str); 8] = [
    ("book/theme/live/lightlab-i18n.js", include_str!("../../book/theme/live/lightlab-i18n.js")),
    ("book/theme/live/lightlab-gl.js", include_str!("../../book/theme/live/lightlab-gl.js")),
    ("book/theme/live/lightlab-live.js", include_str!("../../book/theme/live/lightlab-live.js")),
    ("book/theme/live/lightlab-answer.js", include_str!("../../book/theme/live/lightlab-answer.js")),
    ("book/theme/live/lightlab-decision.js", include_str!("../../book/theme/live/lightlab-decision.js")),
    ("book/theme/live/lightlab-exercise.js", include_str!("../../book/theme/live/lightlab-exercise.js")),
    ("book/theme/live/lightlab-pair.js", include_str!("../../book/theme/live/lightlab-pair.js")),
    ("book/theme/live/lightlab-learner.js", include_str!("../../book/theme/live/lightlab-learner.js")),
];

/// The keys of the page data whose string values (or arrays or objects of strings) a reader
/// sees. `name` counts only inside `switches` (elsewhere it is a shader identifier).
pub const DISPLAY_KEYS: [&str; 22] = [
    "title",
    "hints",
    "hint_args",
    "equivalence_reason",
    "statement",
    "choice",
    "text",
    "why",
    "evidence",
    "label",
    "flag_labels",
    "isolation",
    "slow_text",
    "loop_text",
    "lost_text",
    "never_read_text",
    "forbidden_text",
    "required_text",
    "right",
    "unit",
    "x",
    "y",
];

/// A control option's label built from numbers: the light's time in Basic lighting.
pub const LABEL_TIME: &str = "t = {}";
/// The material's time in seconds (Materials' changing light).
pub const LABEL_SECONDS: &str = "t = {} s";
/// The flashlight's orbiting camera.
pub const LABEL_ORBIT: &str = "azimuth {}°, elevation {}°";
/// A row of the attenuation table: the range, then constant, linear, quadratic.
pub const LABEL_RANGE: &str = "range {} ({}, {}, {})";

/// The labels built from numbers ([`LABEL_TIME`], ...). Each is one msgid, translated once
/// and filled with the numbers as the language writes them ([`Lang::numbers_in`]), instead
/// of one msgid per value: a page word that fits one is looked up through it
/// ([`texts_script`]).
pub const LABEL_TEMPLATES: [&str; 4] = [LABEL_SECONDS, LABEL_TIME, LABEL_ORBIT, LABEL_RANGE];

/// The numbers of `word` in the blanks of `template` (`{}`), if `word` is `template` filled
/// with numbers (`-10`, `0.5`), else `None`.
#[must_use]
pub fn template_numbers<'w>(template: &str, word: &'w str) -> Option<Vec<&'w str>> {
    let parts: Vec<&str> = template.split("{}").collect();
    let mut rest = word.strip_prefix(parts[0])?;
    let mut numbers = Vec::with_capacity(parts.len() - 1);
    for (k, part) in parts.iter().enumerate().skip(1) {
        let end = if k + 1 == parts.len() {
            rest.len().checked_sub(part.len()).filter(|&e| rest[e..] == **part)?
        } else if part.is_empty() {
            return None; // two blanks side by side cannot be told apart
        } else {
            rest.find(part)?
        };
        let number = &rest[..end];
        if !is_number(number) {
            return None;
        }
        numbers.push(number);
        rest = &rest[end + part.len()..];
    }
    rest.is_empty().then_some(numbers)
}

/// `-12`, `0.5`, `3`: an optional minus, digits, and an optional fraction.
fn is_number(s: &str) -> bool {
    let digits = s.strip_prefix('-').unwrap_or(s);
    let (whole, fraction) = digits.split_once('.').unwrap_or((digits, "0"));
    !whole.is_empty()
        && !fraction.is_empty()
        && whole.bytes().all(|b| b.is_ascii_digit())
        && fraction.bytes().all(|b| b.is_ascii_digit())
}

/// `word` in `lang` through the label template it fits, if it fits one.
fn through_template(lang: Lang, word: &str) -> Option<String> {
    LABEL_TEMPLATES.iter().find_map(|t| {
        let numbers: Vec<String> = template_numbers(t, word)?.into_iter().map(|n| lang.numbers_in(n)).collect();
        let numbers: Vec<&str> = numbers.iter().map(String::as_str).collect();
        Some(crate::blanks::fill(&tr(lang, t), &numbers))
    })
}

/// The string literal opening at `s` (after its quote `q`), unescaped, and its length with
/// the closing quote; `None` if it does not close on the line.
fn js_string(s: &str, q: char) -> Option<(String, usize)> {
    let mut out = String::new();
    let mut chars = s.char_indices();
    while let Some((i, c)) = chars.next() {
        match c {
            '\\' => match chars.next()? {
                (_, 'n') => out.push('\n'),
                (_, other) => out.push(other),
            },
            '\n' => return None,
            c if c == q => return Some((out, i + 1)),
            c => out.push(c),
        }
    }
    None
}

/// Every `T('…')` / `TF('…'` literal (single or double quotes) of `source`, in order. A call
/// whose name continues a longer identifier (`xT(`) is not one.
#[must_use]
pub fn script_msgids(source: &str) -> Vec<String> {
    let mut out = Vec::new();
    for call in ["T(", "TF("] {
        let mut from = 0;
        while let Some(at) = source[from..].find(call).map(|i| i + from) {
            from = at + call.len();
            let before = source[..at].chars().next_back();
            if before.is_some_and(|c| c.is_alphanumeric() || c == '_' || c == '$' || c == '.') {
                continue;
            }
            let rest = &source[from..];
            let Some(q) = rest.chars().next().filter(|c| *c == '\'' || *c == '"') else { continue };
            if let Some((text, _)) = js_string(&rest[1..], q) {
                out.push(text);
            }
        }
    }
    out
}

/// Every string a reader sees in page data `v` (see [`DISPLAY_KEYS`]), into `out`.
pub fn display_strings(v: &Value, out: &mut BTreeSet<String>) {
    fn strings(v: &Value, out: &mut BTreeSet<String>) {
        match v {
            Value::String(s) if !s.is_empty() => {
                out.insert(s.clone());
            }
            Value::Array(a) => a.iter().for_each(|x| strings(x, out)),
            Value::Object(o) => o.values().for_each(|x| strings(x, out)),
            _ => {}
        }
    }
    fn walk(v: &Value, parent: &str, out: &mut BTreeSet<String>) {
        match v {
            Value::Object(o) => {
                for (k, x) in o {
                    if DISPLAY_KEYS.contains(&k.as_str()) || (parent == "switches" && k == "name") {
                        strings(x, out);
                    } else {
                        walk(x, k, out);
                    }
                }
            }
            Value::Array(a) => a.iter().for_each(|x| walk(x, parent, out)),
            _ => {}
        }
    }
    walk(v, "", out);
}

/// The page words: the scripts' literals and the display strings of `data`.
#[must_use]
pub fn page_words<'a>(data: impl IntoIterator<Item = &'a Value>) -> BTreeSet<String> {
    let mut out: BTreeSet<String> = SCRIPTS.iter().flat_map(|(_, s)| script_msgids(s)).collect();
    for v in data {
        display_strings(v, &mut out);
    }
    out
}

/// `texts.js` in `lang`: `window.LIGHTLAB_TEXTS` holding the translation of each of `words`
/// that has one (English gets an empty dictionary; every word is still looked up, so the
/// template hears it), the language's code, and its decimal sign (`LIGHTLAB_DECIMAL`, from
/// [`Lang::decimal_comma`]), with which the scripts write the numbers they compute, and the
/// rest of how it writes them (`LIGHTLAB_NUMBERS`: a list's separator, the minus sign and the
/// characters a sign follows, from [`Lang::list_separator`], [`Lang::minus_sign`] and
/// [`crate::i18n::SIGN_FOLLOWS`]), so that a script's `-0.5` or list reads as the crate's.
#[must_use]
pub fn texts_script(lang: Lang, words: &BTreeSet<String>) -> Vec<u8> {
    let mut dict = Map::new();
    for w in words {
        let t = through_template(lang, w).unwrap_or_else(|| tr(lang, w).into_owned());
        if t != w.as_str() {
            dict.insert(w.clone(), json!(t));
        } else if crate::i18n::extract::is_neutral(w) {
            // a slider's number (`0.05`) is no msgid, but is written as the language writes it
            let n = lang.numbers_in(w);
            if n != *w {
                dict.insert(w.clone(), json!(n));
            }
        }
    }
    format!(
        "// generated by lightlab (src/live/texts.rs) from po/{}.po: the page's words in this language\n\
         window.LIGHTLAB_TEXTS = {};\nwindow.LIGHTLAB_LANG = {};\nwindow.LIGHTLAB_DECIMAL = {};\n\
         window.LIGHTLAB_NUMBERS = {};\n",
        lang.code(),
        Value::Object(dict),
        json!(lang.code()),
        json!(if lang.decimal_comma() { "," } else { "." }),
        json!({
            "list": lang.list_separator(),
            "minus": lang.minus_sign().to_string(),
            "sign_follows": crate::i18n::SIGN_FOLLOWS,
        })
    )
    .into_bytes()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_sliders_numbers_take_the_languages_decimal_sign() {
        let words: BTreeSet<String> = ["0.05", "12.5°", "32"].iter().map(|s| (*s).to_owned()).collect();
        let fr = String::from_utf8(texts_script(Lang::Fr, &words)).unwrap();
        assert!(fr.contains(r#""0.05":"0,05""#) && fr.contains(r#""12.5°":"12,5°""#), "{fr}");
        assert!(!fr.contains(r#""32""#), "an integer needs no entry: {fr}");
        let en = String::from_utf8(texts_script(Lang::En, &words)).unwrap();
        assert!(en.contains("window.LIGHTLAB_TEXTS = {};"), "{en}");
    }

    #[test]
    fn the_scripts_get_the_languages_decimal_sign_for_the_numbers_they_compute() {
        let words = BTreeSet::new();
        for (lang, sign) in [(Lang::En, "\".\""), (Lang::Fr, "\",\""), (Lang::Uk, "\",\"")] {
            let script = String::from_utf8(texts_script(lang, &words)).unwrap();
            assert!(script.contains(&format!("window.LIGHTLAB_DECIMAL = {sign};")), "{lang:?}: {script}");
        }
    }

    #[test]
    fn the_scripts_get_the_languages_list_separator_and_minus_sign() {
        for lang in Lang::ALL {
            let script = String::from_utf8(texts_script(lang, &BTreeSet::new())).unwrap();
            let line =
                script.lines().find_map(|l| l.strip_prefix("window.LIGHTLAB_NUMBERS = ")).expect("the numbers line");
            let facts: Value = serde_json::from_str(line.trim_end_matches(';')).unwrap();
            // the facts are those numbers_in applies: a list of two negative numbers written
            // with them is numbers_in of the English list
            let (list, minus) = (facts["list"].as_str().unwrap(), facts["minus"].as_str().unwrap());
            assert_eq!(
                format!("({minus}1{list}{minus}0{}5)", if lang.decimal_comma() { "," } else { "." }),
                lang.numbers_in("(-1, -0.5)"),
                "{lang:?}"
            );
            assert_eq!(facts["sign_follows"], crate::i18n::SIGN_FOLLOWS);
        }
    }

    #[test]
    fn a_label_built_from_numbers_is_one_message_filled_as_the_language_writes_numbers() {
        assert_eq!(template_numbers(LABEL_ORBIT, "azimuth 105°, elevation -10°"), Some(vec!["105", "-10"]));
        assert_eq!(template_numbers(LABEL_TIME, "t = 0.25"), Some(vec!["0.25"]));
        assert_eq!(template_numbers(LABEL_TIME, "t = 0.25 s"), None, "the seconds are another template");
        assert_eq!(template_numbers(LABEL_SECONDS, "t = 0.25 s"), Some(vec!["0.25"]));
        assert_eq!(template_numbers(LABEL_RANGE, "range 7 (1, 0.7, 1.8)"), Some(vec!["7", "1", "0.7", "1.8"]));
        for not_numbers in ["t = x", "t = ", "t = 1.", "t = .5", "t = 1.5.2", "azimuth 105°, elevation -10° more"] {
            assert!(LABEL_TEMPLATES.iter().all(|t| template_numbers(t, not_numbers).is_none()), "{not_numbers}");
        }
        let words: BTreeSet<String> = ["t = 0.25 s".to_owned(), "range 7 (1, 0.7, 1.8)".to_owned()].into();
        let (fr, heard) = crate::i18n::catalog::record(|| String::from_utf8(texts_script(Lang::Fr, &words)).unwrap());
        // the French PO writes the range's list with semicolons, as its decimal commas need
        assert!(fr.contains(r#""t = 0.25 s":"t = 0,25 s""#) && fr.contains("(1\u{a0}; 0,7\u{a0}; 1,8)"), "{fr}");
        assert!(heard.contains(LABEL_SECONDS) && !heard.contains("t = 0.25 s"), "the template is the msgid: {heard:?}");
    }

    #[test]
    fn script_literals_are_found_and_unescaped() {
        let js = r#"a(T('Check')); b = TF("{} of {} cases", [1, 2]); xT('no'); o.T('no'); T('it\'s'); T(name);"#;
        assert_eq!(script_msgids(js), ["Check", "it's", "{} of {} cases"]);
    }

    #[test]
    fn display_strings_skip_shader_names_and_sources() {
        let v = json!({
            "title": "Basic lighting", "reference": "void main() {}",
            "quantities": [{"name": "light.position"}],
            "switches": [{"name": "the ambient term", "quantities": ["ambient"]}],
            "isolation": {"one": "the difference is in {} only"},
            "mutants": [{"id": "x", "title": "Blinn for Phong", "why": "the halfway vector", "shader": "void main() {}"}]
        });
        let mut out = BTreeSet::new();
        display_strings(&v, &mut out);
        let want = [
            "Basic lighting",
            "Blinn for Phong",
            "the ambient term",
            "the difference is in {} only",
            "the halfway vector",
        ];
        assert_eq!(out.into_iter().collect::<Vec<_>>(), want);
    }

    /// The first argument of every canvas text call (`fillText(`, `strokeText(`) in
    /// `source`, up to the first top-level comma, with the 1-based line it is on.
    fn canvas_texts(source: &str) -> Vec<(usize, String)> {
        let mut out = Vec::new();
        for (n, line) in source.lines().enumerate() {
            for call in [".fillText(", ".strokeText("] {
                let mut rest = line;
                while let Some(at) = rest.find(call) {
                    rest = &rest[at + call.len()..];
                    let mut depth = 0;
                    let end = rest
                        .char_indices()
                        .find(|&(_, c)| {
                            depth += i32::from(c == '(') - i32::from(c == ')');
                            depth == 0 && c == ','
                        })
                        .map_or(rest.len(), |(i, _)| i);
                    out.push((n + 1, rest[..end].trim().to_owned()));
                }
            }
        }
        out
    }

    /// Whether canvas text `arg` reaches the reader in the page's language: a translated
    /// word (`T(…)`, `TF(…)`), a computed number (`number(…)`), or a literal with no letter
    /// (a tick's `'0'`), joined by `+`.
    fn in_the_page_language(arg: &str) -> bool {
        let mut depth = 0;
        let mut parts = vec![String::new()];
        for c in arg.chars() {
            depth += i32::from(c == '(') - i32::from(c == ')');
            if c == '+' && depth == 0 {
                parts.push(String::new());
            } else if let Some(last) = parts.last_mut() {
                last.push(c);
            }
        }
        parts.iter().map(|p| p.trim()).all(|p| {
            ["T(", "TF(", "number("].iter().any(|f| p.starts_with(f))
                || ((p.starts_with('\'') || p.starts_with('"')) && !p.chars().any(char::is_alphabetic))
        })
    }

    /// Canvas text is not in the DOM, so the pages' translation checks never see it: a
    /// label drawn on a canvas must be a page word itself. (The attenuation curve once drew
    /// its axes' English names, `axes.y + ' 1'`, on the French and Ukrainian pages.)
    #[test]
    fn canvas_text_is_drawn_in_the_pages_language() {
        assert!(!in_the_page_language("axes.y + ' 1'"));
        assert!(!in_the_page_language("'distance'"));
        assert!(in_the_page_language("T(axes.x) + ' ' + number(axes.max)"));
        let mut calls = 0;
        for (path, source) in SCRIPTS {
            for (line, arg) in canvas_texts(source) {
                calls += 1;
                assert!(in_the_page_language(&arg), "{path}:{line}: canvas text `{arg}` is not translated");
            }
        }
        assert!(calls >= 3, "the curve's labels are drawn on a canvas: {calls} calls found");
    }

    /// A literal glued to a translated word with `+` that holds `:`, `;`, `?` or `!`: the
    /// punctuation French writes after a no-break space, which only a whole message
    /// (`TF('{}: {}', …)`) can carry.
    fn glued_punctuation(source: &str) -> Vec<(usize, String)> {
        let mut found = Vec::new();
        for (n, line) in source.lines().enumerate().filter(|(_, l)| l.contains("T(")) {
            let parts: Vec<&str> = line.split('\'').collect();
            for k in (1..parts.len().saturating_sub(1)).step_by(2) {
                let joined = parts[k - 1].trim_end().ends_with('+') || parts[k + 1].trim_start().starts_with('+');
                if joined && parts[k].chars().any(|c| matches!(c, ':' | ';' | '?' | '!')) {
                    found.push((n + 1, parts[k].to_owned()));
                }
            }
        }
        found
    }

    #[test]
    fn punctuation_that_french_spaces_comes_through_a_whole_message() {
        assert_eq!(glued_punctuation("x = T(a) + ': ' + T(b);").len(), 1);
        assert!(glued_punctuation("x = TF('{}: {}', [T(a), T(b)]);").is_empty());
        assert!(glued_punctuation("x = T('a: b') + T(c);").is_empty(), "a whole message may hold a colon");
        for (path, source) in SCRIPTS {
            let found = glued_punctuation(source);
            assert!(found.is_empty(), "{path}: punctuation glued to translated text with +: {found:?}");
        }
    }

    #[test]
    fn every_script_has_page_words() {
        for (path, source) in SCRIPTS.iter().skip(1) {
            assert!(script_msgids(source).len() > 3, "{path}: its words are not marked with T('…')");
        }
    }
}
