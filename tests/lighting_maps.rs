//! Chapter 4, Lighting maps: texture sampling and the container maps.
use crate::common;

use common::{close3, config, unit_vec3};
use glam::{DVec2, Vec2, Vec3};
use lightlab::maps::{container, Filter, Texture, Wrap};
use lightlab::material::LightProps;
use lightlab::reference::{self, dvec2, dvec3};
use proptest::prelude::*;

/// A texture of 1–8 × 1–8 texels with channels in [0, 1].
fn texture() -> impl Strategy<Value = Texture> {
    (1usize..=8, 1usize..=8).prop_flat_map(|(w, h)| {
        prop::collection::vec(common::color(), w * h).prop_map(move |t| Texture::new(w, h, t).unwrap())
    })
}

/// A coordinate that is a multiple of 1/1024 in [-3, 3]: exact in f32, and
/// exact after adding an integer or multiplying by a width ≤ 8.
fn dyadic() -> impl Strategy<Value = f32> {
    (-3072i32..=3072).prop_map(|k| k as f32 / 1024.0)
}

const WRAPS: [Wrap; 2] = [Wrap::Repeat, Wrap::ClampToEdge];

/// Any `f32` at all: NaN, ±∞, subnormals, huge values.
fn any_f32() -> impl Strategy<Value = f32> {
    proptest::num::f32::ANY
}

proptest! {
    #![proptest_config(config())]

    /// Sampling never panics and returns a texel-range value for any `f32`
    /// coordinates, NaN and ±∞ included (this found an `i64` overflow in `i + 1`
    /// for coordinates near 1e30).
    #[test]
    fn sampling_any_coordinate_never_panics(t in texture(), u in any_f32(), v in any_f32()) {
        let r = reference::maps::Texture::from_f32(&t);
        for wrap in WRAPS {
            for filter in [Filter::Nearest, Filter::Bilinear] {
                let s = t.sample(Vec2::new(u, v), filter, wrap);
                prop_assert!(s.cmpge(Vec3::ZERO - 1e-6).all() && s.cmple(Vec3::ONE + 1e-6).all(), "{filter:?} {wrap:?} at ({u}, {v}): {s}");
                let sd = r.sample(DVec2::new(u as f64, v as f64), filter, wrap);
                prop_assert!(sd.is_finite(), "reference {filter:?} {wrap:?} at ({u}, {v}): {sd}");
            }
        }
    }

    /// At a texel centre, bilinear filtering returns the texel itself (= nearest).
    #[test]
    fn bilinear_at_texel_centres_is_nearest(t in texture(), i in 0usize..8, j in 0usize..8) {
        let (i, j) = (i % t.width(), j % t.height());
        let uv = Vec2::new((i as f32 + 0.5) / t.width() as f32, (j as f32 + 0.5) / t.height() as f32);
        for wrap in WRAPS {
            let near = t.sample(uv, Filter::Nearest, wrap);
            let bil = t.sample(uv, Filter::Bilinear, wrap);
            prop_assert_eq!(near, t.texel(i as i64, j as i64, wrap));
            // (i + ½)/w · w − ½ may round by one ulp of i: fx ≤ 8U, weight error ≤ 8U per texel.
            close3(&format!("{wrap:?} bilinear vs nearest"), dvec3(near), dvec3(bil), 1e-6)?;
            let r = reference::maps::Texture::from_f32(&t);
            // Exact centre in f64 (the f32 uv above is rounded); f64 rounding only.
            let uvd = DVec2::new((i as f64 + 0.5) / t.width() as f64, (j as f64 + 0.5) / t.height() as f64);
            close3("reference", dvec3(near), r.sample(uvd, Filter::Bilinear, wrap), 1e-12)?;
        }
    }

    /// Every sample lies within the per-channel min and max of the texels.
    #[test]
    fn samples_lie_within_texel_range(t in texture(), u in -3.0f32..3.0, v in -3.0f32..3.0) {
        let r = reference::maps::Texture::from_f32(&t);
        let all: Vec<Vec3> = (0..t.height()).flat_map(|j| (0..t.width()).map(move |i| (i, j)))
            .map(|(i, j)| t.texel(i as i64, j as i64, Wrap::Repeat)).collect();
        let lo = all.iter().copied().fold(Vec3::INFINITY, Vec3::min);
        let hi = all.iter().copied().fold(Vec3::NEG_INFINITY, Vec3::max);
        for wrap in WRAPS {
            for filter in [Filter::Nearest, Filter::Bilinear] {
                let s = t.sample(Vec2::new(u, v), filter, wrap);
                // lerp's rounding can overshoot by ~2U · max; 1e-6 slack.
                prop_assert!(s.cmpge(lo - 1e-6).all() && s.cmple(hi + 1e-6).all(), "{filter:?} {wrap:?}: {s} outside [{lo}, {hi}]");
                let sd = r.sample(DVec2::new(u as f64, v as f64), filter, wrap);
                prop_assert!(sd.cmpge(dvec3(lo) - 1e-12).all() && sd.cmple(dvec3(hi) + 1e-12).all(), "reference {sd}");
            }
        }
    }

    /// Repeat wrap is periodic with period 1 in u and v (coordinates exact in f32).
    #[test]
    fn repeat_wrap_is_periodic(t in texture(), u in dyadic(), v in dyadic(), k in -3i32..=3, l in -3i32..=3) {
        let uv = Vec2::new(u, v);
        let shifted = uv + Vec2::new(k as f32, l as f32);
        for filter in [Filter::Nearest, Filter::Bilinear] {
            prop_assert_eq!(t.sample(uv, filter, Wrap::Repeat), t.sample(shifted, filter, Wrap::Repeat), "{:?}", filter);
        }
        for (i, j) in [(0i64, 0i64), (5, -7)] {
            prop_assert_eq!(t.texel(i, j, Wrap::Repeat), t.texel(i + k as i64 * t.width() as i64, j + l as i64 * t.height() as i64, Wrap::Repeat));
        }
    }

    /// Clamp-to-edge: beyond the border the sample equals the border sample.
    #[test]
    fn clamp_to_edge_holds_border(t in texture(), v in 0.0f32..1.0, beyond in 0.0f32..5.0) {
        for filter in [Filter::Nearest, Filter::Bilinear] {
            let edge = t.sample(Vec2::new(1.0 - 0.5 / t.width() as f32, v), filter, Wrap::ClampToEdge);
            let out = t.sample(Vec2::new(1.0 + beyond, v), filter, Wrap::ClampToEdge);
            close3(&format!("{filter:?}"), dvec3(edge), dvec3(out), 1e-6)?;
        }
    }

    /// The container shader: emission is added unlit (independent of the light),
    /// and a black light leaves only the emission.
    #[test]
    fn emission_is_unlit(u in 0.0f32..1.0, v in 0.0f32..1.0, n in unit_vec3(), l in unit_vec3(), view in unit_vec3()) {
        let maps = container(16, true).unwrap();
        let uv = Vec2::new(u, v);
        let (_, e1) = maps.shade(&LightProps::white(), uv, n, l, view);
        let black = LightProps { ambient: Vec3::ZERO, diffuse: Vec3::ZERO, specular: Vec3::ZERO };
        let (t0, e0) = maps.shade(&black, uv, n, l, view);
        prop_assert_eq!(e1, e0);
        prop_assert_eq!(t0.sum(), Vec3::ZERO);
        let r = reference::maps::LightingMaps::from_f32(&maps);
        let (_, er) = r.shade(&reference::material::LightProps::from_f32(&black), dvec2(uv), dvec3(n), dvec3(l), dvec3(view));
        // Bilinear in f32 vs f64: weights differ by ~8U, texels ≤ 1: 1e-6.
        close3("reference emission", er, dvec3(e0), 1e-6)?;
    }
}

#[test]
fn degenerate_textures() {
    let e = Texture::new(0, 4, vec![]).unwrap_err();
    assert!(e.0.starts_with("size"), "{e}");
    let e = Texture::new(4, 0, vec![]).unwrap_err();
    assert!(e.0.starts_with("size"), "{e}");
    let e = Texture::new(2, 2, vec![Vec3::ONE; 3]).unwrap_err();
    assert!(e.0.starts_with("texels"), "{e}");
    assert!(reference::maps::Texture::new(0, 1, vec![]).unwrap_err().0.starts_with("size"));
    assert!(container(3, false).is_err());
    // NaN and infinite coordinates count as 0: no panic, a texel value.
    let t = Texture::new(2, 1, vec![Vec3::X, Vec3::Y]).unwrap();
    for uv in [Vec2::NAN, Vec2::new(f32::INFINITY, 0.0), Vec2::new(f32::NEG_INFINITY, f32::NAN)] {
        assert_eq!(t.sample(uv, Filter::Nearest, Wrap::Repeat), t.sample(Vec2::ZERO, Filter::Nearest, Wrap::Repeat));
        assert!(t.sample(uv, Filter::Bilinear, Wrap::ClampToEdge).is_finite());
    }
    // Huge coordinates: no overflow panic in the index arithmetic.
    assert!(t.sample(Vec2::splat(1e30), Filter::Bilinear, Wrap::Repeat).is_finite());
    assert!(t.sample(Vec2::splat(-1e30), Filter::Nearest, Wrap::ClampToEdge).is_finite());
    let r = reference::maps::Texture::from_f32(&t);
    assert!(r.sample(DVec2::splat(1e300), Filter::Bilinear, Wrap::Repeat).is_finite());
}
