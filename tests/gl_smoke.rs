//! Smoke test of the OpenGL back end on Mesa llvmpipe: context, batch, basic lighting,
//! compile errors, and what the driver returns on GLSL's undefined inputs.
//!
//! Without OpenGL the tests print why and pass, unless `LIGHTLAB_REQUIRE_GL=1`.
#![cfg(feature = "gl")]

use lightlab::gl::{models, Batch, GlContext, GlError};

/// The context, or `None` (with the reason printed) when GL is missing and not required.
fn context() -> Option<GlContext> {
    let start = std::time::Instant::now();
    match GlContext::new() {
        Ok(ctx) => {
            let ms = start.elapsed().as_secs_f64() * 1e3;
            println!("context created in {ms:.1} ms");
            println!("GL_RENDERER = {}", ctx.info().renderer);
            println!("GL_VERSION = {}", ctx.info().version);
            Some(ctx)
        }
        Err(e) if std::env::var("LIGHTLAB_REQUIRE_GL").as_deref() == Ok("1") => {
            panic!("LIGHTLAB_REQUIRE_GL=1 but no OpenGL context: {e}")
        }
        Err(e) => {
            println!("skipped: no OpenGL context: {e}");
            None
        }
    }
}

/// One basic-lighting case in f64.
struct Case {
    frag_pos: [f64; 3],
    normal: [f64; 3],
    light_pos: [f64; 3],
    view_pos: [f64; 3],
    light_color: [f64; 3],
    object_color: [f64; 3],
    ambient: f64,
    specular: f64,
    shininess: f64,
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn unit(a: [f64; 3]) -> [f64; 3] {
    let l = dot(a, a).sqrt();
    [a[0] / l, a[1] / l, a[2] / l]
}
fn f32x4(a: [f64; 3], w: f64) -> [f32; 4] {
    [a[0] as f32, a[1] as f32, a[2] as f32, w as f32]
}

impl Case {
    /// (result rgb, diff, spec), the chapter's formulas written out in f64. The reflection
    /// is formed with the angle identity dot(view, reflect(-l, n)) = 2 (n.l)(n.v) - l.v.
    fn expected(&self) -> ([f64; 3], f64, f64) {
        let n = unit(self.normal);
        let l = unit(sub(self.light_pos, self.frag_pos));
        let v = unit(sub(self.view_pos, self.frag_pos));
        let diff = dot(n, l).max(0.0);
        let r_dot_v = 2.0 * dot(n, l) * dot(n, v) - dot(l, v);
        let spec = r_dot_v.max(0.0).powf(self.shininess);
        let k = self.ambient + diff + self.specular * spec;
        let rgb = [0, 1, 2].map(|i| k * self.light_color[i] * self.object_color[i]);
        (rgb, diff, spec)
    }

    fn inputs(&self) -> [[f32; 4]; 6] {
        [
            f32x4(self.frag_pos, self.ambient),
            f32x4(self.normal, self.specular),
            f32x4(self.light_pos, self.shininess),
            f32x4(self.view_pos, 0.0),
            f32x4(self.light_color, 0.0),
            f32x4(self.object_color, 0.0),
        ]
    }
}

fn base() -> Case {
    Case {
        frag_pos: [0.0; 3],
        normal: [0.0, 0.0, 1.0],
        light_pos: [0.0, 0.0, 2.0],
        view_pos: [0.0, 0.0, 3.0],
        light_color: [1.0; 3],
        object_color: [1.0, 0.5, 0.31],
        ambient: 0.1,
        specular: 0.5,
        shininess: 32.0,
    }
}

fn cases() -> Vec<Case> {
    vec![
        // Normal = light dir = view dir: diff 1, spec 1, result = 1.6 * objectColor.
        base(),
        // Light behind the surface: diff 0, spec 0 (reflect points into the surface).
        Case { light_pos: [0.0, 0.0, -2.0], ..base() },
        // Light at 60 deg from the normal: diff = cos 60 = 0.5.
        Case { light_pos: [3f64.sqrt(), 0.0, 1.0], ..base() },
        // Light at 45 deg, eye on the mirror direction: diff = 0.7071, spec = 1.
        Case { light_pos: [1.0, 0.0, 1.0], view_pos: [-2.0, 0.0, 2.0], ..base() },
        // An unnormalized normal: the shader normalizes it, same as case 0.
        Case { normal: [0.0, 0.0, 7.5], ..base() },
        // The DESIGN scene quad-single at NDC (0.25, -0.5).
        Case {
            frag_pos: [0.25 * 4.0 / 3.0, -0.5, 0.0],
            normal: [0.125, -0.25, 1.0],
            light_pos: [1.2, 1.0, 2.0],
            ..base()
        },
    ]
}

#[test]
fn basic_lighting_matches_hand_checked_cases() {
    let Some(ctx) = context() else { return };
    let batch = models::BASIC_LIGHTING.batch(&ctx).expect("basic lighting compiles");
    let cases = cases();
    let mut inputs = vec![Vec::new(); 6];
    for c in &cases {
        for (k, v) in c.inputs().into_iter().enumerate() {
            inputs[k].push(v);
        }
    }
    let out = batch.run(&inputs).expect("batch runs");
    // Tolerance: the f32 shader path rounds inputs to f32 (2^-24 relative) and llvmpipe's
    // pow is exp2(y * log2(x)), whose relative error grows with y: for y = 32 a log2 error
    // of a few ulps (~1e-7) becomes ~32 * 1e-7 * ln 2 ~ 3e-6; normalize/inversesqrt adds a
    // few ulps. 1e-5 absolute on values <= 1.6 covers this with margin, and is far below a
    // real bug (a wrong sign or a missing term changes results by > 1e-2).
    let tol = 1e-5;
    for (i, c) in cases.iter().enumerate() {
        let (rgb, diff, spec) = c.expected();
        let got = out[0][i];
        let factors = out[1][i];
        println!("case {i}: expected {rgb:?} diff {diff} spec {spec}; got {got:?} factors {factors:?}");
        for ch in 0..3 {
            let d = (got[ch] as f64 - rgb[ch]).abs();
            assert!(d <= tol, "case {i} channel {ch}: expected {} got {} diff {d}", rgb[ch], got[ch]);
        }
        assert!((factors[0] as f64 - diff).abs() <= tol, "case {i} diff");
        assert!((factors[1] as f64 - spec).abs() <= tol, "case {i} spec");
    }
    // Case 0 by hand: (0.1 + 1 + 0.5) * (1, 0.5, 0.31).
    assert!((out[0][0][0] - 1.6).abs() < 1e-6 && (out[0][0][2] - 0.496).abs() < 1e-6);
}

#[test]
fn compile_errors_carry_the_log_and_body_lines() {
    let Some(ctx) = context() else { return };
    let body = "void batch_main(in vec4 v[LIGHTLAB_N_INPUTS], out vec4 o[LIGHTLAB_N_OUTPUTS])\n{\n    o[0] = v[0] * undefined_name;\n}\n";
    let err = Batch::new(&ctx, body, 1, 1).expect_err("must not compile");
    println!("{err}");
    match err {
        GlError::Compile { stage, log, excerpt } => {
            assert_eq!(stage, "fragment");
            assert!(log.contains("undefined_name"), "log: {log}");
            assert!(excerpt.contains("   3 |"), "excerpt names body line 3: {excerpt}");
        }
        other => panic!("expected a compile error, got {other}"),
    }
}

#[test]
fn bad_inputs_are_errors_not_panics() {
    let Some(ctx) = context() else { return };
    assert!(matches!(Batch::new(&ctx, "", 0, 1), Err(GlError::Input { .. })));
    assert!(matches!(Batch::new(&ctx, "", 1, lightlab::gl::batch::MAX_OUTPUTS + 1), Err(GlError::Input { .. })));
    let body = "void batch_main(in vec4 v[LIGHTLAB_N_INPUTS], out vec4 o[LIGHTLAB_N_OUTPUTS]) { o[0] = v[0] + v[1]; }";
    let batch = Batch::new(&ctx, body, 2, 1).unwrap();
    let err = batch.run(&[vec![[0.0; 4]; 3], vec![[0.0; 4]; 2]]).unwrap_err();
    assert!(matches!(err, GlError::Input { ref field, .. } if field == "inputs[1]"), "{err}");
    assert!(batch.run(&[vec![[0.0; 4]; 3]]).is_err());
    let empty = batch.run(&[vec![], vec![]]).unwrap();
    assert!(empty[0].is_empty());
}

/// What llvmpipe returns where GLSL leaves the result undefined. Inputs come from textures
/// so the compiler cannot fold them. Printed, and only checked for what GLSL defines.
#[test]
fn undefined_builtins_on_llvmpipe() {
    let Some(ctx) = context() else { return };
    let body = "void batch_main(in vec4 v[LIGHTLAB_N_INPUTS], out vec4 o[LIGHTLAB_N_OUTPUTS])
{
    // v[0] = (x, y, -, -) for pow; v[1].xyz for normalize; v[1].w for clamp.
    o[0] = vec4(pow(v[0].x, v[0].y), normalize(v[1].xyz).x, clamp(v[1].w, 0.0, 1.0), 0.0);
    o[1] = vec4(normalize(v[1].xyz), 0.0);
}";
    let batch = Batch::new(&ctx, body, 2, 2).unwrap();
    let nan = f32::NAN;
    let cases: [(&str, [f32; 4], [f32; 4]); 10] = [
        ("pow(-2, 2)", [-2.0, 2.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.5]),
        ("pow(-2, 0.5)", [-2.0, 0.5, 0.0, 0.0], [1.0, 0.0, 0.0, 0.5]),
        ("pow(-0.5, 32)", [-0.5, 32.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.5]),
        ("pow(0, 0)", [0.0, 0.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.5]),
        ("pow(0, 32)", [0.0, 32.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.5]),
        ("pow(1e-19, 2) = 1e-38, a denormal", [1e-19, 2.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.5]),
        ("normalize(vec3(0)); clamp(NaN,0,1)", [2.0, 1.0, 0.0, 0.0], [0.0, 0.0, 0.0, nan]),
        ("normalize(1e-30,0,0); clamp(-inf)", [2.0, 1.0, 0.0, 0.0], [1e-30, 0.0, 0.0, f32::NEG_INFINITY]),
        ("normalize(1e30,0,0); clamp(+inf)", [2.0, 1.0, 0.0, 0.0], [1e30, 0.0, 0.0, f32::INFINITY]),
        ("pow(1e-40 denormal in, 1); clamp(1e-40)", [1e-40, 1.0, 0.0, 0.0], [1.0, 0.0, 0.0, 1e-40]),
    ];
    let inputs = vec![cases.iter().map(|c| c.1).collect(), cases.iter().map(|c| c.2).collect()];
    let out = batch.run(&inputs).unwrap();
    for (i, (name, a, b)) in cases.iter().enumerate() {
        println!(
            "{name:40} in {a:?} {b:?} -> pow {:?}, normalize {:?}, clamp {:?}",
            out[0][i][0], out[1][i], out[0][i][2]
        );
    }
    // Defined by GLSL: pow(0, 32) = 0, clamp of a finite value; pow(-2, 2) is undefined.
    assert_eq!(out[0][4][0], 0.0);
    assert_eq!(out[0][0][2], 0.5);
}

#[test]
fn throughput_of_a_million_cases() {
    let Some(ctx) = context() else { return };
    let body = "void batch_main(in vec4 v[LIGHTLAB_N_INPUTS], out vec4 o[LIGHTLAB_N_OUTPUTS])
{
    o[0] = vec4(max(dot(normalize(v[0].xyz), normalize(v[1].xyz)), 0.0));
}";
    let batch = Batch::new(&ctx, body, 2, 1).unwrap();
    let n = 1_000_000;
    let a: Vec<[f32; 4]> = (0..n).map(|i| [1.0, (i % 7) as f32, 0.5, 0.0]).collect();
    let b: Vec<[f32; 4]> = (0..n).map(|i| [0.0, 1.0, (i % 5) as f32, 0.0]).collect();
    let inputs = vec![a, b];
    batch.run(&inputs).unwrap(); // warm-up: shader JIT
    let mut best = f64::INFINITY;
    let mut out = Vec::new();
    for _ in 0..3 {
        let start = std::time::Instant::now();
        let (o, t) = batch.run_timed(&inputs).unwrap();
        let secs = start.elapsed().as_secs_f64();
        println!(
            "{n} cases in {:.1} ms: {:.1} M cases/s (upload {:.1} ms, draw {:.1} ms, read {:.1} ms)",
            secs * 1e3,
            n as f64 / secs / 1e6,
            t.upload.as_secs_f64() * 1e3,
            t.draw.as_secs_f64() * 1e3,
            t.read.as_secs_f64() * 1e3
        );
        best = best.min(secs);
        out = o;
    }
    println!("best: {:.1} M cases/s", n as f64 / best / 1e6);
    assert_eq!(out[0].len(), n);
    // Spot check case 3: a = (1,3,0.5), b = (0,1,3): dot of the unit vectors.
    let (la, lb) = ((1.0f64 + 9.0 + 0.25).sqrt(), 10f64.sqrt());
    let want = (3.0 + 1.5) / (la * lb);
    assert!((out[0][3][0] as f64 - want).abs() < 1e-6, "got {}", out[0][3][0]);
}

/// Every tutorial model compiles, links, takes its uniforms, and runs on a zero-free case.
#[test]
fn every_model_compiles_and_runs() {
    let Some(ctx) = context() else { return };
    for model in models::MODELS {
        let batch = match model.batch(&ctx) {
            Ok(b) => b,
            Err(e) => panic!("model {} failed: {e}", model.id),
        };
        // Input k is (0.3 + 0.1k, 0.4 - 0.05k, 1 + 0.2k, 0.9 - 0.05k): distinct positions and
        // directions, positive colors and attenuation, cutOff (k=5) > outerCutOff (k=6).
        // The Gouraud model matrix is the identity (it must be invertible).
        let labels = model.inputs();
        let inputs: Vec<Vec<[f32; 4]>> = (0..labels.len())
            .map(|k| match labels[k].as_str() {
                s if s.starts_with("model column") => {
                    let c = s.trim_start_matches("model column ").parse::<usize>().unwrap();
                    let mut col = [0.0; 4];
                    col[c] = 1.0;
                    vec![col]
                }
                _ => {
                    let k = k as f32;
                    vec![[0.3 + 0.1 * k, 0.4 - 0.05 * k, 1.0 + 0.2 * k, 0.9 - 0.05 * k]]
                }
            })
            .collect();
        let out = batch.run(&inputs).unwrap();
        println!("{:18} -> {:?} {:?}", model.id, out[0][0], out[1][0]);
        assert!(out.iter().flatten().flatten().all(|x| x.is_finite()), "{} gave a non-finite value", model.id);
    }
}

/// The example user shaders are valid GLSL 3.30 on the real driver (their bugs are semantic).
#[test]
fn example_user_shaders_compile() {
    let Some(ctx) = context() else { return };
    for (name, source) in models::EXAMPLE_SHADERS {
        if let Err(e) = lightlab::gl::batch::compile_fragment(&ctx, source) {
            panic!("{name}: {e}");
        }
    }
}

/// Batches that do not fill their last row, and batches split into several draws, return
/// each case's own result in order.
#[test]
fn partial_rows_and_multiple_draws_keep_case_order() {
    let Some(ctx) = context() else { return };
    let body = "void batch_main(in vec4 v[LIGHTLAB_N_INPUTS], out vec4 o[LIGHTLAB_N_OUTPUTS])
{
    o[0] = v[0] * 2.0;
    o[1] = v[0] + vec4(1.0);
}";
    let batch = Batch::new(&ctx, body, 1, 2).unwrap();
    // 1, 4095, 4097 cases: one partial row, one short row, a full row plus one texel.
    // 4096 * 1024 + 5 cases: two draws (MAX_ROWS_PER_DRAW rows of MAX_WIDTH, then 5).
    let big = lightlab::gl::batch::MAX_WIDTH * lightlab::gl::batch::MAX_ROWS_PER_DRAW + 5;
    for n in [1usize, 4095, 4097, big] {
        // Integers below 2^24 are exact in f32, so doubling and adding 1 are exact too.
        let input: Vec<[f32; 4]> = (0..n).map(|i| [i as f32, -(i as f32), 0.5, 1.0]).collect();
        let out = batch.run(&[input]).unwrap();
        assert_eq!(out[0].len(), n);
        for i in [0, n / 2, n - 1] {
            let x = i as f32;
            assert_eq!(out[0][i], [2.0 * x, -2.0 * x, 1.0, 2.0], "n {n} case {i}");
            assert_eq!(out[1][i], [x + 1.0, 1.0 - x, 1.5, 2.0], "n {n} case {i}");
        }
    }
}
