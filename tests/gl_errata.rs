//! The errata table's listings on OpenGL (Mesa llvmpipe): each listing the table flags as
//! not compiling fails to compile as printed, and its counterpart in the other text (or
//! the one-word fix) compiles; the two listings that compile but compute something else
//! than their text says are run.
//!
//! Every shader is the printed excerpt from `lightlab::errata::listings` inside the
//! smallest harness that declares what the chapter declared before it.
//!
//! Without OpenGL the tests print why and pass, unless `LIGHTLAB_REQUIRE_GL=1`.
#![cfg(feature = "gl")]

use crate::gl_common;

use gl_common::context_or_skip;
use glam::Vec3;
use lightlab::errata::listings;
use lightlab::gl::batch::compile_fragment;
use lightlab::gl::{Batch, GlContext, GlError};

/// The driver's log when `source` does not compile, `None` when it does.
fn compile_log(ctx: &GlContext, source: &str) -> Option<String> {
    match compile_fragment(ctx, source) {
        Ok(()) => None,
        Err(GlError::Compile { log, .. }) => Some(log),
        Err(other) => panic!("unexpected error (not a compile error): {other}"),
    }
}

/// Asserts that `bad` fails with a log mentioning `needle` and that `good` compiles.
fn fails_and_fix_compiles(ctx: &GlContext, what: &str, bad: &str, needle: &str, good: &str) {
    let log = compile_log(ctx, bad).unwrap_or_else(|| panic!("{what}: the printed listing compiled:\n{bad}"));
    println!("{what}: {}", log.trim());
    assert!(log.contains(needle), "{what}: the log does not name {needle:?}: {log}");
    if let Some(log) = compile_log(ctx, good) {
        panic!("{what}: the counterpart does not compile: {log}\n{good}");
    }
}

/// The flashlight fragment shader around a cone-test listing.
fn spot_shader(light_struct: &str, test: &str, declare_color: bool) -> String {
    let light_struct = light_struct.replace("};", "    vec3 ambient;\n};");
    let (decl, write) = if declare_color { ("vec4 color = vec4(0.0);", "FragColor = color;") } else { ("", "") };
    format!(
        "#version 330 core\nout vec4 FragColor;\nin vec2 TexCoords;\nin vec3 FragPos;\n\
         struct Material {{ sampler2D diffuse; sampler2D specular; float shininess; }};\nuniform Material material;\n\
         {light_struct}\nuniform Light light;\nvoid main()\n{{\n    vec3 lightDir = normalize(light.position - FragPos);\n\
         {decl}\n{test}\n{write}\n}}\n"
    )
}

#[test]
fn cutoff_spelled_cutoff_does_not_compile() {
    let Some(ctx) = context_or_skip() else { return };
    // `color` declared here so that only the field name is in question.
    let fr = spot_shader(listings::FR_SPOT_STRUCT, listings::FR_SPOT_TEST, true);
    let uk = spot_shader(listings::FR_SPOT_STRUCT, listings::UK_SPOT_TEST, true);
    fails_and_fix_compiles(&ctx, "spot-cutoff-name-fr", &fr, "cutoff", &uk);
}

#[test]
fn spot_else_branch_writes_an_undeclared_color() {
    let Some(ctx) = context_or_skip() else { return };
    // The chapter's shader declares `out vec4 FragColor` and no `color`.
    let printed = spot_shader(listings::FR_SPOT_STRUCT, listings::UK_SPOT_TEST, false);
    let fixed = printed.replace("\ncolor = vec4(", "\nFragColor = vec4(");
    fails_and_fix_compiles(&ctx, "spot-else-writes-color", &printed, "color", &fixed);
}

#[test]
fn output_is_a_reserved_word() {
    let Some(ctx) = context_or_skip() else { return };
    let functions = "#version 330 core\nconst int nr_of_point_lights = 4;\n\
        vec3 someFunctionToCalculateDirectionalLight() { return vec3(0.1); }\n\
        vec3 someFunctionToCalculatePointLight() { return vec3(0.2); }\n\
        vec3 someFunctionToCalculateSpotLight() { return vec3(0.3); }\n";
    let printed = format!("{functions}{}", listings::OUTPUT_SKELETON);
    let renamed = printed.replace("output", "result");
    fails_and_fix_compiles(&ctx, "output-reserved-word", &printed, "output", &renamed);
}

#[test]
fn french_listing_labels_do_not_compile() {
    let Some(ctx) = context_or_skip() else { return };
    let main = "vec3 CalcDirLight(DirLight light, vec3 normal, vec3 viewDir) { return light.ambient; }\n\
        void main() { FragColor = vec4(CalcDirLight(dirLight, vec3(0.0, 1.0, 0.0), vec3(0.0, 0.0, 1.0)), 1.0); }\n";
    let head = "#version 330 core\nout vec4 FragColor;\n";
    let fr = format!("{head}{}\n{}\n{main}", listings::FR_DIRLIGHT, listings::FR_DIRLIGHT_PROTOTYPE);
    let uk = format!("{head}{}\n{main}", listings::UK_DIRLIGHT);
    // Mesa names the line of the label: `0:LINE(COLUMN): error: syntax error`.
    let line = fr.lines().position(|l| l.trim() == "c17_1_1").unwrap() + 1;
    fails_and_fix_compiles(&ctx, "listing-labels-fr", &fr, &format!("0:{line}("), &uk);
}

#[test]
fn ukrainian_light_struct_lacks_its_semicolon() {
    let Some(ctx) = context_or_skip() else { return };
    let shader = |s: &str| {
        format!(
            "#version 330 core\nout vec4 FragColor;\n{s}\nuniform Light light;\n\
             void main() {{ FragColor = vec4(light.ambient * light.constant, 1.0); }}\n"
        )
    };
    let log = compile_log(&ctx, &shader(listings::UK_POINT_STRUCT)).expect("003 l.1495-1527 must not compile");
    println!("light-struct-semicolon-uk: {}", log.trim());
    assert!(log.contains("error"), "{log}");
    assert_eq!(compile_log(&ctx, &shader(listings::FR_POINT_STRUCT)), None, "000 l.990-998 compiles");
}

/// The C++ initializer as a GLSL 4.20 initializer list (same braces and commas), plus a
/// declaration whose size is `length() − 3`: positive only for four elements.
fn positions_as_glsl(listing: &str) -> String {
    let body = listing.replace("glm::vec3", "vec3");
    format!(
        "#version 420 core\nout vec4 FragColor;\nconst {body}\n\
         uniform float lightlab_four[pointLightPositions.length() - 3];\n\
         void main() {{ FragColor = vec4(pointLightPositions[1] * lightlab_four[0], 1.0); }}\n"
    )
}

#[test]
fn french_point_light_positions_break_the_initializer() {
    let Some(ctx) = context_or_skip() else { return };
    let fr = positions_as_glsl(listings::FR_POINT_LIGHT_POSITIONS);
    let uk = positions_as_glsl(listings::UK_POINT_LIGHT_POSITIONS);
    let log = compile_log(&ctx, &fr).expect("000 l.1357-1368 must not compile");
    println!("point-light-positions-fr: {}", log.trim());
    assert_eq!(compile_log(&ctx, &uk), None, "003 l.2184-2204 compiles with four elements");
    // The French first block alone is a valid initializer, of two elements: the size check fails.
    let first_block = &listings::FR_POINT_LIGHT_POSITIONS[..listings::FR_POINT_LIGHT_POSITIONS.find("};").unwrap() + 2];
    let log = compile_log(&ctx, &positions_as_glsl(first_block)).expect("two elements fail the length check");
    println!("first block alone: {}", log.trim());
}

#[test]
fn opengl_tutorial_listing_drops_the_specular() {
    let Some(ctx) = context_or_skip() else { return };
    let body = format!(
        "void batch_main(in vec4 v[LIGHTLAB_N_INPUTS], out vec4 o[LIGHTLAB_N_OUTPUTS])\n{{\n\
         vec3 MaterialDiffuseColor = vec3(1.0, 0.5, 0.31);\n\
         vec3 MaterialAmbientColor = vec3(0.1,0.1,0.1) * MaterialDiffuseColor;\n\
         vec3 MaterialSpecularColor = vec3(0.3);\nvec3 LightColor = vec3(1.0);\nfloat LightPower = 50.0;\n\
         float cosTheta = v[0].x;\nfloat cosAlpha = v[0].y;\nfloat distance = v[0].z;\nvec3 color;\n{}\n\
         o[0] = vec4(color, 1.0);\n}}\n",
        listings::OPENGL_TUTORIAL_COLOR
    );
    // The listing compiles: the dropped term is a statement without effect, not an error.
    let batch = Batch::new(&ctx, &body, 1, 1).expect("001 l.294-300 compiles");
    // Light on the normal at distance 2, eye on the mirror ray: cosTheta = cosAlpha = 1.
    let model = lightlab::models::OpenGLTutorial::with_defaults(Vec3::new(0.0, 0.0, 2.0), Vec3::new(1.0, 0.5, 0.31));
    let terms = model.terms(Vec3::ZERO, Vec3::Z, Vec3::new(0.0, 0.0, 5.0));
    let out = batch.run(&[vec![[1.0, 1.0, 2.0, 0.0]]]).unwrap();
    let got = Vec3::new(out[0][0][0], out[0][0][1], out[0][0][2]);
    let without = terms.ambient + terms.diffuse;
    println!("specular-statement: GL {got:?}, ambient + diffuse {without:?}, specular {:?}", terms.specular);
    // Tolerance: a handful of f32 operations on values below 13: 1e-5 absolute is ~100 ulps.
    assert!((got - without).abs().max_element() < 1e-5, "expected {without:?}, got {got:?}");
    assert!(terms.specular.x > 1.0, "the dropped term is large here: {:?}", terms.specular);
}

#[test]
fn ogldev_pow_of_a_negative_base() {
    let Some(ctx) = context_or_skip() else { return };
    let body = format!(
        "struct DirectionalLight {{ vec3 Color; vec3 Direction; }};\n\
         void batch_main(in vec4 v[LIGHTLAB_N_INPUTS], out vec4 o[LIGHTLAB_N_OUTPUTS])\n{{\n\
         DirectionalLight gDirectionalLight = DirectionalLight(vec3(1.0), vec3(0.0, -1.0, 0.0));\n\
         vec3 gEyeWorldPos = v[0].xyz;\nvec3 WorldPos0 = vec3(0.0);\nvec3 Normal = vec3(0.0, 1.0, 0.0);\n\
         float gMatSpecularIntensity = 1.0;\nfloat gSpecularPower = v[0].w;\nvec4 SpecularColor = vec4(0.0);\n{}\n\
         o[0] = SpecularColor;\n}}\n",
        listings::OGLDEV_SPECULAR
    );
    let batch = Batch::new(&ctx, &body, 1, 1).expect("002 l.202-208 compiles");
    // The eye 120° from the mirror ray (straight up): dot(VertexToEye, LightReflect) = −0.5.
    let eye = [3f32.sqrt() / 2.0, -0.5, 0.0, 32.0];
    let out = batch.run(&[vec![eye]]).unwrap();
    let ghost = lightlab::models::ogldev_specular_c_powf(-0.5, 32.0);
    println!("pow-before-test: llvmpipe specular {:?}; a C powf would give {ghost:e}", out[0][0]);
    // The code's answer rests on pow's undefined case: llvmpipe's exp2(y·log2 x) is NaN and
    // the test drops it, C's powf is 2^-32 and the test keeps it.
    assert_eq!(out[0][0][0], 0.0);
    assert!(ghost > 0.0);
}

#[test]
fn opaque_struct_as_function_parameter() {
    let Some(ctx) = context_or_skip() else { return };
    let head = "#version 330 core\nout vec4 FragColor;\nin vec2 TexCoords;\n\
        struct Material { sampler2D diffuse; vec3 specular; float shininess; };\nuniform Material material;\n";
    let parameter = format!(
        "{head}vec3 diffuseOf(Material m) {{ return texture(m.diffuse, TexCoords).rgb; }}\n\
         void main() {{ FragColor = vec4(diffuseOf(material), 1.0); }}\n"
    );
    let local = format!("{head}void main() {{ Material m = material; FragColor = vec4(m.specular, 1.0); }}\n");
    // GLSL 3.30 §4.1.7: opaque types may be function parameters or uniforms, nothing else.
    assert_eq!(compile_log(&ctx, &parameter), None, "a Material parameter compiles");
    let log = compile_log(&ctx, &local).expect("a local Material does not compile");
    println!("opaque-struct-parameter: a local copy fails: {}", log.trim());
    assert!(log.contains("opaque") || log.contains("sampler"), "{log}");
}
