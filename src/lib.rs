//! # locomotion-workbook
//!
//! Runnable, verified course material on the mechanics of vibration-driven locomotion:
//! the supplementary material of a paper on a leaning stick that walks on a vertically
//! vibrating plate (dynamic jamming), turned into seven chapters that each re-derive an
//! analysis, check every claim of the document against an independent computation, and
//! draw their figures.
//!
//! Module boundaries (see `DESIGN.md`):
//! - [`numerics`]: integrators, event location, the hybrid driver. Knows nothing of
//!   sticks or plates.
//! - [`physics`]: models only (plates, friction, blocks, the stick). No I/O.
//! - [`scenes`]: the document's scenes, the default and the authors' ones, and their
//!   standard runs, below the chapters (used by chapters, lab, benchmarks and tests).
//! - [`chapters`]: one folder per chapter; composes scenes, physics and numerics into a report.
//! - [`report`], [`plot`], [`render`], [`cli`]: output.
#![warn(missing_docs)]

pub mod chapters;
pub mod cli;
pub mod error;
pub mod flags;
pub mod grammar;
pub mod lab;
pub mod ladder;
pub mod numerics;
pub mod output;
pub mod physics;
pub mod plot;
pub mod render;
pub mod report;
pub mod scenes;
pub mod sweep;
