//! Criterion benchmarks of issue 15: the thesis cubic (3.7), all four
//! functions at 10⁶ points of `u ∈ [0, 1]`, through the batch evaluator and
//! through the checked one-point path, beside one libm `sin_cos` per point;
//! and the same at 336-bit MPFR beside one MPFR `sin_cos`. Peers (NumPy,
//! mpmath) are measured by `bench/peers.py` on the same points.

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use rug::Rational;
use trig_core::{Batch, Family, Mpfr, Ring};

const POINTS: usize = 1_000_000;
const MPFR_POINTS: usize = 1_000;
const PREC: u32 = 336;

fn grid(n: usize) -> Vec<f64> {
    (0..n).map(|i| i as f64 / (n - 1) as f64).collect()
}

fn bench(c: &mut Criterion) {
    let m = [Rational::from((3, 5))];
    let xs = grid(POINTS);
    let mut group = c.benchmark_group("batch_1e6_points");
    group.sample_size(10);
    group.bench_function("libm_sin_cos_per_point", |b| {
        b.iter(|| {
            let mut acc = 0.0;
            for x in &xs {
                let (s, c) = (black_box(*x) * std::f64::consts::FRAC_PI_2).sin_cos();
                acc += s + c;
            }
            black_box(acc)
        })
    });
    let mut batch = Batch::new(Family::ThesisCubic, &m, &0.0, false).expect("valid");
    let mut out = vec![0.0; 4 * POINTS];
    group.bench_function("thesis_cubic_batch_f64", |b| {
        b.iter(|| {
            batch
                .eval_into(black_box(&xs), &mut out)
                .expect("in domain");
            black_box(out[POINTS / 2])
        })
    });
    group.bench_function("thesis_cubic_eval_at_f64", |b| {
        b.iter(|| {
            let mut acc = 0.0;
            for x in &xs {
                acc += Family::ThesisCubic
                    .eval_at(x, &m, false)
                    .expect("in domain")[1];
            }
            black_box(acc)
        })
    });
    group.finish();

    let mut group = c.benchmark_group("mpfr336_1e3_points");
    group.sample_size(10);
    let mxs: Vec<Mpfr> = grid(MPFR_POINTS)
        .iter()
        .map(|&x| Mpfr::from_f64(PREC, x))
        .collect();
    let half_pi = Mpfr::from_f64(PREC, 0.0).pi().0 / 2u32;
    group.bench_function("mpfr_sin_cos_per_point", |b| {
        let mut s = rug::Float::new(PREC);
        let mut c = rug::Float::new(PREC);
        b.iter(|| {
            for x in &mxs {
                use rug::Assign;
                s.assign(&x.0 * &half_pi);
                s.sin_cos_mut(&mut c);
                black_box(&s);
            }
        })
    });
    let like = Mpfr::from_f64(PREC, 0.0);
    let mut batch = Batch::new(Family::ThesisCubic, &m, &like, false).expect("valid");
    let mut out = vec![like.clone(); 4 * MPFR_POINTS];
    group.bench_function("thesis_cubic_batch_mpfr336", |b| {
        b.iter(|| {
            batch
                .eval_into(black_box(&mxs), &mut out)
                .expect("in domain");
            black_box(&out[MPFR_POINTS / 2]);
        })
    });
    group.bench_function("thesis_cubic_eval_at_mpfr336", |b| {
        b.iter(|| {
            for x in &mxs {
                black_box(
                    Family::ThesisCubic
                        .eval_at(x, &m, false)
                        .expect("in domain"),
                );
            }
        })
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
