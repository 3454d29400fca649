//! Scene files: a good file renders; a bad one names its line and field.
#![cfg(feature = "book")]

use lightlab::raster::framebuffer::Framebuffer;
use lightlab::raster::scene_file::{parse, SceneFileError};

#[test]
fn the_example_scene_file_renders() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/images/scenes/gold-torus.toml");
    let world = lightlab::raster::scene_file::load(&path, 4.0 / 3.0).unwrap();
    assert_eq!(world.objects.len(), 2);
    assert_eq!(world.lights.point_lights.len(), 5);
    let mut fb = Framebuffer::new(80, 60).unwrap();
    world.render(&mut fb);
    // the torus fills part of the frame
    let covered = fb.color.iter().filter(|c| c[0] > 0.06).count();
    assert!(covered > 200, "only {covered} lit pixels");
}

fn error(text: &str) -> SceneFileError {
    match parse(text, 1.0) {
        Ok(_) => panic!("expected an error for:\n{text}"),
        Err(e) => e,
    }
}

#[test]
fn bad_files_name_line_and_field() {
    let e = error("[[object]]\nmesh = \"cubee\"\n");
    assert_eq!((e.line, e.field.as_str()), (Some(2), "object[0].mesh"), "{e}");
    assert!(e.to_string().starts_with("line 2: object[0].mesh: unknown mesh"), "{e}");

    let e = error("[[object]]\nmesh = \"cube\"\ncolour = 3\n");
    assert_eq!(e.line, Some(3), "{e}");
    assert!(e.reason.contains("colour"), "{e}");

    let e = error("shading = \"toon\"\n[[object]]\nmesh = \"cube\"\n");
    assert_eq!((e.line, e.field.as_str()), (Some(1), "shading"), "{e}");

    let spot = "[[object]]\nmesh = \"cube\"\n[lights]\n[lights.spot]\nposition = [0.0, 0.0, 3.0]\ndirection = [0.0, 0.0, -1.0]\ncut_off_deg = 20.0\nouter_cut_off_deg = 10.0\nambient = [0.0, 0.0, 0.0]\ndiffuse = [1.0, 1.0, 1.0]\nspecular = [1.0, 1.0, 1.0]\n";
    let e = error(spot);
    assert_eq!(e.field, "lights.spot.cut_off_deg", "{e}");
    assert!(e.line.is_some_and(|l| (4..=11).contains(&l)), "{e}");

    let e = error("[[object]]\nmesh = \"cube\"\n[[lights.point]]\nposition = [0.0, 0.0, 0.0]\nambient = [0.0, 0.0, 0.0]\ndiffuse = [1.0, 1.0, 1.0]\nspecular = [1.0, 1.0, 1.0]\nattenuation = [1.0, -0.1, 0.0]\n");
    assert_eq!((e.line, e.field.as_str()), (Some(8), "lights.point[0].attenuation"), "{e}");

    let e = error("[camera]\neye = [0.0, 0.0, 3.0]\ntarget = [0.0, 0.0, 3.0]\n[[object]]\nmesh = \"cube\"\n");
    assert_eq!(e.field, "camera.target", "{e}");

    let e = error("[[object]]\nmesh = \"cube\"\nmaterial = \"unobtainium\"\n");
    assert_eq!((e.line, e.field.as_str()), (Some(3), "object[0].material"), "{e}");

    let e = error("clear = [1.0, 2.0]\n[[object]]\nmesh = \"cube\"\n");
    assert_eq!(e.line, Some(1), "{e}");

    let e = error("");
    assert_eq!(e.field, "object", "{e}");
}
