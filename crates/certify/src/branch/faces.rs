//! Face arguments of the branch and bound: on a box touching a face of
//! the whole region (`τ = 0`, `τ = 1`, a parameter's range end), where
//! basis functions vanish and no enclosure decides the sign.
//!
//! * When the function vanishes identically on the face (decided in the
//!   exact ring), to order `m`: Taylor's theorem with Lagrange's remainder,
//!   `f(face ± h) = (±h)ᵐ/m!·∂ᵐf(ξ)`, so `f` has the sign of `(±1)ᵐ∂ᵐf` on
//!   the box — the removable zero divided out (`(α − sin α)/α³` is
//!   `cos ξ/6` for some `ξ`).
//! * Otherwise, on boxes narrow in every direction: `f ≥ 0` on the face
//!   (proved on the face's lower-dimensional box) and the derivative into
//!   the box `≥ 0`.
//!
//! An attempt is bounded (evaluations and depth below its box) and doomed
//! as soon as the derivative it needs is certified negative at one box.

use std::rc::Rc;

use rug::Rational;

use crate::coordinates::BoxFunction;

use super::{ATTEMPT, ATTEMPT_DEPTH, Engine, Fun, Goal, MAX_ORDER, Outcome, negate};

/// What the face of a face argument must satisfy: strictly positive for a
/// strict goal on a closed face, `≥ 0` otherwise.
fn face_goal(goal: Goal, open: bool) -> Goal {
    if goal == Goal::Positive && !open {
        Goal::Positive
    } else {
        Goal::NonNegative
    }
}

impl Engine<'_> {
    /// The face argument on side `lower` of coordinate `k`, when that side
    /// lies on the region's boundary: `None` when it does not apply or fails.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn face_argument(
        &mut self,
        f: &Rc<Fun>,
        bx: &[(Rational, Rational)],
        goal: Goal,
        order: usize,
        depth: usize,
        k: usize,
        lower: bool,
    ) -> Option<Outcome> {
        let (global, open) = if k == 0 {
            (
                if lower {
                    Rational::new()
                } else {
                    Rational::from(1)
                },
                self.open_variable,
            )
        } else {
            let a = &self.coords.axes[k - 1];
            if lower {
                (a.lo.clone(), a.lo_open)
            } else {
                (a.hi.clone(), a.hi_open)
            }
        };
        let side = if lower { &bx[k].0 } else { &bx[k].1 };
        if *side != global {
            return None;
        }
        // a function not identically zero on the face is positive near it
        // or touches zero at some points of it: the argument is then tried
        // only on boxes narrow in every direction (splitting does the rest)
        let vanishes = self.coords.zero_on_face(&f.e, bx, k, &global);
        if !vanishes && !(0..bx.len()).all(|j| j == k || self.narrow(bx, j)) {
            return None;
        }
        let (outer, outer_floor) = (self.limit, self.floor);
        self.limit = outer.min(self.evaluations + ATTEMPT);
        self.floor = outer_floor.min(depth + ATTEMPT_DEPTH);
        let result = if vanishes {
            self.vanishing_order(f, bx, goal, order, depth, k, lower, &global, open)
        } else {
            self.face_attempt(f, bx, goal, order, depth, k, lower, global, open)
        };
        (self.limit, self.floor) = (outer, outer_floor);
        // a derivative found negative dooms this attempt only
        self.doomed = None;
        result
    }

    /// `f` vanishes identically on the face: with `m` the order of the
    /// first derivative along `k` that does not (decided exactly), Taylor's
    /// theorem with Lagrange's remainder gives `f(face ± h) =
    /// (±h)ᵐ/m!·∂ᵐf(ξ)` with `ξ` between the face and the point, so `f` has
    /// the sign of `(±1)ᵐ∂ᵐf` on the box — a removable zero divided out
    /// (`(α − sin α)/α³ ∈ [cos ξ/6]`), not a chain of `m` arguments.
    #[allow(clippy::too_many_arguments)]
    fn vanishing_order(
        &mut self,
        f: &Rc<Fun>,
        bx: &[(Rational, Rational)],
        goal: Goal,
        order: usize,
        depth: usize,
        k: usize,
        lower: bool,
        global: &Rational,
        open: bool,
    ) -> Option<Outcome> {
        if goal == Goal::Positive && !open {
            // zero on a face that belongs to the region: not positive
            return None;
        }
        let mut g = f.clone();
        let mut m = 0;
        loop {
            g = self.derived(&g, k);
            m += 1;
            if order + m > MAX_ORDER || g.e.is_zero() {
                return None;
            }
            if !self.coords.zero_on_face(&g.e, bx, k, global) {
                break;
            }
        }
        if !lower && m % 2 == 1 {
            g = negate(&g, bx.len());
        }
        if self.negative_inside(&g.e, bx, k, lower, false) {
            return None;
        }
        match self.decide(&g, bx, goal, order + m, depth) {
            out @ Outcome::Proved { .. } => Some(out),
            _ => None,
        }
    }

    /// True when `g` (negated when `flip`) is certified negative at the
    /// box's centre or at the centre of its side opposite the face (`lower`
    /// side of coordinate `k`), where a derivative that is `≥ 0` next to the
    /// face first turns negative: a face argument that needs `g ≥ 0` on
    /// the whole box is doomed, and given up before any search.
    fn negative_inside(
        &mut self,
        g: &BoxFunction,
        bx: &[(Rational, Rational)],
        k: usize,
        lower: bool,
        flip: bool,
    ) -> bool {
        let centre: Vec<(Rational, Rational)> = bx
            .iter()
            .map(|(l, h)| {
                let c = Rational::from(l + h) / 2u32;
                (c.clone(), c)
            })
            .collect();
        let mut far = centre.clone();
        let side = if lower { &bx[k].1 } else { &bx[k].0 };
        far[k] = (side.clone(), side.clone());
        [centre, far].iter().any(|p| {
            self.enclose(g, p)
                .is_some_and(|v| *(if flip { -v } else { v }).hi() < 0)
        })
    }

    /// The two halves of a face argument (see [`Engine::face_argument`]).
    #[allow(clippy::too_many_arguments)]
    fn face_attempt(
        &mut self,
        f: &Rc<Fun>,
        bx: &[(Rational, Rational)],
        goal: Goal,
        order: usize,
        depth: usize,
        k: usize,
        lower: bool,
        global: Rational,
        open: bool,
    ) -> Option<Outcome> {
        // a derivative into the box certified negative at a point dooms the
        // argument: give up before searching the face
        let d = self.derived(f, k);
        if self.negative_inside(&d.e, bx, k, lower, !lower) {
            return None;
        }
        let face_ok = (face_goal(goal, open) == Goal::NonNegative
            && self.coords.zero_on_face(&f.e, bx, k, &global))
            || {
                let mut face = bx.to_vec();
                face[k] = (global.clone(), global.clone());
                matches!(
                    self.decide(f, &face, face_goal(goal, open), order, depth),
                    Outcome::Proved { .. }
                )
            };
        if !face_ok {
            return None;
        }
        // the derivative into the box (negated on an upper side)
        let mut d = self.derived(f, k);
        if !lower {
            d = negate(&d, bx.len());
        }
        let inner_goal = if goal == Goal::Positive && open {
            Goal::Positive
        } else {
            Goal::NonNegative
        };
        match self.decide(&d, bx, inner_goal, order + 1, depth) {
            out @ Outcome::Proved { .. } => Some(out),
            _ => None,
        }
    }
}
