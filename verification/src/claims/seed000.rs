//! Seed 000 (Majeed et al. 2020): the partition of unity of the printed
//! non-uniform coefficients (2)–(3) (M3), and those coefficients in the
//! uniform case (M3b).

use trig_core::families::seed000::uniform_normaliser;
use trig_core::families::seed000_nonuniform::NonUniform;
use trig_symbolic::Sym;

use crate::claim::Claim;
use trig_judge::exact::{IDENTITY, residual_verdict};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

pub const CLAIMS: &[Claim] = &[Claim {
    id: "M3b",
    check: m3b,
}];

fn zeta() -> Sym {
    Sym::var("zeta")
}

fn m3b() -> Verdict {
    let knots: Vec<Sym> = (0..=20).map(Sym::int).collect();
    let f = NonUniform::new(knots, zeta());
    let j = 10;
    let inv = Sym::one() / &uniform_normaliser(&zeta());
    let zero = Sym::zero();
    let expected_b = [zero.clone(), inv.clone(), zero.clone(), zero.clone()];
    let expected_c = [zero.clone(), zero.clone(), inv.clone(), zero];
    let mut parts: Vec<(String, Verdict)> = Vec::new();
    let mut check = |name: String, got: Result<Sym, trig_core::CoreError>, want: &Sym| {
        let v = match got {
            Ok(x) => residual_verdict(&x, want),
            Err(e) => Verdict::new(
                Status::Fails,
                IDENTITY,
                vec![format!("the printed formula is undefined: {e}")],
            ),
        };
        parts.push((name, v));
    };
    check(format!("a_{j} − 1/(6ζ²−6ζ+10)"), f.a(j), &inv);
    check(format!("d_{j} − 1/(6ζ²−6ζ+10)"), f.d(j), &inv);
    for (name, row, expected) in [("b", f.b(j), &expected_b), ("c", f.c(j), &expected_c)] {
        match row {
            Ok(row) => {
                for k in 0..4 {
                    check(
                        format!("{name}_{{{j},{k}}} − Appendix A"),
                        Ok(row[k].clone()),
                        &expected[k],
                    );
                }
            }
            Err(e) => check(
                format!("{name}_{{{j},0..3}} − Appendix A"),
                Err(e),
                &expected[0],
            ),
        }
    }
    let mut v = Verdict::all(IDENTITY, parts);
    v.evidence.insert(
        0,
        "uniform knots n_i = i (unit spacing; q_j = q_{j−1} = q_{j−2} as the paper states), span j = 10; Appendix A uses F0 = l0/D, F1 = l1/D, F2 = l2/D, F3 = l3/D with D = 6ζ² − 6ζ + 10",
    );
    v
}
