//! One oracle run: each model's cases on llvmpipe, the `f32` core and the `f64` reference,
//! compared case by case ([`run_model`], [`run`]), and llvmpipe's `pow` measured alone
//! ([`measure_pow`]). See [`crate::oracle`] for what is compared and how.

use std::time::Instant;

use proptest::prelude::*;

use super::cases::{self, bounds, CaseModel, Channels, Class, Group, CASE_MODELS};
use super::stats::{ulp_f32, ErrorAcc, ErrorSummary};
use crate::gl::batch::Batch;
use crate::gl::context::{GlContext, GlError};
use crate::gl::model_id::ModelId;

/// Default number of cases per model: 10^5.
pub const DEFAULT_CASES: usize = 100_000;

/// One case with every answer, for counterexamples.
#[derive(Debug, Clone, PartialEq)]
pub struct CaseRecord {
    /// Position in the model's case order.
    pub index: usize,
    /// The packed inputs (layout: [`crate::gl::layout::Layout::input_labels`]).
    pub inputs: Vec<[f32; 4]>,
    /// Uniform group (the scene number for `multiple_lights`, else 0).
    pub group: usize,
    /// The `f64` reference.
    pub reference: Vec<f64>,
    /// The `f32` core.
    pub rust_f32: Vec<f32>,
    /// llvmpipe.
    pub llvmpipe: Vec<f32>,
    /// Every output of the harness on llvmpipe, diagnostics included.
    pub llvmpipe_outputs: Vec<[f32; 4]>,
}

/// The cases of one [`Class`] other than [`Class::Defined`], and what llvmpipe returned.
#[derive(Debug, Clone, PartialEq)]
pub struct ExcludedReport {
    /// The class.
    pub class: Class,
    /// Number of cases.
    pub cases: usize,
    /// Cases where a compared channel of llvmpipe's result is NaN.
    pub result_nan: usize,
    /// Cases where any harness output of llvmpipe (diagnostics included) has a NaN.
    pub any_output_nan: usize,
    /// Cases where llvmpipe's result is within the model's bound of the `f32` core's
    /// documented fallback (zero vectors normalized to zero, `pow` undefined → no highlight).
    pub matches_f32: usize,
    /// The first such case.
    pub example: Option<CaseRecord>,
}

/// The oracle's findings for one model.
#[derive(Debug, Clone, PartialEq)]
pub struct ModelReport {
    /// The model.
    pub model: ModelId,
    /// Cases run.
    pub cases: usize,
    /// Cases in [`Class::Defined`] (the others are in `excluded`).
    pub defined: usize,
    /// The asserted bound on the absolute error.
    pub bound: f64,
    /// The `f32` core against the reference, defined cases.
    pub f32_vs_f64: ErrorSummary,
    /// llvmpipe against the reference, defined cases.
    pub gl_vs_f64: ErrorSummary,
    /// llvmpipe against the `f32` core, defined cases.
    pub gl_vs_f32: ErrorSummary,
    /// The case where llvmpipe is farthest from the reference.
    pub worst_gl: Option<CaseRecord>,
    /// The case where the `f32` core is farthest from the reference.
    pub worst_f32: Option<CaseRecord>,
    /// The excluded cases by class.
    pub excluded: Vec<ExcludedReport>,
    /// Wall time of the draws (upload, draw, read back), milliseconds.
    pub gl_ms: f64,
    /// Wall time of the Rust evaluations (`f32` and `f64`), milliseconds.
    pub rust_ms: f64,
}

impl ModelReport {
    /// Whether both the `f32` core and llvmpipe are within the bound on every defined case.
    pub fn passes(&self) -> bool {
        self.f32_vs_f64.max_abs <= self.bound && self.gl_vs_f64.max_abs <= self.bound
    }
}

/// llvmpipe's `pow(x, y)` against `f64`, on `y` in [1, 256] and `x^y` in [2^-24, 1].
/// The default is the report of no case, every error 0 (what a sum starts from, and what
/// a run that measures no `pow` shows).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PowReport {
    /// Cases with a result above the smallest normal `f32` (smaller ones are flushed).
    pub cases: usize,
    /// Largest relative error.
    pub max_rel: f64,
    /// Mean relative error.
    pub mean_rel: f64,
    /// Largest error in ulps of the result.
    pub max_ulps: f64,
    /// Largest absolute error of `log2` implied by the relative errors (see [`measure_pow`]).
    pub max_log2_abs: f64,
    /// The case of the largest relative error: (x, y, llvmpipe, f64).
    pub worst: (f32, f32, f32, f64),
}

/// The whole oracle run.
#[derive(Debug, Clone, PartialEq)]
pub struct OracleReport {
    /// `GL_RENDERER` of the context.
    pub renderer: String,
    /// `GL_VERSION` of the context.
    pub version: String,
    /// Cases per model.
    pub cases: usize,
    /// The seed.
    pub seed: u64,
    /// llvmpipe's `pow` alone.
    pub pow: PowReport,
    /// One report per model, in chapter order.
    pub models: Vec<ModelReport>,
}

impl OracleReport {
    /// Whether every model passes.
    pub fn passes(&self) -> bool {
        self.models.iter().all(ModelReport::passes)
    }
}

fn widen(c: &Channels<f32>, n: usize) -> Vec<f64> {
    c[..n].iter().map(|&x| x as f64).collect()
}

/// Runs every group of `model` on llvmpipe: `outputs[g][m][i]`.
fn run_groups(ctx: &GlContext, model: &CaseModel, groups: &[Group]) -> Result<Vec<Vec<Vec<[f32; 4]>>>, GlError> {
    let shader = model.shader.ok_or_else(|| GlError::Input {
        field: "model".into(),
        reason: format!("{} has no tutorial shader to run", model.id),
    })?;
    let batch = shader.batch(ctx)?;
    groups
        .iter()
        .map(|g| {
            for (name, value) in &g.uniforms {
                batch.set_uniform(name, *value)?;
            }
            batch.run(&g.columns(model.n_inputs))
        })
        .collect()
}

/// Runs the oracle for one model: `n` cases from `seed`.
///
/// Errors: any [`GlError`] of the draws (compile, framebuffer, missing GL).
pub fn run_model(ctx: &GlContext, model: &CaseModel, n: usize, seed: u64) -> Result<ModelReport, GlError> {
    let groups = cases::generate_cases(model, n, seed, &[])?;
    let clock = Instant::now();
    let outputs = run_groups(ctx, model, &groups)?;
    let gl_ms = clock.elapsed().as_secs_f64() * 1e3;
    let clock = Instant::now();
    let channels = model.channels;
    let (mut f32_acc, mut gl_acc, mut gl32_acc) = (ErrorAcc::default(), ErrorAcc::default(), ErrorAcc::default());
    let mut excluded: Vec<ExcludedReport> = Vec::new();
    let mut records: Vec<(usize, usize, usize)> = Vec::new(); // (index, group, row) of every case
    let mut index = 0;
    for (g, group) in groups.iter().enumerate() {
        let scene = group.scene.as_ref();
        for (i, row) in group.rows.iter().enumerate() {
            let outs: Vec<[f32; 4]> = outputs[g].iter().map(|o| o[i]).collect();
            let gl = widen(&model.gl_channels(&outs), channels);
            let rust = widen(&model.eval_f32(row, scene), channels);
            records.push((index, g, i));
            match model.classify(row, scene) {
                Class::Defined => {
                    let want = &model.eval_f64(row, scene)[..channels];
                    f32_acc.add(index, &rust, want);
                    gl_acc.add(index, &gl, want);
                    gl32_acc.add(index, &gl, &rust);
                }
                class => {
                    let entry = match excluded.iter_mut().position(|e| e.class == class) {
                        Some(k) => &mut excluded[k],
                        None => {
                            excluded.push(ExcludedReport {
                                class,
                                cases: 0,
                                result_nan: 0,
                                any_output_nan: 0,
                                matches_f32: 0,
                                example: None,
                            });
                            excluded.last_mut().expect("just pushed")
                        }
                    };
                    entry.cases += 1;
                    entry.result_nan += usize::from(gl.iter().any(|x| x.is_nan()));
                    entry.any_output_nan += usize::from(outs.iter().flatten().any(|x| x.is_nan()));
                    let close = gl.iter().zip(&rust).all(|(a, b)| (a - b).abs() <= model.bound);
                    entry.matches_f32 += usize::from(close);
                    if entry.example.is_none() {
                        entry.example = Some(record(model, &groups, &outputs, index, g, i));
                    }
                }
            }
            index += 1;
        }
    }
    excluded.sort_by_key(|e| e.class);
    let (f32_vs_f64, gl_vs_f64, gl_vs_f32) = (f32_acc.finish(), gl_acc.finish(), gl32_acc.finish());
    let find = |worst: Option<usize>| {
        worst
            .and_then(|w| records.iter().find(|r| r.0 == w))
            .map(|&(k, g, i)| record(model, &groups, &outputs, k, g, i))
    };
    let rust_ms = clock.elapsed().as_secs_f64() * 1e3;
    Ok(ModelReport {
        model: model.id,
        cases: index,
        defined: f32_vs_f64.count,
        bound: model.bound,
        worst_gl: find(gl_vs_f64.worst),
        worst_f32: find(f32_vs_f64.worst),
        f32_vs_f64,
        gl_vs_f64,
        gl_vs_f32,
        excluded,
        gl_ms,
        rust_ms,
    })
}

fn record(
    model: &CaseModel,
    groups: &[Group],
    outputs: &[Vec<Vec<[f32; 4]>>],
    index: usize,
    g: usize,
    i: usize,
) -> CaseRecord {
    let row = &groups[g].rows[i];
    let scene = groups[g].scene.as_ref();
    let outs: Vec<[f32; 4]> = outputs[g].iter().map(|o| o[i]).collect();
    let n = model.channels;
    CaseRecord {
        index,
        inputs: row.clone(),
        group: g,
        reference: model.eval_f64(row, scene)[..n].to_vec(),
        rust_f32: model.eval_f32(row, scene)[..n].to_vec(),
        llvmpipe: model.gl_channels(&outs)[..n].to_vec(),
        llvmpipe_outputs: outs,
    }
}

const POW_BODY: &str = "void batch_main(in vec4 v[LIGHTLAB_N_INPUTS], out vec4 o[LIGHTLAB_N_OUTPUTS])
{
    o[0] = vec4(pow(v[0].x, v[0].y), 0.0, 0.0, 0.0);
}
";

/// Measures llvmpipe's `pow(x, y)` on `n` random exact inputs, `y` uniform in [1, 256] and
/// `x` such that `x^y` is in [2^-24, 1] (the range of a specular factor that matters),
/// against `f64` `powf` of the same inputs.
///
/// llvmpipe computes `exp2(y·log2 x)`: an absolute error `η` of its `log2` becomes a
/// relative error `ln2·y·η` of the result, beside `ln2·t·ε` from rounding the product
/// `t = |y·log2 x|` and `ε` from `exp2`; the report gives the largest
/// `η = (rel - ln2·t·ε - ε) / (ln2·y)` (see [`crate::oracle::cases::bounds::LOG2_ABS`]).
///
/// Errors: any [`GlError`] of the draw.
pub fn measure_pow(ctx: &GlContext, n: usize, seed: u64) -> Result<PowReport, GlError> {
    check_count(n)?;
    // t = -y·log2(x) uniform in [0, 24], so that x^y = 2^-t stays a normal f32 >= 2^-24.
    let strategy = (0.0f32..=24.0, 1.0f32..=256.0).prop_map(|(t, y)| [(-t / y).exp2(), y, 0.0, 0.0]);
    let inputs = cases::generate(&strategy, n, cases::seed_bytes(seed, 9999))?;
    let out = Batch::new(ctx, POW_BODY, 1, 1)?.run(std::slice::from_ref(&inputs))?;
    let mut report = PowReport::default();
    let mut sum = 0.0;
    for (input, o) in inputs.iter().zip(&out[0]) {
        let want = (input[0] as f64).powf(input[1] as f64);
        if want < f32::MIN_POSITIVE as f64 {
            continue;
        }
        let got = o[0] as f64;
        let rel = if got.is_finite() { (got - want).abs() / want } else { f64::INFINITY };
        if rel > report.max_rel || report.cases == 0 {
            report.max_rel = rel;
            report.worst = (input[0], input[1], o[0], want);
        }
        report.max_ulps = report.max_ulps.max((got - want).abs() / ulp_f32(want));
        // rel ≈ ln2·(y·η + t·ε) + ε: the log2 error η scaled by y, the rounding of the
        // product y·log2(x) (t = |y·log2 x|) and exp2's rounding; solve for η.
        let t = (input[1] as f64 * (input[0] as f64).log2()).abs();
        let ln2 = std::f64::consts::LN_2;
        let eta = (rel - ln2 * t * bounds::EPS - bounds::EPS).max(0.0) / (ln2 * input[1] as f64);
        report.max_log2_abs = report.max_log2_abs.max(eta);
        sum += rel;
        report.cases += 1;
    }
    if report.cases > 0 {
        report.mean_rel = sum / report.cases as f64;
    }
    Ok(report)
}

/// Refuses more than [`cases::MAX_CASES`] cases before anything is allocated.
fn check_count(n: usize) -> Result<(), GlError> {
    if n > cases::MAX_CASES {
        return Err(GlError::Input {
            field: "cases".into(),
            reason: format!("{n} is above the limit {}", cases::MAX_CASES),
        });
    }
    Ok(())
}

/// Runs the whole oracle: [`measure_pow`] then [`run_model`] for every model with
/// [`CaseModel::in_oracle`] (the tutorial shaders).
///
/// Errors: any [`GlError`]; [`GlError::Input`] naming `cases` above [`cases::MAX_CASES`].
pub fn run(ctx: &GlContext, n: usize, seed: u64) -> Result<OracleReport, GlError> {
    check_count(n)?;
    let pow = measure_pow(ctx, n, seed)?;
    let models = CASE_MODELS
        .iter()
        .filter(|m| m.in_oracle)
        .map(|m| run_model(ctx, m, n, seed))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(OracleReport {
        renderer: ctx.info().renderer.clone(),
        version: ctx.info().version.clone(),
        cases: n,
        seed,
        pow,
        models,
    })
}
