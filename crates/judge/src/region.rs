//! Nonnegativity claims of two shape parameters: the box as printed
//! against the region where every function is nonnegative.
//!
//! * **Containment** (`box ⊂ region`): tensor Bernstein subdivision over
//!   the domain × box, quotients and unbounded ranges included.
//! * **Maximality** (`region = box`), decided explicitly:
//!   - when every function depends on one parameter at most, the region is
//!     the product of the two one-parameter maximal intervals, each with
//!     exact ends ([`maximal_against`]): equality is then decided exactly;
//!   - otherwise, a face of the box can be part of the region's edge only
//!     if the face's line divides one of the boundary polynomials (the edge
//!     lies in their zero sets; a line meets the zero set of a polynomial it
//!     does not divide in finitely many points). A face that fails this
//!     has points of the region beyond it: the box is not maximal, shown
//!     by the exact one-parameter section through the middle of the face.
//!   - when every face passes, the window around the box is classified
//!     ([`trig_certify::region`]) and the verdict says what was proved.

use rug::Rational;
use trig_certify::boundary::{candidates, end_conditions};
use trig_certify::range::EndPoint;
use trig_certify::region::{CellKind, Region, region};
use trig_certify::{Bound, ParamBox};
use trig_symbolic::Sym;

use crate::certificate::{MAXIMAL, Published, maximal_against, nonnegative_on_box_named};
use trig_verdict::evidence::{Evidence, EvidenceList, Expr};
use trig_verdict::status::Status;
use trig_verdict::verdict::Verdict;

/// One parameter of the claim: name, printed symbol, printed set, source.
#[derive(Debug, Clone)]
pub struct Axis<'a> {
    pub name: &'a str,
    pub symbol: &'a str,
    pub set: ParamBox,
    pub source: &'a str,
}

/// Quadtree depth for the region picture and the window classification.
pub const REGION_DEPTH: u32 = 5;

/// How the region is decided, as the report states it.
pub const REGION: &str = "certified: containment by exact Bernstein subdivision over (z, λ, μ); the region's edge lies on the zero sets of the boundary polynomials (discriminants and end values in the parameters); separable bases by two exact one-parameter maximal intervals; window cells certified inside (every function ≥ 0 on the cell) or outside (one function < 0 on the whole cell at one exact point of the domain)";

/// `box ⊂ region` (every function ≥ 0 on the domain for every parameter in
/// the box).
pub fn contained(fs: &[Sym], names: &[&str], trig: bool, axes: &[Axis<'_>]) -> Verdict {
    let params: Vec<(&str, ParamBox)> = axes.iter().map(|a| (a.name, a.set.clone())).collect();
    nonnegative_on_box_named(trig, fs, names, &params)
}

/// `region = box` for two parameters.
pub fn maximal(fs: &[Sym], names: &[&str], trig: bool, axes: [Axis<'_>; 2]) -> Verdict {
    let inside = contained(fs, names, trig, &axes);
    let mut evidence = EvidenceList::from(vec![format!(
        "printed box {} ∈ {} × {} ∈ {} ({}; {})",
        axes[0].symbol, axes[0].set, axes[1].symbol, axes[1].set, axes[0].source, axes[1].source
    )]);
    evidence.extend(inside.evidence.iter().map(|e| format!("containment: {e}")));
    if inside.status != Status::Holds {
        if inside.status == Status::Fails {
            evidence.push("the box is not inside the region, so it is not the region");
        }
        return Verdict::new(inside.status, REGION, evidence);
    }
    let depends = |f: &Sym, k: usize| f.variables().contains(axes[k].name);
    if fs.iter().all(|f| !(depends(f, 0) && depends(f, 1))) {
        evidence.push(format!(
            "every function depends on one parameter at most: the region is the product of the maximal interval of {} (functions in {} alone) and that of {}",
            axes[0].symbol, axes[0].symbol, axes[1].symbol
        ));
        let parts = (0..2)
            .map(|k| {
                let chosen: Vec<usize> =
                    (0..fs.len()).filter(|&i| !depends(&fs[i], 1 - k)).collect();
                let group: Vec<Sym> = chosen.iter().map(|&i| fs[i].clone()).collect();
                let group_names: Vec<&str> = chosen.iter().map(|&i| names[i]).collect();
                let published = Published {
                    name: axes[k].name,
                    symbol: axes[k].symbol,
                    range: axes[k].set.to_string(),
                    set: axes[k].set.clone(),
                    source: axes[k].source,
                };
                let v = maximal_against(&group, &group_names, trig, &published).1;
                (axes[k].symbol.to_string(), v)
            })
            .collect();
        let v = Verdict::all(MAXIMAL, parts);
        evidence.extend(v.evidence);
        return Verdict::new(v.status, REGION, evidence);
    }
    coupled(fs, names, trig, &axes, evidence)
}

/// The window around the box that is classified: half the box's width
/// beyond each finite end (a fixed margin beyond an end at infinity).
fn window(set: &ParamBox) -> (Rational, Rational) {
    match (set.lo.value(), set.hi.value()) {
        (Some(a), Some(b)) => {
            let w = (Rational::from(b - a) / 2u32).max(Rational::from(1));
            (Rational::from(a - &w), Rational::from(b + &w))
        }
        (Some(a), None) => (a.clone() - 1u32, a.clone() + 8u32),
        (None, Some(b)) => (b.clone() - 8u32, b.clone() + 1u32),
        (None, None) => (Rational::from(-8), Rational::from(8)),
    }
}

/// The bounds on each parameter implied by the necessary end conditions
/// that are affine in one parameter ([`end_conditions`]): `(axis, lower,
/// value, the condition as text)`.
fn end_bounds(
    fs: &[Sym],
    names: &[&str],
    trig: bool,
    axes: &[Axis<'_>; 2],
) -> Vec<(usize, bool, Rational, String)> {
    let mut out = Vec::new();
    for (f, name) in fs.iter().zip(names) {
        for g in end_conditions(f, trig) {
            let vars = g.variables();
            let Some(k) = (0..2).find(|&k| vars.len() == 1 && vars.contains(axes[k].name)) else {
                continue;
            };
            if g.degree_in(axes[k].name) != 1 {
                continue;
            }
            let a = g.diff(axes[k].name).as_constant().unwrap_or_default();
            let b = g
                .subs(axes[k].name, &trig_symbolic::Poly::zero())
                .as_constant()
                .unwrap_or_default();
            let v = -b / &a;
            out.push((
                k,
                a > 0,
                v,
                format!("{g} ≥ 0 (sign of {name} next to an end of the domain)"),
            ));
        }
    }
    out
}

/// `region ⊂ box` from the end conditions alone, when their half-planes
/// cut out exactly the box: the lines that prove it, or `None`.
fn box_from_end_conditions(
    fs: &[Sym],
    names: &[&str],
    trig: bool,
    axes: &[Axis<'_>; 2],
) -> Option<Vec<String>> {
    let bounds = end_bounds(fs, names, trig, axes);
    let mut lines = Vec::new();
    for (k, axis) in axes.iter().enumerate() {
        for lower in [true, false] {
            let end = if lower { &axis.set.lo } else { &axis.set.hi };
            match end {
                Bound::Infinite => {}
                Bound::Open(_) => return None,
                Bound::Closed(v) => {
                    let (_, _, _, text) = bounds
                        .iter()
                        .find(|(j, l, w, _)| *j == k && *l == lower && w == v)?;
                    lines.push(text.clone());
                }
            }
        }
    }
    Some(lines)
}

/// `region ⊂ box` from the functions of one parameter alone, when the
/// exact ends of their maximal intervals are the box's finite faces (a
/// function of `λ` alone negative just beyond `λ = 1` is negative there for
/// every `μ`): the lines that prove it, or `None`.
fn box_from_one_parameter_functions(
    fs: &[Sym],
    names: &[&str],
    trig: bool,
    axes: &[Axis<'_>; 2],
) -> Option<Vec<String>> {
    let mut lines = Vec::new();
    for k in 0..2 {
        let set = &axes[k].set;
        let faces: Vec<(bool, &Rational)> = [(true, &set.lo), (false, &set.hi)]
            .into_iter()
            .filter_map(|(lower, b)| b.value().map(|v| (lower, v)))
            .collect();
        if faces.is_empty() {
            continue;
        }
        let alone: Vec<usize> = (0..fs.len())
            .filter(|&i| {
                let vars = fs[i].variables();
                vars.contains(axes[k].name) && !vars.contains(axes[1 - k].name)
            })
            .collect();
        if alone.is_empty() {
            return None;
        }
        let group: Vec<Sym> = alone.iter().map(|&i| fs[i].clone()).collect();
        let group_names: Vec<&str> = alone.iter().map(|&i| names[i]).collect();
        let published = Published {
            name: axes[k].name,
            symbol: axes[k].symbol,
            range: set.to_string(),
            set: set.clone(),
            source: axes[k].source,
        };
        let (r, _) = maximal_against(&group, &group_names, trig, &published);
        for (lower, v) in faces {
            let (end, closed) = if lower {
                (&r.lo, matches!(set.lo, Bound::Closed(_)))
            } else {
                (&r.hi, matches!(set.hi, Bound::Closed(_)))
            };
            match end {
                EndPoint::Exact {
                    value, closed: c, ..
                } if value.rational.as_ref() == Some(v) && *c == closed => {
                    lines.push(format!(
                        "the face {} = {v}: the maximal interval of {} on which {} ≥ 0 ends exactly there",
                        axes[k].symbol,
                        axes[k].symbol,
                        group_names.join(", ")
                    ));
                }
                _ => return None,
            }
        }
    }
    Some(lines)
}

/// The coupled case: the end conditions, the face test, then the window.
fn coupled(
    fs: &[Sym],
    names: &[&str],
    trig: bool,
    axes: &[Axis<'_>; 2],
    mut evidence: EvidenceList,
) -> Verdict {
    if let Some(lines) = box_from_end_conditions(fs, names, trig, axes) {
        evidence.push("every parameter where all functions are ≥ 0 satisfies these necessary conditions (the sign of a function next to an end of the domain), whose half-planes cut out exactly the box: so the region is inside the box, and with the containment it is the box");
        evidence.extend(lines.into_iter().map(|l| format!("necessary: {l}")));
        return Verdict::new(Status::Holds, REGION, evidence);
    }
    if let Some(lines) = box_from_one_parameter_functions(fs, names, trig, axes) {
        evidence.push("beyond each finite face of the box a function of that face's parameter alone is negative whatever the other parameter (the exact end of its maximal interval is the face): the part of the region that contains the box lies inside the box, and with the containment it is the box");
        evidence.extend(lines);
        return Verdict::new(Status::Holds, REGION, evidence);
    }
    // the face test needs every boundary polynomial
    let boundary = candidates(fs, names, trig).unwrap_or_default();
    let faces = if boundary.is_empty() {
        vec![]
    } else {
        vec![(0, false), (0, true), (1, false), (1, true)]
    };
    for (k, upper) in faces {
        let set = &axes[k].set;
        let end = if upper { &set.hi } else { &set.lo };
        let Some(v) = end.value() else { continue };
        let line = Sym::var(axes[k].name) - &Sym::rational(v.clone());
        let on_edge = boundary.iter().any(|c| {
            Sym::from_poly(c.poly.clone())
                .subs(axes[k].name, &Sym::rational(v.clone()))
                .is_zero()
        });
        if !on_edge {
            evidence.push(format!(
                "the face {} = {v} is not on the region's edge: {line} divides none of the boundary polynomials, so the region extends beyond the box there",
                axes[k].symbol
            ));
            evidence.extend(face_witness(fs, names, trig, axes, k, v));
            evidence.push(edge_line(&boundary));
            return Verdict::new(Status::Fails, REGION, evidence);
        }
    }
    let reg = classify_window(fs, names, trig, axes);
    evidence.extend(describe_region(&reg, names, axes));
    // a certified-admissible cell outside the box refutes maximality
    let (blo, bhi) = box_corners(axes);
    if let Some(c) = reg
        .cells
        .iter()
        .find(|c| c.kind == CellKind::Inside && c.outside_of(&blo, &bhi))
    {
        evidence.push(format!(
            "the region is larger than the box: every function is certified ≥ 0 for all ({}, {}) in [{}, {}] × [{}, {}], outside the box",
            axes[0].symbol, axes[1].symbol, c.lo[0], c.hi[0], c.lo[1], c.hi[1]
        ));
        return Verdict::new(Status::Fails, REGION, evidence);
    }
    evidence.push("every finite face of the box lies on the zero set of a boundary polynomial, as the edge of the region must; that the region does not extend beyond the faces between the decided cells is not proved: equality is not decided");
    Verdict::new(Status::NotCheckable, REGION, evidence)
}

/// The exact one-parameter section through the middle of face `k`.
fn face_witness(
    fs: &[Sym],
    names: &[&str],
    trig: bool,
    axes: &[Axis<'_>; 2],
    k: usize,
    v: &Rational,
) -> Vec<String> {
    let other = 1 - k;
    let mid = axes[other].set.some_point().unwrap_or_default();
    let section: Vec<Sym> = fs
        .iter()
        .map(|f| f.subs(axes[other].name, &Sym::rational(mid.clone())))
        .collect();
    let published = Published {
        name: axes[k].name,
        symbol: axes[k].symbol,
        range: axes[k].set.to_string(),
        set: axes[k].set.clone(),
        source: "the box's face",
    };
    let (_, verdict) = maximal_against(&section, names, trig, &published);
    let mut out = vec![format!(
        "section {} = {mid} (the face {} = {v} crosses it):",
        axes[other].symbol, axes[k].symbol
    )];
    out.extend(
        verdict
            .evidence
            .into_iter()
            .skip(1)
            .map(|e| format!("  {e}")),
    );
    out
}

fn box_corners(axes: &[Axis<'_>; 2]) -> ([Rational; 2], [Rational; 2]) {
    let (w0, w1) = (window(&axes[0].set), window(&axes[1].set));
    let lo =
        |k: usize, w: &(Rational, Rational)| axes[k].set.lo.value().cloned().unwrap_or(w.0.clone());
    let hi =
        |k: usize, w: &(Rational, Rational)| axes[k].set.hi.value().cloned().unwrap_or(w.1.clone());
    ([lo(0, &w0), lo(1, &w1)], [hi(0, &w0), hi(1, &w1)])
}

/// The window around the printed box, classified, with the box's finite
/// ends as split lines.
pub fn classify_window(fs: &[Sym], names: &[&str], trig: bool, axes: &[Axis<'_>; 2]) -> Region {
    let params = [axes[0].name, axes[1].name];
    classify_window_by(fs, names, trig, axes, |lo, hi| {
        trig_certify::region::classify(fs, trig, params, lo, hi)
    })
}

/// [`classify_window`] with another classification of the cells (the
/// region of a property of which `fs ≥ 0` are necessary conditions; the
/// edge lies on their boundary polynomials).
pub fn classify_window_by(
    fs: &[Sym],
    names: &[&str],
    trig: bool,
    axes: &[Axis<'_>; 2],
    classify: impl Fn(&[Rational; 2], &[Rational; 2]) -> CellKind,
) -> Region {
    let (w0, w1) = (window(&axes[0].set), window(&axes[1].set));
    let ends = |set: &ParamBox| -> Vec<Rational> {
        [&set.lo, &set.hi]
            .into_iter()
            .filter_map(Bound::value)
            .cloned()
            .collect()
    };
    let (s0, s1) = (ends(&axes[0].set), ends(&axes[1].set));
    region(
        fs,
        names,
        trig,
        [axes[0].name, axes[1].name],
        ([w0.0, w1.0], [w0.1, w1.1]),
        [&s0, &s1],
        REGION_DEPTH,
        classify,
    )
}

/// The region in a few lines: cell counts, witnesses, boundary polynomials.
pub fn describe_region(reg: &Region, names: &[&str], axes: &[Axis<'_>; 2]) -> Vec<Evidence> {
    let inside = reg.count(|k| *k == CellKind::Inside);
    let outside = reg.count(|k| matches!(k, CellKind::Outside { .. }));
    let edge = reg.count(|k| *k == CellKind::Boundary);
    let mut out: Vec<Evidence> = vec![Evidence::note(format!(
        "window [{}, {}] × [{}, {}]: {inside} cells certified inside, {outside} certified outside, {edge} undecided along the edge",
        reg.window_lo[0], reg.window_hi[0], reg.window_lo[1], reg.window_hi[1]
    ))];
    if let Some(c) = reg
        .cells
        .iter()
        .find(|c| matches!(c.kind, CellKind::Outside { .. }))
    {
        if let CellKind::Outside {
            function,
            z,
            point,
            value,
        } = &c.kind
        {
            out.push(format!(
                "e.g. outside: {} is < 0 at z = {z} for every ({}, {}) in [{}, {}] × [{}, {}]; at ({}, {}) it is {value} (exact)",
                names.get(*function).copied().unwrap_or("a function"),
                axes[0].symbol,
                axes[1].symbol,
                c.lo[0],
                c.hi[0],
                c.lo[1],
                c.hi[1],
                point[0],
                point[1]
            ).into());
        }
    }
    match &reg.boundary_note {
        Some(why) => out.push(format!("boundary polynomials not computed: {why}").into()),
        None => out.push(edge_line(&reg.boundary)),
    }
    out
}

/// The exact polynomial conditions on whose zero sets the region's edge
/// lies (each boundary polynomial once, up to a constant factor), each as
/// an exact expression labelled by where it comes from (the reports show a
/// long one by its size, the JSON in full).
fn edge_line(boundary: &[trig_certify::boundary::Candidate]) -> Evidence {
    let mut seen: Vec<trig_symbolic::Poly> = Vec::new();
    let mut item =
        Evidence::note("the region's edge lies on the zero sets of these boundary polynomials");
    for c in boundary {
        let (_, p) = c.poly.canonical();
        if seen.contains(&p) {
            continue;
        }
        item = item.with(c.origin.to_string(), Expr::new(&Sym::from_poly(p.clone())));
        seen.push(p);
    }
    item
}
