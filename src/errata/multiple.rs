//! LearnOpenGL "Multiple lights", French (000) and Ukrainian (003).

use crate::casters::LocalLight as _;
use glam::Vec3;

use super::listings::{
    initializer_items, reserved_words_used, struct_fields, FR_DIRLIGHT, FR_DIRLIGHT_PROTOTYPE,
    FR_POINT_LIGHT_POSITIONS, OUTPUT_SKELETON, POINT_LIGHT_STRUCT, UK_DIRLIGHT, UK_POINT_LIGHT_POSITIONS,
};
use super::{cited, Entry};
use crate::scene::{Scene, POINT_LIGHT_POSITIONS};

/// Lines of a listing that are a bare word: no spaces, no punctuation a GLSL line ends with.
fn stray_labels(listing: &str) -> Vec<&str> {
    listing
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with("//") && l.chars().all(|c| c.is_ascii_alphanumeric() || c == '_'))
        .collect()
}

/// The `vec3(x, y, z)` of a printed `glm::vec3( x, y, z)` item.
fn parse_vec3(item: &str) -> Option<Vec3> {
    let inner = item.split_once('(')?.1.rsplit_once(')')?.0;
    let v: Vec<f32> = inner.split(',').map(|x| x.trim().trim_end_matches('f').parse().ok()).collect::<Option<_>>()?;
    (v.len() == 3).then(|| Vec3::new(v[0], v[1], v[2]))
}

/// The value of `#define NAME N` in `source`.
fn define(source: &str, name: &str) -> Option<usize> {
    source.lines().find_map(|l| l.trim().strip_prefix("#define ")?.strip_prefix(name)?.trim().parse().ok())
}

/// Every entry of this part.
pub(super) fn entries() -> Vec<Entry> {
    let scene = Scene::learnopengl_default();
    let lights =
        usize::from(scene.dir_light.is_some()) + scene.point_lights.len() + usize::from(scene.spot_light.is_some());
    let reserved = reserved_words_used(OUTPUT_SKELETON);
    let fr_labels: Vec<&str> =
        stray_labels(FR_DIRLIGHT).into_iter().chain(stray_labels(FR_DIRLIGHT_PROTOTYPE)).collect();
    let uk_labels = stray_labels(UK_DIRLIGHT);
    let nr = define(POINT_LIGHT_STRUCT, "NR_POINT_LIGHTS").unwrap_or(0);
    let fields = struct_fields(POINT_LIGHT_STRUCT).len();
    let fr_items = initializer_items(FR_POINT_LIGHT_POSITIONS);
    let uk_items = initializer_items(UK_POINT_LIGHT_POSITIONS);
    let uk_positions: Vec<Vec3> = uk_items.iter().filter_map(|i| parse_vec3(i)).collect();
    let point = scene.point_lights.first().copied();
    let material = crate::material::Material::coral();
    let (n, frag, view) = (Vec3::Y, Vec3::new(0.5, 0.0, 1.5), Vec3::Y);
    let one = point.map_or(0.0, |p| p.terms(&material, n, frag, view).sum().x);
    let two = scene.point_lights.iter().take(2).map(|p| p.terms(&material, n, frag, view).sum().x).sum::<f32>();
    vec![
        cited("six-lights", &[(0, 1183, 1183), (3, 1801, 1801)])
            .says("lights in the final scene: 1 directional + 4 point + 1 flashlight", "6")
            .number(lights as f64, "Scene::learnopengl_default()"),
        cited("output-reserved-word", &[(0, 1196, 1204), (3, 1828, 1860)])
            .says("the skeleton's accumulator is a GLSL variable", "vec3 output = vec3(0.0);")
            .holds(
                reserved.is_empty(),
                format!("GLSL 3.30 reserves {}", reserved.join(", ")),
                "output is a reserved word (GLSL 3.30 §3.6): the skeleton does not compile even with its placeholder \
                 functions defined (tests/gl_errata.rs); the English original has it too",
            ),
        cited("listing-labels-fr", &[(0, 1217, 1217), (0, 1230, 1230)])
            .says("the DirLight listings are GLSL", "c17_1_1 struct DirLight { … }; c17_1_2 vec3 CalcDirLight(…);")
            .holds(
                fr_labels.is_empty(),
                format!("stray lines {}", fr_labels.join(", ")),
                "the translation's listing labels were left inside the code blocks: as printed they do not compile \
                 (tests/gl_errata.rs)",
            ),
        cited("listing-labels-uk", &[(3, 1878, 1896)])
            .says(
                "the DirLight listings are GLSL",
                "struct DirLight { … }; vec3 CalcDirLight(DirLight light, vec3 normal, vec3 viewDir);",
            )
            .holds(uk_labels.is_empty(), "no stray lines; compiles (tests/gl_errata.rs)".into(), ""),
        cited(
            "four-point-lights",
            &[(0, 1276, 1280), (0, 1371, 1377), (3, 2002, 2009), (3, 2181, 2181), (3, 2207, 2211)],
        )
        .says("point lights (NR_POINT_LIGHTS, \"quatre\", 4 light cubes)", "4")
        .number(
            POINT_LIGHT_POSITIONS.len() as f64,
            &format!("scene::POINT_LIGHT_POSITIONS; #define NR_POINT_LIGHTS {nr} in the printed listing"),
        ),
        cited("uniform-calls-28", &[(0, 1352, 1352)])
            .says("glUniform calls to set every field of the four point lights", "28")
            .number(
                (fields * nr) as f64,
                &format!(
                    "{fields} fields of PointLight (l.1267-1275) × {nr} lights; the Ukrainian l.2179 drops the count"
                ),
            ),
        cited("point-light-positions-fr", &[(0, 1357, 1368)])
            .says(
                "pointLightPositions holds the four positions",
                "glm::vec3( 2.3f, -3.3f, -4.0f),\n};\n…\nglm::vec3( 0.0f, 0.0f, -3.0f)\n};",
            )
            .holds(
                fr_items.len() == POINT_LIGHT_POSITIONS.len(),
                format!("the initializer closes after {} positions; two more follow the closing }};", fr_items.len()),
                "the listing was split across two code blocks and the first one closed with };, so the array has two \
                 elements and the rest is a syntax error (tests/gl_errata.rs compiles it as a GLSL initializer list)",
            ),
        cited("point-light-positions-uk", &[(3, 2184, 2204)])
            .says(
                "pointLightPositions holds the four positions",
                "glm::vec3 pointLightPositions[] = { … four glm::vec3 … };",
            )
            .holds(uk_items.len() == POINT_LIGHT_POSITIONS.len(), format!("{} positions", uk_items.len()), ""),
        cited("point-light-position-values", &[(0, 1358, 1367), (3, 2188, 2200)])
            .says("the four positions", "(0.7, 0.2, 2.0), (2.3, -3.3, -4.0), (-4.0, 2.0, -12.0), (0.0, 0.0, -3.0)")
            .holds(
                uk_positions == POINT_LIGHT_POSITIONS,
                "equal to scene::POINT_LIGHT_POSITIONS".into(),
                "the same values in both texts",
            ),
        cited("lights-add-up", &[(0, 1208, 1208), (3, 1867, 1869)])
            .says(
                "a fragment near two lights is brighter than with one",
                "il sera plus clair que s'il n'est éclairé que par une seule source",
            )
            .holds(
                two > one,
                format!("red at a floor fragment: {one:.4} with the first point light, {two:.4} with two"),
                "casters::PointLight::terms",
            ),
        cited("spot-left-as-exercise", &[(0, 1337, 1342), (3, 2150, 2165)])
            .says(
                "main() adds the directional and the point lights; the spot function is the reader's exercise",
                "//result += CalcSpotLight(spotLight, norm, FragPos, viewDir);",
            )
            .holds(
                lights == 1 + nr + 1,
                format!("as printed main() adds 1 + {nr} lights; the flashlight of l.1183 is the sixth"),
                "",
            ),
    ]
}
