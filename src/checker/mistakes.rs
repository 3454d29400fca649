//! The mistake catalogue: the errors learners make in the tutorials' lighting shaders, each
//! as a rewrite of the verified function files in `src/gl/shaders/*.glsl`.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | mistake | one known error, with an id (`light-dir-reversed`), a title and why it looks as it does |
//! | step | one textual edit of a function file; a step lists alternatives (the files name things differently) and at least one must apply |
//! | form | the steps for the models whose files write the formula in one shape ([`Steps::ByModel`]), when the shapes need different edits |
//! | mutant | a model's function file with every step of a mistake applied, plus the model's harness |
//! | equivalence group | mistakes whose mutants give the same output on every case (see [`EQUIVALENT`]) |
//!
//! The mutants are generated from these descriptions by [`Mistake::mutate`] on the text that
//! the oracle verifies ([`crate::gl::models`]); no shader is kept twice. A rewrite keeps the
//! line count, so a compile error in a mutant points at the function file's line.
//!
//! [`EQUIVALENT`] is written by hand with the reason for each group, and a test
//! (`tests/gl_diagnose.rs`) runs every mutant against every other to prove that the groups
//! are exactly the ones the outputs show.

use crate::gl::model_id::ModelId;

pub use crate::gl::edit::{apply_steps, Edit};

/// One known mistake (see the module docs).
#[derive(Debug, Clone, Copy)]
pub struct Mistake {
    /// Stable id, kebab-case (`light-dir-reversed`).
    pub id: &'static str,
    /// What the learner did, in a few words.
    pub title: &'static str,
    /// One line: why the image looks the way it does.
    pub why: &'static str,
    /// The book page and anchor that explain it (relative to the book's root).
    pub link: &'static str,
    /// A learners' thread where the mistake was made or asked about;
    /// empty for the entries written before sources were cited.
    pub source: &'static str,
    /// The models whose function file it rewrites.
    pub models: &'static [ModelId],
    /// The edits; each step needs at least one alternative that applies.
    pub steps: Steps,
}

/// A mistake's steps: one list for every model, or one per form of the formula.
///
/// The alternatives of a step cover files that name things differently
/// (`light.position` or `lightPos`). When the files write the mistaken formula in a
/// different shape, so that the mistake takes another number of edits (LearnOpenGL's
/// `light.linear * distance + light.quadratic * (distance * distance)` changes in two
/// places, opengl-tutorial 8's `/ (distance * distance)` in one), each shape is a
/// [`Form`] with its own models.
#[derive(Debug, Clone, Copy)]
pub enum Steps {
    /// The same steps for every model (empty: a pair mistake that stands for the other
    /// pair model's reference, see [`VERTEX_CATALOGUE`]).
    Same(&'static [&'static [Edit]]),
    /// The steps of each form; a model takes the form that lists it (a test checks that
    /// each model of the mistake is in exactly one).
    ByModel(&'static [Form]),
}

/// The steps of a mistake for some of its models (see [`Steps::ByModel`]).
#[derive(Debug, Clone, Copy)]
pub struct Form {
    /// The models whose files write the formula in this shape.
    pub models: &'static [ModelId],
    /// The edits, as in [`Steps::Same`].
    pub steps: &'static [&'static [Edit]],
}

impl Steps {
    /// The steps for `model`: [`Steps::Same`]'s for any model; the form listing `model`
    /// for [`Steps::ByModel`], `None` when no form lists it.
    #[must_use]
    pub fn for_model(self, model: ModelId) -> Option<&'static [&'static [Edit]]> {
        match self {
            Steps::Same(steps) => Some(steps),
            Steps::ByModel(forms) => forms.iter().find(|f| f.models.contains(&model)).map(|f| f.steps),
        }
    }

    /// Whether there are no edits for any model (a pair mistake that stands for the other
    /// pair model's reference).
    #[must_use]
    pub fn is_empty(self) -> bool {
        match self {
            Steps::Same(steps) => steps.is_empty(),
            Steps::ByModel(forms) => forms.iter().all(|f| f.steps.is_empty()),
        }
    }
}

/// Why a mistake cannot be applied to a model.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum MutateError {
    /// The model is not in the mistake's list, or has no function file.
    NotApplicable {
        /// Mistake id.
        id: &'static str,
        /// The model.
        model: ModelId,
    },
    /// No alternative of a step occurs in the function file (the file changed).
    NoMatch {
        /// Mistake id.
        id: &'static str,
        /// The model.
        model: ModelId,
        /// The first alternative's pattern.
        pattern: &'static str,
    },
}

impl std::fmt::Display for MutateError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            MutateError::NotApplicable { id, model } => write!(f, "mistake {id} does not apply to model {model}"),
            MutateError::NoMatch { id, model, pattern } => {
                write!(
                    f,
                    "mistake {id}: `{pattern}` (or its alternatives) does not occur in the function text of {model}"
                )
            }
        }
    }
}

impl std::error::Error for MutateError {}

impl Mistake {
    /// Looks a mistake up by id, in [`CATALOGUE`] then in [`VERTEX_CATALOGUE`] (the ids are
    /// unique across both).
    pub fn by_id(id: &str) -> Option<&'static Mistake> {
        CATALOGUE.iter().chain(VERTEX_CATALOGUE).find(|m| m.id == id)
    }

    /// Whether the mistake rewrites `model`'s function file.
    #[must_use]
    pub fn applies_to(&self, model: ModelId) -> bool {
        self.models.contains(&model)
    }

    /// The steps for `model` ([`Steps::for_model`]).
    #[must_use]
    pub fn steps_for(&self, model: ModelId) -> Option<&'static [&'static [Edit]]> {
        self.steps.for_model(model)
    }

    /// `functions` with every step for `model` applied (all occurrences of every matching
    /// alternative).
    ///
    /// Errors: [`MutateError::NotApplicable`] when the mistake has no form for `model`
    /// ([`Steps::ByModel`]); [`MutateError::NoMatch`] naming the first step that matches
    /// nothing.
    pub fn rewrite(&self, model: ModelId, functions: &str) -> Result<String, MutateError> {
        let steps = self.steps_for(model).ok_or(MutateError::NotApplicable { id: self.id, model })?;
        apply_steps(steps, functions).map_err(|pattern| MutateError::NoMatch { id: self.id, model, pattern })
    }

    /// The mutated function file of `model` (the text a learner with this mistake would
    /// have written, in the function file's form).
    ///
    /// Errors: [`MutateError::NotApplicable`] for a model outside [`Mistake::models`];
    /// [`MutateError::NoMatch`] if the file no longer contains a step's pattern.
    pub fn mutate(&self, model: ModelId) -> Result<String, MutateError> {
        let shader = model
            .shader()
            .filter(|_| self.applies_to(model))
            .ok_or(MutateError::NotApplicable { id: self.id, model })?;
        self.rewrite(model, shader.functions())
    }

    /// The mutant's batch body (mutated function file, then the model's harness), as
    /// [`ShaderModel::body`](crate::gl::ShaderModel::body) builds the reference's.
    pub fn mutant_body(&self, model: ModelId) -> Result<String, MutateError> {
        let shader = model.shader().ok_or(MutateError::NotApplicable { id: self.id, model })?;
        Ok(format!("{}\n{}", self.mutate(model)?, shader.harness()))
    }

    /// The equivalence group this mistake belongs to, if any.
    pub fn equivalence(&self) -> Option<&'static Equivalence> {
        EQUIVALENT.iter().find(|e| e.ids.contains(&self.id))
    }
}

/// The LearnOpenGL per-fragment models that share the names the edits look for.
const LEARNOPENGL_MODELS: [ModelId; 9] = [
    ModelId::BasicLighting,
    ModelId::Materials,
    ModelId::LightingMaps,
    ModelId::LightingMapsEmission,
    ModelId::Directional,
    ModelId::Point,
    ModelId::Spot,
    ModelId::MultipleLights,
    ModelId::NormalMatrix,
];
/// [`LEARNOPENGL_MODELS`] as a slice.
const LEARNOPENGL: &[ModelId] = &LEARNOPENGL_MODELS;
/// [`LEARNOPENGL`] and Blinn-Phong (LearnOpenGL's Advanced Lighting, on the same names).
const LEARNOPENGL_AND_BLINN: &[ModelId] = &with_blinn(LEARNOPENGL_MODELS);

/// `models` and then [`ModelId::BlinnPhong`].
const fn with_blinn(models: [ModelId; 9]) -> [ModelId; 10] {
    let mut out = [ModelId::BlinnPhong; 10];
    let mut k = 0;
    while k < models.len() {
        out[k] = models[k];
        k += 1;
    }
    out
}
/// The models with an attenuated light.
const ATTENUATED: &[ModelId] = &[ModelId::Point, ModelId::Spot, ModelId::MultipleLights];
/// [`ATTENUATED`] and opengl-tutorial 8, whose light falls off as 1/d².
const ATTENUATED_AND_OT8: &[ModelId] =
    &[ModelId::Point, ModelId::Spot, ModelId::MultipleLights, ModelId::OpenGLTutorial8];
/// The models with a spotlight.
const SPOT: &[ModelId] = &[ModelId::Spot, ModelId::MultipleLights];
/// The models with an emission map.
const EMISSIVE: &[ModelId] = &[ModelId::LightingMapsEmission];
/// The models of a vertex + fragment pair.
const PAIR: &[ModelId] = &[ModelId::BasicLighting, ModelId::Gouraud];
/// The models whose shader moves the normal by the normal matrix: the vertex shader of a
/// pair, and the fragment shader of the normal-matrix exercise.
const NORMAL_MOVED: &[ModelId] = &[ModelId::BasicLighting, ModelId::Gouraud, ModelId::NormalMatrix];

/// Every mistake, grouped by area: vector directions, the terms, missing parts,
/// attenuation, spotlights, several lights.
pub const CATALOGUE: &[Mistake] = &[
    // ------------------------------------------------------------ vector directions
    Mistake {
        id: "light-dir-reversed",
        title: "light direction reversed (surface minus light)",
        why: "lightDir points from the light into the surface, so N·L changes sign: the lit side gets only ambient and the side facing away lights up",
        link: "02-basic-lighting.html#diffuse",
        source: "",
        models: LEARNOPENGL,
        steps: Steps::Same(&[&[
            ("lightDir = normalize(lightPos - FragPos)", "lightDir = normalize(FragPos - lightPos)"),
            ("lightDir = normalize(light.position - FragPos)", "lightDir = normalize(FragPos - light.position)"),
            ("lightDir = normalize(light.position - fragPos)", "lightDir = normalize(fragPos - light.position)"),
            ("lightDir = normalize(-light.direction)", "lightDir = normalize(light.direction)"),
        ]]),
    },
    Mistake {
        id: "view-dir-reversed",
        title: "view direction reversed (surface minus eye)",
        why: "viewDir points away from the eye, so R·V changes sign: the highlight shows where the eye looks against the mirror direction; ambient and diffuse are right",
        link: "02-basic-lighting.html#specular",
        source: "",
        models: LEARNOPENGL,
        steps: Steps::Same(&[&[("viewDir = normalize(viewPos - FragPos)", "viewDir = normalize(FragPos - viewPos)")]]),
    },
    Mistake {
        id: "view-from-origin",
        title: "eye assumed at the origin in world space",
        why: "normalize(-FragPos) is the view direction only in view space; in world space the highlight is computed for an eye at (0,0,0) and slides as the camera moves",
        link: "07-conventions.html",
        source: "",
        models: LEARNOPENGL,
        steps: Steps::Same(&[&[("viewDir = normalize(viewPos - FragPos)", "viewDir = normalize(-FragPos)")]]),
    },
    Mistake {
        id: "reflect-sign",
        title: "reflect() given lightDir instead of -lightDir",
        why: "reflect wants the incident vector, from the light to the surface; reflect(lightDir, N) is -R, so the highlight appears opposite the true one",
        link: "02-basic-lighting.html#specular",
        source: "",
        models: LEARNOPENGL,
        steps: Steps::Same(&[&[
            ("reflect(-lightDir, norm)", "reflect(lightDir, norm)"),
            ("reflect(-lightDir, normal)", "reflect(lightDir, normal)"),
        ]]),
    },
    // ------------------------------------------------------------ the terms
    Mistake {
        id: "diffuse-no-clamp",
        title: "diffuse factor not clamped at 0",
        why: "without max(…, 0) a surface facing away gets a negative diffuse term that subtracts from the ambient: back sides darker than ambient alone",
        link: "02-basic-lighting.html#diffuse",
        source: "",
        models: LEARNOPENGL,
        steps: Steps::Same(&[&[
            ("max(dot(norm, lightDir), 0.0)", "dot(norm, lightDir)"),
            ("max(dot(normal, lightDir), 0.0)", "dot(normal, lightDir)"),
        ]]),
    },
    Mistake {
        id: "specular-no-clamp",
        title: "specular base not clamped before pow",
        why: "pow of a negative base is undefined in GLSL; llvmpipe returns NaN wherever the base (R·V, or N·H in Blinn-Phong) is negative, so those pixels come out black or garbage",
        link: "08-failure-atlas.html#2-pow-of-a-negative-base",
        source: "",
        models: LEARNOPENGL_AND_BLINN,
        steps: Steps::Same(&[&[
            ("pow(max(dot(viewDir, reflectDir), 0.0), ", "pow(dot(viewDir, reflectDir), "),
            // Blinn-Phong: the model's file and the own-blinn-phong exercise's solution
            ("pow(max(dot(norm, halfwayDir), 0.0), ", "pow(dot(norm, halfwayDir), "),
            ("pow(max(dot(n, halfwayDir), 0.0), ", "pow(dot(n, halfwayDir), "),
        ]]),
    },
    Mistake {
        id: "normal-not-normalized",
        title: "interpolated normal used without normalize",
        why: "interpolated normals are shorter or longer than 1, so N·L and the reflection scale with their length: lighting too dark or too bright, and highlights misplaced",
        link: "08-failure-atlas.html#7-interpolated-normals-left-unnormalized",
        source: "",
        models: LEARNOPENGL,
        steps: Steps::Same(&[&[("vec3 norm = normalize(Normal);", "vec3 norm = Normal;")]]),
    },
    Mistake {
        id: "blinn-for-phong",
        title: "Blinn-Phong (N·H) where Phong (R·V) is asked",
        why: "N·H falls off about four times more slowly than R·V, so with the same shininess the highlight is wider, and it does not vanish beyond 90°",
        link: "02-basic-lighting.html#blinn-phong",
        source: "",
        models: LEARNOPENGL,
        steps: Steps::Same(&[
            &[
                ("vec3 reflectDir = reflect(-lightDir, norm);", "vec3 halfwayDir = normalize(lightDir + viewDir); vec3 n = norm;"),
                (
                    "vec3 reflectDir = reflect(-lightDir, normal);",
                    "vec3 halfwayDir = normalize(lightDir + viewDir); vec3 n = normal;",
                ),
            ],
            &[("dot(viewDir, reflectDir)", "dot(n, halfwayDir)")],
        ]),
    },
    // ------------------------------------------------------------ missing parts
    Mistake {
        id: "ambient-missing",
        title: "ambient term left out",
        why: "without ambient, every point the light does not reach is pure black",
        link: "02-basic-lighting.html#ambient",
        source: "",
        models: LEARNOPENGL,
        steps: Steps::Same(&[&[("vec3 ambient = ", "vec3 ambient = 0.0 * ")]]),
    },
    Mistake {
        id: "specular-missing",
        title: "specular term left out",
        why: "without specular the surface is matte: no highlight anywhere",
        link: "02-basic-lighting.html#specular",
        source: "",
        models: LEARNOPENGL,
        steps: Steps::Same(&[&[("vec3 specular = ", "vec3 specular = 0.0 * ")]]),
    },
    Mistake {
        id: "shininess-ignored",
        title: "shininess hard-coded to 32",
        why: "the exponent ignores the material's shininess, so every material has the same highlight size",
        link: "03-materials.html",
        source: "",
        models: LEARNOPENGL,
        steps: Steps::Same(&[&[("), shininess);", "), 32.0);"), ("), material.shininess);", "), 32.0);")]]),
    },
    // ------------------------------------------------------------ attenuation
    Mistake {
        id: "attenuation-missing",
        title: "attenuation left out",
        why: "without 1/(Kc + Kl·d + Kq·d²) the light is as strong far away as near: distant surfaces too bright",
        link: "05-light-casters.html#point-lights-and-attenuation",
        source: "",
        models: ATTENUATED,
        steps: Steps::Same(&[&[("attenuation = 1.0 / (", "attenuation = 1.0 + 0.0 * (")]]),
    },
    Mistake {
        id: "attenuation-quadratic-uses-d",
        title: "quadratic attenuation term uses d instead of d²",
        why: "Kq·d instead of Kq·d² makes the light fade too slowly beyond d = 1 and too fast nearer than 1",
        link: "05-light-casters.html#point-lights-and-attenuation",
        source: "",
        models: ATTENUATED,
        steps: Steps::Same(&[&[("light.quadratic * (distance * distance)", "light.quadratic * distance")]]),
    },
    Mistake {
        id: "ambient-not-attenuated",
        title: "ambient term not attenuated",
        why: "the ambient term keeps its full strength at any distance, so far from the light the unlit sides glow",
        link: "05-light-casters.html#point-lights-and-attenuation",
        source: "",
        models: ATTENUATED,
        steps: Steps::Same(&[&[
            ("ambient *= attenuation;", "/* ambient kept */"),
            (
                "return (ambient + diffuse + specular) * attenuation;",
                "return ambient + (diffuse + specular) * attenuation;",
            ),
            (
                "return (ambient + diffuse + specular) * (attenuation * intensity);",
                "return ambient + (diffuse + specular) * (attenuation * intensity);",
            ),
        ]]),
    },
    // ------------------------------------------------------------ spotlights
    Mistake {
        id: "spot-epsilon-swapped",
        title: "spot ε computed as outerCutOff - cutOff",
        why: "ε becomes negative, so (θ - γ)/ε is negative inside the cone: the clamp turns the cone dark and the soft edge inverted",
        link: "05-light-casters.html#soft-edges",
        source: "",
        models: SPOT,
        steps: Steps::Same(&[&[("epsilon = light.cutOff - light.outerCutOff", "epsilon = light.outerCutOff - light.cutOff")]]),
    },
    Mistake {
        id: "spot-hard-edge",
        title: "spot with a hard edge (θ > cutOff, no soft edge)",
        why: "the intensity jumps from 1 to 0 at the inner cone, so the edge is a sharp ring instead of a ramp to the outer cone",
        link: "05-light-casters.html#soft-edges",
        source: "",
        models: SPOT,
        steps: Steps::Same(&[&[(
            "intensity = clamp((theta - light.outerCutOff) / epsilon, 0.0, 1.0);",
            "intensity = theta > light.cutOff ? 1.0 : 0.0;",
        )]]),
    },
    Mistake {
        id: "spot-cutoff-degrees",
        title: "cut-offs converted from degrees although they are cosines",
        why: "cos(radians(x)) of a cosine near 1 is about 0.9999 and grows as x shrinks, so the outer cut-off passes the inner one: ε < 0 and the clamp lights everything except a 1° core",
        link: "05-light-casters.html#spotlight",
        source: "",
        models: SPOT,
        steps: Steps::Same(&[
            &[("light.cutOff", "cos(radians(light.cutOff))")],
            &[("light.outerCutOff", "cos(radians(light.outerCutOff))")],
        ]),
    },
    // The chapter's own exercise (Light casters, "invert the vectors"; lightlab's
    // `casters-flip-vectors`): the spot's axis taken as stored, from the light, while
    // `lightDir` points back to the light. Only θ changes: the diffuse and specular terms
    // keep the right `lightDir`.
    Mistake {
        id: "spot-direction-reversed",
        title: "spot direction not negated in θ (dot(lightDir, light.direction))",
        why: "light.direction points from the light into the scene while lightDir points back to the light, so without the minus sign θ is the cosine of the angle from the reversed axis: -1 on the axis, and the cone points backwards: the lit disc goes dark and only fragments behind the spot could be inside it",
        link: "05-light-casters.html#exercise-flip-vectors-and-comparisons",
        source: "",
        models: SPOT,
        steps: Steps::Same(&[&[(
            "theta = dot(lightDir, normalize(-light.direction));",
            "theta = dot(lightDir, normalize(light.direction));",
        )]]),
    },
    // ------------------------------------------------------------ several lights
    Mistake {
        id: "clamp-per-light",
        title: "each light's contribution clamped to [0, 1] before the sum",
        why: "each light saturates on its own, so overlapping lights add up to less than the sum, and a light brighter than 1 in one channel loses its hue",
        link: "08-failure-atlas.html#12-hue-shift-when-many-lights-saturate",
        source: "",
        models: &[ModelId::MultipleLights],
        steps: Steps::Same(&[
            &[("return ambient + diffuse + specular;", "return clamp(ambient + diffuse + specular, 0.0, 1.0);")],
            &[(
                "return (ambient + diffuse + specular) * attenuation;",
                "return clamp((ambient + diffuse + specular) * attenuation, 0.0, 1.0);",
            )],
            &[(
                "return (ambient + diffuse + specular) * (attenuation * intensity);",
                "return clamp((ambient + diffuse + specular) * (attenuation * intensity), 0.0, 1.0);",
            )],
        ]),
    },
    // ------------------------------------------------------------ issue 25: learners' threads
    Mistake {
        id: "light-dir-not-normalized",
        title: "light direction not normalized",
        why: "lightDir is as long as the vector it was made from (lightPos - FragPos is as long as the distance to the light; a directional light's stored direction need not have length 1), so N·L and the reflection scale with that length: too bright where it exceeds 1, too dark below, and the highlight misplaced",
        link: "02-basic-lighting.html#diffuse",
        source: "https://github.com/ThomasSneddon/vxl-renderer/issues/3",
        models: LEARNOPENGL,
        steps: Steps::Same(&[&[
            ("lightDir = normalize(lightPos - FragPos)", "lightDir = (lightPos - FragPos)"),
            ("lightDir = normalize(light.position - FragPos)", "lightDir = (light.position - FragPos)"),
            ("lightDir = normalize(light.position - fragPos)", "lightDir = (light.position - fragPos)"),
            ("lightDir = normalize(-light.direction)", "lightDir = (-light.direction)"),
        ]]),
    },
    Mistake {
        id: "shininess-zero",
        title: "shininess of 0 in pow",
        why: "x⁰ is 1, so the specular factor is 1 everywhere: the highlight covers the whole surface, the side turned from the light included (pow(0, 0) is undefined in GLSL; llvmpipe folds pow(x, 0.0) to 1, other drivers may return NaN)",
        link: "08-failure-atlas.html#3-shininess-0-and-below-1",
        source: "https://github.com/mrdoob/three.js/issues/6057",
        models: LEARNOPENGL,
        steps: Steps::Same(&[&[("), shininess);", "), 0.0);"), ("), material.shininess);", "), 0.0);")]]),
    },
    Mistake {
        id: "spot-cutoff-as-angle",
        title: "spot θ taken as an angle (acos) and compared with cosine cut-offs",
        why: "acos gives an angle in radians, which grows away from the axis while the cut-offs are cosines that shrink: the comparison turns over, so the cone is dark and the light falls outside it",
        link: "05-light-casters.html#spotlight",
        source: "https://github.com/HeapsIO/heaps/pull/300",
        models: SPOT,
        steps: Steps::Same(&[&[(
            "theta = dot(lightDir, normalize(-light.direction));",
            "theta = acos(dot(lightDir, normalize(-light.direction)));",
        )]]),
    },
    Mistake {
        id: "attenuation-distance-squared-twice",
        title: "attenuation from the squared distance taken as the distance (d² for d, d⁴ for d²)",
        why: "squaring a distance that is already squared makes the light fall off much faster beyond d = 1 and more slowly nearer than 1: the lit area shrinks to a bright spot",
        link: "05-light-casters.html#point-lights-and-attenuation",
        source: "https://github.com/RayTracing/raytracing.github.io/issues/469",
        models: ATTENUATED_AND_OT8,
        // LearnOpenGL's Kc + Kl·d + Kq·d² has the distance in two places; opengl-tutorial
        // 8's inverse square divides the diffuse and the specular term by d², one edit
        steps: Steps::ByModel(&[
            Form {
                models: ATTENUATED,
                steps: &[
                    &[("light.linear * distance +", "light.linear * (distance * distance) +")],
                    &[(
                        "light.quadratic * (distance * distance)",
                        "light.quadratic * (distance * distance * distance * distance)",
                    )],
                ],
            },
            Form {
                models: &[ModelId::OpenGLTutorial8],
                steps: &[&[("/ (distance * distance)", "/ (distance * distance * distance * distance)")]],
            },
        ]),
    },
    Mistake {
        id: "light-color-twice",
        title: "light colour applied twice",
        why: "each term already carries lightColor and the sum is multiplied by it again, so the light's colour enters squared: right under a white light, too dark and too saturated under a coloured or dimmed one",
        link: "01-colors.html",
        source: "https://github.com/urho3d/urho3d/issues/2252",
        models: &[ModelId::BasicLighting],
        steps: Steps::Same(&[&[(
            "return (ambient + diffuse + specular) * objectColor;",
            "return (ambient + diffuse + specular) * lightColor * objectColor;",
        )]]),
    },
    // ogldev's reference adds the specular term inside `if (DiffuseFactor > 0.0)`; the
    // mutant takes the test away and clamps the diffuse factor instead, which leaves the
    // diffuse term as it was and adds the specular term on every face.
    Mistake {
        id: "specular-ungated",
        title: "specular term added on faces turned away from the light (no N·L > 0 test)",
        why: "the reference adds the specular term only where the diffuse factor is positive; without that test a highlight appears wherever R·V > 0, on faces the light cannot reach (LearnOpenGL's shaders have no such test either: it is a mistake only against a reference that has it, as ogldev's does)",
        link: "08-failure-atlas.html#1-specular-on-faces-turned-away",
        source: "https://discussions.unity.com/t/bug-in-all-specular-shaders-causing-highlights-from-light-sources-behind-objects/432906",
        models: &[ModelId::Ogldev19],
        steps: Steps::Same(&[&[("if (DiffuseFactor > 0.0) {", "{")], &[("* DiffuseFactor;", "* max(DiffuseFactor, 0.0);")]]),
    },
    // Learners also add the emission to the diffuse texel before lighting, or multiply it by
    // `diff`; the mutant is the form the cited thread shows, the emission scaled by the
    // light (`light.diffuse`), which keeps it on faces turned away but ties it to the lamp.
    Mistake {
        id: "emission-lit",
        title: "emission multiplied by the light's colour",
        why: "the emission map is light the surface gives off itself, but multiplied by light.diffuse it takes the lamp's colour and strength: under a dim or coloured light the glowing strokes fade or change hue, and with the lamp off they go out",
        link: "04-lighting-maps.html#the-shader",
        source: "https://github.com/GarageGames/Torque3D/pull/1693",
        models: EMISSIVE,
        steps: Steps::Same(&[&[("vec3 emission = emissionTexel;", "vec3 emission = emissionTexel * light.diffuse;")]]),
    },
    // opengl-tutorial 8's printed listing ends the diffuse line with `;`: the specular line
    // after it is an expression statement whose value is thrown away (the book's errata).
    // The mutant adds the specular term times zero, which gives the same colours.
    Mistake {
        id: "specular-after-semicolon",
        title: "specular line cut off by a `;` after the diffuse line",
        why: "a `;` at the end of the diffuse line ends the sum there: the specular line below it becomes a statement of its own whose value is thrown away, so it compiles and no highlight appears (opengl-tutorial 8's printed listing has this `;`)",
        link: "10-errata.html#what-the-errata-come-from",
        source: "",
        models: &[ModelId::OpenGLTutorial8],
        steps: Steps::Same(&[&[(
            "+ MaterialSpecularColor * LightColor * LightPower",
            "+ 0.0 * MaterialSpecularColor * LightColor * LightPower",
        )]]),
    },
];

/// A group of mistakes whose outputs are identical, and why.
#[derive(Debug, Clone, Copy)]
pub struct Equivalence {
    /// The mistakes, catalogue order.
    pub ids: &'static [&'static str],
    /// Why they give the same output.
    pub reason: &'static str,
}

/// The mistakes whose mutants take `pow` of a negative base, which GLSL leaves undefined
/// (GLSL 3.30 §8.2, ES 3.00 §8.2): their colours depend on the driver (llvmpipe gives NaN,
/// Chromium's SwiftShader finite values), so the page and the command line agree that
/// they differ and on the mistake, not on how many cases differ.
pub const POW_OF_NEGATIVE: &[&str] = &["specular-no-clamp"];

/// The equivalence groups, proved by running every mutant against every other on the
/// models they share (`tests/gl_diagnose.rs`).
pub const EQUIVALENT: &[Equivalence] = &[Equivalence {
    ids: &["view-dir-reversed", "reflect-sign"],
    reason: "reflect(I, N) = I - 2(N·I)N is linear in I, so reflect(lightDir, N) = -reflect(-lightDir, N): \
             the specular base becomes V·(-R) = (-V)·R, exactly the base with the view direction reversed \
             (negation is exact in floating point, so the outputs agree bit for bit)",
}];

/// The mistakes that apply to `model`'s function file (its fragment shader), catalogue
/// order: the [`CATALOGUE`]'s, then the [`VERTEX_CATALOGUE`]'s whose edits occur in that
/// file (the normal matrix's: a vertex shader's line for a pair, the fragment shader's for
/// the normal-matrix exercise).
#[must_use]
pub fn for_model(model: ModelId) -> Vec<&'static Mistake> {
    let vertex = VERTEX_CATALOGUE.iter().filter(|m| !m.steps.is_empty() && m.mutate(model).is_ok());
    CATALOGUE.iter().filter(|m| m.applies_to(model)).chain(vertex).collect()
}

/// Every mistake that rewrites some model's function file (its fragment shader), with the
/// models it rewrites: the [`CATALOGUE`], then the [`VERTEX_CATALOGUE`] entries whose edits
/// occur in a fragment function file (the normal matrix's, in `normal_matrix`). The
/// in-page checker's catalogue.
#[must_use]
pub fn fragment_mistakes() -> Vec<(&'static Mistake, Vec<ModelId>)> {
    CATALOGUE
        .iter()
        .chain(VERTEX_CATALOGUE)
        .filter(|m| !m.steps.is_empty())
        .map(|m| (m, m.models.iter().copied().filter(|&model| m.mutate(model).is_ok()).collect::<Vec<_>>()))
        .filter(|(_, models)| !models.is_empty())
        .collect()
}

/// The mistakes of a vertex + fragment pair ([`crate::checker::check::pair`]): each rewrites the
/// vertex shader of the model's reference pair (`models` are the pair models,
/// `basic_lighting` and `gouraud`). An entry with no steps stands for the other pair
/// model's reference pair: lighting per vertex where the chapter lights per fragment, and
/// the converse.
pub const VERTEX_CATALOGUE: &[Mistake] = &[
    Mistake {
        id: "normal-matrix-missing",
        title: "normal moved by mat3(model) instead of the normal matrix",
        why: "mat3(model) stretches a normal along a non-uniform scale, so it leans off the surface and the diffuse and specular terms shift; with uniform scales only the length changes, which normalize hides",
        link: "02-basic-lighting.html#normals-and-the-normal-matrix",
        source: "",
        models: NORMAL_MOVED,
        steps: Steps::Same(&[&[("mat3(transpose(inverse(model))) * aNormal", "mat3(model) * aNormal")]]),
    },
    Mistake {
        id: "normal-matrix-not-transposed",
        title: "normal moved by inverse(model) without transpose",
        why: "the normal matrix is the transpose of the inverse: inverse(model) alone undoes the model's rotation instead of applying it and divides by its scales, so the normal turns the wrong way and leans off the surface wherever the model rotates",
        link: "02-basic-lighting.html#normals-and-the-normal-matrix",
        source: "",
        models: NORMAL_MOVED,
        steps: Steps::Same(&[&[("mat3(transpose(inverse(model))) * aNormal", "mat3(inverse(model)) * aNormal")]]),
    },
    Mistake {
        id: "normal-not-transformed",
        title: "object-space normal used in world space",
        why: "the normal never turns with the model, so the lighting stays fixed to the object's original orientation: a rotated object is lit as if it had not moved",
        link: "02-basic-lighting.html#normals-and-the-normal-matrix",
        source: "",
        models: NORMAL_MOVED,
        steps: Steps::Same(&[&[("mat3(transpose(inverse(model))) * aNormal", "aNormal")]]),
    },
    Mistake {
        id: "position-not-transformed",
        title: "object-space position passed as the world position",
        why: "the light and the eye are in world space but the fragment's position is not, so every direction to them is off by the model's transform: the lighting slides as the object moves",
        link: "02-basic-lighting.html#diffuse",
        source: "",
        models: PAIR,
        steps: Steps::Same(&[&[("vec3(model * vec4(aPos, 1.0))", "aPos")]]),
    },
    Mistake {
        id: "gouraud-for-phong",
        title: "lit per vertex (Gouraud) where the chapter lights per fragment",
        why: "the colour is computed at the three vertices and blended, so a highlight inside a triangle is lost or smeared; on large triangles the difference is plain",
        link: "02-basic-lighting.html#gouraud-against-phong-shading",
        source: "",
        models: &[ModelId::BasicLighting],
        steps: Steps::Same(&[]),
    },
    Mistake {
        id: "phong-for-gouraud",
        title: "lit per fragment (Phong) where the exercise asks for Gouraud",
        why: "the lighting is computed for every fragment from the interpolated position and normal: the smooth result the exercise contrasts Gouraud shading with",
        link: "02-basic-lighting.html#gouraud-against-phong-shading",
        source: "",
        models: &[ModelId::Gouraud],
        steps: Steps::Same(&[]),
    },
    Mistake {
        id: "light-not-in-view-space",
        title: "light position left in world space while the lighting is done in view space",
        why: "the position and the normal are moved by view * model but the light is not, so the light sits where its world coordinates fall in view space: it moves with the camera and the whole shading changes as the view turns",
        link: "02-basic-lighting.html#exercises",
        source: "",
        models: &[ModelId::BasicLighting],
        steps: Steps::Same(&[&[("vs_out.LightPos = vec3(view * vec4(lightPos, 1.0));", "vs_out.LightPos = lightPos;")]]),
    },
    Mistake {
        id: "spaces-normal-in-view",
        title: "normal moved to view space while the light, the eye and the fragment stay in world space",
        why: "the normal matrix is built from view * model, so the normal turns with the camera while every other vector of the lighting stays in world space: N·L and the highlight are computed against a normal that points elsewhere, and the shading changes as the view turns",
        link: "02-basic-lighting.html#normals-and-the-normal-matrix",
        source: "https://github.com/raysan5/raylib/issues/1870",
        models: PAIR,
        steps: Steps::Same(&[&[("mat3(transpose(inverse(model))) * aNormal", "mat3(transpose(inverse(view * model))) * aNormal")]]),
    },
    Mistake {
        id: "spaces-normal-in-world",
        title: "normal left in world space while the lighting is done in view space",
        why: "the position is moved by view * model and the light by view, but the normal only by the model's normal matrix, so in view space it points where its world coordinates fall: N·L and the highlight use a normal turned by the camera's rotation, and the shading changes as the view turns",
        link: "02-basic-lighting.html#exercises",
        source: "https://github.com/stackgl/shader-school/issues/130",
        models: &[ModelId::BasicLighting],
        steps: Steps::Same(&[&[("mat3(transpose(inverse(modelView))) * aNormal", "mat3(transpose(inverse(model))) * aNormal")]]),
    },
    // Lighting is the same in every rigid frame, so a light moved to view space while the
    // rest stays in world space is, written in view space, the light moved by the view twice.
    Mistake {
        id: "spaces-light-in-view",
        title: "light position moved to view space while the fragment, the normal and the eye stay in world space",
        why: "the light's view-space coordinates are read as world coordinates, so the light sits somewhere else, and it moves whenever the camera does",
        link: "02-basic-lighting.html#exercises",
        source: "https://github.com/JoeyDeVries/LearnOpenGL/issues/394",
        models: &[ModelId::BasicLighting],
        steps: Steps::Same(&[&[(
            "vs_out.LightPos = vec3(view * vec4(lightPos, 1.0));",
            "vs_out.LightPos = vec3(view * view * vec4(lightPos, 1.0));",
        )]]),
    },
];

#[cfg(test)]
mod tests {
    use super::*;

    /// A mistake with steps by model has exactly one form for each of its models, and no
    /// form for a model outside its list: [`Steps::for_model`] takes the first form that
    /// lists the model, so a model in two forms would silently lose the second.
    #[test]
    fn each_model_of_a_mistake_has_exactly_one_form() {
        for m in CATALOGUE.iter().chain(VERTEX_CATALOGUE) {
            let Steps::ByModel(forms) = m.steps else { continue };
            for &model in m.models {
                let n = forms.iter().filter(|f| f.models.contains(&model)).count();
                assert_eq!(n, 1, "{}: {model} is in {n} forms", m.id);
            }
            for f in forms {
                assert!(
                    f.models.iter().all(|x| m.applies_to(*x)),
                    "{}: a form lists a model outside {:?}",
                    m.id,
                    m.models
                );
                assert!(!f.steps.is_empty(), "{}: an empty form", m.id);
            }
        }
        let twice = Mistake::by_id("attenuation-distance-squared-twice").unwrap();
        assert_eq!(twice.steps_for(ModelId::Point).map(<[_]>::len), Some(2));
        assert_eq!(twice.steps_for(ModelId::OpenGLTutorial8).map(<[_]>::len), Some(1));
        assert_eq!(twice.steps_for(ModelId::BasicLighting), None);
        assert_eq!(
            twice.rewrite(ModelId::BasicLighting, "x"),
            Err(MutateError::NotApplicable { id: twice.id, model: ModelId::BasicLighting })
        );
    }

    /// opengl-tutorial 8's mutant divides both the diffuse and the specular term by d⁴.
    #[test]
    fn opengl_tutorial_8_squared_twice_divides_both_terms_by_d4() {
        let twice = Mistake::by_id("attenuation-distance-squared-twice").unwrap();
        let text = twice.mutate(ModelId::OpenGLTutorial8).unwrap();
        assert_eq!(text.matches("/ (distance * distance * distance * distance)").count(), 2, "{text}");
    }
}
