//! Exact identities of a spec basis on its domain: values at the ends,
//! symmetry under the reflection `x ↦ a + b − x` (with the parameters
//! exchanged when printed so), interpolation, endpoint derivative tables.

use rug::Rational;
use trig_core::{Affine, Mpfr, Real, Ring, Variable};
use trig_deriv::{End, Wrt, endpoint_derivatives};
use trig_specfile::{Printed, Spec};
use trig_symbolic::Sym;

use super::{K, TABLE_ORDERS, params};
use crate::evidence::EvidenceList;
use crate::exact::{IDENTITY, identities};
use crate::numeric::{PREC, differ, show};
use crate::status::Status;
use crate::verdict::Verdict;

/// A printed symmetry `bᵢ(x; p) = b_{offset−i}(A − x; σ(p))`.
pub struct PrintedSymmetry<'a> {
    pub map_text: &'a str,
    pub map: &'a Affine,
    pub index_text: &'a str,
    pub offset: i64,
    pub at: &'a [Rational],
    pub params: &'a [Sym],
    pub params_text: &'a str,
}

/// An exact end or map value as printed in reports (`π/2`, `α`).
fn pretty(a: &Affine, spec: &Spec) -> String {
    let symbols: Vec<String> = spec.params.iter().map(|p| p.symbol.clone()).collect();
    a.text(&symbols)
        .replace("pi", "π")
        .replace(" - ", " − ")
        .replace('-', "−")
}

/// The end of the domain as printed (`0`, `π/2`, `1`, `α`).
pub fn end_text(spec: &Spec, end: End) -> String {
    pretty(end_point(spec, end), spec)
}

fn end_point(spec: &Spec, end: End) -> &Affine {
    match end {
        End::Start => &spec.domain.start,
        End::End => &spec.domain.end,
    }
}

/// `f` at an end of the domain: the atoms there substituted exactly.
pub fn value_at(spec: &Spec, f: &Sym, end: End) -> Sym {
    let atoms = spec
        .domain
        .atoms_at(end_point(spec, end), &Sym::one(), &params(spec))
        .expect("exact atoms at the ends (checked when the spec was read)");
    f.subs("s", &atoms.s)
        .subs("c", &atoms.c)
        .subs("t", &atoms.t)
        .subs("E", &atoms.e)
}

/// `f(A − x; σ(p))` exactly, or why it cannot be formed (the reflected
/// atoms `sin(ω(A − x))` need `sin ωA` exactly; a parameter inside a sine
/// may only be renamed to a parameter with the same base rate).
pub fn reflect(spec: &Spec, f: &Sym, a: &Affine, sigma: &[Sym]) -> Result<Sym, String> {
    let d = &spec.domain;
    let p = params(spec);
    // parameters first, simultaneously; their transcendental atoms renamed
    let mut g = f.clone();
    for (i, q) in spec.params.iter().enumerate() {
        g = g.subs(&q.name, &Sym::var(&format!("__sigma{i}")));
    }
    for (i, image) in sigma.iter().enumerate() {
        g = g.subs(&format!("__sigma{i}"), image);
        if *image == p[i] {
            continue;
        }
        for (bases, sine) in [(&d.param_angles, true), (&d.param_exps, false)] {
            let Some((_, base)) = bases.iter().find(|(j, _)| *j == i) else {
                continue;
            };
            let target = spec.params.iter().position(|q| Sym::var(&q.name) == *image);
            let same = target
                .and_then(|j| bases.iter().find(|(k, _)| *k == j))
                .map(|(_, b)| b);
            let Some(j) = target.filter(|_| same == Some(base)) else {
                return Err(format!(
                    "the parameter {} occurs inside sin/cos/exp and is not renamed to a parameter with the same rate",
                    spec.params[i].name
                ));
            };
            let x = |k: usize| p[k].clone() * &Sym::rational(base.clone());
            let names = |y: Sym| -> Vec<String> {
                if sine {
                    let (s, c) = y.try_sin_cos().expect("a parameter multiple");
                    vec![s.to_string(), c.to_string()]
                } else {
                    vec![y.try_exp().expect("a parameter multiple").to_string()]
                }
            };
            for (from, to) in names(x(i)).into_iter().zip(names(x(j))) {
                g = g.subs(&from, &Sym::var(&format!("__to{to}")));
            }
        }
    }
    for v in g.variables() {
        if let Some(name) = v.strip_prefix("__to") {
            g = g.subs(&v, &Sym::var(name));
        }
    }
    // then x ↦ A − x
    let ps = |x: &Affine| x.eval(&Sym::one(), &p);
    let minus_x = |atom: &str, by: Sym| (atom.to_string(), by);
    let mut images: Vec<(String, Sym)> = vec![minus_x("t", ps(a) - &Sym::var("t"))];
    if let Some(w) = &d.angle {
        let theta = a.times(w).ok_or("the reflected angle is not linear")?;
        let (sa, ca) = d
            .sin_cos_of(&theta, &Sym::one(), &p)
            .ok_or("sin and cos of the reflection's angle are not exact")?;
        let (s, c) = (Sym::var("s"), Sym::var("c"));
        images.push(minus_x("s", sa.clone() * &c - &(ca.clone() * &s)));
        images.push(minus_x("c", ca * &c + &(sa * &s)));
    }
    if let Some(k) = &d.exp {
        let ea = d
            .exp_of(&a.scale(k), &Sym::one(), &p)
            .ok_or("exp of the reflection's end is not exact")?;
        images.push(minus_x("E", ea / &Sym::var("E")));
    }
    for (atom, _) in &images {
        g = g.subs(atom, &Sym::var(&format!("__reflect_{atom}")));
    }
    for (atom, image) in &images {
        g = g.subs(&format!("__reflect_{atom}"), image);
    }
    Ok(g)
}

/// `f_i(x) = f_{offset−i}(A − x; σ(p))` exactly for every `i` with
/// `offset − i` a function; an index outside the basis is noted.
fn exact_symmetry(
    spec: &Spec,
    a: &Affine,
    offset: i64,
    index_text: &str,
    sigma: &[Sym],
) -> Verdict {
    let b = spec.symbolic();
    let n = b.len() as i64;
    let x = &spec.var_name;
    let xr = format!("{} − {x}", pretty(a, spec));
    let mut parts = Vec::new();
    for i in (0..n).filter(|i| (0..n).contains(&(offset - i))) {
        let (i, j) = (i as usize, (offset - i) as usize);
        match reflect(spec, &b[j], a, sigma) {
            Ok(r) => parts.push((
                format!(
                    "{}({x}) − {}({xr})",
                    spec.functions[i].name, spec.functions[j].name
                ),
                b[i].clone(),
                r,
            )),
            Err(why) => {
                return Verdict::not_checkable(format!(
                    "the reflection cannot be formed exactly: {why}"
                ));
            }
        }
    }
    let mut v = identities(parts);
    v.evidence.extend(index_note(spec, offset, index_text));
    v
}

/// The battery's symmetry: the reflection of the domain with the indices
/// reversed; for two parameters, when that fails, the same with the
/// parameters exchanged (the usual symmetry of two-parameter bases).
pub fn battery_symmetry(spec: &Spec) -> (String, Verdict) {
    let n = spec.functions.len() as i64;
    let a = spec.domain.reflection();
    let x = &spec.var_name;
    let xr = format!("{} − {x}", pretty(&a, spec));
    let plain = exact_symmetry(spec, &a, n - 1, "", &params(spec));
    let text = format!("f_i({x}) = f_{{{}−i}}({xr})", n - 1);
    if plain.status == Status::Holds || spec.params.len() != 2 {
        return (text, plain);
    }
    let swapped = [params(spec)[1].clone(), params(spec)[0].clone()];
    let exchanged = exact_symmetry(spec, &a, n - 1, "", &swapped);
    if exchanged.status != Status::Holds {
        return (text, plain);
    }
    let (p, q) = (&spec.params[0].symbol, &spec.params[1].symbol);
    let mut v = exchanged;
    v.evidence.insert(
        0,
        format!("with the parameters kept the identity fails; with {p} and {q} exchanged it holds exactly"),
    );
    (
        format!("f_i({x}; {p}, {q}) = f_{{{}−i}}({xr}; {q}, {p})", n - 1),
        v,
    )
}

/// "as printed the index … is out of range for i = …" when it is.
fn index_note(spec: &Spec, offset: i64, index_text: &str) -> Option<String> {
    let n = spec.functions.len() as i64;
    let i = (0..n).find(|i| !(0..n).contains(&(offset - i)))?;
    let prefix = spec.functions[0]
        .name
        .trim_end_matches(|c: char| c.is_ascii_digit())
        .to_string();
    Some(format!(
        "as printed the index {} is also out of range for i = {i} ({prefix}_{{{}}} does not exist)",
        index_text.replace('-', "−"),
        (offset - i).to_string().replace('-', "−")
    ))
}

/// A printed symmetry claim: exact when the map is the reflection of the
/// domain, otherwise a 256-bit MPFR counterexample at the domain's midpoint.
pub fn symmetry_claim(spec: &Spec, s: &PrintedSymmetry<'_>) -> Verdict {
    let mut v = if *s.map == spec.domain.reflection() {
        exact_symmetry(spec, s.map, s.offset, s.index_text, s.params)
    } else {
        printed_reflection(spec, s)
    };
    if !s.params_text.is_empty() {
        v.evidence
            .insert(0, format!("parameters substituted: {}", s.params_text));
    }
    v
}

fn printed_reflection(spec: &Spec, s: &PrintedSymmetry<'_>) -> Verdict {
    let n = spec.functions.len() as i64;
    let Some(i) = (0..n).find(|i| (0..n).contains(&(s.offset - i))) else {
        return Verdict::new(
            Status::Fails,
            IDENTITY,
            vec![index_note(spec, s.offset, s.index_text).unwrap_or_default()],
        );
    };
    let (i, j) = (i as usize, (s.offset - i) as usize);
    let like = Mpfr::from_rational(PREC, &Rational::new());
    let at: Vec<Mpfr> = s.at.iter().map(|q| like.rational(q)).collect();
    let image: Vec<Rational> = s
        .params
        .iter()
        .map(|e| {
            let mut v = e.clone();
            for (p, q) in spec.params.iter().zip(s.at) {
                v = v.subs(&p.name, &Sym::rational(q.clone()));
            }
            v.as_rational().unwrap_or_default()
        })
        .collect();
    let d = &spec.domain;
    let x = (d.start_value(&like, &at) + &d.end_value(&like, &at)) / &like.int(2);
    let y = s.map.eval(&like, &at) - &x;
    let (a, b) = match (spec.eval_at(&x, s.at, true), spec.eval_at(&y, &image, true)) {
        (Ok(a), Ok(b)) => (a[i].clone(), b[j].clone()),
        (Err(e), _) | (_, Err(e)) => {
            return Verdict::not_checkable(format!("evaluation failed: {e}"));
        }
    };
    let status = if differ(&a, &b) {
        Status::Fails
    } else {
        Status::Holds
    };
    let v = &spec.var_name;
    let mid = match (d.start.as_rational(), d.end.as_rational()) {
        (Some(a0), Some(b0)) => Rational::from(a0 + b0) / 2u32,
        _ => Rational::new(),
    };
    let image_text = s
        .map_text
        .replace(&spec.var_name, &mid.to_string())
        .replace("pi", "π")
        .replace('-', "−");
    let outside = if d.contains(&y, &at) {
        String::new()
    } else {
        format!(
            " ({image_text} ≈ {:.4} lies outside {})",
            y.to_f64(),
            d.to_string().replace(" in ", " ∈ ").replace("pi", "π")
        )
    };
    let shown_params = spec
        .params
        .iter()
        .zip(s.at)
        .map(|(p, q)| format!("{} = {q}, ", p.symbol))
        .collect::<String>();
    let mut point: Vec<(String, String)> = spec
        .params
        .iter()
        .zip(s.at)
        .map(|(p, q)| (p.symbol.clone(), q.to_string()))
        .collect();
    point.push((v.to_string(), mid.to_string()));
    let mut evidence = EvidenceList::from(vec![crate::numeric::counterexample_item(
        format!(
            "{shown_params}{v} = {mid}: {}({mid}) = {}, but {}({image_text}) = {}{outside}",
            spec.functions[i].name,
            show(&a),
            spec.functions[j].name,
            show(&b)
        ),
        &point,
        [
            (format!("{}({mid})", spec.functions[i].name), &a),
            (format!("{}({image_text})", spec.functions[j].name), &b),
        ],
    )]);
    let a_refl = d.reflection();
    let reading = exact_symmetry(spec, &a_refl, n - 1, "", &params(spec));
    if status == Status::Fails && reading.status == Status::Holds {
        evidence.push(if spec.legacy == Some(Variable::UnitAngle) {
            "the statement holds in the angle θ = πu/2 (θ ↦ π/2 − θ), i.e. for u ↦ 1 − u; see the reading".to_string()
        } else {
            format!("the statement holds for the reflection {v} ↦ {} − {v}", pretty(&a_refl, spec))
        });
    }
    evidence.extend(index_note(spec, s.offset, s.index_text));
    Verdict::new(
        status,
        "counterexample evaluated in 256-bit MPFR (difference far above rounding)",
        evidence,
    )
}

pub fn interpolation(spec: &Spec) -> Verdict {
    let b = spec.symbolic();
    let n = b.len();
    let mut parts = Vec::new();
    for (end, one) in [(End::Start, 0), (End::End, n - 1)] {
        for (i, f) in b.iter().enumerate() {
            let expected = if i == one { Sym::one() } else { Sym::zero() };
            parts.push((
                format!(
                    "{}({}) = {expected}",
                    spec.functions[i].name,
                    end_text(spec, end)
                ),
                value_at(spec, f, end),
                expected,
            ));
        }
    }
    identities(parts)
}

/// Printed values at one end; a failure names the computed values as the
/// correction.
pub fn endpoint_values(spec: &Spec, end: End, values: &[Printed]) -> Verdict {
    let b = spec.symbolic();
    let e = end_text(spec, end);
    let computed: Vec<Sym> = values
        .iter()
        .map(|p| value_at(spec, &b[p.function], end))
        .collect();
    let parts = values
        .iter()
        .zip(&computed)
        .map(|(p, c)| {
            let printed = p.text.split_once('=').map_or("", |(_, v)| v.trim());
            (
                format!("{}({e}) = {printed}", spec.functions[p.function].name),
                c.clone(),
                p.value.clone(),
            )
        })
        .collect();
    let v = identities(parts);
    if v.status == Status::Holds {
        return v;
    }
    let mut groups: Vec<(Sym, Vec<String>)> = Vec::new();
    for (p, c) in values.iter().zip(&computed) {
        let name = format!("{}({e})", spec.functions[p.function].name);
        match groups.iter_mut().find(|(g, _)| g == c) {
            Some((_, names)) => names.push(name),
            None => groups.push((c.clone(), vec![name])),
        }
    }
    let text = groups
        .iter()
        .map(|(g, names)| format!("{} = {g}", names.join(" = ")))
        .collect::<Vec<_>>()
        .join(" and ");
    v.with_correction(format!("{text} (the computed values)"))
}

/// How derivatives are described for this spec's `wrt`.
pub fn describe_wrt(spec: &Spec, wrt: Wrt) -> String {
    wrt.describe_on(&spec.domain)
}

/// Exact endpoint derivatives (jets over the symbolic ring) against the
/// printed values.
pub fn endpoint_derivative_values(
    spec: &Spec,
    end: End,
    order: usize,
    wrt: Wrt,
    values: &[Printed],
) -> Verdict {
    let table = endpoint_derivatives::<Sym, K>(spec, &params(spec), end, wrt, &Sym::one());
    let e = end_text(spec, end);
    let parts = values
        .iter()
        .map(|p| {
            let printed = p.text.split_once('=').map_or("", |(_, v)| v.trim());
            (
                format!(
                    "{}^({order})({e}) [{}] = {printed}",
                    spec.functions[p.function].name,
                    describe_wrt(spec, wrt)
                ),
                table[p.function][order].clone(),
                p.value.clone(),
            )
        })
        .collect();
    identities(parts)
}

/// The convention of the standard table: the angle for formulas in
/// `s`, `c` alone, the variable otherwise.
fn table_wrt(spec: &Spec) -> Wrt {
    let declared_angle = spec.shorthand.is_none_or(|k| k == 1);
    if (spec.domain.is_pure_trigonometric() || spec.legacy.is_some()) && declared_angle {
        Wrt::Angle
    } else {
        Wrt::Variable
    }
}

/// The convention of the standard table, as printed.
pub fn table_convention(spec: &Spec) -> String {
    describe_wrt(spec, table_wrt(spec))
}

/// One exact derivative in the table's convention: `d/dθ` (`s ↦ c`,
/// `c ↦ −s`) or `d/dx` (`s ↦ ωc`, `c ↦ −ωs`, `t ↦ 1`, `E ↦ κE`).
fn derive(spec: &Spec, f: &Sym) -> Sym {
    if table_wrt(spec) == Wrt::Angle && spec.domain.is_trigonometric() {
        return f.d_angle();
    }
    trig_certify::atoms::d_variable(f, &spec.domain)
}

/// The standard derivative table, computed twice: by Taylor jets seeded
/// with the exact end atoms, and by repeated exact differentiation
/// evaluated at the end. Holds when they agree.
pub fn derivative_table(spec: &Spec) -> Verdict {
    let wrt = table_wrt(spec);
    let mut parts = Vec::new();
    let mut table = Vec::new();
    for end in [End::Start, End::End] {
        let jets =
            endpoint_derivatives::<Sym, TABLE_ORDERS>(spec, &params(spec), end, wrt, &Sym::one());
        for (i, f) in spec.symbolic().iter().enumerate() {
            let mut d = f.clone();
            for (k, jet) in jets[i].iter().enumerate() {
                let exact = value_at(spec, &d, end);
                if !exact.equals(jet) {
                    parts.push((
                        format!(
                            "{}^({k})({}): jets − symbolic",
                            spec.functions[i].name,
                            end_text(spec, end)
                        ),
                        jet.clone(),
                        exact,
                    ));
                }
                d = derive(spec, &d);
            }
            table.push(format!(
                "{} at {}: {}",
                spec.functions[i].name,
                end_text(spec, end),
                jets[i]
                    .iter()
                    .map(ToString::to_string)
                    .collect::<Vec<_>>()
                    .join(", ")
            ));
        }
    }
    let method =
        "exact: Taylor jets over the symbolic ring, cross-checked by symbolic differentiation";
    if parts.is_empty() {
        let mut evidence = vec![format!(
            "orders 0–{} {}; jets and symbolic differentiation agree exactly",
            TABLE_ORDERS - 1,
            describe_wrt(spec, wrt)
        )];
        evidence.extend(table);
        Verdict::new(Status::Holds, method, evidence)
    } else {
        identities(parts)
    }
}
