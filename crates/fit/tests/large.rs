//! A million-point outline: the C¹ refinement is a banded solve (before,
//! a dense KKT matrix of 30 GB was allocated and the process aborted).

use std::sync::Arc;

use trig_core::Family;
use trig_fit::{Continuity, CornerRule, Corners, FitOptions, Outline, P2, Shape, fit_outline};

#[test]
fn a_million_point_outline_is_refined_without_a_dense_matrix() {
    let n = 1_000_000;
    let contour: Vec<P2> = (0..n)
        .map(|i| {
            let a = std::f64::consts::TAU * i as f64 / n as f64;
            let r = 100.0 + 5.0 * (7.0 * a).sin();
            P2::new(r * a.cos(), r * a.sin())
        })
        .collect();
    let outline = Outline {
        name: "wavy circle".into(),
        provenance: vec![],
        contours: vec![contour],
    };
    let options = FitOptions {
        corners: Corners::Auto(CornerRule::default()),
        max_points: 50,
        threshold: trig_fit::THESIS_THRESHOLD,
        refine: Some(Continuity::ArcLength),
        shape: Shape::Fixed(vec![0.6]),
    };
    let fit = fit_outline(&outline, Arc::new(Family::ThesisCubic), &options).expect("fits");
    assert!(fit.segments.len() > 20_000, "{}", fit.segments.len());
    let after = fit.after.expect("refined");
    // a smooth curve sampled this densely is fitted almost exactly, and the
    // constraints cost little
    assert!(after.max < 1e-6, "max squared error {}", after.max);
    assert!(after.total >= fit.before.total * (1.0 - 1e-9));
}
