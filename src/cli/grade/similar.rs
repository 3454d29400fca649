//! Near-identical submissions: the same token stream once comments, white space and the
//! names the student chose are normalized (each name becomes `_1`, `_2`, ... in order
//! of first use; GLSL's keywords, types, built-in functions and the exercise's uniform
//! and varying names stay). A flag for the teacher to look at, not a verdict. Only
//! submissions that do not agree are compared: right answers converge on the chapter's
//! own code (which every student has read), while two answers wrong in the same way,
//! token for token, are the sign teachers look for.

use std::collections::HashMap;

use super::run::Job;
use super::Row;

/// GLSL words that are not the student's names.
const KEPT: &[&str] = &[
    "void",
    "float",
    "int",
    "bool",
    "vec2",
    "vec3",
    "vec4",
    "mat3",
    "mat4",
    "sampler2D",
    "struct",
    "uniform",
    "in",
    "out",
    "inout",
    "const",
    "if",
    "else",
    "for",
    "while",
    "do",
    "return",
    "break",
    "continue",
    "discard",
    "true",
    "false",
    "main",
    "version",
    "core",
    "define",
    "normalize",
    "dot",
    "cross",
    "reflect",
    "pow",
    "max",
    "min",
    "clamp",
    "mix",
    "length",
    "distance",
    "texture",
    "smoothstep",
    "step",
    "abs",
    "sqrt",
    "inverse",
    "transpose",
    "exp",
    "exp2",
    "log",
    "log2",
    "sin",
    "cos",
    "radians",
    "degrees",
    "gl_FragColor",
    "gl_Position",
    "gl_FragCoord",
];

/// The normalized token stream of a shader.
pub fn tokens(src: &str, kept: &[String]) -> Vec<String> {
    let mut out = Vec::new();
    let mut names: HashMap<String, usize> = HashMap::new();
    let chars: Vec<char> = src.chars().collect();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        if c == '/' && chars.get(i + 1) == Some(&'/') {
            while i < chars.len() && chars[i] != '\n' {
                i += 1;
            }
        } else if c == '/' && chars.get(i + 1) == Some(&'*') {
            i += 2;
            while i + 1 < chars.len() && !(chars[i] == '*' && chars[i + 1] == '/') {
                i += 1;
            }
            i += 2;
        } else if c.is_whitespace() {
            i += 1;
        } else if c.is_ascii_alphabetic() || c == '_' {
            let start = i;
            while i < chars.len() && (chars[i].is_ascii_alphanumeric() || chars[i] == '_') {
                i += 1;
            }
            let word: String = chars[start..i].iter().collect();
            if KEPT.contains(&word.as_str()) || kept.contains(&word) {
                out.push(word);
            } else {
                let n = names.len() + 1;
                out.push(format!("_{}", *names.entry(word).or_insert(n)));
            }
        } else if c.is_ascii_digit() || c == '.' {
            let start = i;
            while i < chars.len() && (chars[i].is_ascii_alphanumeric() || chars[i] == '.') {
                i += 1;
            }
            out.push(chars[start..i].iter().collect());
        } else {
            out.push(c.to_string());
            i += 1;
        }
    }
    out
}

/// The names a shader exercise gives the student (its solution's uniforms, ins and outs).
fn declared(solution: &str) -> Vec<String> {
    solution
        .lines()
        .map(str::trim_start)
        .filter(|l| {
            l.starts_with("uniform ") || l.starts_with("in ") || l.starts_with("out ") || l.starts_with("struct ")
        })
        .filter_map(|l| l.trim_end_matches(';').split_whitespace().last().map(|w| w.trim_end_matches('{').to_string()))
        .collect()
}

/// Flags near-identical submissions of the same exercise: each row's `similar_to` lists
/// the others; returns the groups (file names). One file handed in by several students
/// (a symbolic link in one folder to another's file: the collected paths are resolved)
/// is flagged whatever its verdict; otherwise only submissions that do not agree are
/// compared, by token stream.
pub fn flag(jobs: &[Job], rows: &mut [Row]) -> Vec<Vec<String>> {
    let mut same_file: HashMap<(&str, &std::path::Path), Vec<usize>> = HashMap::new();
    for (k, job) in jobs.iter().enumerate() {
        if let Ok((path, _)) = &job.files {
            same_file.entry((job.exercise.id, path.as_path())).or_default().push(k);
        }
    }
    let shared: Vec<Vec<usize>> = same_file.into_values().filter(|m| m.len() > 1).collect();
    let in_shared: std::collections::HashSet<usize> = shared.iter().flatten().copied().collect();
    let mut groups: HashMap<(&str, Vec<String>), Vec<usize>> = HashMap::new();
    for (k, job) in jobs.iter().enumerate() {
        let Ok((path, _)) = &job.files else { continue };
        if rows[k].agrees || in_shared.contains(&k) {
            continue;
        }
        if !crate::cli::exercise::needs_gl(job.exercise) {
            continue;
        }
        let Ok(bytes) = crate::cli::input::read_limited(path, crate::checker::check::MAX_SOURCE_BYTES) else {
            continue;
        };
        let Ok(text) = crate::exercises::text_of(&bytes) else { continue };
        let solution = job.exercise.solution();
        let kept = declared(&solution);
        let stream = tokens(&text, &kept);
        if stream.len() < 8 || stream == tokens(&solution, &kept) {
            continue;
        }
        groups.entry((job.exercise.id, stream)).or_default().push(k);
    }
    let mut out: Vec<Vec<String>> = Vec::new();
    for members in groups.values().filter(|m| m.len() > 1).chain(&shared) {
        let names: Vec<String> = members.iter().map(|&k| jobs[k].file.clone()).collect();
        for &k in members {
            rows[k].similar_to = names.iter().filter(|n| **n != jobs[k].file).cloned().collect();
        }
        out.push(names);
    }
    out.sort();
    out
}

#[cfg(test)]
mod tests {
    use super::tokens;

    #[test]
    fn renamed_variables_and_comments_give_the_same_stream() {
        let a = "void main() { float diff = max(dot(n, l), 0.0); // mine\n FragColor = vec4(diff); }";
        let b = "void main(){float d=max(dot(norm,lightDir),0.0);/* copied */FragColor=vec4(d);}";
        let kept = vec!["FragColor".to_string()];
        assert_eq!(tokens(a, &kept), tokens(b, &kept));
        let c = "void main() { float diff = max(dot(n, l), 1.0); FragColor = vec4(diff); }";
        assert_ne!(tokens(a, &kept), tokens(c, &kept));
    }
}
