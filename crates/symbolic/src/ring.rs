//! [`Sym`] as a [`trig_core::Ring`]: operators, constants and the symbolic
//! atoms.

use std::ops::{Add, Div, Mul, Neg, Sub};

use rug::Rational;
use trig_core::{Atoms, Ring};

use crate::sym::Sym;
use crate::var::{COS, SIN, T};

/// The atoms `s`, `c`, `t` as variables, to evaluate a catalog formula
/// symbolically: `Family::eval(&symbolic_atoms(), &[Sym::var("m")])`.
pub fn symbolic_atoms() -> Atoms<Sym> {
    Atoms {
        s: Sym::var(SIN),
        c: Sym::var(COS),
        t: Sym::var(T),
    }
}

impl Ring for Sym {
    fn int(&self, n: i64) -> Sym {
        Sym::int(n)
    }

    fn ratio(&self, num: i64, den: i64) -> Sym {
        Sym::rational(Rational::from((num, den)))
    }

    fn rational(&self, q: &Rational) -> Sym {
        Sym::rational(q.clone())
    }

    fn pi(&self) -> Sym {
        Sym::pi()
    }

    fn is_zero(&self) -> bool {
        Sym::is_zero(self)
    }
}

fn divide(a: &Sym, b: &Sym) -> Sym {
    a.checked_div(b)
        .unwrap_or_else(|| panic!("Sym: division of {a} by exact zero (check is_zero first)"))
}

/// Implements `op` for `Sym op Sym`, `Sym op &Sym`, `&Sym op Sym` and
/// `&Sym op &Sym` from a function on references.
macro_rules! binary_op {
    ($Trait:ident, $method:ident, $f:expr) => {
        impl $Trait<&Sym> for &Sym {
            type Output = Sym;
            fn $method(self, rhs: &Sym) -> Sym {
                let f: fn(&Sym, &Sym) -> Sym = $f;
                f(self, rhs)
            }
        }
        impl $Trait<&Sym> for Sym {
            type Output = Sym;
            fn $method(self, rhs: &Sym) -> Sym {
                (&self).$method(rhs)
            }
        }
        impl $Trait<Sym> for Sym {
            type Output = Sym;
            fn $method(self, rhs: Sym) -> Sym {
                (&self).$method(&rhs)
            }
        }
        impl $Trait<Sym> for &Sym {
            type Output = Sym;
            fn $method(self, rhs: Sym) -> Sym {
                self.$method(&rhs)
            }
        }
    };
}

binary_op!(Add, add, |a, b| a.add_signed(b, false));
binary_op!(Sub, sub, |a, b| a.add_signed(b, true));
binary_op!(Mul, mul, |a, b| a.mul_ref(b));
binary_op!(Div, div, divide);

impl Neg for Sym {
    type Output = Sym;
    fn neg(self) -> Sym {
        self.negated()
    }
}

impl Neg for &Sym {
    type Output = Sym;
    fn neg(self) -> Sym {
        self.clone().negated()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A generic formula, as the catalog writes them.
    fn generic<T: Ring>(x: &T) -> T {
        let one = x.int(1);
        (x.clone() + &one) * &(x.clone() - &one) / &x.ratio(1, 2) - &x.square()
    }

    #[test]
    fn ring_constants_and_operators() {
        let m = Sym::var("m");
        // 2(m² − 1) − m² = m² − 2
        assert_eq!(generic(&m), m.clone() * &m - &Sym::int(2));
        assert_eq!(Ring::pi(&m), Sym::var("pi"));
        assert!(Ring::is_zero(&(m.clone() - m.clone())));
        assert_eq!(m.powi(3), &(&m * &m) * &m);
        assert_eq!(-&m + m.clone(), Sym::zero());
        assert_eq!(
            Ring::rational(&m, &Rational::from((2, 3))),
            Sym::int(2) / Sym::int(3)
        );
        assert_eq!(symbolic_atoms().t, Sym::var("t"));
    }
}
