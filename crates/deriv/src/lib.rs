//! # trig-deriv
//!
//! Truncated Taylor jets ([`Jet`]) over any [`trig_core::Ring`] — f64,
//! [`trig_core::Mpfr`], the exact symbolic ring — and derivatives of the
//! catalog's families computed with them.

pub mod continuity;
pub mod jet;
pub mod join;
pub mod surface;

pub use jet::{Jet, angle_atoms, family_derivatives};
pub use join::{
    EndDerivatives, Forced, Join, JoinError, JoinKind, JoinSetup, default_factors, factor_names,
    solve_join, solve_join_for, solve_join_with, vanishing,
};
pub mod table;

pub use surface::{VanishingWeightedSum, surface_corner_derivatives};

pub use table::{
    End, KnotDerivatives, VanishingDenominator, Wrt, curve_endpoint_derivatives,
    endpoint_derivatives, knot_derivatives, rate, rational_curve_endpoint_derivatives,
};
