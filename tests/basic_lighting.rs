//! Chapter 2, Basic lighting: diffuse, Phong and Blinn-Phong specular, view space.
use crate::common;

use common::{close, close3, config, rigid_view, unit_vec3, vec3_in};
use glam::{Mat4, Vec3};
use lightlab::glsl::reflect;
use lightlab::phong::{
    blinn_specular_factor, diffuse_factor, halfway, lobe_half_width_deg, phong_specular_factor, BasicLighting, Terms,
};
use lightlab::reference::{self, dvec3};
use proptest::prelude::*;

fn shininess() -> impl Strategy<Value = f32> {
    0.5f32..256.0
}

/// Scenes near the chapter's: positions in a 10-unit box, shininess up to 256.
fn basic_lighting() -> impl Strategy<Value = BasicLighting> {
    (vec3_in(10.0), vec3_in(10.0), common::color(), common::color(), 0.0f32..1.0, 0.0f32..1.0, 1.0f32..128.0).prop_map(
        |(light_pos, view_pos, light_color, object_color, ambient_strength, specular_strength, shininess)| {
            BasicLighting {
                light_pos,
                view_pos,
                light_color,
                object_color,
                ambient_strength,
                specular_strength,
                shininess,
            }
        },
    )
}

/// `|x̂^s − x^s|` for a base error `dx`, `s ≥ 1` (mean value theorem, as tests/precision.rs).
fn pow_bound(x: f64, s: f64, dx: f64) -> f64 {
    s * (x + dx).min(1.0 + dx).powf(s - 1.0) * dx + 2.0 * common::U * x.powf(s)
}

fn terms_diff(a: &Terms, b: &Terms) -> f32 {
    [a.ambient - b.ambient, a.diffuse - b.diffuse, a.specular - b.specular]
        .iter()
        .map(|v| v.abs().max_element())
        .fold(0.0, f32::max)
}

proptest! {
    #![proptest_config(config())]

    /// For unit vectors, diff = max(n·l, 0) ∈ [0, 1] in both paths.
    #[test]
    fn diffuse_in_unit_interval(n in unit_vec3(), l in unit_vec3()) {
        let d = diffuse_factor(n, l);
        // |n·l| ≤ |n||l| ≤ (1 + 3U)²: allow 1 + 1e-6 for normalize's ulps.
        prop_assert!((0.0..=1.0 + 1e-6).contains(&d), "diffuse_factor = {d}");
        let dr = reference::phong::diffuse_factor(dvec3(n), dvec3(l));
        prop_assert!((0.0..=1.0 + 1e-6).contains(&dr), "reference diffuse_factor = {dr}");
    }

    /// Phong and Blinn-Phong specular factors lie in [0, 1] for unit vectors.
    #[test]
    fn specular_in_unit_interval(n in unit_vec3(), l in unit_vec3(), v in unit_vec3(), s in shininess()) {
        for (name, x) in [("phong", phong_specular_factor(n, l, v, s)), ("blinn", blinn_specular_factor(n, l, v, s))] {
            // Base ≤ 1 + a few ulps (normalize), raised to s ≤ 256: ≤ (1 + 4U)^256 ≈ 1 + 6e-5.
            prop_assert!((0.0..=1.0 + 1e-4).contains(&x), "{name} spec = {x}");
        }
        let (nd, ld, vd) = (dvec3(n), dvec3(l), dvec3(v));
        let p = reference::phong::phong_specular_factor(nd, ld, vd, s as f64);
        let b = reference::phong::blinn_specular_factor(nd, ld, vd, s as f64);
        prop_assert!((0.0..=1.0 + 1e-4).contains(&p) && (0.0..=1.0 + 1e-4).contains(&b), "reference phong {p} blinn {b}");
    }

    /// Phong peaks at the mirror direction: view = reflect_dir gives 1, and any other unit view gives no more.
    #[test]
    fn phong_peaks_at_mirror_direction(n in unit_vec3(), l in unit_vec3(), v in unit_vec3(), s in shininess()) {
        let reflect_dir = reflect(-l, n).normalize();
        let peak = phong_specular_factor(n, l, reflect_dir, s);
        // Base = |r|² within ~8U of 1; pow amplifies by s: 1 − s·8U.
        close("phong peak", 1.0, peak as f64, 256.0 * 8.0 * common::U)?;
        let other = phong_specular_factor(n, l, v, s);
        prop_assert!(other <= peak + 1e-6, "spec at view {v} = {other} > peak {peak}");
        // The f32 unit vectors are unit only to ~U; renormalize in f64 so the
        // reference sees exact unit inputs.
        let (nd, ld) = (dvec3(n).normalize(), dvec3(l).normalize());
        let rd = reference::glsl::reflect(-ld, nd).normalize();
        let peak_d = reference::phong::phong_specular_factor(nd, ld, rd, s as f64);
        close("reference phong peak", 1.0, peak_d, 1e-12)?;
        prop_assert!(reference::phong::phong_specular_factor(nd, ld, dvec3(v).normalize(), s as f64) <= peak_d + 1e-12);
    }

    /// Blinn-Phong peaks at the mirror direction too (halfway = n there), for a
    /// light above the surface (below it, l + reflect_dir points along −n).
    #[test]
    fn blinn_peaks_at_mirror_direction(n in unit_vec3(), l in unit_vec3(), v in unit_vec3(), s in shininess()) {
        prop_assume!(n.dot(l) > 0.05);
        let reflect_dir = reflect(-l, n).normalize();
        let peak = blinn_specular_factor(n, l, reflect_dir, s);
        // halfway = normalize(2(n·l) n): direction error ≲ 8U / (n·l) ≤ 160U; cos error is second order, s·8U for the rest.
        close("blinn peak", 1.0, peak as f64, 256.0 * 8.0 * common::U)?;
        prop_assert!(blinn_specular_factor(n, l, v, s) <= peak + 1e-6);
        let (nd, ld) = (dvec3(n).normalize(), dvec3(l).normalize());
        let rd = reference::glsl::reflect(-ld, nd).normalize();
        let peak_d = reference::phong::blinn_specular_factor(nd, ld, rd, s as f64);
        close("reference blinn peak", 1.0, peak_d, 1e-12)?;
        prop_assert!(reference::phong::blinn_specular_factor(nd, ld, dvec3(v).normalize(), s as f64) <= peak_d + 1e-12);
    }

    /// The halfway vector bisects the angle between light and view.
    #[test]
    fn halfway_bisects(l in unit_vec3(), v in unit_vec3()) {
        prop_assume!((l + v).length() > 0.1);
        let h = halfway(l, v);
        // Angle cosines: each a dot of f32 unit vectors, error ≲ 20U / |l + v|.
        close("h·l vs h·v", h.dot(l) as f64, h.dot(v) as f64, 200.0 * common::U)?;
        close("|h|", 1.0, h.length() as f64, 4.0 * common::U)?;
    }

    /// At the half-width angle from the peak, the lobe is at one half.
    #[test]
    fn lobe_half_width_gives_one_half(s in 1.0f64..512.0) {
        let a = reference::phong::lobe_half_width_deg(s).unwrap().to_radians();
        close("cos(a)^s", 0.5, a.cos().powf(s), 1e-12)?;
        let a32 = lobe_half_width_deg(s as f32).unwrap() as f64;
        // f32 acos near 1 loses digits: |Δa| ≈ U / sin(a); allow 1e-3 degrees.
        close("f32 half width (deg)", a.to_degrees(), a32, 1e-3 + 1e-4 * a.to_degrees())?;
    }

    /// World space and view space agree for any rigid view.
    #[test]
    fn world_and_view_space_agree(b in basic_lighting(), view in rigid_view(), frag in vec3_in(5.0), normal in unit_vec3()) {
        prop_assume!(b.light_pos.distance(frag) > 0.5 && b.view_pos.distance(frag) > 0.5);
        // terms_in_view_space places the eye at the origin of view space, so the
        // world-space eye must be the camera position: view⁻¹ · 0.
        let (view, view_d) = (view.mat4(), view.dmat4());
        let eye = view.inverse().transform_point3(Vec3::ZERO);
        let world = BasicLighting { view_pos: eye, ..b };
        prop_assume!(eye.distance(frag) > 0.5);
        let a = world.terms(frag, normal);
        let c = world.terms_in_view_space(view, frag, normal);
        // Derived bound. The f32 view transform of a point p has error
        // E ≤ γ₄(√3|p| + |t|) + 2U|p| (rounding, and the f32 rotation's
        // non-orthogonality); the eye, through view⁻¹ and back, ≤ 2E. A direction
        // between points ≥ d_min apart then moves by ≤ 2·2E/d_min, plus 4U
        // (normalize); the normal through the cofactor matrix by ≤ 8U. Diffuse
        // (a dot) moves by ≤ Δn + Δl, the specular base by ≤ 2Δn + Δl + Δv;
        // both paths also carry their own 11U / 40U (see tests/precision.rs).
        let u = common::U;
        let p_max = [frag, b.light_pos, eye].iter().map(|p| p.length()).fold(0.0f32, f32::max) as f64;
        let e = 4.0 * u * (3f64.sqrt() * p_max + view.w_axis.truncate().length() as f64) + 2.0 * u * p_max;
        let d_min = b.light_pos.distance(frag).min(eye.distance(frag)) as f64;
        let dd = 4.0 * e / d_min + 4.0 * u;
        let dn = 8.0 * u;
        let (fd, nd) = (dvec3(frag), dvec3(normal));
        let (ld, vd) = ((dvec3(b.light_pos) - fd).normalize(), (dvec3(eye) - fd).normalize());
        let x = vd.dot(reference::glsl::reflect(-ld, nd)).max(0.0);
        let lit = (b.light_color * b.object_color).max_element() as f64;
        let diff_bound = lit * (dn + dd + 2.0 * 11.0 * u);
        let spec_bound = lit * b.specular_strength as f64 * pow_bound(x, b.shininess as f64, 2.0 * dn + 2.0 * dd + 2.0 * 40.0 * u);
        let bound = diff_bound.max(spec_bound) + 3.0 * u * a.sum().max_element().max(c.sum().max_element()) as f64 + 1e-40;
        let d = terms_diff(&a, &c) as f64;
        prop_assert!(d <= bound, "world {a:?}\nview {c:?}\ndifference {d:e} > bound {bound:e}");
        let bd = reference::phong::BasicLighting { view_pos: view_d.inverse().transform_point3(glam::DVec3::ZERO), ..reference::phong::BasicLighting::from_f32(&b) };
        let ad = bd.terms(dvec3(frag), dvec3(normal));
        let cd = bd.terms_in_view_space(view_d, dvec3(frag), dvec3(normal));
        let dd = ad.max_abs_diff(&cd);
        // f64: positions ~25 through a 4×4 product, ~1e-14 absolute; × s ≤ 128 / 0.5.
        prop_assert!(dd <= 1e-10, "reference world {ad:?}\nview {cd:?}\ndifference {dd}");
    }

    /// Ambient never depends on geometry; diffuse and specular vanish for a zero normal.
    #[test]
    fn ambient_is_geometry_free(b in basic_lighting(), frag in vec3_in(5.0), normal in unit_vec3()) {
        let t = b.terms(frag, normal);
        let z = b.terms(frag, Vec3::ZERO);
        prop_assert_eq!(t.ambient, z.ambient);
        prop_assert_eq!(z.diffuse, Vec3::ZERO);
        prop_assert_eq!(z.specular, Vec3::ZERO);
        close3("ambient", dvec3(b.ambient_strength * b.light_color * b.object_color), dvec3(t.ambient), 1e-7)?;
    }
}

#[test]
fn degenerate_basic_lighting() {
    let b = BasicLighting::learnopengl();
    // Fragment at the light and at the eye: no NaN, diffuse/specular zero.
    for frag in [b.light_pos, b.view_pos] {
        let t = b.terms(frag, Vec3::Z);
        assert!(t.sum().is_finite(), "{t:?}");
    }
    let t = b.terms(b.light_pos, Vec3::Z);
    assert_eq!(t.diffuse, Vec3::ZERO);
    // NaN normal: diffuse and specular are 0 (documented).
    let t = b.terms(Vec3::ZERO, Vec3::NAN);
    assert_eq!(t.diffuse, Vec3::ZERO);
    assert_eq!(t.specular, Vec3::ZERO);
    assert_eq!(diffuse_factor(Vec3::NAN, Vec3::Z), 0.0);
    assert_eq!(phong_specular_factor(Vec3::NAN, Vec3::Z, Vec3::Z, 32.0), 0.0);
    assert_eq!(reference::phong::diffuse_factor(glam::DVec3::NAN, glam::DVec3::Z), 0.0);
    assert_eq!(reference::phong::phong_specular_factor(glam::DVec3::NAN, glam::DVec3::Z, glam::DVec3::Z, 32.0), 0.0);
    // Zero normal with the eye behind the fragment, facing the light: before the
    // fix, reflect(-l, 0) = -l = view_dir gave spec = 1 (found by
    // `ambient_is_geometry_free`). No mirror plane, no highlight.
    assert_eq!(phong_specular_factor(Vec3::ZERO, Vec3::Z, -Vec3::Z, 1.0), 0.0);
    assert_eq!(reference::phong::phong_specular_factor(glam::DVec3::ZERO, glam::DVec3::Z, -glam::DVec3::Z, 1.0), 0.0);
    // Opposite light and view: halfway is zero, not NaN.
    assert_eq!(halfway(Vec3::X, -Vec3::X), Vec3::ZERO);
    assert_eq!(blinn_specular_factor(Vec3::Z, Vec3::X, -Vec3::X, 32.0), 0.0);
    assert_eq!(reference::phong::halfway(glam::DVec3::X, -glam::DVec3::X), glam::DVec3::ZERO);
    // Shininess 0 at a grazing base: 0, not 1.
    assert_eq!(phong_specular_factor(Vec3::Z, Vec3::Z, Vec3::X, 0.0), 0.0);
    assert_eq!(lobe_half_width_deg(0.0), None);
    assert_eq!(lobe_half_width_deg(f32::NAN), None);
    // Singular view matrix: zero diffuse and specular.
    let t = b.terms_in_view_space(Mat4::ZERO, Vec3::ZERO, Vec3::Z);
    assert_eq!(t.diffuse, Vec3::ZERO);
    assert_eq!(t.specular, Vec3::ZERO);
}
