//! Axes: scale, label and range ([`Axis`]), ticks ([`tick_label`], [`log_ticks`]), the range a
//! chart is drawn over, and the titled chart frame that line charts and heat maps share.

use crate::error::{err, PlotError};
use plotters::chart::MeshStyle;
use plotters::coord::ranged1d::{AsRangedCoord, ValueFormatter};
use plotters::coord::Shift;
use plotters::prelude::*;

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


/// The font family of every text.
pub(crate) const FONT: &str = "sans-serif";

/// A short, readable tick label: `0.05`, `120`, `1e-6`, `2.5e7`.
pub fn tick_label(v: f64) -> String {
    if v == 0.0 {
        return "0".into();
    }
    numfmt::trimmed(v, 4, 2)
}

pub(crate) fn usable(scale: Scale, v: f64) -> bool {
    v.is_finite() && (scale == Scale::Linear || v > 0.0)
}

/// The plotted range of `axis` for data `values`: the fixed range, or the data's with a margin.
pub(crate) fn fit_range(axis: &Axis, values: impl Iterator<Item = f64>) -> (f64, f64) {
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

pub(crate) fn log_axis(lo: f64, hi: f64) -> plotters::coord::combinators::WithKeyPoints<plotters::coord::combinators::LogCoord<f64>> {
    let (bold, light) = log_ticks(lo, hi);
    (lo..hi).log_scale().with_key_points(bold).with_light_points(light)
}

/// Runs `$body` with `$x`/`$y` bound to plotters range specs for the given scales.
macro_rules! with_ranges {
    ($xs:expr, $xr:expr, $ys:expr, $yr:expr, |$x:ident, $y:ident| $body:expr) => {{
        let ((x0, x1), (y0, y1)) = ($xr, $yr);
        match ($xs, $ys) {
            ($crate::axis::Scale::Linear, Scale::Linear) => {
                let ($x, $y) = (x0..x1, y0..y1);
                $body
            }
            ($crate::axis::Scale::Log, Scale::Linear) => {
                let ($x, $y) = ($crate::axis::log_axis(x0, x1), y0..y1);
                $body
            }
            ($crate::axis::Scale::Linear, Scale::Log) => {
                let ($x, $y) = (x0..x1, $crate::axis::log_axis(y0, y1));
                $body
            }
            ($crate::axis::Scale::Log, Scale::Log) => {
                let ($x, $y) = ($crate::axis::log_axis(x0, x1), $crate::axis::log_axis(y0, y1));
                $body
            }
        }
    }};
}

pub(crate) use with_ranges;

pub(crate) type Area<'a> = DrawingArea<SVGBackend<'a>, Shift>;

/// An axis coordinate over `f64` whose ticks can be labelled: what every chart here is drawn on.
pub(crate) trait PlotAxis: AsRangedCoord<Value = f64, CoordDescType: ValueFormatter<f64>> {}
impl<T: AsRangedCoord<Value = f64, CoordDescType: ValueFormatter<f64>>> PlotAxis for T {}

/// [`tick_label`] of a value, for plotters' label formatters.
pub(crate) fn tick_label_of(v: &f64) -> String {
    tick_label(*v)
}

/// The axis descriptions of `x` and `y` on a mesh, with [`tick_label`] tick labels in the
/// house fonts.
pub(crate) fn labelled<'m, 'a, 'b, X, Y, DB>(mesh: &'m mut MeshStyle<'a, 'b, X, Y, DB>, x: &Axis, y: &Axis) -> &'m mut MeshStyle<'a, 'b, X, Y, DB>
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
pub(crate) type Plane<'a, 'b, X, Y> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<<X as AsRangedCoord>::CoordDescType, <Y as AsRangedCoord>::CoordDescType>>;

/// A chart with a title on `area`, in the house layout (margin, label areas).
pub(crate) fn titled_chart<'a, 'b, X: PlotAxis, Y: PlotAxis>(area: &'a Area<'b>, title: &str, x: X, y: Y) -> Result<Plane<'a, 'b, X, Y>, PlotError> {
    ChartBuilder::on(area)
        .caption(title, (FONT, 18))
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d(x, y)
        .map_err(err)
}


/// Where `v` falls on an axis of `scale` over `range`, as a fraction 0..1 (log axes in ln v,
/// as plotters maps them).
pub(crate) fn axis_fraction(scale: Scale, range: (f64, f64), v: f64) -> f64 {
    match scale {
        Scale::Linear => (v - range.0) / (range.1 - range.0),
        Scale::Log => (v.ln() - range.0.ln()) / (range.1.ln() - range.0.ln()),
    }
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
    fn log_ticks_label_every_decade_or_1_2_5() {
        let (bold, _) = log_ticks(2.0, 62.0);
        assert_eq!(bold, vec![2.0, 5.0, 10.0, 20.0, 50.0]);
        let (bold, light) = log_ticks(4e-6, 0.4);
        assert_eq!(bold, vec![1e-5, 1e-4, 1e-3, 1e-2, 0.1]);
        assert!(light.contains(&4e-6) && light.contains(&0.4) && light.len() > 30);
    }
}
