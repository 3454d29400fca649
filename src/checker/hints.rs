//! Three hints for each mistake of the catalogue, shown one at a time after a failed check
//! (the page's "Show a hint (1/3)", the command line's first hint and `--hints`):
//!
//! 1. where to look, without the answer;
//! 2. the idea behind it;
//! 3. the fix, in the chapter's names.
//!
//! The hints are English msgids, translated through the PO files like the mistakes' titles.

use super::mistakes::Mistake;
use crate::blanks;

/// Each mistake id with its three hints, in the catalogue's order.
pub const HINTS: &[(&str, [&str; 3])] = &[
    (
        "light-dir-reversed",
        [
            "Look at how `lightDir` is computed: which point is subtracted from which.",
            "Every vector at the surface points away from it: `lightDir` must point from the fragment toward the light, so that `dot(norm, lightDir)` is positive on the lit side. For a directional light, `light.direction` points from the light, so it has to be negated.",
            "Compute `lightDir = normalize(lightPos - FragPos)`: the light's position minus the fragment's. For a directional light, write `lightDir = normalize(-light.direction)`.",
        ],
    ),
    (
        "view-dir-reversed",
        [
            "Look at how `viewDir` is computed: which point is subtracted from which.",
            "Like `lightDir`, `viewDir` starts at the surface: it points from the fragment toward the eye, so that `dot(viewDir, reflectDir)` is largest where the mirror direction reaches the eye.",
            "Compute `viewDir = normalize(viewPos - FragPos)`: the eye's position minus the fragment's.",
        ],
    ),
    (
        "view-from-origin",
        [
            "Look at how `viewDir` is computed, and at where it assumes the eye to be.",
            "The lighting happens in world space, where the camera sits at `viewPos`, not at the origin. The shortcut `normalize(-FragPos)` is only right in view space, where the eye is at the origin.",
            "Compute `viewDir = normalize(viewPos - FragPos)`, using the `viewPos` uniform.",
        ],
    ),
    (
        "reflect-sign",
        [
            "Look at the first argument you pass to `reflect`.",
            "`reflect(I, N)` expects the incident vector `I`, travelling from the light toward the surface. `lightDir` points the other way, from the surface toward the light, so reflecting it gives the opposite of the mirror direction.",
            "Negate the light direction: `reflectDir = reflect(-lightDir, norm)`.",
        ],
    ),
    (
        "diffuse-no-clamp",
        [
            "Look at how the diffuse factor `diff` is computed from `dot(norm, lightDir)`.",
            "A dot product becomes negative when the surface faces away from the light. A light cannot take brightness away, so the diffuse factor must never drop below `0.0`; otherwise it darkens the ambient term.",
            "Clamp the dot product: `diff = max(dot(norm, lightDir), 0.0)`.",
        ],
    ),
    (
        "specular-no-clamp",
        [
            "Look at the base you pass to `pow` in the specular term.",
            "`dot(viewDir, reflectDir)` (in Blinn-Phong, `dot(norm, halfwayDir)`) is negative when the eye is far from the mirror direction, and GLSL leaves `pow` undefined for a negative base: the driver may return NaN, which shows as black or garbage pixels.",
            "Clamp the base before raising it to the power: `spec = pow(max(dot(viewDir, reflectDir), 0.0), shininess)`, or `max(dot(norm, halfwayDir), 0.0)` in Blinn-Phong.",
        ],
    ),
    (
        "normal-not-normalized",
        [
            "Look at how `norm` is made from the interpolated `Normal`.",
            "A dot product gives the cosine of the angle only between unit vectors. Normals interpolated across a triangle are no longer of unit length, so the diffuse and specular terms scale with their length.",
            "Normalize the interpolated normal before using it: `vec3 norm = normalize(Normal);`.",
        ],
    ),
    (
        "blinn-for-phong",
        [
            "Look at which vector the specular term compares with which.",
            "The Phong model measures how close the eye is to the mirror direction of the light, with `dot(viewDir, reflectDir)`. The halfway vector with `dot(norm, halfwayDir)` belongs to Blinn-Phong, which gives a wider highlight for the same shininess.",
            "Compute `vec3 reflectDir = reflect(-lightDir, norm);` and use `pow(max(dot(viewDir, reflectDir), 0.0), shininess)` instead of the halfway vector.",
        ],
    ),
    (
        "ambient-missing",
        [
            "Look at the `ambient` term and how much it adds to the result.",
            "The ambient term stands for the light bounced around the scene: it keeps the parts the light does not reach from turning pure black.",
            "Give `ambient` its full value, without the `0.0 *` factor: for example `vec3 ambient = ambientStrength * lightColor;` or `vec3 ambient = light.ambient * material.ambient;`.",
        ],
    ),
    (
        "specular-missing",
        [
            "Look at the `specular` term and how much it adds to the result.",
            "The specular term draws the highlight, the bright spot where the light reflects toward the eye. Without it every surface looks matte.",
            "Give `specular` its full value, without the `0.0 *` factor: for example `vec3 specular = specularStrength * spec * lightColor;` or `vec3 specular = light.specular * (spec * material.specular);`.",
        ],
    ),
    (
        "shininess-ignored",
        [
            "Look at the exponent you pass to `pow` in the specular term.",
            "The shininess is a property of the material: a higher exponent gives a smaller, sharper highlight. A fixed number gives every material the same highlight.",
            "Use the material's value as the exponent: `pow(max(dot(viewDir, reflectDir), 0.0), material.shininess)` (or `shininess` where it is passed in).",
        ],
    ),
    (
        "attenuation-missing",
        [
            "Look at how `attenuation` is computed from `distance`.",
            "A point light grows weaker with distance: its contribution is divided by `light.constant + light.linear * distance + light.quadratic * (distance * distance)`, so far surfaces receive less light.",
            "Compute `attenuation = 1.0 / (light.constant + light.linear * distance + light.quadratic * (distance * distance))` and multiply the light's terms by it.",
        ],
    ),
    (
        "attenuation-quadratic-uses-d",
        [
            "Look at the quadratic term of the `attenuation` formula.",
            "The attenuation formula has a constant, a linear and a quadratic term: the last one multiplies `light.quadratic` by the square of the distance, which makes the light fade fast far away.",
            "Square the distance in the last term: `light.quadratic * (distance * distance)`.",
        ],
    ),
    (
        "ambient-not-attenuated",
        [
            "Look at which terms you multiply by `attenuation`.",
            "In the chapter, attenuation weakens the whole contribution of a point light, its ambient part included. Otherwise the ambient term keeps its full strength at any distance.",
            "Attenuate the ambient term too: add `ambient *= attenuation;`, or write `return (ambient + diffuse + specular) * attenuation;`.",
        ],
    ),
    (
        "spot-epsilon-swapped",
        [
            "Look at how `epsilon` is computed from the inner and outer cut-offs.",
            "The cut-offs are cosines, and the cosine falls as the angle grows: the inner cone's `light.cutOff` is larger than `light.outerCutOff`. `epsilon` must be positive, so that the intensity ramps from the outer cone up to the inner one.",
            "Subtract the outer cut-off from the inner one: `epsilon = light.cutOff - light.outerCutOff`.",
        ],
    ),
    (
        "spot-hard-edge",
        [
            "Look at how `intensity` is computed from `theta`.",
            "A single test against `light.cutOff` makes the intensity jump at the edge of the cone. The chapter adds an outer cone and ramps the intensity linearly in the cosine between the inner and the outer cut-off.",
            "Compute `epsilon = light.cutOff - light.outerCutOff` and `intensity = clamp((theta - light.outerCutOff) / epsilon, 0.0, 1.0);`, then scale `diffuse` and `specular` by `intensity`.",
        ],
    ),
    (
        "spot-cutoff-degrees",
        [
            "Look at how you use `light.cutOff` and `light.outerCutOff` in the shader.",
            "The application already sends the cut-offs as cosines, computed with `cos(radians(...))`, so that the shader can compare them with `theta` directly. Converting them once more gives wrong values, and the outer cut-off passes the inner one.",
            "Use `light.cutOff` and `light.outerCutOff` as they are, without `cos(radians(...))`.",
        ],
    ),
    (
        "spot-direction-reversed",
        [
            "Look at the spot's axis in `theta = dot(lightDir, …)`: which way `light.direction` points, and which way `lightDir` does.",
            "`light.direction` is the way the spot shines, from the light into the scene, and `lightDir` points from the fragment back to the light. θ is the cosine of the angle off the axis only when both point the same way along it: without the minus sign θ is -1 straight ahead, and the cone points backwards.",
            "Negate the spot's direction in θ only: `theta = dot(lightDir, normalize(-light.direction))`; `lightDir` itself stays as it is for the diffuse and specular terms.",
        ],
    ),
    (
        "clamp-per-light",
        [
            "Look at what each light function returns before the results are added up.",
            "Lights add up: their sum may pass the displayable range, and only the final colour is clipped when it is written. Clamping each light on its own loses light where lights overlap and shifts the hue of bright lights.",
            "Return each contribution without `clamp`, for example `return (ambient + diffuse + specular) * attenuation;`, and let `result` sum them.",
        ],
    ),
    (
        "light-dir-not-normalized",
        [
            "Look at how `lightDir` is computed: from the light's position and the fragment's, or from a directional light's `direction`.",
            "`dot(norm, lightDir)` is the cosine of the angle only when both vectors have length 1. The difference of two points is as long as the distance between them, and a directional light's stored direction need not have length 1 (the chapter's is (-0.2, -1.0, -0.3)), so without `normalize` the diffuse and specular terms scale with that length.",
            "Normalize the vector: `lightDir = normalize(light.position - FragPos)`, or `lightDir = normalize(-light.direction)` for a directional light.",
        ],
    ),
    (
        "shininess-zero",
        [
            "Look at the exponent you pass to `pow` in the specular term.",
            "Any positive number to the power 0 is 1, so a shininess of 0 gives a specular factor of 1 everywhere: the highlight covers the whole surface. `pow(0.0, 0.0)` is undefined in GLSL, and some drivers return NaN there.",
            "Raise the base to the material's shininess, which is at least 1: `spec = pow(max(dot(viewDir, reflectDir), 0.0), material.shininess)`.",
        ],
    ),
    (
        "spot-cutoff-as-angle",
        [
            "Look at how `theta` is computed and what it is compared with.",
            "The cut-offs are passed as cosines (`cos(radians(12.5))`), and a cosine shrinks as the angle grows. `acos` turns `theta` into an angle, which grows instead, so every comparison with a cut-off is reversed.",
            "Keep `theta` a cosine: `theta = dot(lightDir, normalize(-light.direction))`, and compare it with `light.cutOff` and `light.outerCutOff` as they are.",
        ],
    ),
    (
        "attenuation-distance-squared-twice",
        [
            "Look at the powers of `distance` in the attenuation's denominator.",
            "The linear term uses the distance `d` and the quadratic term `d²` (opengl-tutorial 8 divides by `d²` alone). If `distance` already holds a squared length (from `dot(v, v)`), or is squared again, `d` becomes `d²` and `d²` becomes `d⁴`, and the light fades far too fast.",
            "Use the length itself: `distance = length(light.position - FragPos)`, then `1.0 / (light.constant + light.linear * distance + light.quadratic * (distance * distance))`; in opengl-tutorial 8, divide by `distance * distance` once.",
        ],
    ),
    (
        "light-color-twice",
        [
            "Look at how many times `lightColor` enters each term and the final sum.",
            "The light's colour multiplies each term once: `ambientStrength * lightColor`, `diff * lightColor`, `specularStrength * spec * lightColor`. Multiplying their sum by `lightColor` again squares it, which a white light hides and a coloured or dimmed light shows.",
            "Multiply the sum by the object's colour only: `(ambient + diffuse + specular) * objectColor`.",
        ],
    ),
    (
        "specular-ungated",
        [
            "Look at where the specular term is computed: inside or outside the test on the diffuse factor.",
            "A face turned away from the light (N·L ≤ 0) receives no light, so it can show no highlight, yet the mirror direction can still point toward the eye there. This reference adds the specular term only inside `if (DiffuseFactor > 0.0)`; LearnOpenGL's shaders do not test, and each exercise follows its own reference.",
            "Move the specular block inside `if (DiffuseFactor > 0.0) { … }`, after the diffuse colour.",
        ],
    ),
    (
        "specular-after-semicolon",
        [
            "Look at the end of the line before the specular term, and whether it ends with `;`.",
            "A `;` ends the statement: the colour is then ambient plus diffuse, and the `+ MaterialSpecularColor * …` line below is a separate expression whose value nobody uses. It still compiles (a driver may only warn), which is why the missing highlight is easy to miss.",
            "Remove the `;` at the end of the diffuse line so that the specular line continues the same sum: `color = MaterialAmbientColor + … / (distance*distance) + MaterialSpecularColor * … / (distance*distance);`.",
        ],
    ),
    (
        "emission-lit",
        [
            "Look at the line that computes the emission, and at what it is multiplied by.",
            "The emission map is light the surface gives off by itself, not light it reflects: no light's colour, no diffuse factor and no attenuation enters it, so it glows the same on the lit side, on the dark side and with the lamp off.",
            "Sample the map and add it to the result unchanged: `vec3 emission = texture(material.emission, TexCoords).rgb;`, then `ambient + diffuse + specular + emission`.",
        ],
    ),
    (
        "normal-matrix-missing",
        [
            "Look at the matrix that moves `aNormal` to world space.",
            "A normal is not moved like a position: under a non-uniform scale, `mat3(model)` tilts it off the surface. The normal matrix, the transpose of the inverse of the model matrix, keeps it perpendicular.",
            "Transform the normal with the normal matrix: `Normal = mat3(transpose(inverse(model))) * aNormal;`.",
        ],
    ),
    (
        "normal-matrix-not-transposed",
        [
            "Look at the matrix that moves the normal: whether `inverse(model)` is transposed.",
            "A normal stays perpendicular to the surface only through the normal matrix, the transpose of the inverse of the model matrix. `inverse(model)` alone turns the normal back by the model's rotation instead of with it, and divides by its scales instead of compensating them.",
            "Move the normal with `mat3(transpose(inverse(model))) * aNormal`.",
        ],
    ),
    (
        "normal-not-transformed",
        [
            "Look at the space `aNormal` is in when you use it for lighting.",
            "The light and the eye are in world space, but `aNormal` is in object space: it must turn with the model, or the lighting stays fixed to the object's original orientation.",
            "Move the normal to world space with the normal matrix: `Normal = mat3(transpose(inverse(model))) * aNormal;`.",
        ],
    ),
    (
        "position-not-transformed",
        [
            "Look at the value you pass on as the fragment's position, `FragPos`.",
            "The light and the eye are given in world space, so the fragment's position must be in world space too. `aPos` is in object space: every direction computed from it is off by the model's transform.",
            "Move the position to world space with the model matrix: `FragPos = vec3(model * vec4(aPos, 1.0));`.",
        ],
    ),
    (
        "gouraud-for-phong",
        [
            "Look at which shader computes the lighting: the vertex shader or the fragment shader.",
            "Phong shading evaluates the lighting at every fragment, from the interpolated position and normal. Computing the colour at the vertices and interpolating it loses or smears a highlight that falls inside a triangle.",
            "Pass `FragPos` and `Normal` from the vertex shader, and compute `ambient`, `diffuse` and `specular` in the fragment shader.",
        ],
    ),
    (
        "phong-for-gouraud",
        [
            "Look at which shader computes the lighting: the vertex shader or the fragment shader.",
            "Gouraud shading evaluates the lighting at the vertices only and interpolates the resulting colour across the triangle; the fragment shader does no lighting of its own.",
            "Compute the lighting in the vertex shader and pass it on as `LightingColor`; in the fragment shader, only multiply it by the object colour: `LightingColor * objectColor`.",
        ],
    ),
    (
        "light-not-in-view-space",
        [
            "Look at the space each point of the lighting is in: the fragment's position, the normal and the light's position.",
            "In view space the camera sits at the origin and every point has been moved by the view matrix. The `lightPos` uniform is given in world space, so it has to be moved by `view` too, or the light follows the camera.",
            "Move the light into view space in the vertex shader and pass it on: `LightPos = vec3(view * vec4(lightPos, 1.0));`, then use it in place of `lightPos` in the fragment shader.",
        ],
    ),
    (
        "spaces-normal-in-view",
        [
            "Look at the matrix the normal goes through in the vertex shader, and at the space the fragment shader's other vectors are in.",
            "Every vector of the lighting must be in one space. The fragment's position, `lightPos` and `viewPos` are in world space here, so the normal must be too, and its matrix comes from `model` alone. A normal matrix built from `view * model` belongs to lighting done entirely in view space.",
            "Build the normal matrix from the model matrix: `Normal = mat3(transpose(inverse(model))) * aNormal;`.",
        ],
    ),
    (
        "spaces-normal-in-world",
        [
            "Look at the matrix the normal goes through in the vertex shader, and at the space the position and the light are in.",
            "In view space every point and vector has been moved by the view matrix: the position by `view * model`, the light by `view`. The normal must turn with them, so its matrix comes from `view * model`; the model's normal matrix alone leaves it in world space.",
            "Build the normal matrix from `view * model`: `Normal = mat3(transpose(inverse(view * model))) * aNormal;`.",
        ],
    ),
    (
        "spaces-light-in-view",
        [
            "Look at the space each point of the lighting is in: the fragment's position, the normal, the eye and the light.",
            "Lighting works in any one space, as long as every point and vector is in it. Here the position, the normal and `viewPos` are in world space, but the light has been moved by `view`: its coordinates now name another point, which moves with the camera.",
            "Keep the light in world space like the rest, using the `lightPos` uniform as it is, or move everything to view space: the position and the normal by `view * model`, and the eye to the origin.",
        ],
    ),
];

/// The isolation step's hints (see [`super::isolation`]), for a shader no catalogue mistake
/// reproduces. Each set is where to look, the idea, and how to fix it, as the catalogue's;
/// `{}` is the name of what was located (a light, a kind of light, one term of every light)
/// or the conditions every failing case meets.
///
/// One term switched off removes the difference: the term's own three hints.
/// The emission (Lighting maps, exercise 4) is a term of its own: light the surface gives
/// off, added after the lighting.
pub const TERM_HINTS: [(&str, [&str; 3]); 4] = [
    (
        "ambient",
        [
            "Look at the line that computes the ambient term: with it switched off in both shaders, they agree on every case.",
            "The ambient term is the light's ambient colour times the surface colour (in the first chapters, `ambientStrength` times the light colour). No direction and no distance enter it, so it is the same all over the object.",
            "Write the ambient term as the chapter does, factor by factor, and check that each factor is the uniform the chapter names.",
        ],
    ),
    (
        "diffuse",
        [
            "Look at the lines that compute the diffuse term: with it switched off in both shaders, they agree on every case.",
            "The diffuse term is `max(dot(N, L), 0.0)` times the light's diffuse colour and the surface colour, where N is the unit normal and L the unit vector from the fragment toward the light.",
            "Write the diffuse term as the chapter does: normalize the normal, take `lightDir` from the fragment toward the light, clamp the dot product at zero, then multiply by the colours.",
        ],
    ),
    (
        "specular",
        [
            "Look at the lines that compute the specular term: with it switched off in both shaders, they agree on every case.",
            "The specular term is `max(dot(V, R), 0.0)` raised to the shininess, times the light's specular colour and the surface's specular colour; R is the light direction mirrored about the normal, and V points from the fragment toward the eye.",
            "Write the specular term as the chapter does: `reflect(-lightDir, norm)`, `viewDir` from the fragment toward the eye, the clamp before `pow`, and each colour once.",
        ],
    ),
    (
        "emission",
        [
            "Look at the lines that use the emission map: with it switched off in both shaders, they agree on every case.",
            "The emission is light the surface gives off by itself: it is added after the lighting, as it is, and no light's colour, no diffuse factor and no attenuation multiplies it. Mixed into the diffuse texel or scaled by `diff`, it fades on the dark side, where it should glow just as much.",
            "Sample the emission map on its own, `vec3 emission = texture(material.emission, TexCoords).rgb;`, leave the other terms as the chapter writes them, and add it last: `ambient + diffuse + specular + emission`.",
        ],
    ),
];

/// One light switched off removes the difference; `{}` is the light.
pub const LIGHT_HINTS: [&str; 3] = [
    "Look at what only {} goes through: with it switched off in both shaders, they agree on every case.",
    "Each light adds its own ambient, diffuse and specular terms. When one light alone is wrong, the mistake is in what it does not share with the others: its uniforms, or the function of its kind when it is the only light of that kind.",
    "Compare the code that computes {} with the chapter's, line by line, and check each uniform name against the ones the program sets.",
];

/// Every light of one kind switched off together removes the difference, and no single
/// one does; `{}` is the kind (`every point light`).
pub const KIND_HINTS: [&str; 3] = [
    "Look at the function shared by {}: switched off together, they take the whole difference with them, while switching off any one of them leaves the others' share.",
    "Lights of one kind share one function, so one mistake in it shows in every light of that kind, and in no other light.",
    "Compare that function with the chapter's, line by line: the light direction, the attenuation, and each of the three terms.",
];

/// One term of every light switched off removes the difference: this first hint (`{}` is
/// `every light's diffuse term`), then the term's idea and fix from [`TERM_HINTS`].
pub const EVERY_LIGHT_TERM_WHERE: &str =
    "Look at how each light function computes the term: with {} switched off in both shaders, they agree on every case.";

/// Nothing switched off removes the difference, but every failing case meets the
/// conditions `{}`.
pub const WHEN_HINTS: [&str; 3] = [
    "Look at what your shader does when {}: every disagreeing case meets that, and some agreeing cases do not.",
    "A difference confined to one region usually comes from a clamp, a sign or a test (a `max`, a comparison, an `if`) that the chapter's shader has and yours does not, or the reverse.",
    "Take one counterexample below, compute each term by hand from its numbers, and compare them with your shader's terms one at a time.",
];

/// Nothing switched off removes the difference, and no condition sets the failing cases apart.
pub const NOWHERE_HINTS: [&str; 3] = [
    "Look at what every term uses: no single term or light switched off removes the difference, so it is in several places, or in something they share, such as the normal, a position or a direction.",
    "The normalized normal, the fragment's position and the direction toward the light enter every term, so one mistake in them spreads to all the terms at once.",
    "Take one counterexample below, compute each term by hand from its numbers, and compare them with your shader's terms one at a time.",
];

/// Nothing switched off removes the difference, no condition sets the failing cases apart,
/// and some terms could not be switched off at all (`{}`: their names): the shader writes
/// what scales them (`ambientStrength`, `specularStrength`) as numbers, so the check cannot
/// set it to zero. [`NOWHERE_HINTS`] would blame what the terms share, which the check
/// did not show (red-team finding 10c).
pub const UNSWITCHED_HINTS: [&str; 3] = [
    "{} could not be switched off to narrow the difference down: your shader writes the values that scale them as numbers in its code, not as uniforms the check can set to zero.",
    "Declare those strengths as uniforms, as the chapter's shader with parameters does, and check again: the check then names the term that differs.",
    "Take one counterexample below, compute each term by hand from its numbers, and compare them with your shader's terms one at a time.",
];

/// The environment variable that asks for every hint (`lightlab --hints` sets it, so the
/// child processes that check a shader see it too): `all`. Anything else, or unset, prints
/// the first hint only.
pub const HINTS_VAR: &str = "LIGHTLAB_HINTS";

/// Whether the command line prints all three hints of a named mistake ([`HINTS_VAR`]).
#[must_use]
pub fn showing_all() -> bool {
    std::env::var(HINTS_VAR).is_ok_and(|v| v == "all")
}

/// The hint lines printed under a named mistake, indented by `indent`: the first hint, or all
/// three numbered when `all`; nothing for an id without hints. Each through `tr`.
#[must_use]
pub fn hint_lines(id: &str, all: bool, indent: &str, tr: impl Fn(&str) -> String) -> Vec<String> {
    let Some(h) = hints(id) else { return Vec::new() };
    let shown: Vec<String> = h.iter().map(|hint| tr(hint)).collect();
    numbered(&shown, all, indent, tr)
}

/// Hint lines of `hints` (already in the reader's language), indented by `indent`: the
/// first as `hint: …`, or all of them as `hint k/n: …` when `all`; `tr` translates the word.
#[must_use]
pub fn numbered(hints: &[String], all: bool, indent: &str, tr: impl Fn(&str) -> String) -> Vec<String> {
    let n = hints.len();
    match hints.first() {
        None => Vec::new(),
        Some(first) if !all => vec![format!("{indent}{}", blanks::fill(&tr(HINT_LINE), &[first]))],
        Some(_) => hints
            .iter()
            .enumerate()
            .map(|(k, h)| {
                format!("{indent}{}", blanks::fill(&tr(HINT_NUMBERED), &[&(k + 1).to_string(), &n.to_string(), h]))
            })
            .collect(),
    }
}

/// A hint on the command line (a msgid: French puts a space before the colon).
pub const HINT_LINE: &str = "hint: {}";
/// One of all the hints (`--hints`): its number, how many, the hint.
pub const HINT_NUMBERED: &str = "hint {}/{}: {}";

/// The hints of mistake `id`, or `None` for an id outside the catalogue (`isolated`).
#[must_use]
pub fn hints(id: &str) -> Option<&'static [&'static str; 3]> {
    HINTS.iter().find(|(m, _)| *m == id).map(|(_, h)| h)
}

impl Mistake {
    /// This mistake's three hints (every catalogue mistake has them: see the tests).
    #[must_use]
    pub fn hints(&self) -> Option<&'static [&'static str; 3]> {
        hints(self.id)
    }
}

#[cfg(test)]
mod tests {
    use super::super::mistakes::{CATALOGUE, VERTEX_CATALOGUE};
    use super::*;

    #[test]
    fn the_first_hint_by_default_all_three_on_request() {
        let id = HINTS[0].0;
        let one = hint_lines(id, false, "  ", str::to_owned);
        assert_eq!(one, [format!("  hint: {}", HINTS[0].1[0])]);
        let all = hint_lines(id, true, "", str::to_owned);
        assert_eq!(all.len(), 3);
        assert!(all[2].starts_with("hint 3/3: ") && all[2].ends_with(HINTS[0].1[2]), "{all:?}");
        assert!(hint_lines("isolated", true, "", str::to_owned).is_empty());
    }

    #[test]
    fn every_mistake_has_three_hints_and_every_hint_a_mistake() {
        let ids: Vec<&str> = CATALOGUE.iter().chain(VERTEX_CATALOGUE).map(|m| m.id).collect();
        let listed: Vec<&str> = HINTS.iter().map(|(id, _)| *id).collect();
        let missing: Vec<&&str> = ids.iter().filter(|id| !listed.contains(id)).collect();
        let unknown: Vec<&&str> = listed.iter().filter(|id| !ids.contains(id)).collect();
        assert!(missing.is_empty() && unknown.is_empty(), "no hints for {missing:?}; hints for unknown {unknown:?}");
        for (id, h) in HINTS {
            for hint in h {
                assert!(hint.len() > 10 && hint.ends_with('.'), "{id}: a hint is a sentence: {hint:?}");
            }
            assert!(h[0] != h[1] && h[1] != h[2] && h[0] != h[2], "{id}: three different hints");
        }
    }
}
