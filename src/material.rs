//! Chapter 3, Materials: material and light properties, and the classic OpenGL materials table.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | `material.ambient/diffuse/specular` | fraction of each light term the surface reflects, per channel |
//! | `material.shininess` | Phong exponent `s` |
//! | `light.ambient/diffuse/specular` | intensity of each term of the light, per channel |
//!
//! ```text
//! ambient  = light.ambient  ⊙ material.ambient
//! diffuse  = light.diffuse  ⊙ (diff · material.diffuse)
//! specular = light.specular ⊙ (spec · material.specular)
//! ```

use glam::Vec3;

use crate::phong::{diffuse_factor, Specular, Terms};

/// The surface's reflectances and specular exponent.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    /// Ambient reflectance per channel.
    pub ambient: Vec3,
    /// Diffuse reflectance per channel.
    pub diffuse: Vec3,
    /// Specular reflectance per channel.
    pub specular: Vec3,
    /// Specular exponent `s` (the tutorials' `shininess`).
    pub shininess: f32,
}

impl Material {
    /// The chapter's coral material: ambient = diffuse = (1, 0.5, 0.31),
    /// specular 0.5, shininess 32.
    ///
    /// Source: LearnOpenGL, Materials.
    pub fn coral() -> Self {
        Material {
            ambient: crate::color::CORAL,
            diffuse: crate::color::CORAL,
            specular: Vec3::splat(0.5),
            shininess: 32.0,
        }
    }
}

/// A light's intensity for each of the three terms.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightProps {
    /// Ambient intensity per channel.
    pub ambient: Vec3,
    /// Diffuse intensity per channel.
    pub diffuse: Vec3,
    /// Specular intensity per channel.
    pub specular: Vec3,
}

impl LightProps {
    /// Materials chapter light: ambient 0.2, diffuse 0.5, specular 1.
    ///
    /// Source: LearnOpenGL, Materials, light properties.
    pub fn learnopengl_materials() -> Self {
        LightProps { ambient: Vec3::splat(0.2), diffuse: Vec3::splat(0.5), specular: Vec3::ONE }
    }

    /// All three terms at full white, `vec3(1.0)`: how the classic table is
    /// meant to be viewed (LearnOpenGL, Materials, exercise).
    pub fn white() -> Self {
        LightProps { ambient: Vec3::ONE, diffuse: Vec3::ONE, specular: Vec3::ONE }
    }

    /// The chapter's time-varying light at time `t` seconds.
    ///
    /// ```text
    /// light_color = (sin(2.0 t), sin(0.7 t), sin(1.3 t))
    /// diffuse = light_color · 0.5;  ambient = diffuse · 0.2;  specular = 1
    /// ```
    ///
    /// Channels go negative for part of each period, as in the chapter: a
    /// negative diffuse *removes* light until the output clamp. Non-finite `t`
    /// gives NaN channels.
    ///
    /// Source: LearnOpenGL, Materials, "Different light colors".
    // ANCHOR: time_varying
    pub fn time_varying(t: f32) -> Self {
        let light_color = Vec3::new((2.0 * t).sin(), (0.7 * t).sin(), (1.3 * t).sin());
        let diffuse = light_color * 0.5;
        LightProps { ambient: diffuse * 0.2, diffuse, specular: Vec3::ONE }
    }
    // ANCHOR_END: time_varying
}

/// The Materials chapter shader's three terms at one fragment.
///
/// ```text
/// ambient  = light.ambient  ⊙ material.ambient
/// diffuse  = light.diffuse  ⊙ (max(n·light_dir, 0) · material.diffuse)
/// specular = light.specular ⊙ (pow(max(view_dir·reflect_dir, 0), s) · material.specular)
/// ```
///
/// `n`, `light_dir` and `view_dir` must be unit length, pointing away from the
/// surface. Degenerate results as [`diffuse_factor`] and
/// [`phong_specular_factor`](crate::phong::phong_specular_factor).
///
/// Source: LearnOpenGL, Materials.
// ANCHOR: material_terms
pub fn material_terms(material: &Material, light: &LightProps, n: Vec3, light_dir: Vec3, view_dir: Vec3) -> Terms {
    material_terms_with(Specular::Phong, material, light, n, light_dir, view_dir)
}

/// [`material_terms`] with a choice of specular lobe (Blinn-Phong replaces
/// `pow(max(view_dir·reflect_dir, 0), s)` by `pow(max(n·halfway, 0), s)`).
///
/// Source: LearnOpenGL, Materials; Advanced lighting for the Blinn lobe.
pub fn material_terms_with(
    specular: Specular,
    material: &Material,
    light: &LightProps,
    n: Vec3,
    light_dir: Vec3,
    view_dir: Vec3,
) -> Terms {
    let diff = diffuse_factor(n, light_dir);
    let spec = specular.factor(n, light_dir, view_dir, material.shininess);
    Terms {
        ambient: light.ambient * material.ambient,
        diffuse: light.diffuse * (diff * material.diffuse),
        specular: light.specular * (spec * material.specular),
    }
}
// ANCHOR_END: material_terms

/// One row of the classic OpenGL materials table.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClassicMaterial {
    /// Name as the table prints it, lower case.
    pub name: &'static str,
    /// Ambient reflectance.
    pub ambient: [f32; 3],
    /// Diffuse reflectance.
    pub diffuse: [f32; 3],
    /// Specular reflectance.
    pub specular: [f32; 3],
    /// Shininess as the table prints it: a fraction of 128.
    pub shininess_fraction: f32,
}

impl ClassicMaterial {
    /// The exponent a shader uses: the table's fraction × 128.
    ///
    /// Source: LearnOpenGL, Materials ("the shininess values were multiplied by 128").
    // ANCHOR: classic_shininess
    pub fn shininess(&self) -> f32 {
        self.shininess_fraction * 128.0
    }
    // ANCHOR_END: classic_shininess

    /// This row as a [`Material`].
    pub fn material(&self) -> Material {
        Material {
            ambient: Vec3::from_array(self.ambient),
            diffuse: Vec3::from_array(self.diffuse),
            specular: Vec3::from_array(self.specular),
            shininess: self.shininess(),
        }
    }
}

const fn row(
    name: &'static str,
    ambient: [f32; 3],
    diffuse: [f32; 3],
    specular: [f32; 3],
    shininess_fraction: f32,
) -> ClassicMaterial {
    ClassicMaterial { name, ambient, diffuse, specular, shininess_fraction }
}

/// The 24 classic OpenGL materials, in the table's order.
///
/// Source: the table LearnOpenGL, Materials links (devernay.free.fr,
/// "OpenGL/VRML Materials"), whose values come from Kilgard's `teapots.c`
/// (1994). Shininess is the table's fraction; multiply by 128.
// The digits are transcribed as the table prints them, even where f32 cannot hold them all.
#[allow(clippy::excessive_precision)]
pub const CLASSIC_MATERIALS: [ClassicMaterial; 24] = [
    row("emerald", [0.0215, 0.1745, 0.0215], [0.07568, 0.61424, 0.07568], [0.633, 0.727811, 0.633], 0.6),
    row("jade", [0.135, 0.2225, 0.1575], [0.54, 0.89, 0.63], [0.316228, 0.316228, 0.316228], 0.1),
    row("obsidian", [0.05375, 0.05, 0.06625], [0.18275, 0.17, 0.22525], [0.332741, 0.328634, 0.346435], 0.3),
    row("pearl", [0.25, 0.20725, 0.20725], [1.0, 0.829, 0.829], [0.296648, 0.296648, 0.296648], 0.088),
    row("ruby", [0.1745, 0.01175, 0.01175], [0.61424, 0.04136, 0.04136], [0.727811, 0.626959, 0.626959], 0.6),
    row("turquoise", [0.1, 0.18725, 0.1745], [0.396, 0.74151, 0.69102], [0.297254, 0.30829, 0.306678], 0.1),
    row(
        "brass",
        [0.329412, 0.223529, 0.027451],
        [0.780392, 0.568627, 0.113725],
        [0.992157, 0.941176, 0.807843],
        0.21794872,
    ),
    row("bronze", [0.2125, 0.1275, 0.054], [0.714, 0.4284, 0.18144], [0.393548, 0.271906, 0.166721], 0.2),
    row("chrome", [0.25, 0.25, 0.25], [0.4, 0.4, 0.4], [0.774597, 0.774597, 0.774597], 0.6),
    row("copper", [0.19125, 0.0735, 0.0225], [0.7038, 0.27048, 0.0828], [0.256777, 0.137622, 0.086014], 0.1),
    row("gold", [0.24725, 0.1995, 0.0745], [0.75164, 0.60648, 0.22648], [0.628281, 0.555802, 0.366065], 0.4),
    row("silver", [0.19225, 0.19225, 0.19225], [0.50754, 0.50754, 0.50754], [0.508273, 0.508273, 0.508273], 0.4),
    row("black plastic", [0.0, 0.0, 0.0], [0.01, 0.01, 0.01], [0.5, 0.5, 0.5], 0.25),
    row("cyan plastic", [0.0, 0.1, 0.06], [0.0, 0.50980392, 0.50980392], [0.50196078, 0.50196078, 0.50196078], 0.25),
    row("green plastic", [0.0, 0.0, 0.0], [0.1, 0.35, 0.1], [0.45, 0.55, 0.45], 0.25),
    row("red plastic", [0.0, 0.0, 0.0], [0.5, 0.0, 0.0], [0.7, 0.6, 0.6], 0.25),
    row("white plastic", [0.0, 0.0, 0.0], [0.55, 0.55, 0.55], [0.7, 0.7, 0.7], 0.25),
    row("yellow plastic", [0.0, 0.0, 0.0], [0.5, 0.5, 0.0], [0.6, 0.6, 0.5], 0.25),
    row("black rubber", [0.02, 0.02, 0.02], [0.01, 0.01, 0.01], [0.4, 0.4, 0.4], 0.078125),
    row("cyan rubber", [0.0, 0.05, 0.05], [0.4, 0.5, 0.5], [0.04, 0.7, 0.7], 0.078125),
    row("green rubber", [0.0, 0.05, 0.0], [0.4, 0.5, 0.4], [0.04, 0.7, 0.04], 0.078125),
    row("red rubber", [0.05, 0.0, 0.0], [0.5, 0.4, 0.4], [0.7, 0.04, 0.04], 0.078125),
    row("white rubber", [0.05, 0.05, 0.05], [0.5, 0.5, 0.5], [0.7, 0.7, 0.7], 0.078125),
    row("yellow rubber", [0.05, 0.05, 0.0], [0.5, 0.5, 0.4], [0.7, 0.7, 0.04], 0.078125),
];

/// Look up a classic material by name.
///
/// Case-insensitive; `_` and `-` count as spaces, so `"cyan_plastic"` and
/// `"Cyan Plastic"` both find `cyan plastic`. `None` for an unknown name.
pub fn classic_material(name: &str) -> Option<&'static ClassicMaterial> {
    let wanted: String =
        name.trim().chars().map(|c| if c == '_' || c == '-' { ' ' } else { c.to_ascii_lowercase() }).collect();
    CLASSIC_MATERIALS.iter().find(|m| m.name == wanted)
}
