//! A claim's region of parameters as a paper prints it, by linear
//! inequalities: `region = "lambda >= 0, mu >= 0, lambda + mu <= 4"`.
//!
//! Fourier–Motzkin elimination in the parameters' declared order turns it
//! into what `ranges` states: the first parameter between two numbers, each
//! later one between two ends linear in the earlier ones
//! (`λ ∈ [0, 4]`, `μ ∈ [0, 4 − λ]`), which the claim is then decided on
//! exactly as if those `ranges` were written ([`crate::given`]). The
//! projection is exact: the region is `{p₁ ∈ [a, b], p₂ ∈ [l₂(p₁), u₂(p₁)],
//! …}` exactly when, at each step, one bound remains on each side (a bound
//! that is the larger of two lines, `μ ≥ max(0, λ − 1)`, is refused: state
//! such a region as claims on its pieces).

use rug::Rational;
use trig_symbolic::Sym;

use crate::spec::Spec;

/// `Σ coef·pᵢ + constant`, over the parameters in declared order.
#[derive(Debug, Clone, PartialEq)]
struct Linear {
    coef: Vec<Rational>,
    constant: Rational,
}

impl Linear {
    fn is_constant(&self) -> bool {
        self.coef.iter().all(|c| *c == 0)
    }

    /// `self · k`.
    fn scaled(&self, k: &Rational) -> Linear {
        Linear {
            coef: self.coef.iter().map(|c| Rational::from(c * k)).collect(),
            constant: Rational::from(&self.constant * k),
        }
    }

    /// `self − other`.
    fn minus(&self, other: &Linear) -> Linear {
        Linear {
            coef: self
                .coef
                .iter()
                .zip(&other.coef)
                .map(|(a, b)| Rational::from(a - b))
                .collect(),
            constant: Rational::from(&self.constant - &other.constant),
        }
    }

    /// The form as formula text (`4 - lambda`), in the parameters' names.
    fn text(&self, names: &[&str]) -> String {
        let sum = self
            .coef
            .iter()
            .zip(names)
            .filter(|(c, _)| **c != 0)
            .fold(Sym::rational(self.constant.clone()), |acc, (c, n)| {
                acc + &(Sym::rational(c.clone()) * &Sym::var(n))
            });
        sum.to_string()
    }
}

/// The ranges a region states, as `ranges` would write them: `(name,
/// "[lo, hi]")` for each parameter it bounds, in declared order (the first
/// with numbers, the later ones with ends in the earlier ones); or why the
/// region cannot be read so.
/// Values the claim fixes (`at`) are substituted into the inequalities
/// first (a line `mu = lambda` keeps them linear).
pub(crate) fn region_ranges(
    spec: &Spec,
    text: &str,
    fixed: &[(String, Sym)],
) -> Result<Vec<(String, String)>, String> {
    let names: Vec<&str> = spec.params.iter().map(|p| p.name.as_str()).collect();
    // each constraint as `form ≥ 0`
    let mut forms: Vec<Linear> = Vec::new();
    for part in text.split(',').map(str::trim).filter(|p| !p.is_empty()) {
        forms.push(constraint(spec, &names, part, fixed)?);
    }
    if forms.is_empty() {
        return Err(
            "an empty region: give inequalities, e.g. \"lambda >= 0, mu >= 0, lambda + mu <= 4\""
                .into(),
        );
    }
    let used: Vec<usize> = (0..names.len())
        .filter(|&k| forms.iter().any(|f| f.coef[k] != 0))
        .collect();
    // backward: every bound of each parameter, the projection of the rest
    // (each lower bound ≤ each upper bound) onto the earlier parameters
    let mut sides: Vec<(usize, Vec<Linear>, Vec<Linear>)> = Vec::new();
    for &k in used.iter().rev() {
        let (mut lower, mut upper, mut rest) = (Vec::new(), Vec::new(), Vec::new());
        for f in forms {
            let a = f.coef[k].clone();
            if a == 0 {
                rest.push(f);
                continue;
            }
            // a·p + r ≥ 0: p ≥ −r/a (a > 0) or p ≤ r/(−a) (a < 0)
            let mut r = f.clone();
            r.coef[k] = Rational::new();
            let bound = r.scaled(&Rational::from(-1 / &a));
            let side: &mut Vec<Linear> = if a > 0 { &mut lower } else { &mut upper };
            if !side.contains(&bound) {
                side.push(bound);
            }
        }
        for (bounds, side) in [(&lower, "below"), (&upper, "above")] {
            if bounds.is_empty() {
                return Err(format!(
                    "the region does not bound `{}` from {side}: add an inequality for it",
                    names[k]
                ));
            }
        }
        for lo in &lower {
            rest.extend(upper.iter().map(|hi| hi.minus(lo)));
        }
        sides.push((k, lower, upper));
        forms = rest;
    }
    // what is left is free of every parameter: each a number ≥ 0
    if let Some(f) = forms.iter().find(|f| f.constant < 0) {
        return Err(format!(
            "the region is empty ({} < 0 after eliminating its parameters)",
            f.constant
        ));
    }
    // forward: each parameter's one bound per side, a bound implied by
    // another over the box enclosing the earlier parameters left out
    sides.reverse();
    let mut enclosure: Vec<Option<(Rational, Rational)>> = vec![None; names.len()];
    let mut bounds: Vec<(usize, Linear, Linear)> = Vec::new();
    for (k, lower, upper) in sides {
        let lo = one_bound(lower, &enclosure, names[k], "below", true)?;
        let hi = one_bound(upper, &enclosure, names[k], "above", false)?;
        enclosure[k] = Some((
            extreme(&lo, &enclosure, false),
            extreme(&hi, &enclosure, true),
        ));
        bounds.push((k, lo, hi));
    }
    // an end in a parameter that itself has ends in others would not be
    // linear once that one is rewritten (a simplex of three parameters)
    for (k, lo, hi) in &bounds {
        let uses = |j: usize| lo.coef[j] != 0 || hi.coef[j] != 0;
        if let Some((j, ..)) = bounds
            .iter()
            .find(|(j, l, h)| uses(*j) && !(l.is_constant() && h.is_constant()))
        {
            return Err(format!(
                "the ends of `{}` depend on `{}`, whose own ends depend on other parameters: regions whose ends chain through three parameters are not supported (state them as claims on boxes of the outer parameters)",
                names[*k], names[*j]
            ));
        }
    }
    Ok(bounds
        .into_iter()
        .map(|(k, lo, hi)| {
            (
                names[k].to_string(),
                format!("[{}, {}]", lo.text(&names), hi.text(&names)),
            )
        })
        .collect())
}

/// The least (`!most`) or greatest value of `form` over the box
/// `enclosure` of the parameters it involves (a corner of the box).
fn extreme(form: &Linear, enclosure: &[Option<(Rational, Rational)>], most: bool) -> Rational {
    form.coef
        .iter()
        .zip(enclosure)
        .filter(|(c, _)| **c != 0)
        .fold(form.constant.clone(), |acc, (c, range)| {
            let (lo, hi) = range.clone().unwrap_or_default();
            let at = if (*c > 0) == most { hi } else { lo };
            acc + Rational::from(c * &at)
        })
}

/// The one bound of a parameter on one side: a bound that another implies
/// over the box `enclosure` of the earlier parameters (`μ ≤ 1` beside
/// `μ ≤ 1 − λ` for `λ ∈ [0, 1]`) is left out; two that remain are refused
/// (the region's edge bends there).
fn one_bound(
    bounds: Vec<Linear>,
    enclosure: &[Option<(Rational, Rational)>],
    name: &str,
    side: &str,
    lower: bool,
) -> Result<Linear, String> {
    // `b` is implied by `other` when the other is at least as tight
    // everywhere: above it (a lower bound) or below it (an upper one)
    let implied = |b: &Linear, other: &Linear| {
        let gap = if lower {
            other.minus(b)
        } else {
            b.minus(other)
        };
        extreme(&gap, enclosure, false) >= 0
    };
    let mut kept: Vec<Linear> = Vec::new();
    for (i, b) in bounds.iter().enumerate() {
        let redundant = bounds
            .iter()
            .enumerate()
            .any(|(j, o)| j != i && implied(b, o) && !(implied(o, b) && j > i));
        if !redundant {
            kept.push(b.clone());
        }
    }
    match kept.as_slice() {
        [one] => Ok(one.clone()),
        _ => Err(format!(
            "`{name}` is bounded from {side} by {} lines at once, neither implied by the other: the region's edge bends there (state the region as claims on its pieces, each with one bound per side)",
            kept.len()
        )),
    }
}

/// One inequality `A >= B`, `A <= B` (or `≥`, `≤`) as `form ≥ 0`, linear
/// in the parameters with rational coefficients.
fn constraint(
    spec: &Spec,
    names: &[&str],
    part: &str,
    fixed: &[(String, Sym)],
) -> Result<Linear, String> {
    let ops = [(">=", true), ("≥", true), ("<=", false), ("≤", false)];
    let Some((at, op, greater)) = ops
        .iter()
        .find_map(|(op, g)| part.find(op).map(|at| (at, *op, *g)))
    else {
        return Err(format!(
            "`{part}`: an inequality is `A >= B` or `A <= B` (a line is `at = {{ NAME = \"…\" }}`)"
        ));
    };
    let side = |s: &str| {
        spec.parse_formula(s, &[])
            .map_err(|e| format!("`{}`: {}", s.trim(), e.message))
    };
    let (a, b) = (side(&part[..at])?, side(&part[at + op.len()..])?);
    let d = fixed
        .iter()
        .try_fold(if greater { a - &b } else { b - &a }, |d, (name, v)| {
            d.try_subs(name, v)
        })
        .map_err(|e| format!("`{part}` at the fixed values: {e}"))?;
    let not_linear = || {
        format!(
            "`{part}`: a region's inequalities are linear in the parameters with rational coefficients"
        )
    };
    let mut form = Linear {
        coef: vec![Rational::new(); names.len()],
        constant: Rational::new(),
    };
    let mut rest = d.clone();
    for v in d.variables() {
        let k = names.iter().position(|n| *n == v).ok_or_else(not_linear)?;
        let c = d.diff(&v).as_rational().ok_or_else(not_linear)?;
        rest = rest - &(Sym::rational(c.clone()) * &Sym::var(&v));
        form.coef[k] = c;
    }
    form.constant = rest.as_rational().ok_or_else(not_linear)?;
    Ok(form)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spec() -> Spec {
        Spec::from_str_named(
            "id = \"r\"\ncitation = \"test\"\nvariable = \"polynomial\"\n[[parameters]]\nname = \"lambda\"\nrange = \"[0, 9]\"\n[[parameters]]\nname = \"mu\"\nrange = \"[0, 9]\"\n[[parameters]]\nname = \"nu\"\nrange = \"[0, 9]\"\n[[functions]]\nname = \"b0\"\nformula = \"1 - t\"\n[[functions]]\nname = \"b1\"\nformula = \"t\"\n",
            "r",
        )
        .expect("spec")
    }

    /// The ranges a region states, unwrapped.
    fn ranges(text: &str) -> Vec<(String, String)> {
        region_ranges(&spec(), text, &[]).unwrap()
    }

    /// `(name, range)` as [`region_ranges`] gives it.
    fn range(name: &str, text: &str) -> (String, String) {
        (name.to_string(), text.to_string())
    }

    #[test]
    fn a_triangle_is_a_range_and_a_range_in_the_first_parameter() {
        assert_eq!(
            ranges("lambda >= 0, mu >= 0, lambda + mu <= 4"),
            [range("lambda", "[0, 4]"), range("mu", "[0, -lambda + 4]")]
        );
        // redundant numbers: the tighter one on each side
        assert_eq!(
            ranges("lambda >= 0, lambda >= 1/2, lambda <= 3, 2*lambda <= 5"),
            [range("lambda", "[1/2, 5/2]")]
        );
        // the triangle as papers often print it, μ ≤ 1 implied by μ ≤ 1 − λ
        assert_eq!(
            ranges("lambda >= 0, lambda <= 1, mu >= 0, mu <= 1, lambda + mu <= 1"),
            [range("lambda", "[0, 1]"), range("mu", "[0, -lambda + 1]")]
        );
        // a bound implied over the other parameter's range: μ ≤ 5
        assert_eq!(
            ranges("lambda >= -2, lambda <= 1, mu >= -2, lambda + mu <= -1, mu <= 5")[1],
            range("mu", "[-2, -lambda - 1]")
        );
    }

    #[test]
    fn regions_that_are_not_one_bound_per_side_are_refused() {
        let bent = region_ranges(
            &spec(),
            "lambda >= 0, lambda <= 2, mu >= 0, mu >= lambda - 1, mu <= 3",
            &[],
        )
        .unwrap_err();
        assert!(bent.contains("2 lines at once, neither implied"), "{bent}");
        let open =
            region_ranges(&spec(), "lambda >= 0, lambda <= 1, lambda + mu >= 4", &[]).unwrap_err();
        assert!(open.contains("from above"), "{open}");
        let empty = region_ranges(&spec(), "lambda >= 3, lambda <= 1", &[]).unwrap_err();
        assert!(empty.contains("empty"), "{empty}");
        let curved = region_ranges(&spec(), "lambda*mu <= 1", &[]).unwrap_err();
        assert!(curved.contains("linear"), "{curved}");
        let line = region_ranges(&spec(), "mu = 3 - lambda", &[]).unwrap_err();
        assert!(line.contains("at = {"), "{line}");
        // a simplex of three parameters chains its ends: refused, said so
        let simplex = region_ranges(
            &spec(),
            "lambda >= 0, mu >= 0, nu >= 0, lambda + mu + nu <= 1",
            &[],
        )
        .unwrap_err();
        assert!(simplex.contains("three parameters"), "{simplex}");
    }

    #[test]
    fn fixed_values_are_substituted_first() {
        // μ = 0 on the triangle: λ ∈ [0, 4], μ gone
        let at = [("mu".to_string(), Sym::zero())];
        let r = region_ranges(&spec(), "lambda >= 0, mu >= 0, lambda + mu <= 4", &at).unwrap();
        assert_eq!(r, [range("lambda", "[0, 4]")]);
        // the line μ = λ: 2λ ≤ 4
        let at = [("mu".to_string(), Sym::var("lambda"))];
        let r = region_ranges(&spec(), "lambda >= 0, mu >= 0, lambda + mu <= 4", &at).unwrap();
        assert_eq!(r, [range("lambda", "[0, 2]")]);
    }
}
