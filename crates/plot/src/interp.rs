//! Piecewise interpolants `y = P(x)` with their data points (thesis 4.3:
//! positivity-preserving interpolation, Figures 4.x). The caller supplies the
//! sampled pieces (crate `trig-interp` builds them), so this picture knows
//! nothing of the schemes.

use crate::chart::{Frame, Look, Mark, Series};
use crate::error::{PlotError, Result};
use crate::picture::Picture;
use crate::style::{BLACK, CURVE, colour, dash, padded};

/// One interpolant: its legend label and its pieces, each a sampled polyline.
#[derive(Debug, Clone, PartialEq)]
pub struct Interpolant {
    pub label: String,
    pub pieces: Vec<Vec<(f64, f64)>>,
}

/// `interpolants` over `data`, with the line `y = 0` (positivity is
/// the point of thesis 4.3). Series: one curve per piece per interpolant,
/// the data points; interpolants with the same pieces are drawn once,
/// labelled `A = B`; the first solid, the others dashed, each its own
/// pattern (so that one over another stays visible).
pub fn interp_svg(
    title: &str,
    data: &[(f64, f64)],
    interpolants: &[Interpolant],
) -> Result<Picture> {
    let all = || {
        data.iter()
            .chain(interpolants.iter().flat_map(|i| i.pieces.iter().flatten()))
    };
    if data.is_empty() || all().any(|(x, y)| !x.is_finite() || !y.is_finite()) {
        return Err(PlotError::Input(
            "interpolant plots need finite data and curves".into(),
        ));
    }
    let x = padded(all().map(|p| p.0), 0.03);
    let y = padded(all().map(|p| p.1).chain([0.0]), 0.08);
    // interpolants with the same pieces are drawn once, with every label
    let mut drawn: Vec<(Vec<&str>, &Interpolant)> = Vec::new();
    for i in interpolants {
        match drawn.iter_mut().find(|(_, d)| d.pieces == i.pieces) {
            Some((labels, _)) => labels.push(&i.label),
            None => drawn.push((vec![&i.label], i)),
        }
    }
    let mut series = Vec::new();
    for (k, (labels, i)) in drawn.into_iter().enumerate() {
        let label = labels.join(" = ");
        for (j, piece) in i.pieces.iter().enumerate() {
            let s = Series::new(
                format!("{label}, piece {}", j + 1),
                piece.iter().copied(),
                Look::line(colour(k), CURVE).dashed(dash(k)),
            );
            series.push(if j == 0 { s.legend(label.clone()) } else { s });
        }
    }
    series.push(
        Series::new(
            "data points",
            data.iter().copied(),
            Look::marks(BLACK, Mark::Dots { radius: 3.0 }),
        )
        .legend("data points"),
    );
    let frame = Frame {
        title: title.into(),
        x_label: "x".into(),
        y_label: "y = P(x)".into(),
        caption: String::new(),
        x,
        y,
        zero_line: true,
        equal_aspect: false,
    };
    Picture::new(frame, series)
}
