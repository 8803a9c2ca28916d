//! The integration tests, one binary (issue 20: each test binary links the whole
//! library, so fourteen binaries made most of a fresh `cargo test`'s build time). Each
//! module is one file of this folder; `cargo test --test suite <module>::` runs one of
//! them, e.g. `cargo test --test suite fuzz::`. The exercises (`tests/exercises.rs`) are
//! their own binary so that a student runs `cargo test --test exercises` alone.

mod accuracy_sweep;
mod architecture;
mod asymmetric_shaking;
mod ch8_differential;
mod chapter_completeness;
mod cli;
mod common;
mod effective_mass;
mod every_chapter;
mod falsification;
mod fuzz;
mod horizontal_shaking;
mod lab;
mod lab_attacks;
mod locomotion_definition;
mod notation;
mod speed_vs_accuracy;
mod stability;
mod stick_numerics;
mod stick_state_machine;
mod stick_with_inertia;
mod terminal;
mod vertical_shaking;
