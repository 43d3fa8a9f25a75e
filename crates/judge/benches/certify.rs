//! The certification engine on published bases (the spec files under
//! `examples/`): one-parameter maximal ranges with exact ends, a range with
//! an irrational end, a quotient basis on a half-line, and regions of two
//! parameters (issue 11: < 0.1 s per range, < 2 s per region).

use std::hint::black_box;
use std::path::PathBuf;

use criterion::{Criterion, criterion_group, criterion_main};
use trig_certify::ParamBox;
use trig_certify::range::maximal_range;
use trig_judge::region::{Axis, classify_window, maximal};
use trig_specfile::Spec;
use trig_symbolic::Sym;

fn load(name: &str) -> Spec {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples")
        .join(name);
    Spec::from_file(&path).expect("example spec")
}

fn range(c: &mut Criterion, file: &str, label: &str) {
    let spec = load(file);
    let fs = spec.symbolic();
    let names: Vec<&str> = spec.functions.iter().map(|f| f.name.as_str()).collect();
    let p = &spec.params[0];
    let start = p.range.interior_point();
    let trig = spec.domain.is_trigonometric();
    c.bench_function(label, |b| {
        b.iter(|| black_box(maximal_range(&fs, &names, trig, &p.name, &start)))
    });
}

fn region_of(c: &mut Criterion, file: &str, label: &str, window: bool) {
    let spec = load(file);
    let fs: Vec<Sym> = spec.symbolic();
    let names: Vec<&str> = spec.functions.iter().map(|f| f.name.as_str()).collect();
    let axes = || {
        [0, 1].map(|k| Axis {
            name: &spec.params[k].name,
            symbol: &spec.params[k].symbol,
            set: ParamBox::from_range(&spec.params[k].range),
            source: &spec.params[k].source,
        })
    };
    let trig = spec.domain.is_trigonometric();
    c.bench_function(label, |b| {
        b.iter(|| {
            if window {
                black_box(classify_window(&fs, &names, trig, &axes()).cells.len());
            } else {
                black_box(maximal(&fs, &names, trig, axes()).status);
            }
        })
    });
}

fn benches(c: &mut Criterion) {
    range(
        c,
        "thesis-cubic.toml",
        "range: thesis cubic m, exact ends -2, 1",
    );
    range(
        c,
        "yan-liang-cubic.toml",
        "range: Yan-Liang cubic, exact ends -3, 1",
    );
    range(
        c,
        "rational-quadratic.toml",
        "range: rational quadratic w, [0, inf)",
    );
    range(
        c,
        "irrational-end.toml",
        "range: irrational ends 2 -+ 2 sqrt 2",
    );
    region_of(
        c,
        "bashir-quadratic.toml",
        "region: Bashir (alpha, beta), region = box",
        false,
    );
    region_of(
        c,
        "rational-cubic.toml",
        "region: rational cubic (w1, w2), region = box",
        false,
    );
    region_of(
        c,
        "bashir-quadratic.toml",
        "region: Bashir window, 5 levels (plot region)",
        true,
    );
}

criterion_group! {
    name = certify;
    config = Criterion::default().sample_size(10);
    targets = benches
}
criterion_main!(certify);
