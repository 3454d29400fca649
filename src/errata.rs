//! Every number the tutorials print, recomputed.
//!
//! STAND-IN written on the `tables` branch with the API the lead specified;
//! the lead's `src/errata.rs` on main replaces it (same API, all entries).
//!
//! | field | meaning |
//! | --- | --- |
//! | `published` | the number as the seed prints it |
//! | `recomputed` | the value from the formula with exact inputs, in `f64` |
//! | `agrees` | whether the published value is the recomputed one after the rounding the text uses |

/// One printed number with its recomputed value.
#[derive(Clone, Debug, PartialEq)]
pub struct Entry {
    /// Stable identifier (`E2-phi`, ...).
    pub id: &'static str,
    /// Seed and line.
    pub source: &'static str,
    /// What the number is.
    pub quantity: &'static str,
    /// The printed text.
    pub published: &'static str,
    /// The printed value as a number, when it is one.
    pub published_value: Option<f64>,
    /// The value recomputed from the formula.
    pub recomputed: f64,
    /// Whether the printed value agrees after the text's rounding.
    pub agrees: bool,
    /// The cause of a discrepancy, or how the value was rounded.
    pub note: &'static str,
}

/// The entries (a subset in this stand-in); discrepancies have `agrees == false`.
///
/// Source: /work/scratch/research.md §1.1.b and §5 (E2, E5).
pub fn entries() -> Vec<Entry> {
    let cos_deg = |d: f64| d.to_radians().cos();
    let (phi, gamma, theta) = (cos_deg(12.5), cos_deg(17.5), cos_deg(15.0));
    vec![
        Entry {
            id: "E2-phi",
            source: "LearnOpenGL, Light casters, spotlight table row 6",
            quantity: "φ = cos(12.5°)",
            published: "0.9978",
            published_value: Some(0.9978),
            recomputed: phi,
            agrees: false,
            note: "0.9978 is cos(12.5 radians); cos(12.5°) = 0.9763",
        },
        Entry {
            id: "E2-I",
            source: "LearnOpenGL, Light casters, spotlight table row 6",
            quantity: "I = (θ − γ)/ε at θ = 15°, φ = 12.5°, γ = 17.5°",
            published: "0.29",
            published_value: Some(0.29),
            recomputed: (theta - gamma) / (phi - gamma),
            agrees: false,
            note: "follows from the wrong φ (degrees/radians slip)",
        },
        Entry {
            id: "E5",
            source: "LearnOpenGL, Colors",
            quantity: "blue of olive (0.33, 0.42, 0.18) × coral (1, 0.5, 0.31)",
            published: "0.06",
            published_value: Some(0.06),
            recomputed: 0.18 * 0.31,
            agrees: true,
            note: "0.0558 rounded to two decimals",
        },
    ]
}
