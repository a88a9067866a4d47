//! The commit record that makes a set of renames survive SIGKILL.
//!
//! Renames of several files are atomic one by one, not as a group: a
//! process killed between two of them leaves new files beside old ones.
//! So before the first rename, with every temporary whole and the
//! directory locked, the writer records which temporary becomes which
//! output in `.umbrac-commit` (written under a temporary name and renamed,
//! so the record is whole or absent); after the last rename it removes the
//! record. The record's rename is the set's commit point: from then on the
//! new set is what the directory holds, even while some of its files are
//! still temporaries. Whoever next takes the directory's lock
//! ([`complete`]: every write, and [`super::read_set`]) finishes the
//! renames a killed writer left, so no one who takes the lock ever sees a
//! mixed set. A writer killed before the commit point leaves the old set
//! and temporaries that the next write removes.
//!
//! The record is the pairs `TEMP\0DEST\0`: names never hold a NUL (they
//! may hold a line break).

use std::io::Write;
use std::path::Path;

/// The record's name in the output directory: hidden, and never an
/// output's name or a temporary's (`.umbrac-PID-N.tmp`).
pub const RECORD: &str = ".umbrac-commit";

/// Writes the record of the renames `pairs` (temporary, destination; file
/// names in `dir`) and makes it visible in one rename: the commit point.
pub fn commit(dir: &Path, pairs: &[(&Path, &Path)]) -> std::io::Result<()> {
    let mut bytes = Vec::new();
    for (temp, dest) in pairs {
        for p in [temp, dest] {
            let name = p.file_name().ok_or_else(|| std::io::Error::other("a path without a file name"))?;
            bytes.extend_from_slice(name.as_encoded_bytes());
            bytes.push(0);
        }
    }
    let staging = super::TempFile::new_in(dir)?;
    staging.file().write_all(&bytes)?;
    staging.persist(&dir.join(RECORD))
}

/// Removes the record once every rename it lists is done.
pub fn finish(dir: &Path) {
    let _ = std::fs::remove_file(dir.join(RECORD));
}

/// Finishes the renames of a writer killed after its commit point (called
/// with the directory's lock held): each temporary the record lists that
/// still exists is renamed onto its destination (one that is gone was
/// renamed already), then the record is removed. Returns how many renames
/// were finished, `None` when there was no record.
pub fn complete(dir: &Path) -> std::io::Result<Option<usize>> {
    let record = dir.join(RECORD);
    let bytes = match std::fs::read(&record) {
        Ok(b) => b,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
        Err(e) => return Err(e),
    };
    let names: Vec<&[u8]> = bytes.split(|&b| b == 0).collect();
    let mut finished = 0;
    // The last piece is what follows the final NUL: empty in a whole record.
    for pair in names[..names.len() - 1].chunks_exact(2) {
        let (temp, dest) = (name_of(pair[0])?, name_of(pair[1])?);
        let (temp, dest) = (dir.join(temp), dir.join(dest));
        match std::fs::rename(&temp, &dest) {
            Ok(()) => finished += 1,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {}
            Err(e) => return Err(e),
        }
    }
    std::fs::remove_file(&record)?;
    Ok(Some(finished))
}

/// A file name from the record; anything that could leave the directory
/// is refused (the record is ours, but it is read from disk).
fn name_of(bytes: &[u8]) -> std::io::Result<&std::ffi::OsStr> {
    let s = std::str::from_utf8(bytes).map_err(|_| std::io::Error::other("a commit record name is not UTF-8"))?;
    if s.is_empty() || s == "." || s == ".." || s.contains(['/', '\\']) {
        return Err(std::io::Error::other("a commit record names a path outside its directory"));
    }
    Ok(std::ffi::OsStr::new(s))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_record_left_by_a_kill_is_finished_and_removed() {
        let d = tempfile::tempdir().unwrap();
        let dir = d.path();
        // Killed after renaming the first of two: a.wgsl is new, b.spv old.
        std::fs::write(dir.join("a.wgsl"), "new a").unwrap();
        std::fs::write(dir.join("b.spv"), "old b").unwrap();
        std::fs::write(dir.join(".umbrac-1-000001.tmp"), "new b").unwrap();
        let (ta, tb) = (dir.join(".umbrac-1-000000.tmp"), dir.join(".umbrac-1-000001.tmp"));
        let (da, db) = (dir.join("a.wgsl"), dir.join("b.spv"));
        commit(dir, &[(ta.as_path(), da.as_path()), (tb.as_path(), db.as_path())]).unwrap();
        assert_eq!(complete(dir).unwrap(), Some(1));
        assert_eq!(std::fs::read_to_string(&da).unwrap(), "new a");
        assert_eq!(std::fs::read_to_string(&db).unwrap(), "new b");
        let mut left: Vec<_> = std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().into_string().unwrap()).collect();
        left.sort();
        assert_eq!(left, ["a.wgsl", "b.spv"]);
        assert_eq!(complete(dir).unwrap(), None, "nothing left to finish");
    }

    #[test]
    fn a_record_naming_a_path_outside_its_directory_is_refused() {
        let d = tempfile::tempdir().unwrap();
        std::fs::write(d.path().join(RECORD), b"../x\0a.wgsl\0").unwrap();
        assert!(complete(d.path()).is_err());
        assert!(d.path().join(RECORD).exists(), "kept for a person to look at");
    }
}
