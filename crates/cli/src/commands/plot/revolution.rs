//! `plot surface --revolution`: a profile curve of any basis swept about the
//! `z` axis by the circle's exact representation in a basis whose span holds
//! `cos θ`, `sin θ` (θ the basis's angle). The quarter circle's control points
//! `C_j` are found exactly by the span judge (`Σ k_j b_j = cos θ` and
//! `= sin θ` identically, [`trig_judge::span::span`]) at the `v` parameter
//! values, and must be rational (a net holds rationals) and the arc a quarter
//! (from `(1, 0)` at the start of the domain to `(0, 1)` at its end). For the
//! profile `Σ_i A_i(u) (r_i, 0, z_i)` the net `P_ij = (r_i C_j^x, r_i C_j^y, z_i)`
//! gives `S(u, v) = (r(u) cos θ(v), r(u) sin θ(v), z(u))` exactly; four such
//! patches, each turned a quarter about `z`, make the whole surface. Example:
//! `examples/han-quadratic.toml` at `λ = 0` spans `1, sin θ, cos θ`, its
//! quarter circle the points `(1, 0), (1, 1), (0, 1)`.

use rug::Rational;
use trig_core::net::ControlNet;
use trig_core::surface::Direction;
use trig_core::{Described, echo};
use trig_judge::exact::ExactBasis;
use trig_judge::span::{Span, span};
use trig_specfile::AnyBasis;
use trig_symbolic::Sym;

use crate::commands::CliError;

/// The control points of the quarter circle `(cos θ, sin θ)` in the `v`
/// direction's basis, exactly.
pub fn quarter_circle(v: &Direction<AnyBasis>) -> Result<Vec<[Rational; 2]>, CliError> {
    let id = v.basis.id();
    let values: Vec<Sym> = v.params.iter().map(|a| a.eval(&Sym::zero(), &[])).collect();
    let functions: Vec<Sym> = v
        .basis
        .exact_functions_at(&values)
        .into_iter()
        .collect::<Option<_>>()
        .ok_or_else(|| CliError::Usage(format!("`{id}` has no exact form at these values")))?;
    let domain = v.basis.domain();
    if domain.angle.is_none() {
        return Err(CliError::Usage(format!(
            "`{id}` has no angle: a circle is exact only in a basis whose span holds cos θ and sin θ"
        )));
    }
    let coefficients = |g: &str| {
        match span(&functions, &Sym::var(g)) {
        Span::Inside {
            coefficients,
            pivots,
        } if pivots.iter().all(|p| !p.is_zero()) => coefficients
            .iter()
            .map(|k| k.as_rational())
            .collect::<Option<Vec<Rational>>>()
            .ok_or_else(|| {
                CliError::Usage(format!(
                    "the circle's control points in `{id}` are not rational ({}): a net holds rationals",
                    coefficients
                        .iter()
                        .map(Sym::to_unicode)
                        .collect::<Vec<_>>()
                        .join(", ")
                ))
            }),
        _ => Err(CliError::Usage(format!(
            "the span of `{id}` at these values does not hold {} of its angle: no exact circle",
            if g == "c" { "cos" } else { "sin" }
        ))),
    }
    };
    let (x, y) = (coefficients("c")?, coefficients("s")?);
    // the arc from θ = 0 at the start to θ = π/2 at the end
    let quarter = [(&domain.start, [1, 0]), (&domain.end, [0, 1])]
        .into_iter()
        .all(|(end, expected)| {
            domain.atoms_at(end, &Sym::one(), &values).is_some_and(|a| {
                a.c.as_rational() == Some(Rational::from(expected[0]))
                    && a.s.as_rational() == Some(Rational::from(expected[1]))
            })
        });
    if !quarter {
        return Err(CliError::Usage(format!(
            "`{}`'s domain is not the quarter θ ∈ [0, π/2] at these values: four patches would not close the circle",
            echo(&id)
        )));
    }
    Ok(x.into_iter().zip(y).map(|(a, b)| [a, b]).collect())
}

/// The four quarter nets of the profile `profile` (one net row of points
/// `(r, 0, z)`) swept with the quarter circle `circle`.
pub fn revolution_nets(
    profile: &ControlNet,
    circle: &[[Rational; 2]],
) -> Result<Vec<ControlNet>, CliError> {
    if profile.rows() != 1 || profile.is_rational() {
        return Err(CliError::Usage(format!(
            "--revolution takes the profile as one net row of points `r 0 z` (no weights), not a {} × {} net",
            profile.rows(),
            profile.columns()
        )));
    }
    let points = &profile.points()[0];
    if points.iter().any(|p| p[1] != 0) {
        return Err(CliError::Usage(
            "--revolution: the profile lies in the xz plane (every y = 0), swept about the z axis"
                .into(),
        ));
    }
    (0..4)
        .map(|quarter| {
            let rows = points
                .iter()
                .map(|[r, _, z]| {
                    circle
                        .iter()
                        .map(|[cx, cy]| {
                            // a quarter turn (x, y) → (−y, x), `quarter` times
                            let (mut x, mut y) = (cx.clone(), cy.clone());
                            for _ in 0..quarter {
                                (x, y) = (-y, x);
                            }
                            [Rational::from(r * &x), Rational::from(r * &y), z.clone()]
                        })
                        .collect()
                })
                .collect();
            ControlNet::new(rows).map_err(|e| CliError::Usage(e.to_string()))
        })
        .collect()
}
