//! Precision: the `f32` shader path against the independent `f64` reference.
//!
//! Each property feeds the *same* `f32` inputs to both paths (widening to `f64`
//! is exact), so the difference is the `f32` path's rounding error alone (the
//! reference's own error, ~1e-15, is negligible). Every bound is derived from
//! the standard model of floating point: each correctly rounded `f32`
//! operation has relative error at most `U = 2^-24`, a dot product of length 3
//! has absolute error at most `γ₃ Σ|aₖbₖ| ≈ 3U Σ|aₖbₖ|` (Higham, "Accuracy and
//! Stability of Numerical Algorithms", §3.1), and for `pow` the mean value
//! theorem gives, for `s ≥ 1`,
//!
//! ```text
//! |x̂^s − x^s| ≤ s · max(x, x̂)^(s−1) · |x̂ − x|      (+ pow's own ≤ 2U · x^s)
//! ```
//!
//! so the base's error is amplified by up to `s`. Run with
//! `cargo test --test suite precision:: -- --nocapture` to see, for each formula, the
//! maximum observed error and the largest error/bound ratio (≤ 1 passes).
use crate::common;

use std::cell::Cell;

use common::{config, unit_vec3, vec3_in, U};
use glam::{DVec3, Mat3, Vec2, Vec3};
use lightlab::reference::{self, dmat3, dvec3};
use proptest::prelude::*;
use proptest::test_runner::{TestCaseError, TestRunner};

/// One comparison: what, expected (reference), actual (f32), allowed difference.
struct Check {
    what: String,
    expected: f64,
    actual: f64,
    bound: f64,
}

/// Absolute floor for every bound: `f32` results below 2^-126 are subnormal,
/// spaced 2^-149 ≈ 1.4e-45 apart, so relative bounds fail there (found by
/// these properties: `pow(0.31, 108)` ≈ 1e-55 underflows to 0 in `f32`). A
/// chain of up to 64 such roundings is covered by 64 · 2^-149.
const UNDERFLOW: f64 = 64.0 * 1.401_298_464_324_817e-45;

fn chk(what: impl Into<String>, expected: f64, actual: f32, bound: f64) -> Check {
    Check { what: what.into(), expected, actual: actual as f64, bound: bound + UNDERFLOW }
}

fn chk3(what: &str, expected: DVec3, actual: Vec3, bound: DVec3) -> Vec<Check> {
    (0..3).map(|k| chk(format!("{what}[{k}]"), expected[k], actual[k], bound[k])).collect()
}

/// Run `cases` cases of `f` over `strategy` from the fixed seed; fail with
/// expected/actual/difference if any check exceeds its bound; print the max
/// observed error and the max error/bound ratio.
fn precision<S: Strategy>(name: &str, cases: u32, strategy: S, f: impl Fn(S::Value) -> Vec<Check>)
where
    S::Value: std::fmt::Debug,
{
    let max_err = Cell::new(0.0f64);
    let max_ratio = Cell::new(0.0f64);
    let mut runner = TestRunner::new(ProptestConfig { cases, ..config() });
    let result = runner.run(&strategy, |v| {
        for c in f(v) {
            let diff = (c.actual - c.expected).abs();
            // A NaN difference or bound must fail too, hence not `diff > bound`.
            if diff.partial_cmp(&c.bound).is_none_or(|o| o.is_gt()) {
                return Err(TestCaseError::fail(format!(
                    "{name} {}: expected {:e}, actual {:e}, difference {diff:e} > bound {:e}",
                    c.what, c.expected, c.actual, c.bound
                )));
            }
            max_err.set(max_err.get().max(diff));
            if c.bound > 0.0 {
                max_ratio.set(max_ratio.get().max(diff / c.bound));
            }
        }
        Ok(())
    });
    eprintln!("precision {name:<28} max |f32 − f64| = {:.3e}  max error/bound = {:.3}", max_err.get(), max_ratio.get());
    if let Err(e) = result {
        panic!("{e}");
    }
}

/// `|x̂^s − x^s|` bound for a base with absolute error `dx`, `s ≥ 1`, `x ≥ 0`.
fn pow_bound(x: f64, s: f64, dx: f64) -> f64 {
    s * (x + dx).min(1.0 + dx).powf(s - 1.0) * dx + 2.0 * U * x.powf(s)
}

/// `n · n − 1` for an `f32` vector, exactly in `f64`: how far from unit it is.
fn unit_defect(n: Vec3) -> f64 {
    (dvec3(n).length_squared() - 1.0).abs()
}

const CASES: u32 = 2048;

#[test]
fn reflect_f32_vs_f64() {
    // Per component: dot (γ₃|i|), product and subtraction (2U|i|) for each of
    // the two uses: ≤ 10U|i|; plus the GLSL formula's deviation from a true
    // mirror when |n|² = 1 + δ: 2|δ||i|.
    precision("reflect", CASES, (vec3_in(10.0), unit_vec3()), |(i, n)| {
        let r = lightlab::glsl::reflect(i, n);
        let rd = reference::glsl::reflect(dvec3(i), dvec3(n));
        let b = (10.0 * U + 2.0 * unit_defect(n)) * dvec3(i).length();
        chk3("r", rd, r, DVec3::splat(b))
    });
}

#[test]
fn diffuse_f32_vs_f64() {
    // max(n·l, 0): one dot product, γ₃ Σ|nₖlₖ| ≤ 3U (+U slack for γ₃ > 3U).
    precision("diffuse_factor", CASES, (unit_vec3(), unit_vec3()), |(n, l)| {
        let (nd, ld) = (dvec3(n), dvec3(l));
        let b = 3.01 * U * (nd * ld).abs().element_sum() + 1e-15;
        vec![chk("diff", reference::phong::diffuse_factor(nd, ld), lightlab::phong::diffuse_factor(n, l), b)]
    });
}

#[test]
fn phong_specular_f32_vs_f64() {
    // Base x = view_dir · reflect_dir: reflect adds ≤ (10U + 2δ) per component
    // (see reflect), the dot γ₃: Δx ≤ √3 (10U + 2δ) + 3U ≤ 21U + 4δ.
    // Then pow: s · (x + Δx)^(s−1) · Δx + 2U x^s.
    precision(
        "phong_specular_factor",
        CASES,
        (unit_vec3(), unit_vec3(), unit_vec3(), 1.0f32..256.0),
        |(n, l, v, s)| {
            let (nd, ld, vd) = (dvec3(n), dvec3(l), dvec3(v));
            let x = vd.dot(reference::glsl::reflect(-ld, nd)).max(0.0);
            let dx = 21.0 * U + 4.0 * unit_defect(n);
            let b = pow_bound(x, s as f64, dx);
            let expected = reference::phong::phong_specular_factor(nd, ld, vd, s as f64);
            vec![chk(
                format!("spec (x = {x}, s = {s})"),
                expected,
                lightlab::phong::phong_specular_factor(n, l, v, s),
                b,
            )]
        },
    );
}

#[test]
fn blinn_specular_f32_vs_f64() {
    // halfway: sum (U), length (2U), division (U): each component ≤ 4U relative.
    // n·h: γ₃ plus Σ|nₖ| 4U|hₖ| ≤ 7U; Δx ≤ 8U. Then pow as above.
    precision(
        "blinn_specular_factor",
        CASES,
        (unit_vec3(), unit_vec3(), unit_vec3(), 1.0f32..256.0),
        |(n, l, v, s)| {
            let (nd, ld, vd) = (dvec3(n), dvec3(l), dvec3(v));
            let x = nd.dot(reference::phong::halfway(ld, vd)).max(0.0);
            let b = pow_bound(x, s as f64, 8.0 * U);
            let expected = reference::phong::blinn_specular_factor(nd, ld, vd, s as f64);
            vec![chk(
                format!("spec (x = {x}, s = {s})"),
                expected,
                lightlab::phong::blinn_specular_factor(n, l, v, s),
                b,
            )]
        },
    );
}

/// The basic-lighting shader from positions: adds normalize(p − q) in f32.
#[test]
fn basic_lighting_f32_vs_f64() {
    // light_dir, view_dir: subtraction (U) and normalize (3U): 4U relative per
    // component. Diffuse base: γ₃ + Σ|nₖ|4U|lₖ| + normal's own normalize 4U ≤ 11U.
    // Specular base: reflect of a 4U-perturbed l about a 4U-perturbed n
    // (≤ 10U + 3·4U per component), dotted with a 4U-perturbed v: Δx ≤ 40U.
    // Products with lit = light ⊙ object and strengths: 3U relative.
    let scene = (vec3_in(10.0), vec3_in(10.0), common::color(), 1.0f32..128.0, vec3_in(5.0), unit_vec3());
    precision("BasicLighting::terms", CASES, scene, |(light_pos, view_pos, light_color, shininess, frag, normal)| {
        let b = lightlab::phong::BasicLighting {
            light_pos,
            view_pos,
            light_color,
            shininess,
            ..lightlab::phong::BasicLighting::learnopengl()
        };
        if light_pos.distance(frag) < 0.5 || view_pos.distance(frag) < 0.5 {
            return vec![];
        }
        let t = b.terms(frag, normal);
        let bd = reference::phong::BasicLighting::from_f32(&b);
        let td = bd.terms(dvec3(frag), dvec3(normal));
        let lit = bd.light_color * bd.object_color;
        let (n, l, v) = (
            dvec3(normal).normalize(),
            (bd.light_pos - dvec3(frag)).normalize(),
            (bd.view_pos - dvec3(frag)).normalize(),
        );
        let x = v.dot(reference::glsl::reflect(-l, n)).max(0.0);
        let mut c = chk3("ambient", td.ambient, t.ambient, td.ambient.abs() * 3.0 * U);
        c.extend(chk3("diffuse", td.diffuse, t.diffuse, lit * 11.0 * U + td.diffuse.abs() * 3.0 * U));
        let spec_b = lit * bd.specular_strength * pow_bound(x, bd.shininess, 40.0 * U) + td.specular.abs() * 3.0 * U;
        c.extend(chk3("specular", td.specular, t.specular, spec_b));
        c
    });
}

/// Sum of |products| in each 2×2 minor: the error scale of each cofactor.
fn cofactor_scale(m: glam::DMat3) -> glam::DMat3 {
    let a = glam::DMat3::from_cols(m.x_axis.abs(), m.y_axis.abs(), m.z_axis.abs());
    let e = |r: usize, c: usize| a.col(c)[r];
    let p = |r1, r2, c1, c2| e(r1, c1) * e(r2, c2) + e(r1, c2) * e(r2, c1);
    // entry (r, c) uses the rows other than r and the columns other than c.
    let others = |k: usize| match k {
        0 => (1, 2),
        1 => (0, 2),
        _ => (0, 1),
    };
    let cols = [0, 1, 2].map(|c| {
        let (c1, c2) = others(c);
        DVec3::from_array([0, 1, 2].map(|r| {
            let (r1, r2) = others(r);
            p(r1, r2, c1, c2)
        }))
    });
    glam::DMat3::from_cols(cols[0], cols[1], cols[2])
}

#[test]
fn normal_matrix_cofactor_f32_vs_f64() {
    // Each cofactor is one 2×2 determinant ad − bc: error ≤ γ₂(|ad| + |bc|) ≈ 2U(|ad| + |bc|).
    precision("normal_matrix_cofactor", CASES, common::invertible_mat3(), |m: Mat3| {
        let c = lightlab::normals::normal_matrix_cofactor(m);
        let cd = reference::normals::normal_matrix_cofactor(dmat3(m));
        let scale = cofactor_scale(dmat3(m));
        (0..3).flat_map(|k| chk3(&format!("col {k}"), cd.col(k), c.col(k), scale.col(k) * 2.01 * U)).collect()
    });
}

#[test]
fn normal_matrix_inverse_transpose_f32_vs_f64() {
    // Perturbation theory for the inverse: ‖Δ(A⁻¹)‖ ≲ c · κ(A) · U · ‖A⁻¹‖ with
    // c a small constant for a 3×3 cofactor inverse (cofactors γ₂, determinant
    // γ₃, one division): c = 8, in the Frobenius norm, applied per entry.
    precision("normal_matrix_inverse_transpose", CASES, common::invertible_mat3(), |m: Mat3| {
        let it = lightlab::normals::normal_matrix_inverse_transpose(m).unwrap();
        let itd = reference::normals::normal_matrix_inverse_transpose(dmat3(m)).unwrap();
        let kappa = lightlab::normals::condition_number(m) as f64;
        let norm = (itd.x_axis.length_squared() + itd.y_axis.length_squared() + itd.z_axis.length_squared()).sqrt();
        let b = 8.0 * kappa * U * norm;
        (0..3)
            .flat_map(|k| chk3(&format!("col {k} (κ = {kappa:.1})"), itd.col(k), it.col(k), DVec3::splat(b)))
            .collect()
    });
}

/// The smallest interior angle of a triangle, in radians (f64).
fn min_angle(p: [DVec3; 3]) -> f64 {
    (0..3).map(|k| reference::angle_between(p[(k + 1) % 3] - p[k], p[(k + 2) % 3] - p[k])).fold(f64::INFINITY, f64::min)
}

#[test]
fn vertex_normals_f32_vs_f64() {
    // Each face normal: cross product (γ₂ per component of a ~|e|² quantity)
    // normalized (3U): ≤ 6U·(1 + |e|²/|c|) ≲ 6U / sin(θ_min) relative.
    // Angle weights: f32 acos of a dot with error ~5U has error 5U / sin θ, so the
    // weight's relative error is ≤ 5U / (θ sin θ). Slivers (θ_min < 10°) are
    // dropped from the mesh, so per face the relative error is ≤ K U with
    // K = 6/sin 10° + 5/(0.1745 · sin 10°) + 4 ≈ 35 + 165 + 4 ≈ 200.
    // The sum's error is then ≤ K U Σ|w_f n_f|, and normalizing divides by |Σ w_f n_f|.
    let mesh = prop::collection::vec(vec3_in(3.0), 4..10).prop_flat_map(|p| {
        let n = p.len() as u32;
        (Just(p), prop::collection::vec(prop::array::uniform3(0..n), 1..12))
    });
    precision("vertex_normals", 512, mesh, |(p, tris)| {
        let pd: Vec<DVec3> = p.iter().map(|&x| dvec3(x)).collect();
        let tris: Vec<[u32; 3]> =
            tris.into_iter().filter(|t| min_angle(t.map(|k| pd[k as usize])) > 10f64.to_radians()).collect();
        let mut checks = vec![];
        for w in [
            lightlab::normals::VertexWeighting::Unweighted,
            lightlab::normals::VertexWeighting::Area,
            lightlab::normals::VertexWeighting::Angle,
        ] {
            let got = lightlab::normals::vertex_normals(&p, &tris, w).unwrap();
            let want = reference::normals::vertex_normals(&pd, &tris, w).unwrap();
            // Σ|w_f n_f| / |Σ w_f n_f| per vertex, in f64.
            let mut abs_sum = vec![0.0; p.len()];
            let mut sum = vec![DVec3::ZERO; p.len()];
            for t in &tris {
                let c =
                    reference::normals::triangle_area_vector(pd[t[0] as usize], pd[t[1] as usize], pd[t[2] as usize]);
                for k in 0..3 {
                    let q = t.map(|i| pd[i as usize]);
                    let weight = match w {
                        lightlab::normals::VertexWeighting::Unweighted => 1.0 / c.length(),
                        lightlab::normals::VertexWeighting::Area => 1.0,
                        lightlab::normals::VertexWeighting::Angle => {
                            reference::angle_between(q[(k + 1) % 3] - q[k], q[(k + 2) % 3] - q[k]) / c.length()
                        }
                    };
                    abs_sum[t[k] as usize] += (c * weight).length();
                    sum[t[k] as usize] += c * weight;
                }
            }
            for (i, (g, e)) in got.iter().zip(&want).enumerate() {
                if sum[i].length() <= 1e-6 * abs_sum[i] {
                    continue; // cancelling sum: direction undefined to f32 precision
                }
                let b = 2.0 * 200.0 * U * abs_sum[i] / sum[i].length();
                checks.extend(chk3(&format!("{w:?} vertex {i}"), *e, *g, DVec3::splat(b)));
            }
        }
        checks
    });
}

#[test]
fn attenuation_f32_vs_f64() {
    // Kc + Kl d + Kq d²: 5 roundings of non-negative terms (no cancellation),
    // then 1/x: relative ≤ 6U.
    let att = (1.0f32..4.0, 0.0f32..1.0, 0.0f32..2.0, 0.0f32..1000.0);
    precision("Attenuation::at", CASES, att, |(c, l, q, d)| {
        let a = lightlab::casters::Attenuation::new(c, l, q).unwrap();
        let ad = reference::casters::Attenuation::from_f32(&a).at(d as f64);
        vec![chk("at", ad, a.at(d), 6.0 * U * ad)]
    });
}

#[test]
fn distance_for_f32_vs_f64() {
    // c' = Kc − 1/f cancels when 1/f ≈ Kc: its relative error is
    // ≤ 2U (Kc + 1/f) / |c'|; the root −2c'/(Kl + sqrt(Kl² − 4Kq c')) adds only
    // positive terms: ≤ 8U more. Bound: (2U (Kc + 1/f)/|c'| + 8U) · d.
    let att = (1.0f32..4.0, 0.0f32..1.0, 0.0f32..2.0, 0.001f32..0.99);
    precision("Attenuation::distance_for", CASES, att, |(c, l, q, f)| {
        if l + q < 1e-3 {
            return vec![];
        }
        let a = lightlab::casters::Attenuation::new(c, l, q).unwrap();
        let ad = reference::casters::Attenuation::from_f32(&a);
        let (fd, cd) = (f as f64, c as f64);
        let cprime = cd - 1.0 / fd;
        let d = ad.distance_for(fd).unwrap();
        if cprime >= 0.0 {
            return vec![chk("d (already below)", d, a.distance_for(f).unwrap(), 0.0)];
        }
        let b = (2.0 * U * (cd + 1.0 / fd) / cprime.abs() + 8.0 * U) * d;
        vec![chk(format!("d (c' = {cprime:e})"), d, a.distance_for(f).unwrap(), b)]
    });
}

#[test]
fn spot_intensity_f32_vs_f64() {
    // Given theta and the cosines as f32 values: two subtractions and a
    // division, each ≤ U relative: ≤ 3U · I (clamping does not add error).
    let cones = (0.5f32..60.0, 0.05f32..20.0, 0.0f32..90.0);
    precision("spot_intensity", CASES, cones, |(inner, gap, a)| {
        let (phi, gamma) = (inner.to_radians().cos(), (inner + gap).to_radians().cos());
        let theta = a.to_radians().cos();
        let e = reference::casters::spot_intensity(theta as f64, phi as f64, gamma as f64);
        vec![chk("intensity", e, lightlab::casters::spot_intensity(theta, phi, gamma), 3.0 * U * e + 1e-15)]
    });
}

#[test]
fn spot_light_from_positions_f32_vs_f64() {
    // From positions, theta = light_dir · normalize(−direction) carries ≤ 11U
    // (two normalizes 4U each, a dot 3U); the ramp divides it by ε = cos φ − cos γ,
    // so intensity error ≤ 11U / ε (+ 3U). With the flashlight's 12.5°/15°,
    // ε = 0.0104: the soft edge amplifies the f32 error about 100×.
    let s = (vec3_in(5.0), unit_vec3(), 1.0f32..40.0, 0.2f32..10.0, vec3_in(5.0));
    precision("SpotLight intensity (positions)", CASES, s, |(pos, dir, inner, gap, frag)| {
        if pos.distance(frag) < 0.5 {
            return vec![];
        }
        let props = lightlab::material::LightProps::white();
        let spot = lightlab::casters::SpotLight::new(
            pos,
            dir,
            inner,
            inner + gap,
            lightlab::casters::Attenuation::LEARNOPENGL,
            props,
        )
        .unwrap();
        let sd = reference::casters::SpotLight::from_f32(&spot);
        let theta = spot.theta((pos - frag).normalize());
        let theta_d = sd.theta((sd.position - dvec3(frag)).normalize());
        let i = lightlab::casters::spot_intensity(theta, spot.cut_off, spot.outer_cut_off);
        let id = reference::casters::spot_intensity(theta_d, sd.cut_off, sd.outer_cut_off);
        let eps = sd.cut_off - sd.outer_cut_off;
        vec![
            chk("theta", theta_d, theta, 11.0 * U),
            chk(format!("intensity (ε = {eps:e})"), id, i, 11.0 * U / eps + 3.0 * U),
        ]
    });
}

#[test]
fn texture_bilinear_f32_vs_f64() {
    // x = u·w − ½: ≤ U|u w| + U|x| ≤ 2U(|u| w + 1) absolute; the same for y.
    // The bilinear value is Lipschitz in (x, y) with constant ≤ max texel
    // difference ≤ 1 per axis; the two nested lerps round ≤ 3U each.
    let tex = (1usize..=8, 1usize..=8).prop_flat_map(|(w, h)| {
        (Just((w, h)), prop::collection::vec(common::color(), w * h), -3.0f32..3.0, -3.0f32..3.0)
    });
    precision("Texture::sample bilinear", CASES, tex, |((w, h), texels, u, v)| {
        let t = lightlab::maps::Texture::new(w, h, texels).unwrap();
        let td = reference::maps::Texture::from_f32(&t);
        let mut c = vec![];
        for wrap in [lightlab::maps::Wrap::Repeat, lightlab::maps::Wrap::ClampToEdge] {
            let s = t.sample(Vec2::new(u, v), lightlab::maps::Filter::Bilinear, wrap);
            let sd = td.sample(glam::DVec2::new(u as f64, v as f64), lightlab::maps::Filter::Bilinear, wrap);
            let b =
                2.0 * U * ((u.abs() * w as f32) as f64 + 1.0) + 2.0 * U * ((v.abs() * h as f32) as f64 + 1.0) + 6.0 * U;
            c.extend(chk3(&format!("{wrap:?}"), sd, s, DVec3::splat(b)));
        }
        c
    });
}

#[test]
fn multiple_lights_scene_f32_vs_f64() {
    // Per light: diffuse base ≤ 11U and specular base ≤ 40U (as basic lighting),
    // specular through pow_bound; attenuation ≤ 9U relative (distance 3U + at 6U);
    // spot intensity ≤ 11U/ε + 3U; final products and the sum ≤ 8U relative.
    // The bound is the sum over lights of (unscaled term scale × those errors).
    let frag = (vec3_in(3.0), unit_vec3(), 0usize..5);
    precision("Scene::shade (presets)", 1024, frag, |(frag, normal, preset)| {
        let scene = match preset {
            0 => lightlab::scene::Scene::learnopengl_default(),
            k => lightlab::scene::Atmosphere::ALL[k - 1].scene(),
        };
        let m = lightlab::material::Material::coral();
        let eye = Vec3::new(0.0, 0.0, 3.0);
        if frag.distance(eye) < 0.5 || scene.point_lights.iter().any(|p| p.position.distance(frag) < 0.5) {
            return vec![];
        }
        let sd = reference::scene::Scene::from_f32(&scene);
        let md = reference::material::Material::from_f32(&m);
        let got = scene.shade(&m, frag, normal, eye);
        let want = sd.shade(&md, dvec3(frag), dvec3(normal), dvec3(eye));
        let (n, v) = (dvec3(normal).normalize(), (dvec3(eye) - dvec3(frag)).normalize());
        let s = md.shininess;
        let light_bound = |props: &reference::material::LightProps, l: DVec3, scale: f64, scale_err: f64| {
            let x = v.dot(reference::glsl::reflect(-l, n)).max(0.0);
            let diff = props.diffuse * md.diffuse * (11.0 * U);
            let spec = props.specular * md.specular * pow_bound(x, s, 40.0 * U);
            let base = props.ambient * md.ambient + props.diffuse * md.diffuse + props.specular * md.specular;
            (diff + spec) * scale + base * (scale_err + 8.0 * U * scale)
        };
        let mut bound = DVec3::ZERO;
        if let Some(d) = &sd.dir_light {
            bound += light_bound(&d.props, d.light_dir(), 1.0, 0.0);
        }
        for p in &sd.point_lights {
            let l = (p.position - dvec3(frag)).normalize();
            let att = p.attenuation.at((p.position - dvec3(frag)).length());
            bound += light_bound(&p.props, l, att, 9.0 * U * att);
        }
        if let Some(sp) = &sd.spot_light {
            let l = (sp.position - dvec3(frag)).normalize();
            let att = sp.attenuation.at((sp.position - dvec3(frag)).length());
            let i = reference::casters::spot_intensity(sp.theta(l), sp.cut_off, sp.outer_cut_off);
            let eps = sp.cut_off - sp.outer_cut_off;
            bound += light_bound(&sp.props, l, att * i, att * (11.0 * U / eps + 3.0 * U) + 9.0 * U * att * i);
        }
        chk3(&format!("preset {preset} rgb"), want.rgb(), got.rgb(), bound + want.rgb().abs() * 8.0 * U)
    });
}

#[test]
fn ogldev_f32_vs_f64() {
    // Diffuse: n·(−Direction) γ₃ + normalize(normal) 4U ≤ 8U, × intensity and
    // colours 4U. Specular base: reflect of Direction about n (≤ 10U + 12U),
    // renormalized (4U), dotted with a 4U vertex_to_eye: ≤ 40U; then pow_bound.
    // The gate n·l > 0 may flip between paths when |n·l| ≤ 8U: such cases are skipped.
    let m = (unit_vec3(), unit_vec3(), vec3_in(5.0), vec3_in(10.0), 1.0f32..128.0);
    precision("Ogldev::terms", CASES, m, |(normal, l, frag, eye, power)| {
        if normal.dot(l).abs() < 1e-5 || frag.distance(eye) < 0.5 {
            return vec![];
        }
        let o = lightlab::models::Ogldev {
            color: Vec3::ONE,
            ambient_intensity: 0.1,
            diffuse_intensity: 0.8,
            direction: -l,
            specular_intensity: 1.0,
            specular_power: power,
            texture_color: Vec3::new(1.0, 0.5, 0.31),
        };
        let od = reference::models::Ogldev::from_f32(&o);
        let t = o.terms(frag, normal, eye);
        let td = od.terms(dvec3(frag), dvec3(normal), dvec3(eye));
        let n = dvec3(normal).normalize();
        let x = (dvec3(eye) - dvec3(frag)).normalize().dot(reference::glsl::reflect(-dvec3(l), n).normalize()).max(0.0);
        let tex = dvec3(o.texture_color);
        let mut c = chk3("diffuse", td.diffuse, t.diffuse, tex * 0.8 * 8.0 * U + td.diffuse.abs() * 4.0 * U);
        c.extend(chk3(
            "specular",
            td.specular,
            t.specular,
            tex * pow_bound(x, power as f64, 40.0 * U) + td.specular.abs() * 4.0 * U,
        ));
        c
    });
}

#[test]
fn opengl_tutorial_f32_vs_f64() {
    // Falloff power / d²: d² from a subtraction and a squared length: ≤ 6U
    // relative, division U. Diffuse base ≤ 11U, specular base ≤ 40U (exponent 5).
    let m = (vec3_in(10.0), vec3_in(5.0), unit_vec3(), vec3_in(10.0));
    precision("OpenGLTutorial::terms", CASES, m, |(light, frag, normal, eye)| {
        if light.distance(frag) < 0.5 || eye.distance(frag) < 0.5 {
            return vec![];
        }
        let o = lightlab::models::OpenGLTutorial::with_defaults(light, Vec3::new(1.0, 0.5, 0.31));
        let od = reference::models::OpenGLTutorial::from_f32(&o);
        let t = o.terms(frag, normal, eye);
        let td = od.terms(dvec3(frag), dvec3(normal), dvec3(eye));
        let d2 = dvec3(light).distance_squared(dvec3(frag));
        let falloff = 50.0 / d2;
        let (n, l) = (dvec3(normal).normalize(), (dvec3(light) - dvec3(frag)).normalize());
        let x = (dvec3(eye) - dvec3(frag)).normalize().dot(reference::glsl::reflect(-l, n)).max(0.0);
        let mut c =
            chk3("diffuse", td.diffuse, t.diffuse, od.diffuse * falloff * 11.0 * U + td.diffuse.abs() * 10.0 * U);
        c.extend(chk3(
            "specular",
            td.specular,
            t.specular,
            od.specular * falloff * pow_bound(x, 5.0, 40.0 * U) + td.specular.abs() * 10.0 * U,
        ));
        c
    });
}

#[test]
fn srgb_f32_vs_f64() {
    // 1.055 · x^(1/2.4) − 0.055: powf ≤ 2U relative, the product U, the
    // subtraction U of a result ≥ 0.04: ≤ 4U · 1.055 absolute + U.
    precision("linear_to_srgb", CASES, 0.0f32..=1.0, |x| {
        vec![chk("srgb", reference::color::linear_to_srgb(x as f64), lightlab::color::linear_to_srgb(x), 6.0 * U)]
    });
}

#[test]
fn modulate_f32_vs_f64() {
    // One product per channel: ≤ U relative.
    precision("modulate", CASES, (common::color(), common::color()), |(l, o)| {
        let e = reference::color::modulate(dvec3(l), dvec3(o));
        chk3("rgb", e, lightlab::color::modulate(l, o), e.abs() * U)
    });
}

#[test]
fn material_terms_f32_vs_f64() {
    // ambient: one product (U). diffuse: diff (γ₃ Σ|nₖlₖ|) then two products (2U).
    // specular: spec through pow_bound with the Phong base error 21U + 4δ, then two products.
    let m = (common::color(), common::color(), common::color(), 1.0f32..128.0, unit_vec3(), unit_vec3(), unit_vec3());
    precision("material_terms", CASES, m, |(mat_d, light_d, spec_c, s, n, l, v)| {
        let mat = lightlab::material::Material { ambient: mat_d, diffuse: mat_d, specular: spec_c, shininess: s };
        let light = lightlab::material::LightProps { ambient: light_d * 0.2, diffuse: light_d, specular: Vec3::ONE };
        let t = lightlab::material::material_terms(&mat, &light, n, l, v);
        let (md, ld) =
            (reference::material::Material::from_f32(&mat), reference::material::LightProps::from_f32(&light));
        let (nd, lv, vd) = (dvec3(n), dvec3(l), dvec3(v));
        let td = reference::material::material_terms(&md, &ld, nd, lv, vd);
        let x = vd.dot(reference::glsl::reflect(-lv, nd)).max(0.0);
        let mut c = chk3("ambient", td.ambient, t.ambient, td.ambient.abs() * U);
        c.extend(chk3(
            "diffuse",
            td.diffuse,
            t.diffuse,
            ld.diffuse * md.diffuse * 3.01 * U + td.diffuse.abs() * 2.0 * U,
        ));
        let sb = ld.specular * md.specular * pow_bound(x, s as f64, 21.0 * U + 4.0 * unit_defect(n))
            + td.specular.abs() * 2.0 * U;
        c.extend(chk3("specular", td.specular, t.specular, sb));
        c
    });
}

#[test]
fn lobe_half_width_f32_vs_f64() {
    // x = 0.5^(1/s) carries ≤ 2U relative (1/s, powf); acos'(x) = −1/√(1 − x²)
    // amplifies it to 2U x / √(1 − x²) radians, and acos itself and the
    // conversion to degrees add ≤ 2U relative.
    precision("lobe_half_width_deg", CASES, 1.0f32..1024.0, |s| {
        let sd = s as f64;
        let x = 0.5f64.powf(1.0 / sd);
        let e = reference::phong::lobe_half_width_deg(sd).unwrap();
        let b = (2.0 * U * x / (1.0 - x * x).sqrt()).to_degrees() + 2.0 * U * e;
        vec![chk(format!("degrees (s = {s})"), e, lightlab::phong::lobe_half_width_deg(s).unwrap(), b)]
    });
}
