//! The maximal interval of a shape parameter on which every function of a
//! family is nonnegative on its whole domain.
//!
//! From a parameter value inside, each end is bracketed by certified point
//! tests (nonnegative, or an exact counterexample) and bisected to a width
//! below 10⁻¹³; the simplest rational in the bracket is then tested as the
//! exact end: nonnegative there, with an exact counterexample 10⁻¹² beyond.
//! Finally the whole interval is certified with two-dimensional boxes.

use rug::Rational;
use trig_symbolic::Sym;

use super::nonneg::{Certificate, ParamBox, certify};

/// Largest distance searched from the starting point before an end is
/// declared unbounded (then certified on the half-line).
const SEARCH: i64 = 1 << 20;

/// One end of the maximal interval.
#[derive(Debug, Clone, PartialEq)]
pub enum EndPoint {
    /// The exact end: nonnegative at `value`, with a counterexample just
    /// beyond.
    Exact { value: Rational, outside: Outside },
    /// The end lies in `(ok, bad)`, width < 10⁻¹³; what happens at `bad`.
    Bracket {
        ok: Rational,
        bad: Rational,
        outside: Outside,
    },
    /// No end within 2²⁰ of the start (certified on the half-line when it is the upper end).
    Unbounded,
}

/// The maximal interval around a starting value, with its certificate.
#[derive(Debug, Clone, PartialEq)]
pub struct MaximalRange {
    pub lo: EndPoint,
    pub hi: EndPoint,
    /// The certificate over the whole (closed, finite part of the) interval.
    pub certificate: Certificate,
}

/// Why a parameter value is not (known to be) inside.
#[derive(Debug, Clone, PartialEq)]
pub enum Outside {
    /// An exact counterexample `(p, z, value)`, `value < 0`.
    Counterexample(Rational, Rational, Rational),
    /// Not certified either way at `p` (depth limit).
    Undecided(Rational),
}

/// All functions nonnegative at the single parameter value `p`, or why not.
fn point(fs: &[Sym], trig: bool, param: &str, p: &Rational) -> Result<(), Outside> {
    for f in fs {
        match certify(
            f,
            trig,
            Some(param),
            &ParamBox::Interval(p.clone(), p.clone()),
        ) {
            Certificate::NonNegative { .. } => {}
            Certificate::Counterexample { p, z, value } => {
                return Err(Outside::Counterexample(p, z, value));
            }
            // not certified: no end is claimed beyond what was proved
            Certificate::Undecided(_) => return Err(Outside::Undecided(p.clone())),
        }
    }
    Ok(())
}

/// The simplest rational (smallest denominator) in `[a, b]`, `a < b`, by
/// the Stern–Brocot descent on continued fractions.
pub fn simplest_between(a: &Rational, b: &Rational) -> Rational {
    let c = a.clone().ceil();
    if c <= *b {
        // an integer lies in [a, b]; the one nearest zero is simplest, but
        // any integer in a bracket of width < 1 is unique
        return c;
    }
    let fl = a.clone().floor();
    let frac_a = a.clone() - &fl;
    let frac_b = b.clone() - &fl;
    // 1/frac lies in [1/frac_b, 1/frac_a]
    let inner = simplest_between(&(Rational::from(1) / frac_b), &(Rational::from(1) / frac_a));
    fl + Rational::from(1) / inner
}

fn find_end(fs: &[Sym], trig: bool, param: &str, start: &Rational, dir: i64) -> EndPoint {
    let tiny = Rational::from((1, 10_000_000_000_000i64));
    let mut step = Rational::from(1);
    let mut ok = start.clone();
    let bad = loop {
        let p = start.clone() + step.clone() * dir;
        match point(fs, trig, param, &p) {
            Ok(()) => ok = p,
            Err(_) => break p,
        }
        step *= 2;
        if step > SEARCH {
            return EndPoint::Unbounded;
        }
    };
    let mut bad = bad;
    while (bad.clone() - &ok).abs() > tiny {
        let mid = (ok.clone() + &bad) / 2u32;
        match point(fs, trig, param, &mid) {
            Ok(()) => ok = mid,
            Err(_) => bad = mid,
        }
    }
    let outside_bad = point(fs, trig, param, &bad).expect_err("bad end");
    let (lo, hi) = if ok < bad {
        (ok.clone(), bad.clone())
    } else {
        (bad.clone(), ok.clone())
    };
    let q = simplest_between(&lo, &hi);
    let beyond = q.clone() + Rational::from((1, 1_000_000_000_000i64)) * dir;
    if point(fs, trig, param, &q).is_ok() {
        if let Err(outside @ Outside::Counterexample(..)) = point(fs, trig, param, &beyond) {
            return EndPoint::Exact { value: q, outside };
        }
    }
    EndPoint::Bracket {
        ok,
        bad,
        outside: outside_bad,
    }
}

/// The maximal interval containing `start` on which every function in `fs`
/// (of one parameter `param`) is nonnegative on its whole domain.
pub fn maximal_range(fs: &[Sym], trig: bool, param: &str, start: &Rational) -> MaximalRange {
    let lo = find_end(fs, trig, param, start, -1);
    let hi = find_end(fs, trig, param, start, 1);
    let inner = |e: &EndPoint| match e {
        EndPoint::Exact { value, .. } => Some(value.clone()),
        EndPoint::Bracket { ok, .. } => Some(ok.clone()),
        EndPoint::Unbounded => None,
    };
    let bx = match (inner(&lo), inner(&hi)) {
        (Some(a), Some(b)) => ParamBox::Interval(a, b),
        (Some(a), None) => ParamBox::FromTo(a),
        (None, Some(b)) => ParamBox::Interval(start.clone() - Rational::from(SEARCH), b),
        (None, None) => ParamBox::FromTo(start.clone() - Rational::from(SEARCH)),
    };
    let certificate = certify_all(fs, trig, param, &bx);
    MaximalRange {
        lo,
        hi,
        certificate,
    }
}

/// Certifies every function on the box (the first failure is returned).
pub fn certify_all(fs: &[Sym], trig: bool, param: &str, bx: &ParamBox) -> Certificate {
    let mut boxes = 0;
    for f in fs {
        match certify(f, trig, Some(param), bx) {
            Certificate::NonNegative { boxes: b } => boxes += b,
            other => return other,
        }
    }
    Certificate::NonNegative { boxes }
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_core::Family;

    use crate::exact::basis;

    #[test]
    fn simplest_rationals() {
        let r = |a, b| Rational::from((a, b));
        assert_eq!(simplest_between(&r(3, 10), &r(4, 10)), r(1, 3));
        assert_eq!(simplest_between(&r(-21, 10), &r(-19, 10)), r(-2, 1));
        assert_eq!(simplest_between(&r(1, 2), &r(1, 2)), r(1, 2));
    }

    #[test]
    fn thesis_cubic_maximal_range_is_minus_two_to_one() {
        let r = maximal_range(&basis(Family::ThesisCubic), true, "m", &Rational::new());
        assert!(
            matches!(&r.lo, EndPoint::Exact { value, .. } if *value == -2),
            "{:?}",
            r.lo
        );
        assert!(
            matches!(&r.hi, EndPoint::Exact { value, .. } if *value == 1),
            "{:?}",
            r.hi
        );
        assert!(
            matches!(r.certificate, Certificate::NonNegative { .. }),
            "{:?}",
            r.certificate
        );
        for end in [&r.lo, &r.hi] {
            match end {
                EndPoint::Exact {
                    outside: Outside::Counterexample(_, _, v),
                    ..
                } => assert!(*v < 0),
                other => panic!("{other:?}"),
            }
        }
    }
}
