//! Writing figures: SVG + PNG of a [`Drawing`], animated GIFs; every file written
//! atomically (a temporary in the same folder, then renamed).

use super::*;

/// Writes `dir/name.svg` and `dir/name.png` of a chart; returns both paths.
pub fn save_chart(c: &Chart, dir: impl AsRef<Path>, name: &str) -> Result<Vec<String>> {
    save_drawing(c, dir, name, CHART_SIZE)
}

/// Several charts in one figure, `cols` per row, row by row.
pub fn save_panels(
    charts: &[Chart],
    cols: usize,
    dir: impl AsRef<Path>,
    name: &str,
) -> Result<Vec<String>> {
    let cols = cols.clamp(1, charts.len().max(1));
    let rows = charts.len().div_ceil(cols).max(1);
    let size = (PANEL_SIZE.0 * cols as u32, PANEL_SIZE.1 * rows as u32);
    save_drawing(&Panels { charts, cols }, dir, name, size)
}

/// Writes a heat map (with its colour bar) as `dir/name.svg` and `dir/name.png`.
pub fn save_heatmap(h: &HeatMap, dir: impl AsRef<Path>, name: &str) -> Result<Vec<String>> {
    save_drawing(h, dir, name, CHART_SIZE)
}

/// Writes any [`Drawing`] as `dir/name.svg` and `dir/name.png` at `size` pixels
/// (each side at least 50); creates `dir`; returns the two paths.
pub fn save_drawing<D: Drawing>(
    d: &D,
    dir: impl AsRef<Path>,
    name: &str,
    size: (u32, u32),
) -> Result<Vec<String>> {
    ensure_font();
    let dir = dir.as_ref();
    check_name(name)?;
    std::fs::create_dir_all(dir)
        .map_err(|e| WorkbookError::Io(format!("cannot create {}: {e}", dir.display())))?;
    let size = (size.0.clamp(50, 20_000), size.1.clamp(50, 20_000));
    let svg = dir.join(format!("{name}.svg"));
    let png = dir.join(format!("{name}.png"));
    let fail = |p: &Path, e: String| {
        WorkbookError::Io(format!("cannot write figure {}: {e}", p.display()))
    };
    // Each file is drawn into a temporary beside it and renamed (crate::output): an
    // interrupted run leaves the old figure, never a truncated one.
    let mut text = String::new();
    render(
        SVGBackend::with_string(&mut text, size).into_drawing_area(),
        d,
    )
    .map_err(|e| fail(&svg, e))?;
    crate::output::write_atomic(&svg, text.as_bytes()).map_err(WorkbookError::Io)?;
    crate::output::with_temp_file(&png, |tmp| {
        render(BitMapBackend::new(tmp, size).into_drawing_area(), d)
    })
    .map_err(WorkbookError::Io)?;
    Ok(vec![svg.display().to_string(), png.display().to_string()])
}

/// Writes an animated GIF `dir/name.gif` of `frames` (one [`Drawing`] per frame, each on
/// a white page of `size` pixels), `delay_ms` milliseconds per frame (rounded to the
/// format's 10 ms), looping forever; returns the path. Colours are quantised per frame
/// by the deterministic NeuQuant of the `gif` crate: the same bytes on every run.
pub fn save_gif<D: Drawing>(
    frames: &[D],
    dir: impl AsRef<Path>,
    name: &str,
    size: (u32, u32),
    delay_ms: u32,
) -> Result<Vec<String>> {
    ensure_font();
    let dir = dir.as_ref();
    check_name(name)?;
    std::fs::create_dir_all(dir)
        .map_err(|e| WorkbookError::Io(format!("cannot create {}: {e}", dir.display())))?;
    let size = (size.0.clamp(50, 4000), size.1.clamp(50, 4000));
    let path = dir.join(format!("{name}.gif"));
    crate::output::with_temp_file(&path, |tmp| {
        let backend = BitMapBackend::gif(tmp, size, delay_ms).map_err(|e| e.to_string())?;
        let root = backend.into_drawing_area();
        for f in frames {
            render_frame(&root, f)?;
        }
        Ok(()) // dropping the backend closes the file before the rename
    })
    .map_err(WorkbookError::Io)?;
    Ok(vec![path.display().to_string()])
}

fn render_frame<DB: DrawingBackend, D: Drawing>(
    root: &DrawingArea<DB, Shift>,
    d: &D,
) -> std::result::Result<(), String> {
    root.fill(&WHITE).map_err(|e| e.to_string())?;
    d.draw(root)?;
    root.present().map_err(|e| e.to_string())
}

/// Whether `name` is a kebab-case file stem (lower-case ASCII letters and digits in
/// words joined by single hyphens, as the chapter ids): the one naming style of figures.
pub fn is_kebab(name: &str) -> bool {
    !name.is_empty()
        && name.split('-').all(|w| {
            !w.is_empty()
                && w.bytes()
                    .all(|b| b.is_ascii_lowercase() || b.is_ascii_digit())
        })
}

/// Refuses a figure name that is not kebab-case (a programming error of a chapter,
/// reported as an output error rather than a silently inconsistent file name).
fn check_name(name: &str) -> Result<()> {
    if is_kebab(name) {
        Ok(())
    } else {
        Err(WorkbookError::Io(format!(
            "figure name {name:?} is not kebab-case (a-z, 0-9, single hyphens)"
        )))
    }
}

fn render<DB: DrawingBackend, D: Drawing>(
    root: DrawingArea<DB, Shift>,
    d: &D,
) -> std::result::Result<(), String> {
    root.fill(&WHITE).map_err(|e| e.to_string())?;
    d.draw(&root)?;
    root.present().map_err(|e| e.to_string())
}
