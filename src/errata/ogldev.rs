//! ogldev tutorial 19 "specular lighting" (French, seed 002).

use glam::Vec3;

use super::listings::{OGLDEV_FRAGMENT_OUTPUT, OGLDEV_SPECULAR, OGLDEV_TECHNIQUE, OGLDEV_UNIFORMS, OGLDEV_VERTEX};
use super::{cited, Entry};
use crate::glsl::reflect;

/// The lines of a listing that are statements or declarations (ending in `;`).
fn statement_lines(listing: &str) -> Vec<&str> {
    listing.lines().map(str::trim).filter(|l| l.ends_with(';')).collect()
}

/// The names a listing introduces as `out` variables or assigns that appear in `new_names`.
fn lines_mentioning<'a>(listing: &'a str, name: &str) -> Vec<&'a str> {
    statement_lines(listing).into_iter().filter(|l| l.contains(name)).collect()
}

/// Every entry of this part.
pub(super) fn entries() -> Vec<Entry> {
    let n = Vec3::Y;
    let i = Vec3::new(0.6, -0.8, 0.0); // incident, toward the surface
    let r = reflect(i, n);
    let v_vec = 2.0 * n * (-n.dot(i));
    let by_formula = i + v_vec;
    let cos = |deg: f64| deg.to_radians().cos();
    let falls = (0..90).all(|d| cos(d as f64 + 1.0) < cos(d as f64));
    // The crate's ogldev light with the tutorial's power 32, shining straight down.
    let model = crate::models::Ogldev {
        direction: Vec3::NEG_Y,
        specular_intensity: 1.0,
        ..crate::models::ogldev_comparable(Vec3::Y)
    };
    let wood = crate::models::Ogldev { specular_intensity: 0.0, ..model };
    let eye_on_ray = Vec3::new(0.0, 5.0, 0.0);
    let lit = model.terms(Vec3::ZERO, n, eye_on_ray);
    let dark_wood = wood.terms(Vec3::ZERO, n, eye_on_ray);
    let half = |p: f32| crate::phong::lobe_half_width_deg(p).unwrap_or(f32::NAN);
    let new_members = OGLDEV_TECHNIQUE.lines().filter(|l| l.contains("Set") || l.contains("Location;")).count();
    let world_pos_lines = lines_mentioning(OGLDEV_VERTEX, "WorldPos0");
    let uniforms = statement_lines(OGLDEV_UNIFORMS).len();
    let pow_first = OGLDEV_SPECULAR.find("pow(").unwrap_or(usize::MAX) < OGLDEV_SPECULAR.find("> 0").unwrap_or(0);
    let ghost = crate::models::ogldev_specular_c_powf(-0.5, 32.0);
    let glsl = crate::models::ogldev_specular_glsl(-0.5, 32.0);
    vec![
        cited("five-things", &[(2, 49, 55)])
            .says("things to watch in the figure (I, N, R, V, α)", "5")
            .number(["« I »", "« N »", "« R »", "« V »", "« α »"].len() as f64, "the five bullets l.51-55"),
        cited("reflection-same-angle", &[(2, 41, 41), (2, 53, 53)])
            .says(
                "the light leaves at the angle it arrived, on the other side of the normal",
                "elle est aussi réfléchie avec le même angle (du côté opposé par rapport à la normale)",
            )
            .holds(
                (r.dot(n) + i.dot(n)).abs() < 1e-6 && (r.x - i.x).abs() < 1e-6,
                format!("I = {:?}, R = reflect(I, N) = {:?}", i.to_array(), r.to_array()),
                "glsl::reflect",
            ),
        cited("alpha-zero-maximum", &[(2, 57, 57)])
            .says(
                "α = 0: the cosine is 1, the maximum",
                "Quand « α » vaut zéro, son cosinus vaut un, ce qui est le facteur maximum",
            )
            .holds(cos(0.0) == 1.0, "cos 0 = 1".into(), ""),
        cited("alpha-decreases", &[(2, 57, 57)])
            .says(
                "as α moves from 0 to 90°, its cosine shrinks",
                "Quand « α » diminue, son cosinus devient plus petit jusqu'à ce que « α » atteigne 90 degrés",
            )
            .holds(
                !falls,
                format!(
                    "cos is decreasing on [0°, 90°]: {:.3} at 0°, {:.3} at 45°, {:.3} at 90°",
                    cos(0.0),
                    cos(45.0),
                    cos(90.0)
                ),
                "the cosine gets smaller as α *increases* toward 90° (\"diminue\" should read \"augmente\"); the \
                 sentence before says so",
            ),
        cited("alpha-past-90", &[(2, 57, 57)])
            .says(
                "beyond 90° the cosine is negative: no specular",
                "Quand « α » vaut plus de 90 degrés, le cosinus devient négatif",
            )
            .holds(cos(120.0) < 0.0, format!("cos 120° = {:.2}", cos(120.0)), ""),
        cited("view-vector", &[(2, 54, 54), (2, 59, 59), (2, 202, 202), (2, 216, 216)])
            .says(
                "V = eye position − surface point (world space)",
                "vec3 VertexToEye = normalize(gEyeWorldPos - WorldPos0);",
            )
            .holds(true, "from the point to the eye, as LearnOpenGL's viewDir".into(), ""),
        cited("opposite-normal-symbol", &[(2, 65, 65)])
            .says(
                "the opposite of the normal N appears as −N",
                "Notons que l'opposée à la normale « V » apparaît aussi comme « -N »",
            )
            .holds(
                "l'opposée à la normale « V »".contains("« N »"),
                "the normal is « N » (l.52)".into(),
                "translation slip: the normal is called « V », the letter l.54 gives the eye vector and this \
                 paragraph gives the vector 2N(−N·I)",
            ),
        cited("projection-half", &[(2, 65, 65)])
            .says("|I·(−N)| over the length of V = 2N(−N·I)", "0.5")
            .number((i.dot(-n) / v_vec.length()) as f64, "\"Cette norme est exactement la moitié de la norme de V\""),
        cited("v-along-n", &[(2, 65, 65)])
            .says("V = 2N(−N·I) has the direction of N", "Comme « V » a la même direction que « N »")
            .holds(v_vec.normalize().dot(n) > 0.999_999, "−N·I > 0 for light arriving at the surface".into(), ""),
        cited("reflection-formula", &[(2, 67, 67), (2, 69, 69)])
            .says(
                "R = I + 2N(−N·I) = I − 2N(N·I), which GLSL's reflect computes",
                "R = I + 2 × N × (-N.I) = I - 2 × N × (N.I)",
            )
            .holds(
                (by_formula - r).length() < 1e-6,
                format!("|formula − reflect(I, N)| = {:.1e}", (by_formula - r).length()),
                "glsl::reflect",
            ),
        cited("zero-intensity-no-specular", &[(2, 73, 75)])
            .says(
                "a material with specular intensity 0 (wood) has no specular",
                "aura une intensité spéculaire de zéro, ce qui mettra à zéro le résultat",
            )
            .holds(
                dark_wood.specular == Vec3::ZERO && lit.specular.x > 0.0,
                format!(
                    "specular {} with M = 0, {:.3} with M = 1 on the mirror ray",
                    dark_wood.specular.x, lit.specular.x
                ),
                "models::Ogldev::terms",
            ),
        cited("power-narrows", &[(2, 75, 79)])
            .says(
                "the specular power sharpens the highlight (shown at 1 and 32)",
                "Son travail est d'intensifier et d'affiner les bords",
            )
            .holds(
                half(32.0) < half(1.0),
                format!("half-width {:.1}° at P = 1, {:.1}° at P = 32", half(1.0), half(32.0)),
                "phong::lobe_half_width_deg",
            ),
        cited("power-32", &[(2, 79, 79), (2, 227, 227)])
            .says("the specular power of the image and of the code", "32")
            .number(
                model.specular_power as f64,
                "SetMatSpecularPower(32), and lightlab's ogldev light (tables::conventions::ogldev_comparable)",
            ),
        cited("three-new-members", &[(2, 106, 116)])
            .says("new members of LightingTechnique, per kind", "3")
            .number((new_members / 2) as f64, "three setters and three uniform locations"),
        cited("one-new-vertex-line", &[(2, 129, 139)])
            .says(
                "the vertex shader has one new line, the last",
                "Le vertex shader ci-dessus intègre une seule nouvelle ligne (la dernière)",
            )
            .holds(
                world_pos_lines.len() == 1,
                format!("WorldPos0 is new in {} lines: {}", world_pos_lines.len(), world_pos_lines.join(" and ")),
                "the out declaration (l.129) is new too",
            ),
        cited("normal-through-world-matrix", &[(2, 135, 135), (2, 139, 139)])
            .says("the world matrix transforms the normal", "Normal0 = (gWorld * vec4(Normal, 0.0)).xyz;")
            .holds(
                crate::normals::model_matrix_normal_error_deg(
                    glam::Mat3::from_diagonal(Vec3::splat(2.0)),
                    i.normalize(),
                )
                .is_some_and(|e| e < 1e-3),
                "right for rotations and uniform scale; a non-uniform scale needs the normal matrix".into(),
                "holds for the tutorial's transforms",
            ),
        cited("fragment-not-vertex", &[(2, 211, 211), (2, 214, 214)])
            .says(
                "the shader with the three new uniforms is the fragment shader",
                "Il y a plusieurs changements dans le vertex shader",
            )
            .holds(
                // A shader that writes the fragment's color is a fragment shader.
                !OGLDEV_FRAGMENT_OUTPUT.starts_with("FragColor"),
                "the listing described (l.178-212) ends by writing FragColor (l.211): a fragment shader".into(),
                "\"vertex shader\" should read \"fragment shader\"",
            ),
        cited("three-new-uniforms", &[(2, 182, 184), (2, 214, 214)])
            .says("new uniforms", "3")
            .number(uniforms as f64, "gEyeWorldPos, gMatSpecularIntensity, gSpecularPower"),
        cited("reflect-original-direction", &[(2, 203, 203), (2, 216, 216)])
            .says(
                "reflect the original light vector (toward the surface), not the one of the diffuse factor",
                "vec3 LightReflect = normalize(reflect(gDirectionalLight.Direction, Normal));",
            )
            .holds(
                reflect(model.direction, n).dot(n) > 0.0 && reflect(-model.direction, n).dot(n) < 0.0,
                "reflect(Direction, N) leaves the surface; reflect(−Direction, N) would point into it".into(),
                "same as LearnOpenGL's reflect(−lightDir, norm)",
            ),
        cited("pow-before-test", &[(2, 204, 208), (2, 218, 218)])
            .says(
                "the test keeps the specular only where the dot product is positive",
                "SpecularFactor = pow(SpecularFactor, gSpecularPower); if (SpecularFactor > 0) {",
            )
            .holds(
                !pow_first,
                format!(
                    "the code tests pow(dot, P), not dot: for dot = −0.5, P = 32 a C powf gives {ghost:.2e} > 0 (a \
                     highlight on the far side), GLSL's domain gives {glsl}"
                ),
                "the text (l.218) says the dot product is checked, the code checks the power: on llvmpipe pow(−0.5, \
                 32) is not a number, so the highlight is dropped by accident, a C-like pow lights the far side \
                 (tests/gl_errata.rs, failure atlas case 2)",
            ),
    ]
}
