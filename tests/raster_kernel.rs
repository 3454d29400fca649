//! The 16-lane multi-light kernel against the scalar `Scene::shade`.

use glam::Vec3;
use lightlab::material::Material;
use lightlab::raster::kernel::{exp2, log2, pow_or_zero, LaneMaterial, MultiLightKernel, Specular, LANES};
use lightlab::scene::{Atmosphere, Scene};

/// A seeded generator (deterministic tests).
struct Lcg(u64);
impl Lcg {
    fn next(&mut self) -> f32 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        ((self.0 >> 40) as f32) / (1u64 << 24) as f32
    }
    fn range(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * self.next()
    }
    fn vec(&mut self, r: f32) -> Vec3 {
        Vec3::new(self.range(-r, r), self.range(-r, r), self.range(-r, r))
    }
    /// 16 positions in [-r, r]³ and 16 normals in [-1, 1]³ (any length), lane by lane.
    fn batch(&mut self, r: f32) -> ([[f32; LANES]; 3], [[f32; LANES]; 3]) {
        let mut pos = [[0.0; LANES]; 3];
        let mut normal = [[0.0; LANES]; 3];
        for l in 0..LANES {
            let (p, n) = (self.vec(r), self.vec(1.0));
            for c in 0..3 {
                pos[c][l] = p[c];
                normal[c][l] = n[c];
            }
        }
        (pos, normal)
    }
}

fn check_scene(scene: &Scene, material: &Material, seed: u64) -> f32 {
    let eye = Vec3::new(0.0, 0.0, 3.0);
    let kernel = MultiLightKernel::new(scene, eye, material.shininess, Specular::Phong);
    let baseline = kernel.clone().baseline();
    // told the material: coloured lights are summed with it folded in
    let folded = kernel.clone().with_material(material);
    let lane_material = LaneMaterial::uniform(material);
    let mut rng = Lcg(seed);
    let mut worst = 0.0f32;
    for _ in 0..200 {
        let (pos, normal) = rng.batch(3.0);
        let (mut fast, mut base, mut fold) = ([[0.0; LANES]; 3], [[0.0; LANES]; 3], [[0.0; LANES]; 3]);
        kernel.shade(&pos, &normal, &lane_material, &mut fast);
        baseline.shade(&pos, &normal, &lane_material, &mut base);
        folded.shade(&pos, &normal, folded.material_lanes().expect("told a material"), &mut fold);
        for l in 0..LANES {
            let p = Vec3::new(pos[0][l], pos[1][l], pos[2][l]);
            let n = Vec3::new(normal[0][l], normal[1][l], normal[2][l]);
            let want = scene.shade(material, p, n, eye).rgb();
            for c in 0..3 {
                // no subnormal ever comes out (they are flushed inside, as llvmpipe does)
                assert!(!fast[c][l].is_subnormal(), "subnormal output {:e}", fast[c][l]);
                let err = (fast[c][l] - want[c]).abs() / want[c].abs().max(1.0);
                let folded_err = (fold[c][l] - want[c]).abs() / want[c].abs().max(1.0);
                worst = worst.max(err).max(folded_err);
                // the builds differ by rounding (fused multiply-adds) and by the AVX builds' 1/sqrt and
                // 1/x estimates after one Newton step (≤ 2e-7 relative with AVX2's 12-bit start), which
                // pow(·, 32) amplifies 32-fold: 1e-4 relative bounds it with room (1/255 is 4e-3)
                let gap = (fast[c][l] - base[c][l]).abs();
                assert!(
                    gap <= 1e-4 * want[c].abs().max(1.0),
                    "fast {} baseline {} gap {gap:e}",
                    fast[c][l],
                    base[c][l]
                );
            }
        }
    }
    worst
}

#[test]
fn kernel_matches_scene_shade_on_the_chapter_scene_and_atmospheres() {
    let coral = Material::coral();
    // 1e-4: regrouped sums (a few ulps), the estimates after one Newton step (2e-7) amplified 32-fold
    // by pow at shininess 32, with room; still 40 times below 1/255
    let tolerance = 1e-4;
    let worst = check_scene(&Scene::learnopengl_default(), &coral, 1);
    assert!(worst < tolerance, "default scene: worst relative error {worst:e} >= {tolerance:e}");
    for (k, a) in Atmosphere::ALL.into_iter().enumerate() {
        let worst = check_scene(&a.scene(), &coral, 10 + k as u64);
        assert!(worst < tolerance, "{}: worst relative error {worst:e} >= {tolerance:e}", a.name());
    }
}

/// A kernel told one material folds it into coloured lights only (fewer operations for
/// the atmospheres, the same count for the grey chapter scene), and shades a call given any
/// material but its own copy exactly as the kernel that was never told.
#[test]
fn a_folded_material_is_used_only_for_its_own_material() {
    let eye = Vec3::new(0.0, 0.0, 3.0);
    let coral = Material::coral();
    let grey = Scene::learnopengl_default();
    let plain = MultiLightKernel::new(&grey, eye, coral.shininess, Specular::Phong);
    let told = plain.clone().with_material(&coral);
    assert_eq!(told.flops_per_fragment(), plain.flops_per_fragment(), "grey lights keep the grey path");
    let scene = Atmosphere::Desert.scene();
    let plain = MultiLightKernel::new(&scene, eye, coral.shininess, Specular::Phong);
    let told = plain.clone().with_material(&coral);
    assert!(told.flops_per_fragment() < plain.flops_per_fragment(), "coloured lights fold the material");
    let mut rng = Lcg(77);
    let mut other = LaneMaterial::uniform(&coral);
    // one lane's diffuse differs: the call's material is not the folded one
    other.diffuse[1][5] = 0.25;
    // another material, one lane changed, and the same values at another address
    for material in
        [LaneMaterial::uniform(&Material { diffuse: Vec3::splat(0.5), ..coral }), other, LaneMaterial::uniform(&coral)]
    {
        let (pos, normal) = rng.batch(3.0);
        let (mut a, mut b) = ([[0.0; LANES]; 3], [[0.0; LANES]; 3]);
        plain.shade(&pos, &normal, &material, &mut a);
        told.shade(&pos, &normal, &material, &mut b);
        assert_eq!(a.map(|c| c.map(f32::to_bits)), b.map(|c| c.map(f32::to_bits)));
    }
}

/// Lanes whose distance to a light is 0, ∞ or NaN send their batch (or pair of
/// batches) down the kernel's general path; every other lane's colour must come out
/// bit for bit as on the fast path, where no such lane is beside it.
#[test]
fn an_irregular_lane_changes_no_bit_of_the_others() {
    use lightlab::raster::clip::MAX_VARYINGS;
    use lightlab::raster::rasterize::FragmentBatch;
    let scene = Scene::learnopengl_default();
    let m = Material::coral();
    let eye = Vec3::new(0.5, 1.0, 3.0);
    let lanes = LaneMaterial::uniform(&m);
    let at_light = scene.point_lights[1].position;
    // at a point light (d = 0), at infinity in one coordinate (d² = ∞), NaN, and so far
    // that d² overflows although every coordinate is finite
    let odd = [at_light, Vec3::new(f32::INFINITY, 0.0, 0.0), Vec3::splat(f32::NAN), Vec3::splat(3e19)];
    let mut rng = Lcg(7);
    for kernel in [
        MultiLightKernel::new(&scene, eye, m.shininess, Specular::Phong),
        MultiLightKernel::new(&scene, eye, m.shininess, Specular::Blinn),
        MultiLightKernel::new(&scene, eye, 10.5, Specular::Phong),
    ] {
        for (k, p) in odd.iter().enumerate() {
            let (pos, normal) = rng.batch(3.0);
            let mut regular = [[0.0; LANES]; 3];
            kernel.shade(&pos, &normal, &lanes, &mut regular);
            // the same batch with lane 5 moved to the odd point, shaded alone and as the
            // second of a pair whose first batch is regular
            let mut odd_pos = pos;
            for c in 0..3 {
                odd_pos[c][5] = p[c];
            }
            let mut alone = [[0.0; LANES]; 3];
            kernel.shade(&odd_pos, &normal, &lanes, &mut alone);
            let batch = |pos: &[[f32; LANES]; 3]| {
                let mut v = [[0.0; LANES]; MAX_VARYINGS];
                v[..3].copy_from_slice(pos);
                v[3..6].copy_from_slice(&normal);
                FragmentBatch::from_varyings(v, LANES)
            };
            let mut pair = vec![[[0.0; LANES]; 3]; 2];
            kernel.shade_batches(&[batch(&pos), batch(&odd_pos)], &lanes, &mut pair);
            for l in (0..LANES).filter(|&l| l != 5) {
                for c in 0..3 {
                    let want = regular[c][l].to_bits();
                    assert_eq!(alone[c][l].to_bits(), want, "odd point {k}, lane {l}, channel {c}, alone");
                    assert_eq!(pair[1][c][l].to_bits(), want, "odd point {k}, lane {l}, channel {c}, paired");
                }
            }
            for l in 0..LANES {
                for c in 0..3 {
                    assert_eq!(
                        pair[0][c][l].to_bits(),
                        regular[c][l].to_bits(),
                        "odd point {k}: regular batch of the pair"
                    );
                }
            }
        }
    }
}

#[test]
fn kernel_degenerate_inputs_match_scalar_path() {
    let scene = Scene::learnopengl_default();
    let m = Material::coral();
    let eye = Vec3::new(0.0, 0.0, 3.0);
    let kernel = MultiLightKernel::new(&scene, eye, m.shininess, Specular::Phong);
    // zero normal; fragment at a point light; fragment at the eye (and the spot); so far
    // from every light that d² overflows to ∞ (only the directional light reaches it)
    let cases = [
        (Vec3::ZERO, Vec3::ZERO),
        (Vec3::new(0.7, 0.2, 2.0), Vec3::Z),
        (eye, Vec3::Y),
        (Vec3::new(3e19, 0.0, 0.0), Vec3::X),
    ];
    let mut pos = [[0.0; LANES]; 3];
    let mut normal = [[0.0; LANES]; 3];
    for (l, (p, n)) in cases.iter().enumerate() {
        for c in 0..3 {
            pos[c][l] = p[c];
            normal[c][l] = n[c];
        }
    }
    let mut out = [[0.0; LANES]; 3];
    kernel.shade(&pos, &normal, &LaneMaterial::uniform(&m), &mut out);
    for (l, (p, n)) in cases.iter().enumerate() {
        let want = scene.shade(&m, *p, *n, eye).rgb();
        for c in 0..3 {
            assert!(out[c][l].is_finite(), "case {l}: non-finite {:?}", out[c][l]);
            // 1e-5: same formula; only the regrouping differs
            assert!(
                (out[c][l] - want[c]).abs() < 1e-5,
                "case {l} channel {c}: kernel {} scalar {}",
                out[c][l],
                want[c]
            );
        }
    }
}

#[test]
fn polynomial_pow_is_close_to_powf() {
    let mut rng = Lcg(7);
    for _ in 0..100_000 {
        let x = rng.range(1e-4, 1.0);
        let y = rng.range(0.5, 256.0);
        let want = x.powf(y);
        if want < 1e-30 {
            continue;
        }
        let got = pow_or_zero(x, y);
        // the exponent e = y·log2 x carries the polynomial's 6e-8 absolute error times y, plus f32
        // rounding of e (2^-24 |e|, doubled for the product and the split); 2^δ − 1 ≈ δ·ln 2
        let e = y * x.log2();
        let rel = (got - want).abs() / want;
        let bound = 1e-6 + std::f32::consts::LN_2 * (6e-8 * y + 2.0 * 6e-8 * e.abs());
        assert!(rel < bound, "pow({x}, {y}) = {got}, powf {want}, rel {rel:e}");
    }
    assert_eq!(pow_or_zero(0.0, 32.0), 0.0);
    assert_eq!(pow_or_zero(-0.5, 32.0), 0.0);
    assert_eq!(pow_or_zero(f32::NAN, 32.0), 0.0);
    assert_eq!(exp2(-200.0), 0.0);
    assert!((log2(8.0) - 3.0).abs() < 1e-6);
}

#[test]
fn whole_shininess_flushes_only_invisible_highlights() {
    // a light straight along the normal and a view that makes reflect·view tiny: spec^32 would be subnormal
    let light = lightlab::casters::DirLight { direction: Vec3::NEG_Z, props: lightlab::material::LightProps::white() };
    let scene = Scene { dir_light: Some(light), point_lights: vec![], spot_light: None, clear_color: Vec3::ZERO };
    let m = Material::coral();
    let kernel = MultiLightKernel::new(&scene, Vec3::new(0.0, 0.0, 3.0), 32.0, Specular::Phong);
    let mut pos = [[0.0; LANES]; 3];
    let mut normal = [[0.0; LANES]; 3];
    for l in 0..LANES {
        // views from 0° to ~89° off the normal: cos from 1 down to ~0.02
        pos[0][l] = 3.0 * (l as f32 * 0.1).tan();
        normal[2][l] = 1.0;
    }
    let mut out = [[0.0; LANES]; 3];
    kernel.shade(&pos, &normal, &LaneMaterial::uniform(&m), &mut out);
    for l in 0..LANES {
        let want = scene.shade(&m, Vec3::new(pos[0][l], 0.0, 0.0), Vec3::Z, Vec3::new(0.0, 0.0, 3.0)).rgb();
        for c in 0..3 {
            assert!(!out[c][l].is_subnormal());
            // 2e-5 relative: the flushed part is below 2^-126; the rest is rounding and the
            // reciprocal estimates amplified by pow, as above
            assert!(
                (out[c][l] - want[c]).abs() < 2e-5 * want[c].abs().max(1.0),
                "lane {l}: {} vs {}",
                out[c][l],
                want[c]
            );
        }
    }
}

#[test]
fn blinn_lobe_matches_the_core_blinn_factor() {
    let light = lightlab::casters::DirLight {
        direction: Vec3::new(-0.2, -1.0, -0.3),
        props: lightlab::material::LightProps::white(),
    };
    let scene = Scene { dir_light: Some(light), point_lights: vec![], spot_light: None, clear_color: Vec3::ZERO };
    let m = Material::coral();
    let eye = Vec3::new(0.0, 0.0, 3.0);
    let kernel = MultiLightKernel::new(&scene, eye, m.shininess, Specular::Blinn);
    let (pos, normal) = Lcg(3).batch(2.0);
    let mut out = [[0.0; LANES]; 3];
    kernel.shade(&pos, &normal, &LaneMaterial::uniform(&m), &mut out);
    for l in 0..LANES {
        let p = Vec3::new(pos[0][l], pos[1][l], pos[2][l]);
        let n = Vec3::new(normal[0][l], normal[1][l], normal[2][l]).normalize();
        let v = (eye - p).normalize();
        let ld = light.light_dir();
        let want = m.ambient
            + lightlab::phong::diffuse_factor(n, ld) * m.diffuse
            + lightlab::phong::blinn_specular_factor(n, ld, v, m.shininess) * m.specular;
        for c in 0..3 {
            // 2e-5 as above
            assert!((out[c][l] - want[c]).abs() < 2e-5, "lane {l}: kernel {} core {}", out[c][l], want[c]);
        }
    }
}

mod range_window {
    use super::*;
    use lightlab::casters::{range_window, Attenuation, PointLight};
    use lightlab::material::LightProps;
    use lightlab::raster::kernel::RangeWindow;

    fn one_light(at: Vec3) -> Scene {
        let light = PointLight {
            position: at,
            attenuation: Attenuation { constant: 1.0, linear: 0.7, quadratic: 1.8 },
            props: LightProps { ambient: Vec3::splat(0.05), diffuse: Vec3::new(0.8, 0.4, 0.2), specular: Vec3::ONE },
        };
        Scene { dir_light: None, point_lights: vec![light], spot_light: None, clear_color: Vec3::ZERO }
    }

    #[test]
    fn one_light_is_scaled_by_the_window_of_its_distance() {
        let m = Material::coral();
        let material = LaneMaterial::uniform(&m);
        let mut rng = Lcg(77);
        let range = 3.0;
        for _ in 0..100 {
            let at = rng.vec(2.0);
            let scene = one_light(at);
            let plain = MultiLightKernel::new(&scene, Vec3::Z, m.shininess, Specular::Phong);
            let windowed = plain.clone().with_range_window(Some(RangeWindow { range, cull: false }));
            let (pos, normal) = rng.batch(3.0);
            let (mut a, mut b) = ([[0.0; LANES]; 3], [[0.0; LANES]; 3]);
            plain.shade(&pos, &normal, &material, &mut a);
            windowed.shade(&pos, &normal, &material, &mut b);
            for l in 0..LANES {
                let p = Vec3::new(pos[0][l], pos[1][l], pos[2][l]);
                let w = range_window(p.distance(at), range);
                for c in 0..3 {
                    // every term of one light carries the same factor, so the window scales the
                    // sum; 1e-5 relative: the kernel's d from rsqrt (2 ulps) through x⁴ and a square
                    let want = a[c][l] * w;
                    assert!((b[c][l] - want).abs() <= 1e-5 * want.abs().max(1e-3), "lane {l}: {} vs {want}", b[c][l]);
                }
            }
        }
    }

    #[test]
    fn culling_beyond_the_range_changes_no_bit() {
        let m = Material::coral();
        let material = LaneMaterial::uniform(&m);
        let mut rng = Lcg(78);
        for range in [0.5f32, 2.0, 7.0] {
            let lights: Vec<_> = (0..40).flat_map(|_| one_light(rng.vec(6.0)).point_lights).collect();
            let scene = Scene { point_lights: lights, ..one_light(Vec3::ZERO) };
            let kernel = MultiLightKernel::new(&scene, Vec3::Z, m.shininess, Specular::Phong);
            let keep = kernel.clone().with_range_window(Some(RangeWindow { range, cull: false }));
            let cull = kernel.with_range_window(Some(RangeWindow { range, cull: true }));
            for spread in [0.2f32, 1.0, 6.0] {
                for _ in 0..50 {
                    let (pos, normal) = rng.batch(spread);
                    let (mut a, mut b) = ([[0.0; LANES]; 3], [[0.0; LANES]; 3]);
                    keep.shade(&pos, &normal, &material, &mut a);
                    cull.shade(&pos, &normal, &material, &mut b);
                    assert_eq!(a.map(|c| c.map(f32::to_bits)), b.map(|c| c.map(f32::to_bits)), "range {range}");
                }
            }
        }
    }

    #[test]
    fn a_range_that_is_not_positive_darkens_the_lights_without_panicking() {
        let m = Material::coral();
        let material = LaneMaterial::uniform(&m);
        let mut rng = Lcg(79);
        let (pos, normal) = rng.batch(1.0);
        for range in [0.0, -1.0, f32::NAN] {
            for cull in [false, true] {
                let k = MultiLightKernel::new(&one_light(Vec3::ZERO), Vec3::Z, m.shininess, Specular::Phong)
                    .with_range_window(Some(RangeWindow { range, cull }));
                let mut out = [[1.0; LANES]; 3];
                k.shade(&pos, &normal, &material, &mut out);
                assert!(out.iter().flatten().all(|&x| x == 0.0), "range {range} cull {cull}: {out:?}");
            }
        }
    }
}
