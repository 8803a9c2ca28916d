//! The crate's module-level import graph, read from the source text: every module
//! (`src/numerics/ode/step.rs` is `numerics::ode::step`), the paths it names (`use`
//! trees expanded, and `crate::`/`super::`/`self::` paths in the code), each resolved to
//! the module that defines the item, following the `use` declarations of the modules on
//! the way (a re-export `pub use step::Step` in `ode/mod.rs` makes `super::Step` an
//! import of `step`). An import from module `a::b::c` of an item of `a::d::e` is an edge
//! `b -> d` of folder `a`; a folder's `mod.rs` (which declares and orchestrates its
//! children) and imports of an ancestor's own items are not edges. Glob imports
//! (`use super::*`) are not followed, and `#[cfg(test)]` code is left out.

use super::{code, cycles, rust_files, src};
use std::collections::{BTreeMap, BTreeSet};

/// A module: its path below the crate root (`[]` for `lib.rs`) and its code.
pub struct Module {
    pub path: Vec<String>,
    pub code: String,
}

/// Every module of the library (`main.rs`, the binary, and test-only files excluded).
pub fn crate_modules() -> Vec<Module> {
    let root = src();
    rust_files(&root)
        .into_iter()
        .filter_map(|f| {
            let rel = f.strip_prefix(&root).ok()?.with_extension("");
            let mut path: Vec<String> = rel
                .components()
                .map(|c| c.as_os_str().to_string_lossy().to_string())
                .collect();
            if path.iter().any(|p| p == "tests") || path == ["main"] {
                return None;
            }
            if path.last().is_some_and(|l| l == "mod" || l == "lib") {
                path.pop();
            }
            Some(Module {
                path,
                code: code(&f),
            })
        })
        .collect()
}

/// The cycles of every folder, one line each: `src/folder: a <-> b <-> c`.
pub fn crate_cycles(modules: &[Module]) -> Vec<String> {
    let mut out = Vec::new();
    for (folder, g) in folder_graphs(modules) {
        for c in cycles(&g) {
            out.push(format!("{folder}: {}", c.join(" <-> ")));
        }
    }
    out
}

/// The import graph among the children of each folder (key: the folder, `src/a/b`).
fn folder_graphs(modules: &[Module]) -> BTreeMap<String, BTreeMap<String, BTreeSet<String>>> {
    let names = Names::new(modules);
    let mut out: BTreeMap<String, BTreeMap<String, BTreeSet<String>>> = BTreeMap::new();
    for m in modules {
        if let Some((own, folder)) = m.path.split_last() {
            let g = out.entry(own_folder(folder)).or_default();
            g.entry(own.clone()).or_default();
        }
        for target in referenced_paths(m).iter().map(|p| names.resolve(p, 0)) {
            let i = common_prefix(&m.path, &target);
            if i < m.path.len() && i < target.len() {
                out.entry(own_folder(&m.path[..i]))
                    .or_default()
                    .entry(m.path[i].clone())
                    .or_default()
                    .insert(target[i].clone());
            }
        }
    }
    out
}

/// The folder of the modules below `path`, as written from the project root (`src/cli`).
fn own_folder(path: &[String]) -> String {
    std::iter::once("src")
        .chain(path.iter().map(String::as_str))
        .collect::<Vec<_>>()
        .join("/")
}

fn common_prefix(a: &[String], b: &[String]) -> usize {
    a.iter().zip(b).take_while(|(x, y)| x == y).count()
}

/// The modules and what each module's `use` declarations bring into scope.
struct Names {
    modules: BTreeSet<Vec<String>>,
    uses: BTreeMap<Vec<String>, BTreeMap<String, Vec<String>>>,
}

impl Names {
    fn new(modules: &[Module]) -> Self {
        let all: BTreeSet<Vec<String>> = modules.iter().map(|m| m.path.clone()).collect();
        let uses = modules
            .iter()
            .map(|m| {
                let scope = use_decls(&m.code)
                    .iter()
                    .flat_map(|d| expand_use(d))
                    .filter_map(|(name, p)| Some((name, absolute(&m.path, &p, &all)?)))
                    .collect();
                (m.path.clone(), scope)
            })
            .collect();
        Names { modules: all, uses }
    }

    /// The module that defines the item at absolute path `p` (a module itself when
    /// `p` names one).
    fn resolve(&self, p: &[String], depth: usize) -> Vec<String> {
        let mut cur: Vec<String> = Vec::new();
        for (i, seg) in p.iter().enumerate() {
            let mut child = cur.clone();
            child.push(seg.clone());
            if self.modules.contains(&child) {
                cur = child;
                continue;
            }
            let via = self.uses.get(&cur).and_then(|u| u.get(seg));
            return match via {
                Some(target) if depth < 16 && target.as_slice() != p => {
                    let mut q = target.clone();
                    q.extend_from_slice(&p[i + 1..]);
                    self.resolve(&q, depth + 1)
                }
                _ => cur,
            };
        }
        cur
    }
}

/// The absolute path (below the crate root) of path `p` written in module `at`, or
/// `None` for a path into another crate.
fn absolute(at: &[String], p: &[String], modules: &BTreeSet<Vec<String>>) -> Option<Vec<String>> {
    let mut base: Vec<String> = at.to_vec();
    let mut rest = p;
    match rest.first().map(String::as_str) {
        Some("crate") => {
            base.clear();
            rest = &rest[1..];
        }
        Some("self") => rest = &rest[1..],
        Some("super") => {
            while rest.first().is_some_and(|s| s == "super") {
                base.pop();
                rest = &rest[1..];
            }
        }
        Some(first) => {
            // a child module (`use stepper::At;` in `ode/mod.rs`), else another crate
            let mut child = base.clone();
            child.push(first.to_string());
            if !modules.contains(&child) {
                return None;
            }
        }
        None => return None,
    }
    base.extend(rest.iter().cloned());
    Some(base)
}

/// The `use` declarations of `code` (lines starting with `use` or `pub... use`), each
/// as the text between `use` and `;`.
fn use_decls(code: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut offset = 0;
    for line in code.split_inclusive('\n') {
        let t = line.trim_start();
        let t = match t.strip_prefix("pub") {
            Some(rest) if rest.starts_with('(') => rest.split_once(')').map_or(t, |(_, r)| r),
            Some(rest) => rest,
            None => t,
        };
        if let Some(decl) = t.trim_start().strip_prefix("use ") {
            let start = offset + (line.len() - decl.len());
            let rest = &code[start..];
            let end = rest.find(';').unwrap_or(rest.len());
            out.push(rest[..end].split_whitespace().collect::<Vec<_>>().join(" "));
        }
        offset += line.len();
    }
    out
}

/// The first occurrence of `word` in `s` not preceded by an identifier character.
fn find_word(s: &str, word: &str) -> Option<usize> {
    s.match_indices(word)
        .find(|(i, _)| {
            s[..*i]
                .chars()
                .next_back()
                .is_none_or(|c| !(c.is_ascii_alphanumeric() || c == '_'))
        })
        .map(|(i, _)| i)
}

/// A `use` tree expanded into (name brought into scope, path) pairs: `super::axis::{self,
/// Pt as P}` gives `("axis", super::axis)` and `("P", super::axis::Pt)`. Globs give none.
pub fn expand_use(tree: &str) -> Vec<(String, Vec<String>)> {
    let mut out = Vec::new();
    expand_into(&[], tree, &mut out);
    out
}

fn expand_into(prefix: &[String], tree: &str, out: &mut Vec<(String, Vec<String>)>) {
    for item in split_top(tree) {
        let item = item.trim();
        if let Some(open) = item.find('{').filter(|&o| item.rfind('}') > Some(o)) {
            let head = item[..open].trim_end_matches("::").trim();
            let body = &item[open + 1..item.rfind('}').unwrap_or(item.len())];
            let mut p = prefix.to_vec();
            p.extend(segments(head));
            expand_into(&p, body, out);
            continue;
        }
        let (path, alias) = match item.split_once(" as ") {
            Some((p, a)) => (p.trim(), Some(a.trim().to_string())),
            None => (item, None),
        };
        let mut p = prefix.to_vec();
        let segs = segments(path);
        if segs.last().is_some_and(|s| s == "*") || segs.is_empty() {
            continue;
        }
        if segs != ["self"] {
            p.extend(segs);
        }
        if let Some(name) = alias.or_else(|| p.last().cloned()) {
            out.push((name, p));
        }
    }
}

/// `a::b::c` as segments (leading `::` and `$` of `$crate` dropped).
fn segments(path: &str) -> Vec<String> {
    path.split("::")
        .map(|s| s.trim().trim_start_matches('$').to_string())
        .filter(|s| !s.is_empty())
        .collect()
}

/// The items of a `use` tree list, split at the commas outside braces.
fn split_top(tree: &str) -> Vec<&str> {
    let (mut out, mut depth, mut start) = (Vec::new(), 0i32, 0);
    for (i, c) in tree.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 0 => {
                out.push(&tree[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    out.push(&tree[start..]);
    out.retain(|s| !s.trim().is_empty());
    out
}

/// The paths module `m` names: its `use` trees and the `crate::`, `super::` and
/// `self::` paths in its code, each absolute (paths into other crates dropped).
fn referenced_paths(m: &Module) -> Vec<Vec<String>> {
    let no_modules = BTreeSet::new(); // relative `use` of a child: parent -> child, no edge
    let mut out: Vec<Vec<String>> = use_decls(&m.code)
        .iter()
        .flat_map(|d| expand_use(d))
        .filter_map(|(_, p)| absolute(&m.path, &p, &no_modules))
        .collect();
    for start in ["crate::", "super::", "self::"] {
        let mut rest = m.code.as_str();
        while let Some(i) = find_word(rest, start) {
            let tail = &rest[i..];
            let len = tail
                .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_' || c == ':'))
                .unwrap_or(tail.len());
            if let Some(p) = absolute(&m.path, &segments(&tail[..len]), &no_modules) {
                out.push(p);
            }
            rest = &tail[len.max(1)..];
        }
    }
    out
}

/// A synthetic crate for the checker's own test: `(path with '/', code)` pairs.
pub fn synthetic(files: &[(&str, &str)]) -> Vec<Module> {
    files
        .iter()
        .map(|(p, c)| Module {
            path: p
                .split('/')
                .filter(|s| !s.is_empty())
                .map(String::from)
                .collect(),
            code: c.to_string(),
        })
        .collect()
}
