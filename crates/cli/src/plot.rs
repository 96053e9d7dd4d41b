//! SVG plots for the front ends (`stribeck`, `map`, and later `cycle`, `figures`, `bench`).
//!
//! Rendering only: every function returns the SVG document as a `String`; writing it to a
//! file (atomically) is the caller's business, so this module does no I/O.
//!
//! - [`line_plot`]: one chart, several series, linear or log axes, shaded x-ranges ([`Band`]).
//! - [`stacked_plot`]: several charts one above the other, e.g. sharing an x axis.
//! - [`heat_map`]: a value over a grid of (x, y) with a colour bar, contour lines and
//!   outlined rectangles ([`Region`]) such as an operating region.
//!
//! Text is emitted as SVG `<text>` (plotters without its font features measures text
//! with a built-in estimate), so any SVG viewer renders it with its own sans-serif font.

use plotters::coord::ranged1d::{AsRangedCoord, ValueFormatter};
use plotters::chart::MeshStyle;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::fmt;

/// A rendering failure (from plotters), as text.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("plot rendering failed: {0}")]
pub struct PlotError(
    /// plotters' error message.
    pub String,
);

fn err<E: fmt::Display>(e: E) -> PlotError {
    PlotError(e.to_string())
}

/// Axis scale.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scale {
    /// Linear axis.
    Linear,
    /// Base-10 logarithmic; non-positive values are left out of the plot.
    Log,
}

/// One axis: its label (with the unit), scale and optional fixed range.
#[derive(Debug, Clone, PartialEq)]
pub struct Axis {
    /// Axis label, with the unit, e.g. "speed [rad/s]".
    pub label: String,
    /// Linear or logarithmic.
    pub scale: Scale,
    /// `None`: fitted to the data.
    pub range: Option<(f64, f64)>,
}

impl Axis {
    /// A linear axis fitted to the data.
    pub fn linear(label: impl Into<String>) -> Self {
        Self { label: label.into(), scale: Scale::Linear, range: None }
    }
    /// A base-10 logarithmic axis fitted to the data.
    pub fn log(label: impl Into<String>) -> Self {
        Self { label: label.into(), scale: Scale::Log, range: None }
    }
    /// The same axis with the fixed range `lo..hi` (in the axis's unit).
    pub fn with_range(mut self, lo: f64, hi: f64) -> Self {
        self.range = Some((lo, hi));
        self
    }
}

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Style {
    /// A solid line.
    Line,
    /// A dashed line.
    Dashed,
    /// Filled circles at the points, no line.
    Points,
    /// A solid line with circles at the points.
    LinePoints,
    /// Crosses at the points, no line.
    Crosses,
}

/// A named set of (x, y) points. Non-finite points (and non-positive ones on log axes)
/// break the line instead of being drawn.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Legend entry; an empty name leaves the series out of the legend.
    pub name: String,
    /// The (x, y) points, in the axes' units, in drawing order.
    pub points: Vec<(f64, f64)>,
    /// How the series is drawn.
    pub style: Style,
    /// Index into [`PALETTE`]; `None`: the series' position in the chart.
    pub colour: Option<usize>,
}

impl Series {
    /// A solid-line series in the next palette colour.
    pub fn line(name: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Self { name: name.into(), points, style: Style::Line, colour: None }
    }
    /// The same series drawn with `style`.
    pub fn styled(mut self, style: Style) -> Self {
        self.style = style;
        self
    }
    /// Draw in `PALETTE[index % 10]`, e.g. to give a model curve and its data points one colour.
    pub fn coloured(mut self, index: usize) -> Self {
        self.colour = Some(index);
        self
    }
}

/// A shaded range of x (e.g. an operating range), shown in the legend.
#[derive(Debug, Clone, PartialEq)]
pub struct Band {
    /// Lower end of the range, in the x axis's unit.
    pub from: f64,
    /// Upper end of the range, in the x axis's unit.
    pub to: f64,
    /// Legend entry of the band.
    pub label: String,
}

/// Dashed vertical lines at `xs` (e.g. the ends of a range), one legend entry.
#[derive(Debug, Clone, PartialEq)]
pub struct Marker {
    /// x positions of the lines, in the x axis's unit.
    pub xs: Vec<f64>,
    /// Legend entry of the lines.
    pub label: String,
}

/// Where the legend sits.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Corner {
    /// Top left.
    UpperLeft,
    /// Top right (the default).
    UpperRight,
    /// Bottom left.
    LowerLeft,
    /// Bottom right.
    LowerRight,
}

impl Corner {
    fn position(self) -> SeriesLabelPosition {
        match self {
            Corner::UpperLeft => SeriesLabelPosition::UpperLeft,
            Corner::UpperRight => SeriesLabelPosition::UpperRight,
            Corner::LowerLeft => SeriesLabelPosition::LowerLeft,
            Corner::LowerRight => SeriesLabelPosition::LowerRight,
        }
    }
}

/// A line chart.
#[derive(Debug, Clone, PartialEq)]
pub struct Chart {
    /// Title above the chart.
    pub title: String,
    /// Horizontal axis.
    pub x: Axis,
    /// Vertical axis.
    pub y: Axis,
    /// Curves and point sets, drawn in order.
    pub series: Vec<Series>,
    /// Shaded x ranges behind the series.
    pub bands: Vec<Band>,
    /// Dashed vertical lines.
    pub markers: Vec<Marker>,
    /// Where the legend sits.
    pub legend: Corner,
}

impl Chart {
    /// An empty chart with the legend at the upper right.
    pub fn new(title: impl Into<String>, x: Axis, y: Axis) -> Self {
        Self { title: title.into(), x, y, series: Vec::new(), bands: Vec::new(), markers: Vec::new(), legend: Corner::UpperRight }
    }
    /// Adds a series.
    pub fn series(mut self, s: Series) -> Self {
        self.series.push(s);
        self
    }
    /// Adds a shaded x range `from..to` with its legend label.
    pub fn band(mut self, from: f64, to: f64, label: impl Into<String>) -> Self {
        self.bands.push(Band { from, to, label: label.into() });
        self
    }
    /// Adds dashed vertical lines at `xs` with one legend label.
    pub fn marker(mut self, xs: &[f64], label: impl Into<String>) -> Self {
        self.markers.push(Marker { xs: xs.to_vec(), label: label.into() });
        self
    }
    /// Moves the legend to `corner`.
    pub fn legend(mut self, corner: Corner) -> Self {
        self.legend = corner;
        self
    }
}

/// Distinguishable line colours (the "tab10" palette).
pub const PALETTE: [RGBColor; 10] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
    RGBColor(188, 189, 34),
    RGBColor(23, 190, 207),
];
const BAND_COLOURS: [RGBColor; 3] = [RGBColor(255, 200, 60), RGBColor(120, 200, 255), RGBColor(200, 160, 255)];

const FONT: &str = "sans-serif";

/// A short, readable tick label: `0.05`, `120`, `1e-6`, `2.5e7`.
pub fn tick_label(v: f64) -> String {
    if v == 0.0 {
        return "0".into();
    }
    crate::numbers::trimmed(v, 4, 2)
}

fn usable(scale: Scale, v: f64) -> bool {
    v.is_finite() && (scale == Scale::Linear || v > 0.0)
}

/// The plotted range of `axis` for data `values`: the fixed range, or the data's with a margin.
fn fit_range(axis: &Axis, values: impl Iterator<Item = f64>) -> (f64, f64) {
    if let Some(r) = axis.range {
        return r;
    }
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for v in values.filter(|&v| usable(axis.scale, v)) {
        lo = lo.min(v);
        hi = hi.max(v);
    }
    match axis.scale {
        Scale::Linear => {
            if lo > hi {
                return (0.0, 1.0);
            }
            if lo == hi {
                let d = if lo == 0.0 { 1.0 } else { 0.1 * lo.abs() };
                return (lo - d, hi + d);
            }
            let pad = 0.04 * (hi - lo);
            (lo - pad, hi + pad)
        }
        Scale::Log => {
            if lo > hi {
                return (1.0, 10.0);
            }
            if lo == hi {
                return (lo / 3.0, hi * 3.0);
            }
            let f = (hi / lo).powf(0.03);
            (lo / f, hi * f)
        }
    }
}

/// Tick positions on a log axis over `lo..hi`: (labelled, light grid lines).
/// 1-2-5 per decade up to 3 decades, powers of ten beyond (every n-th past 8 decades).
pub fn log_ticks(lo: f64, hi: f64) -> (Vec<f64>, Vec<f64>) {
    let (k0, k1) = (lo.log10().floor() as i32, hi.log10().ceil() as i32);
    let decades = (hi / lo).log10();
    let mantissas: &[f64] = if decades <= 1.2 {
        &[1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0]
    } else if decades <= 3.2 {
        &[1.0, 2.0, 5.0]
    } else {
        &[1.0]
    };
    let step = if decades > 8.0 { (decades / 8.0).ceil() as i32 } else { 1 };
    let inside = |v: &f64| *v >= lo * (1.0 - 1e-9) && *v <= hi * (1.0 + 1e-9);
    let mut bold = Vec::new();
    let mut light = Vec::new();
    for k in k0..=k1 {
        let p = 10f64.powi(k);
        if k.rem_euclid(step) == 0 {
            bold.extend(mantissas.iter().map(|m| m * p).filter(inside));
        }
        if decades <= 8.0 {
            light.extend((1..10).map(|m| f64::from(m) * p).filter(inside));
        }
    }
    (bold, light)
}

fn log_axis(lo: f64, hi: f64) -> plotters::coord::combinators::WithKeyPoints<plotters::coord::combinators::LogCoord<f64>> {
    let (bold, light) = log_ticks(lo, hi);
    (lo..hi).log_scale().with_key_points(bold).with_light_points(light)
}

/// Runs `$body` with `$x`/`$y` bound to plotters range specs for the given scales.
macro_rules! with_ranges {
    ($xs:expr, $xr:expr, $ys:expr, $yr:expr, |$x:ident, $y:ident| $body:expr) => {{
        let ((x0, x1), (y0, y1)) = ($xr, $yr);
        match ($xs, $ys) {
            (Scale::Linear, Scale::Linear) => {
                let ($x, $y) = (x0..x1, y0..y1);
                $body
            }
            (Scale::Log, Scale::Linear) => {
                let ($x, $y) = (log_axis(x0, x1), y0..y1);
                $body
            }
            (Scale::Linear, Scale::Log) => {
                let ($x, $y) = (x0..x1, log_axis(y0, y1));
                $body
            }
            (Scale::Log, Scale::Log) => {
                let ($x, $y) = (log_axis(x0, x1), log_axis(y0, y1));
                $body
            }
        }
    }};
}

type Area<'a> = DrawingArea<SVGBackend<'a>, Shift>;

/// An axis coordinate over `f64` whose ticks can be labelled: what every chart here is drawn on.
trait PlotAxis: AsRangedCoord<Value = f64, CoordDescType: ValueFormatter<f64>> {}
impl<T: AsRangedCoord<Value = f64, CoordDescType: ValueFormatter<f64>>> PlotAxis for T {}

/// [`tick_label`] of a value, for plotters' label formatters.
fn tick_label_of(v: &f64) -> String {
    tick_label(*v)
}

/// The axis descriptions of `x` and `y` on a mesh, with [`tick_label`] tick labels in the
/// house fonts.
fn labelled<'m, 'a, 'b, X, Y, DB>(mesh: &'m mut MeshStyle<'a, 'b, X, Y, DB>, x: &Axis, y: &Axis) -> &'m mut MeshStyle<'a, 'b, X, Y, DB>
where
    DB: DrawingBackend,
    X: Ranged<ValueType = f64> + ValueFormatter<f64>,
    Y: Ranged<ValueType = f64> + ValueFormatter<f64>,
{
    mesh.x_desc(x.label.as_str())
        .y_desc(y.label.as_str())
        .x_label_formatter(&tick_label_of)
        .y_label_formatter(&tick_label_of)
        .label_style((FONT, 13))
        .axis_desc_style((FONT, 15))
}

/// A chart drawn on an [`Area`] over the coordinates of `X` and `Y`.
type Plane<'a, 'b, X, Y> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<<X as AsRangedCoord>::CoordDescType, <Y as AsRangedCoord>::CoordDescType>>;

/// A chart with a title on `area`, in the house layout (margin, label areas).
fn titled_chart<'a, 'b, X: PlotAxis, Y: PlotAxis>(area: &'a Area<'b>, title: &str, x: X, y: Y) -> Result<Plane<'a, 'b, X, Y>, PlotError> {
    ChartBuilder::on(area)
        .caption(title, (FONT, 18))
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d(x, y)
        .map_err(err)
}

/// Render one chart to SVG.
pub fn line_plot(chart: &Chart, size: (u32, u32)) -> Result<String, PlotError> {
    let mut svg = String::new();
    let mut paths = Vec::new();
    {
        let root = SVGBackend::with_string(&mut svg, size).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        draw_chart(&root, chart, &mut paths)?;
        root.present().map_err(err)?;
    }
    substitute_paths(&svg, &paths)
}

/// Render several charts one above the other (each `size.1 / n` high), under one title.
pub fn stacked_plot(title: &str, charts: &[Chart], size: (u32, u32)) -> Result<String, PlotError> {
    let mut svg = String::new();
    let mut paths = Vec::new();
    {
        let root = SVGBackend::with_string(&mut svg, size).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let root = if title.is_empty() { root } else { root.titled(title, (FONT, 22)).map_err(err)? };
        let n = charts.len().max(1);
        for (area, chart) in root.split_evenly((n, 1)).iter().zip(charts) {
            draw_chart(area, chart, &mut paths)?;
        }
        root.present().map_err(err)?;
    }
    substitute_paths(&svg, &paths)
}

/// The text of the placeholder element that stands for sub-pixel path `k` until
/// [`substitute_paths`] replaces it.
fn path_marker(k: usize) -> String {
    format!("@@pinjoint-path-{k}@@")
}

/// plotters' SVG backend rounds every coordinate to a whole pixel, which turns a smooth curve
/// into a staircase. Lines are therefore drawn as placeholder `<text>` elements (keeping their
/// place in the drawing order, under the legend) and replaced here by `<polyline>`s with
/// sub-pixel coordinates. `paths[k]` replaces the element holding [`path_marker`]`(k)`.
fn substitute_paths(svg: &str, paths: &[String]) -> Result<String, PlotError> {
    let mut out = svg.to_string();
    for (k, path) in paths.iter().enumerate() {
        let marker = path_marker(k);
        let at = out.find(&marker).ok_or_else(|| PlotError(format!("placeholder of path {k} missing")))?;
        let start = out[..at].rfind("<text").ok_or_else(|| PlotError(format!("placeholder of path {k} is not a text element")))?;
        let end = at + out[at..].find("</text>").ok_or_else(|| PlotError(format!("placeholder of path {k} is not closed")))? + "</text>".len();
        out.replace_range(start..end, path);
    }
    Ok(out)
}

/// Where `v` falls on an axis of `scale` over `range`, as a fraction 0..1 (log axes in ln v,
/// as plotters maps them).
fn axis_fraction(scale: Scale, range: (f64, f64), v: f64) -> f64 {
    match scale {
        Scale::Linear => (v - range.0) / (range.1 - range.0),
        Scale::Log => (v.ln() - range.0.ln()) / (range.1.ln() - range.0.ln()),
    }
}

/// Pixel position of data point `p` in a plotting area with pixel ranges `px` (as
/// `DrawingArea::get_pixel_range`), without rounding: the same affine map as plotters'
/// `Cartesian2d` (x from the left edge to the right edge − 1, y from the bottom edge − 1 up to
/// the top edge), which floors the result to whole pixels.
fn subpixel(px: &(std::ops::Range<i32>, std::ops::Range<i32>), c: &Chart, xr: (f64, f64), yr: (f64, f64), p: (f64, f64)) -> (f64, f64) {
    let (x0, x1) = (f64::from(px.0.start), f64::from(px.0.end - 1));
    let (y_top, y_bottom) = (f64::from(px.1.start), f64::from(px.1.end - 1));
    let tx = axis_fraction(c.x.scale, xr, p.0);
    let ty = axis_fraction(c.y.scale, yr, p.1);
    (x0 + (x1 - x0) * tx, y_bottom + (y_top - y_bottom) * ty)
}

/// An SVG polyline through `pts` (pixels, two decimals).
fn polyline(pts: &[(f64, f64)], col: RGBColor, dashed: bool) -> String {
    let coords: Vec<String> = pts.iter().map(|&(x, y)| format!("{x:.2},{y:.2}")).collect();
    let dash = if dashed { " stroke-dasharray=\"8 5\"" } else { "" };
    format!(
        "<polyline fill=\"none\" stroke=\"#{:02X}{:02X}{:02X}\" stroke-width=\"2\" stroke-linejoin=\"round\"{dash} points=\"{}\"/>",
        col.0,
        col.1,
        col.2,
        coords.join(" ")
    )
}

fn draw_chart(area: &Area<'_>, c: &Chart, paths: &mut Vec<String>) -> Result<(), PlotError> {
    let xr = fit_range(&c.x, c.series.iter().flat_map(|s| s.points.iter().map(|p| p.0)));
    let yr = fit_range(&c.y, c.series.iter().flat_map(|s| s.points.iter().map(|p| p.1)));
    with_ranges!(c.x.scale, xr, c.y.scale, yr, |x, y| draw_chart_in(area, c, x, y, xr, yr, paths))
}

fn draw_chart_in<X: PlotAxis, Y: PlotAxis>(area: &Area<'_>, c: &Chart, x: X, y: Y, xr: (f64, f64), yr: (f64, f64), paths: &mut Vec<String>) -> Result<(), PlotError> {
    let mut ch = titled_chart(area, &c.title, x, y)?;
    labelled(&mut ch.configure_mesh(), &c.x, &c.y)
        .light_line_style(RGBColor(235, 235, 235))
        .draw()
        .map_err(err)?;

    for (i, b) in c.bands.iter().enumerate() {
        let col = BAND_COLOURS[i % BAND_COLOURS.len()];
        let (from, to) = (b.from.max(xr.0), b.to.min(xr.1));
        if from >= to || from.is_nan() || to.is_nan() {
            continue;
        }
        ch.draw_series(std::iter::once(Rectangle::new([(from, yr.0), (to, yr.1)], col.mix(0.25).filled())))
            .map_err(err)?
            .label(b.label.as_str())
            .legend(move |(px, py)| Rectangle::new([(px, py - 6), (px + 18, py + 6)], col.mix(0.5).filled()));
    }

    for m in &c.markers {
        let col = RGBColor(90, 90, 90);
        let lines: Vec<_> = m.xs.iter().filter(|&&x| x >= xr.0 && x <= xr.1).map(|&x| vec![(x, yr.0), (x, yr.1)]).collect();
        if lines.is_empty() {
            continue;
        }
        let mut ann = None;
        for l in lines {
            ann = Some(ch.draw_series(DashedLineSeries::new(l, 6, 4, col.stroke_width(2))).map_err(err)?);
        }
        if let Some(a) = ann {
            a.label(m.label.as_str()).legend(move |(px, py)| PathElement::new(vec![(px + 4, py - 6), (px + 4, py + 6)], col.stroke_width(2)));
        }
    }

    let pixels = ch.plotting_area().get_pixel_range();
    for (i, s) in c.series.iter().enumerate() {
        let col = PALETTE[s.colour.unwrap_or(i) % PALETTE.len()];
        let segments = split_segments(&s.points, c.x.scale, c.y.scale);
        let mut first = true;
        for seg in segments {
            if s.style == Style::Crosses {
                let ann = ch.draw_series(seg.iter().map(|&p| Cross::new(p, 6, col.stroke_width(2)))).map_err(err)?;
                if first && !s.name.is_empty() {
                    ann.label(s.name.as_str()).legend(move |(px, py)| Cross::new((px + 9, py), 6, col.stroke_width(2)));
                    first = false;
                }
                continue;
            }
            if matches!(s.style, Style::Points | Style::LinePoints) {
                let r = if s.style == Style::Points { 5 } else { 4 };
                let ann = ch.draw_series(seg.iter().map(|&p| Circle::new(p, r, col.filled()))).map_err(err)?;
                if s.style == Style::Points {
                    if first && !s.name.is_empty() {
                        ann.label(s.name.as_str()).legend(move |(px, py)| Circle::new((px + 9, py), 5, col.filled()));
                        first = false;
                    }
                    continue;
                }
            }
            // The line: a placeholder text element, replaced by a sub-pixel polyline afterwards.
            let dashed = s.style == Style::Dashed;
            let pts: Vec<(f64, f64)> = seg.iter().map(|&p| subpixel(&pixels, c, xr, yr, p)).collect();
            let marker = path_marker(paths.len());
            paths.push(polyline(&pts, col, dashed));
            let ann = ch.draw_series(std::iter::once(Text::new(marker, seg[0], (FONT, 1)))).map_err(err)?;
            if first && !s.name.is_empty() {
                ann.label(s.name.as_str()).legend(move |(px, py)| {
                    let end = if dashed { px + 10 } else { px + 18 };
                    PathElement::new(vec![(px, py), (end, py)], col.stroke_width(2))
                });
                first = false;
            }
        }
    }
    if c.series.iter().any(|s| !s.name.is_empty()) || !c.bands.is_empty() || !c.markers.is_empty() {
        ch.configure_series_labels()
            .position(c.legend.position())
            .background_style(WHITE.mix(0.85))
            .border_style(RGBColor(180, 180, 180))
            .label_font((FONT, 13))
            .draw()
            .map_err(err)?;
    }
    Ok(())
}

/// Split points into runs of plottable points (finite; positive on log axes).
fn split_segments(points: &[(f64, f64)], xs: Scale, ys: Scale) -> Vec<Vec<(f64, f64)>> {
    let mut out = Vec::new();
    let mut cur = Vec::new();
    for &(x, y) in points {
        if usable(xs, x) && usable(ys, y) {
            cur.push((x, y));
        } else if !cur.is_empty() {
            out.push(std::mem::take(&mut cur));
        }
    }
    if !cur.is_empty() {
        out.push(cur);
    }
    out
}

/// An outlined rectangle on a heat map (e.g. an operating region), shown in the legend.
#[derive(Debug, Clone, PartialEq)]
pub struct Region {
    /// x range (from, to), in the x axis's unit.
    pub x: (f64, f64),
    /// y range (from, to), in the y axis's unit.
    pub y: (f64, f64),
    /// Legend entry of the rectangle.
    pub label: String,
}

/// A value `z[iy][ix]` over grid centres `xs` × `ys` (both increasing).
#[derive(Debug, Clone, PartialEq)]
pub struct HeatMap {
    /// Title above the map.
    pub title: String,
    /// Horizontal axis (its range is that of `xs`).
    pub x: Axis,
    /// Grid centres along x, increasing.
    pub xs: Vec<f64>,
    /// Vertical axis (its range is that of `ys`).
    pub y: Axis,
    /// Grid centres along y, increasing.
    pub ys: Vec<f64>,
    /// The values, `z[iy][ix]`, in the unit of `z_axis`.
    pub z: Vec<Vec<f64>>,
    /// Colour-bar label (quantity and unit) and scale; a fixed range clamps the colours.
    pub z_axis: Axis,
    /// Contour levels drawn as labelled black lines.
    pub contours: Vec<f64>,
    /// Outlined rectangles drawn over the map.
    pub regions: Vec<Region>,
}

/// The viridis colour map at t ∈ [0, 1] (linear interpolation between 9 stops).
pub fn viridis(t: f64) -> RGBColor {
    const STOPS: [(u8, u8, u8); 9] = [
        (68, 1, 84),
        (71, 44, 122),
        (59, 81, 139),
        (44, 113, 142),
        (33, 144, 141),
        (39, 173, 129),
        (92, 200, 99),
        (170, 220, 50),
        (253, 231, 37),
    ];
    let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) } * (STOPS.len() - 1) as f64;
    let i = (t.floor() as usize).min(STOPS.len() - 2);
    let f = t - i as f64;
    let lerp = |a: u8, b: u8| (f64::from(a) + f * (f64::from(b) - f64::from(a))).round() as u8;
    let (a, b) = (STOPS[i], STOPS[i + 1]);
    RGBColor(lerp(a.0, b.0), lerp(a.1, b.1), lerp(a.2, b.2))
}

/// Map v to [0, 1] on `scale` over `range`.
fn normalise(v: f64, scale: Scale, (lo, hi): (f64, f64)) -> f64 {
    match scale {
        Scale::Linear => (v - lo) / (hi - lo),
        Scale::Log => (v.ln() - lo.ln()) / (hi.ln() - lo.ln()),
    }
}

/// Cell edges around increasing centres, midway on the axis scale.
fn cell_edges(c: &[f64], scale: Scale) -> Vec<f64> {
    let f = |v: f64| if scale == Scale::Log { v.ln() } else { v };
    let g = |v: f64| if scale == Scale::Log { v.exp() } else { v };
    let t: Vec<f64> = c.iter().map(|&v| f(v)).collect();
    let n = t.len();
    if n == 1 {
        let d = if scale == Scale::Log { 0.5 } else { 0.5 * t[0].abs().max(1.0) };
        return vec![g(t[0] - d), g(t[0] + d)];
    }
    let mut e = Vec::with_capacity(n + 1);
    e.push(g(t[0] - 0.5 * (t[1] - t[0])));
    for w in t.windows(2) {
        e.push(g(0.5 * (w[0] + w[1])));
    }
    e.push(g(t[n - 1] + 0.5 * (t[n - 1] - t[n - 2])));
    e
}

/// Contour segments of `z` at `level` (marching squares, interpolating on the scales' axes).
pub fn contour_segments(h: &HeatMap, level: f64) -> Vec<[(f64, f64); 2]> {
    let ax = |v: f64, s: Scale| if s == Scale::Log { v.ln() } else { v };
    let un = |v: f64, s: Scale| if s == Scale::Log { v.exp() } else { v };
    let zt = |v: f64| ax(v, h.z_axis.scale);
    let lv = zt(level);
    let mut segs = Vec::new();
    for j in 0..h.ys.len().saturating_sub(1) {
        for i in 0..h.xs.len().saturating_sub(1) {
            // Corners counter-clockwise: (i,j), (i+1,j), (i+1,j+1), (i,j+1).
            let corners = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)];
            let vals: Vec<f64> = corners.iter().map(|&(a, b)| zt(h.z[b][a])).collect();
            if vals.iter().any(|v| !v.is_finite()) {
                continue;
            }
            let mut pts = Vec::new();
            for k in 0..4 {
                let (a, b) = (k, (k + 1) % 4);
                let (va, vb) = (vals[a] - lv, vals[b] - lv);
                if (va >= 0.0) != (vb >= 0.0) {
                    let t = va / (va - vb);
                    let (ia, ja) = corners[a];
                    let (ib, jb) = corners[b];
                    let xa = ax(h.xs[ia], h.x.scale);
                    let xb = ax(h.xs[ib], h.x.scale);
                    let ya = ax(h.ys[ja], h.y.scale);
                    let yb = ax(h.ys[jb], h.y.scale);
                    pts.push((un(xa + t * (xb - xa), h.x.scale), un(ya + t * (yb - ya), h.y.scale)));
                }
            }
            for pair in pts.chunks_exact(2) {
                segs.push([pair[0], pair[1]]);
            }
        }
    }
    segs
}

/// Render a heat map with a colour bar on the right.
pub fn heat_map(h: &HeatMap, size: (u32, u32)) -> Result<String, PlotError> {
    let ny = h.ys.len();
    let nx = h.xs.len();
    if ny == 0 || nx == 0 || h.z.len() != ny || h.z.iter().any(|r| r.len() != nx) {
        return Err(PlotError(format!("heat map grid is {}x{} but z is not", ny, nx)));
    }
    let xe = cell_edges(&h.xs, h.x.scale);
    let ye = cell_edges(&h.ys, h.y.scale);
    let xr = h.x.range.unwrap_or((xe[0], xe[nx]));
    let yr = h.y.range.unwrap_or((ye[0], ye[ny]));
    let zr = fit_range(&h.z_axis, h.z.iter().flatten().copied());
    let zr = if h.z_axis.range.is_some() {
        zr
    } else {
        // The data's own range, without the line-plot margin.
        let vals = h.z.iter().flatten().copied().filter(|&v| usable(h.z_axis.scale, v));
        let (lo, hi) = vals.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(v), b.max(v)));
        if lo < hi { (lo, hi) } else { zr }
    };

    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, size).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let (main, bar) = root.split_horizontally(size.0.saturating_sub(150));
        with_ranges!(h.x.scale, xr, h.y.scale, yr, |x, y| draw_heat_in(&main, h, x, y, &xe, &ye, zr))?;
        with_ranges!(Scale::Linear, (0.0, 1.0), h.z_axis.scale, zr, |x, y| draw_colour_bar(&bar, h, x, y, zr))?;
        root.present().map_err(err)?;
    }
    Ok(svg)
}

#[allow(clippy::too_many_arguments)]
fn draw_heat_in<X: PlotAxis, Y: PlotAxis>(area: &Area<'_>, h: &HeatMap, x: X, y: Y, xe: &[f64], ye: &[f64], zr: (f64, f64)) -> Result<(), PlotError> {
    let mut ch = titled_chart(area, &h.title, x, y)?;
    let mut cells = Vec::with_capacity(h.xs.len() * h.ys.len());
    for (j, row) in h.z.iter().enumerate() {
        for (i, &v) in row.iter().enumerate() {
            let col = if usable(h.z_axis.scale, v) { viridis(normalise(v, h.z_axis.scale, zr)) } else { RGBColor(255, 255, 255) };
            cells.push(Rectangle::new([(xe[i], ye[j]), (xe[i + 1], ye[j + 1])], col.filled()));
        }
    }
    ch.draw_series(cells).map_err(err)?;
    labelled(&mut ch.configure_mesh(), &h.x, &h.y)
        .disable_mesh()
        .draw()
        .map_err(err)?;

    // Labels at staggered heights so that converging contours keep readable labels.
    const LABEL_HEIGHTS: [f64; 6] = [0.8, 0.55, 0.3, 0.67, 0.42, 0.18];
    for (k, &level) in h.contours.iter().enumerate() {
        let segs = contour_segments(h, level);
        if segs.is_empty() {
            continue;
        }
        ch.draw_series(segs.iter().map(|s| PathElement::new(s.to_vec(), BLACK.stroke_width(1)))).map_err(err)?;
        let target = |s: &[(f64, f64); 2]| {
            let ym = 0.5 * (s[0].1 + s[1].1);
            (normalise(ym, h.y.scale, (ye[0], ye[ye.len() - 1])) - LABEL_HEIGHTS[k % LABEL_HEIGHTS.len()]).abs()
        };
        if let Some(s) = segs.iter().min_by(|a, b| target(a).total_cmp(&target(b))) {
            let p = (0.5 * (s[0].0 + s[1].0), 0.5 * (s[0].1 + s[1].1));
            boxed_text(&ch, p, &tick_label(level), true)?;
        }
    }
    let region_colour = RGBColor(230, 30, 60);
    for r in &h.regions {
        let corners = vec![(r.x.0, r.y.0), (r.x.1, r.y.0), (r.x.1, r.y.1), (r.x.0, r.y.1), (r.x.0, r.y.0)];
        ch.draw_series(std::iter::once(PathElement::new(corners, region_colour.stroke_width(3)))).map_err(err)?;
        boxed_text(&ch, (r.x.0, r.y.1), &r.label, false)?;
    }
    Ok(())
}

/// Text on a translucent white box at data point `at`: centred on it, or just below-right
/// of it (inside a region's top-left corner).
fn boxed_text<X, Y>(ch: &ChartContext<'_, SVGBackend<'_>, Cartesian2d<X, Y>>, at: (f64, f64), text: &str, centred: bool) -> Result<(), PlotError>
where
    X: Ranged<ValueType = f64>,
    Y: Ranged<ValueType = f64>,
{
    let area = ch.plotting_area().strip_coord_spec();
    let (bx, by) = area.get_base_pixel();
    let (px, py) = ch.backend_coord(&at);
    let style = TextStyle::from((FONT, 13).into_font()).color(&BLACK);
    let (w, th) = area.estimate_text_size(text, &style).map_err(err)?;
    let (w, th) = (w as i32, th as i32);
    let (x, y) = if centred { (px - bx - w / 2, py - by - th / 2) } else { (px - bx + 8, py - by + 8) };
    area.draw(&Rectangle::new([(x - 3, y - 2), (x + w + 3, y + th + 2)], WHITE.mix(0.8).filled())).map_err(err)?;
    area.draw(&Text::new(text.to_string(), (x, y), style)).map_err(err)?;
    Ok(())
}

/// Tick mark length on the colour bar (px); labels sit twice as far from the bar.
const COLOUR_BAR_TICK: i32 = 5;

fn draw_colour_bar<X: PlotAxis, Y: PlotAxis>(area: &Area<'_>, h: &HeatMap, x: X, y: Y, zr: (f64, f64)) -> Result<(), PlotError> {
    let mut ch = ChartBuilder::on(area)
        .margin_top(42)
        .margin_bottom(57)
        .margin_right(40)
        .y_label_area_size(85)
        .build_cartesian_2d(x, y)
        .map_err(err)?;
    const STEPS: usize = 128;
    let at = |t: f64| match h.z_axis.scale {
        Scale::Linear => zr.0 + t * (zr.1 - zr.0),
        Scale::Log => (zr.0.ln() + t * (zr.1.ln() - zr.0.ln())).exp(),
    };
    ch.draw_series((0..STEPS).map(|k| {
        let (t0, t1) = (k as f64 / STEPS as f64, (k + 1) as f64 / STEPS as f64);
        Rectangle::new([(0.0, at(t0)), (1.0, at(t1))], viridis(0.5 * (t0 + t1)).filled())
    }))
    .map_err(err)?;
    // The bar's plotting area is only ~25 px wide, and plotters' default tick mark is 5 % of
    // it (1 px) with the labels 2 px from the axis: a label's last glyph then merges with the
    // axis line ("0.11" reads "0.1|"). Fixed-size ticks keep the labels clear of the bar.
    ch.configure_mesh()
        .disable_mesh()
        .disable_x_axis()
        .set_all_tick_mark_size(COLOUR_BAR_TICK)
        .y_desc(h.z_axis.label.as_str())
        .y_label_formatter(&|v| tick_label(*v))
        .label_style((FONT, 13))
        .axis_desc_style((FONT, 15))
        .draw()
        .map_err(err)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tick_labels_are_short_and_exact_enough() {
        assert_eq!(tick_label(0.0), "0");
        assert_eq!(tick_label(0.05), "0.05");
        assert_eq!(tick_label(120.0), "120");
        assert_eq!(tick_label(1e-6), "1e-6");
        assert_eq!(tick_label(2.5e7), "2.5e7");
        assert_eq!(tick_label(-0.125), "-0.125");
    }

    #[test]
    fn line_plot_has_labels_title_and_legend_text() {
        let c = Chart::new("T-title", Axis::log("S [-]"), Axis::linear("mu [-]"))
            .series(Series::line("first-series", vec![(1e-3, 0.1), (1e-1, 0.05), (1.0, 0.01)]))
            .series(Series::line("second", vec![(1e-3, 0.2), (f64::NAN, 0.0), (1.0, 0.3)]).styled(Style::Dashed))
            .band(1e-2, 1e-1, "band-label");
        let svg = line_plot(&c, (640, 480)).unwrap();
        for text in ["T-title", "S [-]", "mu [-]", "first-series", "second", "band-label", "<polyline"] {
            assert!(svg.contains(text), "missing {text}");
        }
    }

    /// (x, y) pairs of an SVG attribute list "x,y x,y ...".
    fn pairs(text: &str) -> Vec<(f64, f64)> {
        text.split_whitespace()
            .map(|xy| {
                let (a, b) = xy.split_once(',').unwrap();
                (a.parse().unwrap(), b.parse().unwrap())
            })
            .collect()
    }

    #[test]
    fn lines_have_sub_pixel_coordinates_on_plotters_own_map() {
        // The same points as a line (our sub-pixel polyline) and as dots (plotters' circles,
        // rounded to whole pixels): every vertex lies within a pixel of its dot, and the line is
        // not rounded (a gentle slope over 400 px would otherwise step one pixel at a time).
        for (xs, ys) in [(Scale::Linear, Scale::Linear), (Scale::Log, Scale::Linear), (Scale::Linear, Scale::Log)] {
            let pts: Vec<(f64, f64)> = (1..=60).map(|k| (f64::from(k), 10.0 + 0.05 * f64::from(k))).collect();
            let axis = |s: Scale, name: &str| if s == Scale::Log { Axis::log(name) } else { Axis::linear(name) };
            let c = Chart::new("", axis(xs, "x"), axis(ys, "y"))
                .series(Series::line("line", pts.clone()))
                .series(Series::line("", pts.clone()).styled(Style::Points));
            let svg = line_plot(&c, (640, 480)).unwrap();
            assert!(!svg.contains("@@pinjoint-path"), "a placeholder was left in");
            let lines: Vec<&str> = svg.split("<polyline").skip(1).filter(|p| p.contains("stroke-linejoin=\"round\"")).collect();
            assert_eq!(lines.len(), 1, "{xs:?} {ys:?}");
            let line = pairs(lines[0].split("points=\"").nth(1).unwrap().split('"').next().unwrap());
            let attr = |tag: &str, name: &str| -> f64 { tag.split(&format!("{name}=\"")).nth(1).unwrap().split('"').next().unwrap().parse().unwrap() };
            let dots: Vec<(f64, f64)> = svg.split("<circle").skip(1).map(|t| (attr(t, "cx"), attr(t, "cy"))).collect();
            assert_eq!(line.len(), pts.len());
            assert_eq!(dots.len(), pts.len());
            for (l, d) in line.iter().zip(&dots) {
                assert!((l.0 - d.0).abs() <= 1.0 && (l.1 - d.1).abs() <= 1.0, "{xs:?} {ys:?}: {l:?} vs {d:?}");
            }
            let fractional = line.iter().filter(|p| p.1.fract() != 0.0).count();
            assert!(fractional > line.len() / 2, "{xs:?} {ys:?}: {line:?}");
        }
    }

    #[test]
    fn log_axes_drop_non_positive_points() {
        let segs = split_segments(&[(1.0, 1.0), (2.0, 0.0), (3.0, 2.0), (4.0, 3.0)], Scale::Linear, Scale::Log);
        assert_eq!(segs, vec![vec![(1.0, 1.0)], vec![(3.0, 2.0), (4.0, 3.0)]]);
    }

    #[test]
    fn log_cell_edges_are_geometric_midpoints() {
        let e = cell_edges(&[1.0, 100.0], Scale::Log);
        assert!((e[0] - 0.1).abs() < 1e-12 && (e[1] - 10.0).abs() < 1e-9 && (e[2] - 1000.0).abs() < 1e-9, "{e:?}");
        assert_eq!(cell_edges(&[0.0, 2.0, 4.0], Scale::Linear), vec![-1.0, 1.0, 3.0, 5.0]);
    }

    #[test]
    fn contour_of_a_plane_is_where_the_plane_crosses_the_level() {
        // z = x + y on a 3x3 grid; the level 2 passes through (0,2), (1,1), (2,0).
        let xs = vec![0.0, 1.0, 2.0];
        let h = HeatMap {
            title: String::new(),
            x: Axis::linear("x"),
            y: Axis::linear("y"),
            xs: xs.clone(),
            ys: xs.clone(),
            z: xs.iter().map(|&y| xs.iter().map(|&x| x + y + 1e-9).collect()).collect(),
            z_axis: Axis::linear("z"),
            contours: vec![2.0],
            regions: vec![],
        };
        let segs = contour_segments(&h, 2.0);
        assert!(!segs.is_empty());
        for s in &segs {
            for p in s {
                assert!((p.0 + p.1 - 2.0).abs() < 1e-6, "{p:?}");
            }
        }
        let svg = heat_map(&h, (600, 400)).unwrap();
        assert!(svg.replace('\n', "").contains(">2</text>"), "contour label missing");
    }

    /// (x, anchor, font size, text) of every horizontal `<text>` element of an SVG from plotters.
    fn texts(svg: &str) -> Vec<(f64, String, f64, String)> {
        let attr = |tag: &str, name: &str| -> String {
            let key = format!("{name}=\"");
            let i = tag.find(&key).map(|i| i + key.len()).unwrap_or(0);
            tag[i..].split('"').next().unwrap_or("").to_string()
        };
        svg.split("<text ")
            .skip(1)
            .filter_map(|t| {
                let (tag, rest) = t.split_once('>').unwrap();
                if tag.contains("rotate(") {
                    return None;
                }
                let body = rest.split("</text>").next().unwrap().trim().to_string();
                Some((attr(tag, "x").parse().unwrap(), attr(tag, "text-anchor"), attr(tag, "font-size").parse().unwrap(), body))
            })
            .collect()
    }

    #[test]
    fn colour_bar_labels_stand_clear_of_the_bar_and_inside_the_image() {
        let xs: Vec<f64> = (0..20).map(|i| 1.0 + f64::from(i)).collect();
        let ys: Vec<f64> = (0..10).map(|j| 5.0 + 6.0 * f64::from(j)).collect();
        let h = HeatMap {
            title: "mu".into(),
            x: Axis::log("speed [rpm]"),
            y: Axis::linear("load [kN]"),
            xs: xs.clone(),
            ys: ys.clone(),
            z: ys.iter().map(|_| xs.iter().map(|&x| 0.12 - 0.005 * x).collect()).collect(),
            z_axis: Axis::linear("μ [-]"),
            contours: vec![],
            regions: vec![],
        };
        let width = 960.0;
        let svg = heat_map(&h, (960, 640)).unwrap();
        // The colour bar's vertical axis line: the right-most vertical polyline.
        let axis_x = svg
            .split("points=\"")
            .skip(1)
            .filter_map(|p| {
                let pts: Vec<(f64, f64)> = p.split('"').next()?.split_whitespace().filter_map(|xy| {
                    let (a, b) = xy.split_once(',')?;
                    Some((a.parse().ok()?, b.parse().ok()?))
                }).collect();
                (pts.len() == 2 && pts[0].0 == pts[1].0 && (pts[0].1 - pts[1].1).abs() > 300.0).then_some(pts[0].0)
            })
            .fold(f64::NEG_INFINITY, f64::max);
        assert!(axis_x > width - 150.0, "{axis_x}");
        let labels: Vec<_> = texts(&svg).into_iter().filter(|t| t.0 > width - 150.0 && t.1 == "end").collect();
        assert!(labels.iter().any(|t| t.3 == "0.11"), "{labels:?}");
        for (x, _, size, text) in &labels {
            // A generous width estimate for digits in a sans-serif font: 0.6 em each.
            let left = x - 0.6 * size * text.chars().count() as f64;
            assert!(axis_x - x >= 8.0, "label {text} ends {} px from the bar", axis_x - x);
            assert!(left > width - 150.0 && *x < width, "label {text} spans {left}..{x}");
        }
        for (x, anchor, size, text) in texts(&svg) {
            let w = 0.6 * size * text.chars().count() as f64;
            let (lo, hi) = match anchor.as_str() {
                "end" => (x - w, x),
                "middle" => (x - w / 2.0, x + w / 2.0),
                _ => (x, x + w),
            };
            assert!(lo >= 0.0 && hi <= width, "{text} spans {lo}..{hi}");
        }
    }

    #[test]
    fn log_ticks_label_every_decade_or_1_2_5() {
        let (bold, _) = log_ticks(2.0, 62.0);
        assert_eq!(bold, vec![2.0, 5.0, 10.0, 20.0, 50.0]);
        let (bold, light) = log_ticks(4e-6, 0.4);
        assert_eq!(bold, vec![1e-5, 1e-4, 1e-3, 1e-2, 0.1]);
        assert!(light.contains(&4e-6) && light.contains(&0.4) && light.len() > 30);
    }

    #[test]
    fn viridis_ends() {
        assert_eq!(viridis(0.0), RGBColor(68, 1, 84));
        assert_eq!(viridis(1.0), RGBColor(253, 231, 37));
        assert_eq!(viridis(2.0), viridis(1.0));
    }
}
