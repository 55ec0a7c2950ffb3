//! PLY: a text header declaring elements and their properties, then the data as ASCII (one
//! element per line) or binary (either byte order). The reader keeps `x`, `y`, `z` of `vertex`
//! and the `vertex_indices` (or `vertex_index`) list of `face`, and skips every other property
//! and element by its declared type.

use super::error::corner_problem;
use super::{parse_error, write_xyz, MeshIoError, PlyEncoding, ReadOptions, Soup, TextLines};
use crate::mesh::TriMesh;
use glam::DVec3;
use std::io::{self, BufRead, Read, Write};

#[derive(Clone, Copy, PartialEq)]
enum Encoding {
    Ascii,
    LittleEndian,
    BigEndian,
}

/// A PLY number type. Every one converts to `f64` exactly, so values travel as `f64`.
#[derive(Clone, Copy)]
enum Num {
    I8,
    U8,
    I16,
    U16,
    I32,
    U32,
    F32,
    F64,
}

impl Num {
    fn parse(name: &str) -> Result<Num, String> {
        Ok(match name {
            "char" | "int8" => Num::I8,
            "uchar" | "uint8" => Num::U8,
            "short" | "int16" => Num::I16,
            "ushort" | "uint16" => Num::U16,
            "int" | "int32" => Num::I32,
            "uint" | "uint32" => Num::U32,
            "float" | "float32" => Num::F32,
            "double" | "float64" => Num::F64,
            _ => return Err(format!("unknown PLY type `{name}`")),
        })
    }

    fn size(self) -> usize {
        match self {
            Num::I8 | Num::U8 => 1,
            Num::I16 | Num::U16 => 2,
            Num::I32 | Num::U32 | Num::F32 => 4,
            Num::F64 => 8,
        }
    }

    /// Decodes `self.size()` bytes.
    fn decode(self, bytes: &[u8], big_endian: bool) -> f64 {
        fn le<const N: usize>(bytes: &[u8], big_endian: bool) -> [u8; N] {
            let mut array = [0; N];
            array.copy_from_slice(&bytes[..N]);
            if big_endian {
                array.reverse();
            }
            array
        }
        let b = big_endian;
        match self {
            Num::I8 => f64::from(i8::from_le_bytes(le(bytes, b))),
            Num::U8 => f64::from(bytes[0]),
            Num::I16 => f64::from(i16::from_le_bytes(le(bytes, b))),
            Num::U16 => f64::from(u16::from_le_bytes(le(bytes, b))),
            Num::I32 => f64::from(i32::from_le_bytes(le(bytes, b))),
            Num::U32 => f64::from(u32::from_le_bytes(le(bytes, b))),
            Num::F32 => f64::from(f32::from_le_bytes(le(bytes, b))),
            Num::F64 => f64::from_le_bytes(le(bytes, b)),
        }
    }
}

#[derive(Clone, Copy)]
enum Kind {
    Scalar(Num),
    List { count: Num, item: Num },
}

/// What the reader does with a property's values.
#[derive(Clone, Copy, PartialEq)]
enum Keep {
    Skip,
    Axis(usize),
    Corners,
}

struct Property {
    name: String,
    kind: Kind,
    keep: Keep,
}

#[derive(PartialEq)]
enum Role {
    Vertex,
    Face,
    Other,
}

struct Element {
    name: String,
    count: usize,
    line: usize,
    properties: Vec<Property>,
}

impl Element {
    fn role(&self) -> Role {
        match self.name.as_str() {
            "vertex" => Role::Vertex,
            "face" => Role::Face,
            _ => Role::Other,
        }
    }

    /// Marks the properties to keep, or explains which one is missing.
    fn choose_properties(&mut self) -> Result<(), String> {
        let find = |props: &[Property], names: &[&str]| {
            props.iter().position(|p| names.contains(&p.name.as_str()))
        };
        match self.role() {
            Role::Vertex => {
                for (axis, name) in ["x", "y", "z"].into_iter().enumerate() {
                    let i = find(&self.properties, &[name])
                        .ok_or_else(|| format!("element `vertex` has no property `{name}`"))?;
                    let Kind::Scalar(_) = self.properties[i].kind else {
                        return Err(format!("vertex property `{name}` is a list"));
                    };
                    self.properties[i].keep = Keep::Axis(axis);
                }
            }
            Role::Face => {
                let i = find(&self.properties, &["vertex_indices", "vertex_index"])
                    .ok_or("element `face` has no property `vertex_indices`")?;
                let Kind::List { .. } = self.properties[i].kind else {
                    return Err("face property `vertex_indices` is not a list".to_owned());
                };
                self.properties[i].keep = Keep::Corners;
            }
            Role::Other => {}
        }
        Ok(())
    }
}

pub(super) fn read<R: BufRead>(
    reader: R,
    name: &str,
    options: &ReadOptions,
) -> Result<TriMesh, MeshIoError> {
    let mut lines = TextLines::new(reader, name);
    let (encoding, elements) = read_header(&mut lines, name)?;
    let count = |role| {
        elements
            .iter()
            .find(|e| e.role() == role)
            .map_or(0, |e| e.count)
    };
    let mut soup = Soup::with_capacity(count(Role::Vertex), count(Role::Face));
    let mut reader = Reader {
        soup: &mut soup,
        triangulate: options.triangulate,
        xyz: DVec3::ZERO,
        corners: Vec::new(),
    };
    // An element without properties takes no space, however many there are.
    let elements = elements.iter().filter(|e| !e.properties.is_empty());
    if encoding == Encoding::Ascii {
        for element in elements {
            for index in 0..element.count {
                let end = lines.last_number().max(1);
                let Some((number, line)) = lines.next_line()? else {
                    let message = format!(
                        "the file ends after {index} of {} `{}` elements",
                        element.count, element.name
                    );
                    return Err(parse_error(name, end, message));
                };
                let mut tokens = Tokens(line.split_whitespace());
                reader
                    .element(&mut tokens, element, Some(number))
                    .and_then(|()| match tokens.0.next() {
                        Some(_) => Err(Fault::Data(
                            "the line has more values than the element's properties".to_owned(),
                        )),
                        None => Ok(()),
                    })
                    .map_err(|fault| fault.at_line(name, number))?;
            }
        }
    } else {
        let mut binary = Binary {
            reader: lines.into_inner(),
            big_endian: encoding == Encoding::BigEndian,
        };
        for element in elements {
            for index in 0..element.count {
                reader
                    .element(&mut binary, element, None)
                    .map_err(|fault| fault.in_binary(name, &element.name, index))?;
            }
        }
    }
    soup.build(name, options)
}

/// Reads the header up to `end_header`, leaving `lines` at the first byte of data.
fn read_header<R: BufRead>(
    lines: &mut TextLines<R>,
    name: &str,
) -> Result<(Encoding, Vec<Element>), MeshIoError> {
    match lines.next_line()? {
        Some((_, line)) if line.trim() == "ply" => {}
        _ => {
            let line = lines.last_number().max(1);
            return Err(parse_error(
                name,
                line,
                "not a PLY file: it must start with `ply`",
            ));
        }
    }
    let mut encoding = None;
    let mut elements: Vec<Element> = Vec::new();
    while let Some((number, line)) = lines.next_line()? {
        let error = |message: String| parse_error(name, number, message);
        let tokens: Vec<&str> = line.split_whitespace().collect();
        match tokens[..] {
            ["comment" | "obj_info", ..] => {}
            ["format", format, _version] => {
                encoding = Some(match format {
                    "ascii" => Encoding::Ascii,
                    "binary_little_endian" => Encoding::LittleEndian,
                    "binary_big_endian" => Encoding::BigEndian,
                    _ => return Err(error(format!("unknown PLY format `{format}`"))),
                });
            }
            ["element", element, count] => {
                let count = count
                    .parse()
                    .map_err(|_| error(format!("`{count}` is not an element count")))?;
                if matches!(element, "vertex" | "face")
                    && elements.iter().any(|e| e.name == element)
                {
                    return Err(error(format!("a second `{element}` element")));
                }
                elements.push(Element {
                    name: element.to_owned(),
                    count,
                    line: number,
                    properties: Vec::new(),
                });
            }
            ["property", ref declaration @ .., property] if !declaration.is_empty() => {
                let kind = match *declaration {
                    [ty] => Num::parse(ty).map(Kind::Scalar),
                    ["list", count, item] => Num::parse(count).and_then(|count| {
                        Ok(Kind::List {
                            count,
                            item: Num::parse(item)?,
                        })
                    }),
                    _ => Err(format!("malformed property line `{line}`")),
                }
                .map_err(error)?;
                let element = elements
                    .last_mut()
                    .ok_or_else(|| error("a property before any element".to_owned()))?;
                element.properties.push(Property {
                    name: property.to_owned(),
                    kind,
                    keep: Keep::Skip,
                });
            }
            ["end_header"] => {
                let encoding =
                    encoding.ok_or_else(|| error("the header has no `format` line".to_owned()))?;
                if !elements.iter().any(|e| e.role() == Role::Vertex) {
                    return Err(error("the header declares no `vertex` element".to_owned()));
                }
                for element in &mut elements {
                    let line = element.line;
                    element
                        .choose_properties()
                        .map_err(|message| parse_error(name, line, message))?;
                }
                return Ok((encoding, elements));
            }
            _ => return Err(error(format!("unexpected PLY header line `{line}`"))),
        }
    }
    let end = lines.last_number().max(1);
    Err(parse_error(
        name,
        end,
        "the PLY header has no `end_header` line",
    ))
}

/// Why an element could not be read; where it happened is added by the caller, who knows
/// whether there are lines.
enum Fault {
    Io(io::Error),
    Data(String),
    Corners(usize),
}

impl From<io::Error> for Fault {
    fn from(error: io::Error) -> Fault {
        if error.kind() == io::ErrorKind::UnexpectedEof {
            Fault::Data("the file ends early".to_owned())
        } else {
            Fault::Io(error)
        }
    }
}

impl Fault {
    fn at_line(self, file: &str, line: usize) -> MeshIoError {
        match self {
            Fault::Io(source) => io_error(file, source),
            Fault::Data(message) => parse_error(file, line, message),
            Fault::Corners(corners) => MeshIoError::NotATriangle {
                file: file.to_owned(),
                line,
                corners,
            },
        }
    }

    fn in_binary(self, file: &str, element: &str, index: usize) -> MeshIoError {
        let message = match self {
            Fault::Io(source) => return io_error(file, source),
            Fault::Data(message) => message,
            Fault::Corners(corners) => corner_problem(corners),
        };
        MeshIoError::BinaryParse {
            file: file.to_owned(),
            element: element.to_owned(),
            index,
            message,
        }
    }
}

fn io_error(file: &str, source: io::Error) -> MeshIoError {
    MeshIoError::Io {
        file: file.to_owned(),
        source,
    }
}

/// Where property values come from: the tokens of one ASCII line, or the binary stream.
trait Values {
    fn value(&mut self, num: Num) -> Result<f64, Fault>;
    fn skip(&mut self, num: Num, count: u32) -> Result<(), Fault>;
}

struct Tokens<'a>(std::str::SplitWhitespace<'a>);

impl Values for Tokens<'_> {
    fn value(&mut self, _: Num) -> Result<f64, Fault> {
        let token = self.0.next().ok_or_else(|| {
            Fault::Data("the line has fewer values than the element's properties".to_owned())
        })?;
        token
            .parse()
            .map_err(|_| Fault::Data(format!("`{token}` is not a number")))
    }

    fn skip(&mut self, num: Num, count: u32) -> Result<(), Fault> {
        for _ in 0..count {
            self.value(num)?;
        }
        Ok(())
    }
}

struct Binary<R> {
    reader: R,
    big_endian: bool,
}

impl<R: Read> Values for Binary<R> {
    fn value(&mut self, num: Num) -> Result<f64, Fault> {
        let mut buffer = [0; 8];
        let bytes = &mut buffer[..num.size()];
        self.reader.read_exact(bytes)?;
        Ok(num.decode(bytes, self.big_endian))
    }

    fn skip(&mut self, num: Num, count: u32) -> Result<(), Fault> {
        let length = num.size() as u64 * u64::from(count);
        let skipped = io::copy(&mut self.reader.by_ref().take(length), &mut io::sink())?;
        if skipped < length {
            return Err(io::Error::from(io::ErrorKind::UnexpectedEof).into());
        }
        Ok(())
    }
}

/// Reads elements into the soup, reusing its buffers from one element to the next.
struct Reader<'s> {
    soup: &'s mut Soup,
    triangulate: bool,
    xyz: DVec3,
    corners: Vec<u32>,
}

impl Reader<'_> {
    fn element(
        &mut self,
        values: &mut impl Values,
        element: &Element,
        line: Option<usize>,
    ) -> Result<(), Fault> {
        for property in &element.properties {
            match (property.kind, property.keep) {
                (Kind::Scalar(num), Keep::Axis(axis)) => self.xyz[axis] = values.value(num)?,
                (Kind::Scalar(num), _) => values.skip(num, 1)?,
                (Kind::List { count, item }, keep) => {
                    let count = whole(values.value(count)?, "list length")?;
                    if keep != Keep::Corners {
                        values.skip(item, count)?;
                        continue;
                    }
                    // Checked before reading, so that a corrupt length cannot make us read far.
                    if !Soup::accepts(count as usize, self.triangulate) {
                        return Err(Fault::Corners(count as usize));
                    }
                    self.corners.clear();
                    for _ in 0..count {
                        let index = whole(values.value(item)?, "vertex index")?;
                        self.corners.push(index);
                    }
                }
            }
        }
        match element.role() {
            Role::Vertex => self.soup.push_vertex(self.xyz, line),
            Role::Face => self
                .soup
                .push_polygon(&self.corners, line, self.triangulate)
                .map_err(Fault::Corners)?,
            Role::Other => {}
        }
        Ok(())
    }
}

/// A list length or vertex index, which must be a whole number that fits in `u32`.
fn whole(value: f64, what: &str) -> Result<u32, Fault> {
    if value.fract() == 0.0 && (0.0..=f64::from(u32::MAX)).contains(&value) {
        Ok(value as u32)
    } else {
        Err(Fault::Data(format!(
            "{what} {value} is not a whole number from 0 to {}",
            u32::MAX
        )))
    }
}

pub(super) fn write(mesh: &TriMesh, out: &mut impl Write, encoding: PlyEncoding) -> io::Result<()> {
    let format = match encoding {
        PlyEncoding::Ascii => "ascii",
        PlyEncoding::BinaryLittleEndian => "binary_little_endian",
    };
    writeln!(out, "ply\nformat {format} 1.0")?;
    writeln!(out, "element vertex {}", mesh.vertex_count())?;
    writeln!(
        out,
        "property double x\nproperty double y\nproperty double z"
    )?;
    writeln!(out, "element face {}", mesh.face_count())?;
    writeln!(out, "property list uchar uint vertex_indices\nend_header")?;
    match encoding {
        PlyEncoding::Ascii => {
            for &p in mesh.positions() {
                write_xyz(out, "", p)?;
            }
            for f in mesh.faces() {
                writeln!(out, "3 {} {} {}", f[0], f[1], f[2])?;
            }
        }
        PlyEncoding::BinaryLittleEndian => {
            for p in mesh.positions() {
                for c in p.to_array() {
                    out.write_all(&c.to_le_bytes())?;
                }
            }
            for f in mesh.faces() {
                out.write_all(&[3])?;
                for i in f {
                    out.write_all(&i.to_le_bytes())?;
                }
            }
        }
    }
    Ok(())
}
