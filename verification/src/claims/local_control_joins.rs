//! The join and interpolation claims beside local control (see
//! [`super::local_control`]): the thesis's G² condition against curvature
//! (T51), the control points
//! its C¹ refinement moves (T65), and seed 002's open and closed
//! interpolating splines (D17); with the two curves they share with the
//! local-control claims (seed 002's segment (4), the thesis cubic's end
//! tangents).

use std::fmt;

use trig_core::Family;
use trig_symbolic::Sym;

use super::seed002::rational_ends;
use trig_judge::exact::{IDENTITY, basis, identities, identity_item, symbols};
use trig_verdict::evidence::{Evidence, Kind};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

/// An index `k·n + c` of seed 002's construction (`n`: the last point).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
struct Ix {
    n: i64,
    c: i64,
}

impl Ix {
    const fn at(n: i64, c: i64) -> Ix {
        Ix { n, c }
    }
    fn plus(self, c: i64) -> Ix {
        Ix::at(self.n, self.c + c)
    }
}

impl fmt::Display for Ix {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (self.n, self.c) {
            (0, c) => write!(f, "{c}"),
            (1, 0) => write!(f, "n"),
            (1, c) if c > 0 => write!(f, "n+{c}"),
            (1, c) => write!(f, "n−{}", -c),
            (k, c) => write!(f, "{k}n{c:+}"),
        }
    }
}

/// An index range `[lo, hi]`, with `n` large enough for the order of the
/// ends to be that of their constants when their `n`-coefficients agree.
type Range = (Ix, Ix);

fn contains(outer: Range, inner: Range) -> bool {
    outer.0 <= inner.0 && inner.1 <= outer.1
}

fn text(r: Range) -> String {
    format!("{} … {}", r.0, r.1)
}

/// Segments `Q_a … Q_b` of (6): each `Q_i(t, α_i, α_{i+1})` uses the points
/// `V_{i−1} … V_{i+2}`, the knots `u_i, u_{i+1}`, the parameters `α_i,
/// α_{i+1}`, and runs from `V_i` to `V_{i+1}`; the check that what it needs
/// is given, and the points it interpolates.
fn bookkeeping(
    name: &str,
    segments: Range,
    points: Range,
    knots: Range,
    params: Range,
    want: Range,
) -> Verdict {
    let (a, b) = segments;
    let needs = [
        ("points V", (a.plus(-1), b.plus(2)), points),
        ("knots u", (a, b.plus(1)), knots),
        ("parameters α", (a, b.plus(1)), params),
    ];
    let mut items: Vec<Evidence> = needs
        .iter()
        .map(|(what, need, given)| {
            let ok = contains(*given, *need);
            Evidence::new(
                Kind::Derived,
                format!(
                    "segments Q_{{{}}} need {what}_{{{}}}; given {what}_{{{}}}",
                    text(segments),
                    text(*need),
                    text(*given)
                ),
            )
            .about(
                format!("{name}: {what}"),
                if ok { Status::Holds } else { Status::Fails },
            )
        })
        .collect();
    let reached = (a, b.plus(1));
    items.push(
        Evidence::new(
            Kind::Derived,
            format!(
                "Q_i(0) = V_i, Q_i(π/2) = V_{{i+1}}: interpolated V_{{{}}}; claimed V_{{{}}}",
                text(reached),
                text(want)
            ),
        )
        .about(
            format!("{name}: interpolated points"),
            if reached == want {
                Status::Holds
            } else {
                Status::Fails
            },
        ),
    );
    let status = Status::conjunction(items.iter().filter_map(|e| e.status));
    Verdict::new(status, IDENTITY, items)
}

/// D17: the segment of (6) interpolates its middle points (exactly, from
/// the curve (2) with the points of (3)); the index bookkeeping of the
/// construction, with the added points, knots and parameters, for every
/// `n`; and what the closing knot needs.
pub(super) fn d17() -> Verdict {
    let q = seed002_segment();
    let at = |s: i64, c: i64| q.subs("s", &Sym::int(s)).subs("c", &Sym::int(c));
    let ends = identities(vec![
        ("Q_i(0) = V_i (local V1)".into(), at(0, 1), Sym::var("V1")),
        (
            "Q_i(π/2) = V_{i+1} (local V2)".into(),
            at(1, 0),
            Sym::var("V2"),
        ),
    ]);
    let (zero, n) = (Ix::at(0, 0), Ix::at(1, 0));
    let one = Ix::at(0, 1);
    let printed = bookkeeping(
        "(6) as given",
        (one, n.plus(-2)),
        (zero, n),
        (one, n.plus(-1)),
        (one, n.plus(-1)),
        (one, n.plus(-1)),
    );
    let open = bookkeeping(
        "open",
        (zero, n.plus(-1)),
        (Ix::at(0, -1), n.plus(1)),
        (zero, n),
        (zero, n),
        (zero, n),
    );
    let closed = bookkeeping(
        "closed",
        (zero, n),
        (Ix::at(0, -1), n.plus(2)),
        (zero, n.plus(1)),
        (zero, n.plus(1)),
        (zero, n.plus(1)),
    );
    // the closing knot: Q_n ends at V_{n+1} = V_0 with tangent
    // α_{n+1}(V_{n+2} − V_n) = α_{n+1}(V_1 − V_n) (in t), Q_0 starts with
    // α_0(V_1 − V_{−1}) = α_0(V_1 − V_n): (8) there needs α_{n+1} = α_0
    let (a0, an1) = (Sym::var("a0"), Sym::var("aN"));
    let chord = Sym::var("V1") - &Sym::var("Vn");
    let closing = identity_item(
        "closing knot, t-tangents of Q_n(π/2) and Q_0(0): α_{n+1}(V_1 − V_n) = α_0(V_1 − V_n) (a0 = α_0, aN = α_{n+1}, Vn = V_n)",
        &(an1 * &chord),
        &(a0 * &chord),
    );
    let mut v = Verdict::all(
        IDENTITY,
        vec![
            ("each segment interpolates".into(), ends),
            ("the spline (6)–(7)".into(), printed),
            ("open curve".into(), open),
            ("closed curve".into(), closed),
        ],
    );
    v.evidence.insert(0, Evidence::note("Q_i of (6) on V_{i−1} … V_{i+2} is the rational curve (2) with P0…P5 from (3) (reading D6b); the print names the interpolation points Q_i (and P_i for the closed curve) where (6) has V_i; (7) lists i = 1 … n − 1, but (6) defines segments for i = 1 … n − 2 only (Q_{n−1} would need V_{n+1}); index ranges are decided for every n ≥ 3"));
    let mut note = Evidence::new(
        Kind::Derived,
        "not claimed by the text, but needed for Theorem 1's relations (8) at the closing knot u_{n+1} ≡ u_0: the third added parameter α_{n+1} must equal α_0 (the print leaves it free); otherwise the tangents there differ by the factor α_0/α_{n+1}",
    );
    note.exprs = closing.exprs.clone();
    note.witness = closing.witness.clone();
    v.evidence.push(note);
    v
}

/// The rational curve (2) of seed 002 with the control points fixed by
/// the end conditions (3) (reading D6b): `Q(t, α1, α2)` of (4) on the local
/// points `V0 … V3` (one coordinate), the weights `w0 … w5` as symbols.
/// `P0 = V1`, `P5 = V2`; `P1`, `P2` solve `R'(0)`, `R''(0)`, and `P4`, `P3`
/// solve `R'(π/2)`, `R''(π/2)`, each linear in its point.
pub(super) fn seed002_segment() -> Sym {
    let v = symbols("V", 4);
    let w = symbols("w", 6);
    let mut p = symbols("P", 6);
    let (a1, a2) = (Sym::var("alpha1"), Sym::var("alpha2"));
    let two = Sym::int(2);
    p[0] = v[1].clone();
    p[5] = v[2].clone();
    // (end, order, the unknown point, its right-hand side in (3))
    let steps = [
        (0, 1, 1, a1.clone() * &(v[2].clone() - &v[0])),
        (
            0,
            2,
            2,
            a1 * &(v[0].clone() - &(two.clone() * &v[1]) + &v[2]),
        ),
        (1, 1, 4, a2.clone() * &(v[3].clone() - &v[1])),
        (1, 2, 3, a2 * &(v[1].clone() - &(two * &v[2]) + &v[3])),
    ];
    for (end, order, k, rhs) in steps {
        let (r0, r1) = rational_ends(&p, &w);
        let lhs = if end == 0 { &r0[order] } else { &r1[order] };
        let name = format!("P{k}");
        let coefficient = lhs.diff(&name);
        let rest = lhs.subs(&name, &Sym::zero());
        p[k] = (rhs - &rest) / &coefficient;
    }
    let b = basis(Family::Seed002Quartic);
    let num = (0..6).fold(Sym::zero(), |acc, k| acc + &(w[k].clone() * &b[k] * &p[k]));
    let den = (0..6).fold(Sym::zero(), |acc, k| acc + &(w[k].clone() * &b[k]));
    num / &den
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_seed002_segment_interpolates_its_middle_points() {
        let q = seed002_segment();
        let at = |s: i64, c: i64| q.subs("s", &Sym::int(s)).subs("c", &Sym::int(c));
        assert_eq!(at(0, 1), Sym::var("V1"));
        assert_eq!(at(1, 0), Sym::var("V2"));
    }

    #[test]
    fn index_ranges_print_and_compare() {
        let n = Ix::at(1, 0);
        assert_eq!(n.plus(-2).to_string(), "n−2");
        assert_eq!(n.plus(1).to_string(), "n+1");
        assert!(contains((Ix::at(0, -1), n.plus(1)), (Ix::at(0, 0), n)));
        assert!(!contains((Ix::at(0, 0), n), (Ix::at(0, -1), n)));
    }
}
