//! A claim's range whose ends are printed as exact numbers beyond the
//! rationals: `[-1, 2 + 2*sqrt(2)]` (squared Han: nonnegative exactly up
//! to the root 2 + 2√2 of λ² − 4λ − 4), `[1, pi]`, `(0, (1 + sqrt(5))/2)`.
//!
//! Such a range is decided through rational ranges next to it
//! (`trig_judge::exact_ends`): the printed range rounded outward (a claim
//! that holds there holds on the printed range) and inward (a
//! counterexample there lies inside the printed range); where the claim
//! turns on the end itself, an end `a + b√k` is compared exactly with the
//! exact end of the maximal set ([`ExactEnd::algebraic`]).

use rug::Rational;
use trig_certify::algebraic::Algebraic;
use trig_core::{End, Interval, ParamRange, Ring};
use trig_symbolic::Sym;

use crate::spec::Spec;

/// Precision (bits) of the enclosure of an end.
const BITS: u32 = 128;

/// The grid the rounded ends lie on: decimals of 12 places, so a rounded
/// range is readable and within 10⁻¹² of the printed one.
const GRID: u64 = 1_000_000_000_000;

/// `q` rounded to the grid, up or down.
fn on_grid(q: &Rational, up: bool) -> Rational {
    let scaled = Rational::from(q * GRID);
    let k = if up { scaled.ceil() } else { scaled.floor() };
    Rational::from((k.numer().clone(), rug::Integer::from(GRID)))
}

/// One end of an [`ExactRange`].
#[derive(Debug, Clone, PartialEq)]
pub enum ExactEnd {
    /// `-inf` or `+inf`.
    Unbounded,
    /// A number: `value` exactly (a rational, or with `pi` and square
    /// roots), excluded when `open`.
    Finite {
        text: String,
        value: Sym,
        open: bool,
    },
}

/// A range of a parameter with at least one end beyond the rationals.
#[derive(Debug, Clone, PartialEq)]
pub struct ExactRange {
    /// The parameter's ASCII name.
    pub name: String,
    /// The range as written.
    pub text: String,
    pub lo: ExactEnd,
    pub hi: ExactEnd,
}

impl ExactEnd {
    /// The exact rational value, if the end is one.
    pub fn rational(&self) -> Option<Rational> {
        match self {
            ExactEnd::Finite { value, .. } => value.as_rational(),
            ExactEnd::Unbounded => None,
        }
    }

    /// The value `a + b√k` as a real algebraic number (`None` for an end
    /// with `π`, several square roots, or none).
    pub fn algebraic(&self) -> Option<Algebraic> {
        let ExactEnd::Finite { value, .. } = self else {
            return None;
        };
        if let Some(q) = value.as_rational() {
            return Some(Algebraic::surd(&q, &Rational::new(), 1));
        }
        let vars = value.variables();
        let [root] = vars.iter().collect::<Vec<_>>()[..] else {
            return None;
        };
        let k: u32 = root
            .strip_prefix("sqrt(")?
            .strip_suffix(')')?
            .parse()
            .ok()?;
        let at = |v: i64| value.try_subs(root, &Sym::int(v)).ok()?.as_rational();
        let a = at(0)?;
        let b = at(1)? - &a;
        let rebuilt = Sym::rational(a.clone()) + &(Sym::rational(b.clone()) * &Sym::var(root));
        (rebuilt - value)
            .is_zero()
            .then(|| Algebraic::surd(&a, &b, k))
    }

    /// Rational bounds `lo ≤ value ≤ hi` (`lo = hi` for a rational).
    fn enclosure(&self) -> Option<(Rational, Rational)> {
        let ExactEnd::Finite { value, .. } = self else {
            return None;
        };
        if let Some(q) = value.as_rational() {
            return Some((q.clone(), q));
        }
        let like = Interval::from_rational(BITS, &Rational::new());
        let x = value
            .eval(&like, &|name: &str| match name {
                "pi" => Some(like.pi()),
                _ => {
                    let k: i64 = name
                        .strip_prefix("sqrt(")?
                        .strip_suffix(')')?
                        .parse()
                        .ok()?;
                    like.int(k).try_sqrt()
                }
            })
            .ok()?;
        // the ends of an outward-rounded enclosure, exactly
        Some((x.lo().to_rational()?, x.hi().to_rational()?))
    }
}

impl ExactRange {
    /// The range with each end beyond the rationals replaced by a rational
    /// just outside it (`outward`: the rounded range contains the printed
    /// one) or just inside it; rational and infinite ends as printed.
    pub fn rounded(&self, outward: bool) -> Option<ParamRange> {
        let end = |e: &ExactEnd, lower: bool| -> Option<End> {
            Some(match e {
                ExactEnd::Unbounded => End::Unbounded,
                ExactEnd::Finite { open, .. } => {
                    let (lo, hi) = e.enclosure()?;
                    if lo == hi {
                        if *open {
                            End::Open(lo)
                        } else {
                            End::Closed(lo)
                        }
                    } else if lower == outward {
                        End::Closed(on_grid(&lo, false))
                    } else {
                        End::Closed(on_grid(&hi, true))
                    }
                }
            })
        };
        let range = ParamRange {
            lo: end(&self.lo, true)?,
            hi: end(&self.hi, false)?,
            pi: false,
        };
        let ordered = match (range.lo.value(), range.hi.value()) {
            (Some(a), Some(b)) => a < b,
            _ => true,
        };
        ordered.then_some(range)
    }

    /// The value of a one-point range `[v, v]`, as written (it fixes the
    /// value, like a rational one).
    pub fn point(&self) -> Option<String> {
        match (&self.lo, &self.hi) {
            (
                ExactEnd::Finite {
                    value: a,
                    open: false,
                    text,
                },
                ExactEnd::Finite {
                    value: b,
                    open: false,
                    ..
                },
            ) if (a.clone() - b).is_zero() => Some(text.clone()),
            _ => None,
        }
    }

    /// Reads `[a, b]`, `(a, b]`… whose ends are numbers with `pi` or
    /// square roots (at least one end not rational); `None` when the text is
    /// not such a range.
    pub fn read(spec: &Spec, name: &str, text: &str) -> Option<ExactRange> {
        let t = text.trim();
        let lo_open = match t.chars().next()? {
            '[' => false,
            '(' => true,
            _ => return None,
        };
        let hi_open = match t.chars().last()? {
            ']' => false,
            ')' => true,
            _ => return None,
        };
        let (a, b) = t[1..t.len() - 1].split_once(',')?;
        let end = |s: &str, open: bool, below: bool| -> Option<ExactEnd> {
            let s = s.trim();
            let bare = s.replace('−', "-");
            let infinite = ["inf", "∞", "infinity"];
            match bare.strip_prefix(['-', '+']) {
                Some(rest) if infinite.contains(&rest) => {
                    return (bare.starts_with('-') == below).then_some(ExactEnd::Unbounded);
                }
                _ if infinite.contains(&bare.as_str()) => {
                    return (!below).then_some(ExactEnd::Unbounded);
                }
                _ => {}
            }
            let value = spec.parse_formula(s, &[]).ok()?;
            value
                .variables()
                .iter()
                .all(|v| v == "pi" || v.starts_with("sqrt("))
                .then(|| ExactEnd::Finite {
                    text: s.to_string(),
                    value,
                    open,
                })
        };
        let range = ExactRange {
            name: name.to_string(),
            text: t.to_string(),
            lo: end(a, lo_open, true)?,
            hi: end(b, hi_open, false)?,
        };
        let beyond = |e: &ExactEnd| matches!(e, ExactEnd::Finite { .. }) && e.rational().is_none();
        (beyond(&range.lo) || beyond(&range.hi)).then_some(range)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::cmp::Ordering;

    fn spec() -> Spec {
        Spec::from_str_named(
            "id = \"x\"\ntitle = \"x\"\ncitation = \"x\"\nvariable = \"angle\"\n[[parameters]]\nname = \"lambda\"\nrange = \"[-1, 1]\"\n[[functions]]\nname = \"b0\"\nformula = \"1 - lambda*s\"\n[[functions]]\nname = \"b1\"\nformula = \"lambda*s\"\n",
            "x.toml",
        )
        .expect("a spec")
    }

    #[test]
    fn ends_beyond_the_rationals_are_read_rounded_and_compared() {
        let spec = spec();
        let r = ExactRange::read(&spec, "lambda", "[-1, 2 + 2*sqrt(2))").expect("read");
        assert_eq!(r.lo.rational(), Some(Rational::from(-1)));
        let ExactEnd::Finite { open, .. } = &r.hi else {
            panic!("{r:?}")
        };
        assert!(*open);
        // rounded outward and inward on the grid of 10⁻¹², the rational end
        // kept as printed
        let q = |n: i64, d: i64| Rational::from((n, d));
        let outer = r.rounded(true).expect("outer");
        let inner = r.rounded(false).expect("inner");
        assert_eq!(outer.lo, End::Closed(q(-1, 1)));
        assert_eq!(
            outer.hi,
            End::Closed(q(4_828_427_124_747, 1_000_000_000_000))
        );
        assert_eq!(
            inner.hi,
            End::Closed(q(4_828_427_124_746, 1_000_000_000_000))
        );
        let mut end = r.hi.algebraic().expect("a surd");
        assert_eq!(end.poly_text("x"), "x^2 - 4*x - 4");
        assert_eq!(
            end.cmp(&mut Algebraic::surd(&q(2, 1), &q(2, 1), 2)),
            Ordering::Equal
        );
        // (1 + sqrt(5))/2, and pi: read, but pi has no algebraic form
        let golden = ExactRange::read(&spec, "lambda", "[0, (1 + sqrt(5))/2]").expect("read");
        assert_eq!(
            golden.hi.algebraic().expect("a surd").poly_text("x"),
            "x^2 - x - 1"
        );
        let pi = ExactRange::read(&spec, "lambda", "[1, pi]").expect("read");
        assert!(pi.hi.algebraic().is_none());
        assert!(pi.rounded(true).is_some());
        // rational ends only, an unknown name, a reversed infinity: not such a range
        for text in ["[0, 1]", "[0, 2 + x]", "[+inf, 1]", "0, 1"] {
            assert!(ExactRange::read(&spec, "lambda", text).is_none(), "{text}");
        }
        // a point fixes the value; reversed ends leave nothing inside
        let point = ExactRange::read(&spec, "lambda", "[sqrt(2), 2/sqrt(2)]").expect("read");
        assert_eq!(point.point().as_deref(), Some("sqrt(2)"));
        let reversed = ExactRange::read(&spec, "lambda", "[sqrt(3), sqrt(2)]").expect("read");
        assert!(reversed.point().is_none() && reversed.rounded(false).is_none());
    }
}
