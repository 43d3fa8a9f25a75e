//! The pictures are well-formed SVG (XML) with the expected number of data
//! series, axis labels and legends.

use std::sync::Arc;

use std::path::PathBuf;

use rug::Rational;
use trig_core::Family;
use trig_fit::{Continuity, CornerRule, Corners, FitOptions, Outline, Shape, fit_outline};
use trig_plot::{Interpolant, Plotted, basis_svg, curve_svg, fit_svg, interp_svg};

/// Parses `svg` and returns (curves, markers, texts): polylines of at least
/// three points (ticks and legend swatches have two), circles, and the text
/// contents.
fn census(svg: &str) -> (usize, usize, Vec<String>) {
    let doc = roxmltree::Document::parse(svg).expect("well-formed XML");
    assert_eq!(doc.root_element().tag_name().name(), "svg");
    let curves = doc
        .descendants()
        .filter(|n| n.has_tag_name("polyline"))
        .filter(|n| {
            n.attribute("points")
                .is_some_and(|p| p.split_whitespace().count() >= 3)
        })
        .count();
    let markers = doc
        .descendants()
        .filter(|n| n.has_tag_name("circle"))
        .count();
    let texts = doc
        .descendants()
        .filter(|n| n.has_tag_name("text"))
        .filter_map(|n| n.text().map(|t| t.trim().to_string()))
        .collect();
    (curves, markers, texts)
}

fn r(s: &str) -> Rational {
    s.parse().unwrap()
}

#[test]
fn basis_plot_has_one_curve_per_function_and_value() {
    let values = [r("-2"), r("-1"), r("0"), r("1")];
    let picture =
        basis_svg(&Plotted::family(Family::ThesisCubic, &values, false, "basis").unwrap()).unwrap();
    // the data beside the figure: one series per drawn curve
    assert_eq!(picture.series.len(), 4 * 4);
    assert!(picture.series.iter().any(|s| s.label == "b2, m = -1"));
    assert_eq!(picture.rows().len(), 4 * 4 * 201);
    let svg = picture.svg;
    let (curves, _, texts) = census(&svg);
    assert_eq!(curves, 4 * 4);
    for label in ["m = -2", "m = -1", "m = 0", "m = 1", "basis function value"] {
        assert!(texts.iter().any(|t| t == label), "{label}: {texts:?}");
    }
    let svg = basis_svg(&Plotted::family(Family::Bernstein3, &[], false, "basis").unwrap())
        .unwrap()
        .svg;
    assert_eq!(census(&svg).0, 4);
    // outside the published range without permission: refused
    assert!(Plotted::family(Family::ThesisCubic, &[r("2")], false, "basis").is_err());
}

#[test]
fn curve_plot_has_polygon_and_one_curve_per_value() {
    let control = [(0.0, 0.0), (1.0, 2.0), (3.0, 2.0), (4.0, 0.0)];
    let svg = curve_svg(
        &Plotted::family(Family::Han, &[r("-1"), r("0"), r("1")], false, "curve").unwrap(),
        &control,
    )
    .unwrap()
    .svg;
    let (curves, markers, texts) = census(&svg);
    assert_eq!(curves, 3 + 1, "three curves and the control polygon");
    assert_eq!(markers, 4, "the control points");
    assert!(
        texts.iter().any(|t| t == "control polygon V0…V3"),
        "{texts:?}"
    );
    let han = Plotted::family(Family::Han, &[r("0")], false, "curve").unwrap();
    assert!(curve_svg(&han, &control[..3]).is_err());
}

#[test]
fn fit_plot_has_data_and_every_segment_of_both_stages() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../data/glyphs/delta.csv");
    let outline = Outline::read(&path).unwrap();
    let options = FitOptions {
        corners: Corners::Auto(CornerRule::default()),
        max_points: 50,
        threshold: 1.5,
        refine: Some(Continuity::Local),
        shape: Shape::Fixed(vec![0.6]),
    };
    let fit = fit_outline(&outline, Arc::new(Family::ThesisCubic), &options).unwrap();
    let svg = fit_svg(&outline, &fit).unwrap().svg;
    let (curves, markers, texts) = census(&svg);
    assert_eq!(curves, 2 * fit.segments.len());
    assert_eq!(
        markers,
        outline.point_count() + 1,
        "data points and the legend swatch"
    );
    assert!(texts.iter().any(|t| t == "data (656 points)"), "{texts:?}");
}

#[test]
fn interp_plot_has_pieces_and_data() {
    let pieces = vec![
        vec![(0.0, 1.0), (0.5, 0.5), (1.0, 2.0)],
        vec![(1.0, 2.0), (1.5, 3.0), (2.0, 1.0)],
    ];
    let svg = interp_svg(
        "test",
        &[(0.0, 1.0), (1.0, 2.0), (2.0, 1.0)],
        &[Interpolant {
            label: "P".into(),
            pieces,
        }],
    )
    .unwrap()
    .svg;
    let (curves, markers, _) = census(&svg);
    assert_eq!((curves, markers), (2, 3 + 1));
    assert!(interp_svg("x", &[], &[]).is_err());
}
