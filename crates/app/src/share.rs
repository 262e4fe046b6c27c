//! Scenes in links: the scene file, deflated and base64url-encoded, in the page URL's
//! fragment (`#scene=…`), which never reaches a server. `#example=NAME` opens a built-in
//! scene. A link is untrusted input: its length is capped, inflating stops at a size
//! limit (a few kilobytes can inflate to gigabytes), and the text is parsed and validated
//! like any scene file, every problem reported.

use base64::Engine as _;
use base64::engine::general_purpose::URL_SAFE_NO_PAD;
use physics::{Scene, SceneFormat};

use crate::i18n::{Arg, tr, tr_with};

/// The longest fragment accepted, characters.
pub const MAX_LINK: usize = 512 * 1024;
/// The largest scene file a link may inflate to, bytes.
pub const MAX_SCENE: usize = 8 * 1024 * 1024;

/// Where links point until the user names the address of their browser build: the
/// build served on this computer, as the README's `python3 -m http.server` serves it.
pub const DEFAULT_ADDRESS: &str = "http://127.0.0.1:8080/";

/// The fragment (without `#`) that carries `scene`.
pub fn encode(scene: &Scene) -> String {
    let compressed = miniz_oxide::deflate::compress_to_vec(scene.to_toml().as_bytes(), 9);
    format!("scene={}", URL_SAFE_NO_PAD.encode(compressed))
}

/// The fragment that carries `scene`, if it is short enough to open.
///
/// # Errors
/// A scene too large for a link (the 20,000-star cluster), with the advice to save it as
/// a file instead: a link cut short would not open.
pub fn fragment(scene: &Scene) -> Result<String, String> {
    let fragment = encode(scene);
    if fragment.len() > MAX_LINK {
        #[expect(clippy::cast_precision_loss, reason = "a count of characters")]
        return Err(tr_with(
            "link-scene-too-large",
            &[
                ("length", Arg::Number(fragment.len() as f64)),
                ("limit", Arg::Number(MAX_LINK as f64)),
            ],
        ));
    }
    Ok(fragment)
}

/// A link to `scene` in the browser build at `address` (a page's address; anything after
/// a `#` in it is replaced).
///
/// # Errors
/// As [`fragment`].
pub fn link(address: &str, scene: &Scene) -> Result<String, String> {
    Ok(join(address, &fragment(scene)?))
}

/// The link of `fragment` on the page at `address` (anything after a `#` replaced).
pub fn join(address: &str, fragment: &str) -> String {
    let page = address.trim().split('#').next().unwrap_or_default();
    format!("{page}#{fragment}")
}

/// The scene a link, or a bare fragment, carries: the text pasted into File → Open link.
///
/// # Errors
/// Why it opens nothing, in words: no `NewtonLab` link at all, or [`decode`]'s reasons.
pub fn open(text: &str) -> Result<Scene, String> {
    let text = text.trim();
    let fragment = text.split_once('#').map_or(text, |(_, fragment)| fragment);
    decode(fragment)?.ok_or_else(|| tr("link-not-newtonlab"))
}

/// The scene a fragment carries; `Ok(None)` for a fragment that is not a `NewtonLab`
/// link at all.
///
/// # Errors
/// Why the link cannot be opened, in words for the user.
pub fn decode(fragment: &str) -> Result<Option<Scene>, String> {
    let fragment = fragment.trim_start_matches('#');
    if fragment.len() > MAX_LINK {
        #[expect(clippy::cast_precision_loss, reason = "a count of characters")]
        return Err(tr_with(
            "link-too-long",
            &[
                ("length", Arg::Number(fragment.len() as f64)),
                ("limit", Arg::Number(MAX_LINK as f64)),
            ],
        ));
    }
    if let Some(name) = fragment.strip_prefix("example=") {
        let example = physics::example(name)
            .ok_or_else(|| tr_with("link-no-example", &[("name", Arg::Text(name))]))?;
        return example
            .scene()
            .map(Some)
            .map_err(|e| e.report(&format!("example:{name}")));
    }
    let Some(data) = fragment.strip_prefix("scene=") else {
        return Ok(None);
    };
    let compressed = URL_SAFE_NO_PAD
        .decode(data)
        .map_err(|_| tr("link-not-base64"))?;
    let bytes = miniz_oxide::inflate::decompress_to_vec_with_limit(&compressed, MAX_SCENE)
        .map_err(|e| {
            if matches!(e.status, miniz_oxide::inflate::TINFLStatus::HasMoreOutput) {
                #[expect(clippy::cast_precision_loss, reason = "a few megabytes")]
                let megabytes = (MAX_SCENE / (1024 * 1024)) as f64;
                tr_with("link-too-large", &[("megabytes", Arg::Number(megabytes))])
            } else {
                tr("link-not-unpacked")
            }
        })?;
    let text = String::from_utf8(bytes).map_err(|_| tr("link-not-text"))?;
    Scene::parse(&text, SceneFormat::Toml)
        .map(Some)
        .map_err(|e| e.report("the linked scene"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_link_carries_a_scene_exactly() {
        for example in physics::EXAMPLES {
            let scene = example.scene().unwrap();
            let link = encode(&scene);
            if link.len() > MAX_LINK {
                // The 20,000-star cluster: refused with the reason, never cut short
                // (`#example=star-cluster` links to it).
                let refused = decode(&link).unwrap_err();
                assert!(refused.contains("too long"), "{}: {refused}", example.name);
                continue;
            }
            assert_eq!(decode(&link).unwrap(), Some(scene), "{}", example.name);
        }
        let link = encode(&physics::example("ball-pit").unwrap().scene().unwrap());
        assert!(
            link.len() < 40_000,
            "a 1,000-ball scene fits in a link: {} characters",
            link.len()
        );
    }

    #[test]
    fn damaged_links_are_refused_with_a_reason() {
        let link = encode(&physics::example("collision").unwrap().scene().unwrap());
        let cut = &link[..link.len() / 2];
        assert!(decode(cut).unwrap_err().contains("damaged"), "cut short");
        assert!(
            decode("scene=!!!not-base64!!!")
                .unwrap_err()
                .contains("not valid base64"),
            "garbage"
        );
        let not_deflate = format!("scene={}", URL_SAFE_NO_PAD.encode(b"plain text"));
        assert!(
            decode(&not_deflate).unwrap_err().contains("damaged"),
            "not compressed"
        );
        let invalid = Scene::from_toml("version = 1").unwrap();
        let mut text = invalid.to_toml();
        text.push_str("[[particle]]\nmass = -1\nposition = [0, 0]\n");
        let link = format!(
            "scene={}",
            URL_SAFE_NO_PAD.encode(miniz_oxide::deflate::compress_to_vec(text.as_bytes(), 9))
        );
        let message = decode(&link).unwrap_err();
        assert!(
            message.contains("mass must be greater than 0, got -1"),
            "validated like a file: {message}"
        );
        assert!(
            decode(&"a".repeat(MAX_LINK + 1))
                .unwrap_err()
                .contains("too long"),
            "length cap"
        );
        assert_eq!(decode("").unwrap(), None, "no link");
        assert!(
            decode("example=nope")
                .unwrap_err()
                .contains("does not exist"),
            "unknown example"
        );
    }

    #[test]
    fn a_pasted_link_opens_whatever_page_it_names() {
        let scene = physics::example("lesson-galileo-incline")
            .unwrap()
            .scene()
            .unwrap();
        let made = link("https://school.example/newtonlab/#old", &scene).unwrap();
        assert!(
            made.starts_with("https://school.example/newtonlab/#scene="),
            "{made}"
        );
        assert_eq!(open(&format!("  {made}\n")).unwrap(), scene, "pasted");
        assert_eq!(open(&encode(&scene)).unwrap(), scene, "a bare fragment");
        assert_eq!(
            open("http://127.0.0.1:8080/#example=collision").unwrap(),
            physics::example("collision").unwrap().scene().unwrap()
        );
        for text in ["", "https://example.org/", "https://example.org/#top"] {
            assert!(
                open(text)
                    .unwrap_err()
                    .contains("not a link to a NewtonLab scene"),
                "{text:?}"
            );
        }
        let cluster = physics::example("star-cluster").unwrap().scene().unwrap();
        let refused = link(DEFAULT_ADDRESS, &cluster).unwrap_err();
        assert!(refused.contains("save it as a file"), "{refused}");
    }

    /// A kilobyte-sized link that would inflate to gigabytes stops at the limit.
    #[test]
    fn a_compression_bomb_is_refused() {
        let zeros = vec![b' '; MAX_SCENE + 1];
        let bomb = format!(
            "scene={}",
            URL_SAFE_NO_PAD.encode(miniz_oxide::deflate::compress_to_vec(&zeros, 9))
        );
        assert!(
            bomb.len() < MAX_LINK,
            "small enough to pass the length check"
        );
        assert!(
            decode(&bomb).unwrap_err().contains("larger than"),
            "inflation capped"
        );
    }
}
