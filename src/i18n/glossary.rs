//! The seeds' terms in English, French and Ukrainian: the words the French LearnOpenGL text
//! (seed 000) and the Ukrainian lab (seed 003) use, each cited by seed line, which the
//! translations of the book use too.
//!
//! Where a seed's own term is wrong (the errata's wording rows, `src/errata/wording.rs`),
//! the glossary uses the correct term, says so in `note`, and lists the wrong words in
//! `avoid`: `tests/i18n.rs` fails when a translated message uses one of them.
//!
//! The book prints this table in its appendix "Glossary" (generated from [`TERMS`]).

/// One term in the three languages.
#[derive(Debug, Clone, Copy)]
pub struct Term {
    /// The English term, as the book writes it.
    pub en: &'static str,
    /// The French term and the seed-000 line that uses it.
    pub fr: (&'static str, u32),
    /// The Ukrainian term and the seed-003 line that uses it.
    pub uk: (&'static str, u32),
    /// Stray words the French translation must not use for this term (lower case).
    pub avoid_fr: &'static [&'static str],
    /// Stray words the Ukrainian translation must not use for this term (lower case).
    pub avoid_uk: &'static [&'static str],
    /// Why a seed's term was not taken, or how the two seeds differ.
    pub note: &'static str,
}

const fn term(en: &'static str, fr: (&'static str, u32), uk: (&'static str, u32)) -> Term {
    Term { en, fr, uk, avoid_fr: &[], avoid_uk: &[], note: "" }
}

/// The terms, in the order of the chapters.
pub const TERMS: &[Term] = &[
    term("Phong lighting model", ("modèle de Phong", 1408), ("модель освітлення Phong", 2238)),
    term("ambient lighting", ("éclairage ambiant", 256), ("навколишнє освітлення", 324)),
    term("diffuse lighting", ("éclairage diffus", 288), ("розсіяне освітлення", 325)),
    term("specular lighting", ("éclairage spéculaire", 442), ("дзеркальне освітлення", 326)),
    Term {
        en: "normal vector",
        fr: ("normale", 1411),
        uk: ("нормальний вектор", 405),
        avoid_fr: &[],
        avoid_uk: &["анормальн"],
        note: "seed 003 l.378 glues \"a normal vector\" into \"анормальний вектор\" (abnormal); its heading (l.405) has the right word",
    },
    term("normal matrix", ("matrice normale", 1412), ("матриця нормалей", 585)),
    Term {
        en: "Gouraud shading",
        fr: ("éclairage de Gouraud", 1415),
        uk: ("затінення Гуро", 2246),
        avoid_fr: &[],
        avoid_uk: &[],
        note: "seed 003 keeps the English \"Gouraud shading\" (l.2246); we write the Ukrainian term",
    },
    term("material", ("matériau", 1416), ("матеріал", 697)),
    Term {
        en: "container (the wooden crate)",
        fr: ("conteneur", 695),
        uk: ("контейнер", 97),
        avoid_fr: &["caisse"],
        avoid_uk: &["ящик"],
        note: "seed 000 calls the textured crate \"un conteneur en bois\" (l.695), seed 003 \"контейнер\" (l.97); the translations say so too, not \"caisse\" or \"ящик\"",
    },
    term("diffuse map", ("texture diffuse", 1418), ("дифузна карта", 1004)),
    term("specular map", ("texture spéculaire", 1419), ("дзеркальна карта", 1140)),
    term("directional light", ("lumière directionnelle", 1212), ("спрямоване світло", 1245)),
    term("point light", ("source ponctuelle", 1421), ("точкове світло", 1388)),
    term("attenuation", ("atténuation", 1422), ("затухання", 1400)),
    Term {
        en: "spotlight",
        fr: ("spot", 1423),
        uk: ("прожектор", 1588),
        avoid_fr: &[],
        avoid_uk: &["центр уваги", "центрі уваги"],
        note: "seed 003 l.1594 translates \"spotlight\" by its figurative sense, \"центр уваги\" (centre of attention); its heading (l.1588) says \"прожектор\"",
    },
    Term {
        en: "flashlight",
        fr: ("lampe frontale", 1424),
        uk: ("ліхтарик", 1617),
        avoid_fr: &["lampe torche"],
        avoid_uk: &[],
        note: "seed 000 says \"lampe frontale\" (l.1055, l.1057, l.1424); \"lampe torche\" is not the seed's term",
    },
    Term {
        en: "cut-off (of a spotlight)",
        fr: ("angle de coupure", 1050),
        uk: ("відсічення", 1737),
        avoid_fr: &[],
        avoid_uk: &[
            "кут відсіканн",
            "кути відсіканн",
            "кута відсіканн",
            "куті відсіканн",
            "кутом відсіканн",
            "кутами відсіканн",
            "кутів відсіканн",
        ],
        note: "seed 003 names the spot's inner and outer cut-off \"внутрішнє/зовнішнє відсічення\" (l.1737), elsewhere \"кут обрізання\" (l.1611, l.1787) or \"кут зрізу\" (l.1603); we write \"кут відсічення\", and keep \"відсікання\" for culling (of back faces, of lights). Seed 000 calls it \"l'angle d'ouverture\" (l.1050), \"angle interne/externe\" (l.1165); an opening angle of a cone is usually its full apex angle, twice the cut-off, so we write \"angle de coupure\" (the name of `cutOff`)",
    },
    Term {
        en: "light caster",
        fr: ("projecteur (light caster)", 846),
        uk: ("джерело світла", 2255),
        avoid_fr: &[],
        avoid_uk: &["ролик", "коліщат"],
        note: "seed 003 (l.1239, l.1392) translates \"caster\" as a furniture caster (\"світлові ролики\", \"коліщатка\"); we say \"джерело світла\" (light source), as its glossary does",
    },
    term("shininess", ("brillance", 1413), ("блиск", 2244)),
    term("soft edges", ("atténuation des bords", 63), ("м'які краї", 1719)),
    term("fragment shader", ("fragment shader", 1414), ("фрагментний шейдер", 2245)),
    term("vertex shader", ("vertex shader", 1415), ("вершинний шейдер", 2246)),
    Term {
        en: "uniform",
        fr: ("variable uniforme", 176),
        uk: ("uniform-змінна", 2260),
        avoid_fr: &[],
        avoid_uk: &["рівномірн"],
        note: "seed 003 l.2260 calls a uniform array \"масив рівномірних значень\" (evenly distributed values); GLSL's uniform is kept as the keyword, \"uniform-змінна\"",
    },
];

/// The stray words of `lang` (lower case), each with the term it stands for.
#[must_use]
pub fn avoided(lang: super::Lang) -> Vec<(&'static str, &'static Term)> {
    TERMS
        .iter()
        .flat_map(|t| {
            let words = match lang {
                super::Lang::En => &[][..],
                super::Lang::Fr => t.avoid_fr,
                super::Lang::Uk => t.avoid_uk,
            };
            words.iter().map(move |w| (*w, t))
        })
        .collect()
}

/// The glossary as a Markdown table (the book's appendix includes it).
#[must_use]
pub fn markdown() -> String {
    let mut s =
        String::from("| English | français (seed 000) | українська (seed 003) | note |\n| --- | --- | --- | --- |\n");
    for t in TERMS {
        s += &format!("| {} | {} (l. {}) | {} (l. {}) | {} |\n", t.en, t.fr.0, t.fr.1, t.uk.0, t.uk.1, t.note);
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each cited line of a seed holds the term's first word (so a citation cannot drift).
    #[test]
    fn citations_point_at_lines_that_use_the_term() {
        let seeds = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/seeds");
        let read = |name: &str| std::fs::read_to_string(seeds.join(name)).ok();
        let (Some(fr), Some(uk)) = (read("000_45d0deae98c0cf55.txt"), read("003_c8baabbac4a005cc.txt")) else {
            println!("skipped: the seeds are not beside the clone");
            return;
        };
        for t in TERMS {
            for ((word, line), text, what) in [(t.fr, &fr, "000"), (t.uk, &uk, "003")] {
                let at = text.lines().nth(line as usize - 1).unwrap_or("").to_lowercase();
                let stem: String = word.split_whitespace().next().unwrap().to_lowercase().chars().take(5).collect();
                // where the note says the seed keeps the English, the line holds the English term
                let english = t.note.contains("keeps the English") && at.contains(&t.en.to_lowercase());
                assert!(at.contains(&stem) || english, "{}: seed {what} l.{line} does not use \"{word}\": {at}", t.en);
            }
        }
    }
}
