//! The layout of every model (see [`super`]).

use super::{Layout, LayoutId, QType, Quantity};
use crate::casters::Attenuation;
use crate::gl::model_id::{ModelId, N_MODELS};

use LayoutId::Model;

use QType::{Float as F, Mat4 as M, Texel as T, Vec3 as V};

const fn q(name: &'static str, ty: QType, input: usize, offset: usize, range: (f32, f32)) -> Quantity {
    Quantity::new(name, ty, input, offset, range)
}

/// Ranges of the generated values (see [`crate::oracle::cases`] for the distributions).
mod ranges {
    /// Fragment positions: a box of half-width 5.
    pub const FRAG: (f32, f32) = (-5.0, 5.0);
    /// Interpolated normals: length up to 5.
    pub const NORMAL: (f32, f32) = (-5.0, 5.0);
    /// A light or eye at most 20 from a fragment in the box.
    pub const POINT: (f32, f32) = (-25.0, 25.0);
    /// Colours, strengths and intensities.
    pub const UNIT: (f32, f32) = (0.0, 1.0);
    /// Shininess, 0 included (a degenerate share).
    pub const SHININESS: (f32, f32) = (0.0, 256.0);
    /// Shininess without the degenerate 0.
    pub const SHININESS_1: (f32, f32) = (1.0, 256.0);
    /// Attenuation constants (`Kc`, `Kl`, `Kq`).
    pub const KC: (f32, f32) = (0.5, 2.0);
    /// `Kl`.
    pub const KL: (f32, f32) = (0.0, 1.0);
    /// `Kq`.
    pub const KQ: (f32, f32) = (0.0, 2.0);
}

use ranges as r;

/// The basic-lighting family's quantities: the fragment `pos`, the `normal`, and the
/// ranges of the light and eye positions and of the shininess.
const fn basic(
    pos: (&'static str, (f32, f32)),
    normal: &'static str,
    points: (f32, f32),
    shininess: (f32, f32),
) -> [Quantity; 9] {
    [
        q(pos.0, V, 0, 0, pos.1),
        q("ambientStrength", F, 0, 3, r::UNIT).chapter(0.1),
        q(normal, V, 1, 0, r::NORMAL),
        q("specularStrength", F, 1, 3, r::UNIT).chapter(0.5),
        q("lightPos", V, 2, 0, points),
        q("shininess", F, 2, 3, shininess).chapter(32.0),
        q("viewPos", V, 3, 0, points),
        q("lightColor", V, 4, 0, r::UNIT).rgb(),
        q("objectColor", V, 5, 0, r::UNIT).rgb(),
    ]
}

const BASIC_Q: [Quantity; 9] = basic(("FragPos", r::FRAG), "Normal", r::POINT, r::SHININESS);

/// LearnOpenGL, Basic lighting: Phong per fragment.
pub const BASIC_LIGHTING: Layout =
    layout(Model(ModelId::BasicLighting), "LearnOpenGL, Lighting > Basic lighting", &BASIC_Q, LIT_OUTPUTS);

/// LearnOpenGL, Advanced Lighting: Blinn-Phong (the halfway vector) on the basic-lighting
/// inputs, with the same quantities at the same places (check-shader only: not in the
/// oracle's table).
pub const BLINN_PHONG: Layout = layout(
    Model(ModelId::BlinnPhong),
    "LearnOpenGL, Advanced Lighting > Blinn-Phong (on the Basic lighting inputs)",
    &BASIC_Q,
    LIT_OUTPUTS,
);

/// World positions of the Gouraud cases: `model·aPos` (|T| <= 2, scale <= 4, |aPos| <= 1
/// per component) plus an offset up to 20.
const GOURAUD_POINT: (f32, f32) = (-30.0, 30.0);
/// Entries of `T·R·S` with scales in [0.25, 4] and translations in [-2, 2].
const MODEL_ENTRY: (f32, f32) = (-4.0, 4.0);

const GOURAUD_Q: [Quantity; 10] =
    cat(basic(("aPos", (-1.0, 1.0)), "aNormal", GOURAUD_POINT, r::SHININESS_1), [q("model", M, 6, 0, MODEL_ENTRY)]);

/// LearnOpenGL, Basic lighting, Gouraud exercise: the lighting per vertex.
pub const GOURAUD: Layout = layout(
    Model(ModelId::Gouraud),
    "LearnOpenGL, Lighting > Basic lighting, exercise (Gouraud shading)",
    &GOURAUD_Q,
    &["FragColor.rgb, 1", "LightingColor.rgb, 0"],
);

const VERTEX_PAIR_Q: [Quantity; 12] =
    cat(GOURAUD_Q, [Quantity::uniform("view", M), Quantity::uniform("projection", M)]);

/// A vertex + fragment pair (check-shader `--vertex`): one row per vertex of a triangle,
/// the Gouraud quantities (`aPos`, `aNormal` per vertex; `model` and the lighting uniforms
/// shared), plus the `view` (rigid) and `projection` matrices as uniforms of each group of
/// triangles. What the fragment shader reads
/// from the vertex shader is interpolated, so only the vertex stage reads this layout's
/// per-vertex quantities.
pub const VERTEX_PAIR: Layout = layout(
    LayoutId::VertexPair,
    "LearnOpenGL, Lighting > Basic lighting (vertex and fragment shaders together)",
    &VERTEX_PAIR_Q,
    &["FragColor.rgb, 1"],
);

const NORMAL_MATRIX_Q: [Quantity; 10] =
    cat(basic(("FragPos", r::FRAG), "aNormal", r::POINT, r::SHININESS_1), [q("model", M, 6, 0, MODEL_ENTRY)]);

/// Basic lighting with the normal in object space and a `model` matrix: the shader must
/// apply the normal matrix (check-shader only; no tutorial shader).
pub const NORMAL_MATRIX: Layout = layout(
    Model(ModelId::NormalMatrix),
    "LearnOpenGL, Lighting > Basic lighting, the normal matrix",
    &NORMAL_MATRIX_Q,
    &["FragColor.rgb, 1"],
);

/// LearnOpenGL, Materials: material and light colors per component.
pub const MATERIALS: Layout = Layout {
    id: Model(ModelId::Materials),
    source: "LearnOpenGL, Lighting > Materials",
    quantities: &[
        q("FragPos", V, 0, 0, r::FRAG),
        q("Normal", V, 1, 0, r::NORMAL),
        q("viewPos", V, 2, 0, r::POINT),
        q("material.ambient", V, 3, 0, r::UNIT).rgb(),
        q("material.shininess", F, 3, 3, r::SHININESS),
        q("material.diffuse", V, 4, 0, r::UNIT).rgb(),
        q("material.specular", V, 5, 0, r::UNIT).rgb(),
        q("light.position", V, 6, 0, r::POINT),
        q("light.ambient", V, 7, 0, r::UNIT).rgb(),
        q("light.diffuse", V, 8, 0, r::UNIT).rgb(),
        q("light.specular", V, 9, 0, r::UNIT).rgb(),
    ],
    outputs: &["result.rgb, 1", "diff, spec, 0, 0"],
};

/// The surface of the mapped models: inputs 0 to 4 (and texture coordinates, unused).
macro_rules! mapped_surface {
    () => {
        [
            q("FragPos", V, 0, 0, r::FRAG),
            q("material.shininess", F, 0, 3, r::SHININESS_1),
            q("Normal", V, 1, 0, r::NORMAL),
            q("viewPos", V, 2, 0, r::POINT),
            q("material.diffuse", T, 3, 0, r::UNIT).text("diffuse map texel rgb"),
            q("material.specular", T, 4, 0, r::UNIT).text("specular map texel rgb"),
            Quantity::unused("TexCoords"),
        ]
    };
}

/// The light colours of a single-light mapped model, from input `k`.
macro_rules! light_props {
    ($k:expr) => {
        [
            q("light.ambient", V, $k, 0, r::UNIT).rgb(),
            q("light.diffuse", V, $k + 1, 0, r::UNIT).rgb(),
            q("light.specular", V, $k + 2, 0, r::UNIT).rgb(),
        ]
    };
}

/// Attenuation `(Kc, Kl, Kq)` in input `k`; the chapter's values are
/// [`Attenuation::LEARNOPENGL`] (1, 0.09, 0.032, distance 50).
macro_rules! attenuation {
    ($k:expr) => {
        [
            q("light.constant", F, $k, 0, r::KC).chapter(Attenuation::LEARNOPENGL.constant),
            q("light.linear", F, $k, 1, r::KL).chapter(Attenuation::LEARNOPENGL.linear),
            q("light.quadratic", F, $k, 2, r::KQ).chapter(Attenuation::LEARNOPENGL.quadratic),
        ]
    };
}

/// The Light casters chapter's spotlight cut-offs, `cos(12.5°)` and `cos(17.5°)` as `f32`
/// (`f32::cos` is not a `const fn`; a test checks these are `12.5f32.to_radians().cos()`
/// and `17.5f32.to_radians().cos()` to the bit).
pub const SPOT_CUT_OFFS: (f32, f32) = (0.976_296, 0.953_716_93);

/// A layout (the fields of [`Layout`], in order).
const fn layout(
    id: LayoutId,
    source: &'static str,
    quantities: &'static [Quantity],
    outputs: &'static [&'static str],
) -> Layout {
    Layout { id, source, quantities, outputs }
}

/// The outputs of the single-light harnesses: the colour, then the diffuse and specular
/// factors.
const LIT_OUTPUTS: &[&str] = &["result.rgb, 1", "diff, spec, 0, 0"];

const fn cat<const A: usize, const B: usize, const N: usize>(a: [Quantity; A], b: [Quantity; B]) -> [Quantity; N] {
    assert!(A + B == N);
    let mut out = [Quantity::unused(""); N];
    let mut i = 0;
    while i < A {
        out[i] = a[i];
        i += 1;
    }
    while i < N {
        out[i] = b[i - A];
        i += 1;
    }
    out
}

const MAPS_Q: [Quantity; 11] =
    cat(mapped_surface!(), cat::<1, 3, 4>([q("light.position", V, 5, 0, r::POINT)], light_props!(6)));

/// LearnOpenGL, Lighting maps: diffuse and specular colors sampled from textures.
pub const LIGHTING_MAPS: Layout =
    layout(Model(ModelId::LightingMaps), "LearnOpenGL, Lighting > Lighting maps", &MAPS_Q, LIT_OUTPUTS);

const MAPS_EMISSION_Q: [Quantity; 12] =
    cat(MAPS_Q, [q("material.emission", T, 9, 0, r::UNIT).text("emission map texel rgb")]);

/// LearnOpenGL, Lighting maps, exercise 4: Lighting maps plus an emission map, added to the
/// result without lighting (check-shader only: not in the oracle's table).
pub const LIGHTING_MAPS_EMISSION: Layout = layout(
    Model(ModelId::LightingMapsEmission),
    "LearnOpenGL, Lighting > Lighting maps, exercise 4 (emission map)",
    &MAPS_EMISSION_Q,
    LIT_OUTPUTS,
);

const DIRECTIONAL_Q: [Quantity; 11] = cat(
    mapped_surface!(),
    cat::<1, 3, 4>(
        [q("light.direction", V, 5, 0, r::NORMAL).text("light.direction.xyz (from the light)")],
        light_props!(6),
    ),
);

/// LearnOpenGL, Light casters: directional light.
pub const DIRECTIONAL: Layout = layout(
    Model(ModelId::Directional),
    "LearnOpenGL, Lighting > Light casters, directional light",
    &DIRECTIONAL_Q,
    LIT_OUTPUTS,
);

const POINT_Q: [Quantity; 14] = cat(MAPS_Q, attenuation!(9));

/// LearnOpenGL, Light casters: point light with attenuation.
pub const POINT: Layout = layout(
    Model(ModelId::Point),
    "LearnOpenGL, Lighting > Light casters, point lights, attenuation",
    &POINT_Q,
    &["result.rgb, 1", "diff, spec, attenuation, 0"],
);

const SPOT_Q: [Quantity; 17] = cat(
    mapped_surface!(),
    cat::<7, 3, 10>(
        cat::<4, 3, 7>(
            [
                q("light.position", V, 5, 0, r::POINT),
                // cos of an inner angle in [5°, 60°]; the outer one is up to 15° wider.
                q("light.cutOff", F, 5, 3, (0.5, 1.0)).text("light.cutOff (cosine)").chapter(SPOT_CUT_OFFS.0),
                q("light.direction", V, 6, 0, r::NORMAL).text("light.direction.xyz (from the light)"),
                q("light.outerCutOff", F, 6, 3, (0.25, 1.0))
                    .text("light.outerCutOff (cosine)")
                    .chapter(SPOT_CUT_OFFS.1),
            ],
            light_props!(7),
        ),
        attenuation!(10),
    ),
);

/// LearnOpenGL, Light casters: spotlight, soft edges (and the first, hard-edged version).
pub const SPOT: Layout = layout(
    Model(ModelId::Spot),
    "LearnOpenGL, Lighting > Light casters, spotlight, flashlight, soft edges",
    &SPOT_Q,
    &["soft-edged result.rgb, 1", "hard-cutoff result.rgb, theta"],
);

const MULTI_Q: [Quantity; 10] =
    cat(mapped_surface!(), [Quantity::group("dirLight"), Quantity::group("pointLights"), Quantity::group("spotLight")]);

/// LearnOpenGL, Multiple lights: directional + 4 point lights + flashlight, lights as uniforms.
pub const MULTIPLE_LIGHTS: Layout = layout(
    Model(ModelId::MultipleLights),
    "LearnOpenGL, Lighting > Multiple lights",
    &MULTI_Q,
    &["all lights rgb, 1", "without the spotlight rgb, 1"],
);

/// opengl-tutorial.org tutorial 8: inverse-square point light, camera-space vectors.
pub const OPENGL_TUTORIAL8: Layout = Layout {
    id: Model(ModelId::OpenGLTutorial8),
    source: "opengl-tutorial.org, tutorial 8: Basic shading",
    quantities: &[
        q("Position_worldspace", V, 0, 0, r::FRAG),
        q("LightPower", F, 0, 3, (1.0, 60.0)).chapter(50.0),
        q("Normal_cameraspace", V, 1, 0, r::NORMAL),
        q("specularExponent", F, 1, 3, (0.0, 128.0)).chapter(5.0).text("specular exponent"),
        q("EyeDirection_cameraspace", V, 2, 0, r::FRAG),
        q("LightDirection_cameraspace", V, 3, 0, (-20.0, 20.0)),
        q("LightPosition_worldspace", V, 4, 0, r::POINT),
        q("MaterialDiffuseColor", V, 5, 0, r::UNIT).rgb(),
        q("MaterialSpecularColor", V, 6, 0, r::UNIT).rgb().chapter(0.3),
        q("LightColor", V, 7, 0, r::UNIT).rgb().chapter(1.0),
        q("MaterialAmbientFactor", V, 8, 0, r::UNIT).chapter(0.1).text("ambient factor rgb"),
    ],
    outputs: &["color.rgb, 1", "cosTheta, cosAlpha, distance, 0"],
};

/// ogldev tutorial 19: directional light with specular intensity and power.
pub const OGLDEV19: Layout = Layout {
    id: Model(ModelId::Ogldev19),
    source: "ogldev tutorial 19: Specular lighting",
    quantities: &[
        q("WorldPos0", V, 0, 0, r::FRAG),
        q("gSpecularPower", F, 0, 3, (0.0, 128.0)),
        q("Normal0", V, 1, 0, r::NORMAL),
        q("gMatSpecularIntensity", F, 1, 3, r::UNIT),
        q("gEyeWorldPos", V, 2, 0, r::POINT),
        q("gDirectionalLight.Color", V, 3, 0, r::UNIT).rgb(),
        q("gDirectionalLight.AmbientIntensity", F, 3, 3, r::UNIT),
        q("gDirectionalLight.Direction", V, 4, 0, (-1.0, 1.0)).text("gDirectionalLight.Direction.xyz (from the light)"),
        q("gDirectionalLight.DiffuseIntensity", F, 4, 3, r::UNIT),
        q("gSampler", T, 5, 0, r::UNIT).rgba().text("sampled texel rgba"),
        Quantity::unused("TexCoord0"),
    ],
    outputs: &["FragColor rgba", "DiffuseFactor, SpecularFactor, 0, 0"],
};

/// Every model's layout, in [`ModelId::ALL`] order (chapter order, then the
/// check-shader-only `normal_matrix`, `blinn_phong` and `lighting_maps_emission`); [`ModelId::layout`] indexes it.
pub const LAYOUTS: [&Layout; N_MODELS] = [
    &BASIC_LIGHTING,
    &GOURAUD,
    &MATERIALS,
    &LIGHTING_MAPS,
    &DIRECTIONAL,
    &POINT,
    &SPOT,
    &MULTIPLE_LIGHTS,
    &OPENGL_TUTORIAL8,
    &OGLDEV19,
    &NORMAL_MATRIX,
    &BLINN_PHONG,
    &LIGHTING_MAPS_EMISSION,
];

// Entry `i` of `LAYOUTS` is the layout of `ModelId::ALL[i]` (checked at compile time).
const _: () = {
    let mut i = 0;
    while i < N_MODELS {
        match LAYOUTS[i].id {
            LayoutId::Model(m) => assert!(m as usize == i, "LAYOUTS out of ModelId order"),
            LayoutId::VertexPair => panic!("the vertex pair is no model"),
        }
        i += 1;
    }
};

impl ModelId {
    /// The model's packed layout (the single description of its inputs).
    #[must_use]
    pub const fn layout(self) -> &'static Layout {
        LAYOUTS[self as usize]
    }
}
