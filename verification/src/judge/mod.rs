//! The judges: each decides one kind of claim for any basis — a catalog
//! family or a spec file alike ([`trig_core::Basis`]) — from the engines
//! below it (the exact ring, jets, the join solver, the certifiers), and
//! returns a [`crate::Verdict`] with its evidence. A claim (catalog or spec
//! file) only states what is printed and calls a judge.

pub mod continuity;
pub mod curve;
pub mod domain;
pub mod endpoint;
pub mod join;
pub mod symmetry;
