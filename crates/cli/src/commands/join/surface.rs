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

use super::{JoinArgs, JoinFormat, Solved, json_value, solve, tex, text};
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
    let v = args.surface.v_basis(&u)?;
    if !args.surface.v_params.is_empty() {
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

/// The curve join written for every column (across `u`) or row (across
/// `v`) of the nets: `P_i → P_ij`, `Q_i → Q_ij` (or `P_ji`, `Q_ji`).
fn by_columns(solved: Solved, count: usize, across: Across) -> Solved {
    let n = solved.family.function_names().len();
    let [p, q] = solved.curves.clone();
    let wide = n > 10 || count > 10;
    let name = |letter: &str, i: usize, k: usize| {
        let (a, b) = match across {
            Across::U => (i, k),
            Across::V => (k, i),
        };
        if wide {
            format!("{letter}{a}_{b}")
        } else {
            format!("{letter}{a}{b}")
        }
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::commands::join::ParamsArg;
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
}
