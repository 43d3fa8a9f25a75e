//! `eval --surface`: the point `S(u, v)` of a tensor-product surface over a
//! control net, certified like the basis values (f64 with a proved error
//! bound per coordinate, or the proved digits of `--prec` / `--digits`),
//! through the library's one evaluation path on a
//! [`trig_core::surface::SurfaceAt`].

use trig_core::Affine;
use trig_core::evaluation::{self, Arithmetic};
use trig_core::surface::{SurfaceAt, TensorSurface};
use trig_core::{CoreError, Described};
use trig_specfile::AnyBasis;

use super::{EvalArgs, Evaluation, describe, render, shown};
use crate::commands::surface::{self, parse_uv};
use crate::commands::{CliError, CmdResult};
use trig_judge::surface::exact_point;

pub fn run(args: &EvalArgs, arithmetic: Arithmetic) -> CmdResult {
    if args.piecewise || !args.knots.is_empty() || args.at_file.is_some() {
        return Err(CliError::Usage(
            "--surface evaluates one point --at u,v: without --piecewise, --knots or --at-file"
                .into(),
        ));
    }
    let Some(net) = args.net.as_deref() else {
        return Err(CliError::Usage(
            "eval --surface needs the control net: --net FILE (docs/surfaces.md)".into(),
        ));
    };
    let u = AnyBasis::open(args.family.as_deref(), args.spec.as_deref())?;
    let directions = args
        .surface
        .v
        .directions(&u, &args.params, args.allow_outside_range)?;
    let surface = surface::open(directions, net)?;
    let at = parse_uv(args.at.as_deref().unwrap_or_default())?;
    let zeros = exact_zeros(&surface, [&at[0].0, &at[1].0]);
    let point = SurfaceAt::new(&surface, at, args.allow_outside_range)
        .map_err(super::super::range_hint)?
        .with_zeros(zeros);
    let name = surface::name(&surface);
    let e = evaluation::evaluate(&point, arithmetic, &format!("the {name} at this point"))
        .map_err(|e| match e {
            CoreError::NotRepresentable { .. } => {
                CliError::Usage(format!("{e} (evaluate with --digits N or --prec BITS)"))
            }
            e => e.into(),
        })?;
    let short = match arithmetic {
        Arithmetic::Digits(n) => (e.short_of(n), e.values.len()),
        _ => (0, 0),
    };
    let net_size = format!("{} × {}", surface.net().rows(), surface.net().columns());
    let evaluation = Evaluation {
        id: name,
        citation: format!(
            "{}; {}",
            surface.u().basis.citation(),
            surface.v().basis.citation()
        ),
        names: ["x", "y", "z"].map(String::from).to_vec(),
        values: e.values.iter().map(|v| shown(v, arithmetic)).collect(),
        precision: describe(arithmetic, e.bits, short, e.stopped),
        note: Some(format!(
            "net {} ({net_size}{}); v parameters [{}]",
            net.display(),
            if surface.net().is_rational() {
                ", rational: weights"
            } else {
                ""
            },
            args.surface.v.v_text(&args.params)
        )),
        bits: e.bits,
    };
    Ok(render(args, &evaluation))
}

/// Which coordinates of the point are exactly 0, decided in the exact ring
/// (every function of both directions exact at the point: its atoms exact,
/// a rational or a multiple of π/12): those print as an exact `0` instead of
/// an enclosure of zero that no precision decides.
fn exact_zeros(surface: &TensorSurface<AnyBasis>, [u, v]: [&Affine; 2]) -> [bool; 3] {
    exact_point(surface, u, v).map_or([false; 3], |p| p.map(|c| c.is_zero()))
}
