//! The SVG of a [`Picture`](crate::Picture) description, drawn with
//! `plotters`: the title (none when it is empty: the caption of a paper
//! says it), the chart, and the legend below the chart (never over the
//! data); text in a serif font (its formulas in Unicode, indices as
//! subscripts), negative numbers with a real minus sign.
//!
//! `plotters` writes whole-pixel coordinates, so everything is drawn at
//! [`SCALE`] times the layout (fonts, strokes, margins scaled with it) and
//! the root element is then given the paper size in millimetres with the
//! drawn size as its `viewBox`: coordinates are exact to 1/[`SCALE`] of a
//! layout unit (0.02 mm).

use plotters::coord::Shift;
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use crate::chart::{Frame, Look, Mark, Series};
use crate::error::{PlotError, Result, draw};
use crate::style::{
    CELL_OVERLAP, CHART_HEIGHT, FONT_FAMILY, FONT_LABEL, FONT_LEGEND, FONT_TICK, FONT_TITLE,
    MARGIN, PLOT_AREA, SVG_LEGEND_TWO_COLUMNS, THIN, TITLE_HEIGHT, UNIT_MM, WIDTH, X_LABEL_AREA,
    Y_LABEL_AREA, legend_columns,
};
use trig_tex::unicode;

/// Drawn pixels per layout unit.
pub const SCALE: u32 = 10;

/// Height of one legend row, in units.
const LEGEND_ROW: u32 = 22;

/// Width of a legend swatch, in units.
const SWATCH: u32 = 34;

/// A length in layout units as drawn pixels.
fn px(units: f64) -> u32 {
    (units * f64::from(SCALE)).round() as u32
}

/// A font of `size` units as `plotters` wants it (it writes `size / 1.24`).
fn font(size: f64) -> TextStyle<'static> {
    TextStyle::from((FONT_FAMILY, f64::from(px(size)) * 1.24).into_font())
}

fn colour(look: &Look) -> RGBAColor {
    RGBColor(look.rgb.0, look.rgb.1, look.rgb.2).mix(look.opacity)
}

/// Draws `frame` and `series`; returns the SVG text.
pub fn render(frame: &Frame, series: &[Series]) -> Result<String> {
    // the marked text in Unicode (`⟪b0⟫` → `b₀`)
    let entries: Vec<(String, &Look)> = series
        .iter()
        .filter_map(|s| s.legend.as_deref().map(|t| (unicode(t), &s.look)))
        .collect();
    let columns = legend_columns(
        entries.iter().map(|(t, _)| t.as_str()),
        SVG_LEGEND_TWO_COLUMNS,
    );
    let frame = &Frame {
        title: unicode(&frame.title),
        x_label: unicode(&frame.x_label),
        y_label: unicode(&frame.y_label),
        ..frame.clone()
    };
    let rows = entries.len().div_ceil(columns);
    let legend_height = if rows == 0 {
        0
    } else {
        rows as u32 * LEGEND_ROW + MARGIN
    };
    // no title: no band for it
    let title_height = if frame.title.is_empty() {
        0
    } else {
        TITLE_HEIGHT
    };
    let height = CHART_HEIGHT - TITLE_HEIGHT + title_height + legend_height;
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (px(WIDTH.into()), px(height.into())))
            .into_drawing_area();
        root.fill(&WHITE).map_err(draw)?;
        let (top, rest) = root.split_vertically(px(title_height.into()));
        let (chart_area, legend_area) =
            rest.split_vertically(px(f64::from(CHART_HEIGHT - TITLE_HEIGHT)));
        if title_height > 0 {
            top.draw(&Text::new(
                frame.title.as_str(),
                (px(f64::from(WIDTH) / 2.0) as i32, px(10.0) as i32),
                font(FONT_TITLE).pos(Pos::new(HPos::Center, VPos::Top)),
            ))
            .map_err(draw)?;
        }
        chart(&chart_area, frame, series)?;
        legend(&legend_area, &entries, columns)?;
        root.present().map_err(draw)?;
    }
    paper_size(&svg, height)
}

/// The axes, the line `y = 0` if asked, and the series.
fn chart(
    area: &DrawingArea<SVGBackend<'_>, Shift>,
    frame: &Frame,
    series: &[Series],
) -> Result<()> {
    let mut chart = ChartBuilder::on(area)
        .margin(px(MARGIN.into()))
        .x_label_area_size(px(X_LABEL_AREA.into()))
        .y_label_area_size(px(Y_LABEL_AREA.into()))
        .build_cartesian_2d(frame.x.0..frame.x.1, frame.y.0..frame.y.1)
        .map_err(draw)?;
    chart
        .configure_mesh()
        .x_desc(frame.x_label.as_str())
        .y_desc(frame.y_label.as_str())
        .x_labels(8)
        .y_labels(8)
        .x_label_formatter(&|v| tick(*v))
        .y_label_formatter(&|v| tick(*v))
        .max_light_lines(0)
        .bold_line_style(BLACK.mix(0.12).stroke_width(px(THIN)))
        .axis_style(BLACK.stroke_width(px(THIN)))
        .set_all_tick_mark_size(px(4.0))
        .label_style(font(FONT_TICK))
        .axis_desc_style(font(FONT_LABEL))
        .draw()
        .map_err(draw)?;
    if frame.zero_line && frame.y.0 < 0.0 && frame.y.1 > 0.0 {
        chart
            .draw_series(LineSeries::new(
                [(frame.x.0, 0.0), (frame.x.1, 0.0)],
                BLACK.stroke_width(px(THIN)),
            ))
            .map_err(draw)?;
    }
    for s in series {
        let c = colour(&s.look);
        let points = s.points.iter().copied();
        match s.look.mark {
            Mark::Line {
                width,
                dash,
                vertices,
            } => {
                let style = c.stroke_width(px(width));
                if let Some(d) = dash {
                    chart
                        .draw_series(DashedLineSeries::new(points, px(d.on), px(d.off), style))
                        .map_err(draw)?;
                } else {
                    chart
                        .draw_series(LineSeries::new(points, style))
                        .map_err(draw)?;
                }
                if vertices {
                    chart
                        .draw_series(
                            s.points
                                .iter()
                                .map(|&p| Circle::new(p, px(3.0), c.filled())),
                        )
                        .map_err(draw)?;
                }
            }
            Mark::Dots { radius } => {
                chart
                    .draw_series(
                        s.points
                            .iter()
                            .map(|&p| Circle::new(p, px(radius), c.filled())),
                    )
                    .map_err(draw)?;
            }
            Mark::Crosses => {
                chart
                    .draw_series(
                        s.points
                            .iter()
                            .map(|&p| Cross::new(p, px(5.0), c.stroke_width(px(1.6)))),
                    )
                    .map_err(draw)?;
            }
            Mark::Cell => {
                let [a, b] = s.points[..] else {
                    return Err(PlotError::Input(format!(
                        "the cell `{}` needs two corners",
                        s.label
                    )));
                };
                // a hair beyond its edges: no seam between neighbours
                let (hx, hy) = (
                    CELL_OVERLAP * (frame.x.1 - frame.x.0) / PLOT_AREA.0,
                    CELL_OVERLAP * (frame.y.1 - frame.y.0) / PLOT_AREA.1,
                );
                let corners = [(a.0 - hx, a.1 - hy), (b.0 + hx, b.1 + hy)];
                chart
                    .draw_series(std::iter::once(Rectangle::new(corners, c.filled())))
                    .map_err(draw)?;
            }
        }
    }
    Ok(())
}

/// A tick label: the shortest decimal of `v` (as `plotters` writes it),
/// with a real minus sign.
fn tick(v: f64) -> String {
    let text = format!("{v:.prec$}", prec = decimals(v));
    text.replace('-', "−")
}

/// Decimals enough for a tick value (at most 6, none trailing).
fn decimals(v: f64) -> usize {
    (0..=6)
        .find(|&d| {
            let scale = 10f64.powi(d as i32);
            ((v * scale).round() - v * scale).abs() < 1e-6 * scale.max(1.0)
        })
        .unwrap_or(6)
}

/// The legend below the chart: `columns` columns, swatch and text.
fn legend(
    area: &DrawingArea<SVGBackend<'_>, Shift>,
    entries: &[(String, &Look)],
    columns: usize,
) -> Result<()> {
    let left = MARGIN + Y_LABEL_AREA;
    let column_width = (WIDTH - left - MARGIN) / columns as u32;
    let rows = entries.len().div_ceil(columns);
    for (k, (text, look)) in entries.iter().enumerate() {
        // column-major, as a reader reads a list
        let (col, row) = (k / rows, k % rows);
        let x = f64::from(left + col as u32 * column_width);
        let y = f64::from(row as u32 * LEGEND_ROW + LEGEND_ROW / 2);
        let c = colour(look);
        let at = |dx: f64, dy: f64| (px(x + dx) as i32, px(y + dy) as i32);
        match look.mark {
            Mark::Line {
                width,
                dash,
                vertices,
            } => {
                let style = c.stroke_width(px(width));
                let swatch = if let Some(d) = dash {
                    area.draw(&DashedPathElement::new(
                        [at(0.0, 0.0), at(f64::from(SWATCH) - 4.0, 0.0)],
                        px(d.on),
                        px(d.off),
                        style,
                    ))
                } else {
                    area.draw(&PathElement::new(
                        [at(0.0, 0.0), at(f64::from(SWATCH) - 4.0, 0.0)],
                        style,
                    ))
                };
                swatch.map_err(draw)?;
                if vertices {
                    area.draw(&Circle::new(at(15.0, 0.0), px(3.0), c.filled()))
                        .map_err(draw)?;
                }
            }
            Mark::Dots { radius } => area
                .draw(&Circle::new(at(15.0, 0.0), px(radius.max(2.5)), c.filled()))
                .map_err(draw)?,
            Mark::Crosses => area
                .draw(&Cross::new(at(15.0, 0.0), px(5.0), c.stroke_width(px(1.6))))
                .map_err(draw)?,
            Mark::Cell => area
                .draw(&Rectangle::new(
                    [at(4.0, -6.0), at(f64::from(SWATCH) - 8.0, 6.0)],
                    c.filled(),
                ))
                .map_err(draw)?,
        }
        area.draw(&Text::new(
            text.as_str(),
            at(f64::from(SWATCH), 0.0),
            font(FONT_LEGEND).pos(Pos::new(HPos::Left, VPos::Center)),
        ))
        .map_err(draw)?;
    }
    Ok(())
}

/// The root element with the paper size in millimetres and the drawn size
/// as its `viewBox`.
fn paper_size(svg: &str, height: u32) -> Result<String> {
    let drawn = format!(
        r#"<svg width="{}" height="{}" "#,
        px(WIDTH.into()),
        px(height.into())
    );
    let Some(rest) = svg.strip_prefix(&drawn) else {
        return Err(PlotError::Draw(format!(
            "unexpected SVG root element: {}",
            svg.lines().next().unwrap_or("")
        )));
    };
    let mm = |units: u32| f64::from(units) * UNIT_MM;
    Ok(format!(
        r#"<svg width="{}mm" height="{}mm" {rest}"#,
        mm(WIDTH),
        mm(height)
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tick_labels_have_a_real_minus_sign_and_few_decimals() {
        assert_eq!(tick(-0.2), "−0.2");
        assert_eq!(tick(1.0), "1");
        assert_eq!(tick(-150.0), "−150");
        assert_eq!(tick(0.125), "0.125");
    }
}
