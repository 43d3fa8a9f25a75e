//! The pictures are well-formed SVG (XML) with the expected number of data
//! series, axis labels and legends; 160 mm wide, drawn on a grid finer than
//! the paper's pixels, with the legend below the data.

use std::sync::Arc;

use std::path::PathBuf;

use trig_core::{Affine, Family};
use trig_fit::{Continuity, CornerRule, Corners, FitOptions, Outline, Shape, fit_outline};
use trig_plot::{
    Choice, Interpolant, Plotted, basis_svg, basis_versus_svg, curve_svg, fit_svg, interp_svg,
};

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

/// A catalog family for the values `values` of its one parameter.
fn plotted(family: Family, values: &[Affine], what: &str) -> trig_plot::error::Result<Plotted> {
    let choice = Choice {
        values: values.to_vec(),
        ..Choice::default()
    };
    Plotted::new(family, &choice, what)
}

fn r(s: &str) -> Affine {
    Affine::rational(s.parse().unwrap())
}

#[test]
fn basis_plot_has_one_curve_per_function_and_value() {
    let values = [r("-2"), r("-1"), r("0"), r("1")];
    let picture = basis_svg(&plotted(Family::ThesisCubic, &values, "basis").unwrap()).unwrap();
    // the data beside the figure: one series per drawn curve (the legend
    // entries of the functions and values draw nothing)
    let drawn = || picture.series.iter().filter(|s| !s.points.is_empty());
    assert_eq!(drawn().count(), 4 * 4);
    assert_eq!(picture.series.len(), 4 * 4 + 4 + 4);
    assert_eq!(picture.rows().len(), 4 * 4 * 201);
    // a colour per function, a line style per value (a real minus sign)
    let look = |label: &str| {
        picture
            .series
            .iter()
            .find(|s| s.label == label)
            .unwrap_or_else(|| panic!("{label}"))
            .look
    };
    let dash = |label: &str| match look(label).mark {
        trig_plot::Mark::Line { dash, .. } => dash,
        _ => panic!("{label} is a line"),
    };
    assert_ne!(look("b0, m = −1").rgb, look("b1, m = −1").rgb);
    assert_eq!(look("b0, m = −2").rgb, look("b0, m = 1").rgb);
    assert_ne!(dash("b0, m = −2"), dash("b0, m = −1"));
    assert_eq!(dash("b0, m = 0"), dash("b3, m = 0"));
    let svg = picture.svg.clone();
    // the first value solid: four whole polylines; the others in pieces
    let (curves, _, texts) = census(&svg);
    assert!(curves > 4 * 4, "{curves}");
    let whole = roxmltree::Document::parse(&svg)
        .unwrap()
        .descendants()
        .filter_map(|n| n.attribute("points"))
        .filter(|p| p.split_whitespace().count() == 201)
        .count();
    assert_eq!(whole, 4);
    // the functions' indices as subscripts, the variable's domain
    for label in [
        "b₀",
        "b₃",
        "u ∈ [0, 1] (angle θ = πu/2)",
        "m = −2",
        "m = −1",
        "m = 0",
        "m = 1",
        "basis function value",
    ] {
        assert!(texts.iter().any(|t| t == label), "{label}: {texts:?}");
    }
    assert!(svg.contains(r#"font-family="serif""#), "serif text");
    let svg = basis_svg(&plotted(Family::Bernstein3, &[], "basis").unwrap())
        .unwrap()
        .svg;
    assert_eq!(census(&svg).0, 4);
    // outside the published range without permission: refused
    assert!(plotted(Family::ThesisCubic, &[r("2")], "basis").is_err());
}

#[test]
fn curve_plot_has_polygon_and_one_curve_per_value() {
    let control = [(0.0, 0.0), (1.0, 2.0), (3.0, 2.0), (4.0, 0.0)];
    let svg = curve_svg(
        &plotted(Family::Han, &[r("-1"), r("0"), r("1")], "curve").unwrap(),
        &control,
    )
    .unwrap()
    .svg;
    let (curves, markers, texts) = census(&svg);
    assert_eq!(curves, 3 + 1, "three curves and the control polygon");
    assert_eq!(markers, 4 + 1, "the control points and the legend swatch");
    assert!(
        texts.iter().any(|t| t == "control polygon V₀…V₃"),
        "{texts:?}"
    );
    let han = plotted(Family::Han, &[r("0")], "curve").unwrap();
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
    let svg = fit_svg(&outline, &fit, &["m".to_string()], None)
        .unwrap()
        .svg;
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

/// The root's width and height and its `viewBox` size.
fn root_size(svg: &str) -> ((String, String), (f64, f64)) {
    let doc = roxmltree::Document::parse(svg).expect("well-formed XML");
    let root = doc.root_element();
    let attr = |a: &str| root.attribute(a).expect(a).to_string();
    let view: Vec<f64> = attr("viewBox")
        .split_whitespace()
        .map(|v| v.parse().unwrap())
        .collect();
    ((attr("width"), attr("height")), (view[2], view[3]))
}

#[test]
fn figures_are_paper_sized_and_drawn_finer_than_a_pixel() {
    let plot = plotted(Family::Han, &[r("0")], "basis").unwrap();
    let svg = basis_svg(&plot).unwrap().svg;
    let ((w, h), (vw, vh)) = root_size(&svg);
    assert_eq!(w, "160mm");
    let h: f64 = h.strip_suffix("mm").expect("height in mm").parse().unwrap();
    // at least 40 drawing units per millimetre (whole units are 0.025 mm)
    assert!(vw / 160.0 >= 40.0, "{vw}");
    assert!((vh / h - vw / 160.0).abs() < 1e-9, "{vh} / {h}");
    // the text is set for the paper: 2.5 mm to 4 mm
    let doc = roxmltree::Document::parse(&svg).unwrap();
    for t in doc.descendants().filter(|n| n.has_tag_name("text")) {
        let size: f64 = t.attribute("font-size").unwrap().parse().unwrap();
        let mm = size * 160.0 / vw;
        assert!((2.5..=4.0).contains(&mm), "{:?}: {mm} mm", t.text());
    }
}

#[test]
fn the_legend_is_below_every_curve() {
    let values = [r("-2"), r("0"), r("1")];
    let plot = plotted(Family::ThesisCubic, &values, "basis").unwrap();
    let svg = basis_svg(&plot).unwrap().svg;
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let lowest_curve = doc
        .descendants()
        .filter(|n| n.has_tag_name("polyline"))
        .filter_map(|n| n.attribute("points"))
        .filter(|p| p.split_whitespace().count() >= 3)
        .flat_map(|p| p.split_whitespace().map(|xy| xy.split(',').nth(1).unwrap()))
        .map(|y| y.parse::<f64>().unwrap())
        .fold(f64::NEG_INFINITY, f64::max);
    for label in ["m = −2", "m = 0", "m = 1"] {
        let text = doc
            .descendants()
            .find(|n| n.has_tag_name("text") && n.text().map(str::trim) == Some(label))
            .unwrap_or_else(|| panic!("{label}"));
        let y: f64 = text.attribute("y").unwrap().parse().unwrap();
        assert!(
            y > lowest_curve,
            "{label} at {y}, a curve at {lowest_curve}"
        );
    }
}

#[test]
fn a_listing_is_drawn_over_the_printed_basis() {
    let values = [r("-1"), r("0"), r("1")];
    let listing = plotted(Family::HanListing, &values, "basis").unwrap();
    let han = plotted(Family::Han, &values, "basis").unwrap();
    let picture = basis_versus_svg(&listing, &han).unwrap();
    assert_eq!(picture.series.len(), 2 * 4 * 3 + 4 + 3 + 2);
    // marked text: the formulas set in math (pgfplots) or Unicode (SVG)
    let legend: Vec<&str> = picture.legend().map(|(t, _)| t).collect();
    assert_eq!(
        legend,
        [
            "⟪b0⟫",
            "⟪b1⟫",
            "⟪b2⟫",
            "⟪b3⟫",
            "⟪λ = −1⟫",
            "⟪λ = 0⟫",
            "⟪λ = 1⟫",
            "han-listing",
            "han"
        ]
    );
    // the first value solid (whole polylines of every sample) for both
    // bases, the others dashed or dotted (many short pieces)
    let doc = roxmltree::Document::parse(&picture.svg).unwrap();
    let lengths: Vec<usize> = doc
        .descendants()
        .filter(|n| n.has_tag_name("polyline"))
        .filter_map(|n| n.attribute("points"))
        .map(|p| p.split_whitespace().count())
        .collect();
    assert_eq!(lengths.iter().filter(|&&n| n == 201).count(), 4 * 2);
    assert!(lengths.iter().filter(|&&n| (2..201).contains(&n)).count() > 100);
    let (_, _, texts) = census(&picture.svg);
    assert!(texts.iter().any(|t| t == "λ = 0"), "{texts:?}");
    // b2 differs (the listing's sin), b0 agrees
    let at = |label: &str| {
        &picture
            .series
            .iter()
            .find(|s| s.label == label)
            .unwrap()
            .points
    };
    assert_eq!(at("b0, han-listing: λ = 1"), at("b0, han: λ = 1"));
    assert_ne!(at("b2, han-listing: λ = 1"), at("b2, han: λ = 1"));
    // different values: refused
    let other = plotted(Family::Han, &values[..2], "basis").unwrap();
    assert!(basis_versus_svg(&listing, &other).is_err());
}
