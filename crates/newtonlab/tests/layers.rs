//! The crates' modules form layers: a module may name only the modules below it, so
//! there is no import circle, and a newcomer can read the physics from the bottom up
//! (docs/architecture.md draws the same layers).
//!
//! Each crate's top-level modules are listed lowest first. A reference is any path that
//! starts with `crate::` or `super::` outside a test module, including the names of a
//! `use` tree; a name that the crate root re-exports (`crate::Simulation`) counts as the
//! module it comes from. A module left out of the list, or a reference upwards, fails
//! with the file and the path that names it.

use std::collections::HashMap;
use std::fs;
use std::path::{Path, PathBuf};

/// The physics crate's modules, lowest first.
const PHYSICS: &[&str] = &[
    "tuning",
    "units",
    "profile",
    "parallel",
    "cycle",
    "state",
    "method",
    "impact",
    "quantity",
    "constraints",
    "scene",
    "generated",
    "examples",
    "forces",
    "field",
    "integrators",
    "turning",
    "diagnostics",
    "contacts",
    "bodies",
    "simulation",
    "csv",
    "events",
    "trajectory",
    "series",
    "testing",
];

/// The app's modules, lowest first: the scene's edits and the document under the canvas,
/// the panels above them, the menus and the whole window on top.
const APP: &[&str] = &[
    "edit",
    "document",
    "format",
    "landmarks",
    "recording",
    "timeline",
    "watching",
    "run_loop",
    "canvas",
    "picture",
    "action",
    "analysis",
    "announcer",
    "platform",
    "autosave",
    "experiments",
    "readouts",
    "plots",
    "figure",
    "files",
    "experiment_files",
    "frames",
    "help",
    "lesson",
    "inspector",
    "settings",
    "keeping",
    "share",
    "links",
    "toolbar",
    "web",
    "menu",
    "opening",
    "status",
    "stopwatch",
    "time_bar",
    "worksheet",
];

/// Every `.rs` file under `dir`, with its module path from the crate root.
fn modules(root: &Path) -> Vec<(Vec<String>, PathBuf)> {
    let mut out = Vec::new();
    let mut stack = vec![root.to_path_buf()];
    while let Some(dir) = stack.pop() {
        for entry in fs::read_dir(&dir).expect("readable source folder") {
            let path = entry.expect("a folder entry").path();
            if path.is_dir() {
                stack.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") {
                let relative = path.strip_prefix(root).expect("under the root");
                let mut parts: Vec<String> = relative
                    .with_extension("")
                    .components()
                    .map(|c| c.as_os_str().to_string_lossy().into_owned())
                    .collect();
                if parts.last().is_some_and(|p| p == "mod" || p == "lib") {
                    parts.pop();
                }
                out.push((parts, path));
            }
        }
    }
    out
}

/// The source without comments and without its `#[cfg(test)] mod … { … }` (tests may
/// reach anywhere).
fn code(source: &str) -> String {
    let text: String = source
        .lines()
        .map(|line| line.split("//").next().unwrap_or(""))
        .collect::<Vec<_>>()
        .join("\n");
    let compact: String = text.split_whitespace().collect::<Vec<_>>().join(" ");
    let test_module = compact.match_indices("#[cfg(test)] mod ").find(|(at, m)| {
        let after = &compact[at + m.len()..];
        let name = after.split(' ').next().unwrap_or("");
        after[name.len()..].starts_with(" {")
    });
    match test_module {
        Some((at, _)) => compact[..at].to_owned(),
        None => compact,
    }
}

/// Every path of a `use` tree: `a::{b, c::{d}}` gives `a::b` and `a::c::d`.
fn expand(prefix: &[String], tree: &str, out: &mut Vec<Vec<String>>) {
    let tree = tree.trim();
    if let Some(open) = tree.find('{')
        && tree.ends_with('}')
    {
        let mut head = prefix.to_vec();
        head.extend(
            tree[..open]
                .split("::")
                .map(str::trim)
                .filter(|s| !s.is_empty())
                .map(str::to_owned),
        );
        let inner = &tree[open + 1..tree.len() - 1];
        let (mut depth, mut start) = (0, 0);
        for (i, c) in inner.char_indices() {
            match c {
                '{' => depth += 1,
                '}' => depth -= 1,
                ',' if depth == 0 => {
                    expand(&head, &inner[start..i], out);
                    start = i + 1;
                }
                _ => {}
            }
        }
        expand(&head, &inner[start..], out);
        return;
    }
    let tree = tree.split(" as ").next().unwrap_or(tree);
    let mut path = prefix.to_vec();
    path.extend(
        tree.split("::")
            .map(str::trim)
            .filter(|s| !s.is_empty())
            .map(str::to_owned),
    );
    if !path.is_empty() {
        out.push(path);
    }
}

/// The paths a file names: its `use` trees and the `crate::`/`super::` paths in its code.
fn paths(code: &str) -> Vec<Vec<String>> {
    let mut out = Vec::new();
    let mut rest = code;
    while let Some(at) = rest.find("use ") {
        let before = &rest[..at];
        rest = &rest[at + 4..];
        if before
            .chars()
            .last()
            .is_some_and(|c| c.is_alphanumeric() || c == '_')
        {
            continue;
        }
        if let Some(end) = rest.find(';') {
            expand(&[], &rest[..end], &mut out);
        }
    }
    for word in ["crate::", "super::"] {
        for (at, _) in code.match_indices(word) {
            if code[..at]
                .chars()
                .last()
                .is_some_and(|c| c.is_alphanumeric() || c == '_')
            {
                continue;
            }
            let path: String = code[at..]
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_' || *c == ':')
                .collect();
            out.push(
                path.split("::")
                    .filter(|s| !s.is_empty())
                    .map(str::to_owned)
                    .collect(),
            );
        }
    }
    let mut seen = std::collections::HashSet::new();
    out.retain(|path| seen.insert(path.clone()));
    out
}

/// Each reference from one top-level module to another: (from, to, file, path).
fn references(root: &Path) -> Vec<(String, String, String, String)> {
    let files = modules(root);
    let known: Vec<&Vec<String>> = files.iter().map(|(m, _)| m).collect();
    let lib = code(&fs::read_to_string(root.join("lib.rs")).expect("lib.rs"));
    let mut reexported: HashMap<String, Vec<String>> = HashMap::new();
    let mut rest = lib.as_str();
    while let Some(at) = rest.find("pub use ") {
        rest = &rest[at + 8..];
        let end = rest.find(';').unwrap_or(rest.len());
        let mut trees = Vec::new();
        expand(&[], &rest[..end], &mut trees);
        for mut path in trees {
            if let Some(name) = path.pop() {
                reexported.insert(name, path);
            }
        }
    }
    let mut out = Vec::new();
    for (module, file) in &files {
        let Some(top) = module.first() else {
            continue; // the crate root: it declares and re-exports every module
        };
        let source = fs::read_to_string(file).expect("a readable source file");
        for path in paths(&code(&source)) {
            let target: Vec<String> = match path.first().map(String::as_str) {
                Some("crate") => path[1..].to_vec(),
                Some("super") => {
                    let mut base = module.clone();
                    let mut rest = &path[..];
                    while rest.first().is_some_and(|p| p == "super") {
                        base.pop();
                        rest = &rest[1..];
                    }
                    base.extend(rest.iter().cloned());
                    base
                }
                _ => continue,
            };
            let Some(first) = target.first() else {
                continue;
            };
            let first_module = known.iter().any(|m| m.first() == Some(first));
            let to = if first_module {
                first.clone()
            } else if let Some(source) = reexported.get(first).and_then(|p| p.first()) {
                source.clone()
            } else {
                continue;
            };
            if &to != top {
                let relative = file.strip_prefix(root).unwrap_or(file);
                out.push((
                    top.clone(),
                    to,
                    relative.display().to_string(),
                    path.join("::"),
                ));
            }
        }
    }
    out
}

/// Every reference goes down the `order`, and every module is in it.
fn assert_layered(crate_src: &str, order: &[&str]) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("..")
        .join(crate_src);
    let rank = |m: &str| order.iter().position(|o| *o == m);
    let mut wrong = Vec::new();
    for (from, _) in modules(&root) {
        if let Some(top) = from.first()
            && rank(top).is_none()
        {
            wrong.push(format!("module `{top}` is in no layer of the list"));
        }
    }
    for (from, to, file, path) in references(&root) {
        match (rank(&from), rank(&to)) {
            (Some(a), Some(b)) if b < a => {}
            (Some(_), Some(_)) => {
                wrong.push(format!("{file}: `{path}` names `{to}`, not below `{from}`"));
            }
            _ => {}
        }
    }
    wrong.sort();
    wrong.dedup();
    assert!(wrong.is_empty(), "{crate_src}:\n{}", wrong.join("\n"));
}

#[test]
fn the_physics_modules_form_layers() {
    assert_layered("physics/src", PHYSICS);
}

#[test]
fn the_app_modules_form_layers() {
    assert_layered("app/src", APP);
}

#[test]
fn the_checker_sees_use_trees_re_exports_and_super_paths() {
    let mut out = Vec::new();
    expand(&[], "crate::{a::{B, C}, D as E}", &mut out);
    assert_eq!(
        out,
        [
            vec!["crate", "a", "B"],
            vec!["crate", "a", "C"],
            vec!["crate", "D"],
        ]
    );
    let found = paths(&code(
        "use super::x::Y; #[cfg(test)] mod helpers; fn f() { crate::z::w(); }\n#[cfg(test)]\nmod tests { use crate::q; }",
    ));
    assert_eq!(found, [vec!["super", "x", "Y"], vec!["crate", "z", "w"],]);
}
