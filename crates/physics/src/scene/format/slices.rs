//! A long TOML file read a slice at a time.
//!
//! toml's parser lexes the whole text into tokens before it parses (24 bytes a token, about
//! one token for every two bytes of a scene) and builds its own tree beside the one this
//! reader keeps, so a long file read whole takes some forty times its size. Long scenes are
//! long runs of `[[particle]]` and `[[spring]]` sections under plain names: such a file is
//! cut at its section headers into slices of about `SLICE_BYTES`, each slice is parsed
//! alone, and its sections join the tree, so only one slice's tokens and toml tree are
//! alive at a time.
//!
//! The cut keeps TOML's meaning only where that is plain to see, so anything else is read
//! whole, as a short file is: a file with few headers, a header that is not one plain name
//! (`[world.bounds]`, a quoted key), a `[table]` named twice or also as `[[table]]`, a key
//! before the first header that a header names again, or a slice that does not parse — then
//! every message is the one the whole file gives.

use std::collections::HashSet;

use toml_parser::lexer::TokenKind;

use super::tree::{Entry, Node, Value, toml_entries};

/// Fewer headers than this: the file is read whole (slicing saves nothing worth its cost).
const SLICED_FROM_HEADERS: usize = 1_024;

/// About how much text each slice holds.
const SLICE_BYTES: usize = 1 << 18;

/// A section header at the start of a line: `[name]` or `[[name]]`.
struct Header<'t> {
    start: usize,
    name: &'t str,
    array: bool,
}

/// The file's tree, read slice by slice; `None` where it must be read whole.
pub(super) fn parse_in_slices(text: &str) -> Option<Node<'_>> {
    if text.len() < SLICE_BYTES {
        return None;
    }
    let headers = headers(text)?;
    if headers.len() < SLICED_FROM_HEADERS || !one_meaning(&headers) {
        return None;
    }
    let named: HashSet<&str> = headers.iter().map(|h| h.name).collect();
    let mut root = parse_slice(text, 0, headers[0].start)?;
    if root.iter().any(|entry| named.contains(&*entry.key)) {
        return None;
    }
    let mut cuts = vec![headers[0].start];
    for header in &headers[1..] {
        if header.start - cuts[cuts.len() - 1] >= SLICE_BYTES {
            cuts.push(header.start);
        }
    }
    cuts.push(text.len());
    for slice in cuts.windows(2) {
        join(&mut root, parse_slice(text, slice[0], slice[1])?)?;
    }
    Some(Node {
        value: Value::Table(root),
        span: Some(0..text.len()),
    })
}

/// Every `[table]` named once and never also as `[[table]]`: the sections then mean the same
/// read apart as together.
fn one_meaning(headers: &[Header<'_>]) -> bool {
    let mut tables = HashSet::new();
    let mut arrays = HashSet::new();
    for header in headers {
        if header.array {
            arrays.insert(header.name);
        } else if !tables.insert(header.name) {
            return false;
        }
    }
    tables.is_disjoint(&arrays)
}

/// A slice's sections; `None` when it does not parse alone.
fn parse_slice(text: &str, start: usize, end: usize) -> Option<Vec<Entry<'_>>> {
    let (table, errors) = toml::de::DeTable::parse_recoverable(text.get(start..end)?);
    errors
        .is_empty()
        .then(|| toml_entries(table.into_inner(), start))
}

/// Adds a slice's sections to the tree: a table under a new name, an array of tables after
/// the items it already has. The names keep the order they first appear in, as toml's
/// tables keep theirs; a tree has a few of them, so they are looked through.
fn join<'t>(root: &mut Vec<Entry<'t>>, entries: Vec<Entry<'t>>) -> Option<()> {
    for entry in entries {
        match root.iter_mut().find(|known| known.key == entry.key) {
            Some(known) => match (&mut known.node.value, entry.node.value) {
                (Value::Array(items), Value::Array(more)) => items.extend(more),
                _ => return None,
            },
            None => root.push(entry),
        }
    }
    Some(())
}

/// The section headers of a TOML text, found by its lexer: a `[` first on its line outside
/// any array or inline table. `None` when a header is other than one plain name, or brackets
/// do not pair up.
fn headers(text: &str) -> Option<Vec<Header<'_>>> {
    let mut tokens = toml_parser::Source::new(text)
        .lex()
        .filter(|t| !matches!(t.kind(), TokenKind::Whitespace | TokenKind::Comment))
        .peekable();
    let mut found = Vec::new();
    let mut depth = 0_usize;
    let mut line_start = true;
    while let Some(token) = tokens.next() {
        match token.kind() {
            TokenKind::Newline => {
                line_start = true;
                continue;
            }
            TokenKind::LeftSquareBracket if depth == 0 && line_start => {
                let array = tokens
                    .next_if(|t| t.kind() == TokenKind::LeftSquareBracket)
                    .is_some();
                let key = tokens.next()?;
                let name = text.get(key.span().start()..key.span().end())?;
                let plain = name
                    .bytes()
                    .all(|b| b.is_ascii_alphanumeric() || b == b'_' || b == b'-');
                if key.kind() != TokenKind::Atom || name.is_empty() || !plain {
                    return None;
                }
                for _ in 0..=usize::from(array) {
                    tokens.next_if(|t| t.kind() == TokenKind::RightSquareBracket)?;
                }
                tokens.next_if(|t| matches!(t.kind(), TokenKind::Newline | TokenKind::Eof))?;
                found.push(Header {
                    start: token.span().start(),
                    name,
                    array,
                });
                line_start = true;
                continue;
            }
            TokenKind::LeftSquareBracket | TokenKind::LeftCurlyBracket => depth += 1,
            TokenKind::RightSquareBracket | TokenKind::RightCurlyBracket => {
                depth = depth.checked_sub(1)?;
            }
            _ => {}
        }
        line_start = false;
    }
    (depth == 0).then_some(found)
}

#[cfg(test)]
mod tests {
    use std::fmt::Write as _;

    use super::{SLICE_BYTES, SLICED_FROM_HEADERS, parse_in_slices};
    use crate::scene::Scene;
    use crate::scene::error::LoadError;
    use crate::scene::format::read::Reader;
    use crate::scene::format::tree::parse_toml_whole;

    /// The scene (or its problems) as the whole text reads, without slices.
    fn read_whole(text: &str) -> Result<Scene, LoadError> {
        let root = parse_toml_whole(text)?;
        let mut reader = Reader::new(text);
        let scene = reader.scene(&root);
        reader.finish(scene, &root)
    }

    /// A long scene: `[[particle]]` sections with springs and rods between them, the
    /// `[simulation]` and `[world]` tables in the middle, graphs at the end; `extra` goes
    /// among the particles, 200 before their end.
    fn long_scene(particles: usize, extra: &str) -> String {
        let mut text = "version = 1\nname = \"long\"\n\n".to_owned();
        for i in 0..particles {
            if i + 200 == particles {
                text.push_str(extra);
            }
            if i == particles / 2 {
                text.push_str("[simulation]\ntime_step = 0.002 # the middle\n\n");
                text.push_str("[world]\ngravity = [0, -9.81]\n\n");
            }
            let _ = write!(
                text,
                "[[particle]]\nname = \"p{i}\"\nmass = {}\nposition = [{}, {}]\n\
                 velocity = [ 0.5,\n  -1 ]\nradius = 0.1\n\n",
                1 + i % 3,
                i % 100,
                i / 100,
            );
            if i % 7 == 6 {
                let _ = write!(
                    text,
                    "[[spring]]\nfrom = \"p{}\"\nto = \"p{i}\"\nstiffness = 10\nnatural_length = 1\n\n",
                    i - 1
                );
            }
            if i % 11 == 10 {
                let _ = write!(
                    text,
                    "[[rod]]\nfrom = \"p{}\"\nto = \"p{i}\"\nlength = 2\n\n",
                    i - 3
                );
            }
        }
        text.push_str("[[graph]]\ny = [\"p1.x\"]\n");
        text
    }

    /// A long scene read slice by slice is the scene read whole: every particle, spring,
    /// rod and table, in the file's order.
    #[test]
    fn a_long_scene_read_in_slices_is_the_scene_read_whole() {
        let text = long_scene(6_000, "");
        assert!(
            text.len() > 2 * SLICE_BYTES,
            "the scene spans several slices"
        );
        assert!(
            parse_in_slices(&text).is_some(),
            "the scene is read in slices"
        );
        let sliced = Scene::from_toml(&text).expect("the long scene loads");
        let whole = read_whole(&text).expect("the long scene loads whole");
        assert_eq!(sliced.particles.len(), 6_000, "every particle is read");
        assert_eq!(sliced.ties.len(), 545, "every rod is read");
        assert_eq!(sliced, whole, "slices read the scene the whole text reads");
    }

    /// A problem deep in a long file is placed at the same line and column as when the
    /// whole file is read, both from the reader and from the scene's own checks.
    #[test]
    fn problems_in_a_long_scene_keep_their_places() {
        let extra = "[[particle]]\nname = \"bad\"\nmass = -2\nposition = [0, \"x\"]\n\n";
        let text = long_scene(5_000, extra);
        assert!(
            text.len() > SLICE_BYTES + SLICE_BYTES / 2,
            "the problem is in a later slice"
        );
        assert!(
            parse_in_slices(&text).is_some(),
            "the scene is read in slices"
        );
        let sliced = Scene::from_toml(&text).expect_err("the bad particle is refused");
        let whole = read_whole(&text).expect_err("the bad particle is refused whole");
        assert_eq!(sliced, whole, "the same problems at the same places");
        assert_eq!(sliced.problems.len(), 2, "the mass and the position");
        assert!(
            sliced
                .problems
                .iter()
                .all(|p| p.line.is_some_and(|l| l > 10_000)),
            "both placed deep in the file: {sliced:?}"
        );
    }

    /// What slices could read otherwise than the whole file is read whole, so the messages
    /// are TOML's own: a table named twice, a table also named as an array, a dotted or
    /// quoted header, a key before the headers that a header names again, a syntax error.
    #[test]
    fn what_slices_could_misread_is_read_whole() {
        let cases = [
            "[simulation]\ntime_step = 0.01\n\n",
            "[particle]\nmass = 1\n\n",
            "[world.bounds]\nmin = [0, 0]\n\n",
            "[\"quoted\"]\nx = 1\n\n",
            "[[particle]]\nname = \"broken\nmass = 1\n\n",
        ];
        for extra in cases {
            let text = long_scene(2_000, extra);
            assert!(parse_in_slices(&text).is_none(), "read whole: {extra}");
        }
        let preamble = format!(
            "simulation = {{ time_step = 0.01 }}\n{}",
            long_scene(2_000, "")
        );
        assert!(
            parse_in_slices(&preamble).is_none(),
            "a root key named again"
        );
        let short = long_scene(SLICED_FROM_HEADERS / 4, "");
        assert!(
            parse_in_slices(&short).is_none(),
            "a short scene is read whole"
        );
        // A table named twice is TOML's problem, with its place, as the whole file says.
        let twice = long_scene(2_000, "[simulation]\ntime_step = 0.01\n\n");
        let error = Scene::from_toml(&twice).expect_err("a table named twice is refused");
        assert_eq!(
            error,
            read_whole(&twice).expect_err("refused whole"),
            "the whole file's message"
        );
    }

    /// Lines that could make slices read a file otherwise than whole, each put at the
    /// start of a line somewhere in a long scene (often where a header was): whatever
    /// the file is, slices give exactly what the whole file gives — the same scene, or the
    /// same problems at the same places.
    #[test]
    fn any_line_anywhere_reads_as_the_whole_file_reads() {
        const LINES: &[&str] = &[
            "[simulation]\ntime_step = 0.002\n",
            "[particle]\nmass = 1\n",
            "[[particle]]\nname = \"extra\"\nmass = 2\nposition = [0, -1]\n",
            "[[particle]]\n",
            "[world.bounds]\nmin = [0, 0]\n",
            "[[\"particle\"]]\nname = \"quoted\"\nmass = 1\n",
            "[ [particle] ]\n",
            "[[particle]] # a comment\nname = \"commented\"\nmass = 1\n",
            "points = [\n[1, 2],\n[3, 4]\n]\n",
            "text = \"\"\"\n[[particle]]\n\"\"\"\n",
            "inline = { a = [1, 2], b = { c = 3 } }\n",
            "name = \"twice\"\n",
            "version = 1\n",
            "[view]\ntrails = true\n",
            "[[spring]]\nfrom = \"p1\"\nto = \"p2\"\nstiffness = 5\nnatural_length = 1\n",
            "mass = -1\n",
            "[unclosed\n",
            "]\n",
            "= 3\n",
            "\u{feff}",
            "\r\n",
            "particle = [{ name = \"static\", mass = 1 }]\n",
            "simulation = { time_step = 0.01 }\n",
        ];
        let text = long_scene(3_000, "");
        let starts: Vec<usize> = std::iter::once(0)
            .chain(text.match_indices('\n').map(|(i, _)| i + 1))
            .filter(|&i| i < text.len())
            .collect();
        let mut runner = proptest::test_runner::TestRunner::new(proptest::test_runner::Config {
            cases: 32,
            ..proptest::test_runner::Config::default()
        });
        let cases = (
            0..starts.len(),
            0..LINES.len(),
            0..starts.len(),
            0..LINES.len(),
        );
        runner
            .run(&cases, |(at, line, again, second)| {
                let mut mutated = text.clone();
                let (first, other) = (starts[at].max(starts[again]), starts[at].min(starts[again]));
                mutated.insert_str(first, LINES[line]);
                mutated.insert_str(other, LINES[second]);
                let sliced = Scene::from_toml(&mutated);
                let whole = read_whole(&mutated);
                proptest::prop_assert_eq!(
                    sliced,
                    whole,
                    "{} at {}, {} at {}",
                    LINES[line],
                    first,
                    LINES[second],
                    other
                );
                Ok(())
            })
            .expect("slices read every file as the whole file does");
    }
}
