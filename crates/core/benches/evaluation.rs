//! Criterion benchmarks of issue 2: the thesis cubic basis at one point in f64
//! and at 256-bit MPFR, and a 1,000,000-point curve evaluation.

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use nalgebra::Point2;
use rug::Rational;
use trig_core::curve::Segment;
use trig_core::families::thesis;
use trig_core::{Family, Mpfr, Real};

/// All four functions at `u`: θ = πu/2, one `sin_cos`, then (3.7).
fn cubic_at<T: Real>(u: &T, m: &T) -> [T; 4] {
    let theta = u.clone() * &(u.pi() * &u.ratio(1, 2));
    let (s, c) = theta.sin_cos();
    thesis::cubic(&s, &c, m)
}

fn bench(c: &mut Criterion) {
    c.bench_function("thesis_cubic_f64_one_point", |b| {
        b.iter(|| cubic_at(black_box(&0.37_f64), black_box(&0.6_f64)))
    });
    let u = Mpfr::from_rational(256, &Rational::from((37, 100)));
    let m = Mpfr::from_rational(256, &Rational::from((3, 5)));
    c.bench_function("thesis_cubic_mpfr256_one_point", |b| {
        b.iter(|| cubic_at(black_box(&u), black_box(&m)))
    });
    let points = vec![
        Point2::new(0.0, 0.0),
        Point2::new(1.0, 2.0),
        Point2::new(3.0, 2.0),
        Point2::new(4.0, 0.0),
    ];
    let segment = Segment::new(Family::ThesisCubic, vec![Rational::from((3, 5))], points)
        .expect("valid segment");
    let mut group = c.benchmark_group("curve");
    group.sample_size(10);
    group.bench_function("thesis_cubic_curve_1e6_points_f64", |b| {
        b.iter(|| {
            let n = 1_000_000;
            let mut acc = 0.0;
            for i in 0..n {
                let x = f64::from(i) / f64::from(n - 1);
                acc += segment.eval(&x).expect("in domain").x;
            }
            black_box(acc)
        })
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
