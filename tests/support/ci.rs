//! Missing tools, devices and browsers: skipped with a message, except with
//! `CI=true`, where the test fails. Only std here (see `support`).

/// Whether the environment says `CI=true`.
pub fn on_ci() -> bool {
    std::env::var("CI").is_ok_and(|v| v == "true")
}

/// Something the test needs is missing (`what` says what and how to get
/// it): under `CI=true` the test fails here; otherwise this prints
/// `skipping: WHAT` and the caller returns without checking more.
#[track_caller]
pub fn skip(what: impl std::fmt::Display) {
    if on_ci() {
        panic!("CI=true and {what}");
    }
    eprintln!("skipping: {what}");
}

/// `Ok(v)` as `Some(v)`; `Err(e)` goes through [`skip`] as `WHAT: e`.
#[track_caller]
pub fn or_skip<T, E: std::fmt::Display>(result: Result<T, E>, what: &str) -> Option<T> {
    match result {
        Ok(v) => Some(v),
        Err(e) => {
            skip(format!("{what}: {e}"));
            None
        }
    }
}
