//! Certified evaluation: the values of a computation from exact inputs,
//! in the arithmetic a caller asks for, every printed digit proved.
//!
//! A [`Computation`] builds its values from exact rationals in any scalar
//! ([`Real`]): f64, or MPFR intervals at a working precision. [`evaluate`]
//! runs it in one [`Arithmetic`]:
//!
//! * [`Arithmetic::F64`]: the f64 values, each checked against enclosures
//!   of the exact value — a proved error bound, or the certified value when
//!   f64 is off ([`check_f64`]); the inputs must fit f64;
//! * [`Arithmetic::Bits`]: intervals at a fixed precision, the digits that
//!   precision proves;
//! * [`Arithmetic::Digits`]: intervals at increasing precision until `n`
//!   significant digits are proved (or the precision limit or the work
//!   budget is reached: [`Evaluated::stopped`] says which).
//!
//! The point values of a basis are one computation ([`BasisAt`]); the
//! B-spline pieces of [`crate::piecewise`] and seed 000's non-uniform spans
//! are others. Every front end (`eval`, `table`, a batch mode) shares this
//! path.
//!
//! ```
//! use rug::Rational;
//! use trig_core::evaluation::{Arithmetic, BasisAt, evaluate};
//! use trig_core::{Affine, Family};
//!
//! let pairs = [("m".to_string(), "1/2".to_string())];
//! let at = BasisAt::new(&Family::ThesisCubic, Affine::rational(Rational::from((1, 3))), "1/3", &pairs, false)?;
//! let e = evaluate(&at, Arithmetic::Digits(30), "the thesis basis")?;
//! assert!(e.values.iter().all(|v| v.digits() >= 30));
//! # Ok::<(), trig_core::CoreError>(())
//! ```

use rug::Rational;

use crate::basis::Basis;
use crate::certified::{
    self, CheckedF64, F64_CHECK_DIGITS, Stop, at_bits, check_domain, check_f64, to_digits,
    to_significant_digits,
};
use crate::decimal::{Decimal, max_digits};
use crate::domain::Affine;
use crate::echo::echo;
use crate::error::Result;
use crate::interval::Interval;
use crate::scalar::Real;

/// The arithmetic of an evaluation.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Arithmetic {
    /// f64, each value with a certified error bound (or replaced by the
    /// certified value when f64 is off).
    F64,
    /// Intervals at a fixed precision: the digits that precision proves.
    Bits(u32),
    /// Intervals at increasing precision until this many significant
    /// digits are proved.
    Digits(usize),
}

/// Values computed from exact inputs, in any scalar.
pub trait Computation {
    /// The exact inputs with their names (an f64 evaluation checks that
    /// each fits f64).
    fn inputs(&self) -> Vec<(String, &Rational)>;

    /// The values in the scalar `make` builds from exact rationals.
    fn compute<T: Real>(&self, make: &dyn Fn(&Rational) -> T) -> Result<Vec<T>>;
}

/// One certified value.
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    /// An f64 result checked against the exact value.
    F64(CheckedF64),
    /// The proved digits of an enclosure.
    Proved(Decimal),
}

impl Value {
    /// Proved significant digits (`usize::MAX` for an exact value or an
    /// accurate f64 result, whose error is bounded instead).
    pub fn digits(&self) -> usize {
        match self {
            Value::F64(CheckedF64::Accurate { .. }) => usize::MAX,
            Value::F64(CheckedF64::Replaced { decimal, .. }) | Value::Proved(decimal) => {
                decimal.digits()
            }
        }
    }
}

/// The values of an evaluation and how they were proved.
#[derive(Debug, Clone, PartialEq)]
pub struct Evaluated {
    pub values: Vec<Value>,
    /// The working precision of the last step, in bits.
    pub bits: u32,
    /// Why the precision was not raised further, when the digits asked
    /// for were not all proved.
    pub stopped: Option<Stop>,
}

impl Evaluated {
    /// How many values fall short of `n` proved significant digits (exact
    /// values and accurate f64 results never do).
    pub fn short_of(&self, n: usize) -> usize {
        self.values.iter().filter(|v| v.digits() < n).count()
    }
}

/// The values of `computation` in `arithmetic`; `what` names it in errors.
/// In f64 an input that f64 cannot hold is an error
/// ([`crate::CoreError::NotRepresentable`]).
pub fn evaluate(
    computation: &impl Computation,
    arithmetic: Arithmetic,
    what: &str,
) -> Result<Evaluated> {
    let enclose = |bits: u32| computation.compute(&|q: &Rational| Interval::from_rational(bits, q));
    let proved = |values: &[Interval], max: usize| -> Vec<Value> {
        values
            .iter()
            .map(|v| Value::Proved(v.decimal(max)))
            .collect()
    };
    match arithmetic {
        Arithmetic::F64 => {
            for (name, q) in computation.inputs() {
                certified::to_f64(q, &name)?;
            }
            let exact = to_digits(F64_CHECK_DIGITS, what, enclose)?;
            // f64 failures (a rounded divisor that is exactly zero) leave
            // the certified values in place
            let floats = computation
                .compute(&|q: &Rational| q.to_f64())
                .unwrap_or_else(|_| vec![f64::NAN; exact.values.len()]);
            Ok(Evaluated {
                values: check_f64(&floats, &exact.values)
                    .into_iter()
                    .map(Value::F64)
                    .collect(),
                bits: exact.bits,
                stopped: None,
            })
        }
        Arithmetic::Bits(bits) => {
            let mut f = enclose;
            let e = at_bits(bits, what, &mut f)?;
            Ok(Evaluated {
                values: proved(&e.values, max_digits(bits)),
                bits,
                stopped: None,
            })
        }
        Arithmetic::Digits(n) => {
            let e = to_significant_digits(n, what, enclose)?;
            Ok(Evaluated {
                values: proved(&e.values, n),
                bits: e.bits,
                stopped: e.stopped,
            })
        }
    }
}

/// The functions of a basis at one exact point (a rational or a rational
/// multiple of π) with exact parameters, read and checked.
#[derive(Debug, Clone)]
pub struct BasisAt<'a, B: ?Sized> {
    basis: &'a B,
    x: Affine,
    params: Vec<Affine>,
    /// The point as typed (for messages).
    x_text: String,
    /// Functions known to be exactly 0 — identically at the parameter
    /// values, or at the point (decided exactly by the caller): computed as
    /// an exact 0.
    zero: Vec<bool>,
}

impl<'a, B: Basis + ?Sized> BasisAt<'a, B> {
    /// The point `x` (typed as `x_text`) with the parameters read from
    /// `name=value` pairs ([`crate::Described::params_from_pairs`]);
    /// parameters outside their published range and a point outside the
    /// domain are errors unless `allow_outside`.
    pub fn new(
        basis: &'a B,
        x: Affine,
        x_text: &str,
        pairs: &[(String, String)],
        allow_outside: bool,
    ) -> Result<Self> {
        let params = basis.params_from_pairs(pairs, allow_outside)?;
        if !allow_outside {
            check_domain(&basis.domain(), &x, &params, x_text)?;
        }
        Ok(BasisAt {
            basis,
            x,
            params,
            x_text: x_text.to_string(),
            zero: Vec::new(),
        })
    }

    /// The same with the functions marked in `zero` (by index) known to be
    /// exactly 0 — identically at the parameter values, or at the point;
    /// decided in the exact ring, which this crate does not hold — computed
    /// as an exact 0: the
    /// value is `0`, exact, in every arithmetic, and no precision is spent
    /// on it.
    pub fn with_zeros(mut self, zero: Vec<bool>) -> Self {
        self.zero = zero;
        self
    }

    /// True for the `i`-th function when it is known to be exactly 0
    /// ([`BasisAt::with_zeros`]).
    pub fn is_zero(&self, i: usize) -> bool {
        self.zero.get(i).copied().unwrap_or(false)
    }

    /// The exact parameter values, in the basis' order.
    pub fn params(&self) -> &[Affine] {
        &self.params
    }
}

impl<B: Basis + ?Sized> Computation for BasisAt<'_, B> {
    fn inputs(&self) -> Vec<(String, &Rational)> {
        let point = format!("the point {}", echo(&self.x_text));
        named_affine(&self.basis.param_names(), &self.params)
            .into_iter()
            .chain([(point.clone(), &self.x.constant), (point, &self.x.pi)])
            .collect()
    }

    fn compute<T: Real>(&self, make: &dyn Fn(&Rational) -> T) -> Result<Vec<T>> {
        let zero = make(&Rational::new());
        let x = self.x.eval(&zero, &[]);
        let p: Vec<T> = self.params.iter().map(|a| a.eval(&zero, &[])).collect();
        let mut values = self.basis.eval(&self.basis.domain().atoms(&x), &p);
        for (v, z) in values.iter_mut().zip(&self.zero) {
            if *z {
                *v = zero.clone();
            }
        }
        Ok(values)
    }
}

/// Exact parameter values `c + q·π` as named rationals (both parts).
pub fn named_affine<'a>(names: &[String], params: &'a [Affine]) -> Vec<(String, &'a Rational)> {
    names
        .iter()
        .zip(params)
        .flat_map(|(n, p)| [(n.clone(), &p.constant), (n.clone(), &p.pi)])
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{CoreError, Family};

    fn q(n: i64, d: i64) -> Rational {
        Rational::from((n, d))
    }

    fn thesis_at(x: Rational, m: &str) -> Result<BasisAt<'static, Family>> {
        let pairs = [("m".to_string(), m.to_string())];
        BasisAt::new(
            &Family::ThesisCubic,
            Affine::rational(x.clone()),
            &x.to_string(),
            &pairs,
            false,
        )
    }

    #[test]
    fn every_arithmetic_encloses_the_same_values() {
        let at = thesis_at(q(1, 3), "1/2").unwrap();
        let f64s = evaluate(&at, Arithmetic::F64, "t").unwrap();
        let digits = evaluate(&at, Arithmetic::Digits(40), "t").unwrap();
        assert_eq!(f64s.values.len(), 4);
        for (a, b) in f64s.values.iter().zip(&digits.values) {
            let (Value::F64(CheckedF64::Accurate { text, .. }), Value::Proved(d)) = (a, b) else {
                panic!("{a:?} {b:?}");
            };
            assert!(d.digits() >= 40, "{d}");
            let (x, y): (f64, f64) = (text.parse().unwrap(), d.to_string().parse().unwrap());
            assert!((x - y).abs() <= 1e-15, "{x} {y}");
        }
        // partition of unity, to the digits proved
        let sum: f64 = digits
            .values
            .iter()
            .map(|v| match v {
                Value::Proved(d) => d.to_string().parse::<f64>().unwrap(),
                Value::F64(_) => unreachable!(),
            })
            .sum();
        assert!((sum - 1.0).abs() < 1e-15);
    }

    #[test]
    fn a_fixed_precision_proves_no_more_than_it_can() {
        let at = thesis_at(q(1, 3), "1/2").unwrap();
        let e = evaluate(&at, Arithmetic::Bits(64), "t").unwrap();
        assert_eq!(e.bits, 64);
        assert!(e.values.iter().all(|v| v.digits() <= max_digits(64)));
        assert_eq!(e.short_of(max_digits(64) + 1), 4);
        assert_eq!(e.short_of(1), 0);
    }

    #[test]
    fn inputs_beyond_f64_and_points_outside_the_domain_are_errors() {
        let huge: Rational = crate::parse_exact("1e400").unwrap();
        let pairs = [("m".to_string(), "1/2".to_string())];
        let at = BasisAt::new(
            &Family::ThesisCubic,
            Affine::rational(huge),
            "1e400",
            &pairs,
            true,
        )
        .unwrap();
        assert!(matches!(
            evaluate(&at, Arithmetic::F64, "t"),
            Err(CoreError::NotRepresentable { .. })
        ));
        assert!(matches!(
            thesis_at(q(9, 1), "1/2"),
            Err(CoreError::PointOutsideDomain { .. })
        ));
        assert!(matches!(
            thesis_at(q(1, 3), "7"),
            Err(CoreError::OutOfRange { .. })
        ));
    }
}
