//! The live figures' GLSL ES 3.00 programs, made from the verified function files.
//!
//! Each program is `header + function file + main`. The function file is the text of
//! `src/gl/shaders/<model>.glsl`, the one `lightlab oracle` checks on llvmpipe, included
//! byte for byte; [`to_es`] only puts the ES header in front (`#version 300 es` and
//! `highp` precision, because GLSL ES has no default float precision in the fragment
//! stage) and refuses text that would not compile as ES (a `#version` line of its own).
//! The mains below are the per-figure glue: they read the varyings and uniforms and call
//! the function, as the chapters' `main` does.
//!
//! | program | vertex stage | fragment function |
//! | --- | --- | --- |
//! | `basic` | world space | `basic_lighting` |
//! | `basic_view` | view space (`viewPos = 0`, `lightPos` moved by `view`) | `basic_lighting` |
//! | `blinn` | world space | `basic_lighting` with its `reflect` lobe swapped for the halfway lobe ([`blinn_functions`]) |
//! | `basic_model_normal` | normals through `mat3(model)` (the mistake) | `basic_lighting` |
//! | `gouraud` | `gouraud_vertex` per vertex | `gouraud_fragment` |
//! | `materials` | world space | `materials_lighting` |
//! | `maps` | world space, uv | `lighting_maps` + emission |
//! | `directional`, `point`, `spot` | world space, uv | `directional_light`, `point_light`, `spot_light` |
//! | `multiple` | world space, uv | `multiple_lights` |
//! | `opengl_tutorial8` | `ot8_vertex` (camera-space vectors, from the same file) | `ot8_shade` |
//! | `ogldev19` | ogldev 19's (`WorldPos0`, `Normal0` through `model`) | `ogldev19_shade`, the texel a constant color |
//! | `lamp` | world space | none: a flat `lampColor` |

/// A vertex and fragment shader pair, plus where the editable function text sits.
#[derive(Clone, Debug)]
pub struct Program {
    /// Name used by the figures' draws.
    pub name: &'static str,
    /// GLSL ES 3.00 vertex shader.
    pub vertex: String,
    /// GLSL ES 3.00 fragment shader.
    pub fragment: String,
    /// The model whose function file is in the fragment shader (`None` for none).
    pub model: Option<ModelId>,
    /// The fragment shader's header (lines before the function text).
    pub fragment_header: String,
    /// The fragment shader's main (lines after the function text).
    pub fragment_main: String,
}

use super::LiveError;
use crate::gl::ModelId;

/// The verified function file of `model` (the `src/gl/shaders/<model>.glsl` text the
/// oracle runs, [`crate::gl::models::ShaderModel::functions`]), or an error naming it.
pub fn function_file(model: ModelId) -> Result<&'static str, LiveError> {
    model.shader().map(|m| m.functions()).ok_or_else(|| LiveError::NoFunctionFile(model.name().to_owned()))
}

/// The ES header every live shader starts with.
pub const ES_HEADER: &str = "#version 300 es\nprecision highp float;\nprecision highp int;\n";

/// A desktop function file as GLSL ES 3.00 text: [`ES_HEADER`] then the file.
///
/// The function files use only what GLSL 3.30 core and GLSL ES 3.00 share (no
/// `#version`, no `texture2D`, no default precision assumed), so the conversion is the
/// header; anything that breaks that rule is an error naming the line, so that the
/// book build fails rather than the page.
pub fn to_es(functions: &str) -> Result<String, LiveError> {
    for (i, line) in functions.lines().enumerate() {
        let t = line.trim_start();
        for bad in ["#version", "texture2D", "gl_FragColor", "precision "] {
            if t.starts_with(bad) || (bad != "#version" && bad != "precision " && t.contains(bad)) {
                return Err(LiveError::NotEs { line: i + 1, token: bad.to_string() });
            }
        }
    }
    Ok(format!("{ES_HEADER}{functions}"))
}

/// The Basic lighting function with Blinn's halfway lobe in place of Phong's `reflect`
/// lobe, made from the verified file by replacing its two specular lines (and failing
/// when those lines are not found, so the swap cannot go stale silently).
///
/// ```text
/// reflectDir = reflect(-lightDir, norm); spec = pow(max(dot(viewDir, reflectDir), 0), s)
///   becomes
/// halfwayDir = normalize(lightDir + viewDir); spec = pow(max(dot(norm, halfwayDir), 0), s)
/// ```
///
/// Source: Blinn 1977; LearnOpenGL, Advanced lighting.
pub fn blinn_functions() -> Result<String, LiveError> {
    let text = function_file(ModelId::BasicLighting)?;
    let from =
        ["vec3 reflectDir = reflect(-lightDir, norm);", "spec = pow(max(dot(viewDir, reflectDir), 0.0), shininess);"];
    let to =
        ["vec3 halfwayDir = normalize(lightDir + viewDir);", "spec = pow(max(dot(norm, halfwayDir), 0.0), shininess);"];
    let mut out = text.to_owned();
    for (f, t) in from.iter().zip(to) {
        if !out.contains(f) {
            return Err(LiveError::BlinnSwap(f.to_string()));
        }
        out = out.replace(f, t);
    }
    Ok(out)
}

const VS_WORLD: &str = "layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aTexCoords;
uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
out vec3 FragPos;
out vec3 Normal;
out vec2 TexCoords;
void main()
{
    FragPos = vec3(model * vec4(aPos, 1.0));
    Normal = mat3(transpose(inverse(model))) * aNormal;
    TexCoords = aTexCoords;
    gl_Position = projection * view * vec4(FragPos, 1.0);
}
";

/// The start of the untextured vertex shaders: position and normal in, the three
/// matrices, `FragPos` and `Normal` out, and `main`'s opening brace (a macro, so that
/// `concat!` can take it).
macro_rules! vs_untextured_head {
    () => {
        "layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aNormal;
uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
out vec3 FragPos;
out vec3 Normal;
void main()
{
"
    };
}

const VS_MODEL_NORMAL: &str = concat!(
    vs_untextured_head!(),
    "    FragPos = vec3(model * vec4(aPos, 1.0));
    Normal = mat3(model) * aNormal; // the mistake: no normal matrix
    gl_Position = projection * view * vec4(FragPos, 1.0);
}
"
);

const VS_VIEW: &str = concat!(
    vs_untextured_head!(),
    "    mat4 modelView = view * model;
    FragPos = vec3(modelView * vec4(aPos, 1.0));
    Normal = mat3(transpose(inverse(modelView))) * aNormal;
    gl_Position = projection * vec4(FragPos, 1.0);
}
"
);

const FS_IN: &str = "in vec3 FragPos;\nin vec3 Normal;\nin vec2 TexCoords;\nout vec4 FragColor;\n";

const BASIC_UNIFORMS: &str = crate::checker::complete::basic_lighting_uniforms!();

const MAIN_BASIC: &str = "void main()
{
    float diff, spec;
    vec3 result = basic_lighting(FragPos, Normal, lightPos, viewPos, lightColor, objectColor,
                                 ambientStrength, specularStrength, shininess, diff, spec);
    FragColor = vec4(result, 1.0);
}
";

const MAIN_BASIC_VIEW: &str = "uniform mat4 view;
void main()
{
    // view space: the eye sits at the origin, the light moves with the view matrix
    vec3 lightPosView = vec3(view * vec4(lightPos, 1.0));
    float diff, spec;
    vec3 result = basic_lighting(FragPos, Normal, lightPosView, vec3(0.0), lightColor, objectColor,
                                 ambientStrength, specularStrength, shininess, diff, spec);
    FragColor = vec4(result, 1.0);
}
";

const MAIN_MATERIALS: &str = "uniform Material material;
uniform Light light;
uniform vec3 viewPos;
void main()
{
    float diff, spec;
    FragColor = vec4(materials_lighting(material, light, FragPos, Normal, viewPos, diff, spec), 1.0);
}
";

/// The texel block shared by the mapped programs: each map can be switched off, and
/// then `<map>Const` (set by the figure) replaces the sample.
const TEXELS: &str = "uniform sampler2D diffuseMap;
uniform sampler2D specularMap;
uniform sampler2D emissionMap;
uniform bool useDiffuseMap;
uniform bool useSpecularMap;
uniform bool useEmissionMap;
uniform vec3 diffuseConst;
uniform vec3 specularConst;
uniform float shininess;
uniform vec3 viewPos;
vec3 diffuseTexel() { return useDiffuseMap ? texture(diffuseMap, TexCoords).rgb : diffuseConst; }
vec3 specularTexel() { return useSpecularMap ? texture(specularMap, TexCoords).rgb : specularConst; }
vec3 emission() { return useEmissionMap ? texture(emissionMap, TexCoords).rgb : vec3(0.0); }
";

const MAIN_MAPS: &str = "uniform Light light;
void main()
{
    float diff, spec;
    vec3 result = lighting_maps(diffuseTexel(), specularTexel(), shininess, light,
                                FragPos, Normal, viewPos, diff, spec);
    FragColor = vec4(result + emission(), 1.0);
}
";

/// The `main` of a light-caster program: declares the `light` uniform of type
/// `light_struct`, calls `function` with the texels, and returns its `outs` (the
/// function's trailing `out float` parameters) through locals of the same names.
fn caster_main(light_struct: &str, function: &str, outs: &str) -> String {
    let call = format!("    vec3 result = {function}(");
    let indent = " ".repeat(call.len());
    format!(
        "uniform {light_struct} light;
void main()
{{
    float {outs};
{call}light, diffuseTexel(), specularTexel(), shininess,
{indent}FragPos, Normal, viewPos, {outs});
    FragColor = vec4(result + emission(), 1.0);
}}
"
    )
}

const MAIN_MULTIPLE: &str = "void main()
{
    vec3 withoutSpot;
    vec3 result = multiple_lights(FragPos, Normal, viewPos, diffuseTexel(), specularTexel(),
                                  shininess, withoutSpot);
    FragColor = vec4(result + emission(), 1.0);
}
";

const VS_GOURAUD: &str = "layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aNormal;
uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform vec3 lightPos;
uniform vec3 viewPos;
uniform vec3 lightColor;
uniform float ambientStrength;
uniform float specularStrength;
uniform float shininess;
out vec3 LightingColor;
void main()
{
    gl_Position = projection * view * model * vec4(aPos, 1.0);
    LightingColor = gouraud_vertex(aPos, aNormal, model, lightPos, viewPos, lightColor,
                                   ambientStrength, specularStrength, shininess);
}
";

const FS_GOURAUD: &str = "in vec3 LightingColor;
out vec4 FragColor;
uniform vec3 objectColor;
void main()
{
    FragColor = vec4(gouraud_fragment(LightingColor, objectColor), 1.0);
}
";

const FS_LAMP: &str =
    "out vec4 FragColor;\nuniform vec3 lampColor;\nvoid main()\n{\n    FragColor = vec4(lampColor, 1.0);\n}\n";

/// opengl-tutorial 8's vertex stage: its `ot8_vertex` (in the function file, which comes
/// before this text) gives the camera-space vectors the fragment stage receives.
const VS_OT8: &str = "layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aNormal;
uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform vec3 LightPosition_worldspace;
out vec3 Position_worldspace;
out vec3 EyeDirection_cameraspace;
out vec3 LightDirection_cameraspace;
out vec3 Normal_cameraspace;
void main()
{
    vec3 position, eye, light, normal;
    ot8_vertex(aPos, aNormal, model, view, LightPosition_worldspace, position, eye, light, normal);
    Position_worldspace = position;
    EyeDirection_cameraspace = eye;
    LightDirection_cameraspace = light;
    Normal_cameraspace = normal;
    gl_Position = projection * view * model * vec4(aPos, 1.0);
}
";

/// opengl-tutorial 8's fragment inputs and uniforms, as its shader names them: the
/// checker's frame's declarations, with the ES output `FragColor` for the tutorial's
/// `out vec3 color`.
const FS_OT8: &str = crate::checker::complete::opengl_tutorial8_declarations!("out vec4 FragColor;");

const MAIN_OT8: &str = "void main()
{
    float cosTheta, cosAlpha, lightDistance;
    vec3 color = ot8_shade(Position_worldspace, LightPosition_worldspace, Normal_cameraspace,
                           EyeDirection_cameraspace, LightDirection_cameraspace, MaterialDiffuseColor,
                           MaterialSpecularColor, MaterialAmbientFactor, LightColor, LightPower,
                           specularExponent, cosTheta, cosAlpha, lightDistance);
    FragColor = vec4(color, 1.0);
}
";

/// ogldev 19's vertex shader: world position and normal through `gWorld` (here `model`),
/// the normal without a normal matrix, as the tutorial does.
const VS_OGLDEV19: &str = "layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aNormal;
uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
out vec3 Normal0;
out vec3 WorldPos0;
void main()
{
    gl_Position = projection * view * model * vec4(aPos, 1.0);
    Normal0 = (model * vec4(aNormal, 0.0)).xyz;
    WorldPos0 = (model * vec4(aPos, 1.0)).xyz;
}
";

/// ogldev 19's fragment inputs and uniforms; `gTexel` stands for its `texture(gSampler,
/// TexCoord0)`, one color over the whole object.
const FS_OGLDEV19: &str = "in vec3 Normal0;
in vec3 WorldPos0;
out vec4 FragColor;
uniform vec3 gEyeWorldPos;
uniform float gMatSpecularIntensity;
uniform float gSpecularPower;
uniform vec4 gTexel;
";

const MAIN_OGLDEV19: &str = "uniform DirectionalLight gDirectionalLight;
void main()
{
    float DiffuseFactor, SpecularFactor;
    vec4 color = ogldev19_shade(gDirectionalLight, WorldPos0, Normal0, gEyeWorldPos,
                                gMatSpecularIntensity, gSpecularPower, gTexel,
                                DiffuseFactor, SpecularFactor);
    FragColor = vec4(color.rgb, 1.0);
}
";

fn lit(
    name: &'static str,
    model: Option<ModelId>,
    vs: &str,
    functions: &str,
    pre: &str,
    main: &str,
) -> Result<Program, LiveError> {
    lit_with_inputs(name, model, vs, FS_IN, functions, pre, main)
}

/// A program whose fragment shader is `ES header + fs_in + pre + functions + main`.
fn lit_with_inputs(
    name: &'static str,
    model: Option<ModelId>,
    vs: &str,
    fs_in: &str,
    functions: &str,
    pre: &str,
    main: &str,
) -> Result<Program, LiveError> {
    let header = format!("{ES_HEADER}{fs_in}{pre}");
    let es = to_es(functions)?;
    let body = &es[ES_HEADER.len()..];
    Ok(Program {
        name,
        vertex: format!("{ES_HEADER}{vs}"),
        fragment: format!("{header}{body}\n{main}"),
        model,
        fragment_header: header,
        fragment_main: format!("\n{main}"),
    })
}

/// A program with no function file in its fragment shader (no model, no header or main
/// to split off): [`ES_HEADER`] then each shader's text.
fn without_model(name: &'static str, vs: &str, fs: &str) -> Program {
    Program {
        name,
        vertex: format!("{ES_HEADER}{vs}"),
        fragment: format!("{ES_HEADER}{fs}"),
        model: None,
        fragment_header: String::new(),
        fragment_main: String::new(),
    }
}

/// Every live program (see the module table).
pub fn programs() -> Result<Vec<Program>, LiveError> {
    let basic = function_file(ModelId::BasicLighting)?;
    let gouraud = to_es(function_file(ModelId::Gouraud)?)?;
    let gouraud_body = &gouraud[ES_HEADER.len()..];
    let (basic_model, materials) = (Some(ModelId::BasicLighting), Some(ModelId::Materials));
    let mut all = vec![
        lit("basic", basic_model, VS_WORLD, basic, BASIC_UNIFORMS, MAIN_BASIC)?,
        lit("basic_view", basic_model, VS_VIEW, basic, BASIC_UNIFORMS, MAIN_BASIC_VIEW)?,
        lit("blinn", None, VS_WORLD, &blinn_functions()?, BASIC_UNIFORMS, MAIN_BASIC)?,
        lit("basic_model_normal", None, VS_MODEL_NORMAL, basic, BASIC_UNIFORMS, MAIN_BASIC)?,
        lit("materials", materials, VS_WORLD, function_file(ModelId::Materials)?, "", MAIN_MATERIALS)?,
    ];
    // the mapped programs declare their light struct in the function file, so the texel
    // block (which does not use it) can come before
    for (name, model, main) in [
        ("maps", ModelId::LightingMaps, MAIN_MAPS.to_owned()),
        ("directional", ModelId::Directional, caster_main("DirectionalLight", "directional_light", "diff, spec")),
        ("point", ModelId::Point, caster_main("PointLight", "point_light", "diff, spec, attenuation")),
        ("spot", ModelId::Spot, caster_main("SpotLight", "spot_light", "theta, intensity, attenuation")),
        ("multiple", ModelId::MultipleLights, MAIN_MULTIPLE.to_owned()),
    ] {
        all.push(lit(name, Some(model), VS_WORLD, function_file(model)?, TEXELS, &main)?);
    }
    let ot8 = function_file(ModelId::OpenGLTutorial8)?;
    let ot8_es = to_es(ot8)?;
    let mut ot8_program =
        lit_with_inputs("opengl_tutorial8", Some(ModelId::OpenGLTutorial8), "", FS_OT8, ot8, "", MAIN_OT8)?;
    ot8_program.vertex = format!("{ot8_es}\n{VS_OT8}");
    all.push(ot8_program);
    let ogldev = function_file(ModelId::Ogldev19)?;
    all.push(lit_with_inputs(
        "ogldev19",
        Some(ModelId::Ogldev19),
        VS_OGLDEV19,
        FS_OGLDEV19,
        ogldev,
        "",
        MAIN_OGLDEV19,
    )?);
    all.push(without_model(
        "gouraud",
        &format!("{gouraud_body}\n{VS_GOURAUD}"),
        &format!("{gouraud_body}\n{FS_GOURAUD}"),
    ));
    all.push(without_model("lamp", VS_WORLD, FS_LAMP));
    Ok(all)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_program_contains_its_function_file_verbatim() {
        for p in programs().unwrap() {
            if let Some(model) = p.model {
                assert!(p.fragment.contains(function_file(model).unwrap()), "{}", p.name);
                assert!(p.fragment.starts_with(&p.fragment_header) && p.fragment.ends_with(&p.fragment_main));
            }
            assert!(p.vertex.starts_with(ES_HEADER) && p.fragment.starts_with(ES_HEADER), "{}", p.name);
        }
    }

    #[test]
    fn opengl_tutorial8_runs_its_own_vertex_function_too() {
        let all = programs().unwrap();
        let ot8 = all.iter().find(|p| p.name == "opengl_tutorial8").unwrap();
        let file = function_file(ModelId::OpenGLTutorial8).unwrap();
        assert!(
            file.contains("void ot8_vertex(") && ot8.vertex.contains(file) && ot8.vertex.contains("ot8_vertex(aPos")
        );
    }

    #[test]
    fn es_conversion_rejects_desktop_only_text() {
        assert!(matches!(to_es("#version 330 core\nvoid f(){}"), Err(LiveError::NotEs { line: 1, .. })));
        assert!(matches!(to_es("void f(){}\nvec4 c = texture2D(s, uv);"), Err(LiveError::NotEs { line: 2, .. })));
        assert!(to_es("vec3 f(vec3 a) { return a; }").is_ok());
    }

    #[test]
    fn blinn_swap_changes_exactly_the_lobe() {
        let b = blinn_functions().unwrap();
        assert!(b.contains("halfwayDir") && !b.contains("reflect(-lightDir"));
    }
}
