//! The mistake catalogue and the diagnosis on llvmpipe.
//!
//! - every mistake rewrites every model it names, keeping the line count (no GL);
//! - every mistake's own mutant, as a complete learner shader, is diagnosed as that mistake;
//! - the equivalence groups are exactly the ones the mutants' outputs show;
//! - correct shaders written in other styles agree, with an empty diagnosis;
//! - hand-written buggy shaders are diagnosed; an uncatalogued difference is isolated.
//!
//! Tests that need OpenGL print why and pass without it, unless `LIGHTLAB_REQUIRE_GL=1`.
#![cfg(feature = "gl")]

use crate::gl_common;

use std::collections::{BTreeMap, BTreeSet};

use lightlab::checker::check::Mapping;
use lightlab::checker::complete;
use lightlab::checker::diagnose::{self, check_and_diagnose};
use lightlab::checker::isolation;
use lightlab::checker::mistakes::{self, CATALOGUE, EQUIVALENT};
use lightlab::gl::ModelId;
use lightlab::oracle::cases::{self, DEFAULT_SEED};

/// 3000 cases: every mutant differs from the reference on hundreds of them (the rarest,
/// the spot's soft edge, covers a few percent of the spot cases), and a debug build
/// checks one shader in well under a second.
const CASES: usize = 3000;

const SHADERS: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/shaders");
const EXAMPLES: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/src/gl/shaders/examples");

fn read(dir: &str, name: &str) -> String {
    std::fs::read_to_string(format!("{dir}/{name}")).unwrap()
}

#[test]
fn every_mistake_rewrites_every_model_it_names_and_keeps_the_lines() {
    for m in CATALOGUE {
        assert!(!m.models.is_empty(), "{}", m.id);
        for &model in m.models {
            let original = model.shader().unwrap().functions();
            let mutated = m.mutate(model).unwrap_or_else(|e| panic!("{e}"));
            assert_ne!(mutated, original, "{} leaves {model} unchanged", m.id);
            assert_eq!(mutated.lines().count(), original.lines().count(), "{} on {model}", m.id);
        }
        assert!(m.mutate(ModelId::Ogldev19).is_err() || m.applies_to(ModelId::Ogldev19));
    }
}

#[test]
fn the_catalogue_has_the_required_ids_once_each() {
    let required = [
        "light-dir-reversed",
        "view-dir-reversed",
        "view-from-origin",
        "reflect-sign",
        "diffuse-no-clamp",
        "specular-no-clamp",
        "normal-not-normalized",
        "blinn-for-phong",
        "ambient-missing",
        "specular-missing",
        "shininess-ignored",
        "attenuation-missing",
        "attenuation-quadratic-uses-d",
        "ambient-not-attenuated",
        "spot-epsilon-swapped",
        "spot-hard-edge",
        "spot-cutoff-degrees",
        "spot-direction-reversed",
        "clamp-per-light",
        "light-dir-not-normalized",
        "shininess-zero",
        "spot-cutoff-as-angle",
        "attenuation-distance-squared-twice",
        "light-color-twice",
        "specular-ungated",
        "emission-lit",
    ];
    // the ids are unique across the fragment and the vertex catalogues (Mistake::by_id looks in both)
    let ids: BTreeSet<&str> = CATALOGUE.iter().chain(mistakes::VERTEX_CATALOGUE).map(|m| m.id).collect();
    assert_eq!(ids.len(), CATALOGUE.len() + mistakes::VERTEX_CATALOGUE.len(), "duplicate ids");
    for id in required {
        assert!(ids.contains(id), "missing {id}");
    }
    for m in CATALOGUE {
        assert!(!m.title.is_empty() && !m.why.is_empty() && m.link.contains(".html"), "{}", m.id);
    }
}

/// The book page and anchor of each link exist (mdBook's heading ids: lower case,
/// punctuation dropped, spaces to hyphens).
#[test]
fn every_link_points_at_a_book_heading() {
    fn slug(heading: &str) -> String {
        heading
            .trim()
            .to_lowercase()
            .chars()
            .filter_map(|c| {
                if c.is_alphanumeric() || c == '-' || c == '_' {
                    Some(c)
                } else if c == ' ' {
                    Some('-')
                } else {
                    None
                }
            })
            .collect()
    }
    for m in CATALOGUE.iter().chain(mistakes::VERTEX_CATALOGUE) {
        let (page, anchor) = m.link.split_once('#').unwrap_or((m.link, ""));
        let md = format!("{}/book/src/{}", env!("CARGO_MANIFEST_DIR"), page.replace(".html", ".md"));
        let text = std::fs::read_to_string(&md).unwrap_or_else(|e| panic!("{}: {md}: {e}", m.id));
        if !anchor.is_empty() {
            let found = text.lines().filter(|l| l.starts_with('#')).any(|l| slug(l.trim_start_matches('#')) == anchor);
            assert!(found, "{}: no heading with id {anchor} in {md}", m.id);
        }
    }
}

#[test]
fn the_complete_reference_shaders_agree_with_an_empty_diagnosis() {
    let Some(ctx) = gl_common::context_or_skip() else { return };
    for &model in complete::MODELS {
        let source = complete::reference(model).unwrap();
        let d = check_and_diagnose(&ctx, &source, model, &Mapping::default(), CASES, DEFAULT_SEED)
            .unwrap_or_else(|e| panic!("{model}: {e}"));
        assert!(d.agrees(), "{model}:\n{}", d.format());
        assert!(d.diagnosis.is_empty());
    }
}

/// Each mistake on one of its models (rotating so every model is used), through the whole
/// pipeline: a complete learner shader, `check-shader`'s mapping, the diagnosis.
#[test]
fn every_mistake_is_diagnosed_from_its_own_mutant() {
    let Some(ctx) = gl_common::context_or_skip() else { return };
    for (k, m) in CATALOGUE.iter().enumerate() {
        let model = m.models[k % m.models.len()];
        let source = complete::with_mistake(model, m).unwrap();
        let d = check_and_diagnose(&ctx, &source, model, &Mapping::default(), CASES, DEFAULT_SEED)
            .unwrap_or_else(|e| panic!("{} on {model}: {e}", m.id));
        assert!(!d.agrees(), "{} on {model} agrees", m.id);
        let ids: Vec<&str> = d.diagnosis.iter().map(|f| f.id.as_str()).collect();
        assert!(ids.contains(&m.id), "{} on {model}: diagnosed as {ids:?}\n{}", m.id, d.format());
        let expected: BTreeSet<&str> = m.equivalence().map_or([m.id].into(), |e| e.ids.iter().copied().collect());
        let got: BTreeSet<&str> = ids.iter().copied().collect();
        assert_eq!(got, expected, "{} on {model}: the diagnosis lists exactly its equivalence group", m.id);
    }
}

/// The per-site mutants that these cases cannot tell from the reference (none of the
/// whole-file mutants may be). `blinn-for-phong@spot`: the spotlight's specular term is
/// non-zero only inside its cone and in front of the surface, and Blinn's wider highlight
/// differs beyond `2·bound` there on 2 of the 2948 defined cases of `multiple_lights`,
/// under the [`diagnose::MISMATCH_SHARE`] of 1 in 1000 that a match may miss.
/// `clamp-per-light@point` and `@spot`: one point light or the spotlight alone, attenuated,
/// exceeds 1 in a channel on none of these 2948 cases (measured), so clamping it changes
/// nothing here; the directional light, unattenuated, does.
const INVISIBLE_IN_ONE_SITE: &[&str] = &["blinn-for-phong@spot", "clamp-per-light@point", "clamp-per-light@spot"];

/// Runs every mutant (each mistake everywhere, and in each of its sites) against every
/// other on every model they share; two mutants are equivalent when they match on all of
/// them. The classes, by label (`id` or `id@site`), must be [`EQUIVALENT`].
#[test]
fn the_equivalence_groups_are_the_ones_the_outputs_show() {
    let Some(ctx) = gl_common::context_or_skip() else { return };
    let mut same: BTreeMap<(String, String), bool> = BTreeMap::new();
    let mut labels: BTreeSet<String> = BTreeSet::new();
    let mut invisible: BTreeSet<String> = BTreeSet::new();
    for &model in complete::MODELS {
        let case_model = model.case_model();
        let groups = cases::generate_cases(case_model, CASES, DEFAULT_SEED, &[]).unwrap();
        let functions = case_model.shader.unwrap().functions();
        let reference = diagnose::run_functions(&ctx, case_model, functions, &groups).unwrap();
        let outs = diagnose::run_mutants(&ctx, case_model, functions, &groups).unwrap();
        let tol = 2.0 * case_model.bound;
        println!("{model}: {} mutants", outs.len());
        for (a, oa) in &outs {
            let vs_ref = diagnose::compare_outputs(case_model, &groups, oa, &reference, tol);
            if vs_ref.matches() {
                invisible.insert(a.label());
                continue;
            }
            labels.insert(a.label());
            for (b, ob) in &outs {
                if a.label() < b.label() {
                    let m = diagnose::compare_outputs(case_model, &groups, oa, ob, tol).matches();
                    let e = same.entry((a.label(), b.label())).or_insert(true);
                    *e &= m;
                }
            }
        }
    }
    assert!(labels.contains("attenuation-missing@point"), "the per-site mutants run: {labels:?}");
    assert_eq!(invisible, INVISIBLE_IN_ONE_SITE.iter().map(|s| s.to_string()).collect(), "invisible mutants");
    let mut found: BTreeSet<BTreeSet<String>> = BTreeSet::new();
    for a in &labels {
        let class: BTreeSet<String> = labels
            .iter()
            .filter(|b| a == *b || same.get(&(a.min(b).clone(), a.max(b).clone())).copied().unwrap_or(false))
            .cloned()
            .collect();
        if class.len() > 1 {
            found.insert(class);
        }
    }
    let table: BTreeSet<BTreeSet<String>> =
        EQUIVALENT.iter().map(|e| e.ids.iter().map(|s| s.to_string()).collect()).collect();
    // A whole-file mutant equals its one visible site's mutant when its other sites are
    // invisible on these cases (`clamp-per-light` and `clamp-per-light@directional`): the
    // same on these cases, not on every case, so not an equivalence group.
    let through_invisible_sites = |class: &BTreeSet<String>| {
        let mut it = class.iter();
        let (Some(whole), Some(site), None) = (it.next(), it.next(), it.next()) else { return false };
        let Some((id, _)) = site.split_once('@') else { return false };
        id == whole
            && labels.iter().filter(|l| l.starts_with(&format!("{id}@")) && *l != site).count() == 0
            && invisible.iter().any(|l| l.starts_with(&format!("{id}@")))
    };
    let unexplained: BTreeSet<BTreeSet<String>> =
        found.iter().filter(|c| !table.contains(*c) && !through_invisible_sites(c)).cloned().collect();
    assert!(unexplained.is_empty(), "classes outside EQUIVALENT: {unexplained:?}");
    assert!(table.iter().all(|t| found.contains(t)), "EQUIVALENT {table:?}, found {found:?}");
}

#[test]
fn correct_shaders_in_other_styles_agree() {
    let Some(ctx) = gl_common::context_or_skip() else { return };
    let files = [
        ("basic_handwritten_reflect.frag", ModelId::BasicLighting),
        ("basic_inline.frag", ModelId::BasicLighting),
        ("materials_regrouped.frag", ModelId::Materials),
        ("point_uniform_names.frag", ModelId::Point),
        ("spot_branchy.frag", ModelId::Spot),
        ("directional_halfsum.frag", ModelId::Directional),
    ];
    for (file, model) in files {
        let d = check_and_diagnose(&ctx, &read(SHADERS, file), model, &Mapping::default(), CASES, DEFAULT_SEED)
            .unwrap_or_else(|e| panic!("{file}: {e}"));
        assert!(d.agrees() && d.diagnosis.is_empty(), "{file}:\n{}", d.format());
    }
}

#[test]
fn hand_written_bugs_are_diagnosed() {
    let Some(ctx) = gl_common::context_or_skip() else { return };
    let cases = [
        ("bug_reflect_sign.frag", ModelId::BasicLighting, "reflect-sign"),
        ("bug_unnormalized_normal.frag", ModelId::BasicLighting, "normal-not-normalized"),
    ];
    for (file, model, id) in cases {
        let d =
            check_and_diagnose(&ctx, &read(EXAMPLES, file), model, &Mapping::default(), CASES, DEFAULT_SEED).unwrap();
        assert!(!d.agrees());
        assert!(d.diagnosis.iter().any(|f| f.id == id), "{file}: {:?}", d.diagnosis);
        assert!(d.format().starts_with("Your shader disagrees"), "{}", d.format());
    }
}

/// The spot's axis not negated in θ, in a hand-written spotlight (an if/else ladder, its
/// own names): named `spot-direction-reversed` first, not `light-dir-reversed`, whose hint
/// would send the learner to a `lightDir` that is right.
#[test]
fn a_spot_direction_not_negated_is_named_as_such() {
    let Some(ctx) = gl_common::context_or_skip() else { return };
    let right = read(SHADERS, "spot_branchy.frag");
    let wrong = right.replace("dot(L, normalize(-light.direction))", "dot(L, normalize(light.direction))");
    assert_ne!(wrong, right);
    let d = check_and_diagnose(&ctx, &wrong, ModelId::Spot, &Mapping::default(), CASES, DEFAULT_SEED).unwrap();
    println!("{}", d.format());
    assert!(!d.agrees());
    assert_eq!(d.diagnosis.first().map(|f| f.id.as_str()), Some("spot-direction-reversed"), "{}", d.format());
}

/// The normal-matrix model names its own mistakes, in the example's spelling and in the
/// other order of `transpose(inverse(mat3(model)))`: the model matrix for the normal
/// matrix, no matrix at all, the inverse without the transpose.
#[test]
fn the_normal_matrix_mistakes_are_named_on_the_fragment_model() {
    let Some(ctx) = gl_common::context_or_skip() else { return };
    let right = read(EXAMPLES, "normal_matrix.frag");
    let line = "mat3(transpose(inverse(model))) * aNormal";
    let other = "transpose(inverse(mat3(model))) * aNormal";
    assert!(right.contains(line));
    for (from, to, id) in [
        (line, "mat3(model) * aNormal", "normal-matrix-missing"),
        (line, "aNormal", "normal-not-transformed"),
        (line, "mat3(inverse(model)) * aNormal", "normal-matrix-not-transposed"),
        (line, "inverse(mat3(model)) * aNormal", "normal-matrix-not-transposed"),
    ] {
        let source = right.replace(from, to);
        let d =
            check_and_diagnose(&ctx, &source, ModelId::NormalMatrix, &Mapping::default(), CASES, DEFAULT_SEED).unwrap();
        println!("{to}:\n{}", d.format());
        assert!(!d.agrees(), "{to}");
        assert_eq!(d.diagnosis.first().map(|f| f.id.as_str()), Some(id), "{to}:\n{}", d.format());
    }
    // the other spelling of the right line agrees
    let d = check_and_diagnose(
        &ctx,
        &right.replace(line, other),
        ModelId::NormalMatrix,
        &Mapping::default(),
        CASES,
        DEFAULT_SEED,
    )
    .unwrap();
    assert!(d.agrees(), "{}", d.format());
}

#[test]
fn an_uncatalogued_difference_is_isolated_to_its_term_and_sign() {
    let Some(ctx) = gl_common::context_or_skip() else { return };
    let source = read(SHADERS, "basic_spec_only_when_lit.frag");
    let d =
        check_and_diagnose(&ctx, &source, ModelId::BasicLighting, &Mapping::default(), CASES, DEFAULT_SEED).unwrap();
    assert!(!d.agrees());
    assert_eq!(d.diagnosis.len(), 1, "{:?}", d.diagnosis);
    println!("{}", d.format());
    let f = &d.diagnosis[0];
    assert_eq!(f.id, "isolated");
    assert!(f.title.contains("the specular term only"), "{}", f.title);
    assert!(f.title.contains("N·L < 0"), "{}", f.title);
    // its hints are the specular term's: where to look, the idea, the fix
    let specular = lightlab::checker::hints::TERM_HINTS.iter().find(|(t, _)| *t == "specular").unwrap().1;
    assert_eq!(f.hints, specular.map(String::from), "{}", d.format());
    assert!(d.format().contains(&format!("hint: {}", specular[0])), "the first hint is printed:\n{}", d.format());
}

/// A mistake in every point light and in no other light, outside the catalogue (the
/// specular term doubled in `CalcPointLight` only): switching off one point light leaves
/// the other three wrong, so only the point lights switched off together locate it.
#[test]
fn a_mistake_in_every_point_light_is_isolated_to_the_point_lights() {
    let Some(ctx) = gl_common::context_or_skip() else { return };
    let model = ModelId::MultipleLights;
    let functions = model.shader().unwrap().functions();
    let attenuated = "return (ambient + diffuse + specular) * attenuation;";
    assert_eq!(functions.matches(attenuated).count(), 1, "CalcPointLight's return, and only its");
    let halved = "return (ambient + diffuse + specular) * attenuation * 0.5;";
    let source = complete::complete_with(model, &functions.replace(attenuated, halved));
    let d = check_and_diagnose(&ctx, &source.unwrap(), model, &Mapping::default(), CASES, DEFAULT_SEED).unwrap();
    println!("{}", d.format());
    assert_eq!(d.diagnosis.len(), 1, "{}", d.format());
    let f = &d.diagnosis[0];
    assert_eq!(f.id, "isolated", "{}", d.format());
    assert!(f.title.starts_with("the difference is in the point lights only"), "{}", f.title);
    assert!(f.evidence.contains("with point light 0 off: ") && f.evidence.contains("with the point lights off: 0"));
    let kind = lightlab::checker::hints::KIND_HINTS.map(|h| h.replace("{}", "the point lights"));
    assert_eq!(f.hints, kind, "{}", d.format());
}

/// The emission lit in a form the catalogue does not hold (`emission-lit` multiplies it by
/// `light.diffuse`; here it is multiplied by the diffuse factor `diff`): only the emission
/// switched off in both shaders removes the difference, so the diagnosis is exactly the
/// emission term's isolation, with the emission term's three hints.
#[test]
fn emission_scaled_by_diff_is_isolated_to_the_emission_term() {
    let Some(ctx) = gl_common::context_or_skip() else { return };
    let model = ModelId::LightingMapsEmission;
    let functions = model.shader().unwrap().functions();
    let (from, to) = ("vec3 emission = emissionTexel;", "vec3 emission = emissionTexel * diff;");
    assert_eq!(functions.matches(from).count(), 1);
    let source = complete::complete_with(model, &functions.replace(from, to)).unwrap();
    let d = check_and_diagnose(&ctx, &source, model, &Mapping::default(), CASES, DEFAULT_SEED).unwrap();
    println!("{}", d.format());
    assert_eq!(d.diagnosis.len(), 1, "{}", d.format());
    let f = &d.diagnosis[0];
    assert_eq!(f.id, "isolated", "{}", d.format());
    assert_eq!(f.title, isolation::fill("one", &["the emission term"]), "{}", d.format());
    for term in ["ambient", "diffuse", "specular"] {
        let off = format!("with the {term} term off: 0 ");
        assert!(!f.evidence.contains(&off) && f.evidence.contains(&format!("with the {term} term off: ")), "{off}");
    }
    assert!(f.evidence.ends_with("with the emission term off: 0 disagree"), "{}", f.evidence);
    let emission = lightlab::checker::hints::TERM_HINTS.iter().find(|(t, _)| *t == "emission").unwrap().1;
    assert_eq!(f.hints, emission.map(String::from), "{}", d.format());
}

/// Issue 25, item 1: attenuation dropped in `CalcPointLight` only (written by hand, not by
/// the catalogue's edit) is `attenuation-missing` at the point lights, in words and in JSON;
/// dropped in `CalcSpotLight` only, at the spotlight.
#[test]
fn attenuation_missing_in_one_light_kind_is_named_with_its_site() {
    let Some(ctx) = gl_common::context_or_skip() else { return };
    let model = ModelId::MultipleLights;
    let functions = model.shader().unwrap().functions();
    let point = "return (ambient + diffuse + specular) * attenuation;";
    let spot = "return (ambient + diffuse + specular) * (attenuation * intensity);";
    for (from, to, site) in [
        (point, "return ambient + diffuse + specular;", "point"),
        (spot, "return (ambient + diffuse + specular) * intensity;", "spot"),
    ] {
        assert_eq!(functions.matches(from).count(), 1);
        let source = complete::complete_with(model, &functions.replace(from, to)).unwrap();
        let d = check_and_diagnose(&ctx, &source, model, &Mapping::default(), CASES, DEFAULT_SEED).unwrap();
        println!("{}", d.format());
        assert!(!d.diagnosis.is_empty(), "{}", d.format());
        let f = &d.diagnosis[0];
        assert_eq!((f.id.as_str(), f.site.map(|s| s.name())), ("attenuation-missing", Some(site)), "{}", d.format());
        let phrase = lightlab::checker::sites::Site::parse(site).unwrap().phrase();
        assert_eq!(f.title, format!("attenuation left out, {phrase}"));
        assert!(
            d.format().contains(&format!("attenuation left out, {phrase} [attenuation-missing@{site}]")),
            "{}",
            d.format()
        );
        assert_eq!(d.to_json()["diagnosis"][0]["site"], site);
        // the whole-file mutant (both kinds) does not match a shader wrong in one kind
        assert!(d.diagnosis.iter().all(|f| f.site.is_some()), "{:?}", d.diagnosis);
    }
}

/// Issue 25, item 3: every mistake added from learners' threads cites one.
#[test]
fn the_new_mistakes_cite_a_learners_thread() {
    for id in [
        "light-dir-not-normalized",
        "shininess-zero",
        "spot-cutoff-as-angle",
        "attenuation-distance-squared-twice",
        "light-color-twice",
        "specular-ungated",
        "emission-lit",
        "spaces-normal-in-view",
        "spaces-normal-in-world",
        "spaces-light-in-view",
    ] {
        let m = mistakes::Mistake::by_id(id).unwrap();
        assert!(m.source.starts_with("https://"), "{id}: {}", m.source);
    }
}

/// What llvmpipe returns for `shininess-zero`'s `pow(x, 0.0)` (a literal exponent): 1 for
/// every base, 0 included, never NaN (measured: the compiler folds `pow(x, 0.0)` to 1, while
/// `exp2(0 · log2 0)` would be NaN), as the mistake's `why` says. Were it NaN where the base
/// is 0 (every back-facing case, `max(R·V, 0) = 0`), some outputs would not be finite.
#[test]
fn shininess_zero_gives_one_for_every_base_on_llvmpipe() {
    let Some(ctx) = gl_common::context_or_skip() else { return };
    let model = ModelId::BasicLighting.case_model();
    let groups = cases::generate_cases(model, CASES, DEFAULT_SEED, &[]).unwrap();
    let functions = model.shader.unwrap().functions();
    let outs = diagnose::run_mutants(&ctx, model, functions, &groups).unwrap();
    let (_, out) = outs.iter().find(|(m, _)| m.label() == "shininess-zero").unwrap();
    let all: Vec<&[f32; 4]> = out.iter().flatten().collect();
    let nan = all.iter().filter(|o| o[..3].iter().any(|x| !x.is_finite())).count();
    println!("shininess-zero on basic_lighting: {nan} of {} outputs not finite", all.len());
    assert_eq!(nan, 0, "{nan} of {}", all.len());
}

/// Issue 25, item 4: two mistakes in different terms and sites (the diffuse factor not
/// clamped everywhere, attenuation left out of the point lights only), written by hand,
/// are named together: "two mistakes: … and …".
#[test]
fn two_mistakes_at_once_are_named_together() {
    let Some(ctx) = gl_common::context_or_skip() else { return };
    let model = ModelId::MultipleLights;
    let functions = model.shader().unwrap().functions();
    let point = "return (ambient + diffuse + specular) * attenuation;";
    let text = functions
        .replace(point, "return ambient + diffuse + specular;")
        .replace("max(dot(normal, lightDir), 0.0)", "dot(normal, lightDir)");
    let source = complete::complete_with(model, &text).unwrap();
    let d = check_and_diagnose(&ctx, &source, model, &Mapping::default(), CASES, DEFAULT_SEED).unwrap();
    println!("{}", d.format());
    let labels: Vec<String> = d.diagnosis.iter().map(|f| f.label()).collect();
    assert_eq!(labels.first().map(String::as_str), Some("diffuse-no-clamp + attenuation-missing@point"), "{labels:?}");
    assert!(
        d.format().contains(
            "two mistakes: diffuse factor not clamped at 0 and attenuation left out, in the point lights only"
        ),
        "{}",
        d.format()
    );
    assert_eq!(d.to_json()["diagnosis"][0]["second"]["site"], "point");
}

#[test]
fn mistakes_for_model_lists_only_applicable_ones() {
    let spot = mistakes::for_model(ModelId::Spot);
    assert!(spot.iter().any(|m| m.id == "spot-hard-edge"));
    assert!(!spot.iter().any(|m| m.id == "clamp-per-light"));
    assert!(mistakes::for_model(ModelId::BasicLighting).iter().all(|m| m.applies_to(ModelId::BasicLighting)));
}

/// `emission-lit` rewrites only a model with an emission map: every other model, the
/// Lighting maps chapter's own included, refuses it as not applicable (its function file
/// has no emission to light), and so does its complete shader.
#[test]
fn emission_lit_applies_only_to_the_emission_model() {
    let m = mistakes::Mistake::by_id("emission-lit").unwrap();
    for model in ModelId::ALL {
        if model == ModelId::LightingMapsEmission {
            assert!(m.mutate(model).unwrap().contains("emissionTexel * light.diffuse"));
            continue;
        }
        assert_eq!(m.mutate(model), Err(mistakes::MutateError::NotApplicable { id: "emission-lit", model }));
        assert!(!mistakes::for_model(model).iter().any(|x| x.id == "emission-lit"), "{model}");
    }
    assert_eq!(
        complete::with_mistake(ModelId::LightingMaps, m),
        Err(mistakes::MutateError::NotApplicable { id: "emission-lit", model: ModelId::LightingMaps })
    );
    // every mistake of the chapter's own Lighting maps applies to its emission exercise too
    for x in mistakes::for_model(ModelId::LightingMaps) {
        assert!(x.applies_to(ModelId::LightingMapsEmission), "{}", x.id);
    }
}

/// The emission lit by the light, in a complete learner-style shader, is diagnosed as
/// `emission-lit` and nothing else.
#[test]
fn emission_lit_is_diagnosed_as_itself() {
    let Some(ctx) = gl_common::context_or_skip() else { return };
    let model = ModelId::LightingMapsEmission;
    let m = mistakes::Mistake::by_id("emission-lit").unwrap();
    let source = complete::with_mistake(model, m).unwrap();
    let d = check_and_diagnose(&ctx, &source, model, &Mapping::default(), CASES, DEFAULT_SEED).unwrap();
    println!("{}", d.format());
    let labels: Vec<String> = d.diagnosis.iter().map(|f| f.label()).collect();
    assert_eq!(labels, ["emission-lit"], "{}", d.format());
}

/// The isolation probe (a doubled specular term, outside the catalogue) is isolated by the
/// command line exactly as the in-page checker expects it (`src/live/exercises.rs` exports
/// the same expectation for the page's `?selftest`).
#[test]
fn the_isolation_probe_is_isolated_as_the_page_expects() {
    let Some(ctx) = gl_common::context_or_skip() else { return };
    let (from, to) = isolation::ISOLATION_PROBE;
    let mut tried = 0;
    for &model in complete::MODELS {
        let case_model = model.case_model();
        let functions = model.shader().unwrap().functions();
        let groups = cases::generate_cases(case_model, 1, DEFAULT_SEED, &[]).unwrap();
        let names: Vec<&str> = groups[0].uniforms.iter().map(|(n, _)| n.as_str()).collect();
        let Some(expect) = isolation::probe_expectation(case_model, &names) else { continue };
        if !functions.contains(from) {
            continue;
        }
        let source = complete::complete_with(model, &functions.replace(from, to)).unwrap();
        let d = check_and_diagnose(&ctx, &source, model, &Mapping::default(), CASES, DEFAULT_SEED)
            .unwrap_or_else(|e| panic!("{model}: {e}"));
        assert_eq!(d.diagnosis.len(), 1, "{model}:\n{}", d.format());
        assert_eq!(d.diagnosis[0].id, "isolated", "{model}:\n{}", d.format());
        assert!(d.diagnosis[0].title.starts_with(&expect), "{model}: {} vs {expect}", d.diagnosis[0].title);
        tried += 1;
    }
    assert!(tried >= 5, "the probe applies to the learnopengl models ({tried})");
}

#[test]
fn the_isolation_sentences_fill_their_blanks_in_order() {
    assert_eq!(isolation::fill("one", &["the specular term"]), "the difference is in the specular term only");
    assert_eq!(isolation::fill("evidence_off", &["the ambient term", "3"]), "; with the ambient term off: 3 disagree");
    assert_eq!(isolation::fill("none", &[]), "the difference could not be narrowed to one term");
}
