//! The formulas of every published basis, one file per source document.
//!
//! Each function is generic over [`crate::Ring`] and is the single source of
//! truth for its formula: f64, MPFR, Taylor jets and the exact symbolic ring
//! all evaluate these same functions.

pub mod reference;
pub mod seed000;
pub mod seed000_nonuniform;
pub mod seed002;
pub mod seed004;
pub mod thesis;
