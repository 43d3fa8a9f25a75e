//! Certified evaluation: enclosures of exact values from exact inputs, the
//! precision raised until the requested digits are proved, domain checks on
//! the exact input, and certified error bounds of f64 results.
//!
//! Every function here takes its inputs as exact rationals (the command
//! line reads numbers exactly) and evaluates the one generic formula of a
//! [`Basis`] on [`Interval`]s, so what it prints is proved about the exact
//! value the user asked for — not about a rounded input or a rounded
//! computation. Work is bounded: precisions double from the one the digits
//! need up to [`MAX_BITS`]; what is not proved by then is reported as such
//! (fewer digits, or an error naming the limit), never guessed.

use std::cmp::Ordering;

use rug::Rational;

use crate::basis::Basis;
use crate::decimal::{Decimal, bound_text};
use crate::domain::{Affine, Domain};
use crate::error::{CoreError, Result};
use crate::interval::{Fault, Interval};
use crate::number::parse_exact;
use crate::scalar::{Real, Ring};
use crate::work;

use crate::precision::MIN_BITS;
pub use crate::precision::{MAX_BITS, affine_sign};

/// The most significant digits a request may ask for.
pub const MAX_DIGITS: usize = 10_000;

/// Digits certified for f64 cross-checks: more than f64 carries, so the
/// enclosure's own width is negligible in the stated bound.
pub const F64_CHECK_DIGITS: usize = 20;

/// The f64 result is shown (with its bound) when its certified error is at
/// most this fraction of the largest value of its set; otherwise the
/// certified value replaces it.
const F64_TOLERANCE: f64 = 1e-8;

/// Work budget of one certified evaluation, in [`work`] units (about 10 s
/// of MPFR arithmetic on the reference machine of BENCHMARKS.md). The cost
/// of each precision step is predicted from the step before (the same
/// operations at the new precision, [`work::scale`]): a step whose
/// predicted cost would take the total past the budget is not started.
/// Counted, never timed: the same input proves the same digits anywhere.
pub const WORK_BUDGET: u64 = 500_000_000;

/// Why an evaluation stopped short of its target.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stop {
    /// The precision reached [`MAX_BITS`].
    MaxBits,
    /// The next step would have taken the work past [`WORK_BUDGET`].
    Budget,
}

/// Enclosures proved at some working precision.
#[derive(Debug, Clone)]
pub struct Enclosures {
    pub values: Vec<Interval>,
    /// Working precision of the last evaluation, in bits.
    pub bits: u32,
    /// Why the precision was not raised further, when the target was not
    /// reached.
    pub stopped: Option<Stop>,
}

impl Enclosures {
    /// The fewest proved significant digits over the values (`usize::MAX`
    /// when all are exact). An enclosure of zero proves none: a tiny value
    /// has significant digits, and zero has none, so `0 ± b` delivers no
    /// digit of either.
    pub fn digits(&self, max: usize) -> usize {
        self.values
            .iter()
            .map(|v| v.decimal(max).digits())
            .min()
            .unwrap_or(usize::MAX)
    }
}

/// Checks a set of enclosures: a divisor proved zero, one not proved
/// nonzero, or an end beyond MPFR's exponent range are errors naming
/// `what`.
pub fn check(values: &[Interval], what: &str, bits: u32) -> Result<()> {
    match values.iter().filter_map(Interval::fault).max() {
        Some(Fault::DivisionByZero) => Err(CoreError::DivisionByZero {
            quantity: what.to_string(),
        }),
        Some(Fault::ZeroNotExcluded) => Err(CoreError::NotCertifiedNonzero {
            quantity: what.to_string(),
            bits,
        }),
        None if values.iter().any(|v| !v.is_finite()) => Err(CoreError::Overflow {
            quantity: what.to_string(),
        }),
        None => Ok(()),
    }
}

/// Evaluates `f` at doubling precisions from [`MIN_BITS`]: up to `target`
/// bits, then on while `more` says the result is not good enough, up to
/// [`MAX_BITS`]; each step only if its predicted cost fits the
/// [`WORK_BUDGET`]. A divisor not proved nonzero is retried at the next
/// precision; other errors end the climb.
fn climb(
    target: u32,
    what: &str,
    f: &mut impl FnMut(u32) -> Result<Vec<Interval>>,
    more: impl Fn(&[Interval]) -> bool,
) -> Result<Enclosures> {
    let mut spent = 0u64;
    let mut bits = MIN_BITS.min(target);
    let mut last: Option<Enclosures> = None;
    let over_budget = || CoreError::Limit {
        what: what.to_string(),
        limit: format!("{WORK_BUDGET} units of certified arithmetic"),
    };
    loop {
        let (result, cost) = work::measure(|| {
            f(bits).and_then(|values| check(&values, what, bits).map(|()| values))
        });
        spent = spent.saturating_add(cost);
        let failure = match result {
            Ok(values) => {
                let done = bits >= target && !more(&values);
                last = Some(Enclosures {
                    values,
                    bits,
                    stopped: None,
                });
                if done {
                    break;
                }
                None
            }
            Err(e @ CoreError::NotCertifiedNonzero { .. }) => Some(e),
            Err(e) => return Err(e),
        };
        let next = bits.saturating_mul(2).min(MAX_BITS);
        let stop = if bits >= MAX_BITS {
            Stop::MaxBits
        } else if spent.saturating_add(work::scale(cost, bits, next)) > WORK_BUDGET {
            Stop::Budget
        } else {
            bits = next;
            continue;
        };
        return match (failure, last) {
            (Some(e), _) => Err(e),
            (None, Some(mut e)) => {
                e.stopped = Some(stop);
                Ok(e)
            }
            (None, None) => Err(over_budget()),
        };
    }
    last.ok_or_else(over_budget)
}

/// Evaluates `f` at `bits` (after cheaper steps that predict its cost) and
/// checks the result; an error naming the budget when `bits` cannot be
/// reached within [`WORK_BUDGET`].
pub fn at_bits(
    bits: u32,
    what: &str,
    f: &mut impl FnMut(u32) -> Result<Vec<Interval>>,
) -> Result<Enclosures> {
    let e = climb(bits, what, f, |_| false)?;
    if e.bits < bits {
        return Err(CoreError::Limit {
            what: format!("{what} at {bits} bits (predicted from {} bits)", e.bits),
            limit: format!("{WORK_BUDGET} units of certified arithmetic"),
        });
    }
    Ok(e)
}

/// True when every value has `digits` proved significant digits, or is an
/// enclosure of zero narrower than `10^−digits` times the largest value
/// (at least 1).
fn resolved(values: &[Interval], digits: usize) -> bool {
    let scale = values
        .iter()
        .filter(|v| !v.contains_zero())
        .map(|v| v.mag().to_f64())
        .fold(1.0_f64, f64::max);
    let tiny = scale * 10f64.powi(-(digits.min(300) as i32));
    values.iter().all(|v| match v.decimal(digits) {
        Decimal::Small { .. } => v.mag().to_f64() <= tiny,
        d => d.digits() >= digits,
    })
}

/// Evaluates `f` at increasing precision until every value has `digits`
/// proved significant digits — relative precision: a tiny nonzero value is
/// climbed until its own digits are proved, and only an exact value (a
/// single point, such as an exact zero) needs no more — or [`MAX_BITS`] or
/// the [`WORK_BUDGET`] is reached. Returns the last enclosures: possibly
/// with fewer digits than asked ([`Enclosures::digits`] says how many are
/// proved, [`Enclosures::stopped`] why). This is what a request for
/// `digits` significant digits promises.
pub fn to_significant_digits(
    digits: usize,
    what: &str,
    mut f: impl FnMut(u32) -> Result<Vec<Interval>>,
) -> Result<Enclosures> {
    climb(bits_for(digits), what, &mut f, |v| {
        v.iter().any(|x| x.decimal(digits).digits() < digits)
    })
}

/// The working precision `digits` decimal digits need, with guard bits.
fn bits_for(digits: usize) -> u32 {
    let need = (digits as f64 * std::f64::consts::LOG2_10).ceil() as u32 + 32;
    need.clamp(MIN_BITS, MAX_BITS)
}

/// Evaluates `f` at increasing precision until every value is
/// `resolved` to `digits` (an enclosure of zero far below the largest
/// value counts: for certified error bounds of f64 results, not for
/// printed digits — see [`to_significant_digits`]), or [`MAX_BITS`] or the
/// [`WORK_BUDGET`] is reached.
pub fn to_digits(
    digits: usize,
    what: &str,
    mut f: impl FnMut(u32) -> Result<Vec<Interval>>,
) -> Result<Enclosures> {
    climb(bits_for(digits), what, &mut f, |v| !resolved(v, digits))
}

/// The functions of `basis` at the exact point `x` with exact parameters,
/// enclosed at `bits`.
pub fn enclose_basis<B: Basis + ?Sized>(
    basis: &B,
    x: &Rational,
    params: &[Rational],
    bits: u32,
) -> Vec<Interval> {
    let xi = Interval::from_rational(bits, x);
    let p: Vec<Interval> = params.iter().map(|q| xi.rational(q)).collect();
    basis.eval(&basis.domain().atoms(&xi), &p)
}

/// Whether the exact point `x` (a rational or a rational multiple of π)
/// lies in `domain` for the exact parameters `params`: the differences to
/// the ends, `x − a` and `b − x`, decided exactly by [`affine_sign`].
pub fn domain_contains(domain: &Domain, x: &Affine, params: &[Affine]) -> Result<bool> {
    let minus = |a: &Affine, b: &Affine| a.plus(&b.scale(&Rational::from(-1))).at(params);
    Ok(affine_sign(&minus(x, &domain.start))? != Ordering::Less
        && affine_sign(&minus(&domain.end, x))? != Ordering::Less)
}

/// Checks the exact point `x` (as typed: `input`) against `domain`.
pub fn check_domain(domain: &Domain, x: &Affine, params: &[Affine], input: &str) -> Result<()> {
    if domain_contains(domain, x, params)? {
        Ok(())
    } else {
        Err(CoreError::PointOutsideDomain {
            value: crate::echo::echo(input),
            domain: domain.to_string(),
        })
    }
}

/// The exact rational `q` as an f64, an error naming `what` when it
/// overflows or underflows (a nonzero value that rounds to zero or to a
/// subnormal number).
pub fn to_f64(q: &Rational, what: &str) -> Result<f64> {
    let x = q.to_f64();
    if x.is_finite() && (x.is_normal() || *q == 0) {
        Ok(x)
    } else {
        Err(CoreError::NotRepresentable {
            what: what.to_string(),
            kind: if x.is_finite() {
                "underflows"
            } else {
                "overflows"
            }
            .into(),
        })
    }
}

/// An f64 result checked against an enclosure of the exact value.
#[derive(Debug, Clone, PartialEq)]
pub enum CheckedF64 {
    /// The f64 result as printed, and a proved bound of its distance from
    /// the exact value.
    Accurate { text: String, bound: String },
    /// The f64 result is not finite or too far off: the certified value
    /// (and how far off f64 was, when finite).
    Replaced {
        decimal: Decimal,
        f64_error: Option<String>,
    },
}

impl CheckedF64 {
    /// The text to print for the value.
    pub fn value_text(&self) -> String {
        match self {
            CheckedF64::Accurate { text, .. } => text.clone(),
            CheckedF64::Replaced { decimal, .. } => decimal.to_string(),
        }
    }
}

/// Checks f64 results against enclosures of their exact values (one set:
/// the tolerance is relative to the set's largest value). The bound is
/// between the printed decimal and the exact value.
pub fn check_f64(values: &[f64], exact: &[Interval]) -> Vec<CheckedF64> {
    // the largest value f64 can hold (values beyond it are replaced anyway)
    let scale = exact
        .iter()
        .map(|v| v.mag().to_f64())
        .filter(|m| m.is_finite())
        .fold(0.0_f64, f64::max);
    values
        .iter()
        .zip(exact)
        .map(|(&v, e)| {
            let text = v.to_string();
            let bound = v
                .is_finite()
                .then(|| parse_exact(&text).ok())
                .flatten()
                .and_then(|d| e.distance_bound(&d));
            match bound {
                Some(b) if b.to_f64() <= F64_TOLERANCE * scale => CheckedF64::Accurate {
                    text,
                    bound: bound_text(&b),
                },
                b => CheckedF64::Replaced {
                    decimal: e.decimal(17),
                    f64_error: b.map(|b| bound_text(&b)),
                },
            }
        })
        .collect()
}

/// The error for non-finite values of `basis` at `x` in a floating
/// backend: a parameter the backend cannot hold, a division by zero (the
/// exact value at the backend's point has a divisor not proved nonzero), or
/// else an overflow of the backend's range (the exact values are finite).
pub fn nonfinite_error<B: Basis + ?Sized, T: Real>(
    basis: &B,
    x: &T,
    params: &[Rational],
    quantity: String,
) -> CoreError {
    let names = basis.param_names();
    if let Some((name, _)) = names
        .iter()
        .zip(params)
        .find(|(_, q)| !x.rational(q).is_finite())
    {
        return CoreError::NotRepresentable {
            what: format!("parameter {name}"),
            kind: "overflows".into(),
        };
    }
    let Some(point) = x.to_rational().filter(|_| params.len() == names.len()) else {
        return CoreError::DivisionByZero { quantity };
    };
    let values = enclose_basis(basis, &point, params, 128);
    match check(&values, &quantity, 128) {
        Err(CoreError::Overflow { .. }) | Ok(()) => CoreError::Overflow { quantity },
        Err(_) => CoreError::DivisionByZero { quantity },
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::family::Family;
    use crate::variable::Variable;

    fn q(n: i64, d: i64) -> Rational {
        Rational::from((n, d))
    }

    #[test]
    fn domain_checks_use_the_exact_point() {
        let point = |text: &str| crate::number::parse_point(text).unwrap();
        let domain = |v: Variable| Domain::from_variable(v, &[]);
        let unit = domain(Variable::UnitAngle);
        let angle = domain(Variable::Angle);
        assert!(!domain_contains(&unit, &point("1.00000000000000000000000001"), &[]).unwrap());
        assert!(domain_contains(&unit, &point("1"), &[]).unwrap());
        // 1.5707963267948966 < π/2 < 1.5707963267948967
        assert!(domain_contains(&angle, &point("1.5707963267948966"), &[]).unwrap());
        assert!(!domain_contains(&angle, &point("1.5707963267948967"), &[]).unwrap());
        assert!(!domain_contains(&domain(Variable::Polynomial), &point("-1/10"), &[]).unwrap());
        // multiples of π: the end itself exactly, just past it, and π/4 < 1
        assert!(domain_contains(&angle, &point("pi/2"), &[]).unwrap());
        assert!(domain_contains(&angle, &point("0*pi"), &[]).unwrap());
        assert!(!domain_contains(&angle, &point("-pi/1000000"), &[]).unwrap());
        assert!(!domain_contains(&angle, &point("1000001*pi/2000000"), &[]).unwrap());
        assert!(domain_contains(&unit, &point("pi/4"), &[]).unwrap());
        assert!(!domain_contains(&unit, &point("pi/3"), &[]).unwrap());
    }

    #[test]
    fn digits_are_raised_until_proved() {
        let e = to_digits(50, "b", |bits| {
            Ok(enclose_basis(
                &Family::ThesisCubic,
                &q(1, 4),
                &[q(3, 5)],
                bits,
            ))
        })
        .unwrap();
        assert!(e.digits(50) >= 50, "{}", e.digits(50));
        // b3(1/4; 3/5): digits from `bc -l` at scale 60
        let b3 = e.values[3].decimal(50).to_string();
        assert_eq!(b3, "2.5823702910142048907010730505698383907471382003678e-3");
    }

    /// Han (6.2) at λ = 0, u = 10⁻¹⁰: b₂ ≈ 2.47·10⁻²⁰ and b₃ ≈ 1.52·10⁻⁴⁰ are
    /// tiny, not zero: five significant digits of each are proved (the
    /// precision is raised for them), not `0 ± 2.2e-19`.
    #[test]
    fn tiny_values_get_their_own_significant_digits() {
        let at = crate::number::parse_exact("1e-10").unwrap();
        let e = to_significant_digits(5, "han", |bits| {
            Ok(enclose_basis(&Family::Han, &at, &[q(0, 1)], bits))
        })
        .unwrap();
        assert!(e.digits(5) >= 5, "{:?}", e.values);
        assert!(e.values[2].decimal(5).to_string().starts_with("2.4674e-20"));
        assert!(e.values[3].decimal(5).to_string().ends_with("e-40"));
        // an exact zero is a value with no significant digits: nothing to climb
        let z = to_significant_digits(5, "b", |bits| {
            Ok(vec![Interval::from_rational(bits, &q(0, 1))])
        })
        .unwrap();
        assert_eq!((z.bits, z.digits(5)), (64, usize::MAX));
        // an enclosure of zero proves no digit
        let small = Enclosures {
            values: vec![Interval::from_ends(
                64,
                &rug::Float::with_val(64, -1e-30),
                &rug::Float::with_val(64, 1e-30),
            )],
            bits: 64,
            stopped: None,
        };
        assert_eq!(small.digits(5), 0);
    }

    #[test]
    fn a_proved_zero_divisor_is_a_division_by_zero() {
        // thesis-quadratic with β = −1 divides by β + 1 = 0
        let r = to_digits(10, "H", |bits| {
            Ok(enclose_basis(
                &Family::ThesisQuadratic,
                &q(1, 2),
                &[q(-1, 1)],
                bits,
            ))
        });
        assert!(matches!(r, Err(CoreError::DivisionByZero { .. })), "{r:?}");
    }

    #[test]
    fn f64_results_carry_bounds_or_are_replaced() {
        let exact = [
            Interval::from_rational(128, &q(1, 3)),
            Interval::from_rational(128, &q(2, 3)),
        ];
        let checked = check_f64(&[1.0 / 3.0, 0.5], &exact);
        let CheckedF64::Accurate { bound, .. } = &checked[0] else {
            panic!("{checked:?}")
        };
        // 0.3333333333333333 is 1/3 − 3.3…e-17
        assert_eq!(bound, "3.4e-17");
        assert!(matches!(&checked[1], CheckedF64::Replaced { .. }));
        assert_eq!(checked[1].value_text(), "6.6666666666666667e-1");
    }

    #[test]
    fn f64_conversion_refuses_overflow_and_underflow() {
        assert!(to_f64(&parse_exact("1e400").unwrap(), "m").is_err());
        assert!(to_f64(&parse_exact("1e-400").unwrap(), "h").is_err());
        assert_eq!(to_f64(&q(1, 4), "h").unwrap(), 0.25);
        assert_eq!(to_f64(&q(0, 1), "h").unwrap(), 0.0);
    }
}
