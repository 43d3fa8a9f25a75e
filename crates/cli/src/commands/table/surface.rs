//! `table --surface`: the exact partial derivatives `∂^{a+b}S/∂u^a∂v^b` of
//! a tensor-product surface at its four corners, as combinations of the
//! control points `P_ij`. Each entry is `Σ_i Σ_j P_ij b_i^{(a)}(u₀) b_j^{(b)}(v₀)`
//! (the double sum (5.3) of seed `001_cf6c2ede0355a863.txt` differentiated
//! term by term), from the exact endpoint derivatives of each direction's
//! basis ([`endpoint_derivatives`]), so nothing is re-derived here. With
//! the weights of a net file the surface is rational,
//! `Σ w_ij P_ij B_i B_j / Σ w_ij B_i B_j`, and the entries are the quotient's
//! derivatives ([`surface_corner_derivatives`]), still combinations of the
//! `P_ij`.

use trig_core::Described;
use trig_core::input::Source;
use trig_core::net::ControlNet;
use trig_deriv::{End, Wrt, endpoint_derivatives, surface_corner_derivatives};
use trig_specfile::AnyBasis;
use trig_symbolic::Sym;

use super::{At, TableArgs, exact_params_of};
use crate::cell::{Block, Cell};
use crate::commands::{CliError, CmdResult};
use crate::format::render_blocks;

/// Highest order of a surface table: `(order + 1)²` entries per corner,
/// each a sum over the whole net (the cost model).
pub const MAX_SURFACE_ORDER: usize = 6;

pub fn run(args: &TableArgs, u: &AnyBasis, wrt: Wrt) -> CmdResult {
    if args.numeric || args.curve || args.at == At::Knots || wrt == Wrt::X {
        return Err(CliError::Usage(
            "table --surface is exact, at the four corners, in the control points: without --numeric, --curve, --at knots or --wrt x".into(),
        ));
    }
    if args.order > MAX_SURFACE_ORDER {
        return Err(trig_core::CoreError::Limit {
            what: format!("table --surface --order {}", args.order),
            limit: MAX_SURFACE_ORDER.to_string(),
        }
        .into());
    }
    let v = args.surface.v.v_basis(u)?;
    let same = args.surface.v.v_family.is_none() && args.surface.v.v_spec.is_none();
    let u_params = exact_params_of(&args.params, u)?;
    let v_params = if !args.surface.v.v_params.is_empty() {
        exact_params_of(&args.surface.v.v_params, &v)?
    } else if same {
        u_params.clone()
    } else {
        v.param_names()
            .iter()
            .map(|p| Sym::var(&format!("{p}_v")))
            .collect()
    };
    let (nu, nv) = (u.function_names().len(), v.function_names().len());
    let label = |i: usize, j: usize| {
        if nu <= 10 && nv <= 10 {
            format!("P{i}{j}")
        } else {
            format!("P{i}_{j}")
        }
    };
    let names: Vec<String> = (0..nu)
        .flat_map(|i| (0..nv).map(move |j| label(i, j)))
        .collect();
    let points: Vec<Sym> = names.iter().map(|n| Sym::var(n)).collect();
    let taken = u.param_names().into_iter().chain(v.param_names());
    if let Some(clash) = taken.into_iter().find(|p| names.contains(p)) {
        return Err(CliError::Usage(format!(
            "a parameter is called `{clash}`, as a control point of the table would be"
        )));
    }
    let weights = match &args.net {
        Some(path) => weights_of(path, (u, nu), (&v, nv))?,
        None => None,
    };
    let corners = corner_table(
        args.order,
        [u, &v],
        [&u_params, &v_params],
        wrt,
        &points,
        weights.as_deref(),
    )?;
    let blocks: Vec<Block> = corners
        .into_iter()
        .map(|b| b.map(|cell| cell.combination(&names)))
        .collect();
    let v_text = if same && args.surface.v.v_params.is_empty() {
        "the same parameters".to_string()
    } else {
        v_params
            .iter()
            .zip(v.param_names())
            .map(|(s, n)| format!("{n} = {}", s.to_unicode()))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let model = match (&args.net, &weights) {
        (Some(path), Some(_)) => format!(
            "rational surface S(u, v) = Σ_i Σ_j w_ij P_ij B_i(u) B_j(v) / Σ_i Σ_j w_ij B_i(u) B_j(v), w_ij from {}",
            path.display()
        ),
        _ => "surface S(u, v) = Σ_i Σ_j P_ij B_i(u) B_j(v)".to_string(),
    };
    let heading = format!(
        "{model}, u: {} ({}), v: {} ({}; {v_text}): partial derivatives ∂^(a+b)S/∂u^a∂v^b at the corners, {}, exact",
        u.id(),
        u.citation(),
        v.id(),
        v.citation(),
        wrt.describe_on(&u.domain()),
    );
    render_blocks(&heading, &blocks, args.format, args.standalone)
}

/// The weights of the net in `path` in row order (`None` for a net
/// without weights), the net checked against the sizes of the bases.
fn weights_of(
    path: &std::path::Path,
    (u, nu): (&AnyBasis, usize),
    (v, nv): (&AnyBasis, usize),
) -> Result<Option<Vec<Sym>>, CliError> {
    let net = ControlNet::read(&Source::of(path)).map_err(|e| CliError::Usage(e.to_string()))?;
    net.check_size((&u.id(), nu), (&v.id(), nv))?;
    Ok(net.is_rational().then(|| {
        (0..nu)
            .flat_map(|i| (0..nv).map(move |j| (i, j)))
            .map(|(i, j)| Sym::rational(net.weight(i, j).expect("a rational net").clone()))
            .collect()
    }))
}

/// The four corner blocks (rows `a`, columns `b`), `points` the net in row
/// order (`P_ij` at `i·n_v + j`), `weights` likewise for a rational surface.
fn corner_table(
    order: usize,
    bases: [&AnyBasis; 2],
    params: [&[Sym]; 2],
    wrt: Wrt,
    points: &[Sym],
    weights: Option<&[Sym]>,
) -> Result<Vec<Block<Sym>>, CliError> {
    macro_rules! with_order {
        ($($n:literal),*) => {
            match order {
                $($n => corners::<{ $n + 1 }>(bases, params, wrt, points, weights),)*
                _ => unreachable!("order checked against MAX_SURFACE_ORDER"),
            }
        };
    }
    with_order!(0, 1, 2, 3, 4, 5, 6)
}

fn corners<const K: usize>(
    [u, v]: [&AnyBasis; 2],
    [pu, pv]: [&[Sym]; 2],
    wrt: Wrt,
    points: &[Sym],
    weights: Option<&[Sym]>,
) -> Result<Vec<Block<Sym>>, CliError> {
    let derivatives = |basis: &AnyBasis, params: &[Sym], end: End| {
        endpoint_derivatives::<Sym, K>(basis, params, end, wrt, &Sym::one())
    };
    let mut blocks = Vec::new();
    for eu in [End::Start, End::End] {
        let du = derivatives(u, pu, eu);
        for ev in [End::Start, End::End] {
            let dv = derivatives(v, pv, ev);
            let title = format!("corner u at its {eu}, v at its {ev}");
            let entries = surface_corner_derivatives::<Sym, K>(&du, &dv, points, weights)
                .map_err(|e| CliError::Usage(format!("{title}: {e}")))?;
            blocks.push(Block {
                title,
                corner: "a \\ b".into(),
                columns: (0..K).map(|b| b.to_string()).collect(),
                rows: entries
                    .into_iter()
                    .enumerate()
                    .map(|(a, row)| (a.to_string(), row))
                    .collect(),
            });
        }
    }
    Ok(blocks)
}
