//! # trig-core
//!
//! The scalar abstraction and the catalog of published spline bases with
//! shape parameters, each formula written once and evaluated generically in
//! f64, MPFR ([`Mpfr`]), Taylor jets (crate `trig-deriv`) and the exact
//! symbolic ring (crate `trig-symbolic`).
//!
//! Sources are the documents in `shared/seeds/`: the thesis on a G² cubic
//! trigonometric spline (seed 001), Majeed et al. 2020 (seed 000), Dube &
//! Mishra 2017 (seed 002), the C³ B-spline paper whose formulas are missing
//! (seed 003), and Dube & Mishra 2016 (seed 004).
//!
//! ```
//! use trig_core::{Family, Real};
//! use rug::Rational;
//! // thesis cubic (3.7) at u = 0 is (1, 0, 0, 0)
//! let b = Family::ThesisCubic.eval_at(&0.0_f64, &[Rational::from((3, 5))], false).unwrap();
//! assert_eq!(b, vec![1.0, 0.0, 0.0, 0.0]);
//! ```

pub mod angles;
pub mod basis;
pub mod batch;
pub mod certified;
pub mod curve;
pub mod decimal;
pub mod domain;
pub mod echo;
pub mod error;
pub mod evaluation;
pub mod families;
pub mod family;
mod float;
pub mod input;
pub mod interval;
pub mod knots;
pub mod mpfr;
pub mod net;
pub mod number;
pub mod parallel;
pub mod param;
pub mod piecewise;
mod precision;
pub mod range;
pub mod scalar;
pub mod sincos;
pub mod surface;
pub mod variable;
pub mod work;

pub use basis::{Basis, Described};
pub use batch::Batch;
pub use decimal::Decimal;
pub use domain::{Affine, Domain};
pub use echo::echo;
pub use error::{CoreError, Result};
pub use family::{Family, FamilyInfo, Formula, FormulaVisitor, SEED000_NONUNIFORM, catalog};
pub use interval::{Fault, Interval};
pub use mpfr::Mpfr;
pub use number::{parse_exact, parse_point};
pub use param::{Bound, ParamSpec, Parameter, Range};
pub use range::{End, ParamRange};
pub use scalar::{Real, Ring, RingOps};
pub use variable::{Atoms, Variable};
