//! Reading `check = "surface-join"`: tensor-product patches over control
//! nets that a printed program builds (a **listing file**), joined along
//! seams.
//!
//! ```toml
//! check = "surface-join"
//! data = "appendix-1-cylinder.txt"   # the listing, relative to the claim's file
//! join = "C2"                        # C0…C3
//! wrt = "angle"
//! seams = ["seam P → Q: P | Q", "seam Q → P: Q | P"]
//! at = { m = "1" }
//! ```
//!
//! A listing file holds statements, one a line, evaluated in order (a
//! later one overwrites an earlier one, as the printed program does):
//! `NAME = (x, y, z)` (a point, each coordinate a formula of the basis's
//! language), `NAME = formula` (a combination of points assigned before,
//! `2*P3 - P2`, scalars in the parameters) and `net NAME = A B C D; E F G H`
//! (a net: rows separated by `;`, the points' values when the line is
//! read). `#` starts a comment line. A seam `A | B` joins the last column of
//! net `A` to the first column of net `B` (the second patch beside the
//! first), `A ; B` its last row to `B`'s first row (below).

use trig_deriv::JoinKind;
use trig_symbolic::Sym;

use crate::check::{Across, Check, ListedNet, Seam};
use crate::error::{Result, SpecError};
use crate::fields::{need, wrt_field};
use crate::raw::RawClaim;
use crate::source::Source;
use crate::spec::Spec;

pub(crate) fn surface_join(src: &Source<'_>, spec: &Spec, c: &RawClaim) -> Result<Check> {
    let kind_field = need(src, c, &c.join, "join")?;
    let kind = match kind_field.get_ref().trim().parse::<JoinKind>() {
        Ok(k @ JoinKind::C(_)) => k,
        _ => {
            return src.invalid(
                kind_field.span(),
                "claims.join",
                format!(
                    "`{}`: expected C0, C1, C2 or C3 (continuity across a seam)",
                    kind_field.get_ref().trim()
                ),
            );
        }
    };
    let (path, text) = crate::fields::data_file(src, c)?;
    let data_span = need(src, c, &c.data, "data")?.span();
    let nets =
        listing(spec, &text, fixes_every_parameter(spec, c)).map_err(|(line, message)| {
            SpecError::Invalid {
                at: src.at(data_span.start),
                field: "claims.data".into(),
                message: format!("{path} line {line}: {message}"),
            }
        })?;
    let seams = need(src, c, &c.seams, "seams")?
        .iter()
        .map(|item| {
            let text = item.get_ref();
            let (label, body) = text.split_once(": ").unwrap_or((text.trim(), text));
            let split = body
                .split_once('|')
                .map(|(a, b)| (a, b, Across::Columns))
                .or_else(|| body.split_once(';').map(|(a, b)| (a, b, Across::Rows)));
            let find = |name: &str| nets.iter().position(|n| n.name == name.trim());
            match split {
                Some((a, b, across)) => match (find(a), find(b)) {
                    (Some(first), Some(second)) if first != second => Ok(Seam {
                        label: label.trim().to_string(),
                        first,
                        second,
                        across,
                    }),
                    _ => src.invalid(
                        item.span(),
                        "claims.seams",
                        format!(
                            "`{body}`: expected two different nets of the listing ({})",
                            nets.iter()
                                .map(|n| n.name.as_str())
                                .collect::<Vec<_>>()
                                .join(", ")
                        ),
                    ),
                },
                None => src.invalid(
                    item.span(),
                    "claims.seams",
                    format!("`{text}`: expected `A | B` (B beside A) or `A ; B` (B below A)"),
                ),
            }
        })
        .collect::<Result<Vec<_>>>()?;
    if seams.is_empty() {
        return src.invalid(
            c.check.span(),
            "claims.seams",
            "list at least one seam".into(),
        );
    }
    Ok(Check::SurfaceJoin {
        path,
        kind,
        wrt: wrt_field(src, spec, c.wrt.as_ref())?,
        nets,
        seams,
    })
}

/// `check = "cylinder"`: the one net a listing file builds (the last one
/// it assigns under any name when it builds several: a listing's final
/// net is the one it draws) and the radius `r > 0` of the cylinder
/// `x² + y² = r²`, a number of the formula language.
pub(crate) fn cylinder(src: &Source<'_>, spec: &Spec, c: &RawClaim) -> Result<Check> {
    let (path, net) = last_net(src, spec, c)?;
    let field = need(src, c, &c.radius, "radius")?;
    let radius = spec
        .parse_claim_formula(field.get_ref(), &[], &[])
        .ok()
        .and_then(|(r, _)| r.as_rational())
        .filter(|r| *r > 0);
    let Some(radius) = radius else {
        return src.invalid(
            field.span(),
            "claims.radius",
            format!(
                "`{}`: expected a positive rational number",
                field.get_ref().trim()
            ),
        );
    };
    Ok(Check::Cylinder { path, net, radius })
}

/// `check = "leaves-hull"`: `parameter` with its `values` (each a case),
/// the curves of printed `polygons` and the surface over the last net of
/// a listing (`data`); at least one of the two.
pub(crate) fn leaves_hull(src: &Source<'_>, spec: &Spec, c: &RawClaim) -> Result<Check> {
    let parameter = crate::property_read::parameter_named(src, spec, c)?
        .name
        .clone();
    let values = need(src, c, &c.values, "values")?
        .iter()
        .map(|v| crate::property_read::rational_in(src, spec, v, v.get_ref(), "values"))
        .collect::<Result<Vec<_>>>()?;
    let polygons = match &c.polygons {
        Some(printed) => crate::property_read::printed_polygons(src, spec, c, printed)?,
        None => Vec::new(),
    };
    let net = match &c.data {
        Some(_) => Some(last_net(src, spec, c)?.1),
        None => None,
    };
    if polygons.is_empty() && net.is_none() {
        return src.invalid(
            c.check.span(),
            "claims.polygons",
            "give the curves' `polygons`, a listing's net in `data`, or both".into(),
        );
    }
    Ok(Check::LeavesHull {
        parameter,
        values,
        polygons,
        net,
    })
}

/// The last net a listing file (`data`) builds, with the path as written.
fn last_net(src: &Source<'_>, spec: &Spec, c: &RawClaim) -> Result<(String, ListedNet)> {
    let (path, text) = crate::fields::data_file(src, c)?;
    let data_span = need(src, c, &c.data, "data")?.span();
    let invalid = |message: String| SpecError::Invalid {
        at: src.at(data_span.start),
        field: "claims.data".into(),
        message,
    };
    let nets = listing(spec, &text, fixes_every_parameter(spec, c))
        .map_err(|(line, m)| invalid(format!("{path} line {line}: {m}")))?;
    let Some(net) = nets.into_iter().last() else {
        return Err(invalid(format!(
            "{path}: the listing builds no net (`net NAME = …`)"
        )));
    };
    Ok((path, net))
}

/// Whether the claim fixes every parameter with `at`: a division of the
/// listing is then decided at the values (a denominator vanishing there is
/// refused when they are put in).
fn fixes_every_parameter(spec: &Spec, c: &RawClaim) -> bool {
    c.at.as_ref()
        .is_some_and(|at| spec.params.iter().all(|p| at.contains_key(&p.name)))
}

/// The nets a listing builds; an error is `(line, why)`. A division by a
/// formula of the parameters that vanishes in their declared ranges is
/// refused, unless the claim fixes every parameter (`fixed`): then it is
/// read as printed, the values being put in afterwards.
fn listing(
    spec: &Spec,
    text: &str,
    fixed: bool,
) -> std::result::Result<Vec<ListedNet>, (usize, String)> {
    let n = spec.functions.len();
    let mut points: Vec<(String, [Sym; 3])> = Vec::new();
    let mut nets: Vec<ListedNet> = Vec::new();
    for (k, line) in text.lines().enumerate() {
        let at = k + 1;
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let Some((lhs, rhs)) = line.split_once('=') else {
            return Err((
                at,
                format!("`{line}`: expected `NAME = value` or `net NAME = rows`"),
            ));
        };
        let names: Vec<String> = points.iter().map(|(n, _)| n.clone()).collect();
        if let Some(name) = lhs.trim().strip_prefix("net ") {
            let rows = rhs
                .split(';')
                .map(|row| {
                    row.split_whitespace()
                        .map(|p| {
                            points
                                .iter()
                                .find(|(q, _)| q == p)
                                .map(|(_, v)| v.clone())
                                .ok_or_else(|| {
                                    (at, format!("`{p}`: no point of that name assigned before"))
                                })
                        })
                        .collect::<std::result::Result<Vec<_>, _>>()
                })
                .collect::<std::result::Result<Vec<_>, _>>()?;
            if rows.len() != n || rows.iter().any(|r| r.len() != n) {
                return Err((
                    at,
                    format!(
                        "net `{}`: expected {n} rows of {n} points (the basis has {n} functions in each direction)",
                        name.trim()
                    ),
                ));
            }
            nets.retain(|m| m.name != name.trim());
            nets.push(ListedNet {
                name: name.trim().to_string(),
                points: rows,
            });
            continue;
        }
        let name = lhs.trim();
        if !name.chars().next().is_some_and(|c| c.is_ascii_alphabetic())
            || !name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
        {
            return Err((
                at,
                format!("`{name}`: a point is named by ASCII letters and digits"),
            ));
        }
        let taken = spec
            .param_pairs()
            .iter()
            .any(|(a, b)| a == name || b == name)
            || spec
                .functions
                .iter()
                .chain(&spec.definitions)
                .any(|f| f.name == name);
        if taken {
            return Err((at, format!("`{name}`: a name of the basis, not a point")));
        }
        let formula = |t: &str| {
            let parsed = if fixed {
                spec.parse_claim_formula(t, &names, &[]).map(|(v, _)| v)
            } else {
                spec.parse_formula(t, &names)
            };
            parsed.map_err(|e| (at, format!("`{}`: {e}", t.trim())))
        };
        let rhs = rhs.trim();
        let value: [Sym; 3] = match rhs.strip_prefix('(').and_then(|r| r.strip_suffix(')')) {
            Some(inner) if inner.split(',').count() == 3 => {
                let c: Vec<Sym> = inner
                    .split(',')
                    .map(formula)
                    .collect::<std::result::Result<_, _>>()?;
                if let Some(bad) = c
                    .iter()
                    .find(|x| x.variables().iter().any(|v| names.contains(v)))
                {
                    return Err((
                        at,
                        format!("`{bad}`: a coordinate is a number, not a point"),
                    ));
                }
                [c[0].clone(), c[1].clone(), c[2].clone()]
            }
            _ => {
                let e = formula(rhs)?;
                let Some(terms) = e.linear_in(&names) else {
                    return Err((
                        at,
                        format!(
                            "`{rhs}`: expected a point `(x, y, z)` or a combination of points assigned before"
                        ),
                    ));
                };
                std::array::from_fn(|i| {
                    terms.iter().fold(Sym::zero(), |acc, (p, c)| {
                        let coordinate = &points
                            .iter()
                            .find(|(q, _)| q == p)
                            .expect("an assigned point")
                            .1[i];
                        acc + &(c.clone() * coordinate)
                    })
                })
            }
        };
        points.retain(|(q, _)| q != name);
        points.push((name.to_string(), value));
    }
    if nets.is_empty() {
        return Err((
            text.lines().count(),
            "the listing builds no net (`net NAME = A B C; D E F`)".into(),
        ));
    }
    Ok(nets)
}

#[cfg(test)]
mod tests {
    use crate::check::{Across, Check};
    use crate::spec::Spec;

    fn quadratic_listing(listing: &str, seams: &str) -> crate::error::Result<Spec> {
        quadratic_claim(
            listing,
            &format!(
                "check = \"surface-join\"\ndata = \"nets.txt\"\njoin = \"C1\"\nseams = [{seams}]\n"
            ),
        )
    }

    /// A claim (`fields`, the check and its fields) on the quadratic
    /// Bernstein basis with the listing as `nets.txt` beside it.
    fn quadratic_claim(listing: &str, fields: &str) -> crate::error::Result<Spec> {
        // one folder per listing: the tests run in parallel
        let key = listing
            .bytes()
            .fold(0u64, |h, b| h.wrapping_mul(31).wrapping_add(u64::from(b)));
        let key = fields
            .bytes()
            .fold(key, |h, b| h.wrapping_mul(31).wrapping_add(u64::from(b)));
        let dir = std::env::temp_dir().join(format!("listing-{}-{key}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join("nets.txt"), listing).unwrap();
        let spec = "id = \"b2\"\ncitation = \"c\"\nvariable = \"polynomial\"\n[[functions]]\nname = \"B0\"\nformula = \"(1 - t)^2\"\n[[functions]]\nname = \"B1\"\nformula = \"2*t*(1 - t)\"\n[[functions]]\nname = \"B2\"\nformula = \"t^2\"\n";
        let file = dir.join("b2.toml");
        let text =
            format!("{spec}[[claims]]\nid = \"s\"\nsource = \"s\"\nstatement = \"s\"\n{fields}");
        Spec::from_str_named(&text, file.to_str().unwrap())
    }

    #[test]
    fn statements_are_evaluated_in_order_and_nets_take_the_values_of_their_line() {
        let listing = "# a listing\nA = (0, 0, 0)\nB = (1, 0, 0)\nC = (2, 1/2, 0)\nD = 2*C - B\nnet P = A B C; A B C; A B C\nB = (5, 5, 5)\nnet Q = C D B; C D B; C D B\n";
        let spec = quadratic_listing(listing, "\"P | Q\", \"below: P ; Q\"").unwrap();
        let Check::SurfaceJoin { nets, seams, .. } = &spec.claims[0].check else {
            panic!("a surface join");
        };
        let q = |x: i64| trig_symbolic::Sym::int(x);
        // D = 2C − B with the B of its line; P keeps the first B, Q the overwritten one
        assert_eq!(nets[1].points[0][1], [q(3), q(1), q(0)]);
        assert_eq!(nets[0].points[0][1][0], q(1));
        assert_eq!(nets[1].points[0][2][0], q(5));
        assert_eq!(
            (seams[0].first, seams[0].second, seams[0].across),
            (0, 1, Across::Columns)
        );
        assert_eq!(
            (seams[1].label.as_str(), seams[1].across),
            ("below", Across::Rows)
        );
    }

    #[test]
    fn malformed_listings_are_refused_with_the_line() {
        let e = quadratic_listing(
            "A = (0, 0, 0)\nB = A*A\nnet P = A A A; A A A; A A A\n",
            "\"P | P\"",
        )
        .unwrap_err();
        assert!(e.to_string().contains("line 2"), "{e}");
        let e = quadratic_listing("A = (0, 0, 0)\nnet P = A A; A A\n", "\"P | P\"").unwrap_err();
        assert!(e.to_string().contains("3 rows of 3 points"), "{e}");
        let e = quadratic_listing("A = (0, 0, 0)\nnet P = A A A; A A A; A A A\n", "\"P | P\"")
            .unwrap_err();
        assert!(e.to_string().contains("two different nets"), "{e}");
    }

    #[test]
    fn a_cylinder_claim_takes_the_last_net_and_a_positive_radius() {
        let listing = "A = (1, 0, 0)\nB = (1, 0, 1)\nnet P = A A A; A A A; A A A\nnet Q = A B A; A B A; A B A\n";
        let spec = quadratic_claim(
            listing,
            "check = \"cylinder\"\ndata = \"nets.txt\"\nradius = \"3/2\"\n",
        )
        .unwrap();
        let Check::Cylinder { net, radius, .. } = &spec.claims[0].check else {
            panic!("a cylinder claim");
        };
        assert_eq!(net.name, "Q");
        assert_eq!(net.points[0][1][2], trig_symbolic::Sym::int(1));
        assert_eq!(*radius, rug::Rational::from((3, 2)));
        for (radius, why) in [("0", "positive rational"), ("pi", "positive rational")] {
            let fields =
                format!("check = \"cylinder\"\ndata = \"nets.txt\"\nradius = \"{radius}\"\n");
            let e = quadratic_claim(listing, &fields).unwrap_err();
            assert!(e.to_string().contains(why), "{e}");
        }
        let e = quadratic_claim(
            "A = (1, 0, 0)\n",
            "check = \"cylinder\"\ndata = \"nets.txt\"\nradius = \"1\"\n",
        )
        .unwrap_err();
        assert!(e.to_string().contains("builds no net"), "{e}");
    }

    /// A leaves-hull claim on a basis with the parameter `a`, its listing
    /// `nets.txt` holding one net.
    fn leaves_hull_claim(fields: &str) -> crate::error::Result<Spec> {
        let dir = std::env::temp_dir().join(format!(
            "leaves-hull-{}-{}",
            std::process::id(),
            fields.len()
        ));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(
            dir.join("nets.txt"),
            "A = (0, 0, 0)\nB = (1, 0, 2)\nnet P = A B A; A B A; A B A\n",
        )
        .unwrap();
        let spec = "id = \"b2a\"\ncitation = \"c\"\nvariable = \"polynomial\"\n[[parameters]]\nname = \"a\"\nrange = \"[-2, 1]\"\n[[functions]]\nname = \"B0\"\nformula = \"(1 - t)^2\"\n[[functions]]\nname = \"B1\"\nformula = \"a*t*(1 - t)\"\n[[functions]]\nname = \"B2\"\nformula = \"t^2\"\n";
        let text = format!(
            "{spec}[[claims]]\nid = \"s\"\nsource = \"s\"\nstatement = \"s\"\ncheck = \"leaves-hull\"\nparameter = \"a\"\n{fields}"
        );
        Spec::from_str_named(&text, dir.join("b2a.toml").to_str().unwrap())
    }

    #[test]
    fn a_leaves_hull_claim_takes_values_polygons_and_a_net() {
        let spec = leaves_hull_claim(
            "values = [\"-2\", \"3/2\"]\npolygons = [[\"(0, 0)\", \"(1, 2)\", \"(2, 0)\"]]\ndata = \"nets.txt\"\n",
        )
        .unwrap();
        let Check::LeavesHull {
            parameter,
            values,
            polygons,
            net,
        } = &spec.claims[0].check
        else {
            panic!("a leaves-hull claim");
        };
        assert_eq!(parameter, "a");
        assert_eq!(values[1], rug::Rational::from((3, 2)));
        assert_eq!(polygons[0][1], (1.into(), 2.into()));
        assert_eq!(net.as_ref().map(|n| n.name.as_str()), Some("P"));
        let e = leaves_hull_claim("values = [\"1\"]\n").unwrap_err();
        assert!(e.to_string().contains("`polygons`"), "{e}");
        let e = leaves_hull_claim("values = [\"x\"]\ndata = \"nets.txt\"\n").unwrap_err();
        assert!(e.to_string().contains("x"), "{e}");
    }

    /// A listing dividing by `a + 2`, which vanishes at `a = −2` of the
    /// declared `[−2, 1]`: refused unless the claim fixes `a` with `at`,
    /// then decided at the value (and refused at `a = −2`).
    fn listing_with_division(at: &str) -> crate::error::Result<Spec> {
        let dir = std::env::temp_dir().join(format!(
            "listing-division-{}-{}",
            std::process::id(),
            at.len()
        ));
        std::fs::create_dir_all(&dir).unwrap();
        let listing = "A = (0, 0, 0)\nB = (1, 0, 0)\nC = A + (1/(a + 2))*B\nnet P = A B C; A B C; A B C\nnet Q = C B A; C B A; C B A\n";
        std::fs::write(dir.join("nets.txt"), listing).unwrap();
        let spec = "id = \"b2a\"\ncitation = \"c\"\nvariable = \"polynomial\"\n[[parameters]]\nname = \"a\"\nrange = \"[-2, 1]\"\n[[functions]]\nname = \"B0\"\nformula = \"(1 - t)^2*(1 - a*t)\"\n[[functions]]\nname = \"B1\"\nformula = \"t*(1 - t)*(2 + a)\"\n[[functions]]\nname = \"B2\"\nformula = \"t^2*(1 - a + a*t)\"\n";
        let file = dir.join("b2a.toml");
        let text = format!(
            "{spec}[[claims]]\nid = \"s\"\nsource = \"s\"\nstatement = \"s\"\ncheck = \"surface-join\"\ndata = \"nets.txt\"\njoin = \"C1\"\nseams = [\"P | Q\"]\n{at}"
        );
        Spec::from_str_named(&text, file.to_str().unwrap())
    }

    #[test]
    fn a_division_by_a_parameter_is_read_at_the_fixed_values() {
        let e = listing_with_division("").unwrap_err();
        assert!(e.to_string().contains("vanishes"), "{e}");
        let spec = listing_with_division("at = { a = \"1\" }\n").unwrap();
        let claim = &spec.claims[0];
        // C = A + B/(a + 2), read as printed, then at a = 1
        let (_, fixed) = claim.given.apply(&spec, &claim.check).unwrap();
        let Check::SurfaceJoin { nets, .. } = &fixed else {
            panic!("a surface join");
        };
        let third = trig_symbolic::Sym::int(1) / trig_symbolic::Sym::int(3);
        assert_eq!(nets[0].points[0][2][0], third);
        // at a = −2 the values are refused (the denominator vanishes there)
        let spec = listing_with_division("at = { a = \"-2\" }\n").unwrap();
        let claim = &spec.claims[0];
        let e = claim.given.apply(&spec, &claim.check).unwrap_err();
        assert!(e.to_string().contains("a + 2"), "{e}");
    }
}
