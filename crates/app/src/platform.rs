//! What differs between the desktop and the browser, behind one small seam: reading and
//! writing the user's files. The clock is `web_time::Instant`, which is `std`'s on the
//! desktop and the browser's `performance.now()` on the web.

/// Reads a text file.
///
/// # Errors
/// The operating system's reason, in words.
#[cfg(not(target_arch = "wasm32"))]
pub fn read_text(path: &str) -> Result<String, String> {
    std::fs::read_to_string(path).map_err(|e| {
        crate::i18n::tr_text(
            "file-cannot-read",
            &[("path", path), ("error", &e.to_string())],
        )
    })
}

/// Writes a text file.
///
/// # Errors
/// The operating system's reason, in words.
#[cfg(not(target_arch = "wasm32"))]
pub fn write_text(path: &str, text: &str) -> Result<(), String> {
    write_bytes(path, text.as_bytes())
}

/// Writes `bytes` to the file at `path`, or says why it cannot.
///
/// # Errors
/// The reason, naming the file.
#[cfg(not(target_arch = "wasm32"))]
pub fn write_bytes(path: &str, bytes: &[u8]) -> Result<(), String> {
    write_atomically(std::path::Path::new(path), bytes)
}

/// Writes `bytes` to `path` so that a crash or a kill at any moment leaves either the old
/// file or the new one, never a mix: a temporary file beside it, flushed to the disk, then
/// renamed over it.
///
/// # Errors
/// The operating system's reason, naming the file.
#[cfg(not(target_arch = "wasm32"))]
pub fn write_atomically(path: &std::path::Path, bytes: &[u8]) -> Result<(), String> {
    use std::io::Write as _;
    let fail = |e: std::io::Error| {
        crate::i18n::tr_text(
            "file-cannot-write",
            &[
                ("path", &path.display().to_string()),
                ("error", &e.to_string()),
            ],
        )
    };
    let name = path
        .file_name()
        .map_or_else(|| "file".to_owned(), |n| n.to_string_lossy().into_owned());
    let temporary = path.with_file_name(format!(".{name}.newtonlab-tmp"));
    let mut file = std::fs::File::create(&temporary).map_err(fail)?;
    file.write_all(bytes).map_err(fail)?;
    file.sync_all().map_err(fail)?;
    drop(file);
    std::fs::rename(&temporary, path).map_err(|e| {
        let _ = std::fs::remove_file(&temporary);
        fail(e)
    })
}

/// When the file at `path` was last changed, and its length: to notice a file changed
/// on disk since it was opened or saved.
#[cfg(not(target_arch = "wasm32"))]
pub fn stamp(path: &str) -> Option<(std::time::SystemTime, u64)> {
    let metadata = std::fs::metadata(path).ok()?;
    Some((metadata.modified().ok()?, metadata.len()))
}

/// The entries of a folder, folders first, for the file dialog: (name, is a folder).
#[cfg(not(target_arch = "wasm32"))]
pub fn list_folder(path: &str) -> Vec<(String, bool)> {
    let Ok(entries) = std::fs::read_dir(if path.is_empty() { "." } else { path }) else {
        return Vec::new();
    };
    let mut list: Vec<(String, bool)> = entries
        .filter_map(Result::ok)
        .map(|e| {
            (
                e.file_name().to_string_lossy().into_owned(),
                e.path().is_dir(),
            )
        })
        .filter(|(name, _)| !name.starts_with('.'))
        .collect();
    list.sort_by(|a, b| b.1.cmp(&a.1).then_with(|| a.0.cmp(&b.0)));
    list
}

/// The folder the app started in, as the file dialog's first folder.
#[cfg(not(target_arch = "wasm32"))]
pub fn current_folder() -> String {
    std::env::current_dir()
        .map(|p| p.to_string_lossy().into_owned())
        .unwrap_or_default()
}

/// The browser's side of the seam: a file picker whose result arrives in an inbox the
/// app reads each frame, downloads, the clipboard, the page's address and its storage.
#[cfg(target_arch = "wasm32")]
pub mod web {
    use std::cell::RefCell;

    use wasm_bindgen::JsCast as _;
    use wasm_bindgen::prelude::*;

    thread_local! {
        /// A file the user picked: (name, text), or why it could not be read.
        static INBOX: RefCell<Option<Result<(String, String), String>>> = const { RefCell::new(None) };
    }

    fn window() -> Option<web_sys::Window> {
        web_sys::window()
    }

    /// Asks the browser for a scene file; its text arrives later in [`take_picked_file`].
    pub fn pick_scene_file() {
        let Some(document) = window().and_then(|w| w.document()) else {
            return;
        };
        let Ok(input) = document.create_element("input") else {
            return;
        };
        let Ok(input) = input.dyn_into::<web_sys::HtmlInputElement>() else {
            return;
        };
        input.set_type("file");
        input.set_accept(".toml,.json");
        let target = input.clone();
        let on_change = Closure::once(move || {
            let Some(file) = target.files().and_then(|files| files.get(0)) else {
                return;
            };
            let name = file.name();
            wasm_bindgen_futures::spawn_local(async move {
                let text = wasm_bindgen_futures::JsFuture::from(file.text()).await;
                let result = text
                    .ok()
                    .and_then(|t| t.as_string())
                    .map(|text| (name.clone(), text))
                    .ok_or_else(|| {
                        crate::i18n::tr_text("file-cannot-read-file", &[("path", &name)])
                    });
                INBOX.with(|inbox| *inbox.borrow_mut() = Some(result));
            });
        });
        input.set_onchange(Some(on_change.as_ref().unchecked_ref()));
        on_change.forget();
        input.click();
    }

    /// The file picked since the last call, if any.
    pub fn take_picked_file() -> Option<Result<(String, String), String>> {
        INBOX.with(|inbox| inbox.borrow_mut().take())
    }

    /// Offers `text` as a download named `name`.
    ///
    /// # Errors
    /// When the browser refuses (no document, no object URLs).
    pub fn download(name: &str, text: &str, mime: &str) -> Result<(), String> {
        download_bytes(name, text.as_bytes(), mime)
    }

    /// Offers `bytes` as a download named `name`.
    ///
    /// # Errors
    /// When the browser refuses.
    pub fn download_bytes(name: &str, bytes: &[u8], mime: &str) -> Result<(), String> {
        let fail = |_| crate::i18n::tr_text("file-cannot-download", &[("path", name)]);
        let document = window().and_then(|w| w.document()).ok_or("no document")?;
        let parts = js_sys::Array::of1(&js_sys::Uint8Array::from(bytes));
        let options = web_sys::BlobPropertyBag::new();
        options.set_type(mime);
        let blob = web_sys::Blob::new_with_u8_array_sequence_and_options(&parts, &options)
            .map_err(fail)?;
        let url = web_sys::Url::create_object_url_with_blob(&blob).map_err(fail)?;
        let anchor = document
            .create_element("a")
            .map_err(fail)?
            .dyn_into::<web_sys::HtmlAnchorElement>()
            .map_err(|_| "no anchor".to_owned())?;
        anchor.set_href(&url);
        anchor.set_download(name);
        anchor.click();
        web_sys::Url::revoke_object_url(&url).map_err(fail)?;
        Ok(())
    }

    /// Puts `text` on the clipboard (asynchronously; failures are ignored: the link is
    /// also in the address bar).
    pub fn copy_to_clipboard(text: &str) {
        if let Some(window) = window() {
            let promise = window.navigator().clipboard().write_text(text);
            wasm_bindgen_futures::spawn_local(async move {
                let _ = wasm_bindgen_futures::JsFuture::from(promise).await;
            });
        }
    }

    /// The page's fragment, without `#`.
    pub fn fragment() -> String {
        window()
            .and_then(|w| w.location().hash().ok())
            .unwrap_or_default()
            .trim_start_matches('#')
            .to_owned()
    }

    /// Shows `fragment` in the address bar (without reloading) and returns the full URL.
    pub fn set_fragment(fragment: &str) -> String {
        let Some(window) = window() else {
            return String::new();
        };
        let location = window.location();
        let base = location.href().unwrap_or_default();
        let base = base.split('#').next().unwrap_or_default().to_owned();
        let url = format!("{base}#{fragment}");
        if let Ok(history) = window.history() {
            let _ = history.replace_state_with_url(&JsValue::NULL, "", Some(&url));
        }
        url
    }

    fn storage() -> Option<web_sys::Storage> {
        window().and_then(|w| w.local_storage().ok().flatten())
    }

    /// A value from the browser's local storage.
    pub fn load(key: &str) -> Option<String> {
        storage().and_then(|s| s.get_item(key).ok().flatten())
    }

    /// Keeps a value in the browser's local storage (silently not, if storage is off).
    pub fn store(key: &str, value: &str) {
        if let Some(storage) = storage() {
            let _ = storage.set_item(key, value);
        }
    }
}
