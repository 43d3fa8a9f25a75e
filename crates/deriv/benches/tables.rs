//! Endpoint-derivative tables in the exact ring, and single-point jets in
//! f64 and 256-bit MPFR.

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use rug::Rational;
use trig_core::{Family, Mpfr};
use trig_deriv::{End, Wrt, endpoint_derivatives, family_derivatives};
use trig_symbolic::Sym;

fn tables(c: &mut Criterion) {
    c.bench_function("exact_table_thesis_cubic_orders_0_8_both_ends", |b| {
        let params = [Sym::var("m")];
        let h = Sym::var("h");
        b.iter(|| {
            for end in [End::Start, End::End] {
                black_box(endpoint_derivatives::<Sym, 9>(
                    Family::ThesisCubic,
                    black_box(&params),
                    end,
                    Wrt::U,
                    &h,
                ));
            }
        });
    });

    c.bench_function("jet_order8_f64_thesis_cubic_one_point", |b| {
        b.iter(|| {
            family_derivatives::<f64, 9>(Family::ThesisCubic, black_box(&0.37), black_box(&[0.6]))
        });
    });

    c.bench_function("jet_order8_mpfr256_thesis_cubic_one_point", |b| {
        let x = Mpfr::from_rational(256, &Rational::from((37, 100)));
        let m = [Mpfr::from_rational(256, &Rational::from((3, 5)))];
        b.iter(|| family_derivatives::<Mpfr, 9>(Family::ThesisCubic, black_box(&x), black_box(&m)));
    });
}

criterion_group!(benches, tables);
criterion_main!(benches);
