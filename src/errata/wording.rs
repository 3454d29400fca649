//! Wording, symbols and names where the French (000) and Ukrainian (003) LearnOpenGL
//! texts differ: each row quotes the printed words and checks them against the term,
//! symbol or identifier the chapter's own code or formula uses.

use super::{cited, Entry};

/// Whether every word of `words` (split on whitespace) occurs in `text`.
fn contains_all(text: &str, words: &str) -> bool {
    words.split_whitespace().all(|w| text.contains(w))
}

/// The rows.
pub(super) fn entries() -> Vec<Entry> {
    let uk_zero = "встановити w компонент вектора нормалі до θ; позиція глядача завжди (θ, θ, θ)";
    let uk_vao = "unsigned int lightVAO; glGenVertexArrays(1, &lightVAO); … glBindVertexArray(lightCubeVAO);";
    let fr_vao = "unsigned int lightVAO; glGenVertexArrays(1, &lightVAO); … glBindVertexArray(lightVAO);";
    let created = |s: &str| s.split_once("&").and_then(|(_, t)| t.split_once(')')).map(|(n, _)| n.to_string());
    let bound =
        |s: &str| s.rsplit_once("glBindVertexArray(").and_then(|(_, t)| t.split_once(')')).map(|(n, _)| n.to_string());
    let uk_second = "По-перше, нормальні вектори є лише векторами напрямків … По-друге, нормальні вектори не мають \
                     однорідної координати … По-друге, якщо матриця моделі буде виконувати нерівномірний масштаб";
    let uk_identifiers =
        "за допомогою зворотнийітранспонувати функціонує; `дифузний` вектор матеріалу; `блиск` впливає";
    let fields = super::listings::struct_fields(super::listings::MATERIAL_STRUCT);
    vec![
        cited("zero-digit-fr", &[(0, 412, 412), (0, 450, 450)]).says("w = 0 for a normal; the viewer at (0, 0, 0) in view space", "donner la valeur 0 à la composante w; la position du spectateur est toujours (0, 0, 0)").holds(!"donner la valeur 0 à la composante w".contains('θ'), "the digit 0".into(), ""),
        cited("zero-digit-uk", &[(3, 575, 575), (3, 617, 617), (3, 1361, 1363), (3, 1709, 1709), (3, 1725, 1725), (3, 1751, 1751)]).says("w = 0 for a normal; the viewer at (0, 0, 0) in view space", uk_zero).holds(!uk_zero.contains('θ'), "the digit 0 (and 1.0, 0.0 for w)".into(), "the conversion typeset every 0 as θ and the decimal point as ·: \"1·θ\" is 1.0, \"θ·976\" is 0.976, \
                                                                                                                                                                                                                                                                                         \"vec4(-θ·2f, -1·θf, …)\" is vec4(-0.2f, -1.0f, …), a symbol the same page uses for the angle"),
        cited("normal-vector-term-fr", &[(0, 278, 278)]).says("the vector perpendicular to the surface is called the normal vector", "un vecteur appelé vecteur normal (ou normale)").holds("vecteur normal (ou normale)".contains("normal"), "\"normal vector\"".into(), ""),
        cited("normal-vector-term-uk", &[(3, 378, 378)]).says("the vector perpendicular to the surface is called the normal vector", "ми використовуємо те, що називається **анормальний вектор**").holds(!"анормальний вектор".contains("анормальний"), "\"нормальний вектор\" (a normal vector)".into(), "\"a normal vector\" glued into \"анормальний\" (abnormal); l.402 and l.405 then say \"нормальний\""),
        cited("normal-points-counted-uk", &[(3, 575, 577)]).says("the reasons are counted first, second, third", uk_second).holds(uk_second.matches("По-друге").count() == 1, format!("\"По-друге\" (secondly) printed {} times", uk_second.matches("По-друге").count()), "the second point and the third both open with \"secondly\" (the French merges the first two, l.412)"),
        cited("identifiers-translated-uk", &[(3, 589, 589), (3, 737, 737)]).says("code names in the prose are the shader's identifiers", uk_identifiers).holds(fields.iter().all(|f| uk_identifiers.contains(f.as_str())), format!("inverse, transpose; Material's fields are {}", fields.join(", ")), "the machine translation translated identifiers in code spans: inverse and transpose became one \
                                                                                                                                                                                                                                                                                                        word \"зворотнийітранспонувати\", diffuse became `дифузний`, shininess became `блиск`"),
        cited("lamp-vao-fr", &[(0, 150, 152), (0, 220, 220)]).says("the lamp is drawn with the VAO created for it", fr_vao).holds(created(fr_vao) == bound(fr_vao), format!("created {:?}, bound {:?}", created(fr_vao).unwrap_or_default(), bound(fr_vao).unwrap_or_default()), ""),
        cited("lamp-vao-uk", &[(3, 143, 151), (3, 301, 301)]).says("the lamp is drawn with the VAO created for it", uk_vao).holds(created(uk_vao) == bound(uk_vao), format!("created {:?}, bound {:?}", created(uk_vao).unwrap_or_default(), bound(uk_vao).unwrap_or_default()), "lightCubeVAO is never declared: the listing creates lightVAO (l.143) and binds lightCubeVAO (l.301), \
                                                                                                                                                                                                                                                                                  as does the current English page; the draw call would not compile"),
        cited("caster-term-fr", &[(0, 846, 846)]).says("a source that casts light is a light caster", "Une source qui projette de la lumière sur les objets est appelée un projecteur (light caster)").holds(contains_all("projecteur (light caster)", "light caster"), "\"light caster\"".into(), ""),
        cited("caster-term-uk", &[(3, 1239, 1241), (3, 1392, 1392)]).says("a source that casts light is a light caster", "Світлові ролики; називається **легкий ролик**; різних типів коліщаток світла; як про коліщатка").holds(contains_all("Світлові ролики; легкий ролик; коліщатка", "джерело світла"), "a light caster: a source that casts light (джерело світла)".into(), "\"caster\" was translated as a furniture caster: \"light rollers\", \"a light-weight roller\", \
                                                                                                                                                                                                                                                                                                                                                                                   \"little wheels of light\", in the chapter's title too"),
        cited("spotlight-term-fr", &[(0, 1044, 1044)]).says("a spotlight is represented by a position, a direction and a cut-off angle", "Un spot dans OpenGL est représenté par une position dans l'espace monde, une direction et un angle").holds(true, "spotlight".into(), ""),
        cited("spotlight-term-uk", &[(3, 1594, 1594), (3, 1607, 1609)]).says("a spotlight is represented by a position, a direction and a cut-off angle", "Центр уваги в OpenGL представлений позицією у світовому просторі; бути в центрі уваги").holds("Центр уваги в OpenGL".contains("Прожектор"), "прожектор (the word the section title uses, l.1588)".into(), "\"spotlight\" translated by its figurative sense, \"centre of attention\"; \"θ must be smaller than Φ \
                                                                                                                                                                                                                                                                                                                                                                      to be in the spotlight\" became \"to be the centre of attention\""),
        cited("intensity-symbols-fr", &[(0, 1116, 1118)]).says("the intensity I and the cosine difference ε", "I = (θ − γ) / ε").holds(true, "I, ε".into(), ""),
        cited("intensity-symbols-uk", &[(3, 1729, 1731), (3, 1737, 1737)]).says("the intensity I and the cosine difference ε", "я = (θ − γ) / ε; Отриманий я тоді значення; table header € … я").holds(!"я = (θ − γ) / ε".starts_with('я'), "I, ε".into(), "the symbol I was translated as the pronoun \"я\" (I), and the table's ε header became €"),
    ]
}
