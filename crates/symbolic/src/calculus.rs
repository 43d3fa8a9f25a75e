//! Derivations of [`Sym`]: partial derivatives, the angle derivative
//! `d/dθ` (`s ↦ c`, `c ↦ −s`) and `d/dt`.
//!
//! A derivation `D` is given by the images of some variables (all others
//! map to 0) and extended by the sum, product and quotient rules:
//! `D(N / Π fᵢ^eᵢ) = D(N)/Π fᵢ^eᵢ − N/Π fᵢ^eᵢ · Σ eᵢ·D(fᵢ)/fᵢ`.
//!
//! `D` is well defined on the quotient by `s² + c² − 1` exactly when
//! `s·D(s) + c·D(c) = 0`, which holds for `d/dθ` and for any `D` that
//! ignores `s` and `c`. For other images of `s`, `c` the result is the
//! derivative of the reduced representative.

use crate::poly::Poly;
use crate::sym::Sym;
use crate::var::{COS, SIN, T};

impl Sym {
    /// The partial derivative `∂/∂name` (for `s`, `c`: of the reduced
    /// representative, see [`Sym::derive`]).
    pub fn diff(&self, name: &str) -> Sym {
        self.derive(&[(name, Sym::int(1))])
    }

    /// The derivation with `D(name) = image` for the listed variables and
    /// `D(x) = 0` for all others, extended by the quotient rule
    /// `D(N / Π fᵢ^eᵢ) = D(N)/Π fᵢ^eᵢ − N/Π fᵢ^eᵢ · Σ eᵢ·D(fᵢ)/fᵢ`.
    ///
    /// Well defined on the quotient by `s² + c² − 1` exactly when
    /// `s·D(s) + c·D(c) = 0` (true for [`Sym::d_angle`] and whenever `s`, `c`
    /// are not listed); otherwise it differentiates the reduced
    /// representative.
    pub fn derive(&self, rules: &[(&str, Sym)]) -> Sym {
        let mut out = derive_poly(self.numerator(), rules) * &self.denominator_inverse();
        for (f, e) in self.denominator() {
            let df = derive_poly(f, rules);
            if df.is_zero() {
                continue;
            }
            let term = self.clone() * &df * &Sym::int(i64::from(*e)) / &Sym::from_poly(f.clone());
            out = out - &term;
        }
        out
    }

    /// `d/dθ` with `s = sin θ`, `c = cos θ`: `s ↦ c`, `c ↦ −s`.
    pub fn d_angle(&self) -> Sym {
        self.derive(&[(SIN, Sym::var(COS)), (COS, -Sym::var(SIN))])
    }

    /// `d/dt`: `t ↦ 1`.
    pub fn d_t(&self) -> Sym {
        self.derive(&[(T, Sym::int(1))])
    }
}

/// `D(p) = Σ ∂p/∂v · D(v)` over the listed variables.
fn derive_poly(p: &Poly, rules: &[(&str, Sym)]) -> Sym {
    rules.iter().fold(Sym::zero(), |acc, (name, image)| {
        let partial = p.diff(name);
        if partial.is_zero() || image.is_zero() {
            acc
        } else {
            acc + &(Sym::from_poly(partial) * image)
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(n: &str) -> Sym {
        Sym::var(n)
    }

    #[test]
    fn angle_derivative() {
        assert_eq!(v("s").d_angle(), v("c"));
        assert_eq!(v("c").d_angle(), -v("c").d_angle().d_angle().d_angle());
        assert_eq!(v("c").d_angle(), -v("s"));
        let d = (v("s") * &v("c")).d_angle();
        assert!((d.clone() - &(v("c") * &v("c") - &(v("s") * &v("s")))).is_zero());
        assert!((d - &(Sym::int(1) - &(Sym::int(2) * &v("s") * &v("s")))).is_zero());
        // d/dθ (s/c) = 1/c²
        assert_eq!(
            (v("s") / &v("c")).d_angle(),
            Sym::int(1) / &(v("c") * &v("c"))
        );
    }

    #[test]
    fn quotient_rule() {
        let b1 = v("beta") + &Sym::int(1);
        let d = (v("beta") / &b1).diff("beta");
        assert_eq!(d, Sym::int(1) / &(b1.clone() * &b1));
        assert_eq!(d.denominator().get(b1.numerator()), Some(&2));
        assert_eq!(d.numerator(), &Poly::one());
        // d/dm of m²/(m s + 1)³
        let f = v("m") * &v("s") + &Sym::int(1);
        let x = v("m") * &v("m") / &(f.clone() * &f * &f);
        let expected = Sym::int(2) * &v("m") / &(f.clone() * &f * &f)
            - &(Sym::int(3) * &v("m") * &v("m") * &v("s") / &(f.clone() * &f * &f * &f));
        assert_eq!(x.diff("m"), expected);
    }

    #[test]
    fn t_derivative_and_mixed_rules() {
        let x = v("t") * &v("t") * &v("m") + &v("s");
        assert_eq!(x.d_t(), Sym::int(2) * &v("t") * &v("m"));
        // D(m) = t, D(t) = 1 applied to m·t: t·t + m
        let y = (v("m") * &v("t")).derive(&[("m", v("t")), ("t", Sym::int(1))]);
        assert_eq!(y, v("t") * &v("t") + &v("m"));
    }
}
