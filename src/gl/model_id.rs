//! The one identity of a checker and oracle model: [`ModelId`].
//!
//! A model is named by a string only at the edges: `--model NAME` on the command line,
//! the `model` fields of JSON and TOML files, and the JSON and text the crate prints. Each
//! edge parses the name once ([`ModelId::from_str`](std::str::FromStr::from_str), an error
//! listing every model) and everything inside the crate takes a [`ModelId`]. Every `match`
//! over models lists every variant, so a new model is a compile error at each place that
//! has to say what the model does (its layout, shader, strategy, references, frame, ...).
//!
//! | name | chapter |
//! | --- | --- |
//! | `basic_lighting` | LearnOpenGL, Basic lighting |
//! | `gouraud` | LearnOpenGL, Basic lighting, Gouraud exercise (per vertex) |
//! | `materials` | LearnOpenGL, Materials |
//! | `lighting_maps` | LearnOpenGL, Lighting maps |
//! | `directional`, `point`, `spot` | LearnOpenGL, Light casters |
//! | `multiple_lights` | LearnOpenGL, Multiple lights |
//! | `opengl_tutorial8` | opengl-tutorial 8 |
//! | `ogldev19` | ogldev 19 |
//! | `normal_matrix` | Basic lighting with an object-space normal (check-shader only) |
//! | `blinn_phong` | LearnOpenGL, Advanced Lighting, on Basic lighting's inputs (check-shader only) |
//! | `lighting_maps_emission` | LearnOpenGL, Lighting maps, exercise 4: the emission map (check-shader only) |

use std::fmt;
use std::str::FromStr;

crate::named::named_enum! {
    /// A model with random cases: the ten tutorial shaders in chapter order, then, for
    /// `check-shader` only, `normal_matrix` (basic lighting whose normal arrives in object
    /// space with a `model` matrix, so the shader must apply the normal matrix) and
    /// `blinn_phong` (basic lighting's inputs, Blinn-Phong's halfway-vector specular) and
    /// `lighting_maps_emission` (Lighting maps with the emission map of the chapter's
    /// exercise 4, added without lighting).
    ///
    /// The names are those of the layouts' JSON (`lightlab oracle --layouts`), of
    /// `check-shader --model` and of the function files `src/gl/shaders/<name>.glsl`.
    #[derive(Hash, PartialOrd, Ord)]
    pub enum ModelId {
        /// LearnOpenGL, Basic lighting.
        BasicLighting => "basic_lighting",
        /// LearnOpenGL, Basic lighting, Gouraud exercise (per vertex).
        Gouraud => "gouraud",
        /// LearnOpenGL, Materials.
        Materials => "materials",
        /// LearnOpenGL, Lighting maps.
        LightingMaps => "lighting_maps",
        /// LearnOpenGL, Light casters, directional.
        Directional => "directional",
        /// LearnOpenGL, Light casters, point.
        Point => "point",
        /// LearnOpenGL, Light casters, spot (soft edge and hard cut-off).
        Spot => "spot",
        /// LearnOpenGL, Multiple lights.
        MultipleLights => "multiple_lights",
        /// opengl-tutorial 8.
        OpenGLTutorial8 => "opengl_tutorial8",
        /// ogldev 19.
        Ogldev19 => "ogldev19",
        /// Basic lighting with an object-space normal and a `model` matrix (check-shader only).
        NormalMatrix => "normal_matrix",
        /// LearnOpenGL, Advanced Lighting: Blinn-Phong on the basic-lighting inputs
        /// (check-shader only).
        BlinnPhong => "blinn_phong",
        /// LearnOpenGL, Lighting maps, exercise 4: Lighting maps with an emission map added
        /// unlit (check-shader only).
        LightingMapsEmission => "lighting_maps_emission",
    }
}

/// Number of models ([`ModelId::ALL`]'s length): the length of every per-model table.
pub const N_MODELS: usize = ModelId::ALL.len();

/// A name that is no model; its message lists the models.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct UnknownModel(pub String);

impl fmt::Display for UnknownModel {
    /// `unknown model `NAME`; models: basic_lighting, gouraud, ...`
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "unknown model `{}`; models: {}", self.0, ModelId::names().join(", "))
    }
}

impl std::error::Error for UnknownModel {}

impl ModelId {
    /// Every model's name, in [`ModelId::ALL`] order.
    #[must_use]
    pub fn names() -> [&'static str; N_MODELS] {
        ModelId::ALL.map(ModelId::name)
    }
}

impl FromStr for ModelId {
    type Err = UnknownModel;

    /// Parses a name exactly as [`ModelId::name`] prints it (case included).
    ///
    /// Errors: [`UnknownModel`], whose message lists the models.
    fn from_str(name: &str) -> Result<ModelId, UnknownModel> {
        ModelId::from_name(name).ok_or_else(|| UnknownModel(name.to_string()))
    }
}

impl fmt::Display for ModelId {
    /// The model's name ([`ModelId::name`]), padded as a `str` would be (`{:<17}`).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(self.name())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_and_an_unknown_name_lists_the_models() {
        for m in ModelId::ALL {
            assert_eq!(m.name().parse::<ModelId>(), Ok(m));
            assert_eq!(m.to_string(), m.name());
        }
        assert_eq!(format!("[{:<8}]", ModelId::Spot), "[spot    ]");
        let err = "Spot".parse::<ModelId>().unwrap_err().to_string();
        assert!(err.starts_with("unknown model `Spot`; models: basic_lighting, gouraud, materials"), "{err}");
        assert!(err.ends_with("normal_matrix, blinn_phong, lighting_maps_emission"), "{err}");
    }
}
