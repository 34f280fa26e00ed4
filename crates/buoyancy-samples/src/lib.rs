//! Where the sample meshes of the workspace are: the one place the tests, benchmarks and
//! examples look for them.
//!
//! The meshes (the paper's models and others, `.obj` files) are not part of the repository:
//! they are read from `$BUOYANCY_MESHES` if set, else from `shared/meshes` beside the
//! repository (`<repository>/../shared/meshes`). Everything that uses them also runs on
//! procedural meshes it builds itself, so their absence loses coverage, never correctness;
//! [`meshes_dir`] says so on stderr. The tests and benchmarks look them up with
//! [`mesh_or_fallback`], which says so too, and fails when the environment variable `CI` is
//! `true`: a CI run must test the sample meshes, not pass without them.

use std::io::Write;
use std::path::{Path, PathBuf};

/// The environment variable that names the folder of the sample meshes.
pub const MESHES_VARIABLE: &str = "BUOYANCY_MESHES";

/// The folder the sample meshes are looked for in: `$BUOYANCY_MESHES`, else
/// `<repository>/../shared/meshes`.
pub fn meshes_location() -> PathBuf {
    std::env::var_os(MESHES_VARIABLE)
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../../shared/meshes"))
}

/// The folder of the sample meshes, or `None` (saying where it looked, on stderr) when it does
/// not exist.
pub fn meshes_dir() -> Option<PathBuf> {
    let dir = meshes_location();
    if dir.is_dir() {
        Some(dir)
    } else {
        eprintln!(
            "note: sample meshes not found at {} (set {MESHES_VARIABLE}); using procedural meshes only",
            dir.display()
        );
        None
    }
}

/// The path of the sample mesh `name` (e.g. `bunny.obj`), if the folder and the file exist.
pub fn mesh_path(name: &str) -> Option<PathBuf> {
    let path = meshes_dir()?.join(name);
    if path.is_file() {
        Some(path)
    } else {
        eprintln!("note: sample mesh {} not found", path.display());
        None
    }
}

/// For a test or benchmark that falls back to `fallback` (e.g. "the procedural torus knot")
/// when the sample meshes are absent: the path of the sample mesh `name` (of their folder when
/// `name` is `None`), or `None` when it does not exist, after saying on stderr what is missing,
/// the folder it was looked for in and how to set `$BUOYANCY_MESHES`.
///
/// When the environment variable `CI` is `true`, a missing mesh panics with that message
/// instead: a CI run must test the sample meshes, not pass without them.
///
/// When the mesh exists, this returns what [`mesh_path`] (for `None`, [`meshes_dir`]) returns
/// and prints nothing. The message goes to the process's stderr directly rather than through
/// `eprintln!`, which the test harness captures and shows only for failing tests.
#[track_caller]
pub fn mesh_or_fallback(name: Option<&str>, fallback: &str) -> Option<PathBuf> {
    let ci = std::env::var_os("CI").is_some_and(|v| v == "true");
    let named_by_variable = std::env::var_os(MESHES_VARIABLE).is_some();
    let found = find(&meshes_location(), name, named_by_variable);
    report_missing(found, fallback, ci, &mut std::io::stderr())
}

/// The sample mesh `name` (the folder when `None`) in `dir`, or what [`mesh_or_fallback`] says
/// when it does not exist (`named_by_variable`: whether `dir` is `$BUOYANCY_MESHES`).
fn find(dir: &Path, name: Option<&str>, named_by_variable: bool) -> Result<PathBuf, String> {
    let missing = match name {
        Some(name) if dir.join(name).is_file() => return Ok(dir.join(name)),
        None if dir.is_dir() => return Ok(dir.to_path_buf()),
        Some(name) => format!("sample mesh {name} not found in {}", dir.display()),
        None => format!("the sample meshes' folder {} not found", dir.display()),
    };
    let whence = if named_by_variable {
        format!("the folder ${MESHES_VARIABLE} names")
    } else {
        format!(
            "shared/meshes beside the repository, where they are looked for when {MESHES_VARIABLE} is not set"
        )
    };
    Err(format!(
        "{missing} ({whence}); set {MESHES_VARIABLE} to the folder of the sample meshes to test them"
    ))
}

/// What [`mesh_or_fallback`] does with the result of [`find`]: the path, or `None` after
/// writing the message to `out`, or (`ci`) a panic with it.
#[track_caller]
fn report_missing(
    found: Result<PathBuf, String>,
    fallback: &str,
    ci: bool,
    out: &mut dyn Write,
) -> Option<PathBuf> {
    match found {
        Ok(path) => Some(path),
        Err(message) if ci => {
            panic!("{message}. CI is true, so this run fails rather than fall back to {fallback}")
        }
        Err(message) => {
            // A failed write to stderr leaves nowhere better to report it.
            let _ = writeln!(
                out,
                "note: {message}. Falling back to {fallback} (under CI=true this fails)"
            );
            None
        }
    }
}

/// The `.obj` files of the sample folder, sorted by name; empty when it does not exist.
pub fn obj_files() -> Vec<PathBuf> {
    let Some(dir) = meshes_dir() else {
        return Vec::new();
    };
    let mut paths: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("cannot list {}: {e}", dir.display()))
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "obj"))
        .collect();
    paths.sort();
    paths
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A new empty folder under the system's temporary folder.
    fn empty_folder(tag: &str) -> PathBuf {
        let dir =
            std::env::temp_dir().join(format!("buoyancy-samples-{tag}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    #[test]
    fn a_present_mesh_or_folder_is_found() {
        let dir = empty_folder("present");
        std::fs::write(dir.join("cube.obj"), "").unwrap();
        assert_eq!(find(&dir, None, true), Ok(dir.clone()));
        assert_eq!(find(&dir, Some("cube.obj"), true), Ok(dir.join("cube.obj")));
        assert_eq!(
            report_missing(Ok(dir.join("cube.obj")), "a cube", true, &mut Vec::new()),
            Some(dir.join("cube.obj"))
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_missing_mesh_or_folder_names_where_it_was_looked_for() {
        let dir = empty_folder("missing");
        let message = find(&dir, Some("bunny.obj"), true).unwrap_err();
        assert_eq!(
            message,
            format!(
                "sample mesh bunny.obj not found in {} (the folder $BUOYANCY_MESHES names); set \
                 BUOYANCY_MESHES to the folder of the sample meshes to test them",
                dir.display()
            )
        );
        let gone = dir.join("gone");
        let message = find(&gone, None, false).unwrap_err();
        assert!(
            message.starts_with(&format!(
                "the sample meshes' folder {} not found (shared/meshes beside the repository, \
                 where they are looked for when BUOYANCY_MESHES is not set); set BUOYANCY_MESHES",
                gone.display()
            )),
            "{message}"
        );
        // Outside CI, the caller falls back, and is told so.
        let mut out = Vec::new();
        assert_eq!(
            report_missing(Err(message.clone()), "a cube", false, &mut out),
            None
        );
        assert_eq!(
            String::from_utf8(out).unwrap(),
            format!("note: {message}. Falling back to a cube (under CI=true this fails)\n")
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    #[should_panic(
        expected = "bunny.obj not found in /nowhere (the folder $BUOYANCY_MESHES names); set \
                    BUOYANCY_MESHES to the folder of the sample meshes to test them. CI is \
                    true, so this run fails rather than fall back to a cube"
    )]
    fn a_missing_mesh_fails_under_ci() {
        report_missing(
            find(Path::new("/nowhere"), Some("bunny.obj"), true),
            "a cube",
            true,
            &mut Vec::new(),
        );
    }

    #[test]
    fn the_default_location_is_beside_the_repository() {
        if std::env::var_os(MESHES_VARIABLE).is_some() {
            return;
        }
        // `<repository>/../shared/meshes`: the folder above the repository exists, whether or
        // not the meshes do.
        let repository = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..");
        assert!(repository.join("Cargo.toml").is_file());
        let location = meshes_location();
        assert_eq!(location.file_name().unwrap(), "meshes");
        let shared = location.parent().unwrap();
        assert_eq!(shared.file_name().unwrap(), "shared");
        assert_eq!(
            shared.parent().unwrap().canonicalize().unwrap(),
            repository.join("..").canonicalize().unwrap()
        );
    }
}
