//! The book's diagrams. Each is computed from vectors with glam and the crate's core
//! functions, and drawn with [`super::svg::Canvas`]; nothing is placed by hand. Angles
//! printed in a diagram's key are measured back from the computed vectors.
//!
//! Symbols follow the crate conventions (all unit length, pointing away from the
//! surface point): `n` normal, `light_dir` toward the light, `view_dir` toward the eye,
//! `reflect_dir = reflect(-light_dir, n)`, `halfway = normalize(light_dir + view_dir)`.
//!
//! | diagram | shows | chapter |
//! | --- | --- | --- |
//! | `phong-vectors` | N, L, R, V, H and the angles θ, α, β | Basic lighting |
//! | `reflect-construction` | ogldev's `R = I − 2N(N·I)` built from two projections | Basic lighting |
//! | `diffuse-cosine` | a beam's footprint growing as `1/cos θ` | Basic lighting |
//! | `normal-matrix` | a normal skewed by non-uniform scale and corrected | Basic lighting |
//! | `light-casters` | directional, point (attenuation rings) and spot lights | Light casters |
//! | `spot-cone` | the spotlight's φ, γ and θ | Light casters |
//! | `container-maps` | the procedural container's diffuse, specular and emission maps | Lighting maps |

use super::artifact::Artifact;
use super::svg::{Anchor, Canvas, Pen};
use super::FigureError;
use crate::casters::{spot_intensity, Attenuation, SpotLight, RANGE_TABLE};
use crate::i18n::Lang;
use crate::material::LightProps;
use glam::{Mat3, Vec2, Vec3};

/// A diagram drawn in a language: its PNG and its SVG.
type LocalizedDiagram = fn(Lang) -> Result<[Vec<u8>; 2], FigureError>;

/// The diagrams this module contributes to the book (paths under `book/src/generated/`).
pub fn artifacts() -> Vec<Artifact> {
    let mut all = vec![Artifact::file("diagrams/container-maps.png", container_maps_png)];
    let figures: [(&str, LocalizedDiagram); 6] = [
        ("phong-vectors", phong_vectors_figure),
        ("reflect-construction", reflect_construction_figure),
        ("diffuse-cosine", diffuse_cosine_figure),
        ("normal-matrix", normal_matrix_figure),
        ("light-casters", light_casters_figure),
        ("spot-cone", spot_cone_figure),
    ];
    for (name, figure) in figures {
        let paths = vec![format!("diagrams/{name}.png"), format!("diagrams/{name}.svg")];
        all.extend(Artifact::localized(paths, move |lang| figure(lang).map(Vec::from)));
    }
    all
}

/// A diagram as PNG (rasterized at [`PNG_SCALE`]) and as the SVG it was drawn as,
/// for teachers who want to scale or edit it.
fn png_and_svg(c: &Canvas) -> Result<[Vec<u8>; 2], FigureError> {
    Ok([c.to_png(PNG_SCALE)?, c.finish().into_bytes()])
}

/// Output pixels per SVG pixel: diagrams are drawn at twice their layout size so they
/// stay sharp on high-density screens.
const PNG_SCALE: f32 = 2.0;

const INK: &str = "#222222";
const GREY: &str = "#666666";
const LIGHT_COLOR: &str = "#d97706";
const REFLECT_COLOR: &str = "#2563eb";
const VIEW_COLOR: &str = "#059669";
const HALFWAY_COLOR: &str = "#9333ea";
const WRONG_COLOR: &str = "#dc2626";

/// Angle between `n` and `light_dir` in the Phong vectors diagram, degrees (the light
/// is on the left of the normal).
pub const PHONG_VECTORS_THETA_DEG: f32 = 50.0;
/// Angle between `n` and `view_dir` in the Phong vectors diagram, degrees, on the
/// side of the reflection but nearer the normal than `reflect_dir`, so the angle
/// `alpha` between `reflect_dir` and `view_dir` is theta minus this, 30 degrees, and
/// the halfway vector lies between the light and the normal.
pub const PHONG_VECTORS_VIEW_DEG: f32 = 20.0;

/// The unit vector at `deg` degrees clockwise from +y in the plane z = 0 (x right,
/// y up): the normal is 0°, the right side positive.
fn from_normal(deg: f32) -> Vec3 {
    let a = deg.to_radians();
    Vec3::new(a.sin(), a.cos(), 0.0)
}

fn flat(v: Vec3) -> Vec2 {
    Vec2::new(v.x, v.y)
}

/// The five vectors of the Phong diagram, in the plane z = 0 (x right, y = normal):
/// `(n, light_dir, reflect_dir, view_dir, halfway)`.
///
/// ```text
/// n           = (0, 1, 0)
/// light_dir   = (-sin theta, cos theta, 0)
/// view_dir    = ( sin phi,   cos phi,   0)
/// reflect_dir = reflect(-light_dir, n) = -light_dir + 2 (n . light_dir) n
/// halfway     = normalize(light_dir + view_dir)
/// ```
/// with `theta` = [`PHONG_VECTORS_THETA_DEG`], `phi` = [`PHONG_VECTORS_VIEW_DEG`].
/// LearnOpenGL, Basic Lighting, "Specular lighting"; Blinn 1977 for the halfway vector.
pub fn phong_vectors() -> (Vec3, Vec3, Vec3, Vec3, Vec3) {
    let n = Vec3::Y;
    let light_dir = from_normal(-PHONG_VECTORS_THETA_DEG);
    let view_dir = from_normal(PHONG_VECTORS_VIEW_DEG);
    let reflect_dir = crate::glsl::reflect(-light_dir, n);
    let halfway = crate::phong::halfway(light_dir, view_dir);
    (n, light_dir, reflect_dir, view_dir, halfway)
}

/// A hatched surface line from `x0` to `x1` at height `y` (hatching below it).
fn surface(c: &mut Canvas, x0: f32, x1: f32, y: f32) {
    c.line(Vec2::new(x0, y), Vec2::new(x1, y), &Pen::solid("#444444", 3.0));
    let hatch = Pen::solid("#999999", 1.5);
    let strokes = ((x1 - x0) / 0.2).floor() as i32;
    for i in 0..strokes {
        let x = x0 + 0.1 + 0.2 * i as f32;
        c.line(Vec2::new(x, y), Vec2::new(x - 0.07, y - 0.09), &hatch);
    }
}

/// The unsigned angle between two vectors, degrees (0 when one is zero).
fn angle_deg(a: Vec3, b: Vec3) -> f32 {
    a.cross(b).length().atan2(a.dot(b)).to_degrees()
}

/// The vectors N, L, R, V and H at a surface point with the angles θ (N to L, N to R),
/// α (R to V) and β (N to H), as a PNG. See [`phong_vectors`] for the geometry.
pub fn phong_vectors_figure(lang: Lang) -> Result<[Vec<u8>; 2], FigureError> {
    let (n3, l3, r3, v3, h3) = phong_vectors();
    let (n, l, r, v, h) = (flat(n3), flat(l3), flat(r3), flat(v3), flat(h3));

    let mut c = Canvas::new(560, 330, Vec2::new(280.0, 270.0), 220.0)?.in_lang(lang);
    surface(&mut c, -1.2, 1.2, 0.0);

    let arcs = Pen::solid("#555555", 1.5);
    c.arc(Vec2::ZERO, 0.28, l, n, &arcs, "θ")?;
    c.arc(Vec2::ZERO, 0.28, n, r, &arcs, "θ")?;
    c.arc(Vec2::ZERO, 0.66, v, r, &Pen::solid(VIEW_COLOR, 1.5), "α")?;
    c.arc(Vec2::ZERO, 0.50, h, n, &Pen::solid(HALFWAY_COLOR, 1.5), "β")?;

    c.arrow(Vec2::ZERO, n, &Pen::solid(INK, 2.5), "N")?;
    c.arrow(Vec2::ZERO, l, &Pen::solid(LIGHT_COLOR, 2.5), "L")?;
    c.arrow(Vec2::ZERO, r, &Pen::solid(REFLECT_COLOR, 2.5), "R")?;
    c.arrow(Vec2::ZERO, v, &Pen::solid(VIEW_COLOR, 2.5), "V")?;
    c.arrow(Vec2::ZERO, h * 0.85, &Pen::solid(HALFWAY_COLOR, 2.5), "H")?;

    let key =
        format!("θ = {:.0}°,  α = {:.0}°,  β = {:.0}° = α/2", angle_deg(n3, l3), angle_deg(r3, v3), angle_deg(n3, h3));
    c.text(Vec2::new(1.2, -0.19), &key, 16.0, "#333333", Anchor::End);
    c.text(Vec2::new(-1.2, -0.19), "surface point", 15.0, "#444444", Anchor::Start);
    png_and_svg(&c)
}

/// Angle of incidence in the reflect construction, degrees from the normal.
pub const REFLECT_INCIDENCE_DEG: f32 = 50.0;

/// The vectors of ogldev's construction of `reflect`: `(i, n, projection, r)` with
/// `i` the incident direction (pointing *toward* the surface), `projection =
/// -n (n·i)` and `r = i + 2·projection = reflect(i, n)`.
///
/// Source: ogldev 19, "R = I − 2N(N·I)"; [`crate::glsl::reflect`].
pub fn reflect_construction() -> (Vec3, Vec3, Vec3, Vec3) {
    let n = Vec3::Y;
    let i = -from_normal(-REFLECT_INCIDENCE_DEG);
    let projection = -n * n.dot(i);
    (i, n, projection, crate::glsl::reflect(i, n))
}

/// ogldev 19's derivation of the reflected vector as a PNG: the incident `I`
/// continued below the surface, the projection `−N(N·I)` added twice, landing on `R`.
pub fn reflect_construction_figure(lang: Lang) -> Result<[Vec<u8>; 2], FigureError> {
    let (i3, n3, p3, r3) = reflect_construction();
    let (i, n, p, r) = (flat(i3), flat(n3), flat(p3), flat(r3));
    let mut c = Canvas::new(600, 400, Vec2::new(270.0, 215.0), 190.0)?.in_lang(lang);
    c.line(Vec2::new(-1.3, 0.0), Vec2::new(1.5, 0.0), &Pen::solid("#444444", 3.0));
    c.text(Vec2::new(-1.3, -0.12), "surface", 15.0, "#444444", Anchor::Start);

    let incident = Pen::solid(LIGHT_COLOR, 2.5);
    c.arrow(-i, Vec2::ZERO, &incident, "")?;
    c.text(-i * 0.55 + Vec2::new(-0.08, 0.0), "I", 18.0, LIGHT_COLOR, Anchor::End);
    c.line(Vec2::ZERO, i, &Pen::solid(LIGHT_COLOR, 1.5).dashed());
    c.text(i + Vec2::new(-0.05, -0.02), "I (continued)", 15.0, LIGHT_COLOR, Anchor::End);

    let proj = Pen::solid(VIEW_COLOR, 2.0);
    let foot = i + p;
    c.arrow(i, foot, &proj, "")?;
    c.arrow(foot, foot + p, &proj, "")?;
    for (from, to) in [(i, foot), (foot, foot + p)] {
        c.text((from + to) * 0.5 + Vec2::new(0.07, 0.0), "−N(N·I)", 16.0, VIEW_COLOR, Anchor::Start);
    }
    c.arrow(Vec2::ZERO, n * 0.9, &Pen::solid(INK, 2.5), "N")?;
    c.arrow(Vec2::ZERO, r, &Pen::solid(REFLECT_COLOR, 2.5), "R")?;

    let arcs = Pen::solid("#555555", 1.5);
    c.arc(Vec2::ZERO, 0.3, -i, n, &arcs, "θ")?;
    c.arc(Vec2::ZERO, 0.3, n, r, &arcs, "θ")?;
    // N·I < 0: written with a minus sign, as the key's other terms are
    let key = format!(
        "R = I − 2N(N·I) = I + 2·(−N(N·I)),  N·I = {} = −cos θ,  θ = {:.0}°",
        format!("{:.3}", n3.dot(i3)).replace('-', "−"),
        angle_deg(n3, -i3)
    );
    c.text(Vec2::new(-1.3, -0.9), &key, 15.0, "#333333", Anchor::Start);
    png_and_svg(&c)
}

/// Beam width in the diffuse cosine diagram, math units.
const BEAM_WIDTH: f32 = 0.8;

/// The incidence angles (degrees from the normal) of the diffuse cosine diagram's
/// two panels.
pub const DIFFUSE_COSINE_ANGLES_DEG: [f32; 2] = [0.0, 60.0];

/// The footprint on the surface of a beam of width `BEAM_WIDTH` arriving at
/// `theta_deg` from the normal, and the diffuse factor there:
/// `(footprint, diff)` with `footprint = w / cos θ` and `diff = max(n·l, 0)`
/// ([`crate::phong::diffuse_factor`]). The same power spread over a longer footprint
/// gives each point `cos θ` as much light: Lambert's cosine law.
pub fn diffuse_footprint(theta_deg: f32) -> (f32, f32) {
    let light_dir = from_normal(-theta_deg);
    let diff = crate::phong::diffuse_factor(Vec3::Y, light_dir);
    (BEAM_WIDTH / diff, diff)
}

/// A beam of parallel rays hitting a surface head-on and at 60°, with its footprint
/// on the surface and the diffuse factor, as a PNG.
pub fn diffuse_cosine_figure(lang: Lang) -> Result<[Vec<u8>; 2], FigureError> {
    let mut c = Canvas::new(760, 330, Vec2::new(30.0, 250.0), 140.0)?.in_lang(lang);
    let rays = 5;
    for (k, &theta_deg) in DIFFUSE_COSINE_ANGLES_DEG.iter().enumerate() {
        let centre = Vec2::new(1.3 + 2.6 * k as f32, 0.0);
        surface(&mut c, centre.x - 1.2, centre.x + 1.2, 0.0);
        let (footprint, diff) = diffuse_footprint(theta_deg);
        let travel = -flat(from_normal(-theta_deg));
        let across = Vec2::new(travel.y, -travel.x);
        let ray_pen = Pen::solid(LIGHT_COLOR, 2.0);
        // The rays start on one line across the beam and run until they meet the
        // surface y = 0; the footprint is where they land.
        let start_mid = centre - travel * 1.35;
        let (mut lo, mut hi) = (f32::INFINITY, f32::NEG_INFINITY);
        for j in 0..rays {
            let start = start_mid + across * ((j as f32 / (rays - 1) as f32 - 0.5) * BEAM_WIDTH);
            let hit = start + travel * (start.y / -travel.y);
            (lo, hi) = (lo.min(hit.x), hi.max(hit.x));
            c.arrow(start, hit, &ray_pen, "")?;
        }
        let (a, b) = (start_mid - across * (0.5 * BEAM_WIDTH), start_mid + across * (0.5 * BEAM_WIDTH));
        c.line(a, b, &Pen::solid(GREY, 1.5).dashed());
        c.text((a + b) * 0.5 - travel * 0.14, "w", 17.0, GREY, Anchor::Middle);
        // The footprint on the surface, measured from the drawn rays.
        debug_assert!(((hi - lo) - footprint).abs() < 1e-4, "footprint {footprint} drawn {}", hi - lo);
        c.line(Vec2::new(lo, 0.0), Vec2::new(hi, 0.0), &Pen::solid(WRONG_COLOR, 6.0));
        // two lines: on one, the two panels' labels ran into each other (in French, and
        // nearly in English)
        let footprint_label = format!("θ = {theta_deg:.0}°: footprint = {:.2} w", footprint / BEAM_WIDTH);
        c.text(centre + Vec2::new(0.0, -0.28), &footprint_label, 15.0, "#333333", Anchor::Middle);
        c.text(centre + Vec2::new(0.0, -0.42), &format!("max(n·l, 0) = {diff:.2}"), 15.0, "#333333", Anchor::Middle);
        c.arrow(centre + Vec2::new(1.05, 0.0), centre + Vec2::new(1.05, 0.55), &Pen::solid(INK, 2.0), "N")?;
    }
    png_and_svg(&c)
}

/// The non-uniform scale of the normal matrix diagram: `diag(2, 1, 1)`.
pub const NORMAL_MATRIX_SCALE: Vec3 = Vec3::new(2.0, 1.0, 1.0);

/// The normal matrix diagram's numbers: the triangle's slanted edge has normal
/// `n = (1, 1, 0)/√2`; returns `(wrong, right, error_deg)` where `wrong =
/// normalize(M n)` (the model matrix applied to the normal), `right =
/// normalize(transpose(inverse(M)) n)` and `error_deg` the angle between them from
/// [`crate::normals::model_matrix_normal_error_deg`].
///
/// Returns an error if the model matrix were singular (it is not).
pub fn normal_matrix_vectors() -> Result<(Vec3, Vec3, f32), FigureError> {
    let model = Mat3::from_diagonal(NORMAL_MATRIX_SCALE);
    let n = Vec3::new(1.0, 1.0, 0.0).normalize();
    let normal_matrix = crate::normals::normal_matrix_inverse_transpose(model)
        .ok_or_else(|| "normal matrix diagram: the model matrix is singular".to_owned())?;
    let wrong = crate::normals::transform_normal(model, n);
    let right = crate::normals::transform_normal(normal_matrix, n);
    let error = crate::normals::model_matrix_normal_error_deg(model, n)
        .ok_or_else(|| "normal matrix diagram: no error angle".to_owned())?;
    Ok((wrong, right, error))
}

/// A right triangle with its slanted edge's normal, then the same triangle under
/// `diag(2, 1, 1)` with the normal sent through the model matrix (wrong, not
/// perpendicular) and through the normal matrix (right), as a PNG.
pub fn normal_matrix_figure(lang: Lang) -> Result<[Vec<u8>; 2], FigureError> {
    let model = Mat3::from_diagonal(NORMAL_MATRIX_SCALE);
    let (wrong, right, error) = normal_matrix_vectors()?;
    let n = Vec3::new(1.0, 1.0, 0.0).normalize();
    let corners = [Vec3::ZERO, Vec3::X, Vec3::Y];
    let mut c = Canvas::new(800, 330, Vec2::new(60.0, 250.0), 150.0)?.in_lang(lang);
    let edge_pen = Pen::solid(INK, 2.5);
    let panels: [(Vec2, Mat3); 2] = [(Vec2::ZERO, Mat3::IDENTITY), (Vec2::new(2.0, 0.0), model)];
    for (k, (offset, m)) in panels.iter().enumerate() {
        let p: Vec<Vec2> = corners.iter().map(|&q| offset + flat(*m * q)).collect();
        for e in 0..3 {
            c.line(p[e], p[(e + 1) % 3], &edge_pen);
        }
        let mid = (p[1] + p[2]) * 0.5;
        let len = 0.75;
        if k == 0 {
            c.arrow(mid, mid + flat(n) * len, &Pen::solid(VIEW_COLOR, 2.5), "n")?;
            c.text(offset + Vec2::new(0.0, -0.25), "before: the unit triangle", 15.0, "#333333", Anchor::Start);
        } else {
            c.arrow(mid, mid + flat(wrong) * len, &Pen::solid(WRONG_COLOR, 2.5), "M·n")?;
            c.arrow(mid, mid + flat(right) * len, &Pen::solid(VIEW_COLOR, 2.5), "(M⁻¹)ᵀ·n")?;
            let label = format!(
                "after M = diag({}, {}, {}): M·n is {error:.1}° off",
                NORMAL_MATRIX_SCALE.x, NORMAL_MATRIX_SCALE.y, NORMAL_MATRIX_SCALE.z
            );
            c.text(offset + Vec2::new(0.0, -0.25), &label, 15.0, "#333333", Anchor::Start);
        }
    }
    png_and_svg(&c)
}

/// A full circle of `radius` around `centre`, as four quarter arcs.
fn circle(c: &mut Canvas, centre: Vec2, radius: f32, pen: &Pen) -> Result<(), FigureError> {
    let dirs = [Vec2::X, Vec2::Y, Vec2::NEG_X, Vec2::NEG_Y, Vec2::X];
    for w in dirs.windows(2) {
        c.arc(centre, radius, w[0], w[1], pen, "")?;
    }
    Ok(())
}

/// The attenuation fractions whose distances the light-casters diagram draws as rings.
pub const RING_FRACTIONS: [(f32, &str); 3] = [(0.5, "1/2"), (0.25, "1/4"), (0.125, "1/8")];

/// The distances at which the range-7 row of the attenuation table (1, 0.7, 1.8)
/// falls to each of [`RING_FRACTIONS`], world units, from
/// [`Attenuation::distance_for`]. Returns an error if a distance does not exist.
pub fn ring_distances() -> Result<[f32; 3], String> {
    let a = RANGE_TABLE[0].attenuation;
    let mut out = [0.0; 3];
    for (slot, (fraction, _)) in out.iter_mut().zip(RING_FRACTIONS) {
        *slot = a.distance_for(fraction).ok_or_else(|| format!("no distance for attenuation {fraction}"))?;
    }
    Ok(out)
}

/// The three light casters side by side: a directional light's parallel rays (the
/// direction of LearnOpenGL's sun projected onto the page), a point light with rings
/// where the range-7 attenuation row falls to 1/2, 1/4 and 1/8, and a spotlight with
/// the Light casters chapter's 12.5° and 17.5° cones, as a PNG.
pub fn light_casters_figure(lang: Lang) -> Result<[Vec<u8>; 2], FigureError> {
    let mut c = Canvas::new(900, 340, Vec2::new(20.0, 290.0), 115.0)?.in_lang(lang);
    let ground = 0.0;
    let title = |c: &mut Canvas, x: f32, t: &str| {
        c.text(Vec2::new(x, 2.4), t, 17.0, "#333333", Anchor::Middle);
    };
    let ray_pen = Pen::solid(LIGHT_COLOR, 2.0);

    // Directional: every ray has the same direction.
    let sun = flat(Vec3::new(-0.2, -1.0, -0.3)).normalize();
    let cx = 1.25;
    surface(&mut c, cx - 1.15, cx + 1.15, ground);
    for k in 0..5 {
        let hit = Vec2::new(cx - 0.8 + 0.4 * k as f32, ground);
        c.arrow(hit - sun * 1.9, hit, &ray_pen, "")?;
    }
    title(&mut c, cx, "directional: parallel rays");

    // Point: rings at equal attenuation, rays in every direction.
    let cx = 3.85;
    let centre = Vec2::new(cx, 1.15);
    surface(&mut c, cx - 1.15, cx + 1.15, ground);
    let radii = ring_distances()?;
    let fit = 1.1 / radii[2];
    for (r, (_, label)) in radii.iter().zip(RING_FRACTIONS) {
        circle(&mut c, centre, r * fit, &Pen::solid("#b45309", 1.2).dashed())?;
        // Just outside the ring, up and to the right.
        let at = centre + Vec2::new(0.71, 0.71) * (r * fit + 0.13);
        c.text(at, label, 14.0, "#b45309", Anchor::Start);
    }
    for k in 0..8 {
        let a = std::f32::consts::TAU * k as f32 / 8.0 + 0.3;
        let d = Vec2::new(a.cos(), a.sin());
        c.arrow(centre + d * 0.12, centre + d * 0.5, &Pen::solid(LIGHT_COLOR, 1.8), "")?;
    }
    c.text(centre + Vec2::new(0.0, 0.0), "●", 16.0, LIGHT_COLOR, Anchor::Middle);
    title(&mut c, cx, "point: attenuation rings");

    // Spot: the two cones of the Light casters chapter.
    let cx = 6.45;
    surface(&mut c, cx - 1.15, cx + 1.15, ground);
    let spot = SpotLight::new(Vec3::ZERO, Vec3::NEG_Y, 12.5, 17.5, Attenuation::LEARNOPENGL, LightProps::white())
        .map_err(|e| format!("light casters diagram: {e}"))?;
    let apex = Vec2::new(cx, 1.95);
    let height = apex.y - ground;
    for (cosine, pen) in
        [(spot.cut_off, Pen::solid(LIGHT_COLOR, 2.0)), (spot.outer_cut_off, Pen::solid(LIGHT_COLOR, 1.5).dashed())]
    {
        let half = cosine.acos();
        for side in [-1.0f32, 1.0] {
            let d = Vec2::new(side * half.sin(), -half.cos());
            c.line(apex, apex + d * (height / half.cos()), &pen);
        }
    }
    c.arrow(apex, apex + flat(spot.direction) * 1.2, &Pen::solid(INK, 2.0), "")?;
    c.text(apex + Vec2::new(0.08, 0.0), "spot", 15.0, "#333333", Anchor::Start);
    title(&mut c, cx, "spot: inner and outer cone");
    png_and_svg(&c)
}

/// The spot cone diagram's angles, degrees: inner φ and outer γ (the Light casters
/// chapter's 12.5° and 17.5°) and the fragment's θ, inside the soft edge.
pub const SPOT_CONE_DEG: (f32, f32, f32) = (12.5, 17.5, 15.0);

/// The spotlight cone with φ, γ and θ, and the intensity at the fragment from
/// [`spot_intensity`], as a PNG.
pub fn spot_cone_figure(lang: Lang) -> Result<[Vec<u8>; 2], FigureError> {
    let (phi_deg, gamma_deg, theta_deg) = SPOT_CONE_DEG;
    let spot =
        SpotLight::new(Vec3::ZERO, Vec3::NEG_Y, phi_deg, gamma_deg, Attenuation::LEARNOPENGL, LightProps::white())
            .map_err(|e| format!("spot cone diagram: {e}"))?;
    let mut c = Canvas::new(560, 540, Vec2::new(280.0, 40.0), 230.0)?.in_lang(lang);
    let apex = Vec2::ZERO;
    let depth = 1.6;
    let ground = -depth;
    surface(&mut c, -0.9, 0.9, ground);
    let axis = flat(spot.direction);
    let ray_at = |half_rad: f32, side: f32| Vec2::new(side * half_rad.sin(), -half_rad.cos());
    let (phi, gamma) = (spot.cut_off.acos(), spot.outer_cut_off.acos());
    let theta = theta_deg.to_radians();
    for (half, pen) in [(phi, Pen::solid(LIGHT_COLOR, 2.0)), (gamma, Pen::solid(LIGHT_COLOR, 1.5).dashed())] {
        for side in [-1.0f32, 1.0] {
            c.line(apex, apex + ray_at(half, side) * (depth / half.cos()), &pen);
        }
    }
    c.arrow(apex, apex + axis * 1.25, &Pen::solid(INK, 2.5), "")?;
    c.text(apex + axis * 1.34, "SpotDir", 16.0, INK, Anchor::Middle);

    // The fragment on the right, inside the soft edge; LightDir points back at the light.
    let to_frag = ray_at(theta, 1.0);
    let frag = apex + to_frag * (depth / theta.cos());
    c.line(apex, frag, &Pen::solid(REFLECT_COLOR, 1.5).dashed());
    c.arrow(frag, frag - to_frag * 0.55, &Pen::solid(REFLECT_COLOR, 2.5), "")?;
    c.text(frag - to_frag * 0.4 + Vec2::new(0.05, 0.0), "LightDir", 16.0, REFLECT_COLOR, Anchor::Start);
    // under the surface's hatching (0.09 deep), centred below the fragment
    c.text(Vec2::new(frag.x, ground - 0.17), "fragment", 14.0, REFLECT_COLOR, Anchor::Middle);

    // Arcs from the axis; labels beside the arcs' outer ends.
    let arc_pen = Pen::solid("#555555", 1.5);
    let arcs =
        [(phi, -1.0f32, 0.55, "φ", GREY), (gamma, -1.0, 0.95, "γ", GREY), (theta, 1.0, 0.75, "θ", REFLECT_COLOR)];
    for (half, side, radius, label, color) in arcs {
        let end = ray_at(half, side);
        c.arc(apex, radius, axis, end, &arc_pen, "")?;
        let at = apex + end * radius + Vec2::new(side * 0.08, -0.02);
        let anchor = if side < 0.0 { Anchor::End } else { Anchor::Start };
        c.text(at, label, 18.0, color, anchor);
    }
    let theta_cos = spot.theta(-to_frag.extend(0.0));
    let intensity = spot_intensity(theta_cos, spot.cut_off, spot.outer_cut_off);
    let key = [
        format!("φ = {phi_deg}°: cut_off = cos φ = {:.4}", spot.cut_off),
        format!("γ = {gamma_deg}°: outer_cut_off = cos γ = {:.4}", spot.outer_cut_off),
        format!("θ = {theta_deg}°: theta = {theta_cos:.4}, intensity = {intensity:.3}"),
    ];
    for (k, line) in key.iter().enumerate() {
        c.text(Vec2::new(-1.1, -1.88 - 0.11 * k as f32), line, 14.0, "#333333", Anchor::Start);
    }
    png_and_svg(&c)
}

/// Texels per side of the container maps figure.
const MAP_TEXELS: usize = 64;
/// Each texel is drawn as a square of this many pixels (nearest-neighbour zoom).
const MAP_ZOOM: usize = 3;
/// White gap between the maps, pixels.
const MAP_GAP: usize = 12;

/// The procedural container's three maps side by side (diffuse, specular, emission), as
/// [`crate::maps::container`] generates them at 64 × 64 texels, each texel a 3 × 3
/// square, stored with [`crate::color::to_rgb8`] (no gamma, as every figure here).
/// Row `v = 0` is at the bottom, as OpenGL samples it.
///
/// Returns an error if the maps cannot be made or the PNG cannot be encoded.
pub fn container_maps_png() -> Result<Vec<u8>, FigureError> {
    use image::ImageEncoder as _;
    let maps = crate::maps::container(MAP_TEXELS, true).map_err(|e| format!("container maps: {e}"))?;
    let emission = maps.emission.as_ref().ok_or_else(|| "container maps: no emission map".to_owned())?;
    let panels = [&maps.diffuse, &maps.specular, emission];
    let side = MAP_TEXELS * MAP_ZOOM;
    let (w, h) = (panels.len() * side + (panels.len() - 1) * MAP_GAP, side);
    let mut rgb = vec![255u8; w * h * 3];
    for (k, map) in panels.iter().enumerate() {
        for y in 0..h {
            for x in 0..side {
                let (i, j) = (x / MAP_ZOOM, MAP_TEXELS - 1 - y / MAP_ZOOM);
                let texel = map.texel(i as i64, j as i64, crate::maps::Wrap::ClampToEdge);
                let at = (y * w + k * (side + MAP_GAP) + x) * 3;
                rgb[at..at + 3].copy_from_slice(&crate::color::to_rgb8(texel));
            }
        }
    }
    let mut png = Vec::new();
    image::codecs::png::PngEncoder::new(&mut png)
        .write_image(&rgb, w as u32, h as u32, image::ExtendedColorType::Rgb8)
        .map_err(|e| format!("container maps: PNG encoding failed: {e}"))?;
    Ok(png)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reflection_mirrors_light_about_the_normal() {
        let (n, l, r, _, _) = phong_vectors();
        // Mirror image: same angle to n, opposite tangent component. 1e-6 is a few f32
        // ulps of values near 1.
        assert!((n.dot(l) - n.dot(r)).abs() < 1e-6, "n.l {} n.r {}", n.dot(l), n.dot(r));
        assert!((l.x + r.x).abs() < 1e-6, "l.x {} r.x {}", l.x, r.x);
        assert!((r.length() - 1.0).abs() < 1e-6, "|r| {}", r.length());
    }

    #[test]
    fn halfway_angle_is_half_alpha_in_the_plane() {
        let (n, _, r, v, h) = phong_vectors();
        // Coplanar vectors: angle(n, h) = angle(r, v) / 2 exactly; 1e-3 degree covers
        // the f32 rounding of atan2 near 15 degrees.
        let (beta, alpha) = (angle_deg(n, h), angle_deg(r, v));
        assert!((beta - alpha / 2.0).abs() < 1e-3, "beta {beta} alpha {alpha}");
    }

    #[test]
    fn construction_lands_on_reflect() {
        let (i, _, p, r) = reflect_construction();
        // Same sums in a different order: a few ulps of values near 1.
        assert!((i + 2.0 * p - r).length() < 1e-6);
        assert!((i + p).y.abs() < 1e-6, "the first projection ends on the surface");
    }

    #[test]
    fn footprint_grows_as_one_over_cosine() {
        let (f0, d0) = diffuse_footprint(0.0);
        let (f60, d60) = diffuse_footprint(60.0);
        // cos 60° = 0.5 up to f32 rounding of the angle conversion (1e-6).
        assert!((d0 - 1.0).abs() < 1e-6 && (d60 - 0.5).abs() < 1e-6, "{d0} {d60}");
        assert!((f60 / f0 - 2.0).abs() < 1e-5, "{f0} {f60}");
    }

    #[test]
    fn model_matrix_skews_the_normal_and_the_normal_matrix_does_not() {
        let (wrong, right, error) = normal_matrix_vectors().unwrap();
        // Perpendicular to the scaled slanted edge (-2, 1): exact up to f32 rounding.
        let edge = Vec3::new(-2.0, 1.0, 0.0);
        assert!(right.dot(edge).abs() < 1e-6, "{right}");
        assert!(wrong.dot(edge).abs() > 0.5, "{wrong}");
        // atan(2) − atan(1/2) = 36.87°; 0.01° covers f32 rounding.
        assert!((error - 36.87).abs() < 0.01, "{error}");
    }

    #[test]
    fn rings_are_where_the_attenuation_says() {
        let a = RANGE_TABLE[0].attenuation;
        for (d, (fraction, _)) in ring_distances().unwrap().iter().zip(RING_FRACTIONS) {
            // distance_for solves a quadratic in f32: relative 1e-5.
            assert!((a.at(*d) - fraction).abs() < 1e-5 * fraction.max(1.0), "{d} {fraction}");
        }
    }

    #[test]
    fn every_diagram_renders() {
        for a in artifacts() {
            let files = a.make().unwrap_or_else(|e| panic!("{:?}: {e}", a.paths()));
            for (bytes, path) in files.iter().zip(a.paths()) {
                if path.ends_with(".svg") {
                    let text = std::str::from_utf8(bytes).unwrap();
                    assert!(text.starts_with("<svg") && text.trim_end().ends_with("</svg>"), "{path}");
                } else {
                    assert_eq!(&bytes[1..4], b"PNG", "{path}");
                }
            }
        }
    }
}
