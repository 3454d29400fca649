//! LearnOpenGL "Colors" and the scene set-up, French (000) and Ukrainian (003).

use glam::{DVec3, Mat4, Vec3, Vec4};

use super::{cited, Entry};
use crate::reference::color::modulate;

/// The color products of the Colors chapter, and the coral constant.
pub(super) fn products() -> Vec<Entry> {
    let src: &[(u8, u32, u32)] = &[(0, 100, 100), (0, 108, 108), (0, 116, 116), (3, 52, 52), (3, 66, 66), (3, 80, 80)];
    let coral = crate::reference::dvec3(crate::color::CORAL);
    let white = modulate(DVec3::ONE, coral);
    let green = modulate(DVec3::new(0.0, 1.0, 0.0), coral);
    let olive = modulate(DVec3::new(0.33, 0.42, 0.18), coral);
    let coral_places: &[(u8, u32, u32)] = &[
        (0, 83, 83),
        (0, 99, 99),
        (0, 107, 107),
        (0, 115, 115),
        (0, 178, 178),
        (0, 580, 581),
        (3, 30, 30),
        (3, 48, 48),
        (3, 62, 62),
        (3, 76, 76),
        (3, 221, 221),
        (3, 832, 836),
    ];
    let printed = Vec3::new(1.0, 0.5, 0.31);
    vec![
        cited("coral-constant", coral_places)
            .says("the coral color, printed in 12 places", "coral(1.0f, 0.5f, 0.31f)")
            .holds(
                crate::color::CORAL == printed && crate::material::Material::coral().diffuse == printed,
                format!("color::CORAL = {:?}, Material::coral() uses it", crate::color::CORAL.to_array()),
                "the same three numbers everywhere, in both texts",
            ),
        cited("color-white-r", src).says("white × coral, red", "1.0").number(white.x, "exact"),
        cited("color-white-g", src).says("white × coral, green", "0.5").number(white.y, "exact"),
        cited("color-white-b", src).says("white × coral, blue", "0.31").number(white.z, "exact"),
        cited("color-green-r", src).says("green × coral, red", "0.0").number(green.x, "exact"),
        cited("color-green-g", src).says("green × coral, green", "0.5").number(green.y, "exact"),
        cited("color-green-b", src).says("green × coral, blue", "0.0").number(green.z, "exact"),
        cited("color-olive-r", src).says("(0.33, 0.42, 0.18) × coral, red", "0.33").number(olive.x, "exact"),
        cited("color-olive-g", src).says("(0.33, 0.42, 0.18) × coral, green", "0.21").number(olive.y, "exact"),
        cited("color-olive-b", src)
            .says("(0.33, 0.42, 0.18) × coral, blue", "0.06")
            .number(olive.z, &format!("0.18 × 0.31 = {:.4}, printed rounded to two decimals", olive.z)),
        cited("color-green-half", &[(0, 111, 111), (3, 69, 69)])
            .says("share of the green light the coral toy reflects (\"absorbée pour moitié\")", "0.5")
            .number(green.y, "coral's green channel"),
    ]
}

/// The scene: lamp shader, light position, cube, vertex layout, model matrix.
pub(super) fn scene() -> Vec<Entry> {
    let cube = crate::raster::mesh::Mesh::learnopengl_cube();
    let mut normals: Vec<[i32; 3]> = cube.normals.iter().map(|n| n.round().as_ivec3().to_array()).collect();
    normals.sort_unstable();
    normals.dedup();
    let light_pos = crate::phong::BasicLighting::learnopengl().light_pos;
    let lamp = Vec4::splat(1.0);
    let zero_model = Mat4::ZERO * Mat4::from_translation(light_pos) * Mat4::from_scale(Vec3::splat(0.2));
    let identity_model = Mat4::IDENTITY * Mat4::from_translation(light_pos) * Mat4::from_scale(Vec3::splat(0.2));
    let f = std::mem::size_of::<f32>();
    vec![
        cited("lamp-white", &[(0, 191, 191), (3, 251, 251)])
            .says("vec4(1.0) sets all four components to 1.0", "FragColor = vec4(1.0);")
            .holds(
                lamp.to_array() == [1.0; 4],
                "a one-scalar vec4 constructor fills every component".into(),
                "GLSL constructor rule; glam Vec4::splat agrees",
            ),
        cited("light-position", &[(0, 202, 202), (0, 347, 347), (3, 265, 265), (3, 482, 482)])
            .says("the light's world position", "glm::vec3 lightPos(1.2f, 1.0f, 2.0f);")
            .holds(
                light_pos == Vec3::new(1.2, 1.0, 2.0),
                format!("BasicLighting::learnopengl().light_pos = {:?}", light_pos.to_array()),
                "the same in both texts and in lightlab's scene",
            ),
        cited("cube-vertices-36", &[(0, 221, 221), (0, 893, 893), (3, 305, 305), (3, 1348, 1348)])
            .says("vertices drawn for a cube: 6 faces × 2 triangles × 3", "36")
            .number((cube.triangles.len() * 3) as f64, "Mesh::learnopengl_cube(), triangles × 3"),
        cited("cube-faces-6", &[(0, 295, 295), (3, 407, 407)])
            .says("planes of the cube (\"qui en compte 6\")", "6")
            .number(normals.len() as f64, "distinct normals of the tutorial's cube data"),
        cited("model-identity-fr", &[(0, 208, 208), (0, 888, 888)])
            .says("the lamp's model matrix starts from the identity", "model = glm::mat4();")
            .holds(
                zero_model != Mat4::ZERO,
                "with GLM ≥ 0.9.9 (2018) mat4() is the zero matrix: translate and scale keep it zero, the lamp and \
                 the ten containers collapse to a point"
                    .into(),
                "written for GLM before 0.9.9, whose default constructor was the identity; the Ukrainian text \
                 writes glm::mat4(1.0f)",
            ),
        cited("model-identity-uk", &[(3, 271, 271), (3, 1328, 1328)])
            .says("the lamp's model matrix starts from the identity", "model = glm::mat4(1.0f);")
            .holds(
                identity_model.transform_point3(Vec3::ZERO) == light_pos,
                "mat4(1.0f) is the identity: the lamp's center lands on lightPos".into(),
                "current GLM",
            ),
        cited("stride-position", &[(0, 156, 156), (3, 167, 167)])
            .says(
                "stride of the position-only layout: one vec3",
                "glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), (void*)0);",
            )
            .holds(
                3 * f == std::mem::size_of::<Vec3>(),
                format!("3 * sizeof(float) = {} bytes = size of a vec3", 3 * f),
                "positions only, tightly packed",
            ),
        cited("stride-position-normal", &[(0, 309, 309), (3, 428, 428)])
            .says(
                "stride once normals are added: position + normal",
                "glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), (void*)0);",
            )
            .holds(
                6 * f == 2 * std::mem::size_of::<Vec3>(),
                format!("6 * sizeof(float) = {} bytes = two vec3", 6 * f),
                "the position is read from the first 3 floats of each 6",
            ),
        cited("stride-words-fr", &[(0, 313, 313)])
            .says("the stride is six floats", "il faut donner la taille de six entiers pour le stride")
            .holds(
                "six entiers".contains("float") || "six entiers".contains("réel"),
                "the listing (l.309) writes 6 * sizeof(float): six floats".into(),
                "the translation says \"six integers\"; the size matches only because sizeof(int) = sizeof(float) \
                 on common platforms",
            ),
        cited("stride-words-uk", &[(3, 435, 435)]).says("the stride is six floats", "stride до 6 розміру float").holds(
            "stride до 6 розміру float".contains("float"),
            "the listing (l.428) writes 6 * sizeof(float)".into(),
            "agrees with its listing",
        ),
    ]
}
