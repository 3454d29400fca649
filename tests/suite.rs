//! The integration tests that need no built book, as one test binary: each `tests/NAME.rs`
//! is a module here, so the crate and its dependencies are linked once, not once per file
//! (49 binaries of about 100 MB each took minutes to link). `tests/book.rs`,
//! `tests/browser.rs` and `tests/browser_pair.rs` stay binaries of their own: each builds the
//! book once for its tests. Cargo.toml turns off the automatic discovery of test files
//! (`autotests = false`) and lists the four binaries, so a new `tests/NAME.rs` belongs either
//! here or in Cargo.toml: `every_test_file_is_compiled` below fails on one that is in neither.
//! Run one file's tests with `cargo test --test suite NAME::`.

#[path = "common/mod.rs"]
mod common;
#[path = "gl_common/mod.rs"]
mod gl_common;

#[path = "basic_lighting.rs"]
mod basic_lighting;
#[path = "bench_cli.rs"]
mod bench_cli;
#[path = "bench_llvmpipe.rs"]
mod bench_llvmpipe;
#[path = "bench_roofline.rs"]
mod bench_roofline;
#[path = "cli_exit_codes.rs"]
mod cli_exit_codes;
#[path = "cli_output_paths.rs"]
mod cli_output_paths;
#[path = "cli_shade_fuzz.rs"]
mod cli_shade_fuzz;
#[path = "colors.rs"]
mod colors;
#[path = "conventions.rs"]
mod conventions;
#[path = "culling.rs"]
mod culling;
#[path = "errata.rs"]
mod errata;
#[path = "example_args.rs"]
mod example_args;
#[path = "exercises.rs"]
mod exercises;
#[path = "failure_atlas.rs"]
mod failure_atlas;
#[path = "gl_book_report.rs"]
mod gl_book_report;
#[path = "gl_check_shader.rs"]
mod gl_check_shader;
#[path = "gl_diagnose.rs"]
mod gl_diagnose;
#[path = "gl_errata.rs"]
mod gl_errata;
#[path = "gl_layout.rs"]
mod gl_layout;
#[path = "gl_missing.rs"]
mod gl_missing;
#[path = "gl_models.rs"]
mod gl_models;
#[path = "gl_oracle.rs"]
mod gl_oracle;
#[path = "gl_pair.rs"]
mod gl_pair;
#[path = "gl_smoke.rs"]
mod gl_smoke;
#[path = "glsl.rs"]
mod glsl;
#[path = "grade_cli.rs"]
mod grade_cli;
#[path = "grade_formats.rs"]
mod grade_formats;
#[path = "grade_hostile.rs"]
mod grade_hostile;
#[path = "grade_mapping.rs"]
mod grade_mapping;
#[path = "grade_redteam.rs"]
mod grade_redteam;
#[path = "hostile.rs"]
mod hostile;
#[path = "i18n.rs"]
mod i18n;
#[path = "learner_corpus.rs"]
mod learner_corpus;
#[path = "light_casters.rs"]
mod light_casters;
#[path = "lighting_maps.rs"]
mod lighting_maps;
#[path = "materials.rs"]
mod materials;
#[path = "multiple_lights.rs"]
mod multiple_lights;
#[path = "normals.rs"]
mod normals;
#[path = "precision.rs"]
mod precision;
#[path = "raster_images.rs"]
mod raster_images;
#[path = "raster_kernel.rs"]
mod raster_kernel;
#[path = "raster_mesh.rs"]
mod raster_mesh;
#[path = "raster_pipeline.rs"]
mod raster_pipeline;
#[path = "raster_raycast.rs"]
mod raster_raycast;
#[path = "raster_scene_file.rs"]
mod raster_scene_file;
#[path = "shade_cli.rs"]
mod shade_cli;
#[path = "study_speed.rs"]
mod study_speed;
#[path = "tables.rs"]
mod tables;

/// Every `tests/*.rs` is compiled: a module of this binary or a `[[test]]` of Cargo.toml.
#[test]
fn every_test_file_is_compiled() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let suite = std::fs::read_to_string(dir.join("tests/suite.rs")).unwrap();
    let manifest = std::fs::read_to_string(dir.join("Cargo.toml")).unwrap();
    let mut missing = Vec::new();
    for entry in std::fs::read_dir(dir.join("tests")).unwrap() {
        let name = entry.unwrap().file_name().to_string_lossy().into_owned();
        let Some(stem) = name.strip_suffix(".rs") else { continue };
        let module = format!("#[path = \"{name}\"]\nmod {stem};");
        let binary = format!("path = \"tests/{name}\"");
        if stem != "suite" && !suite.contains(&module) && !manifest.contains(&binary) {
            missing.push(name);
        }
    }
    assert!(missing.is_empty(), "test files compiled by nothing (add them to tests/suite.rs): {missing:?}");
}
