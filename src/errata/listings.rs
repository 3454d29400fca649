//! The printed code listings the errata check, quoted as the seeds print them (the
//! Ukrainian text prints one line per code block; the lines are joined here), and the
//! small parsers the checks use.
//!
//! `tests/gl_errata.rs` compiles these listings on OpenGL: the ones the table flags fail
//! to compile, their counterparts in the other text compile.
//!
//! Sources: `shared/seeds/000` (French LearnOpenGL), `001` (opengl-tutorial 8), `002`
//! (ogldev 19), `003` (Ukrainian lab); line numbers on each constant.

/// 000 l.1062-1067: the flashlight's `Light` struct (the `...` line left out).
pub const FR_SPOT_STRUCT: &str = "struct Light {\n    vec3 position;\n    vec3 direction;\n    float cutOff;\n};";

/// 000 l.1083-1090: the cone test, French text.
pub const FR_SPOT_TEST: &str = "float theta = dot(lightDir, normalize(-light.direction));
if(theta > light.cutoff)
{
    // calculs d'éclairement
}
else // sinon, utiliser la lumière ambiante pour les parties de la scène non éclairées par le spot
    color = vec4(light.ambient * vec3(texture(material.diffuse, TexCoords)), 1.0);";

/// 003 l.1674-1700: the cone test, Ukrainian text.
pub const UK_SPOT_TEST: &str = "float theta = dot(lightDir, normalize(-light.direction));
if(theta > light.cutOff)
{
// do lighting calculations
}
else // else, use ambient light so scene isn't completely dark outside the spotlight.
color = vec4(light.ambient * vec3(texture(material.diffuse, TexCoords)), 1.0);";

/// 000 l.1192-1205 (and 003 l.1812-1864): the multiple-lights skeleton.
pub const OUTPUT_SKELETON: &str = "out vec4 FragColor;
void main()
{
    // définition de la couleur finale
    vec3 output = vec3(0.0);
    // ajout de la contribution des sources directionnelles
    output += someFunctionToCalculateDirectionalLight();
    // idem pour les points lumineux
    for(int i = 0; i < nr_of_point_lights; i++)
        output += someFunctionToCalculatePointLight();
    // et enfin pour les spots ou autres sources
    output += someFunctionToCalculateSpotLight();
    FragColor = vec4(output, 1.0);
}";

/// 000 l.1216-1225: `DirLight`, French text, with the label line the listing prints.
pub const FR_DIRLIGHT: &str = "c17_1_1
struct DirLight {
    vec3 direction;
    vec3 ambient;
    vec3 diffuse;
    vec3 specular;
};
uniform DirLight dirLight;";

/// 000 l.1229-1231: the prototype, French text, with its label line.
pub const FR_DIRLIGHT_PROTOTYPE: &str = "c17_1_2\nvec3 CalcDirLight(DirLight light, vec3 normal, vec3 viewDir);";

/// 003 l.1878-1896: `DirLight` and the prototype, Ukrainian text.
pub const UK_DIRLIGHT: &str = "struct DirLight {
    vec3 direction;
    vec3 ambient;
    vec3 diffuse;
    vec3 specular;
};
uniform DirLight dirLight;
vec3 CalcDirLight(DirLight light, vec3 normal, vec3 viewDir);";

/// 000 l.990-998: the point light's `Light` struct, French text.
pub const FR_POINT_STRUCT: &str = "struct Light {
    vec3 position;
    vec3 ambient;
    vec3 diffuse;
    vec3 specular;
    float constant;
    float linear;
    float quadratic;
};";

/// 003 l.1495-1527: the same struct, Ukrainian text.
pub const UK_POINT_STRUCT: &str = "struct Light {
    vec3 position;
vec3 ambient;
vec3 diffuse;
vec3 specular;
float constant;
float linear;
float quadratic;
}";

/// 000 l.1267-1277 (= 003 l.1966-2006): `PointLight` and the array of four.
pub const POINT_LIGHT_STRUCT: &str = "struct PointLight {
    vec3 position;
    float constant;
    float linear;
    float quadratic;
    vec3 ambient;
    vec3 diffuse;
    vec3 specular;
};
#define NR_POINT_LIGHTS 4
uniform PointLight pointLights[NR_POINT_LIGHTS];";

/// 000 l.1357-1368: `pointLightPositions`, French text, as its two code blocks print it.
pub const FR_POINT_LIGHT_POSITIONS: &str = "glm::vec3 pointLightPositions[] = {
    glm::vec3( 0.7f, 0.2f, 2.0f),
    glm::vec3( 2.3f, -3.3f, -4.0f),
};
glm::vec3(-4.0f, 2.0f, -12.0f),
glm::vec3( 0.0f, 0.0f, -3.0f)
};";

/// 003 l.2184-2204: `pointLightPositions`, Ukrainian text.
pub const UK_POINT_LIGHT_POSITIONS: &str = "glm::vec3 pointLightPositions[] = {
    glm::vec3( 0.7f, 0.2f, 2.0f),
    glm::vec3( 2.3f, -3.3f, -4.0f),
    glm::vec3(-4.0f, 2.0f, -12.0f),
    glm::vec3( 0.0f, 0.0f, -3.0f)
};";

/// 000 l.527-534 (= 003 l.704-732): the `Material` struct.
pub const MATERIAL_STRUCT: &str = "struct Material {
    vec3 ambient;
    vec3 diffuse;
    vec3 specular;
    float shininess;
};";

/// 001 l.294-300: opengl-tutorial 8's final color, as printed.
pub const OPENGL_TUTORIAL_COLOR: &str = "color =
    // Ambient : simulates indirect lighting
    MaterialAmbientColor +
    // Diffuse : \"color\" of the object
    MaterialDiffuseColor * LightColor * LightPower * cosTheta / (distance*distance) ;
    // Specular : reflective highlight, like a mirror
    MaterialSpecularColor * LightColor * LightPower * pow(cosAlpha,5) / (distance*distance);";

/// 002 l.202-208: ogldev 19's specular term.
pub const OGLDEV_SPECULAR: &str = "vec3 VertexToEye = normalize(gEyeWorldPos - WorldPos0);
vec3 LightReflect = normalize(reflect(gDirectionalLight.Direction, Normal));
float SpecularFactor = dot(VertexToEye, LightReflect);
SpecularFactor = pow(SpecularFactor, gSpecularPower);
if (SpecularFactor > 0) {
    SpecularColor = vec4(gDirectionalLight.Color, 1.0f) * gMatSpecularIntensity * SpecularFactor;
}";

/// 002 l.211: the last line of the shader ogldev 19's l.214 describes.
pub const OGLDEV_FRAGMENT_OUTPUT: &str =
    "FragColor = texture2D(gSampler, TexCoord0.xy) * (AmbientColor + DiffuseColor + SpecularColor);";

/// 002 l.129-137: ogldev 19's vertex shader excerpt.
pub const OGLDEV_VERTEX: &str = "out vec3 WorldPos0;

void main()
{
    gl_Position = gWVP * vec4(Position, 1.0);
    TexCoord0 = TexCoord;
    Normal0 = (gWorld * vec4(Normal, 0.0)).xyz;
    WorldPos0 = (gWorld * vec4(Position, 1.0)).xyz;
}";

/// 002 l.106-114: the new members of `LightingTechnique`.
pub const OGLDEV_TECHNIQUE: &str = "    void SetEyeWorldPos(const Vector3f& EyeWorldPos);
    void SetMatSpecularIntensity(float Intensity);
    void SetMatSpecularPower(float Power);

private:
...
    GLuint m_eyeWorldPosLocation;
    GLuint m_matSpecularIntensityLocation;
    GLuint m_matSpecularPowerLocation;";

/// 002 l.182-184: the fragment shader's new uniforms.
pub const OGLDEV_UNIFORMS: &str =
    "uniform vec3 gEyeWorldPos;\nuniform float gMatSpecularIntensity;\nuniform float gSpecularPower;";

/// The field names of the first `struct NAME { … }` in `source`, in order; empty when
/// there is none. Declarations are `TYPE NAME;` with one name each, as in the tutorials.
pub fn struct_fields(source: &str) -> Vec<String> {
    let Some(open) = source.find('{') else { return Vec::new() };
    let body = &source[open + 1..];
    let body = &body[..body.find('}').unwrap_or(body.len())];
    body.split(';')
        .filter_map(|decl| {
            let decl = decl.lines().filter(|l| !l.trim_start().starts_with("//")).collect::<Vec<_>>().join(" ");
            decl.split_whitespace().last().map(|name| name.to_string())
        })
        .collect()
}

/// The identifiers written as `light.NAME` in `source`.
pub fn light_members_used(source: &str) -> Vec<String> {
    source
        .match_indices("light.")
        .map(|(i, m)| {
            source[i + m.len()..].chars().take_while(|c| c.is_ascii_alphanumeric() || *c == '_').collect::<String>()
        })
        .collect()
}

/// The elements of the first brace initializer `= { … };` in `source`: the text
/// between the first `{` and the first `}` that closes it, split on top-level commas,
/// empty items dropped.
pub fn initializer_items(source: &str) -> Vec<String> {
    let Some(open) = source.find('{') else { return Vec::new() };
    let mut depth = 0usize;
    let mut items = Vec::new();
    let mut current = String::new();
    for ch in source[open + 1..].chars() {
        match ch {
            '(' => {
                depth += 1;
                current.push(ch);
            }
            ')' => {
                depth = depth.saturating_sub(1);
                current.push(ch);
            }
            ',' if depth == 0 => items.push(std::mem::take(&mut current)),
            '}' if depth == 0 => break,
            _ => current.push(ch),
        }
    }
    items.push(current);
    items.into_iter().map(|s| s.trim().to_string()).filter(|s| !s.is_empty()).collect()
}

/// Whether the braces of `source` balance (every `}` closes an open `{`, none left open).
pub fn braces_balance(source: &str) -> bool {
    let mut depth = 0i64;
    for ch in source.chars() {
        match ch {
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                if depth < 0 {
                    return false;
                }
            }
            _ => {}
        }
    }
    depth == 0
}

/// Words GLSL 3.30 reserves for future use (GLSL 3.30 spec §3.6), the ones the tutorials'
/// code could meet.
pub const GLSL_RESERVED: [&str; 12] = [
    "output",
    "input",
    "common",
    "partition",
    "active",
    "filter",
    "sizeof",
    "cast",
    "namespace",
    "using",
    "public",
    "static",
];

/// The reserved words of [`GLSL_RESERVED`] that `source` uses as identifiers.
pub fn reserved_words_used(source: &str) -> Vec<&'static str> {
    let words: Vec<&str> = source.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_')).collect();
    GLSL_RESERVED.iter().copied().filter(|r| words.contains(r)).collect()
}
