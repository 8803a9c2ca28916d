//! Numerical methods. They know nothing of sticks, plates or friction.
//!
//! - [`ode`]: explicit Euler, classical RK4, Dormand-Prince 5(4) and 8(5,3) with
//!   adaptive step control and dense output, behind one [`ode::Integrator`].
//! - [`events`]: crossing directions and a bracketing (Illinois) root finder.
//! - [`fit`]: least-squares slopes (the observed order of a convergence study).
//! - [`hybrid`]: the event-driven hybrid-automaton driver: modes, flows (integrated or
//!   in closed form), guards, resets, scheduled breakpoints and a Zeno guard.
//! - [`rounding`]: the unit roundoff and γ_k of the chapters' rounding bounds.
//! - `double_double` (tests only): about 32 digits, to check those bounds.
//! - [`trig`]: sine and cosine together by a table and angle addition (inner loops).

#[cfg(test)]
pub(crate) mod double_double;
pub mod events;
pub mod fit;
pub mod hybrid;
pub mod ode;
pub mod rounding;
pub mod search;
pub mod timestepping;
pub mod trig;
