//! Line charts: series of (x, y) points on linear or log axes ([`Chart`], [`Series`]), shaded
//! x-ranges ([`Band`]) and vertical markers ([`Marker`]), drawn alone ([`line_plot`]) or
//! stacked ([`stacked_plot`]), with sub-pixel lines.

use crate::axis::{axis_fraction, fit_range, labelled, titled_chart, usable, with_ranges, Area, Axis, PlotAxis, Scale, FONT};
use crate::error::{err, PlotError};
use plotters::prelude::*;

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


#[cfg(test)]
mod tests {
    use super::*;

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
}
