//! A closed pair of patches (the thesis's cylinders, Section 5.4.3): the
//! second patch joined to the first at both seams — `u = 1` of the first to
//! `u = 0` of the second, and `u = 1` of the second back to `u = 0` of the
//! first (or in `v`). The first seam forces the second net's first `k + 1`
//! rows ([`second_net`]); the second seam, read backwards (both patches
//! reversed, `ũ = 1 − u`, which turns the join of `Q(1)` to `P(0)` into one of
//! `P̃(1)` to `Q̃(0)` with the same conditions for a symmetric basis), forces
//! its last `k + 1` rows. The rows must not overlap (`2(k + 1) ≤ n`: C⁰, C¹,
//! G¹ for a cubic; the thesis's C² cylinder moves points of the first patch
//! too, which is not built). The closing seam is then checked exactly by the
//! join engine on every column — `Q⁽ʲ⁾(1) = P⁽ʲ⁾(0)` (C^k), `P'(0) = Q'(1)/α`
//! (G¹) — so a basis for which reading backwards is not the same join is
//! refused, not drawn.

use rug::Rational;
use trig_core::Described;
use trig_core::net::ControlNet;
use trig_deriv::{JoinKind, JoinSetup, Wrt};
use trig_specfile::AnyBasis;
use trig_symbolic::Sym;

use super::surface::{Across, JoinValues, second_net};
use crate::commands::CliError;

/// The net with its rows (across `u`) or columns (across `v`) in reverse order.
fn reversed(net: &ControlNet, across: Across) -> Result<ControlNet, CliError> {
    let mut rows: Vec<Vec<[Rational; 3]>> = net.points().to_vec();
    match across {
        Across::U => rows.reverse(),
        Across::V => rows.iter_mut().for_each(|r| r.reverse()),
    }
    ControlNet::new(rows).map_err(|e| CliError::Usage(e.to_string()))
}

/// The second patch of a closed pair (see the module).
pub fn closing_net(
    bases: [&AnyBasis; 2],
    kind: JoinKind,
    across: Across,
    net: &ControlNet,
    values: &JoinValues,
) -> Result<ControlNet, CliError> {
    let curve_basis = match across {
        Across::U => bases[0],
        Across::V => bases[1],
    };
    let n = curve_basis.function_names().len();
    let forced = kind.order() + 1;
    if kind == JoinKind::G2 || 2 * forced > n {
        return Err(CliError::Usage(format!(
            "--close {kind}: the two seams force {} of the {n} rows of the second net; closing is built where they do not overlap (C0, C1, G1 of a cubic)",
            2 * forced
        )));
    }
    if net.is_rational() {
        return Err(CliError::Usage(
            "--close takes a net without weights".into(),
        ));
    }
    let front = second_net(bases, kind, across, net, values)?;
    let back = second_net(bases, kind, across, &reversed(net, across)?, values)?;
    // rows 0…k from the first seam, rows n−1−i from the second (read backwards)
    let take = |i: usize, j: usize| -> [Rational; 3] {
        let (row, col) = match across {
            Across::U => (i, j),
            Across::V => (j, i),
        };
        let from_back = i + forced >= n;
        let (source, index) = if from_back {
            (&back, n - 1 - i)
        } else {
            (&front, i)
        };
        let (r, c) = match across {
            Across::U => (index, col),
            Across::V => (row, index),
        };
        source.points()[r][c].clone()
    };
    let others = match across {
        Across::U => net.columns(),
        Across::V => net.rows(),
    };
    let lines: Vec<Vec<[Rational; 3]>> = (0..n)
        .map(|i| (0..others).map(|j| take(i, j)).collect())
        .collect();
    let points = match across {
        Across::U => lines,
        Across::V => (0..others)
            .map(|j| (0..n).map(|i| lines[i][j].clone()).collect())
            .collect(),
    };
    let closed = ControlNet::new(points).map_err(|e| CliError::Usage(e.to_string()))?;
    check_closing_seam(curve_basis, kind, across, net, &closed, values)?;
    Ok(closed)
}

/// The join of `Q(1)` to `P(0)` on every column, exactly: `C^k` or `G¹` with
/// the factor `1/α`.
fn check_closing_seam(
    basis: &AnyBasis,
    kind: JoinKind,
    across: Across,
    first: &ControlNet,
    second: &ControlNet,
    values: &JoinValues,
) -> Result<(), CliError> {
    let q = |x: &Rational| Sym::rational(x.clone());
    let (p2, p1): (Vec<Sym>, Vec<Sym>) = (
        values.second.iter().map(q).collect(),
        values.first.iter().map(q).collect(),
    );
    let setup = JoinSetup {
        basis,
        first_params: &p2,
        second_params: &p1,
        wrt: Wrt::Angle,
        h: (Sym::one(), Sym::one()),
        factors: [q(&Rational::from(1 / &values.alpha)), Sym::zero()],
    };
    let line = |net: &ControlNet, k: usize, axis: usize| -> Vec<Sym> {
        match across {
            Across::U => net.points().iter().map(|r| q(&r[k][axis])).collect(),
            Across::V => net.points()[k].iter().map(|p| q(&p[axis])).collect(),
        }
    };
    let count = match across {
        Across::U => first.columns(),
        Across::V => first.rows(),
    };
    for k in 0..count {
        for axis in 0..3 {
            let residuals = setup.residuals(kind, &line(second, k, axis), &line(first, k, axis));
            if let Some(r) = residuals.iter().find(|r| !r.is_zero()) {
                return Err(CliError::Usage(format!(
                    "the closing seam of `{}` is not {kind} (a residual {} ≠ 0): reading the seam backwards is not the same join for this basis",
                    basis.id(),
                    r.to_unicode()
                )));
            }
        }
    }
    Ok(())
}
