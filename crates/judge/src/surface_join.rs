//! The surface-join judge: tensor-product patches `S(u, v) = Σᵢ Σⱼ Pᵢⱼ
//! bᵢ(u) bⱼ(v)` of one basis over control nets (`check = "surface-join"`,
//! the nets a printed listing builds), `Cᵏ` across each seam, exactly.
//!
//! Across a seam `A | B` (the last column of `A` meets the first of `B`) the
//! `r`-th derivative in `v` jumps by `Jᵣ(u) = Σᵢ bᵢ(u)·jᵢᵣ`, where `jᵢᵣ` is the
//! jump of the curve join of row `i` (`Σⱼ Bᵢⱼ bⱼ` at the start minus `Σⱼ Aᵢⱼ
//! bⱼ` at the end, the curve join engine's residual); a seam `A ; B` is the
//! same with columns. The seam is `Cᵏ` exactly when every `Jᵣ`, `r ≤ k`,
//! vanishes identically — decided in the exact ring, so a nonzero line jump
//! counts only through the surface's own jump.

use trig_deriv::{JoinKind, JoinSetup, Wrt};
use trig_specfile::{Across, ListedNet, Seam};
use trig_symbolic::Sym;

use crate::domain::{describe_wrt, param_symbols};
use crate::exact::{ExactBasis, basis_of, sum};
use trig_verdict::evidence::{Evidence, EvidenceList, Witness};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

const COORDINATES: [&str; 3] = ["x", "y", "z"];

/// Every seam of the claim `Cᵏ` (`kind`) in the convention `wrt`.
pub fn surface_join<B: ExactBasis>(
    basis: &B,
    kind: JoinKind,
    wrt: Wrt,
    path: &str,
    nets: &[ListedNet],
    seams: &[Seam],
) -> Verdict {
    let own = param_symbols(basis);
    let setup = JoinSetup {
        basis,
        first_params: &own,
        second_params: &own,
        wrt,
        h: (Sym::one(), Sym::one()),
        factors: trig_deriv::default_factors(),
    };
    let ends = setup.end_derivatives();
    let functions = basis_of(basis);
    let convention = describe_wrt(basis, wrt);
    let mut evidence = EvidenceList::default();
    let mut holds = true;
    for seam in seams {
        let (a, b) = (&nets[seam.first], &nets[seam.second]);
        let n = a.points.len();
        // jumps[line][order][coordinate]
        let jumps: Vec<Vec<[Sym; 3]>> = (0..n)
            .map(|line| {
                let per: Vec<Vec<Sym>> = (0..3)
                    .map(|c| {
                        let first = line_of(a, seam.across, line, c);
                        let second = line_of(b, seam.across, line, c);
                        setup.residuals_with(&ends, kind, &first, &second)
                    })
                    .collect();
                (0..=kind.order())
                    .map(|r| std::array::from_fn(|c| per[c][r].clone()))
                    .collect()
            })
            .collect();
        let broken: Vec<usize> = (0..=kind.order())
            .filter(|&r| {
                (0..3).any(|c| {
                    let surface: Vec<Sym> = (0..n)
                        .map(|line| functions[line].clone() * &jumps[line][r][c])
                        .collect();
                    !sum(&surface).is_zero()
                })
            })
            .collect();
        if broken.is_empty() {
            evidence.push(format!(
                "{}: {} holds exactly in every {}",
                seam.label,
                superscript(kind),
                line_word(seam.across)
            ));
            continue;
        }
        holds = false;
        let mut witnessed = false;
        for (line, per_order) in jumps.iter().enumerate() {
            for (r, jump) in per_order.iter().enumerate() {
                let Some(c) = jump.iter().position(|x| !x.is_zero()) else {
                    continue;
                };
                let what = format!(
                    "{} {line} (points {}): order-{r} jump (second − first)",
                    line_word(seam.across),
                    indices(n, seam.across, line)
                );
                let vector: Vec<String> = jump.iter().map(ToString::to_string).collect();
                let text = format!("{}: {what} = ({})", seam.label, vector.join(", "));
                let witness = if witnessed {
                    None
                } else {
                    jump_witness(&setup, &ends, kind, (a, b), seam, (line, r, c), &what).map(|mut w| {
                        w.note = Some(format!(
                            "{}: the {}-coordinates of {} {line} of the nets, derivatives {convention}",
                            seam.label,
                            COORDINATES[c],
                            line_word(seam.across)
                        ));
                        w
                    })
                };
                witnessed = true;
                evidence.push(Evidence::note(text).witnessed(witness));
            }
        }
        let orders: Vec<String> = broken.iter().map(ToString::to_string).collect();
        evidence.push(format!(
            "{}: the surface's jump Σᵢ bᵢ·(jump of {} i) across the seam is not identically 0 (exact) for the order(s) {}",
            seam.label,
            line_word(seam.across),
            orders.join(", ")
        ));
    }
    let status = if holds { Status::Holds } else { Status::Fails };
    Verdict::new(
        status,
        format!(
            "the control nets of `{path}` built statement by statement (exact); the jumps of orders 0–{} across each seam, {} by {}, derivatives {convention}; a seam is {} when the surface's jumps there vanish identically",
            kind.order(),
            "line",
            "line",
            superscript(kind)
        ),
        evidence,
    )
}

/// Row `line` of the net (a seam beside it) or its column (a seam below),
/// coordinate `c`: the control points of one curve crossing the seam.
fn line_of(net: &ListedNet, across: Across, line: usize, c: usize) -> Vec<Sym> {
    let n = net.points.len();
    (0..n)
        .map(|k| match across {
            Across::Columns => net.points[line][k][c].clone(),
            Across::Rows => net.points[k][line][c].clone(),
        })
        .collect()
}

/// `C⁰`…`C³`.
fn superscript(kind: JoinKind) -> String {
    let digits = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    let k = kind.order();
    format!("C{}", digits.get(k).map_or(k.to_string(), char::to_string))
}

fn line_word(across: Across) -> &'static str {
    match across {
        Across::Columns => "row",
        Across::Rows => "column",
    }
}

/// The row-major numbers `i·n + j` of the points of one line.
fn numbers(n: usize, across: Across, line: usize) -> Vec<usize> {
    (0..n)
        .map(|k| match across {
            Across::Columns => line * n + k,
            Across::Rows => k * n + line,
        })
        .collect()
}

fn indices(n: usize, across: Across, line: usize) -> String {
    let k = numbers(n, across, line);
    match across {
        Across::Columns => format!("{}…{}", k[0], k[n - 1]),
        Across::Rows => k
            .iter()
            .map(ToString::to_string)
            .collect::<Vec<_>>()
            .join(", "),
    }
}

/// The jump of `order` in coordinate `c` of one line as a formula in the
/// line's control points, named by net and row-major number (`P4r…`), at
/// their values; `None` where a value is not a rational number.
fn jump_witness<B: ExactBasis>(
    setup: &JoinSetup<'_, &B>,
    ends: &trig_deriv::EndDerivatives,
    kind: JoinKind,
    (a, b): (&ListedNet, &ListedNet),
    seam: &Seam,
    (line, order, c): (usize, usize, usize),
    what: &str,
) -> Option<Witness> {
    let n = a.points.len();
    let names = |net: &ListedNet| {
        numbers(n, seam.across, line)
            .into_iter()
            .map(|k| format!("{}{k}", net.name))
            .collect::<Vec<_>>()
    };
    let (na, nb) = (names(a), names(b));
    let vars = |ns: &[String]| ns.iter().map(|x| Sym::var(x)).collect::<Vec<_>>();
    let formula = setup.residuals_with(ends, kind, &vars(&na), &vars(&nb))[order].clone();
    let values = line_of(a, seam.across, line, c)
        .into_iter()
        .chain(line_of(b, seam.across, line, c))
        .map(|x| x.as_rational())
        .collect::<Option<Vec<_>>>()?;
    let point: Vec<(String, rug::Rational)> = na.iter().chain(&nb).cloned().zip(values).collect();
    let names: Vec<String> = point.iter().map(|(x, _)| x.clone()).collect();
    let label = format!("{what}, {}", COORDINATES[c]);
    trig_verdict::witness::of_exprs(&point, &names, &[(label.as_str(), &formula)])
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_specfile::{Check, Spec};

    /// Bernstein quadratic patches over the listing `nets`, C¹ across `P | Q`.
    fn decided(name: &str, nets: &str) -> Verdict {
        let dir = std::env::temp_dir().join(format!("surface-join-{name}-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join("nets.txt"), nets).unwrap();
        let text = "id = \"b2\"\ncitation = \"c\"\nvariable = \"polynomial\"\n[[functions]]\nname = \"B0\"\nformula = \"(1 - t)^2\"\n[[functions]]\nname = \"B1\"\nformula = \"2*t*(1 - t)\"\n[[functions]]\nname = \"B2\"\nformula = \"t^2\"\n[[claims]]\nid = \"s\"\nsource = \"s\"\nstatement = \"s\"\ncheck = \"surface-join\"\ndata = \"nets.txt\"\njoin = \"C1\"\nseams = [\"P | Q\"]\n";
        let spec = Spec::from_str_named(text, dir.join("b2.toml").to_str().unwrap())
            .unwrap_or_else(|e| panic!("{e}"));
        let Check::SurfaceJoin {
            path,
            kind,
            wrt,
            nets,
            seams,
        } = &spec.claims[0].check
        else {
            panic!("a surface join");
        };
        surface_join(&spec, *kind, *wrt, path, nets, seams)
    }

    const FIRST: &str = "A = (0, 0, 0)\nB = (1, 2, 0)\nC = (2, 0, 1)\nD = (0, 0, 1)\nE = (1, 2, 1)\nF = (2, 0, 2)\nnet P = A B C; D E F; A B C\n";

    #[test]
    fn a_seam_is_smooth_exactly_when_every_line_joins() {
        // Q's first two columns from P's last two: C¹ in every row
        let smooth = format!("{FIRST}G = 2*C - B\nH = 2*F - E\nnet Q = C G A; F H A; C G A\n");
        let v = decided("smooth", &smooth);
        assert_eq!(v.status, Status::Holds, "{v:?}");
        // one row's tangent off: the surface's jump is not 0, the row named
        let kinked = format!("{FIRST}G = 2*C - B\nH = 2*F - D\nnet Q = C G A; F H A; C G A\n");
        let v = decided("kinked", &kinked);
        assert_eq!(v.status, Status::Fails);
        let row = v
            .evidence
            .iter()
            .find(|e| {
                e.text
                    .starts_with("P | Q: row 1 (points 3…5): order-1 jump")
            })
            .unwrap_or_else(|| panic!("{v:?}"));
        assert!(row.witness.is_some(), "the first jump's witness");
        assert!(
            !v.evidence
                .iter()
                .any(|e| e.text.starts_with("P | Q: row 0"))
        );
    }
}
