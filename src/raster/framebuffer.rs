//! The float framebuffer: linear RGBA and depth, kept unquantized for error metrics;
//! and the 8-bit one, [`Rgba8Framebuffer`], whose colour is quantized as it is written.
//!
//! Rows are stored top to bottom (image order): row `r` holds window row
//! `y = height − 1 − r`. A cleared pixel has alpha 0; a drawn fragment writes
//! alpha 1, so coverage is `alpha > 0`, as `llvmpipe_bench.py` counts it.

use glam::Vec4;

/// A zero or oversized framebuffer request, naming the dimension (`width` or `height`).
pub type SizeError = crate::error::FieldError;

/// The largest width or height accepted (keeps fixed-point edge math in range).
pub const MAX_SIZE: u32 = 8192;

/// Linear float RGBA color and depth, row-major, top row first.
#[derive(Clone, Debug, PartialEq)]
pub struct Framebuffer {
    width: u32,
    height: u32,
    /// RGBA per pixel, linear, unclamped.
    pub color: Vec<[f32; 4]>,
    /// Window depth in [0, 1] per pixel, 1 = far (cleared).
    pub depth: Vec<f32>,
}

impl Framebuffer {
    /// A framebuffer cleared to transparent black and depth 1.
    ///
    /// Errors name the field when a size is 0 or above [`MAX_SIZE`].
    pub fn new(width: u32, height: u32) -> Result<Framebuffer, SizeError> {
        for (field, v) in [("width", width), ("height", height)] {
            if v == 0 || v > MAX_SIZE {
                return Err(SizeError { field, reason: format!("must be in 1..={MAX_SIZE}, got {v}") });
            }
        }
        let n = width as usize * height as usize;
        Ok(Framebuffer { width, height, color: vec![[0.0; 4]; n], depth: vec![1.0; n] })
    }

    /// Width in pixels.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Height in pixels.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// Set every pixel to `color` and every depth to 1.
    pub fn clear(&mut self, color: Vec4) {
        self.color.fill(color.to_array());
        self.depth.fill(1.0);
    }

    /// The pixel at column `x`, image row `row` (0 = top); `None` outside.
    pub fn pixel(&self, x: u32, row: u32) -> Option<[f32; 4]> {
        (x < self.width && row < self.height).then(|| self.color[(row * self.width + x) as usize])
    }

    /// How many pixels have alpha > 0 (covered by a fragment).
    pub fn covered(&self) -> usize {
        self.color.iter().filter(|c| c[3] > 0.0).count()
    }

    /// RGBA8 bytes, top row first: each channel clamped to [0, 1], optionally
    /// encoded to sRGB (color channels only), then `round(255 x)`.
    ///
    /// NaN channels become 0 (the clamp's documented result).
    pub fn to_rgba8(&self, srgb: bool) -> Vec<u8> {
        let q = quantize;
        let mut out = Vec::with_capacity(self.color.len() * 4);
        for c in &self.color {
            for (k, &v) in c.iter().enumerate() {
                let v = if srgb && k < 3 { crate::color::linear_to_srgb(v) } else { v };
                out.push(q(v));
            }
        }
        out
    }

    /// Write a PNG (RGBA8, see [`Framebuffer::to_rgba8`]) to `path` with
    /// [`crate::outfile::write_atomically`]: through a temporary file in the same
    /// directory renamed into place; a symbolic link is followed; a directory,
    /// device or FIFO is refused with an error naming the path.
    #[cfg(feature = "book")]
    pub fn save_png(&self, path: &std::path::Path, srgb: bool) -> Result<(), Box<dyn std::error::Error>> {
        save_rgba8_png(path, self.width, self.height, self.to_rgba8(srgb))
    }
}

/// One channel as the 8-bit colour buffers store it:
///
/// ```text
/// quantize(x) = round(255 · clamp(x, 0, 1)),   NaN ↦ 0,   halves away from zero
/// ```
///
/// Any f32 is accepted (±∞ clamp to 0 and 255). [`Framebuffer::to_rgba8`] and the
/// rasterizer's writes into an [`Rgba8Framebuffer`] both use it, so a frame drawn into
/// either gives the same bytes. OpenGL 3.3 core §2.1.6.1 (conversion to normalized
/// fixed point) allows either rounding; this one is the crate's since its first PNG.
#[inline(always)]
pub fn quantize(x: f32) -> u8 {
    (crate::glsl::saturate(if x.is_nan() { 0.0 } else { x }) * 255.0).round() as u8
}

/// An RGBA8 colour buffer and an f32 depth buffer, row-major, top row first, as
/// [`Framebuffer`]; each written colour is [`quantize`]d on the way in, so it holds
/// exactly [`Framebuffer::to_rgba8`]`(false)` of the same frame drawn into a
/// [`Framebuffer`]. A quarter of the colour bytes to clear and store: the target of a
/// frame that is only shown or saved (the benchmarks' `--rgba8`), never of error metrics,
/// which need the unclamped values. No sRGB encoding: the channels are linear.
#[derive(Clone, Debug, PartialEq)]
pub struct Rgba8Framebuffer {
    width: u32,
    height: u32,
    /// RGBA8 per pixel, linear.
    pub color: Vec<[u8; 4]>,
    /// Window depth in [0, 1] per pixel, 1 = far (cleared).
    pub depth: Vec<f32>,
}

impl Rgba8Framebuffer {
    /// A framebuffer cleared to transparent black and depth 1; errors as [`Framebuffer::new`].
    pub fn new(width: u32, height: u32) -> Result<Rgba8Framebuffer, SizeError> {
        let Framebuffer { depth, .. } = Framebuffer::new(width, height)?;
        Ok(Rgba8Framebuffer { width, height, color: vec![[0; 4]; depth.len()], depth })
    }

    /// Width in pixels.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Height in pixels.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// The RGBA8 frame of `fb`: each channel [`quantize`]d, as [`Framebuffer::to_rgba8`]`(false)`.
    pub fn from_float(fb: &Framebuffer) -> Rgba8Framebuffer {
        let color = fb.color.iter().map(|c| c.map(quantize)).collect();
        Rgba8Framebuffer { width: fb.width, height: fb.height, color, depth: fb.depth.clone() }
    }

    /// How many pixels have alpha > 0 (as `llvmpipe_bench.py` counts them). A clear
    /// alpha below 1/510 is stored as 0, so such a cleared pixel does not count here,
    /// while [`Framebuffer::covered`] counts it.
    pub fn covered(&self) -> usize {
        self.color.iter().filter(|c| c[3] > 0).count()
    }

    /// The RGBA8 bytes, top row first.
    pub fn to_rgba8(&self) -> Vec<u8> {
        self.color.as_flattened().to_vec()
    }

    /// Write a PNG of [`Rgba8Framebuffer::to_rgba8`] to `path`, as [`Framebuffer::save_png`]
    /// does (the same bytes for the same frame, without sRGB).
    #[cfg(feature = "book")]
    pub fn save_png(&self, path: &std::path::Path) -> Result<(), Box<dyn std::error::Error>> {
        save_rgba8_png(path, self.width, self.height, self.to_rgba8())
    }
}

/// A PNG of `width × height` RGBA8 `bytes` (top row first), written atomically.
#[cfg(feature = "book")]
fn save_rgba8_png(
    path: &std::path::Path,
    width: u32,
    height: u32,
    bytes: Vec<u8>,
) -> Result<(), Box<dyn std::error::Error>> {
    let image = image::RgbaImage::from_raw(width, height, bytes).ok_or("framebuffer size mismatch")?;
    let mut png = Vec::new();
    image.write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png)?;
    crate::outfile::write_atomically(path, png)?;
    Ok(())
}
