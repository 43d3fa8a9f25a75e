//! Property tests of the formula parser and a fuzz of the spec reader.
//!
//! * print-then-parse: any value built in the exact ring, printed with its
//!   canonical `Display`, parses back to the same value;
//! * random formula texts parse to exactly the value built directly with
//!   [`Sym`] operations, and evaluate identically in f64;
//! * the spec reader never panics on arbitrary bytes or on arbitrary
//!   combinations of spec fragments (case counts in /work/notes/spec_notes.md).

use proptest::prelude::*;
use rug::Rational;
use trig_core::{Basis, Domain, Variable};
use trig_specfile::Spec;
use trig_specfile::formula::{Scope, parse};
use trig_symbolic::Sym;

/// A formula as text together with its value built directly in the ring.
#[derive(Debug, Clone)]
struct Formula {
    text: String,
    value: Sym,
}

fn leaf() -> impl Strategy<Value = Formula> {
    prop_oneof![
        (0i64..20, 1i64..7).prop_map(|(n, d)| Formula {
            text: format!("{n}/{d}"),
            value: Sym::rational(Rational::from((n, d))),
        }),
        (0u32..1000).prop_map(|k| Formula {
            text: format!("{}.{:03}", k / 1000, k % 1000),
            value: Sym::rational(Rational::from((i64::from(k), 1000))),
        }),
        Just(Formula {
            text: "s".into(),
            value: Sym::var("s")
        }),
        Just(Formula {
            text: "c".into(),
            value: Sym::var("c")
        }),
        Just(Formula {
            text: "m".into(),
            value: Sym::var("m")
        }),
        Just(Formula {
            text: "λ".into(),
            value: Sym::var("lambda")
        }),
        Just(Formula {
            text: "pi".into(),
            value: Sym::pi()
        }),
        Just(Formula {
            text: "sin(pi*u/2)".into(),
            value: Sym::var("s")
        }),
        Just(Formula {
            text: "cos(2*pi*u/2)".into(),
            value: Sym::var("c") * &Sym::var("c") - &(Sym::var("s") * &Sym::var("s")),
        }),
    ]
}

fn formula() -> impl Strategy<Value = Formula> {
    leaf().prop_recursive(4, 24, 2, |inner| {
        prop_oneof![
            (inner.clone(), inner.clone()).prop_map(|(a, b)| Formula {
                text: format!("({}) + ({})", a.text, b.text),
                value: a.value + &b.value,
            }),
            (inner.clone(), inner.clone()).prop_map(|(a, b)| Formula {
                text: format!("({}) - ({})", a.text, b.text),
                value: a.value - &b.value,
            }),
            (inner.clone(), inner.clone()).prop_map(|(a, b)| Formula {
                text: format!("({})*({})", a.text, b.text),
                value: a.value * &b.value,
            }),
            (inner.clone(), 0u32..4).prop_map(|(a, e)| Formula {
                text: format!("({})^{e}", a.text),
                value: (0..e).fold(Sym::one(), |acc, _| acc * &a.value),
            }),
            // a divisor that cannot vanish: 3 + s² + c (≥ 2)
            inner.clone().prop_map(|a| Formula {
                text: format!("({})/(3 + s^2 + c)", a.text),
                value: a.value
                    / &(Sym::int(3) + &(Sym::var("s") * &Sym::var("s")) + &Sym::var("c")),
            }),
            inner.prop_map(|a| Formula {
                text: format!("-({})", a.text),
                value: -a.value,
            }),
        ]
    })
}

fn params() -> Vec<(String, String)> {
    vec![("m".into(), "m".into()), ("lambda".into(), "λ".into())]
}

fn scope<'a>(domain: &'a Domain, params: &'a [(String, String)]) -> Scope<'a> {
    Scope {
        domain,
        var_name: "u",
        shorthand: Some(1),
        params,
        resolve: &|_| None,
        extra: &[],
        divisor: &|d: &Sym| {
            if d.is_zero() {
                Err("zero".into())
            } else {
                Ok(())
            }
        },
    }
}

fn eval_f64(x: &Sym) -> Option<f64> {
    let (s, c) = (0.3f64.sin(), 0.3f64.cos());
    x.eval(&0.0, &|n| match n {
        "s" => Some(s),
        "c" => Some(c),
        "m" => Some(0.7),
        "lambda" => Some(-1.3),
        "pi" => Some(std::f64::consts::PI),
        _ => None,
    })
    .ok()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn print_then_parse_round_trips(f in formula()) {
        let p = params();
        let d = Domain::from_variable(Variable::UnitAngle, &["m", "lambda"]);
        let printed = f.value.to_string();
        let back = parse(&printed, &scope(&d, &p)).map_err(|e| TestCaseError::fail(format!("{printed}: {e}")))?;
        prop_assert_eq!(back, f.value);
    }

    #[test]
    fn parsed_text_equals_direct_construction(f in formula()) {
        let p = params();
        let d = Domain::from_variable(Variable::UnitAngle, &["m", "lambda"]);
        let parsed = parse(&f.text, &scope(&d, &p)).map_err(|e| TestCaseError::fail(format!("{}: {e}", f.text)))?;
        prop_assert_eq!(&parsed, &f.value);
        // same values in f64 (relative 1e-9: both evaluate the same reduced form)
        if let (Some(a), Some(b)) = (eval_f64(&parsed), eval_f64(&f.value)) {
            prop_assert!((a - b).abs() <= 1e-9 * (1.0 + b.abs()), "{} vs {}", a, b);
        }
    }
}

/// Fragments of spec files, right and wrong, combined at random.
const FRAGMENTS: &[&str] = &[
    "id = \"x\"\n",
    "id = \"\"\n",
    "citation = \"c\"\n",
    "variable = \"unit-angle\"\n",
    "variable = \"angle\"\n",
    "variable = \"polynomial\"\n",
    "variable = \"banana\"\n",
    "[[parameters]]\nname = \"m\"\nrange = \"[-2, 1]\"\n",
    "[[parameters]]\nname = \"m\"\nrange = \"[1, -2]\"\n",
    "[[parameters]]\nname = \"s\"\nrange = \"[0, 1]\"\n",
    "[[parameters]]\nname = \"a\"\nrange = \"(0, inf)\"\n",
    "[[functions]]\nname = \"b0\"\nformula = \"(1 - s)^2*(1 - m*s)\"\n",
    "[[functions]]\nname = \"b1\"\nformula = \"1 - b0\"\n",
    "[[functions]]\nname = \"b2\"\nformula = \"s/(m + 2)\"\n",
    "[[functions]]\nname = \"b3\"\nformula = \"t^2/(1 + t\"\n",
    "[[functions]]\nname = \"b4\"\nformula = \"cos(2*t) + q\"\n",
    "[[functions]]\nname = \"b5\"\nformula = \"(((((((((s)))))))))^64^64\"\n",
    "[[claims]]\nid = \"A\"\nsource = \"s\"\nstatement = \"p\"\ncheck = \"unity\"\n",
    "[[claims]]\nid = \"B\"\nsource = \"s\"\nstatement = \"p\"\ncheck = \"symmetry\"\nmap = \"1 - u\"\nindex = \"3 - i\"\n",
    "[[claims]]\nid = \"C\"\nsource = \"s\"\nstatement = \"p\"\ncheck = \"endpoint-values\"\nend = \"end\"\nvalues = [\"b0 = 1\", \"zz = 2\"]\n",
    "[[claims]]\nid = \"D\"\nsource = \"s\"\nstatement = \"p\"\ncheck = \"join\"\njoin = \"C1\"\nconditions = [\"Q1 = 2*P3 - P2\", \"P0 = 1\"]\n",
    "[[claims]]\nid = \"E\"\nsource = \"s\"\nstatement = \"p\"\ncheck = \"continuity\"\norder = 99\n",
    "[[claims]]\nid = \"F\"\nsource = \"s\"\nstatement = \"p\"\ncheck = \"monotone\"\nfunctions = [\"b0 sideways\"]\n",
    "variable = \"t\"\ndomain = \"[0, alpha]\"\n",
    "variable = \"x\"\ndomain = \"[-pi/2, pi/2]\"\n",
    "variable = \"t\"\ndomain = \"[1, 0]\"\n",
    "domain = \"[0, pi]\"\n",
    "[[parameters]]\nname = \"alpha\"\nrange = \"(0, 3)\"\n",
    "[[parameters]]\nname = \"mu\"\nrange = \"[-2, 1]\"\n",
    "[[definitions]]\nname = \"w\"\nformula = \"alpha - sin(alpha)\"\n",
    "[[definitions]]\nname = \"k\"\nformula = \"k + 1\"\n",
    "[[functions]]\nname = \"z0\"\nformula = \"(t - sin(t))/w\"\n",
    "[[functions]]\nname = \"z1\"\nformula = \"1 - z0 - z2\"\n",
    "[[functions]]\nname = \"z2\"\nformula = \"sinh(t)*exp(-2*t) + cos(3*t/2)*sin(t/2)\"\n",
    "[[functions]]\nname = \"z3\"\nformula = \"cos(24*t)^64\"\n",
    "[[functions]]\nname = \"z4\"\nformula = \"((1 + s)^64)^64\"\n",
    "[[functions]]\nname = \"z5\"\nformula = \"2 s + sqrt(2)*sin(pi/4)\"\n",
    "[[claims]]\nid = \"G\"\nsource = \"s\"\nstatement = \"p\"\ncheck = \"symmetry\"\nmap = \"alpha - t\"\nindex = \"3 - i\"\nparams = { m = \"mu\", mu = \"m\" }\n",
    "[[claims]]\nid = \"H\"\nsource = \"s\"\nstatement = \"p\"\ncheck = \"join\"\njoin = \"G2\"\ndifferent = true\nconditions = [\"Q0 = P3\", \"Q1 = P3 + gamma*(P3 - P2)/m1\"]\n",
    "[[claims]]\nid = \"I\"\nsource = \"s\"\nstatement = \"p\"\ncheck = \"curve-derivative\"\nend = \"start\"\norder = 1\nvalue = \"(m + 2)*(P1 - P0)\"\n",
    "[[claims]]\nid = \"J\"\nsource = \"s\"\nstatement = \"p\"\ncheck = \"convex-hull\"\n",
    "garbage = [1, 2\n",
    "\u{0}\u{ff}\n",
];

proptest! {
    #![proptest_config(ProptestConfig::with_cases(20_000))]

    #[test]
    fn spec_reader_never_panics_on_bytes(bytes in proptest::collection::vec(any::<u8>(), 0..400)) {
        let text = String::from_utf8_lossy(&bytes);
        let _ = Spec::from_str_named(&text, "fuzz.toml");
    }

    #[test]
    fn spec_reader_never_panics_on_fragments(picks in proptest::collection::vec(0..FRAGMENTS.len(), 0..12), cut in 0usize..2000) {
        let text: String = picks.iter().map(|&i| FRAGMENTS[i]).collect();
        let cut = text.char_indices().map(|(i, _)| i).find(|&i| i >= cut).unwrap_or(text.len());
        for t in [&text[..], &text[..cut]] {
            if let Ok(spec) = Spec::from_str_named(t, "fuzz.toml") {
                // a spec that loads evaluates without panicking
                let p: Vec<f64> = spec.params.iter().map(|q| q.range.interior_point().to_f64()).collect();
                let d = spec.domain.clone();
                let pv: Vec<f64> = p.clone();
                let x = (d.start_value(&0.0, &pv) + d.end_value(&0.0, &pv)) / 2.0;
                let atoms = d.atoms(&x);
                let _ = Basis::eval(&spec, &atoms, &p);
            }
        }
    }
}
