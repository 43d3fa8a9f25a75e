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
    if args.piecewise || args.at_file.is_some() {
        return Err(CliError::Usage(
            "--surface evaluates one point --at u,v: without --piecewise or --at-file".into(),
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
    let at = parse_uv(args.at.as_deref().unwrap_or_default())?;
    let (surface, at, span) = if args.knots.is_empty() {
        (surface::open(directions, net)?, at, None)
    } else {
        let (surface, local, span) = knot_span(args, directions, net, &at)?;
        (surface, local, Some(span))
    };
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
            "net {} ({net_size}{}{}); v parameters [{}]",
            net.display(),
            span.unwrap_or_default(),
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

/// A surface point `(u, v)`, each exact and as printed.
type Point = [(Affine, String); 2];

/// The piece of a spline surface over the knot vectors `--knots`,
/// `--v-knots` that holds the point (`ControlNet::span_at`, seed 004 (5)):
/// the surface over its window, the point in the window's local
/// coordinates, and the span as the note says it.
fn knot_span(
    args: &EvalArgs,
    directions: [trig_core::surface::Direction<AnyBasis>; 2],
    net: &std::path::Path,
    at: &[(Affine, String); 2],
) -> Result<(TensorSurface<AnyBasis>, Point, String), CliError> {
    if args.v_knots.is_empty() {
        return Err(CliError::Usage(
            "a spline surface over knot vectors takes both: --knots (u) and --v-knots (v)".into(),
        ));
    }
    let read = |texts: &[String]| -> Result<Vec<rug::Rational>, CliError> {
        Ok(texts
            .iter()
            .map(|k| trig_core::number::parse_exact(k))
            .collect::<Result<_, CoreError>>()?)
    };
    let (uk, vk) = (read(&args.knots)?, read(&args.v_knots)?);
    let point = [
        super::rational_point(&at[0].0, &at[0].1)?,
        super::rational_point(&at[1].0, &at[1].1)?,
    ];
    let whole = trig_core::net::ControlNet::read(&trig_core::input::Source::of(net))
        .map_err(|e| CliError::Usage(e.to_string()))?;
    let sizes = (directions[0].len(), directions[1].len());
    let (window, lu, lv) = whole.span_at(
        [&uk, &vk],
        sizes,
        point,
        [at[0].1.as_str(), at[1].1.as_str()],
    )?;
    let span = format!(
        "; over knot vectors: the piece of the net's {} × {} points at local ({lu}, {lv})",
        whole.rows(),
        whole.columns()
    );
    let [u, v] = directions;
    let local = [
        (Affine::rational(lu.clone()), lu.to_string()),
        (Affine::rational(lv.clone()), lv.to_string()),
    ];
    Ok((TensorSurface::new(u, v, window)?, local, span))
}

/// Which coordinates of the point are exactly 0, decided in the exact ring
/// (every function of both directions exact at the point: its atoms exact,
/// a rational or a multiple of π/12): those print as an exact `0` instead of
/// an enclosure of zero that no precision decides.
fn exact_zeros(surface: &TensorSurface<AnyBasis>, [u, v]: [&Affine; 2]) -> [bool; 3] {
    exact_point(surface, u, v).map_or([false; 3], |p| p.map(|c| c.is_zero()))
}
