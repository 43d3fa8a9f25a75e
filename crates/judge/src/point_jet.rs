//! The derivatives of a formula at an exact point by Taylor jets: `f` in
//! the atoms `s = sin ωx`, `c = cos ωx`, `t = x`, `E = exp κx` (and
//! constants) evaluated over truncated series in `h` at `x = x₀ + h`,
//! `f⁽ᵏ⁾(x₀) = k!·[hᵏ] f` — the same exact value as differentiating `f`
//! symbolically and substituting the point, without forming the
//! derivative of a large quotient (seed 000's `Q_i = w_i F_i / Σ w F` with
//! general coefficients: milliseconds where the symbolic derivative takes
//! minutes).

use trig_core::{Atoms, Ring};
use trig_deriv::{Jet, angle_atoms};
use trig_symbolic::Sym;

/// Orders `0 … 5` are formed by jets, of the fewest coefficients the
/// order needs.
pub const ORDERS: usize = 6;

/// `f⁽ᵏ⁾` at the point whose exact atoms are `at` (`at.t` the point
/// `x₀`), for `k < ORDERS`; `omega`, `kappa` the rates of the angle and the
/// exponential (`None`: no such atom). `None` where a denominator of `f`
/// vanishes at the point.
pub fn derivative_at(
    f: &Sym,
    order: usize,
    at: &Atoms<Sym>,
    omega: Option<&Sym>,
    kappa: Option<&Sym>,
) -> Option<Sym> {
    match order {
        0 => jet::<1>(f, order, at, omega, kappa),
        1 => jet::<2>(f, order, at, omega, kappa),
        2 => jet::<3>(f, order, at, omega, kappa),
        3 => jet::<4>(f, order, at, omega, kappa),
        4 => jet::<5>(f, order, at, omega, kappa),
        5 => jet::<ORDERS>(f, order, at, omega, kappa),
        _ => None,
    }
}

/// [`derivative_at`] with jets of `K > order` coefficients.
fn jet<const K: usize>(
    f: &Sym,
    order: usize,
    at: &Atoms<Sym>,
    omega: Option<&Sym>,
    kappa: Option<&Sym>,
) -> Option<Sym> {
    // `[hᵏ]` scaled by `rateᵏ`: a series in the angle `ε = ω·h`
    let scaled = |jet: &Jet<Sym, K>, rate: &Sym| {
        let mut power = Sym::one();
        let coeffs = jet.coeffs().clone().map(|c| {
            let v = c * &power;
            power = power.clone() * rate;
            v
        });
        Jet::from_coeffs(coeffs)
    };
    let one = Sym::one();
    let angle = angle_atoms::<Sym, K>(&at.s, &at.c, Sym::zero());
    let s = scaled(&angle.s, omega.unwrap_or(&one));
    let c = scaled(&angle.c, omega.unwrap_or(&one));
    // exp(κh) = Σ (κh)ᵏ/k!, times E₀
    let mut factorial = Sym::one();
    let e = Jet::from_coeffs(std::array::from_fn(|k| {
        if k > 0 {
            factorial = factorial.clone() * &Sym::int(k as i64);
        }
        let rate = kappa.cloned().unwrap_or_else(Sym::zero);
        at.e.clone() * &rate.powi(k as u32) / &factorial
    }));
    let t = Jet::variable(at.t.clone());
    let like = Jet::<Sym, K>::constant(Sym::zero());
    let jet = f
        .eval(&like, &|name: &str| match name {
            "s" if omega.is_some() => Some(s.clone()),
            "c" if omega.is_some() => Some(c.clone()),
            "t" => Some(t.clone()),
            "E" if kappa.is_some() => Some(e.clone()),
            other => Some(Jet::constant(Sym::var(other))),
        })
        .ok()?;
    Some(jet.derivative(order))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The jets give the symbolic derivative at the point, orders 0–5, for
    /// a quotient in `s`, `c`, `t` with a rate `ω = 3` and a symbol; a
    /// denominator vanishing at the point gives none.
    #[test]
    fn jets_give_the_symbolic_derivatives_at_a_point() {
        let (s, c, t, w) = (Sym::var("s"), Sym::var("c"), Sym::var("t"), Sym::var("w"));
        let omega = Sym::int(3);
        let f = (w.clone() * &s * &s + &t) / &(Sym::int(2) + &c + &(w * &s));
        let rules = [
            ("s", omega.clone() * &c),
            ("c", -(omega.clone() * &s)),
            ("t", Sym::one()),
        ];
        let at = Atoms {
            s: Sym::one(),
            c: Sym::zero(),
            t: Sym::var("x0"),
            e: Sym::one(),
        };
        let mut symbolic = f.clone();
        for k in 0..ORDERS {
            let expected = symbolic.subs("s", &at.s).subs("c", &at.c).subs("t", &at.t);
            let jet = derivative_at(&f, k, &at, Some(&omega), None).expect("defined");
            assert!((jet - &expected).is_zero(), "order {k}");
            symbolic = symbolic.derive(&rules);
        }
        assert!(derivative_at(&f, ORDERS, &at, Some(&omega), None).is_none());
        let pole = Sym::one() / &s;
        let origin = Atoms {
            s: Sym::zero(),
            c: Sym::one(),
            t: Sym::zero(),
            e: Sym::one(),
        };
        assert!(derivative_at(&pole, 1, &origin, Some(&omega), None).is_none());
    }
}
