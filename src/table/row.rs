//! One table row from any serde-serialisable struct: its fields, with nested structs and maps
//! flattened into the row (a map's keys become column names), each a typed [`Cell`]. A run's
//! summary is a typed struct; this is how it becomes a CSV row or a Parquet row without its
//! columns being listed by hand anywhere.

use serde::ser::{self, Serialize};

/// One value of a row.
#[derive(Debug, Clone, PartialEq)]
pub enum Cell {
    /// A flag.
    Bool(bool),
    /// A signed count.
    Int(i64),
    /// An unsigned count.
    UInt(u64),
    /// A quantity.
    Float(f64),
    /// Text.
    Str(String),
    /// No value (an absent option).
    Empty,
}

impl Cell {
    /// The cell as CSV text: floats with 10 significant digits in exponent form, so that every
    /// table prints a quantity the same way.
    pub fn text(&self) -> String {
        match self {
            Cell::Bool(b) => b.to_string(),
            Cell::Int(v) => v.to_string(),
            Cell::UInt(v) => v.to_string(),
            Cell::Float(v) => format!("{v:.9e}"),
            Cell::Str(s) => s.clone(),
            Cell::Empty => String::new(),
        }
    }
}

/// The row of `value`: (column name, cell) in field order.
pub fn cells<T: Serialize + ?Sized>(value: &T) -> Result<Vec<(String, Cell)>, String> {
    match value.serialize(NodeSer).map_err(|e| e.0)? {
        Node::Fields(f) => {
            let mut out = Vec::new();
            flatten(f, &mut out);
            Ok(out)
        }
        Node::Leaf(_) => Err("a row must be a struct or a map".into()),
    }
}

fn flatten(fields: Vec<(String, Node)>, out: &mut Vec<(String, Cell)>) {
    for (name, node) in fields {
        match node {
            Node::Leaf(c) => out.push((name, c)),
            Node::Fields(f) => flatten(f, out),
        }
    }
}

enum Node {
    Leaf(Cell),
    Fields(Vec<(String, Node)>),
}

#[derive(Debug)]
struct SerError(String);

impl std::fmt::Display for SerError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for SerError {}

impl ser::Error for SerError {
    fn custom<T: std::fmt::Display>(msg: T) -> Self {
        SerError(msg.to_string())
    }
}

struct NodeSer;

fn unsupported<T>(what: &str) -> Result<T, SerError> {
    Err(SerError(format!("a table row cannot hold {what}")))
}

struct Fields {
    fields: Vec<(String, Node)>,
    key: Option<String>,
}

impl ser::Serializer for NodeSer {
    type Ok = Node;
    type Error = SerError;
    type SerializeSeq = ser::Impossible<Node, SerError>;
    type SerializeTuple = ser::Impossible<Node, SerError>;
    type SerializeTupleStruct = ser::Impossible<Node, SerError>;
    type SerializeTupleVariant = ser::Impossible<Node, SerError>;
    type SerializeMap = Fields;
    type SerializeStruct = Fields;
    type SerializeStructVariant = ser::Impossible<Node, SerError>;

    fn serialize_bool(self, v: bool) -> Result<Node, SerError> {
        Ok(Node::Leaf(Cell::Bool(v)))
    }
    fn serialize_i8(self, v: i8) -> Result<Node, SerError> {
        Ok(Node::Leaf(Cell::Int(v.into())))
    }
    fn serialize_i16(self, v: i16) -> Result<Node, SerError> {
        Ok(Node::Leaf(Cell::Int(v.into())))
    }
    fn serialize_i32(self, v: i32) -> Result<Node, SerError> {
        Ok(Node::Leaf(Cell::Int(v.into())))
    }
    fn serialize_i64(self, v: i64) -> Result<Node, SerError> {
        Ok(Node::Leaf(Cell::Int(v)))
    }
    fn serialize_u8(self, v: u8) -> Result<Node, SerError> {
        Ok(Node::Leaf(Cell::UInt(v.into())))
    }
    fn serialize_u16(self, v: u16) -> Result<Node, SerError> {
        Ok(Node::Leaf(Cell::UInt(v.into())))
    }
    fn serialize_u32(self, v: u32) -> Result<Node, SerError> {
        Ok(Node::Leaf(Cell::UInt(v.into())))
    }
    fn serialize_u64(self, v: u64) -> Result<Node, SerError> {
        Ok(Node::Leaf(Cell::UInt(v)))
    }
    fn serialize_f32(self, v: f32) -> Result<Node, SerError> {
        Ok(Node::Leaf(Cell::Float(v.into())))
    }
    fn serialize_f64(self, v: f64) -> Result<Node, SerError> {
        Ok(Node::Leaf(Cell::Float(v)))
    }
    fn serialize_char(self, v: char) -> Result<Node, SerError> {
        Ok(Node::Leaf(Cell::Str(v.to_string())))
    }
    fn serialize_str(self, v: &str) -> Result<Node, SerError> {
        Ok(Node::Leaf(Cell::Str(v.to_string())))
    }
    fn serialize_bytes(self, _: &[u8]) -> Result<Node, SerError> {
        unsupported("bytes")
    }
    fn serialize_none(self) -> Result<Node, SerError> {
        Ok(Node::Leaf(Cell::Empty))
    }
    fn serialize_some<T: Serialize + ?Sized>(self, v: &T) -> Result<Node, SerError> {
        v.serialize(self)
    }
    fn serialize_unit(self) -> Result<Node, SerError> {
        Ok(Node::Leaf(Cell::Empty))
    }
    fn serialize_unit_struct(self, _: &'static str) -> Result<Node, SerError> {
        Ok(Node::Leaf(Cell::Empty))
    }
    fn serialize_unit_variant(self, _: &'static str, _: u32, variant: &'static str) -> Result<Node, SerError> {
        Ok(Node::Leaf(Cell::Str(variant.to_string())))
    }
    fn serialize_newtype_struct<T: Serialize + ?Sized>(self, _: &'static str, v: &T) -> Result<Node, SerError> {
        v.serialize(self)
    }
    fn serialize_newtype_variant<T: Serialize + ?Sized>(self, _: &'static str, _: u32, _: &'static str, _: &T) -> Result<Node, SerError> {
        unsupported("an enum variant with data")
    }
    fn serialize_seq(self, _: Option<usize>) -> Result<Self::SerializeSeq, SerError> {
        unsupported("a sequence")
    }
    fn serialize_tuple(self, _: usize) -> Result<Self::SerializeTuple, SerError> {
        unsupported("a tuple")
    }
    fn serialize_tuple_struct(self, _: &'static str, _: usize) -> Result<Self::SerializeTupleStruct, SerError> {
        unsupported("a tuple struct")
    }
    fn serialize_tuple_variant(self, _: &'static str, _: u32, _: &'static str, _: usize) -> Result<Self::SerializeTupleVariant, SerError> {
        unsupported("an enum variant with data")
    }
    fn serialize_map(self, _: Option<usize>) -> Result<Fields, SerError> {
        Ok(Fields { fields: Vec::new(), key: None })
    }
    fn serialize_struct(self, _: &'static str, _: usize) -> Result<Fields, SerError> {
        Ok(Fields { fields: Vec::new(), key: None })
    }
    fn serialize_struct_variant(self, _: &'static str, _: u32, _: &'static str, _: usize) -> Result<Self::SerializeStructVariant, SerError> {
        unsupported("an enum variant with data")
    }
}

impl ser::SerializeStruct for Fields {
    type Ok = Node;
    type Error = SerError;
    fn serialize_field<T: Serialize + ?Sized>(&mut self, key: &'static str, value: &T) -> Result<(), SerError> {
        self.fields.push((key.to_string(), value.serialize(NodeSer)?));
        Ok(())
    }
    fn end(self) -> Result<Node, SerError> {
        Ok(Node::Fields(self.fields))
    }
}

impl ser::SerializeMap for Fields {
    type Ok = Node;
    type Error = SerError;
    fn serialize_key<T: Serialize + ?Sized>(&mut self, key: &T) -> Result<(), SerError> {
        match key.serialize(NodeSer)? {
            Node::Leaf(c) => {
                self.key = Some(c.text());
                Ok(())
            }
            Node::Fields(_) => unsupported("a map key that is not a value"),
        }
    }
    fn serialize_value<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), SerError> {
        let key = self.key.take().ok_or_else(|| SerError("map value without a key".into()))?;
        self.fields.push((key, value.serialize(NodeSer)?));
        Ok(())
    }
    fn end(self) -> Result<Node, SerError> {
        Ok(Node::Fields(self.fields))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(serde::Serialize)]
    struct Inner {
        b_j: f64,
        flag: bool,
    }

    #[derive(serde::Serialize)]
    struct Outer {
        name: String,
        n: u64,
        inner: Inner,
        gone: Option<f64>,
        extra: std::collections::BTreeMap<String, f64>,
    }

    #[test]
    fn nested_structs_and_maps_flatten_into_one_row() {
        let o = Outer {
            name: "x".into(),
            n: 3,
            inner: Inner { b_j: 1.5, flag: true },
            gone: None,
            extra: [("p_min".to_string(), -1.0)].into_iter().collect(),
        };
        let row = cells(&o).unwrap();
        let names: Vec<&str> = row.iter().map(|(n, _)| n.as_str()).collect();
        assert_eq!(names, ["name", "n", "b_j", "flag", "gone", "p_min"]);
        assert_eq!(row[2].1, Cell::Float(1.5));
        assert_eq!(row[2].1.text(), "1.500000000e0");
        assert_eq!(row[4].1, Cell::Empty);
    }
}
