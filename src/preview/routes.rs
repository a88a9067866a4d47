//! What the preview server answers to a request line: a pure function of
//! the method, the URL and the `Host` header, so that what it serves is
//! checked without a socket.

/// The page's files, built into the binary: the only files served.
const ASSETS: &[(&str, &str, &str)] = &[
    ("index.html", "text/html; charset=utf-8", include_str!("../../web/preview/index.html")),
    ("preview.js", "text/javascript; charset=utf-8", include_str!("../../web/preview/preview.js")),
    ("draw.js", "text/javascript; charset=utf-8", include_str!("../../web/preview/draw.js")),
    ("controls.js", "text/javascript; charset=utf-8", include_str!("../../web/preview/controls.js")),
    ("scene.js", "text/javascript; charset=utf-8", include_str!("../../web/preview/scene.js")),
    ("passes.js", "text/javascript; charset=utf-8", include_str!("../../web/preview/passes.js")),
    ("textures.js", "text/javascript; charset=utf-8", include_str!("../../web/preview/textures.js")),
    ("preview.css", "text/css; charset=utf-8", include_str!("../../web/preview/preview.css")),
];

/// What a request gets.
#[derive(Debug, PartialEq, Eq)]
pub enum Route {
    /// One of the page's files, by name.
    Static(&'static str),
    /// The latest bundle, as JSON.
    Bundle,
    /// The Server-Sent Events stream of bundles.
    Events,
    /// A file of the built playground, by its name in [`super::playground::FILES`].
    Playground(&'static str),
    /// `/playground/live.json`: the page is under a preview server.
    Live,
    /// `/scene/NAME`: an image file the scene file names (checked by
    /// [`super::SceneFile::image`] against the scene and its directory).
    SceneImage(String),
    /// `/playground` without its slash: the page's relative URLs need it.
    Redirect(&'static str),
    /// An error status and why.
    Refused(u16, &'static str),
}

/// Answers `url` (path and query, as the request line has it). `host` is
/// the `Host` header: a page of another site that a DNS name of its own
/// points at 127.0.0.1 (DNS rebinding) sends its own name there, and is
/// refused.
pub fn route(get: bool, url: &str, host: Option<&str>, port: u16) -> Route {
    let ours = [format!("127.0.0.1:{port}"), format!("localhost:{port}")];
    if !host.is_some_and(|h| ours.iter().any(|o| o.eq_ignore_ascii_case(h))) {
        return Route::Refused(403, "only requests to this server's loopback address are answered");
    }
    if !get {
        return Route::Refused(405, "only GET and HEAD are answered");
    }
    let path = url.split(['?', '#']).next().unwrap_or("");
    // No name served has a dot-dot, a backslash or an escape: such a
    // path is a try at another file (`/../`, `%2e%2e`, `..%2f`).
    if path.contains("..") || path.contains('\\') || path.contains('%') || !path.starts_with('/') {
        return Route::Refused(403, "not a name this server serves");
    }
    match path {
        "/" => Route::Static("index.html"),
        "/bundle.json" => Route::Bundle,
        "/events" => Route::Events,
        "/playground" => Route::Redirect("/playground/"),
        "/playground/" => Route::Playground("index.html"),
        "/playground/live.json" => Route::Live,
        _ if path.starts_with("/scene/") && path.len() > "/scene/".len() => Route::SceneImage(path["/scene/".len()..].to_string()),
        _ if path.starts_with("/playground/") => match super::playground::FILES.iter().find(|(name, _)| path["/playground/".len()..] == **name) {
            Some((name, _)) => Route::Playground(name),
            None => Route::Refused(404, "not found"),
        },
        _ => match ASSETS.iter().find(|(name, _, _)| path[1..] == **name) {
            Some((name, _, _)) => Route::Static(name),
            None => Route::Refused(404, "not found"),
        },
    }
}

/// A page file's content type and bytes. With `UMBRAC_PREVIEW_WEB=DIR`
/// (working on the page) the same names are read from DIR instead, so a
/// reload shows an edit without a rebuild; still only those names.
pub fn asset(name: &str) -> Option<(&'static str, Vec<u8>)> {
    let (name, kind, text) = ASSETS.iter().find(|(n, _, _)| *n == name)?;
    if let Some(dir) = std::env::var_os("UMBRAC_PREVIEW_WEB") {
        return std::fs::read(std::path::Path::new(&dir).join(name)).ok().map(|b| (*kind, b));
    }
    Some((*kind, text.as_bytes().to_vec()))
}

#[cfg(test)]
mod tests {
    use super::*;

    const H: Option<&str> = Some("127.0.0.1:8000");

    #[test]
    fn the_page_the_bundle_and_the_stream_are_served() {
        assert_eq!(route(true, "/", H, 8000), Route::Static("index.html"));
        assert_eq!(route(true, "/draw.js?v=2", H, 8000), Route::Static("draw.js"));
        assert_eq!(route(true, "/bundle.json", H, 8000), Route::Bundle);
        assert_eq!(route(true, "/events", Some("localhost:8000"), 8000), Route::Events);
        assert_eq!(route(true, "/playground/", H, 8000), Route::Playground("index.html"));
        assert_eq!(route(true, "/playground/umbrac_web_bg.wasm", H, 8000), Route::Playground("umbrac_web_bg.wasm"));
        assert_eq!(route(true, "/playground/live.json?x", H, 8000), Route::Live);
        assert_eq!(route(true, "/playground", H, 8000), Route::Redirect("/playground/"));
        assert_eq!(route(true, "/scene/brick.png?x", H, 8000), Route::SceneImage("brick.png".into()));
        assert_eq!(route(true, "/scene/maps/brick.png", H, 8000), Route::SceneImage("maps/brick.png".into()));
        for (name, _, _) in ASSETS {
            assert!(asset(name).is_some_and(|(_, b)| !b.is_empty()), "{name}");
        }
    }

    #[test]
    fn nothing_else_is() {
        for url in ["/../Cargo.toml", "/%2e%2e/Cargo.toml", "/..%2fCargo.toml", "/draw.js/../../x", "//etc/passwd", "/etc/passwd", "/web/preview/draw.js", "\\..\\x", "http://evil/", "/index.html%00", "/playground/../Cargo.toml", "/playground/umbrac_web.js", "/playground/pkg/umbrac_web.js", "/playground//etc/passwd", "/playground/index.html/", "/playground/draw.js", "/main.js", "/scene/", "/scene/../Cargo.toml", "/scene/%2e%2e/x.png", "/scene/..%2fx.png", "/scene/a\\..\\b.png"] {
            assert!(matches!(route(true, url, H, 8000), Route::Refused(403 | 404, _)), "{url}");
        }
        assert!(matches!(route(false, "/", H, 8000), Route::Refused(405, _)));
    }

    #[test]
    fn other_hosts_are_refused() {
        for host in [None, Some("evil.example:8000"), Some("127.0.0.1:8001"), Some("0.0.0.0:8000")] {
            assert!(matches!(route(true, "/", host, 8000), Route::Refused(403, _)), "{host:?}");
        }
    }
}
