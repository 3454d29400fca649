//! The quantities the strategies write and the Rust answers read, resolved from the
//! layouts at compile time ([`Layout::get`] is a `const fn`: a name the layout lacks is a
//! compile error). Each model family gets one struct of places.

use crate::gl::layout::{self as l, Layout, Quantity};

/// Basic lighting and its two variants (Gouraud, normal matrix).
pub(super) struct Basic {
    pub pos: Quantity,
    pub ambient_strength: Quantity,
    pub normal: Quantity,
    pub specular_strength: Quantity,
    pub light_pos: Quantity,
    pub shininess: Quantity,
    pub view_pos: Quantity,
    pub light_color: Quantity,
    pub object_color: Quantity,
    pub model: Option<Quantity>,
}

impl Basic {
    const fn of(l: &Layout, pos: &str, normal: &str, model: bool) -> Basic {
        Basic {
            pos: l.get(pos),
            ambient_strength: l.get("ambientStrength"),
            normal: l.get(normal),
            specular_strength: l.get("specularStrength"),
            light_pos: l.get("lightPos"),
            shininess: l.get("shininess"),
            view_pos: l.get("viewPos"),
            light_color: l.get("lightColor"),
            object_color: l.get("objectColor"),
            model: if model { Some(l.get("model")) } else { None },
        }
    }

    /// The model matrix (Gouraud and normal matrix only).
    pub fn model(&self) -> Quantity {
        match self.model {
            Some(q) => q,
            None => panic!("basic lighting has no model matrix"),
        }
    }
}

pub(super) const BASIC: Basic = Basic::of(&l::BASIC_LIGHTING, "FragPos", "Normal", false);
pub(super) const BLINN_PHONG: Basic = Basic::of(&l::BLINN_PHONG, "FragPos", "Normal", false);
pub(super) const GOURAUD: Basic = Basic::of(&l::GOURAUD, "aPos", "aNormal", true);
pub(super) const NORMAL_MATRIX: Basic = Basic::of(&l::NORMAL_MATRIX, "FragPos", "aNormal", true);

/// The surface of the Materials chapter and of the mapped models.
pub(super) struct Surface {
    pub frag: Quantity,
    pub normal: Quantity,
    pub view_pos: Quantity,
    pub shininess: Quantity,
    /// `material.ambient` (Materials) or the diffuse texel (the mapped models: `Ka = Kd`).
    pub ambient: Quantity,
    pub diffuse: Quantity,
    pub specular: Quantity,
}

impl Surface {
    const fn of(l: &Layout, ambient: &str) -> Surface {
        Surface {
            frag: l.get("FragPos"),
            normal: l.get("Normal"),
            view_pos: l.get("viewPos"),
            shininess: l.get("material.shininess"),
            ambient: l.get(ambient),
            diffuse: l.get("material.diffuse"),
            specular: l.get("material.specular"),
        }
    }
}

/// One light of the single-light models.
pub(super) struct Light {
    /// `light.position`, or `light.direction` for the directional light.
    pub at: Quantity,
    pub ambient: Quantity,
    pub diffuse: Quantity,
    pub specular: Quantity,
    /// `(constant, linear, quadratic)`.
    pub attenuation: Option<[Quantity; 3]>,
}

impl Light {
    const fn of(l: &Layout, at: &str, attenuation: bool) -> Light {
        Light {
            at: l.get(at),
            ambient: l.get("light.ambient"),
            diffuse: l.get("light.diffuse"),
            specular: l.get("light.specular"),
            attenuation: if attenuation {
                Some([l.get("light.constant"), l.get("light.linear"), l.get("light.quadratic")])
            } else {
                None
            },
        }
    }

    /// The attenuation's three places (point and spot only).
    pub fn attenuation(&self) -> [Quantity; 3] {
        match self.attenuation {
            Some(a) => a,
            None => panic!("this light has no attenuation"),
        }
    }
}

pub(super) const MATERIALS: (Surface, Light) =
    (Surface::of(&l::MATERIALS, "material.ambient"), Light::of(&l::MATERIALS, "light.position", false));
pub(super) const LIGHTING_MAPS: (Surface, Light) =
    (Surface::of(&l::LIGHTING_MAPS, "material.diffuse"), Light::of(&l::LIGHTING_MAPS, "light.position", false));
pub(super) const LIGHTING_MAPS_EMISSION: (Surface, Light) = (
    Surface::of(&l::LIGHTING_MAPS_EMISSION, "material.diffuse"),
    Light::of(&l::LIGHTING_MAPS_EMISSION, "light.position", false),
);
/// The emission texel of Lighting maps' exercise 4.
pub(super) const EMISSION: Quantity = l::LIGHTING_MAPS_EMISSION.get("material.emission");
pub(super) const DIRECTIONAL: (Surface, Light) =
    (Surface::of(&l::DIRECTIONAL, "material.diffuse"), Light::of(&l::DIRECTIONAL, "light.direction", false));
pub(super) const POINT: (Surface, Light) =
    (Surface::of(&l::POINT, "material.diffuse"), Light::of(&l::POINT, "light.position", true));
pub(super) const SPOT: (Surface, Light) =
    (Surface::of(&l::SPOT, "material.diffuse"), Light::of(&l::SPOT, "light.position", true));
pub(super) const MULTIPLE_LIGHTS: Surface = Surface::of(&l::MULTIPLE_LIGHTS, "material.diffuse");

/// The spot's cone: `light.direction` (the axis) and the two cut-off cosines.
pub(super) const SPOT_DIRECTION: Quantity = l::SPOT.get("light.direction");
pub(super) const SPOT_CUT_OFF: Quantity = l::SPOT.get("light.cutOff");
pub(super) const SPOT_OUTER_CUT_OFF: Quantity = l::SPOT.get("light.outerCutOff");

/// `places!(Name, CONST = LAYOUT { field: "quantity", … })` declares a struct of places
/// and its constant, each field the layout's quantity of that name (resolved at compile
/// time, as [`Layout::get`] is a `const fn`).
macro_rules! places {
    ($(#[$doc:meta])* $name:ident, $konst:ident = $layout:path { $($field:ident: $quantity:literal),* $(,)? }) => {
        $(#[$doc])*
        pub(super) struct $name {
            $(pub $field: Quantity,)*
        }

        pub(super) const $konst: $name = {
            let l = &$layout;
            $name { $($field: l.get($quantity),)* }
        };
    };
}

places!(
    /// opengl-tutorial 8.
    Ot8, OT8 = l::OPENGL_TUTORIAL8 {
        position: "Position_worldspace",
        light_power: "LightPower",
        normal: "Normal_cameraspace",
        exponent: "specularExponent",
        eye_direction: "EyeDirection_cameraspace",
        light_direction: "LightDirection_cameraspace",
        light_position: "LightPosition_worldspace",
        diffuse: "MaterialDiffuseColor",
        specular: "MaterialSpecularColor",
        light_color: "LightColor",
        ambient_factor: "MaterialAmbientFactor",
    }
);

places!(
    /// ogldev 19.
    Ogldev, OGLDEV = l::OGLDEV19 {
        world_pos: "WorldPos0",
        specular_power: "gSpecularPower",
        normal: "Normal0",
        specular_intensity: "gMatSpecularIntensity",
        eye_world_pos: "gEyeWorldPos",
        color: "gDirectionalLight.Color",
        ambient_intensity: "gDirectionalLight.AmbientIntensity",
        direction: "gDirectionalLight.Direction",
        diffuse_intensity: "gDirectionalLight.DiffuseIntensity",
        texel: "gSampler",
    }
);
