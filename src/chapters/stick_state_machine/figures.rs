//! The chapter's figures (full mode with figures only).

use super::evidence::Evidence;
use crate::chapters::Context;
use crate::error::Result;
use crate::numerics::hybrid::Options;
use crate::physics::stick::run::RunSummary;
use crate::physics::stick::StickParams;
use std::path::Path;

/// Draws every figure; returns the written paths.
pub fn draw_all(
    _dir: &Path,
    _p: &StickParams,
    _main: &RunSummary,
    _ev: &Evidence,
    _ctx: &Context,
    _opts: &Options,
) -> Result<Vec<String>> {
    Ok(Vec::new())
}
