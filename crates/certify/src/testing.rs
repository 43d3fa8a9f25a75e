//! Shared test fixtures of the crate's unit tests.

use rug::Rational;
use trig_core::{Affine, Domain};

/// `a/b`.
pub fn q(a: i64, b: i64) -> Rational {
    Rational::from((a, b))
}

/// `t ∈ [0, π]` with `s, c = sin t, cos t` and a parameter `lambda`.
pub fn zero_to_pi() -> Domain {
    Domain {
        name: "t".into(),
        param_names: vec!["lambda".into()],
        start: Affine::default(),
        end: Affine::pi_times(q(1, 1)),
        angle: Some(Affine::rational(q(1, 1))),
        uses_variable: true,
        exp: None,
        param_angles: Vec::new(),
        param_exps: Vec::new(),
    }
}
