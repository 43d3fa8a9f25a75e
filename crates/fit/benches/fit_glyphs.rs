//! Fit of every committed glyph with every compared family, before and after
//! C¹ refinement (issue 6 target: under 1 s in release), and with the shape
//! parameter optimised per segment.

use std::sync::Arc;

use std::path::PathBuf;

use criterion::{Criterion, criterion_group, criterion_main};
use trig_core::Family;
use trig_fit::optimise::search_interval;
use trig_fit::{Continuity, CornerRule, Corners, FitOptions, Outline, Shape, fit_outline};

const FAMILIES: [Family; 6] = [
    Family::ThesisCubic,
    Family::MajeedQayyum,
    Family::Han,
    Family::Usman,
    Family::HanListing,
    Family::Bernstein3,
];

fn outlines() -> Vec<Outline> {
    ["epsilon", "delta", "ain"]
        .iter()
        .map(|g| {
            let p = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
                .join(format!("../../data/glyphs/{g}.csv"));
            Outline::read(&p).expect("committed glyph data")
        })
        .collect()
}

fn fit_all(outlines: &[Outline], optimise: bool) -> f64 {
    let mut total = 0.0;
    for o in outlines {
        for f in FAMILIES {
            let info = f.info();
            let shape = match (optimise, info.params.first()) {
                (true, Some(spec)) => {
                    let (lo, hi) = search_interval(&spec.range).expect("bounded range");
                    Shape::Optimise {
                        lo,
                        hi,
                        fixed: vec![],
                    }
                }
                (_, Some(_)) => Shape::Fixed(vec![0.6]),
                (_, None) => Shape::Fixed(vec![]),
            };
            let options = FitOptions {
                corners: Corners::Auto(CornerRule::default()),
                max_points: 50,
                threshold: 1.5,
                refine: Some(Continuity::Local),
                shape,
            };
            let fit = fit_outline(o, Arc::new(f), &options).expect("fit");
            total += fit.after.expect("refined").total;
        }
    }
    total
}

fn bench(c: &mut Criterion) {
    let outlines = outlines();
    c.bench_function("fit 3 glyphs x 6 families, C0 + C1 (m = 0.6)", |b| {
        b.iter(|| fit_all(&outlines, false))
    });
    c.bench_function("fit 3 glyphs x 6 families, optimised m, C0 + C1", |b| {
        b.iter(|| fit_all(&outlines, true))
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
