//! Chapter 6, Multiple lights: one directional light, N point lights and one spot, summed.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | `dir_light` | the directional light (`CalcDirLight`) |
//! | `point_lights` | point lights (`CalcPointLight`), each attenuated |
//! | `spot_light` | the flashlight (`CalcSpotLight`), attenuated and × intensity |
//! | `result` | the sum of every light's ambient + diffuse + specular, unclamped |
//!
//! Source: LearnOpenGL, Multiple lights.

use crate::casters::LocalLight as _;
use glam::Vec3;

use crate::casters::{Attenuation, DirLight, PointLight, SpotLight};
use crate::material::{LightProps, Material};
use crate::phong::{Specular, Terms};

/// A scene of lights, as the chapter's fragment shader sums them.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// Optional directional light.
    pub dir_light: Option<DirLight>,
    /// Point lights, in order.
    pub point_lights: Vec<PointLight>,
    /// Optional spot light.
    pub spot_light: Option<SpotLight>,
    /// The background (`glClearColor`), for renders.
    pub clear_color: Vec3,
}

/// Which light a contribution came from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LightId {
    /// The directional light.
    Dir,
    /// Point light number `i`.
    Point(usize),
    /// The spot light.
    Spot,
}

impl std::fmt::Display for LightId {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            LightId::Dir => f.write_str("dir"),
            LightId::Point(i) => write!(f, "point[{i}]"),
            LightId::Spot => f.write_str("spot"),
        }
    }
}

/// The per-light terms at one fragment and their sum.
#[derive(Clone, Debug, PartialEq)]
pub struct Shaded {
    /// Each light's terms, in shader order: dir, points, spot.
    pub lights: Vec<(LightId, Terms)>,
}

impl Shaded {
    /// The unclamped sum of every term of every light.
    pub fn rgb(&self) -> Vec3 {
        self.lights.iter().map(|(_, t)| t.sum()).sum()
    }
}

impl Scene {
    /// Shade one fragment.
    ///
    /// ```text
    /// norm = normalize(normal); view_dir = normalize(view_pos - frag_pos)
    /// result = CalcDirLight + Σ CalcPointLight + CalcSpotLight
    /// ```
    ///
    /// `normal` need not be unit length (it is normalized as the shader
    /// does). Degenerate input: a zero normal or a fragment at the eye gives
    /// ambient-only terms; no panic.
    ///
    /// Source: LearnOpenGL, Multiple lights, fragment shader `main`.
    // ANCHOR: scene_shade
    pub fn shade(&self, material: &Material, frag_pos: Vec3, normal: Vec3, view_pos: Vec3) -> Shaded {
        self.shade_with(Specular::Phong, material, frag_pos, normal, view_pos)
    }

    /// [`Self::shade`] with a choice of specular lobe for every light.
    pub fn shade_with(
        &self,
        specular: Specular,
        material: &Material,
        frag_pos: Vec3,
        normal: Vec3,
        view_pos: Vec3,
    ) -> Shaded {
        let norm = normal.normalize_or_zero();
        let view_dir = (view_pos - frag_pos).normalize_or_zero();
        let mut lights = Vec::with_capacity(self.point_lights.len() + 2);
        if let Some(d) = &self.dir_light {
            lights.push((LightId::Dir, d.terms_with(specular, material, norm, view_dir)));
        }
        for (i, p) in self.point_lights.iter().enumerate() {
            lights.push((LightId::Point(i), p.terms_with(specular, material, norm, frag_pos, view_dir)));
        }
        if let Some(s) = &self.spot_light {
            lights.push((LightId::Spot, s.terms_with(specular, material, norm, frag_pos, view_dir)));
        }
        Shaded { lights }
    }
    // ANCHOR_END: scene_shade

    /// The chapter's scene: the camera at (0, 0, 3) looking down −z holds the flashlight.
    ///
    /// - dir light (−0.2, −1, −0.3), ambient 0.05, diffuse 0.4, specular 0.5;
    /// - point lights at (0.7, 0.2, 2), (2.3, −3.3, −4), (−4, 2, −12), (0, 0, −3),
    ///   ambient 0.05, diffuse 0.8, specular 1, attenuation (1, 0.09, 0.032);
    /// - spot at the camera, cut-offs 12.5° and 15°, ambient 0, diffuse 1, specular 1.
    ///
    /// Source: LearnOpenGL, Multiple lights; the same constants as
    /// `../shared/DESIGN.md`'s quad-multi scene.
    pub fn learnopengl_default() -> Scene {
        let grey = |a: f32, d: f32, s: f32| LightProps {
            ambient: Vec3::splat(a),
            diffuse: Vec3::splat(d),
            specular: Vec3::splat(s),
        };
        let point = |position: Vec3| PointLight {
            position,
            attenuation: Attenuation::LEARNOPENGL,
            props: grey(0.05, 0.8, 1.0),
        };
        Scene {
            dir_light: Some(DirLight { direction: Vec3::new(-0.2, -1.0, -0.3), props: grey(0.05, 0.4, 0.5) }),
            point_lights: POINT_LIGHT_POSITIONS.iter().map(|&p| point(p)).collect(),
            spot_light: SpotLight::flashlight(Vec3::new(0.0, 0.0, 3.0), Vec3::NEG_Z),
            clear_color: Vec3::new(0.1, 0.1, 0.1),
        }
    }
}

/// The chapter's four point light positions.
///
/// Source: LearnOpenGL, Multiple lights, `pointLightPositions`.
pub const POINT_LIGHT_POSITIONS: [Vec3; 4] =
    [Vec3::new(0.7, 0.2, 2.0), Vec3::new(2.3, -3.3, -4.0), Vec3::new(-4.0, 2.0, -12.0), Vec3::new(0.0, 0.0, -3.0)];

crate::named::named_enum! {
    /// The four atmospheres of the Multiple lights exercise, in the exercise's order.
    pub enum Atmosphere {
        /// Warm sand-coloured light, orange and red lamps, a narrow yellow flashlight.
        Desert => "desert",
        /// Cold blue light, a wide-reaching white flashlight.
        Factory => "factory",
        /// Almost dark; dim grey lamps, one reddish; a white flashlight.
        Horror => "horror",
        /// Bright white, green lamps and a green flashlight.
        BiochemicalLab => "biochemical-lab",
    }
}

impl Atmosphere {
    /// The scene for this atmosphere, the camera (and flashlight) at (0, 0, 3) looking down −z.
    ///
    /// Every point light `i` has ambient `0.1 · color_i`, diffuse and specular
    /// `color_i`; the spot's ambient is 0. Positions are the chapter's
    /// [`POINT_LIGHT_POSITIONS`].
    ///
    /// Source: LearnOpenGL repository, `src/2.lighting/6.multiple_lights_exercise1/
    /// multiple_lights_exercise1.cpp` (commit 0a65422), values transcribed.
    pub fn scene(self) -> Scene {
        let s = self.spec();
        let point = |(i, &color): (usize, &[f32; 3])| {
            let color = Vec3::from_array(color);
            let (kc, kl, kq) = s.point_attenuation[i];
            PointLight {
                position: POINT_LIGHT_POSITIONS[i],
                attenuation: Attenuation { constant: kc, linear: kl, quadratic: kq },
                props: LightProps { ambient: 0.1 * color, diffuse: color, specular: color },
            }
        };
        let (kc, kl, kq) = s.spot_attenuation;
        let spot_color = Vec3::from_array(s.spot_color);
        let spot = SpotLight::new(
            Vec3::new(0.0, 0.0, 3.0),
            Vec3::NEG_Z,
            s.cut_offs_deg.0,
            s.cut_offs_deg.1,
            Attenuation { constant: kc, linear: kl, quadratic: kq },
            LightProps { ambient: Vec3::ZERO, diffuse: spot_color, specular: spot_color },
        );
        Scene {
            dir_light: Some(DirLight {
                direction: Vec3::new(-0.2, -1.0, -0.3),
                props: LightProps {
                    ambient: Vec3::from_array(s.dir[0]),
                    diffuse: Vec3::from_array(s.dir[1]),
                    specular: Vec3::from_array(s.dir[2]),
                },
            }),
            point_lights: s.point_colors.iter().enumerate().map(point).collect(),
            spot_light: spot.ok(),
            clear_color: Vec3::from_array(s.clear_color),
        }
    }

    fn spec(self) -> AtmosphereSpec {
        const L50: (f32, f32, f32) = (1.0, 0.09, 0.032);
        const L32: (f32, f32, f32) = (1.0, 0.14, 0.07);
        const L20: (f32, f32, f32) = (1.0, 0.22, 0.20);
        const L65: (f32, f32, f32) = (1.0, 0.07, 0.017);
        match self {
            Atmosphere::Desert => AtmosphereSpec {
                clear_color: [0.75, 0.52, 0.3],
                dir: [[0.3, 0.24, 0.14], [0.7, 0.42, 0.26], [0.5, 0.5, 0.5]],
                point_colors: [[1.0, 0.6, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.2, 0.2, 1.0]],
                point_attenuation: [L50; 4],
                spot_color: [0.8, 0.8, 0.0],
                spot_attenuation: L50,
                cut_offs_deg: (12.5, 13.0),
            },
            Atmosphere::Factory => AtmosphereSpec {
                clear_color: [0.1, 0.1, 0.1],
                dir: [[0.05, 0.05, 0.1], [0.2, 0.2, 0.7], [0.7, 0.7, 0.7]],
                point_colors: [[0.2, 0.2, 0.6], [0.3, 0.3, 0.7], [0.0, 0.0, 0.3], [0.4, 0.4, 0.4]],
                point_attenuation: [L50; 4],
                spot_color: [1.0, 1.0, 1.0],
                spot_attenuation: (1.0, 0.009, 0.0032),
                cut_offs_deg: (10.0, 12.5),
            },
            Atmosphere::Horror => AtmosphereSpec {
                clear_color: [0.0, 0.0, 0.0],
                dir: [[0.0, 0.0, 0.0], [0.05, 0.05, 0.05], [0.2, 0.2, 0.2]],
                point_colors: [[0.1, 0.1, 0.1], [0.1, 0.1, 0.1], [0.1, 0.1, 0.1], [0.3, 0.1, 0.1]],
                point_attenuation: [L32, L32, L20, L32],
                spot_color: [1.0, 1.0, 1.0],
                spot_attenuation: L50,
                cut_offs_deg: (10.0, 15.0),
            },
            Atmosphere::BiochemicalLab => AtmosphereSpec {
                clear_color: [0.9, 0.9, 0.9],
                dir: [[0.5, 0.5, 0.5], [1.0, 1.0, 1.0], [1.0, 1.0, 1.0]],
                point_colors: [[0.4, 0.7, 0.1]; 4],
                point_attenuation: [L65; 4],
                spot_color: [0.0, 1.0, 0.0],
                spot_attenuation: L65,
                cut_offs_deg: (7.0, 10.0),
            },
        }
    }
}

/// The transcribed constants of one atmosphere.
struct AtmosphereSpec {
    clear_color: [f32; 3],
    /// Directional light ambient, diffuse, specular.
    dir: [[f32; 3]; 3],
    point_colors: [[f32; 3]; 4],
    point_attenuation: [(f32, f32, f32); 4],
    spot_color: [f32; 3],
    spot_attenuation: (f32, f32, f32),
    /// Inner and outer cut-off in degrees.
    cut_offs_deg: (f32, f32),
}
