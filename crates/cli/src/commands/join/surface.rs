//! `join --surface`: the control points of a second tensor-product patch
//! that a C^k / G^k join across a boundary forces. Across `u` (the end
//! `u = 1` of `S₁ = Σ_i Σ_j P_ij B_i(u) B_j(v)` meeting the start `u = 0` of
//! `S₂ = Σ_i Σ_j Q_ij B_i(u) B_j(v)`, one `v` basis and its parameters for
//! both): `∂^k S/∂u^k` along the boundary is `Σ_j B_j(v) (Σ_i b_i^{(k)} P_ij)`,
//! so the join of the curves `P_0j … P_nj`, `Q_0j … Q_nj` of every column `j`
//! is sufficient, and necessary when the functions `B_j` are linearly
//! independent — the reduction of the thesis's Theorems 5.1–5.4 (seed
//! `001_cf6c2ede0355a863.txt`, Section 5.3). The curve join is solved once by
//! the join engine ([`super::solve`]) and written out column by column;
//! across `v` the roles of the directions are exchanged. `G¹`, `G²` take
//! constant factors `α`, `β` along the boundary.

use clap::ValueEnum;
use trig_core::Described;
use trig_deriv::JoinKind;
use trig_specfile::AnyBasis;
use trig_symbolic::Sym;

use rug::Rational;
use trig_core::net::ControlNet;

use super::{JoinArgs, JoinFormat, ParamsArg, Solved, json_value, solve, tex, text};
use crate::commands::{CliError, CmdResult};
use crate::format;

/// The boundary two patches share.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Across {
    /// `u = 1` of the first patch is `u = 0` of the second.
    U,
    /// `v = 1` of the first patch is `v = 0` of the second.
    V,
}

pub fn run(args: &JoinArgs, u: AnyBasis, kind: JoinKind) -> CmdResult {
    let v = args.surface.v.v_basis(&u)?;
    if !args.surface.v.v_params.is_empty() {
        return Err(CliError::Usage(
            "join --surface: the parameters stay symbols (the forced points hold for every value); drop --v-param".into(),
        ));
    }
    let (curve_basis, other) = match args.across {
        Across::U => (u.clone(), v.clone()),
        Across::V => (v.clone(), u.clone()),
    };
    let solved = solve(curve_basis, kind, args.params, args.wrt.into())?;
    let surface = by_columns(solved, other.function_names().len(), args.across);
    let boundary = match args.across {
        Across::U => {
            "across u: u = 1 of the first patch is u = 0 of the second; the curve join for each column j"
        }
        Across::V => {
            "across v: v = 1 of the first patch is v = 0 of the second; the curve join for each row i"
        }
    };
    let [p, q] = &surface.curves;
    let lead = [
        format!(
            "surface patches: Σ_i Σ_j {p}_ij B_i(u) B_j(v) and Σ_i Σ_j {q}_ij B_i(u) B_j(v), u: {}, v: {}",
            u.id(),
            v.id()
        ),
        format!(
            "{boundary} (sufficient; necessary where the functions of the other direction are linearly independent)"
        ),
    ];
    Ok(match args.format {
        JoinFormat::Text => format!("{}\n{}", lead.join("\n"), text(&surface)),
        JoinFormat::Tex => {
            let comments: String = lead.iter().map(|l| trig_tex::comment(l)).collect();
            format!("{comments}{}", tex(&surface))
        }
        JoinFormat::Json => {
            let mut value = json_value(&surface);
            value["surface"] = serde_json::json!({
                "u": u.id(),
                "v": v.id(),
                "across": match args.across { Across::U => "u", Across::V => "v" },
            });
            format::json(&value)
        }
    })
}

/// The name of the control point in net row `row`, column `column`
/// (`P12`, or `P1_2` when an index may have two digits).
fn point_name(letter: &str, row: usize, column: usize, wide: bool) -> String {
    if wide {
        format!("{letter}{row}_{column}")
    } else {
        format!("{letter}{row}{column}")
    }
}

/// The curve join written for every column (across `u`) or row (across
/// `v`) of the nets: `P_i → P_ij`, `Q_i → Q_ij` (or `P_ji`, `Q_ji`).
fn by_columns(solved: Solved, count: usize, across: Across) -> Solved {
    let n = solved.family.function_names().len();
    let [p, q] = solved.curves.clone();
    let wide = n > 10 || count > 10;
    let name = |letter: &str, i: usize, k: usize| match across {
        Across::U => point_name(letter, i, k, wide),
        Across::V => point_name(letter, k, i, wide),
    };
    let renamed = |value: &Sym, k: usize| {
        (0..n).fold(value.clone(), |v, i| {
            [&p, &q].into_iter().fold(v, |v, letter| {
                v.subs(&format!("{letter}{i}"), &Sym::var(&name(letter, i, k)))
            })
        })
    };
    let index = |point: &Sym| -> usize {
        point
            .to_string()
            .trim_start_matches(q.as_str())
            .parse()
            .expect("a control point of the second segment")
    };
    let mut forced = Vec::new();
    for k in 0..count {
        for (point, value, singular) in &solved.forced {
            forced.push((
                Sym::var(&name(&q, index(point), k)),
                renamed(value, k),
                singular.clone(),
            ));
        }
    }
    let names = [&p, &q]
        .into_iter()
        .flat_map(|letter| (0..n).flat_map(move |i| (0..count).map(move |k| name(letter, i, k))))
        .collect();
    let factor = solved.factor.clone();
    Solved {
        forced,
        names,
        factor,
        ..solved
    }
}

/// The values a drawn join is made of: the parameters of each patch's
/// joined direction, the factors `α`, `β`.
pub struct JoinValues {
    pub first: Vec<Rational>,
    pub second: Vec<Rational>,
    pub alpha: Rational,
    pub beta: Rational,
}

/// The net of the second patch of a join, in numbers: the forced points
/// from the exact join (every symbol replaced by its value, exactly), the
/// free ones the first net moved on by its extent across the boundary
/// (`Q_ij = P_ij + P_{n−1,j} − P_{0,j}` across `u`): a second patch beside
/// the first, as the thesis's Figures 5.4–5.7 draw them. A net with weights
/// is joined in homogeneous coordinates `(w_ij P_ij, w_ij)`: the join of
/// the homogeneous patches (the same curve join, column by column, on four
/// coordinates) joins their quotients; the free points keep the weights of
/// the points they are moved from, and a forced weight ≤ 0 is an error.
pub fn second_net(
    [u, v]: [&AnyBasis; 2],
    kind: JoinKind,
    across: Across,
    net: &ControlNet,
    values: &JoinValues,
) -> Result<ControlNet, CliError> {
    let (curve_basis, other) = match across {
        Across::U => (u, v),
        Across::V => (v, u),
    };
    let params = if values.first == values.second {
        ParamsArg::Same
    } else {
        ParamsArg::Different
    };
    let solved = solve(curve_basis.clone(), kind, params, trig_deriv::Wrt::Angle)?;
    let (n, count) = (
        curve_basis.function_names().len(),
        other.function_names().len(),
    );
    let joined = by_columns(solved, count, across);
    let [p, q] = joined.curves.clone();
    let wide = n > 10 || count > 10;
    let mut known: Vec<(String, Rational)> = Vec::new();
    for (symbols, values) in [
        (&joined.first_params, &values.first),
        (&joined.second_params, &values.second),
    ] {
        for (s, x) in symbols.iter().zip(values) {
            known.push((s.to_string(), x.clone()));
        }
    }
    known.push((joined.factors[0].to_string(), values.alpha.clone()));
    known.push((joined.factors[1].to_string(), values.beta.clone()));
    let rows = net.rows();
    let columns = net.columns();
    let moved = |i: usize, j: usize, axis: usize| {
        let pts = net.points();
        let shift = match across {
            Across::U => Rational::from(&pts[rows - 1][j][axis] - &pts[0][j][axis]),
            Across::V => Rational::from(&pts[i][columns - 1][axis] - &pts[i][0][axis]),
        };
        Rational::from(&pts[i][j][axis] + &shift)
    };
    let weight = |i: usize, j: usize| net.weight(i, j).cloned().unwrap_or(Rational::from(1));
    // homogeneous coordinate `axis` (0…2: w·x, w·y, w·z; 3: w) of a point
    let homogeneous = |w: Rational, x: Rational, axis: usize| match axis {
        3 => w,
        _ => w * x,
    };
    // one homogeneous coordinate of every point of the second net
    let coordinate = |axis: usize| -> Result<Vec<Vec<Rational>>, CliError> {
        let cartesian =
            |x: &dyn Fn(usize) -> Rational| if axis < 3 { x(axis) } else { Rational::new() };
        let mut table = known.clone();
        for i in 0..rows {
            for j in 0..columns {
                let first = cartesian(&|a| net.points()[i][j][a].clone());
                let free = cartesian(&|a| moved(i, j, a));
                table.push((
                    point_name(&p, i, j, wide),
                    homogeneous(weight(i, j), first, axis),
                ));
                table.push((
                    point_name(&q, i, j, wide),
                    homogeneous(weight(i, j), free, axis),
                ));
            }
        }
        let value_of = |formula: &Sym| {
            let mut f = formula.clone();
            if let Some((beta, fixed)) = &joined.factor {
                f = f.subs(&beta.to_string(), fixed);
            }
            for (name, x) in &table {
                f = f.subs(name, &Sym::rational(x.clone()));
            }
            f.as_rational().ok_or_else(|| {
                CliError::Usage(format!(
                    "the forced point is not a rational number at these values: {}",
                    f.to_unicode()
                ))
            })
        };
        (0..rows)
            .map(|i| {
                (0..columns)
                    .map(|j| {
                        let name = point_name(&q, i, j, wide);
                        match joined
                            .forced
                            .iter()
                            .find(|(pt, _, _)| pt.to_string() == name)
                        {
                            Some((_, formula, _)) => value_of(formula),
                            None => Ok(homogeneous(
                                weight(i, j),
                                cartesian(&|a| moved(i, j, a)),
                                axis,
                            )),
                        }
                    })
                    .collect()
            })
            .collect()
    };
    let [x, y, z] = [coordinate(0)?, coordinate(1)?, coordinate(2)?];
    let w = if net.is_rational() {
        coordinate(3)?
    } else {
        vec![vec![Rational::from(1); columns]; rows]
    };
    if let Some(bad) = w.iter().flatten().find(|w| **w <= 0) {
        return Err(CliError::Usage(format!(
            "the join forces a weight {bad} ≤ 0 on the second patch: no rational patch has it (other weights or parameter values)"
        )));
    }
    let out = (0..rows)
        .map(|i| {
            (0..columns)
                .map(|j| [&x, &y, &z].map(|c| Rational::from(&c[i][j] / &w[i][j])))
                .collect()
        })
        .collect();
    ControlNet::with_weights(
        out,
        net.is_rational().then_some(w),
        "the second patch's forced net",
    )
    .map_err(|e| CliError::Usage(e.to_string()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_core::Family;
    use trig_deriv::{JoinSetup, Wrt};

    /// Each column (row) of the written-out join meets the curve join's
    /// conditions exactly: the residuals of the join engine are 0.
    #[test]
    fn every_column_of_the_forced_net_joins_exactly() {
        let basis = AnyBasis::Family(Family::ThesisCubic);
        for (kind, params) in [
            (JoinKind::C(2), ParamsArg::Same),
            (JoinKind::G2, ParamsArg::Different),
        ] {
            for across in [Across::U, Across::V] {
                let solved = solve(basis.clone(), kind, params, Wrt::Angle).unwrap();
                let setup_params = (solved.first_params.clone(), solved.second_params.clone());
                let factors = solved.factors.clone();
                let lengths = solved.lengths.clone();
                let surface = by_columns(solved, 4, across);
                let setup = JoinSetup {
                    basis: &basis,
                    first_params: &setup_params.0,
                    second_params: &setup_params.1,
                    wrt: Wrt::Angle,
                    h: (lengths[0].clone(), lengths[1].clone()),
                    factors,
                };
                let name = |l: &str, i: usize, k: usize| match across {
                    Across::U => format!("{l}{i}{k}"),
                    Across::V => format!("{l}{k}{i}"),
                };
                for k in 0..4 {
                    let first: Vec<Sym> = (0..4).map(|i| Sym::var(&name("P", i, k))).collect();
                    let second: Vec<Sym> = (0..4)
                        .map(|i| {
                            let q = name("Q", i, k);
                            surface
                                .forced
                                .iter()
                                .find(|(p, _, _)| p.to_string() == q)
                                .map_or_else(|| Sym::var(&q), |(_, v, _)| v.clone())
                        })
                        .collect();
                    let mut residuals = setup.residuals(kind, &first, &second);
                    if let Some((beta, value)) = &surface.factor {
                        residuals = residuals
                            .iter()
                            .map(|r| r.subs(&beta.to_string(), value))
                            .collect();
                    }
                    assert!(
                        residuals.iter().all(Sym::is_zero),
                        "{kind} {across:?} column {k}: {residuals:?}"
                    );
                    // and the forced points name this column only
                    assert_eq!(
                        surface
                            .forced
                            .iter()
                            .filter(|(p, _, _)| {
                                (0..4).any(|i| p.to_string() == name("Q", i, k))
                            })
                            .count(),
                        kind.order() + 1
                    );
                }
            }
        }
    }

    /// The second patch of a rational join, built in homogeneous
    /// coordinates, meets the first in the rational surfaces' own
    /// derivatives: `∂^{a+b}S/∂u^a∂v^b` at the two corners of the boundary
    /// agree for `a ≤ k` (and not beyond for C¹), every `b`.
    #[test]
    fn a_rational_join_meets_in_the_quotient_derivatives() {
        use trig_deriv::{End, endpoint_derivatives, surface_corner_derivatives};
        let basis = AnyBasis::Family(Family::ThesisCubic);
        let text: String = (0..4)
            .map(|i| {
                (0..4)
                    .map(|j| {
                        format!(
                            "{i} {j} {} {}\n",
                            (7 * i * i + 3 * j + i * j * j) % 5,
                            2 + i + j
                        )
                    })
                    .collect::<String>()
                    + "\n"
            })
            .collect();
        let net = ControlNet::parse(&text, "net").unwrap();
        let m = Rational::from((1, 2));
        let values = JoinValues {
            first: vec![m.clone()],
            second: vec![m.clone()],
            alpha: Rational::from(1),
            beta: Rational::new(),
        };
        let params = [Sym::rational(m)];
        let d = |end| endpoint_derivatives::<Sym, 4>(&basis, &params, end, Wrt::Angle, &Sym::one());
        let flat = |net: &ControlNet, f: &dyn Fn(usize, usize) -> Rational| -> Vec<Sym> {
            (0..net.rows())
                .flat_map(|i| (0..net.columns()).map(move |j| (i, j)))
                .map(|(i, j)| Sym::rational(f(i, j)))
                .collect()
        };
        for kind in [JoinKind::C(1), JoinKind::C(2)] {
            let second = second_net([&basis, &basis], kind, Across::U, &net, &values).unwrap();
            assert!(second.is_rational());
            for axis in 0..3 {
                for ev in [End::Start, End::End] {
                    let corner = |n: &ControlNet, eu| {
                        let points = flat(n, &|i, j| n.points()[i][j][axis].clone());
                        let weights = flat(n, &|i, j| n.weight(i, j).unwrap().clone());
                        surface_corner_derivatives::<Sym, 4>(
                            &d(eu),
                            &d(ev),
                            &points,
                            Some(&weights),
                        )
                        .unwrap()
                    };
                    let (first, next) = (corner(&net, End::End), corner(&second, End::Start));
                    let k = kind.order();
                    assert_eq!(first[..=k], next[..=k], "{kind} axis {axis} v at its {ev}");
                    // the heights are generic (x, y continue linearly; the
                    // free point moved on, Q₃ = 2P₃ − P₀, meets C³ here)
                    assert!(
                        axis < 2 || k > 1 || first[k + 1] != next[k + 1],
                        "{kind} z v at its {ev}: the join holds beyond its order"
                    );
                }
            }
        }
    }
}
