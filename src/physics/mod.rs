//! Physical models: no I/O, no integrator choice, no printing.
//!
//! A model that has a phase with a closed form exposes it; a model that needs
//! integration exposes itself as a [`crate::numerics::hybrid::HybridSystem`].

pub mod block;
pub mod domain;
pub mod friction;
pub mod locomotion;
pub mod plate;
pub mod rigid;
pub mod sawtooth;
pub mod stick;
pub mod stick_inertia;
