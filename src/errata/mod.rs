//! Every checkable claim the four tutorials print, checked: one table of
//! "source | quantity | published | recomputed | verdict | note", used by the tests,
//! the `errata` example and the book's errata chapter.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | [`Cite`] | one place in a seed: seed number, line range, chapter and section |
//! | [`Verdict`] | `agrees`, `rounding`, `DISCREPANCY` (a wrong number) or `text` (a wrong statement, formula or listing) |
//! | [`Recomputed`] | lightlab's value (from the `f32` core or the `f64` [`crate::reference`]) or the verified statement |
//! | [`Entry`] | one claim with its citations, excerpt, recomputation, verdict and cause |
//!
//! A claim is a printed number (computed or quoted), a constant printed in two places,
//! a statement of direction or monotonicity, a count, a listing that contradicts its
//! text or would not compile, or a formula as typeset (precedence included).
//!
//! Verdicts for numbers, with `p` the printed value, `k` its count of decimals and `r`
//! the recomputed one:
//!
//! ```text
//! agrees       |p − r| ≤ 1e-7 · max(1, |r|)           (printed exactly; 1e-7 covers the
//!                                                      f32 rounding of the core's constants)
//! rounding     |p − r| ≤ ½ · 10^(−k)  (+1e-12)          (equal at printed precision),
//!              or p is what the text's own rounded inputs give
//! DISCREPANCY  anything else
//! ```
//!
//! Statements, counts, formulas and listings are `agrees` when the check holds and
//! `text` when it does not; every such check is computed here or, for a listing that
//! does not compile, shown on OpenGL by `tests/gl_errata.rs`.
//!
//! Seeds: `000` LearnOpenGL "Lighting" (French), `001` opengl-tutorial 8 (French), `002`
//! ogldev 19 (French), `003` the Ukrainian lecture and lab on LearnOpenGL. A citation
//! names the seed, its lines, and the chapter and section as the tutorial prints them,
//! so a reader with the published page finds the place.

use std::fmt::Write as _;

mod casters;
mod colors;
mod lighting;
pub mod listings;
mod multiple;
mod ogldev;
mod opengl_tutorial;
mod spot;
mod wording;

/// One place in a seed document.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Cite {
    /// Seed number: 0 LearnOpenGL (fr), 1 opengl-tutorial 8, 2 ogldev 19, 3 the Ukrainian lab.
    pub seed: u8,
    /// First line (1-based, as in `shared/seeds/`).
    pub from: u32,
    /// Last line (equal to `from` for one line).
    pub to: u32,
}

impl Cite {
    /// `l.N` or `l.N-M`.
    pub fn lines(&self) -> String {
        if self.from == self.to {
            format!("l.{}", self.from)
        } else {
            format!("l.{}-{}", self.from, self.to)
        }
    }

    /// The tutorial's chapter and section holding the first line, e.g.
    /// `Light casters › V-D Lampe frontale`.
    pub fn section(&self) -> String {
        let (chapter, section) = headings(self.seed)
            .take_while(|(line, _, _)| *line <= self.from)
            .last()
            .map_or(("", ""), |(_, c, s)| (c, s));
        if section.is_empty() {
            chapter.to_string()
        } else {
            format!("{chapter} › {section}")
        }
    }
}

/// The seeds' headings, one file per seed (`quoted/sections_00N.tsv`): a line per heading,
/// `first line<TAB>chapter<TAB>section as printed`, in line order. Chapters are named as in
/// the original tutorials so the French and Ukrainian texts line up.
const SECTIONS: [&str; 4] = [
    include_str!("quoted/sections_000.tsv"),
    include_str!("quoted/sections_001.tsv"),
    include_str!("quoted/sections_002.tsv"),
    include_str!("quoted/sections_003.tsv"),
];

/// The headings of seed `seed` (0 to 3; larger reads 3) as `(first line, chapter,
/// section)`; a line that does not parse is skipped (a test holds every line to the form).
fn headings(seed: u8) -> impl Iterator<Item = (u32, &'static str, &'static str)> {
    SECTIONS[usize::from(seed.min(3))].lines().filter_map(|l| {
        let mut f = l.split('\t');
        let line = f.next()?.parse().ok()?;
        Some((line, f.next()?, f.next().unwrap_or("")))
    })
}

/// The outcome of checking one claim.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Verdict {
    /// A wrong number.
    Discrepancy,
    /// A wrong statement, formula as typeset, count or listing.
    Text,
    /// A number equal at its printed precision, or to what its own rounded inputs give.
    Rounding,
    /// Printed exactly, or a statement that holds.
    Agrees,
}

impl Verdict {
    /// The label of the table's `verdict` column.
    pub fn label(self) -> &'static str {
        match self {
            Verdict::Discrepancy => "DISCREPANCY",
            Verdict::Text => "text",
            Verdict::Rounding => "rounding",
            Verdict::Agrees => "agrees",
        }
    }

    /// All four, in the table's order (errata first).
    pub const ALL: [Verdict; 4] = [Verdict::Discrepancy, Verdict::Text, Verdict::Rounding, Verdict::Agrees];
}

/// lightlab's side of a claim.
#[derive(Clone, Debug, PartialEq)]
pub enum Recomputed {
    /// A value computed by the crate.
    Number(f64),
    /// The verified statement (for counts, directions, formulas and listings), with the
    /// crate's numbers formatted into it.
    Statement(String),
}

impl Recomputed {
    /// The number, when there is one.
    pub fn value(&self) -> Option<f64> {
        match self {
            Recomputed::Number(x) => Some(*x),
            Recomputed::Statement(_) => None,
        }
    }

    /// The cell: a number with 6 decimals, or the statement.
    pub fn cell(&self) -> String {
        match self {
            Recomputed::Number(x) => crate::table::num(*x, 6),
            Recomputed::Statement(s) => s.clone(),
        }
    }
}

/// One printed claim and its check.
#[derive(Clone, Debug, PartialEq)]
pub struct Entry {
    /// Short stable identifier, e.g. `spot-row6-phi`. Rows that differ between the French
    /// and the Ukrainian text end in `-fr` and `-uk`.
    pub id: String,
    /// Every place the claim is printed.
    pub cites: Vec<Cite>,
    /// The citations as one cell: `000 l.N (chapter › section); 003 l.M (…)`.
    pub source: String,
    /// What is claimed.
    pub quantity: String,
    /// The printed excerpt, short.
    pub published: String,
    /// The printed number, when the claim is one (or the value the printed formula gives).
    pub published_value: Option<f64>,
    /// lightlab's value or the verified statement.
    pub recomputed: Recomputed,
    /// The check's outcome.
    pub verdict: Verdict,
    /// `true` for `agrees` and `rounding` (no erratum).
    pub agrees: bool,
    /// The cause of an erratum, or how the check was done.
    pub note: String,
}

/// Whether `published` (as printed) equals `value` to the printed precision.
///
/// ```text
/// |published − value| ≤ ½ · 10^(−decimals)   (+ 1e-12 for the binary representation)
/// ```
///
/// `false` when `published` is not a plain decimal number.
// ANCHOR: agrees_to_printed_precision
pub fn agrees_to_printed_precision(published: &str, value: f64) -> bool {
    let Ok(p) = published.trim().parse::<f64>() else {
        return false;
    };
    let decimals = published.trim().split_once('.').map_or(0, |(_, frac)| frac.len()) as i32;
    (p - value).abs() <= 0.5 * 10f64.powi(-decimals) + 1e-12
}
// ANCHOR_END: agrees_to_printed_precision

/// Whether `published` is `value` itself (not only its rounding):
/// `|p − value| ≤ 1e-7 · max(1, |value|)`. The margin is the `f32` rounding of the core's
/// constants (half an ulp is 6e-8 relative: `0.1f32` widens to 0.10000000149).
/// `false` when `published` is not a number.
pub fn printed_exactly(published: &str, value: f64) -> bool {
    published.trim().parse::<f64>().is_ok_and(|p| (p - value).abs() <= 1e-7 * value.abs().max(1.0))
}

/// The verdict of a printed number against its recomputation (see the module docs).
pub fn number_verdict(published: &str, value: f64) -> Verdict {
    if printed_exactly(published, value) {
        Verdict::Agrees
    } else if agrees_to_printed_precision(published, value) {
        Verdict::Rounding
    } else {
        Verdict::Discrepancy
    }
}

/// Citations from `(seed, from, to)` triples.
pub(crate) fn cites(places: &[(u8, u32, u32)]) -> Vec<Cite> {
    places.iter().map(|&(seed, from, to)| Cite { seed, from, to }).collect()
}

/// The `source` cell: citations grouped by seed and section, in the order given.
pub fn source_cell(cites: &[Cite]) -> String {
    let mut groups: Vec<(u8, String, Vec<String>)> = Vec::new();
    for c in cites {
        let section = c.section();
        match groups.last_mut() {
            Some((seed, s, lines)) if *seed == c.seed && *s == section => lines.push(c.lines()),
            _ => groups.push((c.seed, section, vec![c.lines()])),
        }
    }
    let mut out = String::new();
    for (i, (seed, section, lines)) in groups.iter().enumerate() {
        if i > 0 {
            out += "; ";
        }
        let _ = write!(out, "{seed:03} {} ({section})", lines.join(", "));
    }
    out
}

/// Where a claim is printed: its identifier and citations, as `(seed, from, to)`.
/// [`At::says`] adds what it says, then [`Said::number`] or [`Said::holds`] checks it.
pub(crate) struct At<'a> {
    id: &'a str,
    places: &'a [(u8, u32, u32)],
}

/// A claim's place and words (the quantity and the printed excerpt), before its check.
pub(crate) struct Said<'a> {
    at: At<'a>,
    quantity: &'a str,
    published: &'a str,
}

/// Start an entry: the claim `id`, printed at `places`.
pub(crate) fn cited<'a>(id: &'a str, places: &'a [(u8, u32, u32)]) -> At<'a> {
    At { id, places }
}

impl<'a> At<'a> {
    /// What is claimed (`quantity`) and the printed excerpt (`published`).
    pub(crate) fn says(self, quantity: &'a str, published: &'a str) -> Said<'a> {
        Said { at: self, quantity, published }
    }
}

impl Said<'_> {
    fn entry(&self, note: &str) -> Entry {
        let cites = cites(self.at.places);
        Entry {
            id: self.at.id.to_string(),
            source: source_cell(&cites),
            cites,
            quantity: self.quantity.to_string(),
            published: self.published.to_string(),
            published_value: self.published.trim().parse().ok(),
            recomputed: Recomputed::Number(f64::NAN),
            verdict: Verdict::Agrees,
            agrees: true,
            note: note.to_string(),
        }
    }

    /// A printed number against the crate's value; the verdict follows [`number_verdict`].
    pub(crate) fn number(self, recomputed: f64, note: &str) -> Entry {
        let verdict = number_verdict(self.published, recomputed);
        Entry {
            recomputed: Recomputed::Number(recomputed),
            verdict,
            agrees: verdict >= Verdict::Rounding,
            ..self.entry(note)
        }
    }

    /// A statement, count, formula or listing: `agrees` when `holds`, `text` otherwise.
    pub(crate) fn holds(self, holds: bool, statement: String, note: &str) -> Entry {
        let verdict = if holds { Verdict::Agrees } else { Verdict::Text };
        Entry {
            recomputed: Recomputed::Statement(statement),
            verdict,
            agrees: holds,
            published_value: None,
            ..self.entry(note)
        }
    }
}

impl Entry {
    /// A number that misses the exact value but is what the text's own rounded inputs
    /// give (`from_printed_inputs`) is `rounding`, not a discrepancy.
    pub(crate) fn or_rounding_from(mut self, from_printed_inputs: f64) -> Entry {
        if self.verdict == Verdict::Discrepancy && agrees_to_printed_precision(&self.published, from_printed_inputs) {
            self.verdict = Verdict::Rounding;
            self.agrees = true;
        }
        self
    }

    /// A printed formula (not a number) whose value at the row's input is `value`.
    pub(crate) fn with_published_value(mut self, value: f64) -> Entry {
        self.published_value = Some(value);
        self
    }

    /// A wrong formula printed as text: the row keeps its numbers, the verdict is `text`.
    pub(crate) fn into_text_erratum(mut self) -> Entry {
        self.verdict = Verdict::Text;
        self.agrees = false;
        self
    }
}

/// The seed numbers of an entry's citations, without repeats, in order.
pub fn seeds_of(e: &Entry) -> Vec<u8> {
    let mut s: Vec<u8> = e.cites.iter().map(|c| c.seed).collect();
    s.sort_unstable();
    s.dedup();
    s
}

/// Every entry, in the order of the texts (LearnOpenGL chapters with the French and
/// Ukrainian places together, then opengl-tutorial 8, then ogldev 19).
pub fn entries() -> Vec<Entry> {
    PARTS.iter().flat_map(|part| part()).collect()
}

/// The parts of the table, one function per chapter section, in the order of
/// [`entries`].
const PARTS: [fn() -> Vec<Entry>; 14] = [
    colors::products,
    colors::scene,
    lighting::basic_lighting,
    lighting::materials,
    lighting::maps,
    wording::entries,
    casters::directional,
    casters::attenuation,
    casters::range_table,
    spot::cone,
    spot::table_rows,
    multiple::entries,
    opengl_tutorial::entries,
    ogldev::entries,
];

/// Every entry with the errata first: DISCREPANCY, then `text`, then `rounding`, then
/// `agrees` (stable within each group).
pub fn discrepancies_first() -> Vec<Entry> {
    let mut all = entries();
    all.sort_by_key(|e| e.verdict);
    all
}

/// Claims per seed and how many get each verdict.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Coverage {
    /// Seed number.
    pub seed: u8,
    /// Entries citing this seed.
    pub claims: usize,
    /// Of those: `agrees`, `rounding`, `DISCREPANCY`, `text`.
    pub agrees: usize,
    /// `rounding`.
    pub rounding: usize,
    /// `DISCREPANCY`.
    pub discrepancy: usize,
    /// `text`.
    pub text: usize,
}

/// Coverage of each seed (0–3): an entry that cites several seeds counts once in each.
pub fn coverage() -> Vec<Coverage> {
    let all = entries();
    (0..4u8)
        .map(|seed| {
            let mine: Vec<&Entry> = all.iter().filter(|e| seeds_of(e).contains(&seed)).collect();
            let count = |v: Verdict| mine.iter().filter(|e| e.verdict == v).count();
            Coverage {
                seed,
                claims: mine.len(),
                agrees: count(Verdict::Agrees),
                rounding: count(Verdict::Rounding),
                discrepancy: count(Verdict::Discrepancy),
                text: count(Verdict::Text),
            }
        })
        .collect()
}

/// The seed's short name, for tables.
pub fn seed_name(seed: u8) -> &'static str {
    match seed {
        0 => "000 LearnOpenGL, Lighting (French)",
        1 => "001 opengl-tutorial 8 (French)",
        2 => "002 ogldev 19 (French)",
        _ => "003 Lecture and lab 8 on LearnOpenGL (Ukrainian)",
    }
}

/// The French/Ukrainian pairs: entries whose ids end in `-fr` and `-uk` with the same
/// stem, as `(stem, French entry, Ukrainian entry)`.
pub fn french_ukrainian_pairs() -> Vec<(String, Entry, Entry)> {
    let all = entries();
    all.iter()
        .filter_map(|fr| {
            let stem = fr.id.strip_suffix("-fr")?;
            let uk = all.iter().find(|e| e.id == format!("{stem}-uk"))?;
            Some((stem.to_string(), fr.clone(), uk.clone()))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_heading_line_parses_in_line_order() {
        for (seed, text) in SECTIONS.iter().enumerate() {
            let parsed: Vec<_> = headings(seed as u8).collect();
            assert_eq!(parsed.len(), text.lines().count(), "seed {seed}: a line does not parse");
            assert!(parsed.len() >= 4, "seed {seed}: its headings are there");
            assert!(parsed.windows(2).all(|w| w[0].0 < w[1].0), "seed {seed}: not in line order");
        }
    }
}
