//! Certified inequalities.
//!
//! A function of the catalog is a polynomial in `s = sin θ`, `c = cos θ`
//! (or `t`) over parameter denominators. The Weierstrass substitution
//! `z = tan(θ/2)`, `s = 2z/(1+z²)`, `c = (1−z²)/(1+z²)` maps `θ ∈ [0, π/2]` to
//! `z ∈ [0, 1]` and turns it into `N(z, p) / ((1+z²)^k D(p))`: its sign is
//! that of `N` when `D` keeps one sign on the parameter box. `N` is then
//! decided by exact Bernstein subdivision ([`bernstein`]). Counterexamples
//! are exact: a rational `z` gives a rational point `(s, c)` on the circle.
//! The number of maxima is counted from the certified sign changes of the
//! derivative ([`unimodal`], exact root isolation by Sturm sequences,
//! [`sturm`]).

pub mod bernstein;
pub mod evidence;
pub mod nonneg;
pub mod range;
pub mod sturm;
pub mod unimodal;
