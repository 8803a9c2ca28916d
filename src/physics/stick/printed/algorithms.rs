//! Algorithms 1 to 4 of section 5, line by line. Each printed condition that holds
//! counts under its rule id ([`PrintedStick::fired`]); each line that an [`Erratum`]
//! corrects reads the rule set first.

use super::{AlgResult, Erratum, PrintedStick, Semantics, Target};
use crate::physics::stick::rules::Next;
use crate::physics::stick::{Mode, State, OM, VXC, VZC, ZC};

/// The `Next Phase` variable under the rule set's [`Semantics`].
struct Sel {
    next: Option<Target>,
    first_wins: bool,
}

impl Sel {
    fn new(s: Semantics) -> Self {
        Sel {
            next: None,
            first_wins: s == Semantics::FirstWins,
        }
    }

    /// Whether the algorithm still runs (under FirstWins it ends at the first assert).
    fn open(&self) -> bool {
        !(self.first_wins && self.next.is_some())
    }

    fn go(&mut self, m: Mode) {
        self.next = Some(Target::Phase(m));
    }
}

impl PrintedStick {
    /// Algorithm 1 (HINGE), on a violation of the pivot's inequalities.
    pub(super) fn alg1(&self, t: f64, mut y: State) -> AlgResult {
        let mut sel = Sel::new(self.rules.semantics);
        let f = self.m.pivot_eval(t, &y);
        let mu = self.m.p.mu;
        let zs = self.m.plate(t).0;
        // "if mu F_z + F_x > 0 then" (corrected: < 0)
        // a corrected test counts a reaction on the cone's edge to the event accuracy
        // (tol_f) as outside: Alg. 1 runs because an edge was crossed
        let tol = self.tol_f();
        let right = if self.fix(Erratum::A1SlideRightTest) {
            mu * f.fz + f.fx < tol
        } else {
            mu * f.fz + f.fx > 0.0
        };
        if sel.open() && right {
            self.fire("a1-slide-right-test");
            // "if |theta| = 0 then FLIGHT; z_c <- z_s else SLIDE RIGHT"
            if !self.fix(Erratum::A1VerticalFlight) && y[0].abs() <= 1e-9 {
                self.fire("a1-vertical-flight");
                sel.go(Mode::Flight);
                y[ZC] = zs;
            } else {
                sel.go(Mode::SlideRight);
            }
        }
        // "if mu F_z - F_x > 0 then SLIDE LEFT" (corrected: < 0)
        let left = if self.fix(Erratum::A1SlideLeftTest) {
            mu * f.fz - f.fx < tol
        } else {
            mu * f.fz - f.fx > 0.0
        };
        if sel.open() && left {
            self.fire("a1-slide-left-test");
            sel.go(Mode::SlideLeft);
        }
        // "if F_z > 0 then FLIGHT; z_c <- z_s" (corrected: F_z < 0 and the flight lifts C)
        let flight = if self.fix(Erratum::A1FlightTest) {
            f.fz < tol && matches!(self.m.takeoff(t, &y), Next::To(..))
        } else {
            f.fz > 0.0
        };
        if sel.open() && flight {
            self.fire("a1-flight-test");
            sel.go(Mode::Flight);
            y[ZC] = zs;
        }
        self.finish(
            sel,
            t,
            y,
            "a1-abort-heights",
            "Algorithm 1, ABORT if z_c < 0 or z_p < 0",
        )
    }

    /// The closing ABORT line shared by the four algorithms.
    fn finish(
        &self,
        mut sel: Sel,
        t: f64,
        y: State,
        id: &'static str,
        line: &'static str,
    ) -> AlgResult {
        if sel.open() && self.abort_test(t, &y) {
            self.fire(id);
            sel.next = Some(Target::Abort(line));
        }
        Ok((sel.next, y))
    }

    /// Algorithm 2 (FLIGHT), on a violation of `h_c > 0`.
    pub(super) fn alg2(&self, t: f64, mut y: State) -> AlgResult {
        let mut sel = Sel::new(self.rules.semantics);
        let (zs, vs, _) = self.m.plate(t);
        let (th, _) = self.angle(&y);
        let l = self.m.p.length_m;
        let mu = self.m.p.mu;
        // "if z_c - z_s = 0 then" (to the event tolerance)
        if sel.open() && (y[ZC] - zs).abs() <= self.tol_h() {
            self.fire("a2-landing");
            let tan_ok = if self.fix(Erratum::A2TanTest) {
                th.tan().abs() <= mu
            } else {
                th.tan() <= mu
            };
            if tan_ok {
                self.fire("a2-tan-test");
                let (ux, uz) = self.rel_velocity(t, &y);
                let (s, c) = th.sin_cos();
                let d = l * (s * ux + c * uz); // (xdot_p i + (zdot_p - zdot_s) k) . r_CP, r_CP = L (sin, cos)
                let no_impulse = if self.fix(Erratum::A2ShorteningBranch) {
                    d >= 0.0
                } else {
                    d < 0.0
                };
                if no_impulse {
                    self.alg2_hinge_forces(&mut sel, t, &mut y);
                } else {
                    self.alg2_impulse(&mut sel, t, &mut y, ux, uz)?;
                }
            } else {
                self.alg2_free(&mut sel, t, &mut y)?;
            }
        }
        let _ = vs;
        self.finish(
            sel,
            t,
            y,
            "a2-abort-heights",
            "Algorithm 2, ABORT if z_c < 0 or z_p < 0",
        )
    }

    /// Alg. 2, the branch "Compute F_x and F_z in the HINGE phase" (no velocity change).
    fn alg2_hinge_forces(&self, sel: &mut Sel, t: f64, y: &mut State) {
        self.fire("a2-hinge-forces-branch");
        let f = self.m.pivot_eval(t, y);
        let mu = self.m.p.mu;
        if f.fz > 0.0 {
            let hinge = if self.fix(Erratum::A2HingeTest) {
                mu * f.fz >= f.fx.abs()
            } else {
                mu * f.fz < f.fx.abs()
            };
            if sel.open() && hinge {
                self.fire("a2-hinge-test");
                sel.go(Mode::Pivot);
            }
            // "if F_x > 0 then SLIDE LEFT else SLIDE RIGHT" (corrected: only if not HINGE)
            if sel.open() && (!hinge || !self.fix(Erratum::A2SlideOverridesHinge)) {
                if f.fx > 0.0 {
                    self.fire("a2-slide-left-by-fx");
                    sel.go(Mode::SlideLeft);
                } else {
                    self.fire("a2-slide-right-by-fx");
                    sel.go(Mode::SlideRight);
                }
            }
        } else if sel.open() {
            // "Tensional ground reaction implies flight" (corrected: only if the flight lifts C)
            self.fire("a2-tension-flight");
            let lifts = matches!(self.m.takeoff(t, y), Next::To(..));
            if self.fix(Erratum::A2TensionFlight) && !lifts {
                sel.go(if f.fx > 0.0 {
                    Mode::SlideLeft
                } else {
                    Mode::SlideRight
                });
            } else {
                sel.go(Mode::Flight);
                y[ZC] = self.m.plate(t).0;
            }
        }
    }

    /// Alg. 2, the branch "Rod not shortening": the angular-momentum map.
    fn alg2_impulse(
        &self,
        sel: &mut Sel,
        t: f64,
        y: &mut State,
        ux: f64,
        uz: f64,
    ) -> Result<(), String> {
        self.fire("a2-impulse-branch");
        let (zs, vs, _) = self.m.plate(t);
        let l = self.m.p.length_m;
        let (s, c) = y[0].sin_cos();
        if sel.open() {
            sel.go(Mode::Pivot);
            y[VXC] = 0.0;
            y[ZC] = zs;
            // theta' = (r_CP x (v_p - v_s)) / L^2, the scalar cross product of C.15
            let cross = l * (s * uz - c * ux);
            let sign = if self.fix(Erratum::A2ThetaDotSign) {
                -1.0
            } else {
                1.0
            };
            y[OM] = sign * cross / (l * l);
            // x_p' <- x_c' + L theta' cos, z_p' <- z_s' - L theta' sin: C moves with the plate
            y[VZC] = vs;
            if !self.fix(Erratum::A2DeadBranch) {
                if s.abs() < 1e-12 {
                    return Err("Algorithm 2, theta' <- -(z_p' - z_s')/(L sin(theta)) divides by sin(theta) = 0".into());
                }
                // "if x_c' > 0 then SLIDE RIGHT else SLIDE LEFT", with x_c' = 0 just assigned
                let right = y[VXC] > 0.0;
                self.fire(if right {
                    "a2-dead-branch-right"
                } else {
                    "a2-dead-branch-left"
                });
                sel.go(if right {
                    Mode::SlideRight
                } else {
                    Mode::SlideLeft
                });
                // theta' <- -(z_p' - z_s')/(L sin): z_p' - z_s' = -L theta' sin, unchanged
            }
        }
        Ok(())
    }

    /// Alg. 2, the branch `tan(theta) > mu`: landing without an impulse.
    fn alg2_free(&self, sel: &mut Sel, t: f64, y: &mut State) -> Result<(), String> {
        self.fire("a2-free-landing");
        let (zs, vs, _) = self.m.plate(t);
        let l = self.m.p.length_m;
        let (s, c) = y[0].sin_cos();
        let [_, _, vxp, vzp] = self.m.tip(y);
        if s.abs() < 1e-12 {
            return Err(
                "Algorithm 2, x_c' <- x_p' + (z_p' - z_s') cot(theta) divides by sin(theta) = 0"
                    .into(),
            );
        }
        let xc_new = vxp + (vzp - vs) * c / s;
        let om_new = -(vzp - vs) / (l * s);
        // as printed the test reads x_c' before its assignment (the flight's value)
        let test = if self.fix(Erratum::A2FreeLandingOrder) {
            xc_new
        } else {
            y[VXC]
        };
        if sel.open() {
            let right = test > 0.0;
            self.fire(if right {
                "a2-free-slide-right"
            } else {
                "a2-free-slide-left"
            });
            sel.go(if right {
                Mode::SlideRight
            } else {
                Mode::SlideLeft
            });
            y[VXC] = xc_new;
            y[ZC] = zs;
            y[OM] = om_new;
            y[VZC] = vs;
        }
        Ok(())
    }

    /// Algorithm 3 (SLIDE RIGHT) or 4 (SLIDE LEFT), on a violation of the slide's
    /// inequalities.
    pub(super) fn alg_slide(&self, mode: Mode, t: f64, mut y: State) -> AlgResult {
        let mut sel = Sel::new(self.rules.semantics);
        let key = if mode == Mode::SlideRight { "a3" } else { "a4" };
        let id = |what: &str| -> &'static str {
            match (key, what) {
                ("a3", "hinge") => "a3-hinge-test",
                ("a3", "other") => "a3-other-slide",
                ("a3", "abort-fz") => "a3-abort",
                ("a3", "flight") => "a3-flight-test",
                ("a3", _) => "a3-abort-heights",
                (_, "hinge") => "a4-hinge-test",
                (_, "other") => "a4-other-slide",
                (_, "abort-fz") => "a4-abort",
                (_, "flight") => "a4-flight-test",
                _ => "a4-abort-heights",
            }
        };
        let zs = self.m.plate(t).0;
        let mu = self.m.p.mu;
        let mut flag = false;
        let h = self.m.pivot_eval(t, &y);
        let mut last = h;
        let hinge = mu * h.fz >= h.fx.abs()
            && (self.slip_stopped(&y) || !self.fix(Erratum::SlideHingeWhileSlipping));
        if sel.open() && hinge {
            self.fire(id("hinge"));
            sel.go(Mode::Pivot);
            y[VXC] = 0.0;
            y[ZC] = zs;
            flag = true;
        }
        if sel.open() && !flag {
            let other = if mode == Mode::SlideRight {
                Mode::SlideLeft
            } else {
                Mode::SlideRight
            };
            let target = if self.fix(Erratum::SlideOtherSlide) {
                if h.fx > 0.0 {
                    Mode::SlideLeft
                } else {
                    Mode::SlideRight
                }
            } else {
                other
            };
            let f = self.m.slide_eval(target.sigma(), t, &y);
            last = f;
            if f.fz > 0.0 {
                self.fire(id("other"));
                sel.go(target);
                y[ZC] = zs;
            } else if self.fix(Erratum::SlideAbort) {
                self.fire(id("abort-fz"));
                sel.go(Mode::Flight);
            } else {
                self.fire(id("abort-fz"));
                sel.next = Some(Target::Abort(if key == "a3" {
                    "Algorithm 3, ABORT when the SLIDE LEFT F_z <= 0"
                } else {
                    "Algorithm 4, ABORT when the SLIDE RIGHT F_z <= 0"
                }));
            }
        }
        // "if F_z = 0 or F_x = 0 then FLIGHT" (the forces computed last; corrected: F_z only)
        let tol = self.tol_f();
        let flight =
            last.fz.abs() <= tol || (!self.fix(Erratum::SlideFlightFx) && last.fx.abs() <= tol);
        if sel.open() && flight {
            self.fire(id("flight"));
            sel.go(Mode::Flight);
            y[ZC] = zs;
        }
        let line = if key == "a3" {
            "Algorithm 3, ABORT if z_c < 0 or z_p < 0"
        } else {
            "Algorithm 4, ABORT if z_c < 0 or z_p < 0"
        };
        self.finish(sel, t, y, id("abort"), line)
    }
}
