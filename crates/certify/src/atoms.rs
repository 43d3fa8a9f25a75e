//! The atoms of a basis on its [`Domain`] as names of the exact ring, with
//! their values in any ring and their derivatives: one place that says
//! what `s`, `c`, `t`, `E`, `sin(α/2)`, `exp(β)`, `sqrt(2)` and `pi` are,
//! used by numeric evaluation of spec bases and by the interval engine.

use rug::Rational;
use trig_core::{Atoms, Domain, Ring};
use trig_symbolic::Sym;

/// An atom of a parameter: `sin(b·p)`, `cos(b·p)` or `exp(b·p)` for the
/// parameter with index `param` and base rate `base`.
#[derive(Debug, Clone, PartialEq)]
pub struct ParamAtom {
    pub name: String,
    pub param: usize,
    pub base: Rational,
    pub kind: Kind,
}

/// Which function of the base multiple.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    Sin,
    Cos,
    Exp,
}

/// The parameter atoms of a domain, named as the exact ring names them
/// ([`Ring::try_sin_cos`] of `Sym`).
pub fn param_atoms(domain: &Domain) -> Vec<ParamAtom> {
    let multiple =
        |i: usize, b: &Rational| Sym::var(&domain.param_names[i]) * &Sym::rational(b.clone());
    let mut out = Vec::new();
    for (i, b) in &domain.param_angles {
        if let Some((s, c)) = multiple(*i, b).try_sin_cos() {
            for (name, kind) in [(s, Kind::Sin), (c, Kind::Cos)] {
                out.push(ParamAtom {
                    name: name.to_string(),
                    param: *i,
                    base: b.clone(),
                    kind,
                });
            }
        }
    }
    for (i, b) in &domain.param_exps {
        if let Some(e) = multiple(*i, b).try_exp() {
            out.push(ParamAtom {
                name: e.to_string(),
                param: *i,
                base: b.clone(),
                kind: Kind::Exp,
            });
        }
    }
    out
}

/// The value of the atom or parameter called `name` in the ring of
/// `atoms`: the variable's atoms, `pi`, a parameter (by its name in
/// `domain.param_names`), a parameter atom formed from its value, or a
/// radical `sqrt(p)`.
pub fn value<T: Ring>(
    name: &str,
    domain: &Domain,
    atoms: &Atoms<T>,
    params: &[T],
    param_atoms: &[ParamAtom],
) -> Option<T> {
    match name {
        "s" => return Some(atoms.s.clone()),
        "c" => return Some(atoms.c.clone()),
        "t" => return Some(atoms.t.clone()),
        "E" => return Some(atoms.e.clone()),
        "pi" => return Some(atoms.t.pi()),
        _ => {}
    }
    if let Some(i) = domain.param_names.iter().position(|p| p == name) {
        return params.get(i).cloned();
    }
    if let Some(p) = name.strip_prefix("sqrt(").and_then(|r| r.strip_suffix(')')) {
        return atoms.t.int(p.parse().ok()?).try_sqrt();
    }
    let a = param_atoms.iter().find(|a| a.name == name)?;
    match a.kind {
        Kind::Sin => param_sin_cos(a, atoms, params).map(|(s, _)| s),
        Kind::Cos => param_sin_cos(a, atoms, params).map(|(_, c)| c),
        Kind::Exp => (params[a.param].clone() * &atoms.t.rational(&a.base)).try_exp(),
    }
}

/// `(sin(b·p), cos(b·p))` of a sine or cosine atom `a` of a parameter, both
/// at once (a ring whose sine is costly forms the pair once).
pub fn param_sin_cos<T: Ring>(a: &ParamAtom, atoms: &Atoms<T>, params: &[T]) -> Option<(T, T)> {
    (params[a.param].clone() * &atoms.t.rational(&a.base)).try_sin_cos()
}

/// The names of the sine and the cosine atom of the same multiple as `a`
/// (`None` unless `a` is one of such a pair).
pub fn sin_cos_names<'p>(
    a: &ParamAtom,
    param_atoms: &'p [ParamAtom],
) -> Option<(&'p str, &'p str)> {
    let find = |k: Kind| {
        param_atoms
            .iter()
            .find(|x| x.param == a.param && x.base == a.base && x.kind == k)
            .map(|x| x.name.as_str())
    };
    Some((find(Kind::Sin)?, find(Kind::Cos)?))
}

/// `d/dx` of an exact value: `s ↦ ωc`, `c ↦ −ωs`, `t ↦ 1`, `E ↦ κE`.
pub fn d_variable(f: &Sym, domain: &Domain) -> Sym {
    let omega = domain.angle_rate(&Sym::one());
    let kappa = Sym::rational(domain.exp.clone().unwrap_or_default());
    let (s, c, e) = (Sym::var("s"), Sym::var("c"), Sym::var("E"));
    f.derive(&[
        ("s", omega.clone() * &c),
        ("c", -(omega * &s)),
        ("t", Sym::one()),
        ("E", kappa * &e),
    ])
}

/// `∂/∂pᵢ` of an exact value, the variable held fixed: the parameter and
/// its atoms (`sin(bp) ↦ b·cos(bp)`, `exp(bp) ↦ b·exp(bp)`).
pub fn d_param(f: &Sym, domain: &Domain, i: usize, param_atoms: &[ParamAtom]) -> Sym {
    let mut rules: Vec<(String, Sym)> = vec![(domain.param_names[i].clone(), Sym::one())];
    for a in param_atoms.iter().filter(|a| a.param == i) {
        let b = Sym::rational(a.base.clone());
        let partner = |k: Kind| {
            param_atoms
                .iter()
                .find(|x| x.param == i && x.base == a.base && x.kind == k)
                .map(|x| Sym::var(&x.name))
        };
        let image = match a.kind {
            Kind::Sin => partner(Kind::Cos).map(|c| b * &c),
            Kind::Cos => partner(Kind::Sin).map(|s| -(b * &s)),
            Kind::Exp => Some(b * &Sym::var(&a.name)),
        };
        if let Some(image) = image {
            rules.push((a.name.clone(), image));
        }
    }
    let rules: Vec<(&str, Sym)> = rules.iter().map(|(n, v)| (n.as_str(), v.clone())).collect();
    f.derive(&rules)
}

/// `f(a + b − x)`: `f` on the domain's reflection `x ↦ a + b − x` (which
/// maps the domain onto itself), exactly; `None` when the atoms at
/// `a + b` are not exact (`sin ω(a + b)`, `exp κ(a + b)`).
pub fn reflect(f: &Sym, domain: &Domain) -> Option<Sym> {
    let sum = domain.reflection();
    let p: Vec<Sym> = domain.param_names.iter().map(|n| Sym::var(n)).collect();
    let mut images: Vec<(&str, Sym)> = vec![("t", sum.eval(&Sym::one(), &p) - &Sym::var("t"))];
    if let Some(w) = &domain.angle {
        let (sa, ca) = domain.sin_cos_of(&sum.times(w)?, &Sym::one(), &p)?;
        let (s, c) = (Sym::var("s"), Sym::var("c"));
        images.push(("s", sa.clone() * &c - &(ca.clone() * &s)));
        images.push(("c", ca * &c + &(sa * &s)));
    }
    if let Some(k) = &domain.exp {
        let ea = domain.exp_of(&sum.scale(k), &Sym::one(), &p)?;
        images.push(("E", ea / &Sym::var("E")));
    }
    let mut g = f.clone();
    for (atom, _) in &images {
        g = g.subs(atom, &Sym::var(&format!("__reflect_{atom}")));
    }
    for (atom, image) in &images {
        g = g.try_subs(&format!("__reflect_{atom}"), image).ok()?;
    }
    Some(g)
}

#[cfg(test)]
mod tests {
    use super::*;
    use trig_core::{Affine, Variable};

    fn c_curve() -> Domain {
        Domain {
            name: "t".into(),
            param_names: vec!["alpha".into()],
            start: Affine::default(),
            end: Affine::param(0),
            angle: Some(Affine::rational(Rational::from(1))),
            uses_variable: true,
            exp: None,
            param_angles: vec![(0, Rational::from(1))],
            param_exps: Vec::new(),
        }
    }

    #[test]
    fn atoms_are_named_valued_and_derived() {
        let d = c_curve();
        let pa = param_atoms(&d);
        assert_eq!(pa.len(), 2);
        assert_eq!(pa[0].name, "sin(alpha)");
        let atoms = d.atoms(&0.5_f64);
        let v = |n: &str| value(n, &d, &atoms, &[2.0], &pa).unwrap();
        assert!((v("sin(alpha)") - 2f64.sin()).abs() < 1e-15);
        assert!((v("s") - 0.5f64.sin()).abs() < 1e-15 && v("alpha") == 2.0);
        assert!((v("sqrt(2)") - 2f64.sqrt()).abs() < 1e-15);
        // d/dα (α − sin α) = 1 − cos α; d/dt (t − sin t) = 1 − cos t
        let a = Sym::var("alpha") - &Sym::var("sin(alpha)");
        assert_eq!(
            d_param(&a, &d, 0, &pa),
            Sym::one() - &Sym::var("cos(alpha)")
        );
        let b = Sym::var("t") - &Sym::var("s");
        assert_eq!(d_variable(&b, &d), Sym::one() - &Sym::var("c"));
        let p = Domain::from_variable(Variable::Polynomial, &[]);
        assert_eq!(d_variable(&Sym::var("t"), &p), Sym::one());
        // t − sin t reflected on [0, α]: α − t − sin(α − t)
        let r = reflect(&b, &d).unwrap();
        let expected =
            Sym::var("alpha") - &Sym::var("t") - &(Sym::var("sin(alpha)") * &Sym::var("c"))
                + &(Sym::var("cos(alpha)") * &Sym::var("s"));
        assert_eq!(r, expected);
    }
}
