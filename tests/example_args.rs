//! The chapter examples take the chapter's numbers as arguments: parsing, the
//! errors a student sees, and tables whose notes print the values used.

#[path = "../examples/common/args.rs"]
mod args;

use args::{Args, Opt};
use glam::Vec3;
use lightlab::phong::BasicLighting;
use lightlab::tables::{basic_lighting, colors, Format};

const OPTIONS: [Opt; 2] = [
    Opt { name: "light-pos", value: "X,Y,Z", help: "lightPos" },
    Opt { name: "shininess", value: "S", help: "exponent" },
];

fn parse(args: &[&str]) -> Result<Option<Args>, String> {
    Args::parse(args.iter().map(|s| s.to_string()), &OPTIONS)
}

#[test]
fn good_arguments_are_read() {
    let a = parse(&["--light-pos", "2,1,0", "--shininess=64", "--format", "csv"]).unwrap().unwrap();
    assert_eq!(a.vec3("light-pos", Vec3::ZERO).unwrap(), Vec3::new(2.0, 1.0, 0.0));
    assert_eq!(a.number("shininess", 32.0).unwrap(), 64.0);
    assert_eq!(a.format, Format::Csv);
    // negative values are values, not flags
    let a = parse(&["--light-pos", "-1.5, 2, -3"]).unwrap().unwrap();
    assert_eq!(a.vec3("light-pos", Vec3::ZERO).unwrap(), Vec3::new(-1.5, 2.0, -3.0));
    // absent: the chapter's default
    let a = parse(&[]).unwrap().unwrap();
    assert_eq!(a.number("shininess", 32.0).unwrap(), 32.0);
    assert!(parse(&["--help"]).unwrap().is_none());
}

#[test]
fn bad_arguments_name_the_option() {
    let err = |args: &[&str], f: &dyn Fn(&Args) -> Result<(), String>| match parse(args) {
        Err(e) => e,
        Ok(Some(a)) => f(&a).unwrap_err(),
        Ok(None) => panic!("--help"),
    };
    let vec = |a: &Args| a.vec3("light-pos", Vec3::new(1.2, 1.0, 2.0)).map(|_| ());
    let num = |a: &Args| a.number_at_least("shininess", 32.0, 0.0).map(|_| ());
    type Check<'a> = &'a dyn Fn(&Args) -> Result<(), String>;
    let cases: [(&[&str], Check, &str); 8] = [
        (&["--light-pos", "2,1"], &vec, "--light-pos: expected three numbers x,y,z like 1.2,1,2, got \"2,1\""),
        (&["--light-pos", "2,1,0,5"], &vec, "--light-pos: expected three numbers"),
        (&["--light-pos", "2,inf,0"], &vec, "--light-pos: expected three numbers"),
        (&["--shininess", "shiny"], &num, "--shininess: expected a finite number like 32, got \"shiny\""),
        (&["--shininess", "NaN"], &num, "--shininess: expected a finite number"),
        (&["--shininess", "-4"], &num, "--shininess: must be at least 0, got -4"),
        (&["--shininess"], &num, "--shininess needs a value"),
        (&["--shine", "4"], &num, "unknown option --shine"),
    ];
    for (args, f, want) in cases {
        let e = err(args, f);
        assert!(e.starts_with(want), "{args:?}: {e:?} should start with {want:?}");
    }
}

#[test]
fn basic_lighting_notes_print_the_values_used() {
    let chapter = basic_lighting::tables();
    assert_eq!(chapter, basic_lighting::tables_for(&BasicLighting::learnopengl()));
    let mine = BasicLighting {
        light_pos: Vec3::new(2.0, 1.0, 0.0),
        ambient_strength: 0.2,
        shininess: 64.0,
        ..BasicLighting::learnopengl()
    };
    let t = basic_lighting::tables_for(&mine);
    assert!(t[0].note.contains("light at (2, 1, 0), eye at (0, 0, 3)"), "{}", t[0].note);
    assert!(t[0].note.contains("pow(max(v·r, 0), 64)"), "{}", t[0].note);
    assert!(t[1].note.starts_with("ambient = 0.2 · light ⊙ coral"), "{}", t[1].note);
    // and the numbers follow: the front centre's n·l changes with the light
    assert_ne!(t[0].rows[0], chapter[0].rows[0]);
    assert!(chapter[0].note.contains("light at (1.2, 1, 2)"));
}

#[test]
fn colors_take_an_object_and_a_light_of_your_own() {
    let t = &colors::tables_for(Vec3::new(0.2, 0.6, 0.9), Some(Vec3::new(0.5, 0.5, 0.5)))[0];
    assert_eq!(t.title, "Object (0.2, 0.6, 0.9) under colored lights");
    let last = t.rows.last().unwrap();
    assert_eq!(last[0], "yours");
    assert_eq!(last[3], "(0.1000, 0.3000, 0.4500)");
    // published values belong to coral only
    assert!(t.rows.iter().all(|r| r[2] == "—"));
    assert_eq!(colors::tables(), colors::tables_for(lightlab::color::CORAL, None));
}
