//! LearnOpenGL "Basic lighting", "Materials" and "Lighting maps", French (000) and
//! Ukrainian (003).

use glam::{Mat3, Mat4, Vec3};

use super::listings::{struct_fields, MATERIAL_STRUCT};
use super::{cited, Entry};
use crate::material::{LightProps, Material};
use crate::phong::{diffuse_factor, lobe_half_width_deg, BasicLighting};

/// 003 l.907: the light's diffuse sentence and its specular sentence.
const UK_DIFFUSE_SENTENCE: &str =
    "Розсіяний компонент джерела світла зазвичай налаштований на точний колір, який ми хотіли б мати; часто яскраво-білого кольору.";
const UK_SPECULAR_SENTENCE: &str =
    "Дзеркальний компонент зазвичай налаштований на точний колір, який ми хотіли б мати; часто яскраво-білого кольору.";

/// The part of a sentence after "зазвичай" (usually).
fn after_usually(s: &str) -> &str {
    s.split_once("зазвичай").map_or(s, |(_, t)| t)
}

pub(super) fn basic_lighting() -> Vec<Entry> {
    let basic = BasicLighting::learnopengl();
    let n = Vec3::Z;
    let at = |deg: f32| {
        let r = deg.to_radians();
        diffuse_factor(n, Vec3::new(r.sin(), 0.0, r.cos()))
    };
    let falls = (0..180).all(|d| at(d as f32 + 1.0) <= at(d as f32));
    let l = Vec3::new(0.6, 0.0, 0.8);
    let model = Mat4::from_scale_rotation_translation(
        Vec3::splat(1.5),
        glam::Quat::from_axis_angle(Vec3::new(1.0, 0.3, 0.5).normalize(), 50f32.to_radians()),
        Vec3::new(1.0, 2.0, 3.0),
    );
    let normal = Vec3::new(0.0, 0.6, 0.8);
    let by_mat3 = Mat3::from_mat4(model) * normal;
    let by_w0 = (model * normal.extend(0.0)).truncate();
    let diag = |x: f32, y: f32, z: f32| Mat3::from_diagonal(Vec3::new(x, y, z));
    let slanted = Vec3::new(1.0, 1.0, 0.0).normalize();
    let uniform_err = crate::normals::model_matrix_normal_error_deg(diag(2.0, 2.0, 2.0), slanted).unwrap_or(f32::NAN);
    let stretch_err = crate::normals::model_matrix_normal_error_deg(diag(1.0, 2.0, 1.0), slanted).unwrap_or(f32::NAN);
    let stretch = diag(1.0, 2.0, 1.0);
    let tangent = Vec3::new(1.0, -1.0, 0.0);
    let fixed = crate::normals::normal_matrix_inverse_transpose(stretch).map(|m| m * slanted);
    let fixed_dot = fixed.map_or(f32::NAN, |nn| nn.dot(stretch * tangent));
    let eye = Vec3::new(2.0, 1.0, 3.0);
    let view = crate::raster::camera::look_at(eye, Vec3::ZERO, Vec3::Y).unwrap_or(Mat4::NAN);
    let eye_in_view = view.transform_point3(eye);
    let light_dir = Vec3::new(0.0, 0.6, 0.8);
    let reflected = crate::glsl::reflect(-light_dir, n);
    let widths: Vec<f32> = [8.0, 32.0, 128.0].iter().map(|&s| lobe_half_width_deg(s).unwrap_or(f32::NAN)).collect();
    let narrows = (1..=256).all(|s| {
        lobe_half_width_deg(s as f32 + 1.0).unwrap_or(f32::NAN) < lobe_half_width_deg(s as f32).unwrap_or(f32::NAN)
    });
    vec![
        cited("ambient-strength", &[(0, 261, 261), (3, 349, 349)])
            .says("ambientStrength", "0.1")
            .number(basic.ambient_strength as f64, "BasicLighting::learnopengl()"),
        cited(
            "diffuse-falls-with-angle",
            &[(0, 280, 280), (0, 384, 384), (0, 404, 404), (3, 380, 388), (3, 539, 539), (3, 567, 567)],
        )
        .says(
            "the larger the angle between normal and light, the darker the fragment",
            "plus l'angle θ sera grand, moins la lumière aura d'effet",
        )
        .holds(
            falls,
            format!("max(n·l, 0) = {:.3} at 0°, {:.3} at 60°, {:.3} at 90° and after", at(0.0), at(60.0), at(90.0)),
            "diffuse_factor non-increasing over 0°…180° in 1° steps",
        ),
        cited("dot-needs-unit-vectors", &[(0, 284, 284), (3, 390, 394)])
            .says(
                "with non-unit vectors the dot product is more than the cosine",
                "sinon le produit scalaire donnerait une valeur différente",
            )
            .holds(
                (2.0 * n).dot(l) != n.dot(l),
                format!("dot(2n, l) = {:.2} where cos = {:.2}", (2.0 * n).dot(l), n.dot(l)),
                "scaling one vector scales the dot product",
            ),
        cited("diffuse-negative-past-90", &[(0, 391, 391), (3, 549, 549)])
            .says(
                "beyond 90° the dot product is negative, max(…, 0) keeps it at 0",
                "Si l'angle entre les deux vecteurs est supérieur à 90°, le produit scalaire est négatif",
            )
            .holds(
                n.dot(Vec3::new(120f32.to_radians().sin(), 0.0, 120f32.to_radians().cos())) < 0.0 && at(120.0) == 0.0,
                format!(
                    "n·l = {:.2} at 120°, diffuse_factor = {}",
                    n.dot(Vec3::new(120f32.to_radians().sin(), 0.0, 120f32.to_radians().cos())),
                    at(120.0)
                ),
                "",
            ),
        cited("normal-w0-equals-mat3", &[(0, 412, 412), (3, 575, 575)])
            .says(
                "dropping the translation (mat3) is the same as w = 0 with the 4×4 matrix",
                "on pourrait aussi donner la valeur 0 à la composante w de la normale",
            )
            .holds(
                (by_mat3 - by_w0).length() < 1e-6,
                format!("|mat3(M)·n − (M·(n,0)).xyz| = {:.1e} for a translated model", (by_mat3 - by_w0).length()),
                "the fourth column only meets w",
            ),
        cited("uniform-scale-keeps-normals", &[(0, 418, 418), (3, 583, 583)])
            .says(
                "a uniform scale changes the normals' length, not their direction",
                "une mise à l'échelle uniforme ne modifie pas la direction des normales",
            )
            .holds(
                uniform_err < 1e-3,
                format!("model-matrix normal off by {uniform_err:.4}° under scale 2"),
                "normals::model_matrix_normal_error_deg",
            ),
        cited("nonuniform-scale-bends-normals", &[(0, 414, 418), (3, 577, 583)])
            .says(
                "a non-uniform scale leaves the model-matrix normal off the perpendicular",
                "les normales ne sont plus perpendiculaires aux surfaces",
            )
            .holds(
                stretch_err > 1.0,
                format!("scale (1, 2, 1): a 45° normal comes out {stretch_err:.2}° off"),
                "normals::model_matrix_normal_error_deg",
            ),
        cited("normal-matrix-restores", &[(0, 422, 427), (3, 587, 594)])
            .says(
                "transpose(inverse(mat3(model))) keeps normals perpendicular",
                "Normal = mat3(transpose(inverse(model))) * aNormal;",
            )
            .holds(
                fixed_dot.abs() < 1e-5,
                format!("dot(N·n, M·t) = {fixed_dot:.1e} for scale (1, 2, 1)"),
                "normals::normal_matrix_inverse_transpose",
            ),
        cited("view-space-viewer-at-origin", &[(0, 450, 450), (3, 617, 617)])
            .says("in view space the viewer is at the origin", "la position du spectateur est toujours (0, 0, 0)")
            .holds(
                eye_in_view.length() < 1e-5,
                format!("look_at(eye)·eye = {:?}", eye_in_view.to_array().map(|c| (c * 1e5).round() / 1e5)),
                "",
            ),
        cited("specular-strength", &[(0, 465, 465), (3, 634, 634)])
            .says("specularStrength", "0.5")
            .number(basic.specular_strength as f64, "BasicLighting::learnopengl()"),
        cited("reflect-wants-incident", &[(0, 475, 475), (3, 647, 647)])
            .says(
                "reflect() takes the vector from the light to the fragment, hence -lightDir",
                "vec3 reflectDir = reflect(-lightDir, norm);",
            )
            .holds(
                (reflected.dot(n) - light_dir.dot(n)).abs() < 1e-6 && (reflected + light_dir).cross(n).length() < 1e-6,
                "reflect(−l, n) leaves the surface at the angle l arrived: r·n = l·n, r + l ∥ n".into(),
                "glsl::reflect",
            ),
        cited(
            "shininess-32",
            &[(0, 480, 480), (0, 484, 488), (0, 583, 586), (3, 652, 652), (3, 659, 662), (3, 844, 847)],
        )
        .says("the shininess of the chapter's examples", "32")
        .number(Material::coral().shininess as f64, "Material::coral(); the same in code and prose of both texts"),
        cited("shininess-narrows-highlight", &[(0, 484, 484), (3, 659, 659)])
            .says(
                "the higher the shininess, the narrower the highlight",
                "Plus grande est cette valeur …, plus la lumière sera reflétée dans une direction précise",
            )
            .holds(
                narrows,
                format!(
                    "half-width of cos^s: {:.1}° at s = 8, {:.1}° at 32, {:.1}° at 128",
                    widths[0], widths[1], widths[2]
                ),
                "phong::lobe_half_width_deg, decreasing for s = 1…257",
            ),
    ]
}

pub(super) fn materials() -> Vec<Entry> {
    let coral = Material::coral();
    let props = LightProps::learnopengl_materials();
    let named = ["emerald", "pearl", "bronze", "gold", "cyan plastic", "red plastic", "green rubber", "yellow rubber"];
    let found = named.iter().filter(|n| crate::material::classic_material(n).is_some()).count();
    let cyan = crate::material::classic_material("cyan plastic").map_or(f64::NAN, |m| m.shininess() as f64);
    let samples = 10_000;
    let negative = (0..samples)
        .filter(|i| LightProps::time_varying(*i as f32 * std::f32::consts::TAU / samples as f32).diffuse.x < 0.0)
        .count() as f64
        / samples as f64;
    let t = 0.3f32;
    let ratio = LightProps::time_varying(t).ambient.x / (2.0 * t).sin();
    vec![
        cited("material-four-properties", &[(0, 541, 541), (3, 739, 739)])
            .says("properties of the Material struct", "4")
            .number(
                struct_fields(MATERIAL_STRUCT).len() as f64,
                "fields of the printed struct (l.527-534): ambient, diffuse, specular, shininess",
            ),
        cited("material-coral-values", &[(0, 580, 583), (3, 832, 844)])
            .says(
                "the coral material set from the application",
                "material.ambient 1.0, 0.5, 0.31; diffuse 1.0, 0.5, 0.31; specular 0.5; shininess 32.0",
            )
            .holds(
                coral.ambient == crate::color::CORAL
                    && coral.diffuse == crate::color::CORAL
                    && coral.specular == Vec3::splat(0.5)
                    && coral.shininess == 32.0,
                "Material::coral() holds the same values".into(),
                "",
            ),
        cited("eight-materials-named", &[(0, 541, 541)])
            .says("materials named under the figure, found in the classic table", "8")
            .number(
                found as f64,
                "émeraude, perle, bronze, or, plastique cyan, plastique rouge, gomme verte, gomme jaune: all in \
                 material::CLASSIC_MATERIALS",
            ),
        cited("cyan-plastic-shininess", &[(0, 675, 675), (3, 994, 994)])
            .says("cyan plastic shininess of the exercise's solution (table 0.25 × 128)", "32")
            .number(cyan, "the table's shininess is a fraction of 128"),
        cited("light-properties", &[(0, 638, 641), (3, 932, 940)])
            .says(
                "the light's ambient, diffuse and specular intensities",
                "light.ambient 0.2f; light.diffuse 0.5f; light.specular 1.0f",
            )
            .holds(
                props.ambient == Vec3::splat(0.2) && props.diffuse == Vec3::splat(0.5) && props.specular == Vec3::ONE,
                "LightProps::learnopengl_materials() = (0.2, 0.5, 1.0)".into(),
                "",
            ),
        cited("light-specular-sentence-fr", &[(0, 625, 625)])
            .says(
                "the light's specular is usually vec3(1.0) at full intensity",
                "La composante spéculaire est en général définie par un vec3(1.0) brillant à pleine intensité",
            )
            .holds(props.specular == Vec3::ONE, "LightProps::learnopengl_materials().specular = (1, 1, 1)".into(), ""),
        cited("light-specular-sentence-uk", &[(3, 907, 910)])
            .says("the light's specular is usually vec3(1.0) at full intensity", UK_SPECULAR_SENTENCE)
            .holds(
                after_usually(UK_SPECULAR_SENTENCE) != after_usually(UK_DIFFUSE_SENTENCE),
                "specular = vec3(1.0), full intensity (the code at l.940 sets 1.0)".into(),
                "the specular sentence repeats the diffuse one word for word; vec3(1.0) is left dangling on l.910",
            ),
        cited("animated-light-goes-negative", &[(0, 660, 666), (3, 958, 978)])
            .says("the animated light color is a color", "lightColor.x = sin(glfwGetTime() * 2.0f);")
            .holds(
                negative == 0.0,
                format!("diffuse.x < 0 for {:.1} % of a period: negative light that darkens", 100.0 * negative),
                "sin() spans [−1, 1]; the listing never clamps or offsets it (0.5 + 0.5·sin would stay a color)",
            ),
        cited("animated-ambient-is-0.1", &[(0, 665, 666), (3, 974, 978)])
            .says(
                "ambient = 0.2 × diffuse = 0.2 × 0.5 × light: the Basic lighting ambient strength",
                "diffuseColor = lightColor * glm::vec3(0.5f); ambientColor = diffuseColor * glm::vec3(0.2f);",
            )
            .holds(
                (ratio - BasicLighting::learnopengl().ambient_strength).abs() < 1e-6,
                format!("ambient / light = {ratio:.4}"),
                "LightProps::time_varying",
            ),
        cited("sin-name-fr", &[(0, 658, 658)])
            .says("the animation uses sin() and glfwGetTime()", "au moyen des fonctions `sin()` et `glfwGetTime()`")
            .holds(true, "sin and glfwGetTime, as in the listing".into(), ""),
        cited("sin-name-uk", &[(3, 688, 688), (3, 955, 955)])
            .says("the animation uses sin() and glfwGetTime()", "`grіx` або `cos`; за допомогою `rpixiglfwGetTime`")
            .holds(
                "`grіx` або `cos`".contains("sin"),
                "sin (the listing at l.962 calls sin)".into(),
                "the function name sin was translated as the word гріх (a moral sin), then transliterated and glued \
                 to glfwGetTime",
            ),
    ]
}

pub(super) fn maps() -> Vec<Entry> {
    let struct_without_ambient = "struct Material {\nsampler2D diffuse;\nvec3    specular;\nfloat    shininess;\n};";
    let fields = struct_fields(struct_without_ambient);
    vec![
        cited("material-drops-ambient", &[(0, 705, 715), (3, 1020, 1039)])
            .says("the ambient vector is removed from Material", "sampler2D diffuse; vec3 specular; float shininess;")
            .holds(
                !fields.iter().any(|f| f == "ambient") && fields.len() == 3,
                format!("fields: {}", fields.join(", ")),
                "ambient is sampled from the diffuse map (l.731, 003 l.1061)",
            ),
        cited("opaque-struct-parameter", &[(0, 703, 703), (3, 1018, 1018)])
            .says(
                "a struct holding a sampler2D fails when used other than as a uniform, \"like a function parameter\"",
                "Si l'on instanciat cette structure autrement que par une variable uniforme (comme un paramètre de \
                 fonction), GLSL donnerait des erreurs étranges",
            )
            .holds(
                false,
                "opaque types may be function parameters or uniforms (GLSL 3.30 §4.1.7): a Material parameter \
                 compiles, a local Material does not"
                    .into(),
                "the example is the one case that works: llvmpipe compiles the struct as a function parameter and \
                 rejects a local copy (tests/gl_errata.rs); the English original says the same",
            ),
        cited("texture-units", &[(0, 755, 758), (0, 794, 797), (3, 1115, 1127), (3, 1165, 1177)])
            .says(
                "each sampler's unit matches the texture bound to it",
                "setInt(\"material.diffuse\", 0) … GL_TEXTURE0; setInt(\"material.specular\", 1) … GL_TEXTURE1",
            )
            .holds(true, "unit 0 holds diffuseMap, unit 1 holds specularMap".into(), ""),
        cited("tires-fr", &[(0, 685, 685)]).says("tyres are dull, so no highlight", "les pneus sont ternes").holds(
            true,
            "a dull material has a small specular".into(),
            "",
        ),
        cited("tires-uk", &[(3, 1000, 1000)])
            .says(
                "tyres are dull, so no highlight",
                "його шини майже блискучі, тому на них немає дзеркальних відблисків",
            )
            .holds(
                "його шини майже блискучі".contains("не блискучі"),
                "\"almost shiny, so no highlights\" contradicts itself: the original says almost entirely non-shiny"
                    .into(),
                "a dropped negation in the translation",
            ),
    ]
}
