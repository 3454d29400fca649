//! opengl-tutorial.org, tutorial 8 "basic shading" (French, seed 001).

use glam::{Mat4, Quat, Vec3};

use super::listings::OPENGL_TUTORIAL_COLOR;
use super::{cited, Entry};
use crate::models::OpenGLTutorial;

/// The statements of `listing` (split on `;`, comments dropped), trimmed, empty ones left out.
pub fn statements(listing: &str) -> Vec<String> {
    let code: String = listing.lines().map(|l| l.split_once("//").map_or(l, |(c, _)| c)).collect::<Vec<_>>().join(" ");
    code.split(';').map(|s| s.split_whitespace().collect::<Vec<_>>().join(" ")).filter(|s| !s.is_empty()).collect()
}

/// Every entry of this part.
pub(super) fn entries() -> Vec<Entry> {
    let (v1, v2, v3) = (Vec3::new(0.0, 0.0, 0.0), Vec3::new(2.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.5));
    let tri = crate::normals::triangle_normal(v1, v2, v3);
    let positions = [Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::new(-1.0, -1.0, 0.5)];
    let triangles = [[0u32, 1, 2], [0, 2, 3], [0, 3, 1]];
    let vn = crate::normals::vertex_normals(&positions, &triangles, crate::normals::VertexWeighting::Unweighted)
        .map_or(Vec3::NAN, |n| n[0]);
    let model = OpenGLTutorial::with_defaults(Vec3::new(0.0, 0.0, 2.0), Vec3::new(1.0, 0.0, 0.0));
    let frag = Vec3::ZERO;
    let n = Vec3::Z;
    let at = |light: Vec3, eye: Vec3| OpenGLTutorial { light_pos: light, ..model }.terms(frag, n, eye);
    let above = at(Vec3::new(0.0, 0.0, 2.0), Vec3::new(0.0, 0.0, 5.0));
    let grazing = at(Vec3::new(2.0, 0.0, 0.0), Vec3::new(0.0, 0.0, 5.0));
    let behind = at(Vec3::new(0.0, 0.0, -2.0), Vec3::new(0.0, 0.0, 5.0));
    let near = crate::casters::inverse_square_falloff(50.0, 1.0);
    let far = crate::casters::inverse_square_falloff(50.0, 2.0);
    let spec_on = at(Vec3::new(1.0, 0.0, 1.0), Vec3::new(-1.0, 0.0, 1.0));
    let stmts = statements(OPENGL_TUTORIAL_COLOR);
    let assigned_has_spec = stmts.first().is_some_and(|s| s.contains("MaterialSpecularColor"));
    let half = |p: f32| crate::phong::lobe_half_width_deg(p).unwrap_or(f32::NAN);
    // A rigid view and a non-rigid model: the dot product survives the first only.
    let view = Mat4::from_rotation_translation(Quat::from_rotation_y(0.7), Vec3::new(1.0, 2.0, 3.0));
    let (a, b) = (Vec3::new(0.0, 0.6, 0.8), Vec3::new(0.8, 0.6, 0.0));
    let rigid_dot = view.transform_vector3(a).dot(view.transform_vector3(b));
    let v_world = Vec3::new(0.3, -0.2, 1.0);
    let cam = view.transform_point3(v_world);
    let light_world = Vec3::new(4.0, 4.0, 4.0);
    let eye_dir = Vec3::ZERO - cam;
    let light_dir = view.transform_point3(light_world) + eye_dir;
    let red = crate::color::modulate(Vec3::ONE, Vec3::new(1.0, 0.0, 0.0));
    let cos_alpha = 0.8f32;
    let slanted = crate::phong::diffuse_factor(n, Vec3::new(60f32.to_radians().sin(), 0.0, 60f32.to_radians().cos()));
    let spread = 1.0 / 60f32.to_radians().cos();
    let moved = Mat4::from_translation(Vec3::new(0.0, 1.0, 0.0));
    let printed_date = "2015-19-11 07:13:47 +0200";
    let month: u32 = printed_date.get(5..7).and_then(|m| m.parse().ok()).unwrap_or(0);
    vec![
        cited("page-date", &[(1, 6, 6)]).says("the page's publication date, year-month-day", printed_date).holds((1..=12).contains(&month), format!("month {month} does not exist; read as year-day-month it is 19 November 2015"), "the front matter swaps day and month"),
        cited("triangle-normal", &[(1, 40, 49)]).says("normalize(cross(v2 − v1, v3 − v1)) is unit and perpendicular to the triangle", "triangle.normale = cross(edge1, edge2).normalize()").holds((tri.length() - 1.0).abs() < 1e-6 && tri.dot(v2 - v1).abs() < 1e-6 && tri.dot(v3 - v1).abs() < 1e-6, format!(
                "|n| = {:.6}, n·edge1 = {:.1e}, n·edge2 = {:.1e}",
                tri.length(),
                tri.dot(v2 - v1),
                tri.dot(v3 - v1)
            ), "normals::triangle_normal"),
        cited("vertex-normal", &[(1, 56, 62)]).says("a vertex normal is the normalized sum of the adjacent triangles' normals", "v1.normal = normalize( tr1.normal + tr2.normal + tr3.normal )").holds((vn.length() - 1.0).abs() < 1e-6, format!("unit, {:?} for a vertex shared by 3 triangles", vn.to_array().map(|c| (c * 1e4).round() / 1e4)), "normals::vertex_normals (unweighted)"),
        cited("normal-buffer-layout", &[(1, 73, 73), (1, 82, 89)]).says("the normal buffer is tightly packed vec3s, read as 3 floats with stride 0", "normals.size() * sizeof(glm::vec3); glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, 0, (void*)0)").holds(std::mem::size_of::<Vec3>() == 3 * std::mem::size_of::<f32>(), format!("sizeof(vec3) = {} bytes = 3 floats", std::mem::size_of::<Vec3>()), "stride 0 means tightly packed"),
        cited("perpendicular-wording", &[(1, 104, 104), (1, 116, 117)]).says("\"perpendicular\" names the brightest case (l.104) and the darkest (l.117)", "Si la lumière est perpendiculaire à la surface, elle est concentrée …; light is perpendicular to the \
                                                                                                                                                            triangle -> 0").holds(above.diffuse.x == grazing.diffuse.x, format!(
                "light along the normal: diffuse {:.2}; light in the surface's plane: {:.2}",
                above.diffuse.x, grazing.diffuse.x
            ), "the prose calls a ray along the normal perpendicular (to the surface), the code comment calls a \
                ray in the plane perpendicular (to the normal): the same word for the two opposite cases"),
        cited("same-light-spread-out", &[(1, 108, 108)]).says("slanted light: each point darker, the total the same", "la quantité de lumière totale reste la même").holds((slanted * spread - 1.0).abs() < 1e-6, format!(
                "at 60°: cos θ = {slanted:.3} per point, over 1/cos θ = {spread:.3} times the area: {:.3}",
                slanted * spread
            ), "Lambert's cosine law"),
        cited("clamp-behind", &[(1, 128, 137)]).says("light behind the triangle: n·l < 0, clamped to 0", "float cosTheta = clamp( dot( n,l ), 0,1 );").holds(behind.diffuse == Vec3::ZERO && n.dot(Vec3::NEG_Z) < 0.0, "n·l = −1, diffuse 0".into(), "models::OpenGLTutorial::terms"),
        cited("red-material", &[(1, 145, 153)]).says("white light on a red material leaves red", "color = MaterialDiffuseColor * LightColor * cosTheta;").holds(red == Vec3::new(1.0, 0.0, 0.0), format!("white ⊙ red = {:?}", red.to_array()), "color::modulate"),
        cited("inverse-square", &[(1, 161, 165)]).says("twice as far: the light divided by", "4").number((near / far) as f64, "casters::inverse_square_falloff(50, 1) / (50, 2)"),
        cited("light-power-example", &[(1, 169, 169), (1, 183, 183)]).says("LightPower, a uniform; 60 W is given \"par exemple\"", "la puissance (par exemple 60 watts)").holds(true, format!(
                "an example value: the shader takes LightPower as a uniform (l.183); lightlab's default is {}, the \
                 tutorial's own source",
                model.light_power
            ), "not an erratum: the text offers 60 as an example, not as the tutorial's constant"),
        cited("same-space-for-n-and-l", &[(1, 185, 185)]).says("n·l is the same in any space both vectors share (here camera space)", "On peut les exprimer dans n'importe quel espace de coordonnées tant qu'il est le même pour les deux").holds((rigid_dot - a.dot(b)).abs() < 1e-6, format!("rigid view: n·l = {:.4} before and {rigid_dot:.4} after", a.dot(b)), "true for spaces related by rigid motions, as camera and world space are; a scaling model space \
                                                                                                                                                                                                                                                                                                                                                                       would change it"),
        cited("camera-space-vectors", &[(1, 206, 213)]).says("EyeDirection = 0 − position; LightDirection = LightPosition + EyeDirection, both from the vertex", "LightDirection_cameraspace = LightPosition_cameraspace + EyeDirection_cameraspace;").holds((light_dir - (view.transform_point3(light_world) - cam)).length() < 1e-5, "L + (0 − p) = L − p: from the vertex to the light".into(), ""),
        cited("model-matrix-omitted", &[(1, 211, 212)]).says("M is left out of the light's transform because M is the identity", "// Vector that goes from the vertex to the light, in camera space. M is ommited because it's identity.").holds((view * moved).transform_point3(light_world) == view.transform_point3(light_world), "the light position is given in world space (LightPosition_worldspace), so V alone brings it to \
                                                                                                                                                                                                                                                                                                                                      camera space whatever M is"
                .into(), "the code is right for any model matrix; the comment's reason is wrong (and would make a reader \
                          multiply by M when it is not the identity)"),
        cited("normal-without-inverse-transpose", &[(1, 216, 216)]).says("V·M·(n, 0) is correct only if M does not scale", "// Only correct if ModelMatrix does not scale the model ! Use its inverse transpose if not.").holds(crate::normals::model_matrix_normal_error_deg(glam::Mat3::from_diagonal(Vec3::splat(3.0)), a)
                .is_some_and(|e| e < 1e-3), "a uniform scale is harmless too, since the fragment shader normalizes (l.190)".into(), "the warning is stricter than needed, not wrong"),
        cited("back-black-without-ambient", &[(1, 234, 234)]).says("with diffuse only and clamp(), the back is black", "l'arrière de Suzanne est complètement noir car nous avons utilisé clamp()").holds(behind.diffuse == Vec3::ZERO && behind.specular == Vec3::ZERO, "no diffuse, no specular behind the light".into(), ""),
        cited("ambient-factor", &[(1, 250, 250), (1, 268, 268)]).says("MaterialAmbientColor = factor × MaterialDiffuseColor", "0.1").number(model.ambient_factor as f64, "models::OpenGLTutorial::with_defaults"),
        cited("reflect-direction", &[(1, 286, 291), (1, 304, 304)]).says("R = reflect(−l, n) is where the light goes; looking along it gives cosAlpha = 1", "vec3 R = reflect(-l,n);").holds(spec_on.specular.x > 0.0, format!("eye on the mirror ray: specular {:.3} > 0", spec_on.specular.x), "models::OpenGLTutorial::terms"),
        cited("specular-statement", &[(1, 294, 300)]).says("color = ambient + diffuse + specular", "… cosTheta / (distance*distance) ;\n    MaterialSpecularColor * … pow(cosAlpha,5) / (distance*distance);").holds(assigned_has_spec, format!("the assignment ends at the first ';': {} statements, the second unused", stmts.len()), "the semicolon after the diffuse line ends the assignment; the specular line is an expression \
                                                                                                                                                                                                                                                                                                                                         statement with no effect. It compiles, and on llvmpipe the color has no highlight \
                                                                                                                                                                                                                                                                                                                                         (tests/gl_errata.rs)"),
        cited("exponent-narrows-lobe", &[(1, 300, 300), (1, 306, 306)]).says("pow(cosAlpha, 5): raise the 5 for a thinner lobe", "Augmentez le *5* pour obtenir un lobe plus mince").holds(half(10.0) < half(5.0) && cos_alpha.powf(10.0) < cos_alpha.powf(5.0), format!("half-width {:.1}° at 5, {:.1}° at 10", half(5.0), half(10.0)), "phong::lobe_half_width_deg"),
    ]
}
