//! The symmetry judge: `bᵢ(x; p) = b_{k−i}(A − x; σ(p))` for any basis,
//! exactly when the map is the reflection of the domain (the parameters
//! exchanged when printed so), by a 256-bit MPFR counterexample otherwise;
//! and the battery's symmetry, which finds the exchange by itself.

use std::ops::Range;

use rug::Rational;
use trig_core::basis::eval_at;
use trig_core::{Affine, Mpfr, Real, Ring, Variable};
use trig_symbolic::Sym;

use crate::domain::{param_symbols, pretty};
use crate::exact::ExactBasis;
use crate::exact::{IDENTITY, basis_of, identities};
use crate::numeric::{PREC, differ, show};
use trig_verdict::evidence::EvidenceList;
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

/// A printed symmetry `bᵢ(x; p) = b_{offset−i}(A − x; σ(p))`.
#[derive(Debug)]
pub struct PrintedSymmetry<'a> {
    pub map_text: &'a str,
    pub map: &'a Affine,
    pub index_text: &'a str,
    pub offset: i64,
    pub at: &'a [Rational],
    pub params: &'a [Sym],
    pub params_text: &'a str,
}

/// `f(A − x; σ(p))` exactly, or why it cannot be formed (the reflected
/// atoms `sin(ω(A − x))` need `sin ωA` exactly; a parameter inside a sine
/// may only be renamed to a parameter with the same base rate).
pub fn reflect<B: ExactBasis>(
    basis: &B,
    f: &Sym,
    a: &Affine,
    sigma: &[Sym],
) -> Result<Sym, String> {
    let d = &basis.domain();
    let p = param_symbols(basis);
    // parameters first, simultaneously; their transcendental atoms renamed
    let mut g = f.clone();
    for (i, q) in basis.parameters().iter().enumerate() {
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
            let target = basis
                .parameters()
                .iter()
                .position(|q| Sym::var(&q.name) == *image);
            let same = target
                .and_then(|j| bases.iter().find(|(k, _)| *k == j))
                .map(|(_, b)| b);
            let Some(j) = target.filter(|_| same == Some(base)) else {
                return Err(format!(
                    "the parameter {} occurs inside sin/cos/exp and is not renamed to a parameter with the same rate",
                    basis.parameters()[i].name
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

/// `f_i(x) = f_{offset−i}(A − x; σ(p))` exactly for every `i` in
/// `indices` with `offset − i` a function (the offset as printed:
/// `index_text`); an index outside the basis is noted.
fn exact_symmetry<B: ExactBasis>(
    basis: &B,
    a: &Affine,
    (offset, index_text): (i64, &str),
    sigma: &[Sym],
    indices: Range<i64>,
) -> Verdict {
    let b = basis_of(basis);
    let names = basis.function_names();
    let n = b.len() as i64;
    let x = &basis.variable_name();
    let xr = format!("{} − {x}", pretty(a, basis));
    let mut parts = Vec::new();
    for i in indices.filter(|i| (0..n).contains(&(offset - i))) {
        let (i, j) = (i as usize, (offset - i) as usize);
        match reflect(basis, &b[j], a, sigma) {
            Ok(r) => parts.push((
                format!("{}({x}) − {}({xr})", names[i], names[j]),
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
    v.evidence.extend(index_note(basis, offset, index_text));
    v
}

/// `f_i(x) = f_{n−1−i}(A − x)` for the printed `i` (`indices`), exactly:
/// the reflection of the domain with the indices reversed and the
/// parameters kept.
pub fn reflection_symmetry<B: ExactBasis>(basis: &B, indices: Range<i64>) -> Verdict {
    let n = basis.function_names().len() as i64;
    let a = basis.domain().reflection();
    crate::exact::defined_by(
        exact_symmetry(basis, &a, (n - 1, ""), &param_symbols(basis), indices),
        basis,
    )
}

/// The battery's symmetry: the reflection of the domain with the indices
/// reversed; for two parameters, when that fails, the same with the
/// parameters exchanged (the usual symmetry of two-parameter bases).
pub fn battery_symmetry<B: ExactBasis>(basis: &B) -> (String, Verdict) {
    let n = basis.function_names().len() as i64;
    let a = basis.domain().reflection();
    let x = &basis.variable_name();
    let xr = format!("{} − {x}", pretty(&a, basis));
    let plain = reflection_symmetry(basis, 0..n);
    // the functions' own letter (`b_i`), `f_i` when they have none
    let f = crate::unity::indexed_letter(&basis.function_names()).unwrap_or_else(|| "f".into());
    let text = format!("{f}_i({x}) = {f}_{{{}−i}}({xr})", n - 1);
    if plain.status == Status::Holds || basis.parameters().len() != 2 {
        return (text, plain);
    }
    let swapped = [
        param_symbols(basis)[1].clone(),
        param_symbols(basis)[0].clone(),
    ];
    let exchanged = exact_symmetry(basis, &a, (n - 1, ""), &swapped, 0..n);
    if exchanged.status != Status::Holds {
        return (text, plain);
    }
    let (p, q) = (&basis.parameters()[0].symbol, &basis.parameters()[1].symbol);
    let mut v = exchanged;
    v.evidence.insert(
        0,
        format!("with the parameters kept the identity fails; with {p} and {q} exchanged it holds exactly"),
    );
    (
        format!("{f}_i({x}; {p}, {q}) = {f}_{{{}−i}}({xr}; {q}, {p})", n - 1),
        v,
    )
}

/// "as printed the index … is out of range for i = …" when it is.
fn index_note<B: ExactBasis>(basis: &B, offset: i64, index_text: &str) -> Option<String> {
    let n = basis.function_names().len() as i64;
    let i = (0..n).find(|i| !(0..n).contains(&(offset - i)))?;
    let prefix = basis.function_names()[0]
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
pub fn symmetry_claim<B: ExactBasis>(basis: &B, s: &PrintedSymmetry<'_>) -> Verdict {
    let mut v = if *s.map == basis.domain().reflection() {
        let n = basis.function_names().len() as i64;
        exact_symmetry(basis, s.map, (s.offset, s.index_text), s.params, 0..n)
    } else {
        printed_reflection(basis, s)
    };
    if !s.params_text.is_empty() {
        v.evidence
            .insert(0, format!("parameters substituted: {}", s.params_text));
    }
    crate::exact::defined_by(v, basis)
}

fn printed_reflection<B: ExactBasis>(basis: &B, s: &PrintedSymmetry<'_>) -> Verdict {
    let names = basis.function_names();
    let parameters = basis.parameters();
    let n = names.len() as i64;
    let Some(i) = (0..n).find(|i| (0..n).contains(&(s.offset - i))) else {
        return Verdict::new(
            Status::Fails,
            IDENTITY,
            vec![index_note(basis, s.offset, s.index_text).unwrap_or_default()],
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
            for (p, q) in basis.parameters().iter().zip(s.at) {
                v = v.subs(&p.name, &Sym::rational(q.clone()));
            }
            v.as_rational().unwrap_or_default()
        })
        .collect();
    let d = &basis.domain();
    let x = (d.start_value(&like, &at) + &d.end_value(&like, &at)) / &like.int(2);
    let y = s.map.eval(&like, &at) - &x;
    let (a, b) = match (
        eval_at(basis, &x, s.at, true),
        eval_at(basis, &y, &image, true),
    ) {
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
    let v = &basis.variable_name();
    let mid = match (d.start.as_rational(), d.end.as_rational()) {
        (Some(a0), Some(b0)) => Rational::from(a0 + b0) / 2u32,
        _ => Rational::new(),
    };
    let image_text = s
        .map_text
        .replace(&basis.variable_name(), &mid.to_string())
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
    let shown_params = parameters
        .iter()
        .zip(s.at)
        .map(|(p, q)| format!("{} = {q}, ", p.symbol))
        .collect::<String>();
    let mut point: Vec<(String, String, String)> = parameters
        .iter()
        .zip(s.at)
        .map(|(p, q)| {
            (
                p.symbol.clone(),
                Sym::var(&p.name).to_sympy(),
                q.to_string(),
            )
        })
        .collect();
    point.push((v.to_string(), v.to_string(), mid.to_string()));
    // the two values as expressions: each function with its parameters set
    // (the image's for the second), at its point of the variable
    let functions = crate::exact::basis_of(basis);
    let with_params = |f: &Sym, values: &[Rational]| {
        parameters
            .iter()
            .zip(values)
            .fold(f.clone(), |acc, (p, q)| {
                acc.subs(&p.name, &Sym::rational(q.clone()))
            })
    };
    let image_sympy = s.map_text.replace(v.as_str(), &format!("({mid})"));
    let of_a = crate::numeric::at_sympy(
        &with_params(&functions[i], s.at),
        basis.variable(),
        &mid.to_string(),
    );
    let of_b = crate::numeric::at_sympy(
        &with_params(&functions[j], &image),
        basis.variable(),
        &image_sympy,
    );
    let mut evidence = EvidenceList::from(vec![crate::numeric::counterexample_item(
        format!(
            "{shown_params}{v} = {mid}: {}({mid}) = {}, but {}({image_text}) = {}{outside}",
            names[i],
            show(&a),
            names[j],
            show(&b)
        ),
        &point,
        [
            (format!("{}({mid})", names[i]), &a, of_a),
            (format!("{}({image_text})", names[j]), &b, of_b),
        ],
    )]);
    let a_refl = d.reflection();
    let reading = exact_symmetry(basis, &a_refl, (n - 1, ""), &param_symbols(basis), 0..n);
    if status == Status::Fails && reading.status == Status::Holds {
        evidence.push(if basis.variable() == Some(Variable::UnitAngle) {
            "the statement holds in the angle θ = πu/2 (θ ↦ π/2 − θ), i.e. for u ↦ 1 − u; see the reading".to_string()
        } else {
            format!("the statement holds for the reflection {v} ↦ {} − {v}", pretty(&a_refl, basis))
        });
    }
    evidence.extend(index_note(basis, s.offset, s.index_text));
    Verdict::new(
        status,
        "counterexample evaluated in 256-bit MPFR (difference far above rounding)",
        evidence,
    )
}
