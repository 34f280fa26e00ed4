//! Where the sample meshes of the workspace are: the one place the tests, benchmarks and
//! examples look for them.
//!
//! The meshes (the paper's models and others, `.obj` files) are not part of the repository:
//! they are read from `$BUOYANCY_MESHES` if set, else from `shared/meshes` beside the
//! repository (`<repository>/../shared/meshes`). Everything that uses them also runs on
//! procedural meshes it builds itself, so their absence loses coverage, never correctness;
//! [`meshes_dir`] says so on stderr.

use std::path::PathBuf;

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
