//! The tutorials' shaders, written as GLSL function files, and their batch harnesses.
//!
//! Each [`ShaderModel`] pairs a function file (`src/gl/shaders/<name>.glsl`, reusable in a
//! real fragment shader) with a harness (`<name>.harness.glsl`) that unpacks the batch's
//! `vec4` inputs into the function's uniforms and varyings. The GLSL is written for lightlab
//! from the chapters' text (names and constants as in the tutorials), not copied.
//!
//! The packed layouts are listed in [`ShaderModel::inputs`] and [`ShaderModel::outputs`];
//! `-` marks an unused component.

use super::batch::{Batch, Uniform};
use super::context::{GlContext, GlError};

/// One tutorial shader: its GLSL function file, its harness and the packed layout.
#[derive(Debug, Clone, Copy)]
pub struct ShaderModel {
    /// Short name, also the file stem under `src/gl/shaders/`.
    pub name: &'static str,
    /// The chapter the function follows.
    pub source: &'static str,
    /// The function file.
    pub functions: &'static str,
    /// The harness defining `batch_main`.
    pub harness: &'static str,
    /// Meaning of each `vec4` input, in order.
    pub inputs: &'static [&'static str],
    /// Meaning of each `vec4` output, in order.
    pub outputs: &'static [&'static str],
    /// Uniforms shared by all cases, set by [`ShaderModel::batch`] (the chapter's values).
    pub uniforms: &'static [(&'static str, Uniform)],
}

impl ShaderModel {
    /// The batch body: function file then harness. Compile errors number its lines.
    pub fn body(&self) -> String {
        format!("{}\n{}", self.functions, self.harness)
    }

    /// Compiles the model into a [`Batch`] and sets its default uniforms.
    pub fn batch<'a>(&self, ctx: &'a GlContext) -> Result<Batch<'a>, GlError> {
        let batch = Batch::new(ctx, &self.body(), self.inputs.len(), self.outputs.len())?;
        for (name, value) in self.uniforms {
            batch.set_uniform(name, *value)?;
        }
        Ok(batch)
    }

    /// Looks a model up by name; `None` if there is none.
    pub fn by_name(name: &str) -> Option<&'static ShaderModel> {
        MODELS.iter().find(|m| m.name == name)
    }
}

/// LearnOpenGL, Basic lighting: Phong per fragment.
pub const BASIC_LIGHTING: ShaderModel = ShaderModel {
    name: "basic_lighting",
    source: "LearnOpenGL, Lighting > Basic lighting",
    functions: include_str!("shaders/basic_lighting.glsl"),
    harness: include_str!("shaders/basic_lighting.harness.glsl"),
    inputs: &[
        "FragPos.xyz, ambientStrength",
        "Normal.xyz, specularStrength",
        "lightPos.xyz, shininess",
        "viewPos.xyz, -",
        "lightColor.rgb, -",
        "objectColor.rgb, -",
    ],
    outputs: &["result.rgb, 1", "diff, spec, 0, 0"],
    uniforms: &[],
};

/// LearnOpenGL, Basic lighting, Gouraud exercise: the lighting per vertex.
pub const GOURAUD: ShaderModel = ShaderModel {
    name: "gouraud",
    source: "LearnOpenGL, Lighting > Basic lighting, exercise (Gouraud shading)",
    functions: include_str!("shaders/gouraud.glsl"),
    harness: include_str!("shaders/gouraud.harness.glsl"),
    inputs: &[
        "aPos.xyz, ambientStrength",
        "aNormal.xyz, specularStrength",
        "lightPos.xyz, shininess",
        "viewPos.xyz, -",
        "lightColor.rgb, -",
        "objectColor.rgb, -",
        "model column 0",
        "model column 1",
        "model column 2",
        "model column 3",
    ],
    outputs: &["FragColor.rgb, 1", "LightingColor.rgb, 0"],
    uniforms: &[],
};

/// LearnOpenGL, Materials: material and light colors per component.
pub const MATERIALS: ShaderModel = ShaderModel {
    name: "materials",
    source: "LearnOpenGL, Lighting > Materials",
    functions: include_str!("shaders/materials.glsl"),
    harness: include_str!("shaders/materials.harness.glsl"),
    inputs: &[
        "FragPos.xyz, -",
        "Normal.xyz, -",
        "viewPos.xyz, -",
        "material.ambient.rgb, material.shininess",
        "material.diffuse.rgb, -",
        "material.specular.rgb, -",
        "light.position.xyz, -",
        "light.ambient.rgb, -",
        "light.diffuse.rgb, -",
        "light.specular.rgb, -",
    ],
    outputs: &["result.rgb, 1", "diff, spec, 0, 0"],
    uniforms: &[],
};

const MAPPED_SURFACE: [&str; 5] = [
    "FragPos.xyz, material.shininess",
    "Normal.xyz, -",
    "viewPos.xyz, -",
    "diffuse map texel rgb, -",
    "specular map texel rgb, -",
];

/// LearnOpenGL, Lighting maps: diffuse and specular colors sampled from textures.
pub const LIGHTING_MAPS: ShaderModel = ShaderModel {
    name: "lighting_maps",
    source: "LearnOpenGL, Lighting > Lighting maps",
    functions: include_str!("shaders/lighting_maps.glsl"),
    harness: include_str!("shaders/lighting_maps.harness.glsl"),
    inputs: &[
        MAPPED_SURFACE[0],
        MAPPED_SURFACE[1],
        MAPPED_SURFACE[2],
        MAPPED_SURFACE[3],
        MAPPED_SURFACE[4],
        "light.position.xyz, -",
        "light.ambient.rgb, -",
        "light.diffuse.rgb, -",
        "light.specular.rgb, -",
    ],
    outputs: &["result.rgb, 1", "diff, spec, 0, 0"],
    uniforms: &[],
};

/// LearnOpenGL, Light casters: directional light.
pub const DIRECTIONAL: ShaderModel = ShaderModel {
    name: "directional",
    source: "LearnOpenGL, Lighting > Light casters, directional light",
    functions: include_str!("shaders/directional.glsl"),
    harness: include_str!("shaders/directional.harness.glsl"),
    inputs: &[
        MAPPED_SURFACE[0],
        MAPPED_SURFACE[1],
        MAPPED_SURFACE[2],
        MAPPED_SURFACE[3],
        MAPPED_SURFACE[4],
        "light.direction.xyz (from the light), -",
        "light.ambient.rgb, -",
        "light.diffuse.rgb, -",
        "light.specular.rgb, -",
    ],
    outputs: &["result.rgb, 1", "diff, spec, 0, 0"],
    uniforms: &[],
};

/// LearnOpenGL, Light casters: point light with attenuation.
pub const POINT: ShaderModel = ShaderModel {
    name: "point",
    source: "LearnOpenGL, Lighting > Light casters, point lights, attenuation",
    functions: include_str!("shaders/point.glsl"),
    harness: include_str!("shaders/point.harness.glsl"),
    inputs: &[
        MAPPED_SURFACE[0],
        MAPPED_SURFACE[1],
        MAPPED_SURFACE[2],
        MAPPED_SURFACE[3],
        MAPPED_SURFACE[4],
        "light.position.xyz, -",
        "light.ambient.rgb, -",
        "light.diffuse.rgb, -",
        "light.specular.rgb, -",
        "light.constant, light.linear, light.quadratic, -",
    ],
    outputs: &["result.rgb, 1", "diff, spec, attenuation, 0"],
    uniforms: &[],
};

/// LearnOpenGL, Light casters: spotlight, soft edges (and the first, hard-edged version).
pub const SPOT: ShaderModel = ShaderModel {
    name: "spot",
    source: "LearnOpenGL, Lighting > Light casters, spotlight, flashlight, soft edges",
    functions: include_str!("shaders/spot.glsl"),
    harness: include_str!("shaders/spot.harness.glsl"),
    inputs: &[
        MAPPED_SURFACE[0],
        MAPPED_SURFACE[1],
        MAPPED_SURFACE[2],
        MAPPED_SURFACE[3],
        MAPPED_SURFACE[4],
        "light.position.xyz, light.cutOff (cosine)",
        "light.direction.xyz (from the light), light.outerCutOff (cosine)",
        "light.ambient.rgb, -",
        "light.diffuse.rgb, -",
        "light.specular.rgb, -",
        "light.constant, light.linear, light.quadratic, -",
    ],
    outputs: &["soft-edged result.rgb, 1", "hard-cutoff result.rgb, theta"],
    uniforms: &[],
};

/// cos(12.5 deg), the flashlight's inner cut-off in LearnOpenGL (glm::cos(glm::radians(12.5f))).
const COS_12_5_DEG: f32 = 0.976_296;
/// cos(15 deg), the flashlight's outer cut-off in the Multiple lights chapter.
const COS_15_DEG: f32 = 0.965_925_8;
const POINT_LIGHT_AMBIENT: Uniform = Uniform::Vec3([0.05, 0.05, 0.05]);
const POINT_LIGHT_DIFFUSE: Uniform = Uniform::Vec3([0.8, 0.8, 0.8]);
const WHITE: Uniform = Uniform::Vec3([1.0, 1.0, 1.0]);

macro_rules! point_light_uniforms {
    ($i:literal, $x:expr, $y:expr, $z:expr) => {
        [
            (concat!("pointLights[", $i, "].position"), Uniform::Vec3([$x, $y, $z])),
            (concat!("pointLights[", $i, "].constant"), Uniform::Float(1.0)),
            (concat!("pointLights[", $i, "].linear"), Uniform::Float(0.09)),
            (concat!("pointLights[", $i, "].quadratic"), Uniform::Float(0.032)),
            (concat!("pointLights[", $i, "].ambient"), POINT_LIGHT_AMBIENT),
            (concat!("pointLights[", $i, "].diffuse"), POINT_LIGHT_DIFFUSE),
            (concat!("pointLights[", $i, "].specular"), WHITE),
        ]
    };
}

const P0: [(&str, Uniform); 7] = point_light_uniforms!("0", 0.7, 0.2, 2.0);
const P1: [(&str, Uniform); 7] = point_light_uniforms!("1", 2.3, -3.3, -4.0);
const P2: [(&str, Uniform); 7] = point_light_uniforms!("2", -4.0, 2.0, -12.0);
const P3: [(&str, Uniform); 7] = point_light_uniforms!("3", 0.0, 0.0, -3.0);

/// The scene of the Multiple lights chapter (the `quad-multi` scene of the design): one
/// directional light, four point lights with attenuation (1, 0.09, 0.032), and a flashlight
/// at the camera (0, 0, 3) pointing down -z with cut-offs 12.5 and 15 degrees.
pub const MULTIPLE_LIGHTS_SCENE: &[(&str, Uniform)] = &[
    ("dirLight.direction", Uniform::Vec3([-0.2, -1.0, -0.3])),
    ("dirLight.ambient", Uniform::Vec3([0.05, 0.05, 0.05])),
    ("dirLight.diffuse", Uniform::Vec3([0.4, 0.4, 0.4])),
    ("dirLight.specular", Uniform::Vec3([0.5, 0.5, 0.5])),
    P0[0],
    P0[1],
    P0[2],
    P0[3],
    P0[4],
    P0[5],
    P0[6],
    P1[0],
    P1[1],
    P1[2],
    P1[3],
    P1[4],
    P1[5],
    P1[6],
    P2[0],
    P2[1],
    P2[2],
    P2[3],
    P2[4],
    P2[5],
    P2[6],
    P3[0],
    P3[1],
    P3[2],
    P3[3],
    P3[4],
    P3[5],
    P3[6],
    ("spotLight.position", Uniform::Vec3([0.0, 0.0, 3.0])),
    ("spotLight.direction", Uniform::Vec3([0.0, 0.0, -1.0])),
    ("spotLight.cutOff", Uniform::Float(COS_12_5_DEG)),
    ("spotLight.outerCutOff", Uniform::Float(COS_15_DEG)),
    ("spotLight.constant", Uniform::Float(1.0)),
    ("spotLight.linear", Uniform::Float(0.09)),
    ("spotLight.quadratic", Uniform::Float(0.032)),
    ("spotLight.ambient", Uniform::Vec3([0.0, 0.0, 0.0])),
    ("spotLight.diffuse", WHITE),
    ("spotLight.specular", WHITE),
];

/// LearnOpenGL, Multiple lights: directional + 4 point lights + flashlight, lights as uniforms.
pub const MULTIPLE_LIGHTS: ShaderModel = ShaderModel {
    name: "multiple_lights",
    source: "LearnOpenGL, Lighting > Multiple lights",
    functions: include_str!("shaders/multiple_lights.glsl"),
    harness: include_str!("shaders/multiple_lights.harness.glsl"),
    inputs: &MAPPED_SURFACE,
    outputs: &["all lights rgb, 1", "without the spotlight rgb, 1"],
    uniforms: MULTIPLE_LIGHTS_SCENE,
};

/// opengl-tutorial.org tutorial 8: inverse-square point light, camera-space vectors.
pub const OPENGL_TUTORIAL8: ShaderModel = ShaderModel {
    name: "opengl_tutorial8",
    source: "opengl-tutorial.org, tutorial 8: Basic shading",
    functions: include_str!("shaders/opengl_tutorial8.glsl"),
    harness: include_str!("shaders/opengl_tutorial8.harness.glsl"),
    inputs: &[
        "Position_worldspace.xyz, LightPower",
        "Normal_cameraspace.xyz, specular exponent",
        "EyeDirection_cameraspace.xyz, -",
        "LightDirection_cameraspace.xyz, -",
        "LightPosition_worldspace.xyz, -",
        "MaterialDiffuseColor.rgb, -",
        "MaterialSpecularColor.rgb, -",
        "LightColor.rgb, -",
        "ambient factor rgb, -",
    ],
    outputs: &["color.rgb, 1", "cosTheta, cosAlpha, distance, 0"],
    uniforms: &[],
};

/// ogldev tutorial 19: directional light with specular intensity and power.
pub const OGLDEV19: ShaderModel = ShaderModel {
    name: "ogldev19",
    source: "ogldev tutorial 19: Specular lighting",
    functions: include_str!("shaders/ogldev19.glsl"),
    harness: include_str!("shaders/ogldev19.harness.glsl"),
    inputs: &[
        "WorldPos0.xyz, gSpecularPower",
        "Normal0.xyz, gMatSpecularIntensity",
        "gEyeWorldPos.xyz, -",
        "gDirectionalLight.Color.rgb, gDirectionalLight.AmbientIntensity",
        "gDirectionalLight.Direction.xyz (from the light), gDirectionalLight.DiffuseIntensity",
        "sampled texel rgba",
    ],
    outputs: &["FragColor rgba", "DiffuseFactor, SpecularFactor, 0, 0"],
    uniforms: &[],
};

/// Every model, in chapter order.
pub const MODELS: &[ShaderModel] = &[
    BASIC_LIGHTING,
    GOURAUD,
    MATERIALS,
    LIGHTING_MAPS,
    DIRECTIONAL,
    POINT,
    SPOT,
    MULTIPLE_LIGHTS,
    OPENGL_TUTORIAL8,
    OGLDEV19,
];

/// Complete fragment shaders as a user would write them, for `lightlab check-shader`:
/// `(file name, source)`. `basic_lighting.frag`, `normal_matrix.frag` and
/// `renamed_uniforms.frag` (with `renamed_uniforms.toml`) are correct; the `bug_*` files and
/// `ot8_printed_semicolon.frag` each carry one documented mistake (see their header).
pub const EXAMPLE_SHADERS: &[(&str, &str)] = &[
    ("basic_lighting.frag", include_str!("shaders/examples/basic_lighting.frag")),
    ("bug_reflect_sign.frag", include_str!("shaders/examples/bug_reflect_sign.frag")),
    ("bug_unnormalized_normal.frag", include_str!("shaders/examples/bug_unnormalized_normal.frag")),
    ("bug_spot_degrees.frag", include_str!("shaders/examples/bug_spot_degrees.frag")),
    ("ot8_printed_semicolon.frag", include_str!("shaders/examples/ot8_printed_semicolon.frag")),
    ("normal_matrix.frag", include_str!("shaders/examples/normal_matrix.frag")),
    ("bug_model_matrix_normal.frag", include_str!("shaders/examples/bug_model_matrix_normal.frag")),
    ("renamed_uniforms.frag", include_str!("shaders/examples/renamed_uniforms.frag")),
];
