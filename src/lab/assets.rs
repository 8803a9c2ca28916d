//! The lab's page: one HTML file with its style sheet and script inlined, embedded in
//! the binary (no CDN, no file read at run time: the lab works offline and from any
//! folder). The parts are kept as four files for editing.

use std::sync::LazyLock;

const HTML: &str = include_str!("page.html");
const CSS: &str = include_str!("page.css");
const JS: &str = include_str!("page.js");
const DRAW_JS: &str = include_str!("page-draw.js");

static PAGE: LazyLock<String> = LazyLock::new(|| {
    HTML.replacen("/*LAB-STYLE*/", CSS, 1).replacen(
        "//LAB-SCRIPT",
        &format!("{JS}\n{DRAW_JS}\nstart();\n"),
        1,
    )
});

/// The page, self-contained.
pub fn page() -> &'static str {
    &PAGE
}
