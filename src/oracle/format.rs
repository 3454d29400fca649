//! The oracle's report as text (`lightlab oracle`) and as Markdown (the book's table,
//! `book/data/oracle.md`).

use std::fmt::Write as _;

use super::cases;
use super::compare::{run, CaseRecord, ModelReport, OracleReport};
use crate::gl::context::{GlContext, GlError};
use crate::gl::model_id::ModelId;

/// Creates a context, runs the oracle with `cases` cases per model and the default seed,
/// and formats it with [`format_markdown`] (for the book).
///
/// Errors: any [`GlError`], including a missing OpenGL.
pub fn report_markdown(cases: usize) -> Result<String, GlError> {
    let ctx = GlContext::new()?;
    Ok(format_markdown(&run(&ctx, cases, cases::DEFAULT_SEED)?))
}

fn e(x: f64) -> String {
    if x.is_infinite() {
        "inf".into()
    } else if x == 0.0 {
        "0".into()
    } else {
        format!("{x:.2e}")
    }
}

fn u(x: f64) -> String {
    if x.is_infinite() {
        "inf".into()
    } else {
        format!("{x:.1}")
    }
}

fn excluded_summary(m: &ModelReport) -> String {
    if m.excluded.is_empty() {
        return "none".into();
    }
    m.excluded.iter().map(|x| format!("{} {}", x.cases, x.class.describe())).collect::<Vec<_>>().join(", ")
}

fn verdict(m: &ModelReport) -> &'static str {
    if m.passes() {
        "pass"
    } else {
        "FAIL"
    }
}

/// The inputs of a record, labelled with the model's layout.
pub fn describe_inputs(model: ModelId, inputs: &[[f32; 4]]) -> Vec<String> {
    let labels = model.layout().input_labels();
    inputs
        .iter()
        .enumerate()
        .map(|(k, v)| {
            let label = labels.get(k).map_or("-", String::as_str);
            format!("{label} = ({:?}, {:?}, {:?}, {:?})", v[0], v[1], v[2], v[3])
        })
        .collect()
}

fn fmt_vals<T: std::fmt::Debug>(v: &[T]) -> String {
    v.iter().map(|x| format!("{x:?}")).collect::<Vec<_>>().join(", ")
}

fn write_record(out: &mut String, model: ModelId, title: &str, r: &CaseRecord, indent: &str) {
    let _ = writeln!(out, "{indent}{title}: case {} (group {})", r.index, r.group);
    for line in describe_inputs(model, &r.inputs) {
        let _ = writeln!(out, "{indent}    {line}");
    }
    let _ = writeln!(out, "{indent}    f64 reference = [{}]", fmt_vals(&r.reference));
    let _ = writeln!(out, "{indent}    f32 core      = [{}]", fmt_vals(&r.rust_f32));
    let _ = writeln!(out, "{indent}    llvmpipe      = [{}]", fmt_vals(&r.llvmpipe));
    let outs: Vec<String> = r.llvmpipe_outputs.iter().map(|o| format!("{o:?}")).collect();
    let _ = writeln!(out, "{indent}    llvmpipe outputs = {}", outs.join(" "));
}

fn header(r: &OracleReport) -> String {
    let p = &r.pow;
    format!(
        "Renderer: {} ({}); {} cases per model, seed {:#x}.\n\
         llvmpipe pow(x, y), y in [1, 256], x^y in [2^-24, 1], {} cases: max relative error {} ({} ulps), mean {}, \
         as an absolute log2 error at most {} ({:.2} eps); worst pow({:?}, {:?}) = {:?}, f64 {:e}.\n",
        r.renderer,
        r.version,
        r.cases,
        r.seed,
        p.cases,
        e(p.max_rel),
        u(p.max_ulps),
        e(p.mean_rel),
        e(p.max_log2_abs),
        p.max_log2_abs / cases::bounds::EPS,
        p.worst.0,
        p.worst.1,
        p.worst.2,
        p.worst.3
    )
}

/// One model's row of the per-model table, for both formats: model, cases, defined; the
/// f32 core against f64 (max, mean, max ulps, mean ulps); llvmpipe against f64 (the same
/// four); the bound, the verdict and the excluded cases.
fn model_cells(m: &ModelReport) -> [String; 14] {
    let (a, b) = (&m.f32_vs_f64, &m.gl_vs_f64);
    [
        m.model.name().to_string(),
        m.cases.to_string(),
        m.defined.to_string(),
        e(a.max_abs),
        e(a.mean_abs),
        u(a.max_ulps),
        u(a.mean_ulps),
        e(b.max_abs),
        e(b.mean_abs),
        u(b.max_ulps),
        u(b.mean_ulps),
        e(m.bound),
        verdict(m).to_string(),
        excluded_summary(m),
    ]
}

/// The width of the text table's model column: the longest model name of `r`, at least
/// the heading's `model`.
fn model_column_width(r: &OracleReport) -> usize {
    r.models.iter().map(|m| m.model.name().len()).fold("model".len(), usize::max)
}

/// Formats the report as a fixed-width text table followed by the worst cases and the
/// excluded (undefined) cases of each model.
pub fn format_text(r: &OracleReport) -> String {
    let mut out = header(r);
    let w = model_column_width(r);
    let _ = writeln!(
        out,
        "\n{:<w$} {:>7} {:>7} | {:>9} {:>9} {:>7} {:>6} | {:>9} {:>9} {:>7} {:>6} | {:>9} | {:<7} | excluded",
        "model",
        "cases",
        "defined",
        "f32 max",
        "f32 mean",
        "max ulp",
        "mean",
        "gl max",
        "gl mean",
        "max ulp",
        "mean",
        "bound",
        "verdict"
    );
    for m in &r.models {
        let c = model_cells(m);
        let _ = writeln!(
            out,
            "{:<w$} {:>7} {:>7} | {:>9} {:>9} {:>7} {:>6} | {:>9} {:>9} {:>7} {:>6} | {:>9} | {:<7} | {}",
            c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8], c[9], c[10], c[11], c[12], c[13]
        );
    }
    let _ = writeln!(out, "\n(f32 = the Rust f32 core, gl = llvmpipe; both against the f64 reference, defined cases.)");
    for m in &r.models {
        let _ = writeln!(
            out,
            "\n## {}: llvmpipe vs f32 core max {} ({} ulps)",
            m.model,
            e(m.gl_vs_f32.max_abs),
            u(m.gl_vs_f32.max_ulps)
        );
        if let Some(w) = &m.worst_gl {
            write_record(&mut out, m.model, "worst llvmpipe case", w, "  ");
        }
        if let Some(w) = &m.worst_f32 {
            write_record(&mut out, m.model, "worst f32 case", w, "  ");
        }
        for x in &m.excluded {
            let _ = writeln!(
                out,
                "  excluded, {}: {} cases; llvmpipe result NaN in {}, some output NaN in {}, equal to the f32 core's fallback (within the bound) in {}",
                x.class.describe(),
                x.cases,
                x.result_nan,
                x.any_output_nan,
                x.matches_f32
            );
            if let Some(ex) = &x.example {
                write_record(&mut out, m.model, "example", ex, "    ");
            }
        }
    }
    out
}

/// Formats the report as Markdown: the per-model table, then the worst cases and the
/// excluded cases in code blocks.
pub fn format_markdown(r: &OracleReport) -> String {
    let mut out = header(r);
    out += "\n| model | cases | defined | f32 vs f64 max | mean | max ulps | mean ulps | llvmpipe vs f64 max | mean | max ulps | mean ulps | bound | verdict | excluded (undefined in GLSL) |\n";
    out += "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- | --- |\n";
    for m in &r.models {
        // the model is the name `--model` takes: a code span, not a word to translate
        let mut cells = model_cells(m);
        cells[0] = format!("`{}`", cells[0]);
        let _ = writeln!(out, "| {} |", cells.join(" | "));
    }
    out += "\nWorst cases and excluded cases:\n\n```text\n";
    let text = format_text(r);
    if let Some(k) = text.find("\n## ") {
        out += text[k + 1..].trim_end();
        out += "\n";
    }
    out += "```\n";
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::oracle::{ErrorSummary, PowReport};

    /// A report of `models` whose numbers are all zero.
    fn report_of(models: &[ModelId]) -> OracleReport {
        let row = |model: ModelId| ModelReport {
            model,
            cases: 1000,
            defined: 990,
            bound: 1e-5,
            f32_vs_f64: ErrorSummary::default(),
            gl_vs_f64: ErrorSummary::default(),
            gl_vs_f32: ErrorSummary::default(),
            worst_gl: None,
            worst_f32: None,
            excluded: Vec::new(),
            gl_ms: 0.0,
            rust_ms: 0.0,
        };
        OracleReport {
            renderer: "test".into(),
            version: "test".into(),
            cases: 1000,
            seed: cases::DEFAULT_SEED,
            pow: PowReport::default(),
            models: models.iter().map(|&m| row(m)).collect(),
        }
    }

    #[test]
    fn the_text_table_columns_line_up_with_the_longest_model_name() {
        // the shortest and the longest names (`lighting_maps_emission`, 22 characters)
        let longest = *ModelId::ALL.iter().max_by_key(|m| m.name().len()).unwrap();
        let text = format_text(&report_of(&[ModelId::Gouraud, longest]));
        let table: Vec<&str> = text.lines().skip_while(|l| !l.starts_with("model ")).take(3).collect();
        let bars = |line: &str| line.match_indices('|').map(|(i, _)| i).collect::<Vec<_>>();
        assert_eq!(table.len(), 3, "{text}");
        for line in &table[1..] {
            assert_eq!(bars(line), bars(table[0]), "misaligned:\n{}", table.join("\n"));
        }
    }
}
