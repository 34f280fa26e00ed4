//! Stanford PLY, ASCII and binary (little and big endian), read with the `ply-rs-bw` crate.

use alloc::format;
use alloc::string::{String, ToString};
use alloc::vec::Vec;

use nalgebra::Point3;
use ply_rs_bw::parser::{ParseError, Parser, Reader};
use ply_rs_bw::ply::{
    BeginList, Encoding, Header, Property, PropertyAccess, PropertyAccessResult, PropertyType,
    ScalarType,
};

use super::parse_error;
use crate::mesh::primitives::Shape;
use crate::{Error, Real};

/// The names of a face's list of vertex indices.
const INDEX_LISTS: [&str; 2] = ["vertex_indices", "vertex_index"];

/// The names of a vertex's coordinates.
const AXES: [&str; 3] = ["x", "y", "z"];

/// Parses a PLY file, ASCII or binary (little or big endian): the `x`, `y` and `z` properties
/// of the `vertex` element (`float` or `double`, or any other number type) and the
/// `vertex_indices` (or `vertex_index`) integer list of the `face` element, polygons fanned
/// into triangles (`[a, b, c, d]` gives `[a, b, c]` and `[a, c, d]`). Other properties and
/// elements (normals, colours, texture coordinates, edges, …) are read past and ignored. PLY
/// indices count from 0, as [`Mesh::new`](crate::Mesh::new)'s do.
///
/// ```
/// let text = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n\
///             property float z\nelement face 4\nproperty list uchar int vertex_indices\n\
///             end_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
/// let (vertices, triangles) = buoyancy_core::io::parse_ply::<f64>(text.as_bytes())?;
/// assert_eq!((vertices.len(), triangles.len()), (4, 4));
/// assert_eq!(triangles[0], [0, 2, 1]);
/// # Ok::<(), buoyancy_core::Error>(())
/// ```
///
/// # Errors
/// [`Error::Parse`] naming what is wrong: a header that is not PLY or lacks the vertex
/// coordinates or the face list (the message lists what the header has instead), data that
/// ends early or does not match the header, a face with fewer than three vertices or an index
/// that is negative or not below the vertex count, a file with no face. The line is given for
/// the header and ASCII data, 0 for binary data.
pub fn parse_ply<T: Real>(bytes: &[u8]) -> Result<Shape<T>, Error> {
    let mut reader = Reader::new(bytes);
    let header = Parser::<Skipped>::new()
        .read_header(&mut reader)
        .map_err(|e| crate_error("PLY header", &e, true))?;
    check_header(&header)?;
    let ascii = header.encoding == Encoding::Ascii;
    let mut points: Vec<PlyVertex> = Vec::new();
    let mut faces: Vec<PlyFace> = Vec::new();
    let mut first_face_line = 0;
    for element in header.elements.values() {
        let context = format!("PLY element `{}`", element.name);
        let failed = |e: ParseError| crate_error(&context, &e, ascii);
        match element.name.as_str() {
            "vertex" => {
                points = Parser::new()
                    .read_payload_for_element(&mut reader, element, &header)
                    .map_err(failed)?;
            }
            "face" => {
                first_face_line = reader.line().max(1);
                faces = Parser::new()
                    .read_payload_for_element(&mut reader, element, &header)
                    .map_err(failed)?;
            }
            _ => {
                Parser::<Skipped>::new()
                    .read_payload_for_element(&mut reader, element, &header)
                    .map_err(failed)?;
            }
        }
    }
    let mut triangles = Vec::with_capacity(faces.len());
    for (number, face) in faces.iter().enumerate() {
        let line = if ascii { first_face_line + number } else { 0 };
        let corners = &face.corners;
        if let Some(index) = face.negative {
            return Err(parse_error(
                line,
                format!("PLY face {number} has the negative vertex index {index}"),
            ));
        }
        if let Some(&index) = corners.iter().find(|&&i| i as usize >= points.len()) {
            return Err(parse_error(
                line,
                format!(
                    "PLY face {number} refers to vertex {index}, but the file has {} vertices \
                     (PLY indices count from 0)",
                    points.len()
                ),
            ));
        }
        if corners.len() < 3 {
            return Err(parse_error(
                line,
                format!(
                    "PLY face {number} has {} vertices; a face needs at least three",
                    corners.len()
                ),
            ));
        }
        for k in 1..corners.len() - 1 {
            triangles.push([corners[0], corners[k], corners[k + 1]]);
        }
    }
    if triangles.is_empty() {
        return Err(parse_error(0, "the PLY file has no faces".into()));
    }
    let vertices = points
        .iter()
        .map(|p| Point3::from(p.xyz.map(T::from_f64_lossy)))
        .collect();
    Ok((vertices, triangles))
}

/// Checks that the header declares the vertex coordinates and the faces' index lists, naming
/// what it has instead when it does not.
fn check_header(header: &Header) -> Result<(), Error> {
    let header_error = |message: String| parse_error(0, format!("PLY header: {message}"));
    let listed = |names: Vec<&String>| match names.is_empty() {
        true => String::from("none"),
        false => names
            .iter()
            .map(|n| format!("`{n}`"))
            .collect::<Vec<_>>()
            .join(", "),
    };
    let elements = || listed(header.elements.keys().collect());
    let vertex = header.elements.get("vertex").ok_or_else(|| {
        header_error(format!(
            "no `element vertex` (the elements declared: {})",
            elements()
        ))
    })?;
    for axis in AXES {
        match vertex.properties.get(axis).map(|p| &p.data_type) {
            None => {
                return Err(header_error(format!(
                    "the vertex element has no `{axis}` property (its properties: {})",
                    listed(vertex.properties.keys().collect())
                )));
            }
            Some(PropertyType::List(..)) => {
                return Err(header_error(format!(
                    "vertex property `{axis}` is a list; a coordinate is one number, e.g. \
                     `property float {axis}`"
                )));
            }
            Some(PropertyType::Scalar(_)) => {}
        }
    }
    let face = header.elements.get("face").ok_or_else(|| {
        header_error(format!(
            "no `element face`, so no surface: the file holds points only (the elements \
             declared: {})",
            elements()
        ))
    })?;
    let Some(list) = INDEX_LISTS.iter().find_map(|n| face.properties.get(*n)) else {
        return Err(header_error(format!(
            "the face element has no `vertex_indices` (or `vertex_index`) list (its properties: \
             {})",
            listed(face.properties.keys().collect())
        )));
    };
    match &list.data_type {
        PropertyType::List(_, item @ (ScalarType::Float | ScalarType::Double)) => {
            Err(header_error(format!(
                "face property `{}` is a list of {}; vertex indices are integers, e.g. \
                 `property list uchar int {}`",
                list.name,
                scalar_name(item),
                list.name
            )))
        }
        PropertyType::Scalar(_) => Err(header_error(format!(
            "face property `{}` is one number; it must be a list of vertex indices, e.g. \
             `property list uchar int {}`",
            list.name, list.name
        ))),
        PropertyType::List(..) => Ok(()),
    }
}

/// A PLY scalar type as the header spells it.
fn scalar_name(scalar: &ScalarType) -> &'static str {
    match scalar {
        ScalarType::Char => "char",
        ScalarType::UChar => "uchar",
        ScalarType::Short => "short",
        ScalarType::UShort => "ushort",
        ScalarType::Int => "int",
        ScalarType::UInt => "uint",
        ScalarType::Float => "float",
        ScalarType::Double => "double",
    }
}

/// An [`Error::Parse`] from an error of the PLY reader, on one line: its summary, the text it
/// could not read and its reason (a grammar's internal state left out). Lines are kept where
/// they mean something: in the header and in ASCII data.
fn crate_error(context: &str, error: &ParseError, has_lines: bool) -> Error {
    let line = error.line().filter(|_| has_lines).unwrap_or(0);
    let text = error.to_string();
    let text = error
        .line()
        .and_then(|n| text.strip_prefix(&format!("Line {n}: ")))
        .unwrap_or(&text);
    let mut parts = text.split("\n\t");
    let summary = parts.next().unwrap_or("").trim().trim_end_matches('.');
    let mut message = format!("{context}: {summary}");
    for part in parts {
        if let Some(read) = part.strip_prefix("String: ") {
            let read = read.trim().trim_matches('\'').trim();
            message += &format!(" (read: `{read}`)");
        } else if let Some(reason) = part.strip_prefix("Error: ")
            && !reason.starts_with("ParseError {")
        {
            message += &format!(": {}", reason.trim().trim_end_matches('.'));
        }
    }
    parse_error(line, message)
}

/// A vertex's coordinates, in the order x, y, z.
#[derive(Default)]
struct PlyVertex {
    xyz: [f64; 3],
}

impl PlyVertex {
    fn set(&mut self, name: &str, value: f64) -> PropertyAccessResult {
        match AXES.iter().position(|&axis| axis == name) {
            Some(axis) => {
                self.xyz[axis] = value;
                PropertyAccessResult::Set
            }
            None => PropertyAccessResult::Ignored,
        }
    }
}

impl PropertyAccess for PlyVertex {
    fn new() -> Self {
        Self::default()
    }

    fn set_float(&mut self, name: &str, value: f32) -> PropertyAccessResult {
        self.set(name, f64::from(value))
    }

    fn set_double(&mut self, name: &str, value: f64) -> PropertyAccessResult {
        self.set(name, value)
    }

    /// Coordinates of an integer type (lists are ignored: the header check rejects them).
    fn set_property(&mut self, name: &str, property: Property) -> PropertyAccessResult {
        let value = match property {
            Property::Char(v) => f64::from(v),
            Property::UChar(v) => f64::from(v),
            Property::Short(v) => f64::from(v),
            Property::UShort(v) => f64::from(v),
            Property::Int(v) => f64::from(v),
            Property::UInt(v) => f64::from(v),
            Property::Float(v) => f64::from(v),
            Property::Double(v) => v,
            _ => return PropertyAccessResult::Ignored,
        };
        self.set(name, value)
    }
}

/// A face's vertex indices, and the first negative one, if any (reported after reading).
#[derive(Default)]
struct PlyFace {
    corners: Vec<u32>,
    negative: Option<i64>,
}

impl PropertyAccess for PlyFace {
    fn new() -> Self {
        Self::default()
    }

    fn begin_list_uint(&mut self, name: &str, _len: usize) -> BeginList<'_, u32> {
        if INDEX_LISTS.contains(&name) {
            BeginList::Fill(&mut self.corners)
        } else {
            BeginList::UseSetter
        }
    }

    /// Index lists of the other integer types.
    fn set_property(&mut self, name: &str, property: Property) -> PropertyAccessResult {
        if !INDEX_LISTS.contains(&name) {
            return PropertyAccessResult::Ignored;
        }
        let indices: Vec<i64> = match property {
            Property::ListChar(v) => v.into_iter().map(i64::from).collect(),
            Property::ListUChar(v) => v.into_iter().map(i64::from).collect(),
            Property::ListShort(v) => v.into_iter().map(i64::from).collect(),
            Property::ListUShort(v) => v.into_iter().map(i64::from).collect(),
            Property::ListInt(v) => v.into_iter().map(i64::from).collect(),
            Property::ListUInt(v) => v.into_iter().map(i64::from).collect(),
            _ => return PropertyAccessResult::UnsupportedType,
        };
        self.negative = indices.iter().copied().find(|&i| i < 0);
        self.corners = indices.iter().map(|&i| i.max(0) as u32).collect();
        PropertyAccessResult::Set
    }
}

/// An element whose properties are all read past.
struct Skipped;

impl PropertyAccess for Skipped {
    fn new() -> Self {
        Skipped
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Mesh, mesh::primitives};
    use alloc::vec;
    use std::path::PathBuf;

    /// How the data after the header is stored.
    #[derive(Clone, Copy, Debug)]
    enum Storage {
        Ascii,
        Little,
        Big,
    }

    /// A PLY file of a unit cube made of six quads, with `double` coordinates, a colour per
    /// vertex, a `uint` index list and a trailing `edge` element, all to be read or read past.
    fn cube_ply(storage: Storage) -> Vec<u8> {
        let (v, t) = primitives::cube::<f64>(1).unwrap();
        // The cube's triangles come in pairs sharing a diagonal: [a, b, c], [a, c, d].
        let quads: Vec<[u32; 4]> = t
            .chunks_exact(2)
            .map(|pair| {
                assert_eq!((pair[0][0], pair[0][2]), (pair[1][0], pair[1][1]));
                [pair[0][0], pair[0][1], pair[0][2], pair[1][2]]
            })
            .collect();
        let format = match storage {
            Storage::Ascii => "ascii",
            Storage::Little => "binary_little_endian",
            Storage::Big => "binary_big_endian",
        };
        let mut out = format!(
            "ply\nformat {format} 1.0\ncomment made by a test\nelement vertex {}\n\
             property double x\nproperty double y\nproperty double z\nproperty uchar red\n\
             element face {}\nproperty list uchar uint vertex_indices\n\
             element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n",
            v.len(),
            quads.len()
        )
        .into_bytes();
        let push_f64 = |out: &mut Vec<u8>, x: f64| match storage {
            Storage::Ascii => out.extend(format!("{x} ").bytes()),
            Storage::Little => out.extend(x.to_le_bytes()),
            Storage::Big => out.extend(x.to_be_bytes()),
        };
        for p in &v {
            p.iter().for_each(|&c| push_f64(&mut out, c));
            match storage {
                Storage::Ascii => out.extend(b"200\n"),
                _ => out.push(200),
            }
        }
        let push_u32 = |out: &mut Vec<u8>, i: u32| match storage {
            Storage::Ascii => out.extend(format!(" {i}").bytes()),
            Storage::Little => out.extend(i.to_le_bytes()),
            Storage::Big => out.extend(i.to_be_bytes()),
        };
        for quad in &quads {
            match storage {
                Storage::Ascii => out.push(b'4'),
                _ => out.push(4),
            }
            quad.iter().for_each(|&i| push_u32(&mut out, i));
            if let Storage::Ascii = storage {
                out.push(b'\n');
            }
        }
        match storage {
            Storage::Ascii => out.extend(b"0 1\n"),
            Storage::Little => [0i32, 1].iter().for_each(|i| out.extend(i.to_le_bytes())),
            Storage::Big => [0i32, 1].iter().for_each(|i| out.extend(i.to_be_bytes())),
        }
        out
    }

    /// A directory of its own under the system's temporary directory, removed on drop.
    struct TempDir(PathBuf);

    impl TempDir {
        fn new(name: &str) -> Self {
            let dir =
                std::env::temp_dir().join(format!("buoyancy-core-{name}-{}", std::process::id()));
            std::fs::create_dir_all(&dir).unwrap();
            TempDir(dir)
        }

        fn write(&self, file: &str, bytes: &[u8]) -> PathBuf {
            let path = self.0.join(file);
            std::fs::write(&path, bytes).unwrap();
            path
        }
    }

    impl Drop for TempDir {
        fn drop(&mut self) {
            let _ = std::fs::remove_dir_all(&self.0);
        }
    }

    #[test]
    fn ascii_and_binary_files_load_alike() {
        let dir = TempDir::new("ply-storage");
        let (v, t) = primitives::cube::<f64>(1).unwrap();
        for (storage, file) in [
            (Storage::Ascii, "cube.ply"),
            (Storage::Little, "cube-le.PLY"),
            (Storage::Big, "cube-be.ply"),
        ] {
            let path = dir.write(file, &cube_ply(storage));
            let (pv, pt) = crate::io::load::<f64>(&path).unwrap();
            assert_eq!(pv, v, "{storage:?}");
            // Each quad fanned into the cube's own two triangles.
            assert_eq!(pt, t, "{storage:?}");
            let mesh = Mesh::new(pv, pt).unwrap();
            assert!((mesh.volume() - 1.0).abs() < 1e-15, "{storage:?}");
            let (fv, _) = crate::io::load::<f32>(&path).unwrap();
            assert_eq!(fv[3], v[3].map(|c| c as f32), "{storage:?}");
        }
    }

    #[test]
    fn float_and_integer_coordinates_and_index_types_are_read() {
        let header = "ply\nformat binary_big_endian 1.0\nelement vertex 4\nproperty float x\n\
                      property short y\nproperty uchar z\nelement face 4\n\
                      property list uchar ushort vertex_index\nend_header\n";
        let mut bytes = header.as_bytes().to_vec();
        for [x, y, z] in [
            [0.5f32, 0.0, 0.0],
            [1.5, 0.0, 0.0],
            [0.5, 1.0, 0.0],
            [0.5, 0.0, 1.0],
        ] {
            bytes.extend(x.to_be_bytes());
            bytes.extend((y as i16).to_be_bytes());
            bytes.push(z as u8);
        }
        for face in [[0u16, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]] {
            bytes.push(3);
            face.iter().for_each(|i| bytes.extend(i.to_be_bytes()));
        }
        let (v, t) = parse_ply::<f64>(&bytes).unwrap();
        assert_eq!(v[1], Point3::new(1.5, 0.0, 0.0));
        assert_eq!(v[3], Point3::new(0.5, 0.0, 1.0));
        assert_eq!(t, vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]);
        assert!((Mesh::new(v, t).unwrap().volume() - 1.0 / 6.0).abs() < 1e-15);
    }

    /// The message of the parse error `text` gives, and its line.
    fn parse_failure(text: &str) -> (usize, String) {
        match parse_ply::<f64>(text.as_bytes()) {
            Err(Error::Parse { line, message }) => (line, message),
            other => panic!("expected a parse error for {text:?}, got {other:?}"),
        }
    }

    /// A tetrahedron's vertices, lines 10 to 13 of the files `with_header` makes.
    const VERTEX_LINES: &str = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
    /// Its faces, lines 14 to 17.
    const FACE_LINES: &str = "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

    /// A tetrahedron's ASCII PLY with the `vertex` and `face` declarations given.
    fn with_header(vertex: &str, face: &str) -> String {
        format!("ply\nformat ascii 1.0\n{vertex}{face}end_header\n{VERTEX_LINES}{FACE_LINES}")
    }

    const VERTEX: &str = "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n";
    const FACE: &str = "element face 4\nproperty list uchar int vertex_indices\n";

    #[test]
    fn a_bad_header_is_named() {
        assert!(parse_ply::<f64>(with_header(VERTEX, FACE).as_bytes()).is_ok());
        let cases: [(String, &str); 9] = [
            (
                "solid cube\n".into(),
                "PLY header: Expected magic number 'ply'",
            ),
            (
                "ply\nelement vertex 0\nend_header\n".into(),
                "PLY header: No format line found",
            ),
            (
                "ply\nformat ascii 1.0\nelement vertex 4\n".into(),
                "missing 'end_header'",
            ),
            (
                with_header(
                    "element vertex 4\nproperty flt x\nproperty float y\nproperty float z\n",
                    FACE,
                ),
                "(read: `property flt x`)",
            ),
            (
                with_header(
                    "element vertex 4\nproperty float x\nproperty float y\n",
                    FACE,
                ),
                "the vertex element has no `z` property (its properties: `x`, `y`)",
            ),
            (
                with_header(
                    "element vertex 4\nproperty float x\nproperty float y\n\
                     property list uchar float z\n",
                    FACE,
                ),
                "vertex property `z` is a list",
            ),
            (
                with_header(VERTEX, ""),
                "no `element face`, so no surface: the file holds points only (the elements \
                 declared: `vertex`)",
            ),
            (
                with_header(VERTEX, "element face 4\nproperty list uchar int corners\n"),
                "the face element has no `vertex_indices` (or `vertex_index`) list (its \
                 properties: `corners`)",
            ),
            (
                with_header(
                    VERTEX,
                    "element face 4\nproperty list uchar float vertex_indices\n",
                ),
                "face property `vertex_indices` is a list of float; vertex indices are integers",
            ),
        ];
        for (text, expected) in cases {
            let (_, message) = parse_failure(&text);
            assert!(message.contains(expected), "{message:?} lacks {expected:?}");
            assert!(!message.contains('\n'), "{message:?}");
        }
        let (line, message) = parse_failure(&with_header(
            "element vertex 4\nproperty flt x\nproperty float y\nproperty float z\n",
            FACE,
        ));
        assert_eq!(line, 4, "{message}");
        let (_, message) = parse_failure("");
        assert!(message.contains("end of file"), "{message}");
    }

    #[test]
    fn bad_data_is_named() {
        // Face 2 (line 16 of the file) with an index past the four vertices.
        let text = with_header(VERTEX, FACE).replace("3 0 3 2\n", "3 0 3 7\n");
        assert_eq!(
            parse_failure(&text),
            (
                16,
                "PLY face 2 refers to vertex 7, but the file has 4 vertices (PLY indices count \
                 from 0)"
                    .into()
            )
        );
        let text = with_header(VERTEX, FACE).replace("3 0 3 2\n", "3 0 -3 2\n");
        let (line, message) = parse_failure(&text);
        assert_eq!(line, 16);
        assert!(message.contains("negative vertex index -3"), "{message}");
        let text = with_header(VERTEX, FACE).replace("3 0 3 2\n", "2 0 3\n");
        let (_, message) = parse_failure(&text);
        assert!(message.contains("face 2 has 2 vertices"), "{message}");
        let text = with_header(VERTEX, FACE).replace("0 1 0\n", "0 one 0\n");
        let (line, message) = parse_failure(&text);
        assert_eq!(line, 12, "{message}");
        assert!(
            message.starts_with("PLY element `vertex`") && message.contains("`0 one 0`"),
            "{message}"
        );
        let text = with_header(VERTEX, FACE).replace("3 1 2 3\n", "");
        let (_, message) = parse_failure(&text);
        assert!(message.contains("end of file"), "{message}");
        let no_faces = format!(
            "ply\nformat ascii 1.0\n{VERTEX}element face 0\n\
             property list uchar int vertex_indices\nend_header\n{VERTEX_LINES}"
        );
        let (_, message) = parse_failure(&no_faces);
        assert!(message.contains("no faces"), "{message}");
        // Binary data that ends early: no line to name.
        let mut bytes = cube_ply(Storage::Little);
        bytes.truncate(bytes.len() - 30);
        match parse_ply::<f64>(&bytes) {
            Err(Error::Parse { line: 0, message }) => {
                assert!(message.starts_with("PLY element `face`"), "{message}")
            }
            other => panic!("{other:?}"),
        }
    }
}
