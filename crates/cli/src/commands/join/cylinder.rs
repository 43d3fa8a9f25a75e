//! A closed pair of patches (the thesis's cylinders, Section 5.4.3): the
//! second patch joined to the first at both seams — `u = 1` of the first to
//! `u = 0` of the second, and `u = 1` of the second back to `u = 0` of the
//! first (or in `v`). The first seam forces the second net's first `k + 1`
//! rows ([`second_net`]); the second seam, read backwards (both patches
//! reversed, `ũ = 1 − u`, which turns the join of `Q(1)` to `P(0)` into one of
//! `P̃(1)` to `Q̃(0)` with the same conditions for a symmetric basis), forces
//! its last `k + 1` rows, where they do not overlap (`2(k + 1) ≤ n`: C⁰, C¹,
//! G¹ for a cubic). The closing seam is then checked exactly by the join
//! engine on every column — `Q⁽ʲ⁾(1) = P⁽ʲ⁾(0)` (C^k), `P'(0) = Q'(1)/α`
//! (G¹) — so a basis for which reading backwards is not the same join is
//! refused, not drawn. Where the rows overlap (C², G² of a cubic) both
//! patches are solved together, as the thesis builds its C² cylinder
//! (`Q₂ = P₁ − (4m + 4)P₂ + (4m + 4)P₃` and `P₂ = Q₁ − (4m + 4)Q₂ + (4m + 4)Q₃`
//! at once): on every column the end rows `P₀`, `P_{n−1}` of the first net
//! are kept, its inner rows and the whole second net are the unknowns of the
//! two seams' join conditions (the join engine's residuals, linear in the
//! points), eliminated exactly; the closing seam's factors are those of the
//! first seam read backwards, `1/α` and `−β/α³` (`P'(0) = Q'(1)/α`,
//! `P''(0) = Q''(1)/α² − βQ'(1)/α³`), and both seams' residuals are then
//! checked to be exactly 0.

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

/// The two patches of a closed pair (see the module): the first net (moved
/// where the seams overlap) and the second.
pub fn closing_net(
    bases: [&AnyBasis; 2],
    kind: JoinKind,
    across: Across,
    net: &ControlNet,
    values: &JoinValues,
) -> Result<[ControlNet; 2], CliError> {
    let curve_basis = match across {
        Across::U => bases[0],
        Across::V => bases[1],
    };
    let n = curve_basis.function_names().len();
    let forced = kind.order() + 1;
    if net.is_rational() {
        return Err(CliError::Usage(
            "--close takes a net without weights".into(),
        ));
    }
    if kind == JoinKind::G2 || 2 * forced > n {
        return solved_together(curve_basis, kind, across, net, values);
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
    Ok([net.clone(), closed])
}

/// The join engine at the two seams of a closed pair: `P(1)` to `Q(0)` with
/// the factors `α`, `β`, and `Q(1)` to `P(0)` with the first seam's read
/// backwards, `1/α`, `−β/α³`.
fn seams<'a>(
    basis: &'a AnyBasis,
    params: &'a [Vec<Sym>; 2],
    values: &JoinValues,
) -> [JoinSetup<'a, &'a AnyBasis>; 2] {
    let alpha = Sym::rational(values.alpha.clone());
    let beta = Sym::rational(values.beta.clone());
    let back = [
        Sym::one().checked_div(&alpha).expect("α > 0"),
        (Sym::zero() - &beta)
            .checked_div(&(alpha.clone() * &alpha * &alpha))
            .expect("α > 0"),
    ];
    let setup = |first: &'a [Sym], second: &'a [Sym], factors: [Sym; 2]| JoinSetup {
        basis,
        first_params: first,
        second_params: second,
        wrt: Wrt::Angle,
        h: (Sym::one(), Sym::one()),
        factors,
    };
    [
        setup(&params[0], &params[1], [alpha, beta]),
        setup(&params[1], &params[0], back),
    ]
}

/// A closed pair whose seams overlap (see the module): on every column and
/// coordinate the first net's inner rows and the second net are the
/// unknowns of both seams' conditions, eliminated exactly.
fn solved_together(
    basis: &AnyBasis,
    kind: JoinKind,
    across: Across,
    net: &ControlNet,
    values: &JoinValues,
) -> Result<[ControlNet; 2], CliError> {
    let n = basis.function_names().len();
    let q = |x: &Rational| Sym::rational(x.clone());
    let params = [
        values.first.iter().map(q).collect(),
        values.second.iter().map(q).collect(),
    ];
    let [there, back] = seams(basis, &params, values);
    let (ends_there, ends_back) = (there.end_derivatives(), back.end_derivatives());
    let count = match across {
        Across::U => net.columns(),
        Across::V => net.rows(),
    };
    let at = |i: usize, k: usize| match across {
        Across::U => (i, k),
        Across::V => (k, i),
    };
    let unknowns: Vec<String> = (1..n - 1)
        .map(|i| format!("P{i}"))
        .chain((0..n).map(|i| format!("Q{i}")))
        .collect();
    let singular = || {
        CliError::Usage(format!(
            "--close {kind}: the two seams' conditions do not determine the inner rows of `{}` at these values (no unique rational solution)",
            basis.id()
        ))
    };
    // the solved line of one coordinate: `P_i` then `Q_i`, `i = 0…n−1`
    let solve_line = |k: usize, axis: usize| -> Result<Vec<Rational>, CliError> {
        let kept = |i: usize| {
            let (r, c) = at(i, k);
            q(&net.points()[r][c][axis])
        };
        let first: Vec<Sym> = (0..n)
            .map(|i| match i {
                0 => kept(0),
                i if i == n - 1 => kept(i),
                i => Sym::var(&format!("P{i}")),
            })
            .collect();
        let second: Vec<Sym> = (0..n).map(|i| Sym::var(&format!("Q{i}"))).collect();
        let mut conditions = there.residuals_with(&ends_there, kind, &first, &second);
        conditions.extend(back.residuals_with(&ends_back, kind, &second, &first));
        let solution = eliminate(conditions, &unknowns).ok_or_else(singular)?;
        let value = |name: String| {
            let at = unknowns
                .iter()
                .position(|u| *u == name)
                .expect("an unknown");
            solution[at].as_rational().ok_or_else(singular)
        };
        (0..n)
            .map(|i| match i {
                0 => Ok(net.points()[at(0, k).0][at(0, k).1][axis].clone()),
                i if i == n - 1 => Ok(net.points()[at(i, k).0][at(i, k).1][axis].clone()),
                i => value(format!("P{i}")),
            })
            .chain((0..n).map(|i| value(format!("Q{i}"))))
            .collect()
    };
    let mut nets = [net.points().to_vec(), net.points().to_vec()];
    for k in 0..count {
        let lines = [solve_line(k, 0)?, solve_line(k, 1)?, solve_line(k, 2)?];
        for i in 0..n {
            let (r, c) = at(i, k);
            for (patch, points) in nets.iter_mut().enumerate() {
                points[r][c] = std::array::from_fn(|a| lines[a][patch * n + i].clone());
            }
        }
    }
    let [first, second] =
        nets.map(|p| ControlNet::new(p).map_err(|e| CliError::Usage(e.to_string())));
    let (first, second) = (first?, second?);
    check_seam(
        &there,
        "the first seam",
        basis,
        kind,
        across,
        &first,
        &second,
    )?;
    check_seam(
        &back,
        "the closing seam",
        basis,
        kind,
        across,
        &second,
        &first,
    )?;
    Ok([first, second])
}

/// The unique solution of linear `conditions` (each `= 0`) for `unknowns`,
/// by exact elimination; `None` when they do not determine every unknown
/// or contradict each other.
fn eliminate(conditions: Vec<Sym>, unknowns: &[String]) -> Option<Vec<Sym>> {
    let mut solved: Vec<(usize, Sym)> = Vec::new();
    for condition in conditions {
        let reduced = solved
            .iter()
            .fold(condition, |c, (i, v)| c.subs(&unknowns[*i], v));
        let pivot = (0..unknowns.len())
            .filter(|i| solved.iter().all(|(s, _)| s != i))
            .find(|&i| !reduced.diff(&unknowns[i]).is_zero());
        let Some(index) = pivot else {
            if reduced.is_zero() {
                continue;
            }
            return None;
        };
        let name = &unknowns[index];
        let value = Sym::var(name) - &reduced.checked_div(&reduced.diff(name))?;
        for (_, v) in &mut solved {
            *v = v.subs(name, &value);
        }
        solved.push((index, value));
    }
    (solved.len() == unknowns.len()).then(|| {
        solved.sort_by_key(|(i, _)| *i);
        solved.into_iter().map(|(_, v)| v).collect()
    })
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
    let params = [
        values.first.iter().map(q).collect(),
        values.second.iter().map(q).collect(),
    ];
    let [_, back] = seams(basis, &params, values);
    check_seam(
        &back,
        "the closing seam",
        basis,
        kind,
        across,
        second,
        first,
    )
}

/// The join of `from(1)` to `to(0)` by `setup` on every column (across `u`)
/// or row, exactly: every residual of the join engine 0.
fn check_seam(
    setup: &JoinSetup<'_, &AnyBasis>,
    which: &str,
    basis: &AnyBasis,
    kind: JoinKind,
    across: Across,
    from: &ControlNet,
    to: &ControlNet,
) -> Result<(), CliError> {
    let q = |x: &Rational| Sym::rational(x.clone());
    let line = |net: &ControlNet, k: usize, axis: usize| -> Vec<Sym> {
        match across {
            Across::U => net.points().iter().map(|r| q(&r[k][axis])).collect(),
            Across::V => net.points()[k].iter().map(|p| q(&p[axis])).collect(),
        }
    };
    let count = match across {
        Across::U => from.columns(),
        Across::V => from.rows(),
    };
    for k in 0..count {
        for axis in 0..3 {
            let residuals = setup.residuals(kind, &line(from, k, axis), &line(to, k, axis));
            if let Some(r) = residuals.iter().find(|r| !r.is_zero()) {
                return Err(CliError::Usage(format!(
                    "{which} of `{}` is not {kind} (a residual {} ≠ 0): reading the seam backwards is not the same join for this basis",
                    basis.id(),
                    r.to_unicode()
                )));
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_core::Family;

    /// The closed C² and G² pairs of the thesis cubic: solved together, both
    /// seams exact (checked inside), and every point of a column — of both
    /// nets — on the line through the column's kept ends `P₀`, `P₃`: the
    /// conditions are affine, so their unique solution is an affine
    /// combination of `P₀` and `P₃`.
    #[test]
    fn the_overlapping_closed_pairs_are_solved_together_and_are_flat() {
        let basis = AnyBasis::Family(Family::ThesisCubic);
        let text: String = (0..4)
            .map(|i| {
                (0..4)
                    .map(|j| format!("{i} {} {}\n", (i * j + 1) % 4, (i * i + j) % 3))
                    .collect::<String>()
                    + "\n"
            })
            .collect();
        let net = ControlNet::parse(&text, "net").unwrap();
        let r = |n: i64, d: i64| Rational::from((n, d));
        for (kind, alpha, beta) in [
            (JoinKind::C(2), r(1, 1), r(0, 1)),
            (JoinKind::G2, r(1, 2), r(2, 1)),
        ] {
            let values = JoinValues {
                first: vec![r(1, 1)],
                second: vec![r(1, 2)],
                alpha,
                beta,
            };
            let [first, second] =
                closing_net([&basis, &basis], kind, Across::U, &net, &values).unwrap();
            assert_ne!(first, net, "{kind}: the first patch moves");
            for j in 0..4 {
                let p = |n: &ControlNet, i: usize| n.points()[i][j].clone();
                let (p0, p3) = (p(&net, 0), p(&net, 3));
                assert_eq!((p(&first, 0), p(&first, 3)), (p0.clone(), p3.clone()));
                let d: [Rational; 3] = std::array::from_fn(|a| Rational::from(&p3[a] - &p0[a]));
                for x in (0..4).flat_map(|i| [p(&first, i), p(&second, i)]) {
                    let e: [Rational; 3] = std::array::from_fn(|a| Rational::from(&x[a] - &p0[a]));
                    for a in 0..3 {
                        let (b, c) = ((a + 1) % 3, (a + 2) % 3);
                        let cross = Rational::from(&e[b] * &d[c]) - Rational::from(&e[c] * &d[b]);
                        assert_eq!(cross, 0, "{kind} column {j}: {x:?} off the line");
                    }
                }
            }
        }
    }
}
