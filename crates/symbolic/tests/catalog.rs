//! The catalog's partitions of unity hold exactly in the symbolic ring.

use trig_core::Family;
use trig_symbolic::{Sym, symbolic_atoms};

fn sum(family: Family, param: &str) -> Sym {
    family
        .eval(&symbolic_atoms(), &[Sym::var(param)])
        .iter()
        .fold(Sym::int(0), |acc, x| acc + x)
}

#[test]
fn thesis_cubic_sums_to_one() {
    let s = sum(Family::ThesisCubic, "m");
    assert!(s.equals(&Sym::int(1)));
    assert_eq!(s.to_string(), "1");
}

#[test]
fn seed000_uniform_sums_to_one() {
    let s = sum(Family::Seed000Uniform, "zeta");
    assert!(s.equals(&Sym::int(1)));
    assert_eq!(s.to_string(), "1");
}

#[test]
fn thesis_quadratic_sums_to_one() {
    let s = sum(Family::ThesisQuadratic, "beta");
    assert!(s.equals(&Sym::int(1)));
    let h0 = &Family::ThesisQuadratic.eval(&symbolic_atoms(), &[Sym::var("beta")])[0];
    // β/(β+1)(1 − s)², reduced with s² = 1 − c²
    assert_eq!(h0.to_string(), "(-beta*c^2 - 2*beta*s + 2*beta)/(beta + 1)");
}

#[test]
fn seed000_uniform_functions_keep_the_normaliser() {
    let f = Family::Seed000Uniform.eval(&symbolic_atoms(), &[Sym::var("zeta")]);
    for x in &f {
        assert_eq!(x.denominator().len(), 1);
        let (d, e) = x.denominator().iter().next().unwrap();
        assert_eq!((d.to_string().as_str(), *e), ("3*zeta^2 - 3*zeta + 5", 1));
    }
}

#[test]
fn derivatives_of_the_sums_vanish() {
    for (family, param) in [
        (Family::ThesisCubic, "m"),
        (Family::Seed000Uniform, "zeta"),
        (Family::Han, "lambda"),
        (Family::MajeedQayyum, "eta"),
    ] {
        let b = family.eval(&symbolic_atoms(), &[Sym::var(param)]);
        let mut d: Vec<Sym> = b;
        for _ in 0..3 {
            d = d.iter().map(Sym::d_angle).collect();
            let total = d.iter().fold(Sym::int(0), |acc, x| acc + x);
            assert!(total.is_zero(), "{family:?}: {total}");
        }
    }
}
