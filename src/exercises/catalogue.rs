//! The exercises, in chapter order, and the crate computations behind the numeric and
//! choice answers.

use glam::Vec3;

use super::{Check, Exercise};
use crate::casters::{self, Attenuation};
use crate::checker::check::pair::PairModel;
use crate::gl::ModelId;
use crate::material::{self, LightProps, Material};
use crate::phong;

/// The answer of a numeric exercise; `None` for other kinds or unknown ids.
pub fn answer_number(id: &str) -> Option<f64> {
    match super::Exercise::by_id(id)?.check {
        Check::Numeric { answer, .. } => Some(answer()),
        _ => None,
    }
}

/// The answer (choice index) of a choice exercise; `None` for other kinds or unknown ids.
pub fn answer_choice(id: &str) -> Option<usize> {
    match super::Exercise::by_id(id)?.check {
        Check::Choice { answer, .. } => Some(answer()),
        _ => None,
    }
}

/// The shininess whose Phong lobe has a half-width of 10°: bisection on
/// [`phong::lobe_half_width_deg`], which decreases as the shininess grows.
fn shininess_for_half_width_10() -> f64 {
    let (mut lo, mut hi) = (1.0f32, 4096.0f32);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        match phong::lobe_half_width_deg(mid) {
            Some(w) if w > 10.0 => lo = mid,
            _ => hi = mid,
        }
    }
    f64::from(0.5 * (lo + hi))
}

/// Cyan plastic's exponent: the classic table's fraction × 128 ([`material::ClassicMaterial::shininess`]).
fn cyan_plastic_shininess() -> f64 {
    material::classic_material("cyan plastic").map_or(f64::NAN, |m| f64::from(m.shininess()))
}

/// The lamp's green channel at t = 2 s when the lamp shows the light's diffuse color
/// ([`LightProps::time_varying`]).
fn lamp_green_at_2s() -> f64 {
    f64::from(LightProps::time_varying(2.0).diffuse.y)
}

/// Lighting maps with light (0.2, 0.5, 1.0), the fragment facing the light, the eye on
/// the mirror direction, diffuse texel (0.6, 0.4, 0.2), specular texel 0.5, shininess 32:
/// the red channel ([`material::material_terms`]).
fn maps_red() -> f64 {
    let n = Vec3::Z;
    let m = Material {
        ambient: Vec3::new(0.6, 0.4, 0.2),
        diffuse: Vec3::new(0.6, 0.4, 0.2),
        specular: Vec3::splat(0.5),
        shininess: 32.0,
    };
    let light = LightProps { ambient: Vec3::splat(0.2), diffuse: Vec3::splat(0.5), specular: Vec3::ONE };
    f64::from(material::material_terms(&m, &light, n, n, n).sum().x)
}

/// The emission exercise: a fragment facing away from the light (only the ambient term),
/// light.ambient 0.2, diffuse texel green 0.4, emission green 1: the green channel written
/// to an 8-bit framebuffer (clamped, [`crate::glsl::saturate`]).
fn emission_green() -> f64 {
    let m = Material {
        ambient: Vec3::new(0.5, 0.4, 0.3),
        diffuse: Vec3::new(0.5, 0.4, 0.3),
        specular: Vec3::ZERO,
        shininess: 32.0,
    };
    let light = LightProps { ambient: Vec3::splat(0.2), diffuse: Vec3::splat(0.5), specular: Vec3::ONE };
    let lit = material::material_terms(&m, &light, Vec3::Z, -Vec3::Z, Vec3::Z).sum();
    f64::from(crate::glsl::saturate(lit.y + 1.0))
}

/// The distance at which attenuation (1, 0.09, 0.032) falls to one half
/// ([`Attenuation::distance_for`]).
fn half_distance() -> f64 {
    Attenuation::new(1.0, 0.09, 0.032).ok().and_then(|a| a.distance_for(0.5)).map_or(f64::NAN, f64::from)
}

/// Gouraud against Phong on a large triangle lit head-on at its centre: the centre's
/// specular under Gouraud (the mean of the vertices') against Phong's (at the centre),
/// both from [`phong::phong_specular_factor`]. Choice 1 ("much smaller") when Gouraud's is
/// below half of Phong's, 2 when above 1.5×, else 0.
fn gouraud_choice() -> usize {
    let eye = Vec3::new(0.0, 0.0, 3.0);
    let n = Vec3::Z;
    let spec = |p: Vec3| phong::phong_specular_factor(n, (eye - p).normalize(), (eye - p).normalize(), 32.0);
    let vertices = [Vec3::new(-2.0, -1.5, 0.0), Vec3::new(2.0, -1.5, 0.0), Vec3::new(0.0, 2.0, 0.0)];
    let centre = vertices.iter().copied().sum::<Vec3>() / 3.0;
    let gouraud = vertices.iter().map(|&v| spec(v)).sum::<f32>() / 3.0;
    let phong_centre = spec(centre);
    if gouraud < 0.5 * phong_centre {
        1
    } else if gouraud > 1.5 * phong_centre {
        2
    } else {
        0
    }
}

/// The flashlight's θ with the un-negated direction, on the axis straight ahead: the
/// intensity from [`casters::spot_intensity`] with the chapter's cut-offs (12.5°, 17.5°).
/// Choice 1 (dark) when the intensity is 0, 0 when 1, else 2.
fn flipped_direction_choice() -> usize {
    let direction = Vec3::new(0.0, 0.0, -1.0);
    let light_dir = -direction; // from the fragment ahead on the axis back to the light
    let theta = light_dir.dot(direction.normalize()); // the mistake: no minus sign
    let i = casters::spot_intensity(theta, 12.5f32.to_radians().cos(), 17.5f32.to_radians().cos());
    if i == 0.0 {
        1
    } else if i == 1.0 {
        0
    } else {
        2
    }
}

/// The hard-edged spot with `theta < cutOff`: a fragment 40° off the axis (outside the
/// 12.5° cone) is lit iff the swapped test holds; [`casters::hard_spot`] gives the
/// correct test's result for comparison. Choice 1 ("outside lit, inside dark") when the
/// swapped test lights the outside fragment and not the axis one.
fn swapped_comparison_choice() -> usize {
    let cut = 12.5f32.to_radians().cos();
    let outside = 40f32.to_radians().cos();
    let inside = 1.0f32;
    let swapped = |theta: f32| theta < cut;
    let correct_outside = casters::hard_spot(outside, cut) == 1.0;
    match (swapped(outside), swapped(inside), correct_outside) {
        (true, false, false) => 1,
        (false, true, _) => 0,
        _ => 2,
    }
}

const VIEW_SPACE_MAPPING: &str = "[values]\nviewPos = [0.0, 0.0, 0.0]\n\n[rules]\nforbid = [\"viewPos\"]\n";
const OGLDEV_ATTRIBUTES_MAPPING: &str =
    "[names]\nSpecularIntensity0 = \"gMatSpecularIntensity\"\nSpecularPower0 = \"gSpecularPower\"\n";

/// Inverted specular map: `1 - specularTexel`.
const INVERT_SPECULAR: &[&[(&str, &str)]] = &[&[(
    "vec3 specular = light.specular * spec * specularTexel;",
    "vec3 specular = light.specular * spec * (1.0 - specularTexel);",
)]];

/// Blinn-Phong: the catalogue's `blinn-for-phong` edits, here the asked-for model.
const BLINN: &[&[(&str, &str)]] = &[
    &[(
        "vec3 reflectDir = reflect(-lightDir, norm);",
        "vec3 halfwayDir = normalize(lightDir + viewDir); vec3 n = norm;",
    )],
    &[("dot(viewDir, reflectDir)", "dot(n, halfwayDir)")],
];

const fn shader(model: ModelId) -> Check {
    Check::Shader { model, mapping: "" }
}

/// Every exercise, chapter order, ours last.
pub const EXERCISES: &[Exercise] = &[
    Exercise {
        id: "basic-move-light",
        chapter: "basic-lighting",
        source: "LearnOpenGL, Basic lighting, exercise 1",
        title: "Move the light over time",
        statement: "Move the light around the scene over time, for example `lightPos.x = 1.0 + sin(time) * 2.0; \
                    lightPos.y = sin(time / 2.0) * 1.0;` in the application. Your fragment shader must take the \
                    light's position from the `lightPos` uniform every frame (no constant position), with the \
                    chapter's Phong model: ambient, diffuse and specular. The check moves the light to random \
                    positions.",
        check: shader(ModelId::BasicLighting),
        solution_text: None,
        stub: None,
    },
    Exercise {
        id: "basic-shininess-half-width",
        chapter: "basic-lighting",
        source: "LearnOpenGL, Basic lighting, exercise 2 (play with the strengths and the shininess)",
        title: "The shininess of a 10° highlight",
        statement: "The Phong highlight falls as cos(α)^shininess, α being the angle between the view direction and \
                    the mirror direction. At which shininess is the highlight's half-width 10°, that is, at which \
                    shininess does cos(10°)^shininess equal 1/2? Answer to within 0.5 (a shininess 0.5 away moves \
                    the half-width by about 0.06°).",
        check: Check::Numeric { answer: shininess_for_half_width_10, tolerance: 0.5, unit: "" },
        solution_text: None,
        stub: None,
    },
    Exercise {
        id: "basic-view-space",
        chapter: "basic-lighting",
        source: "LearnOpenGL, Basic lighting, exercise 3",
        title: "Phong in view space",
        statement: "Compute the lighting in view space: `FragPos`, `Normal` and `lightPos` arrive already in view \
                    space, so the eye is at the origin and you need no `viewPos` (do not declare it). The check \
                    fixes the eye at (0, 0, 0).",
        check: Check::Shader { model: ModelId::BasicLighting, mapping: VIEW_SPACE_MAPPING },
        solution_text: Some(include_str!("solutions/basic_view_space.frag")),
        stub: None,
    },
    Exercise {
        id: "basic-gouraud",
        chapter: "basic-lighting",
        source: "LearnOpenGL, Basic lighting, exercise 4 (Gouraud shading)",
        title: "Gouraud against Phong",
        statement: "A large triangle (vertices (-2, -1.5, 0), (2, -1.5, 0), (0, 2, 0), normal +z) is lit by a light \
                    at the eye, (0, 0, 3), shininess 32, so the mirror direction points at the eye at the triangle's \
                    centre. With Gouraud shading the lighting is computed at the vertices and interpolated. How \
                    does the centre's specular compare with Phong shading's?",
        check: Check::Choice {
            choices: &[
                "about the same as with Phong shading",
                "much smaller: the highlight is lost between the vertices",
                "much larger: interpolation spreads the highlight",
            ],
            answer: gouraud_choice,
        },
        solution_text: None,
        stub: None,
    },
    Exercise {
        id: "basic-gouraud-pair",
        chapter: "basic-lighting",
        source: "LearnOpenGL, Basic lighting, exercise 4 (Gouraud shading)",
        title: "Light per vertex: Gouraud",
        statement: "Move the lighting into the vertex shader (Gouraud shading): the vertex shader computes the \
                    ambient, diffuse and specular terms at its vertex, in world space, and passes the lit colour \
                    on; the fragment shader only multiplies the interpolated colour by `objectColor`. The starter is \
                    the chapter's per-fragment pair. Both shaders are checked together, on random triangles: \
                    `lightlab exercise check basic-gouraud-pair FRAG --vertex VERT`.",
        check: Check::Pair { model: PairModel::PerVertex },
        solution_text: None,
        stub: None,
    },
    Exercise {
        id: "materials-cyan-plastic",
        chapter: "materials",
        source: "LearnOpenGL, Materials, exercise (a real material: cyan plastic)",
        title: "Cyan plastic",
        statement: "Give the container the cyan plastic material from the classic materials table (ambient, diffuse, \
                    specular and shininess, with all light components 1.0). The table prints the shininess as a \
                    fraction. Which value do you pass to `material.shininess`?",
        check: Check::Numeric { answer: cyan_plastic_shininess, tolerance: 0.01, unit: "" },
        solution_text: None,
        stub: None,
    },
    Exercise {
        id: "materials-lamp-follows-light",
        chapter: "materials",
        source: "Lab 8 (lecture 8), task: the lamp cube follows the light's color",
        title: "The lamp shows the light's color",
        statement: "The light's color changes over time: `lightColor = (sin(2t), sin(0.7t), sin(1.3t))`, \
                    `diffuse = lightColor * 0.5`, `ambient = diffuse * 0.2`. Make the lamp cube's fragment shader \
                    output the light's diffuse color through a uniform. What green value does the lamp show at \
                    t = 2 s (unclamped, to within 0.005)?",
        check: Check::Numeric { answer: lamp_green_at_2s, tolerance: 0.005, unit: "" },
        solution_text: None,
        stub: None,
    },
    Exercise {
        id: "maps-light-components",
        chapter: "lighting-maps",
        source: "LearnOpenGL, Lighting maps, exercise 1 (play with the light's components)",
        title: "The light's components",
        statement: "With `light.ambient = 0.2`, `light.diffuse = 0.5`, `light.specular = 1.0`, a fragment facing the \
                    light head-on, the eye on the mirror direction, a diffuse-map texel (0.6, 0.4, 0.2), a \
                    specular-map texel 0.5 and shininess 32: what is the red channel before the output clamp (to \
                    within 0.001)?",
        check: Check::Numeric { answer: maps_red, tolerance: 0.001, unit: "" },
        solution_text: None,
        stub: None,
    },
    Exercise {
        id: "maps-invert-specular",
        chapter: "lighting-maps",
        source: "LearnOpenGL, Lighting maps, exercise 2",
        title: "Invert the specular map",
        statement: "Invert the specular map's colors in the shader: wood shines and the steel border does not. Use \
                    `1.0 - texel` for the specular texel; everything else is the chapter's shader.",
        check: Check::Variant { model: ModelId::LightingMaps, steps: INVERT_SPECULAR, mapping: "" },
        solution_text: None,
        stub: None,
    },
    Exercise {
        id: "maps-colored-specular",
        chapter: "lighting-maps",
        source: "LearnOpenGL, Lighting maps, exercise 3",
        title: "A colored specular map",
        statement: "Use a specular map with colors instead of grays. Your shader must multiply the specular term by \
                    the full RGB texel (not only its red channel). The check draws colored texels.",
        check: shader(ModelId::LightingMaps),
        solution_text: None,
        stub: None,
    },
    Exercise {
        id: "maps-emission",
        chapter: "lighting-maps",
        source: "LearnOpenGL, Lighting maps, exercise 4 (an emission map)",
        title: "An emission map",
        statement: "Add an emission map: `emission = texture(material.emission, TexCoords).rgb`, added to the result. \
                    At a fragment facing away from the light, with `light.ambient = 0.2`, a diffuse texel \
                    (0.5, 0.4, 0.3) and an emission texel (0, 1, 0), what green value ends up in an 8-bit \
                    framebuffer (as a fraction of 1)?",
        check: Check::Numeric { answer: emission_green, tolerance: 0.002, unit: "" },
        solution_text: None,
        stub: None,
    },
    Exercise {
        id: "maps-emission-shader",
        chapter: "lighting-maps",
        source: "LearnOpenGL, Lighting maps, exercise 4 (an emission map), as a shader",
        title: "An emission map in the shader",
        statement: "Add an emission map to the chapter's shader: a third map `material.emission` in the material, its \
                    texel read at `TexCoords` and added to the result as it is, unlit (no light's color or \
                    strength multiplies it). The check draws colored emission texels on lit and unlit fragments.",
        check: shader(ModelId::LightingMapsEmission),
        solution_text: None,
        stub: None,
    },
    Exercise {
        id: "casters-flip-vectors",
        chapter: "light-casters",
        source: "LearnOpenGL, Light casters, exercise (invert the vectors, then explain)",
        title: "Invert the spot direction",
        statement: "In the flashlight's shader, write `theta = dot(lightDir, normalize(light.direction))` (the minus \
                    sign forgotten). Cut-offs 12.5° and 17.5°. What happens to a fragment straight ahead of the \
                    flashlight, on its axis?",
        check: Check::Choice {
            choices: &[
                "it stays fully lit",
                "it goes dark: θ = -1, far outside the cone, which now points backwards",
                "it falls in the soft edge",
            ],
            answer: flipped_direction_choice,
        },
        solution_text: None,
        stub: None,
    },
    Exercise {
        id: "casters-swap-comparison",
        chapter: "light-casters",
        source: "LearnOpenGL, Light casters, exercise (swap < and >, then explain)",
        title: "Swap the comparison",
        statement: "In the hard-edged spotlight, write `if (theta < light.cutOff)` instead of `>`. θ and cutOff are \
                    cosines. Which fragments get the diffuse and specular terms now?",
        check: Check::Choice {
            choices: &[
                "those inside the cone, as before",
                "those outside the cone; the inside gets only ambient",
                "none",
            ],
            answer: swapped_comparison_choice,
        },
        solution_text: None,
        stub: None,
    },
    Exercise {
        id: "multi-atmosphere",
        chapter: "multiple-lights",
        source: "LearnOpenGL, Multiple lights, exercise (the atmospheres)",
        title: "Make an atmosphere",
        statement: "Recreate one of the chapter's atmospheres (desert, factory, horror, biochemical lab) by changing \
                    the lights' uniforms only. Your shader must handle any light values: the check sets random \
                    directional, point and spot lights.",
        check: shader(ModelId::MultipleLights),
        solution_text: None,
        stub: None,
    },
    Exercise {
        id: "multi-calc-spot",
        chapter: "multiple-lights",
        source: "LearnOpenGL, Multiple lights (CalcSpotLight is left to the reader)",
        title: "Write CalcSpotLight",
        statement: "Write `CalcSpotLight`: the spotlight of the Light casters chapter (soft edge between `cutOff` and \
                    `outerCutOff`, attenuation), returning `(ambient + diffuse + specular) * attenuation * \
                    intensity` as the chapter's code does. The rest of the shader is given.",
        check: shader(ModelId::MultipleLights),
        solution_text: None,
        stub: Some("CalcSpotLight"),
    },
    Exercise {
        id: "ogldev-specular-attributes",
        chapter: "ogldev19",
        source: "ogldev tutorial 19, exercise (specular intensity and power as vertex attributes)",
        title: "Specular intensity and power per vertex",
        statement: "Make the specular intensity and power vertex attributes: the fragment shader receives them as \
                    `in float SpecularIntensity0` and `in float SpecularPower0` instead of the uniforms \
                    `gMatSpecularIntensity` and `gSpecularPower`. The check maps them to the model's names.",
        check: Check::Shader { model: ModelId::Ogldev19, mapping: OGLDEV_ATTRIBUTES_MAPPING },
        solution_text: Some(include_str!("solutions/ogldev_specular_attributes.frag")),
        stub: None,
    },
    Exercise {
        id: "own-blinn-phong",
        chapter: "basic-lighting",
        source: "lightlab",
        title: "Blinn-Phong",
        statement: "Replace Phong's `dot(viewDir, reflectDir)` by Blinn-Phong's `dot(norm, halfwayDir)` with \
                    `halfwayDir = normalize(lightDir + viewDir)`, keeping everything else (and the shininess) as \
                    in the Basic lighting shader.",
        check: Check::Variant { model: ModelId::BasicLighting, steps: BLINN, mapping: "" },
        solution_text: None,
        stub: None,
    },
    Exercise {
        id: "own-directional",
        chapter: "light-casters",
        source: "lightlab",
        title: "A directional light",
        statement: "Write the directional light of Light casters with lighting maps: `light.direction` points from \
                    the light, so `lightDir = normalize(-light.direction)`.",
        check: shader(ModelId::Directional),
        solution_text: None,
        stub: None,
    },
    Exercise {
        id: "own-point-attenuation",
        chapter: "light-casters",
        source: "lightlab",
        title: "A point light with attenuation",
        statement: "Write the point light of Light casters: all three terms multiplied by \
                    `1 / (constant + linear·d + quadratic·d²)`.",
        check: shader(ModelId::Point),
        solution_text: None,
        stub: None,
    },
    Exercise {
        id: "own-soft-spot",
        chapter: "light-casters",
        source: "lightlab",
        title: "A spotlight with soft edges",
        statement: "Write the soft-edged spotlight of Light casters: `intensity = clamp((theta - outerCutOff) / \
                    epsilon, 0, 1)` scales diffuse and specular; attenuation scales all three terms.",
        check: shader(ModelId::Spot),
        solution_text: None,
        stub: None,
    },
    Exercise {
        id: "own-normal-matrix",
        chapter: "basic-lighting",
        source: "lightlab",
        title: "The normal matrix",
        statement: "The normal arrives in object space (`aNormal`) with the `model` matrix, which may scale \
                    non-uniformly. Move it to world space with the normal matrix `transpose(inverse(mat3(model)))`, \
                    then light as in Basic lighting.",
        check: shader(ModelId::NormalMatrix),
        solution_text: Some(include_str!("../gl/shaders/examples/normal_matrix.frag")),
        stub: None,
    },
    Exercise {
        id: "own-attenuation-half",
        chapter: "light-casters",
        source: "lightlab",
        title: "Where the light falls to half",
        statement: "With the attenuation constants (1, 0.09, 0.032) of the chapter's table (range 50), at which \
                    distance has the attenuation fallen to 1/2? Answer to within 0.01.",
        check: Check::Numeric { answer: half_distance, tolerance: 0.01, unit: "" },
        solution_text: None,
        stub: None,
    },
    Exercise {
        id: "own-opengl-tutorial8",
        chapter: "opengl-tutorial8",
        source: "lightlab",
        title: "opengl-tutorial 8, all three terms",
        statement: "Write the fragment shader of opengl-tutorial 8: ambient `MaterialAmbientFactor * \
                    MaterialDiffuseColor`, diffuse and specular scaled by `LightColor * LightPower / distance²`, \
                    specular exponent `specularExponent`. The printed listing ends the diffuse line with `;`: \
                    make sure all three terms are summed.",
        check: shader(ModelId::OpenGLTutorial8),
        solution_text: None,
        stub: None,
    },
];
