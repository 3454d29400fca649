//! The page's vertex + fragment pair check (`book/theme/live/lightlab-pair.js`) in headless
//! Chromium against `check-shader --vertex` on llvmpipe: on the crate's pair data
//! (`lightlab::live::pair`), the reference pair agrees, and every vertex mutant pair gets
//! the command line's verdict and is named by its own id (`gouraud-for-phong` for a
//! Gouraud pair, `normal-matrix-missing`, ...). A page that loads only the pair scripts and
//! the data, so no book is built.
//!
//! Skips without Chromium (unless `LIGHTLAB_REQUIRE_BROWSER=1`) or without OpenGL (unless
//! `LIGHTLAB_REQUIRE_GL=1`).
#![cfg(all(feature = "gl", feature = "book"))]

#[allow(dead_code)]
mod browser_common;
mod common;
mod gl_common;

use std::fs;
use std::path::Path;

use lightlab::checker::check::pair::{self, PairModel};
use lightlab::checker::check::Mapping;
use lightlab::live::pair::{pair_json, N_PAIR_CASES};

/// A page running `LightlabPair.check` on the reference and every mutant of `data`, the
/// results as JSON in `<pre id="pair-result">`.
fn page(dir: &Path, data: &serde_json::Value) -> std::path::PathBuf {
    let live = Path::new(env!("CARGO_MANIFEST_DIR")).join("book/theme/live");
    let scripts: String = ["lightlab-i18n.js", "lightlab-gl.js", "lightlab-decision.js", "lightlab-pair.js"]
        .iter()
        .map(|s| format!("<script src=\"file://{}\"></script>\n", live.join(s).display()))
        .collect();
    let json = data.to_string().replace("</", "<\\/");
    let html = format!(
        "<!DOCTYPE html><html><body><pre id=\"pair-result\"></pre>\n<script>window.LL_PAIR = {json};</script>\n{scripts}\
         <script>\n\
         var data = window.LL_PAIR, out = {{}};\n\
         function one(name, v, f) {{\n\
           try {{ var r = LightlabPair.check(data, v, f);\n\
             out[name] = {{ verdict: r.verdict, failing: r.failing, error: r.error || null, ids: r.diagnosis.map(function (d) {{ return d.id; }}) }};\n\
           }} catch (e) {{ out[name] = {{ verdict: 'exception', error: String(e && e.stack || e), ids: [] }}; }}\n\
         }}\n\
         one('reference', data.reference.vertex, data.reference.fragment);\n\
         data.mutants.forEach(function (m) {{ one(m.id, m.vertex, m.fragment); }});\n\
         document.getElementById('pair-result').textContent = JSON.stringify(out);\n\
         </script></body></html>\n"
    );
    let path = dir.join(format!("pair-{}.html", data["model"].as_str().unwrap()));
    fs::write(&path, html).unwrap();
    path
}

/// GLSL ES 3.00 has no `in`/`out` interface blocks, so a pair written with them (the
/// view-space pair's mutant) cannot run in the page; the page skips such a mutant.
fn runs_in_the_page(vertex: &str) -> bool {
    !vertex.contains("VS_OUT")
}

#[test]
fn the_page_pair_check_gives_the_command_lines_verdicts() {
    let Some(browser) = browser_common::chromium() else { return };
    let Some(ctx) = gl_common::context_or_skip() else { return };
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("browser-pair-{}", std::process::id()));
    fs::create_dir_all(&dir).unwrap();
    let seed = lightlab::live::exercises::SEED;
    for model in [PairModel::PerFragment, PairModel::PerVertex] {
        let data = pair_json(model).unwrap();
        let started = std::time::Instant::now();
        let text = browser_common::run_page(&browser, &page(&dir, &data), "", "pair-result").unwrap();
        println!("{}: page run in {:.1} s", model.model(), started.elapsed().as_secs_f64());
        println!("{text}");
        let results: serde_json::Value = serde_json::from_str(&text).unwrap_or_else(|e| panic!("{e}: {text}"));
        assert_eq!(results["reference"]["verdict"], "agrees", "{}: {text}", model.model());
        let mut programs = vec![("reference".to_string(), data["reference"].clone())];
        programs.extend(
            data["mutants"].as_array().unwrap().iter().map(|m| (m["id"].as_str().unwrap().to_string(), m.clone())),
        );
        for (id, p) in programs {
            let (v, f) = (p["vertex"].as_str().unwrap(), p["fragment"].as_str().unwrap());
            if !runs_in_the_page(v) {
                continue;
            }
            let cli = pair::compile_pair(&ctx, v, f, model.model(), &Mapping::default()).unwrap();
            let checked = cli.check(N_PAIR_CASES, seed).unwrap();
            let verdict = if checked.report.agrees() { "agrees" } else { "disagrees" };
            let got = &results[&id];
            assert_eq!(got["verdict"], verdict, "{id} on {}: page {got}", model.model());
            // the same triangles fail: the page's colours (SwiftShader) and llvmpipe's are
            // both f32 runs of the same shaders, far from the bound on these triangles; not
            // where the shader's output is undefined in GLSL (pow of a negative base)
            if !lightlab::checker::mistakes::POW_OF_NEGATIVE.contains(&id.as_str()) {
                assert_eq!(got["failing"], checked.report.failing, "{id} on {}: page {got}", model.model());
            }
            if id != "reference" {
                let ids: Vec<&str> = got["ids"].as_array().unwrap().iter().filter_map(|x| x.as_str()).collect();
                // Exactly the mutant's own mistake, or the mistakes of its equivalence group
                // (view-dir-reversed and reflect-sign give the same colours bit for bit).
                let group = lightlab::checker::mistakes::EQUIVALENT
                    .iter()
                    .find(|e| e.ids.contains(&id.as_str()))
                    .map_or_else(|| vec![id.as_str()], |e| e.ids.to_vec());
                assert_eq!(ids, group, "{id} on {}: the page names {ids:?}", model.model());
            }
        }
    }
    let _ = fs::remove_dir_all(&dir);
}

/// The pair editors: a Gouraud pair typed into the two editors of a box checked as
/// Phong per fragment is named `gouraud-for-phong` (issue 24's Done-when), and both texts
/// are saved under the exercise's keys. `LIGHTLAB_PAIR_SHOTS=DIR` also writes the page
/// and screenshots it at 1200 and 390 px wide.
#[test]
fn a_gouraud_pair_in_the_editors_is_named() {
    let Some(browser) = browser_common::chromium() else { return };
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("browser-pair-box-{}", std::process::id()));
    fs::create_dir_all(&dir).unwrap();
    let data = pair_json(PairModel::PerFragment).unwrap();
    let (gv, gf) = pair::reference_pair(PairModel::PerVertex);
    let (rv, rf) = pair::reference_pair(PairModel::PerFragment);
    let live = Path::new(env!("CARGO_MANIFEST_DIR")).join("book/theme/live");
    let scripts: String = ["lightlab-i18n.js", "lightlab-gl.js", "lightlab-decision.js", "lightlab-pair.js"]
        .iter()
        .map(|s| format!("<script src=\"file://{}\"></script>\n", live.join(s).display()))
        .collect();
    let js = |s: &str| serde_json::Value::from(s).to_string().replace("</", "<\\/");
    let html = format!(
        "<!DOCTYPE html><html><head><link rel=\"stylesheet\" href=\"file://{css}\"></head><body style=\"margin:0\">\
         <div id=\"box\"></div><pre id=\"pair-result\"></pre>\n<script>window.LL_PAIR = {json};</script>\n{scripts}\
         <script>\n\
         var box = new LightlabPair.PairBox(document.getElementById('box'), window.LL_PAIR, 'pair-test', 'Phong per fragment', {{ vertex: {rv}, fragment: {rf} }});\n\
         var shot = location.search.indexOf('shot') >= 0;\n\
         if (!shot) {{ box.vertex.value = {gv}; box.fragment.value = {gf};\n\
           box.vertex.dispatchEvent(new Event('input')); box.fragment.dispatchEvent(new Event('input')); }}\n\
         var r = box.check();\n\
         var shown = Array.prototype.map.call(document.querySelectorAll('#box [data-mistake]'), function (li) {{ return li.getAttribute('data-mistake'); }});\n\
         document.getElementById('pair-result').textContent = JSON.stringify({{ verdict: r.verdict, error: r.error || null, shown: shown,\n\
           saved_vertex: localStorage.getItem('pair-test:vertex') === {gv}, saved_fragment: localStorage.getItem('pair-test') === {gf} }});\n\
         </script></body></html>\n",
        css = live.join("lightlab-live.css").display(),
        json = data.to_string().replace("</", "<\\/"),
        rv = js(rv), rf = js(rf), gv = js(gv), gf = js(gf),
    );
    let page = dir.join("pair-box.html");
    fs::write(&page, html).unwrap();
    let text = browser_common::run_page(&browser, &page, "", "pair-result").unwrap();
    let got: serde_json::Value = serde_json::from_str(&text).unwrap_or_else(|e| panic!("{e}: {text}"));
    assert_eq!(got["verdict"], "disagrees", "{text}");
    assert_eq!(got["shown"], serde_json::json!(["gouraud-for-phong"]), "{text}");
    assert_eq!(got["saved_vertex"], true, "{text}");
    assert_eq!(got["saved_fragment"], true, "{text}");
    if let Some(shots) = std::env::var_os("LIGHTLAB_PAIR_SHOTS") {
        fs::create_dir_all(&shots).unwrap();
        fs::copy(&page, Path::new(&shots).join("pair-box.html")).unwrap();
    }
    let _ = fs::remove_dir_all(&dir);
}
