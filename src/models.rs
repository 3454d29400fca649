//! The three tutorials' conventions as named shading models.
//!
//! | model | light | specular | gate | ambient |
//! | --- | --- | --- | --- | --- |
//! | `learnopengl` | any caster, `1/(Kc+Kl d+Kq d²)` | `pow(max(v·r,0), s)` | none: specular even where `n·l < 0` | light.ambient ⊙ material |
//! | `blinn-phong` | as learnopengl | `pow(max(n·h,0), s)` | none | as learnopengl |
//! | `opengl-tutorial` | one point light, `LightPower / d²` | `pow(clamp(E·R,0,1), 5)` | none | `0.1 × MaterialDiffuseColor` |
//! | `ogldev` | one directional light, intensities | `pow(V·R, power)` taken *before* its `> 0` test | specular only where `n·l > 0` | `Color × AmbientIntensity` |
//!
//! Sources: LearnOpenGL, Basic lighting and Multiple lights; opengl-tutorial 8
//! "Basic shading"; ogldev tutorial 19 "Specular lighting".

use glam::Vec3;

use crate::color::CORAL;
use crate::glsl::{pow, reflect, saturate};
use crate::phong::Terms;

crate::named::named_enum! {
    /// The named shading models of `lightlab shade` and the conventions chapter.
    pub enum ShadingModel {
        /// LearnOpenGL's Phong model (the default).
        LearnOpenGL => "learnopengl",
        /// LearnOpenGL's model with the Blinn half vector.
        BlinnPhong => "blinn-phong",
        /// opengl-tutorial 8.
        OpenGLTutorial => "opengl-tutorial",
        /// ogldev 19.
        Ogldev => "ogldev",
    }
}

/// opengl-tutorial 8's shader inputs (its uniforms, in world space).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OpenGLTutorial {
    /// `LightPosition_worldspace`.
    pub light_pos: Vec3,
    /// `LightColor`.
    pub light_color: Vec3,
    /// `LightPower` (the tutorial uses 50).
    pub light_power: f32,
    /// `MaterialDiffuseColor` (sampled from the texture in the tutorial).
    pub diffuse: Vec3,
    /// `MaterialSpecularColor` (the tutorial uses 0.3).
    pub specular: Vec3,
    /// Factor of `MaterialAmbientColor = factor × MaterialDiffuseColor` (0.1).
    pub ambient_factor: f32,
    /// The specular exponent (5).
    pub exponent: f32,
}

impl OpenGLTutorial {
    /// The tutorial's constants with a white light of power 50 at `light_pos`
    /// and diffuse color `diffuse`: specular 0.3, ambient 0.1 × diffuse, exponent 5.
    pub fn with_defaults(light_pos: Vec3, diffuse: Vec3) -> Self {
        OpenGLTutorial {
            light_pos,
            light_color: Vec3::ONE,
            light_power: 50.0,
            diffuse,
            specular: Vec3::splat(0.3),
            ambient_factor: 0.1,
            exponent: 5.0,
        }
    }

    /// Shade a fragment.
    ///
    /// ```text
    /// n = normalize(normal); l = normalize(light_pos - frag_pos); E = normalize(eye_pos - frag_pos)
    /// cosTheta = clamp(n·l, 0, 1);   R = reflect(-l, n);   cosAlpha = clamp(E·R, 0, 1)
    /// ambient  = ambient_factor · diffuse
    /// diffuse  = diffuse ⊙ LightColor · LightPower · cosTheta / d²
    /// specular = specular ⊙ LightColor · LightPower · pow(cosAlpha, 5) / d²
    /// ```
    ///
    /// The tutorial works in camera space; the vectors are the same in world
    /// space because the view is rigid. Degenerate input: `d = 0` gives
    /// infinite diffuse and specular (the atlas shows it); a zero normal
    /// gives ambient only.
    ///
    /// Deviation: the tutorial's printed listing ends the diffuse line with
    /// `;`, so its specular line is a statement with no effect; lightlab adds
    /// the specular term, as the text and the tutorial's images intend.
    ///
    /// Source: opengl-tutorial 8, "Basic shading".
    // ANCHOR: opengl_tutorial_terms
    pub fn terms(&self, frag_pos: Vec3, normal: Vec3, eye_pos: Vec3) -> Terms {
        let n = normal.normalize_or_zero();
        let to_light = self.light_pos - frag_pos;
        let l = to_light.normalize_or_zero();
        let e = (eye_pos - frag_pos).normalize_or_zero();
        let cos_theta = saturate(n.dot(l));
        // A zero normal has no mirror plane: no highlight (the doc's "ambient only").
        let cos_alpha = if n == Vec3::ZERO { 0.0 } else { saturate(e.dot(reflect(-l, n))) };
        let falloff = crate::casters::inverse_square_falloff(self.light_power, to_light.length());
        Terms {
            ambient: self.ambient_factor * self.diffuse,
            diffuse: self.diffuse * self.light_color * falloff * cos_theta,
            specular: self.specular * self.light_color * falloff * crate::glsl::pow_or_zero(cos_alpha, self.exponent),
        }
    }
    // ANCHOR_END: opengl_tutorial_terms
}

/// ogldev 19's shader inputs: one directional light and specular intensity and power.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ogldev {
    /// `gDirectionalLight.Color`.
    pub color: Vec3,
    /// `gDirectionalLight.AmbientIntensity`.
    pub ambient_intensity: f32,
    /// `gDirectionalLight.DiffuseIntensity`.
    pub diffuse_intensity: f32,
    /// `gDirectionalLight.Direction`, pointing *from* the light.
    pub direction: Vec3,
    /// `gMatSpecularIntensity` (the tutorial sets 1.0).
    pub specular_intensity: f32,
    /// `gSpecularPower` (the tutorial sets 32).
    pub specular_power: f32,
    /// The texture color the sum is multiplied by.
    pub texture_color: Vec3,
}

impl Ogldev {
    /// Shade a fragment, in world space with the eye at `eye_world_pos`.
    ///
    /// ```text
    /// ambient = Color · AmbientIntensity
    /// DiffuseFactor = dot(normalize(Normal), -Direction)
    /// if DiffuseFactor > 0:
    ///     diffuse = Color · DiffuseIntensity · DiffuseFactor
    ///     SpecularFactor = pow(dot(VertexToEye, normalize(reflect(Direction, N))), SpecularPower)
    ///     if SpecularFactor > 0: specular = Color · SpecularIntensity · SpecularFactor
    /// FragColor = texture ⊙ (ambient + diffuse + specular)
    /// ```
    ///
    /// `pow` is taken before the `> 0` test, so a negative base reaches
    /// `pow`, where GLSL leaves the result undefined. lightlab uses
    /// [`crate::glsl::pow`], which returns NaN there; `NaN > 0` is false, so
    /// the specular term is 0, which is also what llvmpipe's
    /// `exp2(y·log2 x)` gives. The failure atlas shows the ghost highlights a
    /// C `powf` produces instead. `Direction` is used as given (the tutorial
    /// normalizes it on the CPU); a zero normal gives ambient only.
    ///
    /// Source: ogldev tutorial 19, "Specular lighting".
    // ANCHOR: ogldev_terms
    pub fn terms(&self, world_pos: Vec3, normal: Vec3, eye_world_pos: Vec3) -> Terms {
        let n = normal.normalize_or_zero();
        let diffuse_factor = n.dot(-self.direction);
        let mut terms = Terms { ambient: self.color * self.ambient_intensity * self.texture_color, ..Terms::default() };
        if diffuse_factor > 0.0 {
            terms.diffuse = self.color * self.diffuse_intensity * diffuse_factor * self.texture_color;
            let vertex_to_eye = (eye_world_pos - world_pos).normalize_or_zero();
            let light_reflect = reflect(self.direction, n).normalize_or_zero();
            let specular_factor = pow(vertex_to_eye.dot(light_reflect), self.specular_power);
            if specular_factor > 0.0 {
                terms.specular = self.color * self.specular_intensity * specular_factor * self.texture_color;
            }
        }
        terms
    }
    // ANCHOR_END: ogldev_terms
}

/// The ogldev light used to compare the three conventions: white, directional,
/// travelling from the LearnOpenGL light position `light_pos` toward the
/// origin, ambient 0.1, diffuse 1, specular intensity 0.5, power 32, texture =
/// coral, so that its constants match LearnOpenGL's as far as the model allows.
///
/// Used by the conventions chapter (`tables::conventions`), the errata and the
/// renders.
pub fn ogldev_comparable(light_pos: Vec3) -> Ogldev {
    Ogldev {
        color: Vec3::ONE,
        ambient_intensity: 0.1,
        diffuse_intensity: 1.0,
        direction: (-light_pos).normalize_or_zero(),
        specular_intensity: 0.5,
        specular_power: 32.0,
        texture_color: CORAL,
    }
}

/// ogldev's specular factor computed with C `powf` (failure atlas case 2, the failure).
///
/// ```text
/// SpecularFactor = powf(dot(VertexToEye, LightReflect), SpecularPower)
/// specular = SpecularFactor > 0 ? SpecularFactor : 0
/// ```
///
/// `v_dot_r < 0` (eye behind the mirror direction) with an even power gives
/// a positive ghost; an odd power is caught by the `> 0` test here, but
/// without the test it is negative light ([`crate::study::atlas::case2_pow`]).
///
/// Source: ogldev tutorial 19.
pub fn ogldev_specular_c_powf(v_dot_r: f32, power: f32) -> f32 {
    let factor = v_dot_r.powf(power);
    if factor > 0.0 {
        factor
    } else {
        0.0
    }
}

/// ogldev's specular factor with GLSL's domain (failure atlas case 2, the fix):
/// the same test with [`crate::glsl::pow`] (NaN for a negative base, so `> 0`
/// is false), which is also llvmpipe's result.
/// Equal to `pow_or_zero(max(v_dot_r, 0), power)` for `power > 0`.
pub fn ogldev_specular_glsl(v_dot_r: f32, power: f32) -> f32 {
    let factor = pow(v_dot_r, power);
    if factor > 0.0 {
        factor
    } else {
        0.0
    }
}
