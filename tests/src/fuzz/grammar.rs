//! The command-line grammar as proptest strategies: every subcommand with
//! its options, values drawn from the published ranges (so that most cases
//! compute something) and from a list of hostile inputs (non-finite and
//! enormous numbers, points a hair outside the domain, long and multi-line
//! strings, out-of-range precisions), plus plain garbage.

use std::path::PathBuf;

use proptest::prelude::*;
use proptest::strategy::BoxedStrategy;
use rug::Rational;
use trig_core::{Described as _, Domain, Family};
use trig_specfile::Spec;

/// What the oracle can check beyond "no panic, no hang, one-line errors".
#[derive(Debug, Clone)]
pub enum Check {
    /// Nothing more.
    Plain,
    /// `eval` of a basis at a point: every printed digit against a
    /// reference.
    Eval {
        basis: Subject,
        params: Vec<(String, String)>,
        at: String,
        piecewise: bool,
    },
    /// `join --format json`: the symbols the tool introduces (G factors,
    /// interval lengths) read unlike every parameter name and symbol.
    Namespace { params: Vec<String> },
    /// `table --numeric` at the ends: every printed digit against a
    /// reference.
    Table {
        basis: Subject,
        params: Vec<(String, String)>,
        order: usize,
        wrt: String,
        h: Option<String>,
    },
}

/// A basis the oracle can evaluate in plain MPFR.
#[derive(Debug, Clone)]
pub enum Subject {
    Family(Family),
    Spec(PathBuf),
}

/// One generated command line.
#[derive(Debug, Clone)]
pub struct Case {
    pub args: Vec<String>,
    pub check: Check,
}

/// A parameter as the generator sees it: name and finite range ends.
#[derive(Debug, Clone)]
struct Param {
    name: String,
    lo: Option<Rational>,
    hi: Option<Rational>,
}

/// A basis to put on a command line.
#[derive(Debug, Clone)]
struct Basis {
    /// Command-line form: `[id]` or `["--spec", path]`.
    arg: Vec<String>,
    subject: Option<Subject>,
    params: Vec<Param>,
    /// The domain `[a, b]` (ends at interior parameter values), rounded.
    span: (f64, f64),
}

/// The ends of `domain` in f64 with the parameters at interior values.
fn span(domain: &Domain, params: &[Param]) -> (f64, f64) {
    let p: Vec<f64> = params
        .iter()
        .map(|p| match (&p.lo, &p.hi) {
            (Some(a), Some(b)) => ((a.clone() + b) / 2u32).to_f64(),
            (Some(a), None) => a.to_f64() + 1.0,
            (None, Some(b)) => b.to_f64() - 1.0,
            (None, None) => 0.0,
        })
        .collect();
    (domain.start_value(&1.0, &p), domain.end_value(&1.0, &p))
}

fn examples_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../examples")
}

/// The catalog families, the shipped spec files and the hostile ones in
/// `scratch`.
fn bases(scratch: &std::path::Path) -> Vec<Basis> {
    let mut out: Vec<Basis> = Family::ALL
        .into_iter()
        .filter(Family::has_formulas)
        .map(|f| {
            let params: Vec<Param> = f
                .info()
                .params
                .iter()
                .map(|p| Param {
                    name: p.name.into(),
                    lo: p.range.lo.value(),
                    hi: p.range.hi.value(),
                })
                .collect();
            Basis {
                arg: vec![f.info().id.to_string()],
                subject: Some(Subject::Family(f)),
                span: span(&f.domain(), &params),
                params,
            }
        })
        .collect();
    let mut files: Vec<PathBuf> = [examples_dir(), scratch.to_path_buf()]
        .iter()
        .flat_map(|dir| {
            std::fs::read_dir(dir)
                .map(|d| {
                    d.filter_map(|e| e.ok().map(|e| e.path()))
                        .collect::<Vec<_>>()
                })
                .unwrap_or_default()
        })
        .collect();
    files.retain(|p| p.extension().is_some_and(|e| e == "toml"));
    files.sort();
    for path in files {
        let Ok(spec) = Spec::from_file(&path) else {
            continue;
        };
        let params: Vec<Param> = spec
            .params
            .iter()
            .map(|p| Param {
                name: p.name.clone(),
                lo: p.range.lo.value().cloned(),
                hi: p.range.hi.value().cloned(),
            })
            .collect();
        let span = span(&spec.domain, &params);
        out.push(Basis {
            arg: vec!["--spec".into(), path.display().to_string()],
            subject: Some(Subject::Spec(path)),
            params,
            span,
        });
    }
    // a spec refused for a shadowing symbol, and devices as spec files
    for odd in [
        scratch.join("shadow.toml").display().to_string(),
        "/dev/zero".into(),
        "/dev/null".into(),
    ] {
        out.push(Basis {
            arg: vec!["--spec".into(), odd],
            subject: None,
            params: Vec::new(),
            span: (0.0, 1.0),
        });
    }
    for odd in [
        "seed000-nonuniform",
        "seed000-nonuniform",
        "seed000-nonuniform",
        "seed003",
        "no-such-family",
        "",
    ] {
        out.push(Basis {
            arg: vec![odd.into()],
            subject: None,
            params: vec![Param {
                name: "zeta".into(),
                lo: Some(Rational::new()),
                hi: Some(Rational::from(4)),
            }],
            span: (0.0, std::f64::consts::FRAC_PI_2),
        });
    }
    out
}

/// Hostile numbers: non-finite, enormous, tiny, a hair outside ranges,
/// malformed, long, multi-line.
pub fn hostile_number() -> BoxedStrategy<String> {
    let fixed = [
        "0",
        "1",
        "-1",
        "2",
        "-2",
        "1/3",
        "-1/2",
        "0.6",
        "1e400",
        "-1e400",
        "1e-400",
        "1e308",
        "-1e308",
        "1e-320",
        "1e10000",
        "-1e10000",
        "1e10001",
        "nan",
        "NaN",
        "inf",
        "-inf",
        "infinity",
        "1/0",
        "0/0",
        "1.00000000000000000000000001",
        "-0.00000000000000000000000001",
        "0.99999999999999999999999999",
        "1.5707963267948966",
        "1.5707963267948967",
        "",
        " ",
        "-",
        "+",
        ".",
        "e",
        "1e",
        "1e+",
        "--1",
        "1..2",
        "1/2/3",
        "0x10",
        "٣",
        "1\n2",
        "1,5",
        "½",
        "99999999999999999999999999999999999999",
        "-0",
        "+0.5",
        " 0.5 ",
        "5e-1",
    ];
    prop_oneof![
        4 => proptest::sample::select(fixed.to_vec()).prop_map(String::from),
        1 => (any::<i64>(), -400i32..400).prop_map(|(m, e)| format!("{m}e{e}")),
        1 => (-10_000i64..10_000, 1i64..10_000).prop_map(|(n, d)| format!("{n}/{d}")),
        1 => any::<f64>().prop_map(|x| x.to_string()),
        1 => "[0-9]{1,200}(\\.[0-9]{0,200})?",
        1 => "\\PC{0,30}",
    ]
    .boxed()
}

/// A value strictly inside `[lo, hi]` (one step beyond a single finite end).
fn inside(p: &Param) -> BoxedStrategy<String> {
    let (lo, hi) = (p.lo.clone(), p.hi.clone());
    (0u32..=1000)
        .prop_map(move |k| {
            let t = Rational::from((k + 1, 1002));
            let v = match (&lo, &hi) {
                (Some(a), Some(b)) => a.clone() + (b.clone() - a) * t,
                (Some(a), None) => a.clone() + t * 7u32,
                (None, Some(b)) => b.clone() - t * 7u32,
                (None, None) => (t - Rational::from((1, 2))) * 10u32,
            };
            v.to_string()
        })
        .boxed()
}

/// `--param name=value` for every parameter: mostly in range, sometimes
/// hostile, rarely misnamed or missing.
fn params(ps: &[Param]) -> BoxedStrategy<Vec<(String, String)>> {
    let each: Vec<BoxedStrategy<Option<(String, String)>>> = ps
        .iter()
        .map(|p| {
            let name = p.name.clone();
            let wrong = name.clone();
            prop_oneof![
                40 => inside(p).prop_map(move |v| Some((name.clone(), v))),
                4 => hostile_number().prop_map(move |v| Some((wrong.clone(), v))),
                1 => Just(None),
                1 => ("[a-zβ]{1,6}", hostile_number()).prop_map(|(n, v)| Some((n, v))),
            ]
            .boxed()
        })
        .collect();
    each.prop_map(|v| v.into_iter().flatten().collect()).boxed()
}

/// A point: mostly inside the domain `span`, sometimes hostile.
fn point(span: (f64, f64)) -> BoxedStrategy<String> {
    let lo = Rational::from_f64(span.0).unwrap_or_default();
    let scale = Rational::from_f64(span.1 - span.0).unwrap_or_default();
    prop_oneof![
        12 => (0u32..=1000).prop_map(move |k| (lo.clone() + Rational::from((k, 1000)) * &scale).to_string()),
        2 => proptest::sample::select(vec!["0", "1", "0.5", "1.5707963267948966", "0.0"]).prop_map(String::from),
        3 => hostile_number(),
    ]
    .boxed()
}

/// A count option's values: mostly `usual`, sometimes `odd` (invalid or
/// at a limit), with `heavy` also the `big` ones.
fn amounts(
    usual: std::ops::Range<u64>,
    odd: Vec<&'static str>,
    big: Vec<&'static str>,
    heavy: bool,
) -> BoxedStrategy<String> {
    let mut v: Vec<BoxedStrategy<String>> = vec![
        usual.clone().prop_map(|b| b.to_string()).boxed(),
        usual.prop_map(|b| b.to_string()).boxed(),
        proptest::sample::select(odd).prop_map(String::from).boxed(),
    ];
    if heavy {
        v.push(proptest::sample::select(big).prop_map(String::from).boxed());
    }
    proptest::strategy::Union::new(v).boxed()
}

/// `--prec` values; `heavy` adds the largest precisions.
fn prec(heavy: bool) -> BoxedStrategy<String> {
    let odd = vec![
        "0",
        "1",
        "2",
        "53",
        "256",
        "1024",
        "65537",
        "4294967295",
        "99999999999",
        "-1",
        "x",
    ];
    amounts(2..700, odd, vec!["4096", "16384", "65536"], heavy)
}

/// `--digits` values; `heavy` adds the largest counts.
fn digits(heavy: bool) -> BoxedStrategy<String> {
    let odd = vec![
        "0",
        "17",
        "100",
        "10001",
        "99999999999999999999",
        "-3",
        "1.5",
    ];
    amounts(1..80, odd, vec!["1000", "3000", "10000"], heavy)
}

/// The arithmetic options of `eval` and `table --numeric`.
fn arithmetic(heavy: bool) -> BoxedStrategy<Vec<String>> {
    prop_oneof![
        8 => Just(vec![]),
        6 => prec(heavy).prop_map(|p| vec!["--prec".into(), p]),
        6 => digits(heavy).prop_map(|d| vec!["--digits".into(), d]),
        1 => (prec(false), digits(false)).prop_map(|(p, d)| vec!["--prec".into(), p, "--digits".into(), d]),
    ]
    .boxed()
}

fn flag(name: &'static str, weight: u32) -> BoxedStrategy<Vec<String>> {
    prop_oneof![weight => Just(vec![name.to_string()]), 10 - weight => Just(vec![])].boxed()
}

fn push_params(args: &mut Vec<String>, ps: &[(String, String)]) {
    for (n, v) in ps {
        args.push("--param".into());
        args.push(format!("{n}={v}"));
    }
}

fn eval(bases: &[Basis], heavy: bool) -> BoxedStrategy<Case> {
    proptest::sample::select(bases.to_vec())
        .prop_flat_map(move |b| {
            // knots (and a point among them) for seed 000's non-uniform case only
            let knots: BoxedStrategy<Option<(Vec<String>, Option<String>)>> =
                if b.arg.first().is_some_and(|a| a == "seed000-nonuniform") {
                    prop_oneof![
                        1 => proptest::collection::vec(hostile_number(), 0..20).prop_map(|k| Some((k, None))),
                        4 => (proptest::collection::vec(1u32..20, 5..18), 0u32..=1000).prop_map(|(steps, t)| {
                            let knots: Vec<Rational> = steps
                                .iter()
                                .scan(Rational::new(), |acc, s| {
                                    *acc += Rational::from((*s, 7));
                                    Some(acc.clone())
                                })
                                .collect();
                            let last = knots.last().cloned().unwrap_or_default();
                            let at = last * Rational::from((t, 1000));
                            Some((knots.iter().map(Rational::to_string).collect(), Some(at.to_string())))
                        }),
                    ]
                    .boxed()
                } else {
                    prop_oneof![30 => Just(None), 1 => proptest::collection::vec(hostile_number(), 0..5).prop_map(|k| Some((k, None)))].boxed()
                };
            (
                Just(b.clone()),
                params(&b.params),
                point(b.span),
                arithmetic(heavy),
                flag("--allow-outside-range", 2),
                flag("--piecewise", 1),
                prop_oneof![8 => Just("text"), 6 => Just("json"), 1 => Just("xml")],
                knots,
            )
        })
        .prop_map(|(b, ps, at, arith, outside, piecewise, format, knots)| {
            let mut args = vec!["eval".to_string()];
            args.extend(b.arg.iter().cloned());
            push_params(&mut args, &ps);
            let at = match &knots {
                Some((_, Some(point))) => point.clone(),
                _ => at,
            };
            args.push(format!("--at={at}"));
            args.extend(arith);
            args.extend(outside);
            args.extend(piecewise.clone());
            args.extend(["--format".to_string(), format.to_string()]);
            if let Some((k, _)) = knots {
                args.push(format!("--knots={}", k.join(",")));
            }
            let check = match b.subject {
                Some(basis) => Check::Eval {
                    basis,
                    params: ps,
                    at,
                    piecewise: !piecewise.is_empty(),
                },
                None => Check::Plain,
            };
            Case { args, check }
        })
        .boxed()
}

fn table(bases: &[Basis], heavy: bool) -> BoxedStrategy<Case> {
    let order = prop_oneof![8 => (0usize..=13).prop_map(|o| o.to_string()), 1 => hostile_number()];
    proptest::sample::select(bases.to_vec())
        .prop_flat_map(move |b| {
            (
                Just(b.clone()),
                params(&b.params),
                order.clone(),
                prop_oneof![4 => Just("start"), 4 => Just("end"), 6 => Just("both"), 2 => Just("knots"), 1 => Just("middle")],
                prop_oneof![6 => Just("angle"), 6 => Just("u"), 6 => Just("x"), 1 => Just("y")],
                prop_oneof![6 => Just("md"), 6 => Just("csv"), 1 => Just("tex"), 1 => Just("json")],
                prop_oneof![6 => Just(0u8), 2 => Just(1u8), 1 => Just(2u8)],
                prop_oneof![3 => Just(true), 2 => Just(false)],
                arithmetic(heavy),
                prop_oneof![6 => Just(None), 1 => hostile_number().prop_map(Some), 3 => (1u32..50, 1u32..50).prop_map(|(n, d)| Some(format!("{n}/{d}")))],
                flag("--allow-outside-range", 2),
            )
        })
        .prop_map(|(b, ps, order, at, wrt, format, curve, numeric, arith, h, outside)| {
            let mut args = vec!["table".to_string()];
            args.extend(b.arg.iter().cloned());
            args.extend(["--order".into(), order.clone(), "--at".into(), at.into(), "--wrt".into(), wrt.into()]);
            args.extend(["--format".into(), format.into()]);
            match (curve, numeric) {
                (1, false) => args.push("--curve".into()),
                (2, false) => args.extend(["--curve".into(), "--rational".into()]),
                (_, true) if curve == 2 && order == "3" => args.push("--curve".into()),
                _ => {}
            }
            if numeric {
                args.push("--numeric".into());
                push_params(&mut args, &ps);
                args.extend(arith);
                if let Some(h) = &h {
                    args.push(format!("--h={h}"));
                }
                args.extend(outside);
            }
            let check = match (&b.subject, numeric, order.parse::<usize>(), at) {
                (Some(basis), true, Ok(order), "start" | "end" | "both") => Check::Table {
                    basis: basis.clone(),
                    params: ps,
                    order,
                    wrt: wrt.into(),
                    h,
                },
                _ => Check::Plain,
            };
            Case { args, check }
        })
        .boxed()
}

/// `list`, `join`, `plot basis|curve`, `interp`, `fit`: no value check.
fn others(bases: &[Basis], scratch: PathBuf) -> BoxedStrategy<Case> {
    let ids: Vec<String> = bases
        .iter()
        .filter_map(|b| b.arg.first().cloned())
        .filter(|a| a != "--spec")
        .collect();
    let family = proptest::sample::select(ids);
    let output = prop_oneof![
        4 => Just(scratch.join("plot.svg").display().to_string()),
        1 => proptest::sample::select(vec!["/nonexistent/dir/x.svg", "/dev/full", "/", ""]).prop_map(String::from),
    ];
    let glyph = prop_oneof![
        3 => Just(PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../data/glyphs/epsilon.csv").display().to_string()),
        2 => Just(scratch.join("hostile.csv").display().to_string()),
        1 => Just("/nonexistent.csv".to_string()),
    ];
    let list = prop_oneof![Just("text"), Just("json"), Just("md")]
        .prop_map(|f| vec!["list".to_string(), "--format".into(), f.into()]);
    let join = (
        family.clone(),
        prop_oneof![
            Just("c0"),
            Just("c1"),
            Just("c2"),
            Just("c3"),
            Just("g1"),
            Just("g2"),
            Just("c9"),
            Just("")
        ],
        prop_oneof![Just("same"), Just("different")],
        prop_oneof![Just("angle"), Just("u"), Just("x")],
        prop_oneof![Just("text"), Just("tex"), Just("json")],
    )
        .prop_map(|(f, k, p, w, fmt)| {
            [
                "join", &f, "--kind", k, "--params", p, "--wrt", w, "--format", fmt,
            ]
            .map(String::from)
            .to_vec()
        });
    let plot_basis = (
        family.clone(),
        proptest::collection::vec(hostile_number(), 0..4),
        flag("--allow-outside-range", 3),
        output.clone(),
    )
        .prop_map(|(f, vals, outside, out)| {
            let mut a = vec!["plot".to_string(), "basis".into(), "--family".into(), f];
            if !vals.is_empty() {
                a.push(format!("--values={}", vals.join(",")));
            }
            a.extend(outside);
            a.extend(["--output".to_string(), out]);
            a
        });
    let plot_curve = (
        family.clone(),
        proptest::collection::vec(hostile_number(), 0..3),
        proptest::collection::vec(
            prop_oneof![2 => hostile_number(), 3 => (-100i32..100).prop_map(|x| x.to_string())],
            0..13,
        ),
        flag("--allow-outside-range", 3),
        output,
    )
        .prop_map(|(f, vals, control, outside, out)| {
            let mut a = vec!["plot".to_string(), "curve".into(), "--family".into(), f];
            if !vals.is_empty() {
                a.push(format!("--values={}", vals.join(",")));
            }
            if !control.is_empty() {
                a.push(format!("--control={}", control.join(",")));
            }
            a.extend(outside);
            a.extend(["--output".to_string(), out]);
            a
        });
    let interp = (
        prop_oneof![
            Just("thesis-table-4.1"),
            Just("thesis-table-4.2"),
            Just("thesis-table-4.3"),
            Just("thesis-table-4.4"),
            Just("thesis-table-4.5"),
            Just("thesis-table-4.6"),
            Just("thesis-table-9")
        ],
        prop_oneof![Just("c1"), Just("c2"), Just("g1"), Just("g2"), Just("c3")],
        prop_oneof![Just("printed"), Just("corrected")],
        prop_oneof![Just("text"), Just("json")],
    )
        .prop_map(|(d, s, v, f)| {
            [
                "interp",
                "--data",
                d,
                "--scheme",
                s,
                "--variant",
                v,
                "--format",
                f,
            ]
            .map(String::from)
            .to_vec()
        });
    let fit = (
        glyph,
        prop_oneof![
            Just("thesis-cubic"),
            Just("han"),
            Just("bernstein3"),
            Just("eh"),
            Just("nope")
        ],
        proptest::collection::vec(
            prop_oneof![
                hostile_number().prop_map(|v| format!("--threshold={v}")),
                (0usize..500).prop_map(|m| format!("--max-points={m}")),
                proptest::collection::vec(0usize..400, 0..5).prop_map(|c| format!(
                    "--corners={}",
                    c.iter().map(usize::to_string).collect::<Vec<_>>().join(",")
                )),
                hostile_number().prop_map(|v| format!("--corner-angle={v}")),
                (0usize..20).prop_map(|w| format!("--corner-window={w}")),
                prop_oneof![Just("c1"), Just("c1-arc")].prop_map(|r| format!("--refine={r}")),
                hostile_number().prop_map(|v| format!("--param=m={v}")),
                Just("--optimise".to_string()),
            ],
            0..4,
        ),
    )
        .prop_map(|(g, f, opts)| {
            let mut a = vec![
                "fit".to_string(),
                "--glyph".into(),
                g,
                "--family".into(),
                f.into(),
            ];
            a.extend(opts);
            a
        });
    prop_oneof![
        1 => list,
        2 => join,
        2 => plot_basis,
        2 => plot_curve,
        2 => interp,
        2 => fit,
    ]
    .prop_map(|args| Case {
        args,
        check: Check::Plain,
    })
    .boxed()
}

/// Garbage: random words, some of them options of the real grammar.
fn garbage() -> BoxedStrategy<Case> {
    let word = prop_oneof![
        3 => "\\PC{0,12}",
        2 => proptest::sample::select(vec![
            "eval", "table", "list", "join", "plot", "fit", "interp", "audit", "--at", "--param",
            "--prec", "--digits", "--order", "--numeric", "--curve", "--rational", "--spec",
            "--format", "--help", "-h", "--version", "--", "-", "thesis-cubic", "m=0.5", "basis",
        ])
        .prop_map(String::from),
        1 => hostile_number(),
    ];
    proptest::collection::vec(word, 0..8)
        .prop_map(|args| Case {
            args,
            check: Check::Plain,
        })
        .boxed()
}

/// The whole grammar. `heavy` adds the largest precisions and digit
/// counts (seconds per case: the long run only); `scratch` is a directory
/// for plot output and a hostile outline file.
pub fn case(heavy: bool, scratch: PathBuf) -> BoxedStrategy<Case> {
    let bases = bases(&scratch);
    prop_oneof![
        10 => eval(&bases, heavy),
        6 => table(&bases, heavy),
        3 => round2(&bases, heavy, scratch.clone()),
        4 => others(&bases, scratch),
        1 => garbage(),
    ]
    .boxed()
}

/// Issue 22's classes on the command lines `eval`/`table` do not reach
/// (they draw the new spec files through [`bases`] too): joins of specs
/// whose parameters are named like the tool's symbols (their factors and
/// lengths checked by the oracle), rational curve tables up to the cost
/// model's bound and past it (`heavy`: orders to 5), `--at-file` from devices, with a byte-order
/// mark or an over-long line, and outputs that are devices, `-` or a
/// symbolic link.
fn round2(bases: &[Basis], heavy: bool, scratch: PathBuf) -> BoxedStrategy<Case> {
    let spec = |name: &str| scratch.join(format!("{name}.toml")).display().to_string();
    let clash_names: Vec<String> = ["alpha", "gamma", "γ", "w1", "h1", "l1"]
        .map(String::from)
        .to_vec();
    let quotient_names: Vec<String> = (1..=8).map(|k| format!("a{k}")).collect();
    let specs = vec![
        (spec("clash"), clash_names),
        (spec("quotient"), quotient_names),
        (spec("radical"), Vec::new()),
        (spec("wide"), Vec::new()),
    ];
    let join = (
        proptest::sample::select(specs.clone()),
        proptest::sample::select(vec!["c0", "c1", "c2", "c3", "g1", "g2"]),
        prop_oneof![Just("same"), Just("different")],
        prop_oneof![Just("u"), Just("x"), Just("t")],
    )
        .prop_map(|((path, params), kind, p, wrt)| Case {
            args: [
                "join", "--spec", &path, "--kind", kind, "--params", p, "--wrt", wrt, "--format",
                "json",
            ]
            .map(String::from)
            .to_vec(),
            check: Check::Namespace { params },
        });
    // up to the cost model's bound (seconds per case: the long run only)
    let orders = if heavy { 0usize..=5 } else { 0usize..=2 };
    let curve = (proptest::sample::select(specs), orders, any::<bool>()).prop_map(
        |((path, _), order, rational)| {
            let mut args: Vec<String> = ["table", "--spec", &path, "--curve"]
                .map(String::from)
                .to_vec();
            if rational {
                args.push("--rational".into());
            }
            args.extend(["--order".into(), order.to_string()]);
            Case {
                args,
                check: Check::Plain,
            }
        },
    );
    let files = vec![
        scratch.join("points.txt").display().to_string(),
        scratch.join("long-line.txt").display().to_string(),
        "/dev/zero".into(),
        "/dev/null".into(),
        "/nonexistent/points.txt".into(),
    ];
    let at_file = proptest::sample::select(bases.to_vec())
        .prop_flat_map(move |b| {
            (
                Just(b.clone()),
                params(&b.params),
                proptest::sample::select(files.clone()),
                prop_oneof![2 => Just(None), 1 => (1usize..40).prop_map(Some)],
                prop_oneof![3 => Just("text"), 1 => Just("json")],
            )
        })
        .prop_map(|(b, ps, file, digits, format)| {
            let mut args = vec!["eval".to_string()];
            args.extend(b.arg.iter().cloned());
            push_params(&mut args, &ps);
            args.extend(["--at-file".into(), file]);
            if let Some(d) = digits {
                args.extend(["--digits".into(), d.to_string()]);
            }
            args.extend(["--format".into(), format.into()]);
            Case {
                args,
                check: Check::Plain,
            }
        });
    let outputs = vec![
        "/dev/null".to_string(),
        "-".into(),
        scratch.join("link.svg").display().to_string(),
    ];
    let output = (proptest::sample::select(outputs), any::<bool>()).prop_map(|(out, plot)| Case {
        args: if plot {
            [
                "plot",
                "basis",
                "--family",
                "thesis-cubic",
                "--output",
                &out,
            ]
            .map(String::from)
            .to_vec()
        } else {
            ["audit", "--claim", "T9", "--output", &out]
                .map(String::from)
                .to_vec()
        },
        check: Check::Plain,
    });
    prop_oneof![3 => join, 3 => curve, 3 => at_file, 1 => output].boxed()
}
