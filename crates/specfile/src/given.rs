//! What a claim fixes of the parameters before it is decided: values
//! (`at = { lambda = "0" }`, or a one-point range `range = "[0, 0]"`),
//! lines (`at = { mu = "lambda" }`), its own ranges of the others
//! (`ranges = { mu = "[0, 1]" }`) and regions bounded by lines
//! (`ranges = { mu = "[0, 4 - lambda]" }`, [`Between`]).
//!
//! A fixed value is substituted into every formula of the basis and of the
//! claim before any judge runs — identities, conics and inequalities alike
//! — so "at λ = 0 the curve is an arc of a circle" is decided at `λ = 0`
//! and never as if `λ` were free. The specialised basis has one parameter
//! fewer: `λ` disappears from the functions, from the parameter atoms
//! (`sin(λ/2)` at `λ = π` is `1`), and from the ends of the domain
//! (`[0, α]` at `α = π/2` is `[0, π/2]`).

use rug::Rational;
use trig_core::{Affine, ParamRange, Ring};
use trig_symbolic::{Poly, Sym};

use crate::check::{Between, Check, Condition, Given, Printed};
use crate::spec::Spec;

/// Why a claim's fixed values cannot be substituted.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum GivenError {
    /// A denominator of a formula vanishes at the value.
    #[error("{what} is undefined at {at}: its denominator {denominator} vanishes there")]
    Undefined {
        what: String,
        at: String,
        denominator: String,
    },
    /// A parameter atom or a domain end that the exact ring cannot hold at
    /// the value.
    #[error("{what} at {at} is not exact in the symbolic ring ({why})")]
    NotExact {
        what: String,
        at: String,
        why: String,
    },
    /// What the claim gives cannot be taken as given (values that refer
    /// to each other, a region whose ends are not ordered).
    #[error("{what}: {why}")]
    Refused { what: String, why: String },
    /// The printed coefficient formulas of a basis on a knot vector are
    /// undefined on the claim's knots ([`crate::knots`]): the basis the
    /// claim is about does not exist there.
    #[error("the printed coefficient formulas are undefined on {knots}: {why}")]
    Coefficients { knots: String, why: String },
}

impl Given {
    /// True when the claim fixes nothing and narrows nothing.
    pub fn is_empty(&self) -> bool {
        self.fixed.is_empty()
            && self.ranges.is_empty()
            && self.between.is_empty()
            && self.exact.is_empty()
            && self.knots.is_none()
    }

    /// `λ = 0, μ ∈ [0, 1]` in the parameters' printed symbols.
    pub fn describe(&self, spec: &Spec) -> String {
        let symbol = |name: &str| {
            spec.params
                .iter()
                .find(|p| p.name == name)
                .map_or(name.to_string(), |p| p.symbol.clone())
        };
        self.fixed
            .iter()
            .map(|f| format!("{} = {}", symbol(&f.name), f.text))
            .chain(
                self.ranges
                    .iter()
                    .map(|(n, r)| format!("{} ∈ {r}", symbol(n))),
            )
            .chain(
                self.exact
                    .iter()
                    .map(|r| format!("{} ∈ {}", symbol(&r.name), r.text)),
            )
            .chain(self.between.iter().map(|b| {
                format!(
                    "{} ∈ {} (written {} = lo + {}·(hi − lo), {} ∈ [0, 1])",
                    symbol(&b.name),
                    b.text,
                    symbol(&b.name),
                    b.fraction(),
                    b.fraction()
                )
            }))
            .chain(self.knots.iter().map(crate::knots::Knots::describe))
            .collect::<Vec<_>>()
            .join(", ")
    }

    /// The spec and the check with the given values substituted and the
    /// given ranges in place of the declared ones.
    pub fn apply(&self, spec: &Spec, check: &Check) -> Result<(Spec, Check), GivenError> {
        let mut spec = match &self.knots {
            Some(knots) => knots.apply(spec)?,
            None => spec.clone(),
        };
        let mut check = check.clone();
        let segments = matches!(
            check,
            Check::Join {
                different: true,
                ..
            }
        );
        for (name, range) in &self.ranges {
            if let Some(p) = spec.params.iter_mut().find(|p| &p.name == name) {
                p.range = range.clone();
            }
        }
        let mut earlier: Vec<(String, Sym)> = Vec::new();
        for f in &self.fixed {
            // a value in other parameters sees the values fixed before it
            let mut value = f.value.clone();
            for (name, v) in &earlier {
                value = value.try_subs(name, v).map_err(|_| GivenError::Undefined {
                    what: format!("the value `{}` of `{}`", f.text, f.name),
                    at: format!("{name} = {v}"),
                    denominator: f.value.denominator_poly().to_string(),
                })?;
            }
            if value.variables().contains(&f.name) {
                return Err(GivenError::Refused {
                    what: format!("{} = {}", f.name, f.text),
                    why: "the values fixed refer to each other in a circle".into(),
                });
            }
            earlier.push((f.name.clone(), value.clone()));
            let at = format!(
                "{} = {}",
                spec.params
                    .iter()
                    .find(|p| p.name == f.name)
                    .map_or(f.name.as_str(), |p| p.symbol.as_str()),
                f.text
            );
            let Some(index) = spec.params.iter().position(|p| p.name == f.name) else {
                continue;
            };
            let subst = Substitution::new(&spec, index, &value, &at, segments)?;
            check = subst.check(&check)?;
            spec = subst.spec(&spec)?;
        }
        for b in &self.between {
            let at = format!("{} ∈ {}", b.name, b.text);
            let (mut lo, mut hi) = (b.lo.clone(), b.hi.clone());
            for (name, v) in &earlier {
                let undefined = |_| GivenError::Undefined {
                    what: format!("the range {at}"),
                    at: format!("{name} = {v}"),
                    denominator: String::new(),
                };
                lo = lo.try_subs(name, v).map_err(undefined)?;
                hi = hi.try_subs(name, v).map_err(undefined)?;
            }
            let Some(index) = spec.params.iter().position(|p| p.name == b.name) else {
                continue;
            };
            b.ordered(&spec, &lo, &hi, &at)?;
            let fraction = b.fraction();
            if spec.params.iter().any(|p| p.name == fraction) {
                return Err(GivenError::Refused {
                    what: format!("the new parameter `{fraction}` for {at}"),
                    why: "a parameter of the basis has that name".into(),
                });
            }
            let value = lo.clone() + &(Sym::var(&fraction) * &(hi - &lo));
            let subst = Substitution::new(&spec, index, &value, &at, segments)?;
            check = subst.check(&check)?;
            if let Check::Symmetry { at, params, .. } = &mut check {
                at.push(Rational::from((1, 2)));
                params.push(Sym::var(&fraction));
            }
            let symbol = spec.params[index].symbol.clone();
            spec = subst.spec(&spec)?;
            spec.params.push(trig_core::Parameter {
                name: fraction.clone(),
                symbol: format!("{symbol}′"),
                range: ParamRange {
                    lo: trig_core::End::Closed(Rational::new()),
                    hi: trig_core::End::Closed(Rational::from(1)),
                    pi: false,
                },
                source: format!(
                    "{symbol} = lo + {symbol}′·(hi − lo) for the claim's range {symbol} ∈ {}",
                    b.text
                ),
            });
            spec.domain.param_names.push(fraction);
        }
        singular_again(&spec, &mut check);
        Ok((spec, check))
    }
}

impl Spec {
    /// The basis with the parameters `values` (name, exact value) fixed,
    /// as a claim's fixed values are ([`Given::apply`]): substituted into
    /// every formula, into the parameters' atoms (`sin(λ/2)` at `λ = π` is
    /// `1`) and into the domain. Names that are not parameters are skipped.
    pub fn at_values(&self, values: &[(String, Sym)]) -> Result<Spec, GivenError> {
        let mut spec = self.clone();
        for (name, value) in values {
            let Some(index) = spec.params.iter().position(|p| &p.name == name) else {
                continue;
            };
            let at = format!("{} = {value}", spec.params[index].symbol);
            spec = Substitution::new(&spec, index, value, &at, false)?.spec(&spec)?;
        }
        Ok(spec)
    }
}

/// The divisions of the printed formulas that may vanish, found again on
/// the specialised basis and the claim's ranges: the notes read with the
/// printed claim spoke of the declared ones (a pole at `λ2 = −2` is gone at
/// `λ = 0`, and outside a claim's box `λ ∈ [0, 1]`).
fn singular_again(spec: &Spec, check: &mut Check) {
    let mut ranges = spec.ranges();
    if let Check::Join {
        different: true,
        segments,
        ..
    } = check
    {
        for copies in segments.param_copies(spec) {
            for (p, copy) in spec.params.iter().zip(copies) {
                ranges.push((copy.to_string(), p.range.clone()));
            }
        }
    }
    let divisions = |v: &Sym| -> Vec<String> {
        v.denominator()
            .keys()
            .filter_map(|f| {
                crate::nonvanishing::check(&Sym::from_poly(f.clone()), &spec.domain, &ranges).err()
            })
            .collect()
    };
    match check {
        Check::Join { conditions, .. } => {
            for c in conditions.iter_mut() {
                c.singular = divisions(&c.value);
            }
        }
        Check::Conic {
            points, singular, ..
        } => {
            *singular = points
                .iter()
                .flat_map(|(x, y)| divisions(x).into_iter().chain(divisions(y)))
                .collect();
        }
        _ => {}
    }
}

impl Between {
    /// The name of the parameter that replaces it: `mu_u`.
    pub fn fraction(&self) -> String {
        format!("{}_u", self.name)
    }

    /// `lo ≤ hi` over the other parameters' ranges: both ends linear, the
    /// difference `≥ 0` at every corner of their box (finite ends).
    fn ordered(&self, spec: &Spec, lo: &Sym, hi: &Sym, at: &str) -> Result<(), GivenError> {
        let names: Vec<String> = spec.params.iter().map(|p| p.name.clone()).collect();
        let refuse = |why: &str| GivenError::Refused {
            what: format!("the range {at}"),
            why: why.to_string(),
        };
        let gap = affine_of(&(hi.clone() - lo), &names)
            .filter(|g| g.pi == 0)
            .ok_or_else(|| refuse("its ends must be linear in the other parameters"))?;
        let mut corners = vec![gap.constant.clone()];
        for (i, q) in &gap.params {
            let r = &spec.params[*i].range;
            let (Some(a), Some(b)) = (r.lo.value(), r.hi.value()) else {
                return Err(refuse(
                    "its ends may use only parameters with finite ranges",
                ));
            };
            // (the ends name only other parameters: read so)
            if r.pi {
                return Err(refuse(
                    "its ends may use only parameters with rational ranges",
                ));
            }
            corners = corners
                .iter()
                .flat_map(|c| {
                    [
                        c.clone() + Rational::from(q * a),
                        c.clone() + Rational::from(q * b),
                    ]
                })
                .collect();
        }
        if corners.iter().any(|c| *c < 0) {
            return Err(refuse(
                "its lower end exceeds its upper end somewhere in the box",
            ));
        }
        Ok(())
    }
}

/// One parameter replaced by a value: in the formulas, in its atoms and
/// in the domain.
struct Substitution<'a> {
    index: usize,
    /// The parameters' names before the substitution, by index.
    names: Vec<String>,
    /// `(name, value)` pairs substituted in order: the parameter, then its
    /// atoms; with `different` joins also `name1`, `name2`.
    pairs: Vec<(String, Sym)>,
    value: &'a Sym,
    at: &'a str,
}

impl<'a> Substitution<'a> {
    /// With `segments` (a join whose segments have their own parameters
    /// `p1`, `p2`) the copies `name1`, `name2` take the value too, each with
    /// the other parameters of its own segment.
    fn new(
        spec: &Spec,
        index: usize,
        value: &'a Sym,
        at: &'a str,
        segments: bool,
    ) -> Result<Self, GivenError> {
        let name = spec.params[index].name.clone();
        let mut pairs = vec![(name.clone(), value.clone())];
        if segments {
            for segment in [1, 2] {
                let own = spec.params.iter().fold(value.clone(), |v, p| {
                    v.subs(&p.name, &Sym::var(&format!("{}{segment}", p.name)))
                });
                pairs.push((format!("{name}{segment}"), own));
            }
        }
        for atom in trig_certify::atoms::param_atoms(&spec.domain) {
            if atom.param != index {
                continue;
            }
            let multiple = Sym::rational(atom.base.clone()) * value;
            let not_exact = |why: &str| GivenError::NotExact {
                what: format!("`{}`", atom.name),
                at: at.to_string(),
                why: why.to_string(),
            };
            let v = match atom.kind {
                trig_certify::atoms::Kind::Exp => multiple
                    .is_zero()
                    .then(Sym::one)
                    .ok_or_else(|| not_exact("exp of a nonzero constant"))?,
                kind => {
                    let (s, c) = multiple
                        .try_sin_cos()
                        .filter(|(s, c)| radicals_only(s) && radicals_only(c))
                        .ok_or_else(|| {
                            not_exact("sine and cosine are exact at multiples of π/12 only")
                        })?;
                    if kind == trig_certify::atoms::Kind::Sin {
                        s
                    } else {
                        c
                    }
                }
            };
            pairs.push((atom.name, v));
        }
        Ok(Substitution {
            index,
            names: spec.params.iter().map(|p| p.name.clone()).collect(),
            pairs,
            value,
            at,
        })
    }

    fn sym(&self, x: &Sym, what: &str) -> Result<Sym, GivenError> {
        let mut y = x.clone();
        for (name, v) in &self.pairs {
            if y.variables().contains(name) {
                y = y.try_subs(name, v).map_err(|_| GivenError::Undefined {
                    what: what.to_string(),
                    at: self.at.to_string(),
                    denominator: y.denominator_poly().to_string(),
                })?;
            }
        }
        Ok(y)
    }

    /// An end of the domain (or its angle rate) with the value put in.
    fn affine(&self, a: &Affine, what: &str) -> Result<Affine, GivenError> {
        let mut out = Affine {
            constant: a.constant.clone(),
            pi: a.pi.clone(),
            params: Vec::new(),
        };
        for (i, q) in &a.params {
            match i.cmp(&self.index) {
                std::cmp::Ordering::Less => out.params.push((*i, q.clone())),
                std::cmp::Ordering::Greater => out.params.push((i - 1, q.clone())),
                std::cmp::Ordering::Equal => {
                    let v =
                        affine_of(self.value, &self.names).ok_or_else(|| GivenError::NotExact {
                            what: what.to_string(),
                            at: self.at.to_string(),
                            why: "a domain end is linear in π and the parameters".into(),
                        })?;
                    let v = v.scale(q);
                    out.constant += v.constant;
                    out.pi += v.pi;
                    for (j, c) in v.params {
                        let j = if j > self.index { j - 1 } else { j };
                        match out.params.iter_mut().find(|(k, _)| *k == j) {
                            Some((_, d)) => *d += c,
                            None => out.params.push((j, c)),
                        }
                    }
                }
            }
        }
        out.params.retain(|(_, c)| *c != 0);
        out.params.sort_by_key(|(k, _)| *k);
        Ok(out)
    }

    fn spec(&self, spec: &Spec) -> Result<Spec, GivenError> {
        let mut s = spec.clone();
        for f in s.functions.iter_mut().chain(s.definitions.iter_mut()) {
            f.value = self.sym(&f.value, &format!("`{}`", f.name))?;
        }
        let d = &mut s.domain;
        d.start = self.affine(&spec.domain.start, "the start of the domain")?;
        d.end = self.affine(&spec.domain.end, "the end of the domain")?;
        if let Some(w) = &spec.domain.angle {
            d.angle = Some(self.affine(w, "the angle rate")?);
        }
        let reindex = |list: &[(usize, Rational)]| -> Vec<(usize, Rational)> {
            list.iter()
                .filter(|(i, _)| *i != self.index)
                .map(|(i, q)| (if *i > self.index { i - 1 } else { *i }, q.clone()))
                .collect()
        };
        d.param_angles = reindex(&spec.domain.param_angles);
        d.param_exps = reindex(&spec.domain.param_exps);
        d.param_names.remove(self.index);
        s.params.remove(self.index);
        let symbols: Vec<Sym> = s.params.iter().map(|p| Sym::var(&p.name)).collect();
        for (end, x) in [("start", &s.domain.start), ("end", &s.domain.end)] {
            if s.domain.atoms_at(x, &Sym::one(), &symbols).is_none() {
                return Err(GivenError::NotExact {
                    what: format!("the atoms at the {end} of the domain"),
                    at: self.at.to_string(),
                    why: "sin/cos of a constant angle are exact at multiples of π/12 only".into(),
                });
            }
        }
        Ok(s)
    }

    fn printed(&self, values: &[Printed]) -> Result<Vec<Printed>, GivenError> {
        values
            .iter()
            .map(|p| {
                Ok(Printed {
                    value: self.sym(&p.value, &format!("the printed `{}`", p.text))?,
                    ..p.clone()
                })
            })
            .collect()
    }

    fn condition(&self, c: &Condition) -> Result<Condition, GivenError> {
        let what = format!("the printed condition `{}`", c.text);
        Ok(Condition {
            value: self.sym(&c.value, &what)?,
            terms: c
                .terms
                .iter()
                .map(|t| self.sym(t, &what))
                .collect::<Result<_, _>>()?,
            denominator: self.sym(&c.denominator, &what)?,
            ..c.clone()
        })
    }

    /// The check with the value put into its printed formulas; a range of
    /// the fixed parameter (the one-point range that fixed it) is gone.
    fn check(&self, check: &Check) -> Result<Check, GivenError> {
        let mut c = check.clone();
        match &mut c {
            Check::Nonnegative { range, .. }
            | Check::ConvexHull { range, .. }
            | Check::Independent { range, .. }
            | Check::TotalPositivity { range, .. }
            | Check::Monotone { range, .. }
            | Check::EndDirection { range, .. } => *range = None,
            Check::EndpointValues { values, .. } => *values = self.printed(values)?,
            Check::EndpointDerivatives { values, .. } => {
                for v in values.iter_mut() {
                    v.value = self.sym(&v.value, &format!("the printed `{}`", v.printed))?;
                }
            }
            Check::CurveDerivative { value, text, .. } => {
                *value = self.sym(value, &format!("the printed `{text}`"))?;
            }
            Check::Join { conditions, .. } => {
                *conditions = conditions
                    .iter()
                    .map(|k| self.condition(k))
                    .collect::<Result<_, _>>()?;
            }
            Check::Conic {
                points, equation, ..
            } => {
                for (x, y) in points.iter_mut() {
                    *x = self.sym(x, "a printed control point")?;
                    *y = self.sym(y, "a printed control point")?;
                }
                *equation = self.sym(equation, "the printed equation")?;
            }
            Check::Symmetry { at, params, .. } => {
                if self.index < at.len() {
                    at.remove(self.index);
                }
                if self.index < params.len() {
                    params.remove(self.index);
                }
                for p in params.iter_mut() {
                    *p = self.sym(p, "the printed exchange of parameters")?;
                }
            }
            Check::Identity {
                identities,
                curves,
                readings,
                change,
                lets,
                correction,
                ..
            } => {
                for l in lets.iter_mut() {
                    l.value = self.sym(&l.value, &format!("the claim's `let` name `{}`", l.name))?;
                }
                for point in curves.iter_mut().flat_map(|k| k.points.iter_mut().flatten()) {
                    *point = self.sym(point, "a printed control point of a curve")?;
                }
                if let Some(change) = change {
                    change.value = self.sym(&change.value, "the printed change of variable")?;
                }
                for own in curves.iter_mut().filter_map(|k| k.change.as_mut()) {
                    *own = self.sym(own, "a curve's own change of variable")?;
                }
                let read = readings.iter_mut().map(|r| &mut r.identity);
                let read = read.chain(correction.iter_mut().flat_map(|c| c.identities.iter_mut()));
                for item in identities.iter_mut().chain(read) {
                    let what = format!("the printed identity `{}`", item.text);
                    for a in &mut item.applications {
                        if let crate::check::Argument::Formula(x) = &mut a.argument {
                            *x = self.sym(x, &what)?;
                        }
                    }
                    if item.applications.iter().any(|a| {
                        matches!(&a.argument, crate::check::Argument::Linear(l) if !l.rest.params.is_empty())
                    }) {
                        return Err(GivenError::Refused {
                            what,
                            why: "an argument in the parameters is not decided at fixed values (state the argument with the value)".into(),
                        });
                    }
                    item.lhs = self.sym(&item.lhs, &what)?;
                    item.rhs = self.sym(&item.rhs, &what)?;
                }
            }
            Check::SameBasis { params, .. } => {
                for (_, f) in params.iter_mut() {
                    *f = self.sym(f, "the printed change of parameter")?;
                }
            }
            Check::SurfaceJoin { nets, .. } => {
                for x in nets.iter_mut().flat_map(|n| n.points.iter_mut().flatten().flatten()) {
                    *x = self.sym(x, "a point of the listing")?;
                }
            }
            Check::Cylinder { net, .. }
            | Check::LeavesHull {
                net: Some(net), ..
            } => {
                for x in net.points.iter_mut().flatten().flatten() {
                    *x = self.sym(x, "a point of the listing")?;
                }
            }
            Check::Unity
            | Check::OneMaximum
            | Check::FourierSpan { .. }
            | Check::KnotCoefficients { .. }
            | Check::ShapeEffect { .. }
            | Check::EndCurvature { .. }
            | Check::LeavesHull { net: None, .. }
            | Check::Continuity { .. }
            | Check::LocalControl { .. }
            | Check::All { .. }
            // read without fixed values or ranges (its values index the parameters)
            | Check::JoinSingular { .. }
            | Check::NotPrinted { .. }
            | Check::InterpolantNonnegative { .. }
            | Check::InterpolantContinuity { .. }
            | Check::TableArithmetic { .. }
            | Check::TableQuotes { .. }
            | Check::TableCompare { .. }
            | Check::TableCount { .. }
            | Check::DataValues { .. }
            | Check::InterpolantMaximum { .. } => {}
        }
        Ok(c)
    }
}

/// True when `x` is a constant of the ring whose only atoms are radicals.
fn radicals_only(x: &Sym) -> bool {
    x.variables().iter().all(|v| v.starts_with("sqrt("))
}

/// `x` as `q₀ + q_π·π + Σ qᵢ·pᵢ` (the parameters `names`, by index) when
/// it is linear in π and the parameters.
fn affine_of(x: &Sym, names: &[String]) -> Option<Affine> {
    if !x.denominator().is_empty() || x.numerator().total_degree() > 1 {
        return None;
    }
    let mut out = Affine::default();
    for v in x.variables() {
        let coefficient = x.numerator().coefficients_in(&v).get(1)?.as_constant()?;
        if v == "pi" {
            out.pi = coefficient;
        } else {
            let i = names.iter().position(|n| *n == v)?;
            out.params.push((i, coefficient));
        }
    }
    let rest = x
        .variables()
        .iter()
        .fold(x.numerator().clone(), |p, v| p.subs(v, &Poly::zero()));
    out.constant = rest.as_constant()?;
    Some(out)
}
