//! Line charts: several named series over one x axis, drawn with plotters into an RGB
//! buffer and encoded as PNG with `image`.
//!
//! Text uses the vendored DejaVu Sans, registered with plotters' `ab_glyph` font table
//! under the name `sans-serif`; no system font is read, so the bytes are the same on
//! every machine.
//!
//! ```no_run
//! use lightlab::figures::chart::{LineChart, Series};
//! let xs: Vec<f64> = (0..=90).map(f64::from).collect();
//! let chart = LineChart::new("angle (degrees)", "cos")
//!     .series(Series::from_fn("cos", &xs, |a| a.to_radians().cos()));
//! let png: Vec<u8> = chart.to_png()?;
//! # Ok::<(), lightlab::figures::FigureError>(())
//! ```

use super::FigureError;
use image::ImageEncoder;
use plotters::coord::combinators::WithKeyPoints;
use plotters::coord::ranged1d::{AsRangedCoord, ValueFormatter};
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use std::ops::Range;
use std::sync::OnceLock;

/// Colors given to series in order (the Okabe-Ito palette, readable with the common
/// colour-vision deficiencies); series past the eighth reuse them.
pub const PALETTE: [RGBColor; 8] = [
    RGBColor(0, 114, 178),
    RGBColor(213, 94, 0),
    RGBColor(0, 158, 115),
    RGBColor(204, 121, 167),
    RGBColor(230, 159, 0),
    RGBColor(86, 180, 233),
    RGBColor(0, 0, 0),
    RGBColor(240, 228, 66),
];

/// Largest accepted chart side, in pixels (keeps the supersampled RGB buffer under
/// 1 GB).
const MAX_SIDE_PX: u32 = 8000;

/// The margin above and below a y range that spans the data, as a share of the
/// range (of its logarithm on a log axis).
const Y_MARGIN: f64 = 0.05;

/// Charts are drawn this many times larger in each direction, then averaged down, to
/// antialias lines and text.
const SUPERSAMPLE: u32 = 2;

/// One named line: points `(x, y)` joined in the given order.
#[derive(Clone, Debug, PartialEq)]
pub struct Series {
    /// Legend text.
    pub name: String,
    /// The points, joined in order.
    pub points: Vec<(f64, f64)>,
    /// Line width in output pixels (2 unless set with [`Series::width`]).
    pub width: u32,
    /// `Some((dash, gap))` in output pixels draws the line dashed, so a line drawn on
    /// top of another one with the same values leaves the lower one visible.
    pub dash: Option<(u32, u32)>,
}

impl Series {
    /// A solid series of width 2 through `points`.
    pub fn new(name: &str, points: Vec<(f64, f64)>) -> Series {
        Series { name: name.to_owned(), points, width: 2, dash: None }
    }

    /// A series named `name` with `y = f(x)` at each of `xs`.
    pub fn from_fn(name: &str, xs: &[f64], f: impl Fn(f64) -> f64) -> Series {
        Series::new(name, xs.iter().map(|&x| (x, f(x))).collect())
    }

    /// The same series with line width `width` output pixels (at least 1).
    pub fn width(mut self, width: u32) -> Series {
        self.width = width.max(1);
        self
    }

    /// The same series dashed: `dash` pixels drawn, `gap` pixels left out (each at
    /// least 1).
    pub fn dashed(mut self, dash: u32, gap: u32) -> Series {
        self.dash = Some((dash.max(1), gap.max(1)));
        self
    }
}

/// Where the legend box sits inside the plot area.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Legend {
    /// Top right corner (the default).
    UpperRight,
    /// Top left corner.
    UpperLeft,
    /// Bottom left corner.
    LowerLeft,
    /// Bottom right corner.
    LowerRight,
    /// No legend.
    Hidden,
}

/// A chart of several named line series over x. Build it with [`LineChart::new`] and
/// the chained setters, then call [`LineChart::to_png`].
#[derive(Clone, Debug, PartialEq)]
pub struct LineChart {
    /// Title above the plot; empty for none.
    pub title: String,
    /// Label of the x axis.
    pub x_label: String,
    /// Label of the y axis.
    pub y_label: String,
    /// Logarithmic x axis (every x must then be > 0).
    pub x_log: bool,
    /// Logarithmic y axis (every y must then be > 0).
    pub y_log: bool,
    /// Fixed x range; `None` spans the data.
    pub x_range: Option<(f64, f64)>,
    /// Fixed y range; `None` spans the data.
    pub y_range: Option<(f64, f64)>,
    /// Image size in pixels.
    pub size: (u32, u32),
    /// Legend placement.
    pub legend: Legend,
    /// The lines, drawn and listed in this order.
    pub series: Vec<Series>,
    /// Tick labels with a decimal comma (`0,25`), as French and Ukrainian write them.
    pub decimal_comma: bool,
}

impl LineChart {
    /// An empty 800x500 chart with linear axes labelled `x_label` and `y_label`.
    pub fn new(x_label: &str, y_label: &str) -> LineChart {
        LineChart {
            title: String::new(),
            x_label: x_label.to_owned(),
            y_label: y_label.to_owned(),
            x_log: false,
            y_log: false,
            x_range: None,
            y_range: None,
            size: (800, 500),
            legend: Legend::UpperRight,
            series: Vec::new(),
            decimal_comma: false,
        }
    }

    /// Set the title.
    pub fn title(mut self, title: &str) -> Self {
        self.title = title.to_owned();
        self
    }

    /// Use a logarithmic x axis.
    pub fn x_log(mut self) -> Self {
        self.x_log = true;
        self
    }

    /// Use a logarithmic y axis.
    pub fn y_log(mut self) -> Self {
        self.y_log = true;
        self
    }

    /// Fix the x range to `lo..hi`.
    pub fn x_range(mut self, lo: f64, hi: f64) -> Self {
        self.x_range = Some((lo, hi));
        self
    }

    /// Fix the y range to `lo..hi`.
    pub fn y_range(mut self, lo: f64, hi: f64) -> Self {
        self.y_range = Some((lo, hi));
        self
    }

    /// Set the image size in pixels.
    pub fn size(mut self, width: u32, height: u32) -> Self {
        self.size = (width, height);
        self
    }

    /// Set the legend placement.
    pub fn legend(mut self, legend: Legend) -> Self {
        self.legend = legend;
        self
    }

    /// Add a series.
    pub fn series(mut self, series: Series) -> Self {
        self.series.push(series);
        self
    }

    /// The chart in `lang`: its title, axis labels and series names through
    /// [`crate::i18n::tr`] (English words are the msgids), and tick labels with the
    /// language's decimal separator.
    #[must_use]
    pub fn in_lang(&self, lang: crate::i18n::Lang) -> LineChart {
        let tr = |s: &str| if s.is_empty() { String::new() } else { crate::i18n::tr(lang, s).into_owned() };
        let mut out = self.clone();
        out.title = tr(&self.title);
        out.x_label = tr(&self.x_label);
        out.y_label = tr(&self.y_label);
        for s in &mut out.series {
            s.name = tr(&s.name);
        }
        out.decimal_comma = lang.decimal_comma();
        out
    }

    /// Render to PNG bytes (8-bit RGB).
    ///
    /// Returns an error naming the field when: there is no series or a series has no
    /// point; a coordinate is not finite; a log axis meets a value <= 0; a range is
    /// empty or reversed; the size is zero or larger than 8000 pixels a side.
    pub fn to_png(&self) -> Result<Vec<u8>, FigureError> {
        let (w, h) = self.size;
        let (xr, yr) = self.checked()?;
        // Plotters' bitmap back end does not antialias: draw SUPERSAMPLE times larger
        // and average down.
        let (big_w, big_h) = (w * SUPERSAMPLE, h * SUPERSAMPLE);
        let mut buf = vec![0u8; big_w as usize * big_h as usize * 3];
        {
            let root = BitMapBackend::with_buffer(&mut buf, (big_w, big_h)).into_drawing_area();
            self.draw_any(root, SUPERSAMPLE, xr, yr)?;
        }
        downsample_to_png(buf, w, h, SUPERSAMPLE, "LineChart")
    }

    /// Render to an SVG document with the same layout as [`LineChart::to_png`] (text
    /// names the `sans-serif` family; a viewer without DejaVu Sans uses its own).
    ///
    /// Errors: as [`LineChart::to_png`].
    pub fn to_svg(&self) -> Result<String, FigureError> {
        let (w, h) = self.size;
        let (xr, yr) = self.checked()?;
        let mut out = String::new();
        {
            let root = SVGBackend::with_string(&mut out, (w, h)).into_drawing_area();
            self.draw_any(root, 1, xr, yr)?;
        }
        Ok(out)
    }

    /// Draw on `root` (scaled by `k`) with linear or log axes as the chart says.
    fn draw_any<DB: DrawingBackend>(
        &self,
        root: DrawingArea<DB, plotters::coord::Shift>,
        k: u32,
        xr: Range<f64>,
        yr: Range<f64>,
    ) -> Result<(), FigureError> {
        match (self.x_log, self.y_log) {
            (false, false) => self.draw(root, k, lin(xr), lin(yr)),
            (true, false) => self.draw(root, k, xr.log_scale(), lin(yr)),
            (false, true) => self.draw(root, k, lin(xr), log_one_two_five(yr)),
            (true, true) => self.draw(root, k, xr.log_scale(), log_one_two_five(yr)),
        }
    }

    /// Check the size and the data, load the font, and return the ranges to draw.
    fn checked(&self) -> Result<(Range<f64>, Range<f64>), FigureError> {
        let (w, h) = self.size;
        if w == 0 || h == 0 || w > MAX_SIDE_PX || h > MAX_SIDE_PX {
            return Err(FigureError::Invalid(format!(
                "LineChart.size: {w}x{h} must be between 1 and {MAX_SIDE_PX} a side"
            )));
        }
        let ranges = self.ranges()?;
        ensure_font()?;
        Ok(ranges)
    }

    /// Check the data and return the x and y ranges to draw.
    fn ranges(&self) -> Result<(Range<f64>, Range<f64>), FigureError> {
        if self.series.is_empty() {
            return Err(FigureError::Invalid("LineChart.series: no series to draw".to_owned()));
        }
        for s in &self.series {
            if s.points.is_empty() {
                return Err(FigureError::Invalid(format!("LineChart.series '{}': no points", s.name)));
            }
            for &(x, y) in &s.points {
                if !(x.is_finite() && y.is_finite()) {
                    return Err(FigureError::Invalid(format!(
                        "LineChart.series '{}': point ({x}, {y}) is not finite",
                        s.name
                    )));
                }
                if (self.x_log && x <= 0.0) || (self.y_log && y <= 0.0) {
                    return Err(FigureError::Invalid(format!(
                        "LineChart.series '{}': point ({x}, {y}) is <= 0 on a log axis",
                        s.name
                    )));
                }
            }
        }
        let all = || self.series.iter().flat_map(|s| s.points.iter().copied());
        let span = |vals: Vec<f64>| {
            let lo = vals.iter().copied().fold(f64::INFINITY, f64::min);
            let hi = vals.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            // A flat series still needs a non-empty range.
            if hi > lo {
                (lo, hi)
            } else {
                (lo - 0.5 * lo.abs().max(1.0), hi + 0.5 * hi.abs().max(1.0))
            }
        };
        let x = self.x_range.unwrap_or_else(|| span(all().map(|p| p.0).collect()));
        // A data-spanning y range gets a margin of Y_MARGIN of its height at each end,
        // so a line at the largest or smallest value is not drawn on the frame.
        let y = self.y_range.unwrap_or_else(|| {
            let (lo, hi) = span(all().map(|p| p.1).collect());
            if self.y_log {
                let f = (hi / lo).powf(Y_MARGIN);
                (lo / f, hi * f)
            } else {
                let m = (hi - lo) * Y_MARGIN;
                (lo - m, hi + m)
            }
        });
        check_range("x_range", x, self.x_log)?;
        check_range("y_range", y, self.y_log)?;
        Ok((x.0..x.1, y.0..y.1))
    }

    fn draw<DB: DrawingBackend, X, Y>(
        &self,
        root: DrawingArea<DB, plotters::coord::Shift>,
        k: u32,
        x: X,
        y: Y,
    ) -> Result<(), FigureError>
    where
        X: AsRangedCoord<Value = f64>,
        Y: AsRangedCoord<Value = f64>,
        X::CoordDescType: ValueFormatter<f64>,
        Y::CoordDescType: ValueFormatter<f64>,
    {
        let err = |e: &dyn std::fmt::Debug| FigureError::backend("LineChart: drawing failed", format!("{e:?}"));
        // Every length below is in output pixels, times k for the supersampled buffer.
        let px = |v: u32| v * k;
        let font = |size: u32| ("sans-serif", f64::from(size * k));
        let comma = self.decimal_comma;
        let tick = move |v: &f64| if comma { tick_label(v).replace('.', ",") } else { tick_label(v) };
        root.fill(&WHITE).map_err(|e| err(&e))?;
        let mut builder = ChartBuilder::on(&root);
        builder.margin(px(16)).x_label_area_size(px(50)).y_label_area_size(px(66));
        if !self.title.is_empty() {
            builder.caption(&self.title, font(22));
        }
        let mut chart = builder.build_cartesian_2d(x, y).map_err(|e| err(&e))?;
        chart
            .configure_mesh()
            .x_desc(&self.x_label)
            .y_desc(&self.y_label)
            .x_label_formatter(&tick)
            .y_label_formatter(&tick)
            .label_style(font(16))
            .axis_desc_style(font(18))
            .light_line_style(RGBColor(238, 238, 238).stroke_width(k))
            .bold_line_style(RGBColor(210, 210, 210).stroke_width(k))
            .axis_style(RGBColor(90, 90, 90).stroke_width(k))
            .max_light_lines(4)
            .set_all_tick_mark_size(px(4))
            .draw()
            .map_err(|e| err(&e))?;
        for (i, s) in self.series.iter().enumerate() {
            let style = PALETTE[i % PALETTE.len()].stroke_width(px(s.width));
            let len = px(24) as i32;
            let drawn = match s.dash {
                None => chart.draw_series(LineSeries::new(s.points.iter().copied(), style)),
                Some((dash, gap)) => {
                    chart.draw_series(DashedLineSeries::new(s.points.iter().copied(), px(dash), px(dash + gap), style))
                }
            };
            let legend_dash = s.dash.map(|(d, g)| (px(d) as i32, px(d + g) as i32));
            drawn.map_err(|e| err(&e))?.label(s.name.as_str()).legend(move |(lx, ly)| {
                // The legend's sample shows the line's dashes too (two dashes).
                let (d, period) = legend_dash.unwrap_or((len, len));
                EmptyElement::at((lx, ly))
                    + PathElement::new(vec![(0, 0), (d.min(len), 0)], style)
                    + PathElement::new(vec![(period.min(len), 0), ((period + d).min(len), 0)], style)
            });
        }
        let position = match self.legend {
            Legend::UpperRight => SeriesLabelPosition::UpperRight,
            Legend::UpperLeft => SeriesLabelPosition::UpperLeft,
            Legend::LowerLeft => SeriesLabelPosition::LowerLeft,
            Legend::LowerRight => SeriesLabelPosition::LowerRight,
            Legend::Hidden => return root.present().map_err(|e| err(&e)),
        };
        chart
            .configure_series_labels()
            .position(position)
            .margin(px(12))
            .legend_area_size(px(30))
            .label_font(font(16))
            .background_style(WHITE.mix(0.92))
            .border_style(RGBColor(150, 150, 150).stroke_width(k))
            .draw()
            .map_err(|e| err(&e))?;
        root.present().map_err(|e| err(&e))
    }
}

/// Average an RGB buffer drawn `k` times larger in each direction (`w·k × h·k`, 8-bit,
/// row-major) down to `w × h` with a triangle filter, then encode it as PNG. Errors
/// (a buffer of the wrong size, a failing encoder) name `what`.
pub(crate) fn downsample_to_png(buf: Vec<u8>, w: u32, h: u32, k: u32, what: &str) -> Result<Vec<u8>, FigureError> {
    let big = image::RgbImage::from_raw(w * k, h * k, buf).ok_or_else(|| format!("{what}: buffer size mismatch"))?;
    let small = image::imageops::resize(&big, w, h, image::imageops::FilterType::Triangle);
    let mut png = Vec::new();
    image::codecs::png::PngEncoder::new(&mut png)
        .write_image(small.as_raw(), w, h, image::ExtendedColorType::Rgb8)
        .map_err(|e| format!("{what}: PNG encoding failed: {e}"))?;
    Ok(png)
}

/// A tick label: at most three decimals, trailing zeros dropped (`10`, `0.25`); below a
/// thousandth, a power of ten as a reader writes it, not as a program prints it (`10⁻⁴`,
/// `2.5×10⁻⁵`, at most three significant digits).
pub(crate) fn tick_label(v: &f64) -> String {
    let v = *v;
    if v != 0.0 && v.abs() < 1e-3 {
        return power_of_ten(v);
    }
    let s = format!("{v:.3}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".to_owned()
    } else {
        s.to_owned()
    }
}

/// `v` as `m×10ⁿ` with superscript digits, `m` of at most three significant digits and
/// left out when it is 1: `10⁻⁴`, `2.5×10⁻⁵`, `-3×10⁻⁷`.
fn power_of_ten(v: f64) -> String {
    let printed = format!("{v:.2e}");
    let (mantissa, exponent) = printed.split_once('e').unwrap_or((&printed, "0"));
    let mantissa = mantissa.trim_end_matches('0').trim_end_matches('.');
    let superscript: String = exponent
        .chars()
        .map(|c| match c {
            '-' => '⁻',
            d => ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'][d.to_digit(10).unwrap_or(0) as usize],
        })
        .collect();
    match mantissa {
        "1" => format!("10{superscript}"),
        "-1" => format!("-10{superscript}"),
        m => format!("{m}×10{superscript}"),
    }
}

/// A box in pixels: left, top, right, bottom.
pub(crate) type Rect = [i32; 4];

/// Where a label of `size` (width, height, pixels) goes beside the point at `at`: the
/// offset of its top-left corner. The first of these that lies inside `area` (the plot's
/// box, so that no label runs over an axis) and meets none of `taken`: right of the point
/// (`gap` pixels away, centred on it), then a row further down, a row further up, and so
/// on for eight rows each way, then the same on the left; if every place is taken, the
/// first.
pub(crate) fn free_label_offset(at: (i32, i32), size: (i32, i32), taken: &[Rect], gap: i32, area: Rect) -> (i32, i32) {
    let (w, h) = size;
    let meets = |r: &Rect, o: (i32, i32)| {
        let (x0, y0) = (at.0 + o.0, at.1 + o.1);
        x0 < r[2] && r[0] < x0 + w && y0 < r[3] && r[1] < y0 + h
    };
    let inside = |o: (i32, i32)| {
        let (x0, y0) = (at.0 + o.0, at.1 + o.1);
        area[0] <= x0 && x0 + w <= area[2] && area[1] <= y0 && y0 + h <= area[3]
    };
    let rows = (0..=8).flat_map(|k| if k == 0 { vec![0] } else { vec![k, -k] });
    let places: Vec<(i32, i32)> =
        [gap, -gap - w].into_iter().flat_map(|dx| rows.clone().map(move |row| (dx, -h / 2 + row * h))).collect();
    places.iter().copied().find(|&o| inside(o) && !taken.iter().any(|r| meets(r, o))).unwrap_or(places[0])
}

/// A point's label of `size` placed by [`free_label_offset`] and added to `taken`: its
/// offset from the point, and the leader line to draw from the point (to the label's near
/// edge when it is not where it would go on an empty chart; the point alone otherwise).
pub(crate) fn place_label(
    at: (i32, i32),
    size: (i32, i32),
    taken: &mut Vec<Rect>,
    gap: i32,
    area: Rect,
) -> ((i32, i32), Vec<(i32, i32)>) {
    let offset = free_label_offset(at, size, taken, gap, area);
    taken.push([at.0 + offset.0, at.1 + offset.1, at.0 + offset.0 + size.0, at.1 + offset.1 + size.1]);
    let end = (if offset.0 > 0 { offset.0 } else { offset.0 + size.0 }, offset.1 + size.1 / 2);
    let moved = offset != free_label_offset(at, size, &[], gap, area);
    (offset, if moved { vec![(0, 0), end] } else { vec![(0, 0)] })
}

/// The pixels a polyline through `points` (backend pixels) covers, as boxes for a label to
/// keep off ([`free_label_offset`]'s `taken`): squares of side `2·half` centred every `half`
/// pixels along each segment, so that a label box of any size crossing the line meets one.
pub(crate) fn line_boxes(points: &[(i32, i32)], half: i32) -> Vec<Rect> {
    let half = half.max(1);
    let mut boxes = Vec::new();
    for pair in points.windows(2) {
        let ((x0, y0), (x1, y1)) = (pair[0], pair[1]);
        let (dx, dy) = (f64::from(x1 - x0), f64::from(y1 - y0));
        let steps = (dx.hypot(dy) / f64::from(half)).ceil().max(1.0) as i32;
        for s in 0..=steps {
            let t = f64::from(s) / f64::from(steps);
            let (x, y) = ((f64::from(x0) + t * dx).round() as i32, (f64::from(y0) + t * dy).round() as i32);
            boxes.push([x - half, y - half, x + half, y + half]);
        }
    }
    boxes
}

/// A chart's plotting box in backend pixels, for [`free_label_offset`].
pub(crate) fn plot_box<DB: DrawingBackend, C: plotters::coord::CoordTranslate>(
    chart: &ChartContext<'_, DB, C>,
) -> Rect {
    let (x, y) = chart.plotting_area().get_pixel_range();
    [x.start, y.start, x.end, y.end]
}

/// A log f64 axis over `r` with ticks at 1, 2 and 5 times each power of ten inside it,
/// and light grid lines at the other whole multiples (3, 4, 6, …).
///
/// plotters' own log ticks start at the first power of ten inside the range, so an axis
/// from 1.5 to 45 was labelled only at 10, 20, 30 and 40, and a line running from 2 to 20
/// could not be read below 10. Over more than [`MAX_DECADES_1_2_5`] decades, only the
/// powers of ten are labelled, as the labels would run together.
fn log_one_two_five(r: Range<f64>) -> WithKeyPoints<plotters::coord::combinators::LogCoord<f64>> {
    let (bold, light) = log_ticks(r.start, r.end);
    r.log_scale().with_key_points(bold).with_light_points(light)
}

/// Decades up to which [`log_one_two_five`] labels 1, 2 and 5 (beyond, powers of ten only).
const MAX_DECADES_1_2_5: f64 = 3.0;

/// The labelled ticks and the light grid lines of a log axis from `lo` to `hi` (both > 0,
/// `lo < hi`), each ascending: whole multiples `m · 10^e` inside the range, labelled when
/// `m` is 1, 2 or 5 (only 1 over more than [`MAX_DECADES_1_2_5`] decades), light otherwise.
fn log_ticks(lo: f64, hi: f64) -> (Vec<f64>, Vec<f64>) {
    let (mut bold, mut light) = (Vec::new(), Vec::new());
    if !(lo > 0.0 && hi > lo && hi.is_finite()) {
        return (bold, light);
    }
    let wide = (hi / lo).log10() > MAX_DECADES_1_2_5;
    let labelled: &[u32] = if wide { &[1] } else { &[1, 2, 5] };
    for e in lo.log10().floor() as i32..=hi.log10().ceil() as i32 {
        for m in 1..10u32 {
            // m · 10^e written as a division for negative e, so 0.2 is the float nearest 0.2
            let v = if e >= 0 { f64::from(m) * 10f64.powi(e) } else { f64::from(m) / 10f64.powi(-e) };
            if v < lo || v > hi {
                continue;
            }
            if labelled.contains(&m) {
                bold.push(v);
            } else {
                light.push(v);
            }
        }
    }
    (bold, light)
}

/// A linear f64 axis over `r`.
fn lin(r: Range<f64>) -> RangedCoordf64 {
    r.into()
}

fn check_range(field: &str, (lo, hi): (f64, f64), log: bool) -> Result<(), FigureError> {
    if !(lo.is_finite() && hi.is_finite() && lo < hi) {
        return Err(FigureError::Invalid(format!("LineChart.{field}: ({lo}, {hi}) must be finite with lo < hi")));
    }
    if log && lo <= 0.0 {
        return Err(FigureError::Invalid(format!("LineChart.{field}: ({lo}, {hi}) must be > 0 on a log axis")));
    }
    Ok(())
}

/// Register the vendored font as plotters' `sans-serif`, once per process.
pub(super) fn ensure_font() -> Result<(), FigureError> {
    // String error: a OnceLock must hold a Clone value; the message becomes a FigureError at each use.
    static REGISTERED: OnceLock<Result<(), String>> = OnceLock::new();
    REGISTERED
        .get_or_init(|| {
            plotters::style::register_font("sans-serif", FontStyle::Normal, super::FONT_DATA)
                .map_err(|_| "the vendored DejaVu Sans does not parse".to_owned())
        })
        .clone()
        .map_err(FigureError::Invalid)
}

/// Log-scaled `f64` axes in both directions.
pub(crate) type LogLog =
    Cartesian2d<plotters::coord::combinators::LogCoord<f64>, plotters::coord::combinators::LogCoord<f64>>;

/// A chart with log axes on `root` (drawn at `k` times the nominal size): the caption, the
/// label areas, the mesh with both axis descriptions, ticks written by `tick`, and the
/// light and bold grid lines every log chart of the book shares.
#[allow(clippy::too_many_arguments)]
pub(crate) fn log_log_chart<'a, DB: DrawingBackend>(
    root: &'a DrawingArea<DB, plotters::coord::Shift>,
    caption: &str,
    x: Range<f64>,
    y: Range<f64>,
    x_desc: &str,
    y_desc: &str,
    tick: &dyn Fn(&f64) -> String,
    k: u32,
) -> Result<ChartContext<'a, DB, LogLog>, FigureError> {
    let err = |e: &dyn std::fmt::Debug| FigureError::Invalid(format!("{caption}: {e:?}"));
    let font = |s: u32| ("sans-serif", f64::from(s * k));
    // a log axis may tick every integer of a decade (700, 800, 900, 1000 run together):
    // only 1, 2 and 5 times a power of ten are labelled
    let sparse = |v: &f64| if is_one_two_five(*v) { tick(v) } else { String::new() };
    let mut chart = ChartBuilder::on(root)
        .caption(caption, font(20))
        .margin(16 * k)
        .x_label_area_size(50 * k)
        .y_label_area_size(70 * k)
        .build_cartesian_2d(x.log_scale(), y.log_scale())
        .map_err(|e| err(&e))?;
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc(y_desc)
        .x_label_formatter(&sparse)
        .y_label_formatter(&sparse)
        .label_style(font(14))
        .axis_desc_style(font(16))
        .light_line_style(RGBColor(238, 238, 238).stroke_width(k))
        .bold_line_style(RGBColor(210, 210, 210).stroke_width(k))
        .draw()
        .map_err(|e| err(&e))?;
    Ok(chart)
}

/// Whether `v` is 1, 2 or 5 times a power of ten (to a relative 1e-9, which absorbs the
/// rounding of a log axis's tick values).
fn is_one_two_five(v: f64) -> bool {
    if !(v > 0.0 && v.is_finite()) {
        return false;
    }
    let mantissa = v / 10f64.powf(v.log10().floor());
    [1.0, 2.0, 5.0, 10.0].iter().any(|m| (mantissa - m).abs() < 1e-9 * m)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The sweep's axis (1.5 to 45 ms) is labelled below 10 too; a wide axis only at
    /// powers of ten; the light lines are the other whole multiples inside the range.
    #[test]
    fn a_log_axis_ticks_one_two_five_in_each_decade() {
        let (bold, light) = log_ticks(1.5, 45.0);
        assert_eq!(bold, [2.0, 5.0, 10.0, 20.0]);
        assert_eq!(light, [3.0, 4.0, 6.0, 7.0, 8.0, 9.0, 30.0, 40.0]);
        let (bold, _) = log_ticks(0.015, 0.6);
        assert_eq!(bold, [0.02, 0.05, 0.1, 0.2, 0.5]);
        let (bold, light) = log_ticks(0.5, 20_000.0);
        assert_eq!(bold, [1.0, 10.0, 100.0, 1000.0, 10_000.0]);
        assert!(light.contains(&0.5) && light.contains(&20_000.0) && !light.contains(&1.0));
        assert_eq!(log_ticks(0.0, 1.0), (vec![], vec![]));
    }

    #[test]
    fn log_ticks_are_labelled_at_one_two_five() {
        for v in [1.0, 2.0, 5.0, 10.0, 200.0, 0.005, 1e-6] {
            assert!(is_one_two_five(v), "{v}");
        }
        for v in [3.0, 700.0, 900.0, 0.0007, 0.0, -1.0, f64::NAN] {
            assert!(!is_one_two_five(v), "{v}");
        }
    }

    fn one_line() -> LineChart {
        LineChart::new("x", "y").series(Series::from_fn("id", &[1.0, 2.0, 3.0], |x| x))
    }

    #[test]
    fn renders_png() {
        let png = one_line().to_png().unwrap();
        assert_eq!(&png[1..4], b"PNG");
    }

    #[test]
    fn same_chart_same_bytes() {
        assert_eq!(one_line().to_png().unwrap(), one_line().to_png().unwrap());
    }

    #[test]
    fn all_log_combinations_render() {
        assert!(one_line().x_log().to_png().is_ok());
        assert!(one_line().y_log().to_png().is_ok());
        assert!(one_line().x_log().y_log().to_png().is_ok());
    }

    #[test]
    fn bad_input_is_an_error_naming_the_field() {
        let e = LineChart::new("x", "y").to_png().unwrap_err();
        assert!(e.to_string().contains("series"), "{e}");
        let e = one_line().size(0, 10).to_png().unwrap_err();
        assert!(e.to_string().contains("size"), "{e}");
        let zero = LineChart::new("x", "y").series(Series::from_fn("z", &[0.0, 1.0], |x| x));
        let e = zero.y_log().to_png().unwrap_err();
        assert!(e.to_string().contains("log"), "{e}");
        let e = one_line().x_range(2.0, 1.0).to_png().unwrap_err();
        assert!(e.to_string().contains("x_range"), "{e}");
        let nan = LineChart::new("x", "y").series(Series::from_fn("n", &[1.0], |_| f64::NAN));
        assert!(nan.to_png().unwrap_err().to_string().contains("finite"));
    }

    #[test]
    fn tick_labels_are_short() {
        assert_eq!(tick_label(&10.0), "10");
        assert_eq!(tick_label(&0.25), "0.25");
        assert_eq!(tick_label(&-0.0), "0");
        assert_eq!(tick_label(&0.0001), "10⁻⁴");
        assert_eq!(tick_label(&0.000_25), "2.5×10⁻⁴");
        assert_eq!(tick_label(&-3e-7), "-3×10⁻⁷");
        assert_eq!(tick_label(&(1e-5 * (1.0 + f64::EPSILON))), "10⁻⁵", "a power a rounding away, as powf gives");
        assert_eq!(tick_label(&1.234_56e-12), "1.23×10⁻¹²");
    }

    #[test]
    fn flat_series_gets_a_range() {
        let flat = LineChart::new("x", "y").series(Series::from_fn("c", &[1.0, 2.0], |_| 0.0));
        assert!(flat.to_png().is_ok());
    }

    /// A plot box no label leaves.
    const WIDE: Rect = [0, 0, 10_000, 10_000];

    fn meet(a: &Rect, b: &Rect) -> bool {
        a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3]
    }

    #[test]
    fn a_label_goes_right_of_its_point_when_nothing_is_there() {
        assert_eq!(free_label_offset((100, 100), (120, 14), &[], 8, WIDE), (8, -7));
    }

    #[test]
    fn labels_of_crowded_points_meet_neither_a_point_nor_each_other() {
        // five points within a few pixels of each other, as the roofline's multi scenes
        let points = [(300, 200), (302, 201), (301, 204), (299, 198), (303, 200)];
        let mut taken: Vec<Rect> = points.iter().map(|&(x, y)| [x - 7, y - 7, x + 7, y + 7]).collect();
        let dots = taken.len();
        for &p in &points {
            let o = free_label_offset(p, (120, 14), &taken, 8, WIDE);
            taken.push([p.0 + o.0, p.1 + o.1, p.0 + o.0 + 120, p.1 + o.1 + 14]);
        }
        for (i, a) in taken.iter().enumerate().skip(dots) {
            for (j, b) in taken.iter().enumerate() {
                assert!(i == j || !meet(a, b), "label {} meets box {j}: {a:?} {b:?}", i - dots);
            }
        }
    }

    #[test]
    fn a_label_keeps_off_a_line() {
        // a diagonal line from (0, 200) to (400, 0) passes right of the point (100, 120):
        // the label's first place, right of the point, crosses it; with the line's boxes
        // taken it goes elsewhere and meets no pixel of the line
        let area = [0, 0, 1000, 600];
        let line = [(0, 200), (400, 0)];
        let (at, size) = ((100, 120), (120, 14));
        let [(x0, y0), (x1, y1)] = line;
        let on_line = |o: (i32, i32)| {
            (x0..=x1).any(|x| {
                // the line's pixel in column x
                let y = y0 + (x - x0) * (y1 - y0) / (x1 - x0);
                let (l, t) = (at.0 + o.0, at.1 + o.1);
                l <= x && x <= l + size.0 && t <= y && y <= t + size.1
            })
        };
        assert!(on_line(free_label_offset(at, size, &[], 8, area)), "the test's line must cross the free place");
        let taken = line_boxes(&line, 2);
        let o = free_label_offset(at, size, &taken, 8, area);
        assert!(!on_line(o), "{o:?}");
    }

    #[test]
    fn a_label_stays_inside_the_plot() {
        // a point at the plot's left edge, with the right of it taken: the label goes
        // down the right, never left over the axis
        let area = [50, 0, 1000, 600];
        let taken = [[60, 90, 400, 110]];
        let o = free_label_offset((55, 100), (120, 14), &taken, 8, area);
        assert!(55 + o.0 >= 50 && o.0 > 0, "{o:?}");
        assert!(!meet(&[55 + o.0, 100 + o.1, 175 + o.0, 114 + o.1], &taken[0]));
    }
}
