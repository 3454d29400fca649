//! The JSON export of the layouts (schema in [`super`]).

use std::fmt::Write as _;

use super::{Quantity, Slot};
use crate::gl::batch::Uniform;
use crate::gl::model_id::ModelId;

fn json_str(s: &str) -> String {
    let mut out = String::from("\"");
    for c in s.chars() {
        match c {
            '"' => out += "\\\"",
            '\\' => out += "\\\\",
            c if (c as u32) < 0x20 => {
                let _ = write!(out, "\\u{:04x}", c as u32);
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

fn json_f32(x: f32) -> String {
    if x.is_finite() {
        format!("{x:?}")
    } else {
        "null".into()
    }
}

fn json_list<T>(items: impl IntoIterator<Item = T>, f: impl Fn(T) -> String) -> String {
    format!("[{}]", items.into_iter().map(f).collect::<Vec<_>>().join(", "))
}

fn json_quantity(q: &Quantity, k: usize) -> String {
    let (storage, input, offset) = match q.slot {
        Slot::Case { input, offset } => ("case", input.to_string(), offset.to_string()),
        Slot::Group => ("group", "null".into(), "null".into()),
        Slot::Unused => ("unused", "null".into(), "null".into()),
    };
    let default = q.default.map_or("null".into(), |d| json_list(d, json_f32));
    let range = q.range.map_or("null".into(), |(lo, hi)| json_list([lo, hi], json_f32));
    let label = if q.slot == Slot::Group { q.name.to_string() } else { q.label_in(k) };
    format!(
        "{{\"name\": {}, \"type\": {}, \"storage\": \"{storage}\", \"input\": {input}, \"offset\": {offset}, \
         \"components\": {}, \"label\": {}, \"default\": {default}, \"range\": {range}}}",
        json_str(q.name),
        json_str(q.ty.name()),
        q.components,
        json_str(&label),
    )
}

fn json_uniform((name, value): &(String, Uniform)) -> String {
    let (ty, v) = match value {
        Uniform::Int(i) => ("int", i.to_string()),
        Uniform::Float(x) => ("float", json_f32(*x)),
        Uniform::Vec3(v) => ("vec3", json_list(*v, json_f32)),
        Uniform::Vec4(v) => ("vec4", json_list(*v, json_f32)),
        Uniform::Mat4(m) => ("mat4", json_list(*m, json_f32)),
    };
    format!("{{\"name\": {}, \"type\": \"{ty}\", \"value\": {v}}}", json_str(name))
}

/// Every layout as JSON (the schema is in the module docs): deterministic, one model per
/// block, ending with a newline.
pub fn export_json() -> String {
    let mut out = String::from("{\n  \"schema\": 1,\n  \"models\": [\n");
    for (i, model) in ModelId::ALL.into_iter().enumerate() {
        let l = model.layout();
        let tutorial = model.shader().is_some();
        let _ = writeln!(out, "    {{");
        let _ = writeln!(out, "      \"model\": {},", json_str(model.name()));
        let _ = writeln!(out, "      \"source\": {},", json_str(l.source));
        let _ = writeln!(out, "      \"tutorial_shader\": {tutorial},");
        let _ = writeln!(out, "      \"n_inputs\": {},", l.n_inputs());
        let _ = writeln!(out, "      \"n_outputs\": {},", l.n_outputs());
        let _ = writeln!(out, "      \"inputs\": {},", json_list(l.input_labels(), |s| json_str(&s)));
        let _ = writeln!(out, "      \"outputs\": {},", json_list(l.outputs.iter(), |s| json_str(s)));
        out += "      \"quantities\": [\n";
        let qs: Vec<String> =
            l.quantities.iter().map(|q| format!("        {}", json_quantity(q, q.inputs().start))).collect();
        out += &qs.join(",\n");
        out += "\n      ],\n";
        let uniforms: Vec<String> =
            l.chapter_uniforms().iter().map(|u| format!("        {}", json_uniform(u))).collect();
        if uniforms.is_empty() {
            out += "      \"uniforms\": []\n";
        } else {
            out += "      \"uniforms\": [\n";
            out += &uniforms.join(",\n");
            out += "\n      ]\n";
        }
        out += if i + 1 < ModelId::ALL.len() { "    },\n" } else { "    }\n" };
    }
    out += "  ]\n}\n";
    out
}
