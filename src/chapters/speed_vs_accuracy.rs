//! Chapter `speed-vs-accuracy`: not built yet (see the registry in `chapters/mod.rs`).

use super::Context;
use crate::error::Result;
use crate::report::ChapterReport;

/// Flags of the chapter (none yet).
#[derive(clap::Args, Debug, Clone, Default)]
pub struct Args {}

/// Runs the chapter: not built yet, so it reports no claims.
pub fn run(_args: &Args, _ctx: &Context) -> Result<ChapterReport> {
    Ok(super::not_built("speed-vs-accuracy"))
}
