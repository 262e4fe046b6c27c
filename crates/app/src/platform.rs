//! What differs between the desktop and the browser, behind one small seam: reading and
//! writing the user's files. The clock is `web_time::Instant`, which is `std`'s on the
//! desktop and the browser's `performance.now()` on the web.

/// Reads a text file.
///
/// # Errors
/// The operating system's reason, in words.
#[cfg(not(target_arch = "wasm32"))]
pub fn read_text(path: &str) -> Result<String, String> {
    std::fs::read_to_string(path).map_err(|e| format!("cannot read '{path}': {e}"))
}

/// Writes a text file.
///
/// # Errors
/// The operating system's reason, in words.
#[cfg(not(target_arch = "wasm32"))]
pub fn write_text(path: &str, text: &str) -> Result<(), String> {
    std::fs::write(path, text).map_err(|e| format!("cannot write '{path}': {e}"))
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
