//! Every message id the code names exists in English: an id that is not there would show
//! as itself on screen (`tr` falls back to the id), so a typo in one is a bug this finds.
//! The ids are the string literals of the workspace's sources that look like ids of the
//! families the messages use (`scene-…`, `cli-…`, `menu-…`, …).

use std::path::Path;

/// The prefixes of message ids.
const FAMILIES: &[&str] = &[
    "scene-",
    "cli-",
    "run-",
    "menu-",
    "toolbar-",
    "tool-",
    "status-",
    "key-",
    "keys-",
    "canvas-key-",
    "readout-",
    "bar-",
    "impacts-",
    "graph-",
    "announce-",
    "instrument-",
    "stopwatch-",
    "notice-",
    "file-",
    "timeline-",
    "inspector-",
    "link-",
    "failure-",
    "edit-",
    "units-",
    "field-",
];

fn sources(dir: &Path, out: &mut Vec<(String, String)>) {
    for entry in std::fs::read_dir(dir).expect("a source folder").flatten() {
        let path = entry.path();
        if path.is_dir() {
            sources(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            let text = std::fs::read_to_string(&path).expect("a source file");
            out.push((path.display().to_string(), text));
        }
    }
}

/// The string literals of `text` that look like message ids.
fn ids(text: &str) -> Vec<String> {
    text.split('"')
        .skip(1)
        .step_by(2)
        .filter(|literal| {
            FAMILIES.iter().any(|family| literal.starts_with(family))
                && literal
                    .chars()
                    .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '-')
                && !literal.ends_with('-')
        })
        .map(str::to_owned)
        .collect()
}

#[test]
fn every_id_in_the_code_is_a_message() {
    let english: Vec<&str> = newtonlab_i18n::SOURCES[0]
        .lines()
        .filter_map(|line| line.split_once(" = ").map(|(id, _)| id))
        .collect();
    let crates = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut files = Vec::new();
    for name in ["app", "physics", "newtonlab"] {
        sources(&crates.join(name).join("src"), &mut files);
    }
    let mut named = 0;
    let mut missing = Vec::new();
    for (path, text) in &files {
        for id in ids(text) {
            named += 1;
            if !english.contains(&id.as_str()) {
                missing.push(format!("{path}: {id}"));
            }
        }
    }
    assert!(missing.is_empty(), "not messages:\n{}", missing.join("\n"));
    assert!(named > 200, "only {named} ids found: the scan is broken");
}
