//! Chapter 1, Colors: modulation, quantization, sRGB.
use crate::common;

use common::{close3, color, config};
use glam::Vec3;
use lightlab::color::{linear_to_srgb, modulate, to_rgb8, CORAL};
use lightlab::reference::{self, dvec3};
use proptest::prelude::*;

proptest! {
    #![proptest_config(config())]

    /// Modulation is commutative, white is its identity, and colours in [0, 1]
    /// stay in [0, 1] (a surface reflects no more than it receives).
    #[test]
    fn modulate_is_a_channelwise_product(light in color(), object in color()) {
        let r = modulate(light, object);
        prop_assert_eq!(r, modulate(object, light));
        prop_assert_eq!(modulate(Vec3::ONE, object), object);
        prop_assert!(r.cmpge(Vec3::ZERO).all() && r.cmple(light.min(object)).all(), "{r} not within [0, min(light, object)]");
        // One rounding per channel: |Δ| ≤ U · |product| ≤ 6e-8.
        close3("f64 reference", reference::color::modulate(dvec3(light), dvec3(object)), dvec3(r), 6e-8)?;
    }

    /// Every 8-bit level k/255 quantizes back to k, in both paths.
    #[test]
    fn to_rgb8_round_trips_levels(k in prop::array::uniform3(0u8..=255)) {
        let c = Vec3::new(k[0] as f32, k[1] as f32, k[2] as f32) / 255.0;
        prop_assert_eq!(to_rgb8(c), k);
        prop_assert_eq!(reference::color::to_rgb8(dvec3(c)), k);
    }

    /// sRGB encoding maps [0, 1] into [0, 1] and is non-decreasing.
    #[test]
    fn srgb_is_monotone_on_unit_interval(a in 0.0f32..=1.0, b in 0.0f32..=1.0) {
        let (lo, hi) = if a <= b { (a, b) } else { (b, a) };
        let (slo, shi) = (linear_to_srgb(lo), linear_to_srgb(hi));
        prop_assert!((0.0..=1.0).contains(&slo) && (0.0..=1.0).contains(&shi));
        prop_assert!(slo <= shi, "srgb({lo}) = {slo} > srgb({hi}) = {shi}");
    }
}

#[test]
fn published_colors_chapter_products() {
    // LearnOpenGL, Colors: white × coral = coral; green × coral = (0, 0.5, 0).
    assert_eq!(modulate(Vec3::ONE, CORAL), CORAL);
    assert_eq!(modulate(Vec3::Y, CORAL), Vec3::new(0.0, 0.5, 0.0));
    // Olive × coral is printed (0.33, 0.21, 0.06); the blue channel is 0.0558
    // exactly (errata E5: 0.06 is a 2-dp rounding). f32 error ≤ 1 ulp.
    let olive = modulate(Vec3::new(0.33, 0.42, 0.18), CORAL);
    assert!((olive.z - 0.0558).abs() < 1e-7, "expected 0.0558, got {}", olive.z);
}

#[test]
fn nan_colors_quantize_to_black() {
    assert_eq!(to_rgb8(Vec3::NAN), [0, 0, 0]);
    assert_eq!(reference::color::to_rgb8(glam::DVec3::NAN), [0, 0, 0]);
    assert_eq!(linear_to_srgb(f32::NAN), 0.0);
}
