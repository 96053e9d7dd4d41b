//! Heat maps: a value over a grid of (x, y) ([`HeatMap`]) in the viridis colours, with a
//! colour bar, labelled contour lines and outlined rectangles ([`Region`]).

use crate::axis::{fit_range, labelled, tick_label, titled_chart, usable, with_ranges, Area, Axis, PlotAxis, Scale, FONT};
use crate::error::{err, PlotError};
use plotters::prelude::*;

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
    fn viridis_ends() {
        assert_eq!(viridis(0.0), RGBColor(68, 1, 84));
        assert_eq!(viridis(1.0), RGBColor(253, 231, 37));
        assert_eq!(viridis(2.0), viridis(1.0));
    }
}
