//! The chapter examples take the chapter's numbers as arguments: parsing, the
//! errors a student sees, and tables whose notes print the values used.

#[path = "../examples/common/args.rs"]
mod args;

use args::{Args, Opt};
use glam::Vec3;
use lightlab::phong::BasicLighting;
use lightlab::table::Format;
use lightlab::tables::{basic_lighting, colors};

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

#[test]
fn spotlight_and_attenuation_take_your_numbers() {
    use lightlab::casters::Attenuation;
    use lightlab::tables::{attenuation, spotlight};
    assert_eq!(spotlight::tables(), spotlight::tables_for(12.5, 17.5));
    let t = &spotlight::tables_for(10.0, 20.0)[2];
    assert_eq!(t.headers[2], "hard 10°");
    assert_eq!(t.headers[3], "soft 10°/20°");
    assert!(t.note.contains("your cut-offs 10°/20°"), "{}", t.note);
    // the outer cut-off is a row, where the soft edge reaches 0
    let at20 = t.rows.iter().find(|r| r[0] == "20").unwrap();
    assert_eq!(at20[3], "0.0000");
    let at10 = t.rows.iter().find(|r| r[0] == "10").unwrap();
    assert_eq!(at10[3], "1.0000");

    assert_eq!(attenuation::tables(), attenuation::tables_for(None));
    let a = Attenuation::new(1.0, 0.14, 0.07).unwrap();
    let t = attenuation::tables_for(Some(a));
    assert_eq!(t[0].rows.last().unwrap()[0], "yours");
    assert_eq!(t[1].headers.last().unwrap(), "F yours");
    // F(10) = 1 / (1 + 1.4 + 7) = 0.1064
    let at10 = t[1].rows.iter().find(|r| r[0] == "10").unwrap();
    assert_eq!(at10.last().unwrap(), "0.1064");
}

#[test]
fn specular_takes_your_exponent() {
    use lightlab::tables::specular;
    assert_eq!(specular::tables(), specular::tables_for(32.0));
    let t = specular::tables_for(50.0);
    assert_eq!(t[1].title, "Phong against Blinn-Phong at the same angles (s = 50)");
    assert_eq!(t[1].headers[1..4], ["Phong s=50", "Blinn s=50", "Blinn s=200 (4×)"]);
    // 50 joins the figure's exponents, in order, in the lobe and matching tables
    let rows: Vec<&str> = t[0].rows.iter().map(|r| r[0].as_str()).collect();
    assert_eq!(rows, ["2", "4", "8", "16", "32", "50", "64", "128", "256"]);
    assert_eq!(t[2].rows.len(), 9);
    // cos(10°)^50 = exp(50 · ln 0.984808) = exp(−0.765447) = 0.4651
    assert_eq!(t[0].rows[5][3], "0.4651");
}

#[test]
fn two_numbers_and_choices_are_read_and_bad_ones_named() {
    const MORE: [Opt; 2] =
        [Opt { name: "uv", value: "U,V", help: "uv" }, Opt { name: "atmosphere", value: "NAME", help: "which" }];
    let parse = |args: &[&str]| Args::parse(args.iter().map(|s| s.to_string()), &MORE).unwrap().unwrap();
    let a = parse(&["--uv", "0.3, 0.6", "--atmosphere", "Desert"]);
    assert_eq!(a.vec2("uv", "0.3,0.6").unwrap(), Some(glam::Vec2::new(0.3, 0.6)));
    assert_eq!(a.choice("atmosphere", &["factory", "desert"]).unwrap(), Some(1));
    assert_eq!(parse(&[]).vec2("uv", "0.3,0.6").unwrap(), None);
    let e = parse(&["--uv", "0.3"]).vec2("uv", "0.3,0.6").unwrap_err();
    assert_eq!(e, "--uv: expected two numbers u,v like 0.3,0.6, got \"0.3\"");
    let e = parse(&["--atmosphere", "sunset"]).choice("atmosphere", &["factory", "desert"]).unwrap_err();
    assert_eq!(e, "--atmosphere: expected one of factory, desert, got \"sunset\"");
}

#[test]
fn materials_take_a_light_of_your_own() {
    use lightlab::material::LightProps;
    use lightlab::tables::materials;
    assert_eq!(materials::tables(), materials::tables_for(materials::REFERENCE_LIGHT_POS, &LightProps::white()));
    let light = LightProps::learnopengl_materials();
    let t = &materials::tables_for(Vec3::new(2.0, 1.0, 0.0), &light)[1];
    assert!(
        t.note.contains("light at (2, 1, 0) with ambient (0.2, 0.2, 0.2), diffuse (0.5, 0.5, 0.5), specular (1, 1, 1)"),
        "{}",
        t.note
    );
    // emerald's ambient (0.0215, 0.1745, 0.0215) × the light's 0.2
    assert_eq!(t.rows[0][0], "emerald");
    assert_eq!(t.rows[0][1], "(0.0043, 0.0349, 0.0043)");
}

#[test]
fn lighting_maps_sample_your_uv_and_repeat_wraps_it() {
    use lightlab::tables::lighting_maps;
    assert_eq!(lighting_maps::tables(), lighting_maps::tables_for(None));
    let t = &lighting_maps::tables_for(Some(glam::Vec2::new(1.5, 0.5)))[0];
    let yours: Vec<&Vec<String>> = t.rows.iter().filter(|r| r[0] == "yours").collect();
    let centre: Vec<&Vec<String>> = t.rows.iter().filter(|r| r[0] == "centre").collect();
    assert_eq!(yours.len(), 2, "one row per filter");
    // GL_REPEAT: u = 1.5 samples the same texels as u = 0.5, through both filters
    for (y, c) in yours.iter().zip(&centre) {
        assert_eq!(y[1], "(1.5, 0.5)");
        assert_eq!(y[2..], c[2..]);
    }
}

#[test]
fn multiple_lights_show_one_atmosphere_and_your_fragment() {
    use lightlab::scene::Atmosphere;
    use lightlab::tables::{multiple_lights, Fragment};
    assert_eq!(multiple_lights::tables(), multiple_lights::tables_for(None, None));
    let front = multiple_lights::FRAGMENTS[0];
    let yours = Fragment { name: "yours", ..front };
    let t = multiple_lights::tables_for(Some(Atmosphere::Desert), Some(yours));
    assert_eq!(t.len(), 2);
    assert!(t[1].title.contains("desert"), "{}", t[1].title);
    // the same fragment under another name gives the same rows
    let of = |name: &str| -> Vec<Vec<String>> {
        t[1].rows.iter().filter(|r| r[0] == name).map(|r| r[1..].to_vec()).collect()
    };
    assert!(!of("yours").is_empty());
    assert_eq!(of("yours"), of(front.name));
}

#[test]
fn normal_matrix_takes_your_scale_and_normal() {
    use lightlab::tables::normal_matrix;
    assert_eq!(normal_matrix::tables(), normal_matrix::tables_for(None, Vec3::ONE));
    let t = normal_matrix::tables_for(Some(Vec3::new(1.0, 0.2, 1.0)), Vec3::new(1.0, 1.0, 0.0));
    let last = t[0].rows.last().unwrap();
    assert_eq!(last[0], "yours: scale (1, 0.2, 1)");
    let chapter = t[0].rows.iter().find(|r| r[0] == "scale (1, 0.2, 1)").unwrap();
    assert_eq!(last[1..], chapter[1..]);
    assert_eq!(t[1].title, "Inverse-transpose against cofactor, n = normalize(1, 1, 0)");
    // n ∝ (1, 1, 0) through scale (1, 0.2, 1): the normal matrix diag(1, 5, 1) gives
    // (1, 5, 0), normalized (1, 5, 0)/√26 = (0.1961, 0.9806, 0)
    assert_eq!(t[1].rows.last().unwrap()[2], "(0.1961, 0.9806, 0.0000)");
}

#[test]
fn conventions_move_the_light_for_all_three_models() {
    use lightlab::tables::conventions;
    assert_eq!(conventions::tables(), conventions::tables_for(BasicLighting::learnopengl().light_pos));
    let t = conventions::tables_for(Vec3::new(2.0, 1.0, 0.0));
    assert!(t[0].note.contains("white light at (2, 1, 0)"), "{}", t[0].note);
    assert!(t[0].note.contains("along −normalize(2, 1, 0)"), "{}", t[0].note);
    assert_ne!(t[0].rows, conventions::tables()[0].rows);
}
