//! A uniform value as a frame plan names it: a DSL type and its 32-bit
//! words (floats by their bits, bools as 0 / 1, matrices column by column,
//! arrays element by element). Where the words go in memory is not its
//! business: that is the manifest's, read by [`crate::render::bind`].

use glam::{Mat4, Vec2, Vec3, Vec4};

/// The scalar kind of a value's components.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Scalar {
    Float,
    Int,
    Uint,
    Bool,
}

impl Scalar {
    /// The DSL type name of one component (`float`, `int`, `uint`, `bool`).
    pub fn name(self) -> &'static str {
        match self {
            Scalar::Float => "float",
            Scalar::Int => "int",
            Scalar::Uint => "uint",
            Scalar::Bool => "bool",
        }
    }
}

/// The shape of one element.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Shape {
    Scalar,
    /// 2, 3 or 4 components.
    Vector(u8),
    /// `columns` columns of `rows` floats.
    Matrix { columns: u8, rows: u8 },
}

impl Shape {
    /// 32-bit words in one element.
    pub fn words(self) -> usize {
        match self {
            Shape::Scalar => 1,
            Shape::Vector(n) => n as usize,
            Shape::Matrix { columns, rows } => columns as usize * rows as usize,
        }
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct Value {
    pub scalar: Scalar,
    pub shape: Shape,
    /// `Some(n)` for an array of `n` elements.
    pub array: Option<u32>,
    /// Every element's words, in order.
    pub words: Vec<u32>,
}

impl Value {
    fn of(scalar: Scalar, shape: Shape, words: Vec<u32>) -> Value {
        debug_assert_eq!(words.len(), shape.words());
        Value { scalar, shape, array: None, words }
    }

    pub fn float(v: f32) -> Value {
        Value::of(Scalar::Float, Shape::Scalar, vec![v.to_bits()])
    }

    pub fn int(v: i32) -> Value {
        Value::of(Scalar::Int, Shape::Scalar, vec![v as u32])
    }

    pub fn uint(v: u32) -> Value {
        Value::of(Scalar::Uint, Shape::Scalar, vec![v])
    }

    pub fn bool(v: bool) -> Value {
        Value::of(Scalar::Bool, Shape::Scalar, vec![v as u32])
    }

    pub fn floats(shape: Shape, v: &[f32]) -> Value {
        Value::of(Scalar::Float, shape, v.iter().map(|f| f.to_bits()).collect())
    }

    pub fn vec2(v: Vec2) -> Value {
        Value::floats(Shape::Vector(2), &v.to_array())
    }

    pub fn vec3(v: Vec3) -> Value {
        Value::floats(Shape::Vector(3), &v.to_array())
    }

    pub fn vec4(v: Vec4) -> Value {
        Value::floats(Shape::Vector(4), &v.to_array())
    }

    /// A 4x4 matrix, column by column (glam's and GL's order).
    pub fn mat4(m: Mat4) -> Value {
        Value::floats(Shape::Matrix { columns: 4, rows: 4 }, &m.to_cols_array())
    }

    /// An array of values of one type. Panics on an empty list or mixed
    /// types (a plan builder's bug).
    pub fn array(elements: Vec<Value>) -> Value {
        let first = elements.first().expect("an array value has elements");
        assert!(elements.iter().all(|e| e.scalar == first.scalar && e.shape == first.shape && e.array.is_none()), "mixed array");
        Value {
            scalar: first.scalar,
            shape: first.shape,
            array: Some(elements.len() as u32),
            words: elements.iter().flat_map(|e| e.words.iter().copied()).collect(),
        }
    }

    /// Elements (1 for a value that is not an array).
    pub fn elements(&self) -> usize {
        self.array.map_or(1, |n| n as usize)
    }

    /// The words of element `i`.
    pub fn element(&self, i: usize) -> &[u32] {
        let n = self.shape.words();
        &self.words[i * n..(i + 1) * n]
    }

    /// The DSL type, as the manifest writes it: `float`, `int3`,
    /// `float4x4`, `float4x4[3]`.
    pub fn dsl_type(&self) -> String {
        let s = self.scalar.name();
        let element = match self.shape {
            Shape::Scalar => s.to_string(),
            Shape::Vector(n) => format!("{s}{n}"),
            Shape::Matrix { columns, rows } => format!("float{columns}x{rows}"),
        };
        match self.array {
            Some(n) => format!("{element}[{n}]"),
            None => element,
        }
    }

    /// A value of DSL type `ty` (`float`, `bool2`, `float3x2`, `int[4]`)
    /// from its words in order, as the manifest's `uniforms[].default`
    /// gives them; `None` for a type no value has (a struct) or words that
    /// do not fit it.
    pub fn from_words(ty: &str, words: &[u32]) -> Option<Value> {
        let (element, array) = match ty.strip_suffix(']').and_then(|t| t.rsplit_once('[')) {
            Some((e, n)) => (e, Some(n.parse::<u32>().ok()?)),
            None => (ty, None),
        };
        let (scalar, rest) = [("float", Scalar::Float), ("uint", Scalar::Uint), ("int", Scalar::Int), ("bool", Scalar::Bool)]
            .into_iter()
            .find_map(|(p, s)| element.strip_prefix(p).map(|r| (s, r)))?;
        let dim = |d: &str| d.parse::<u8>().ok().filter(|n| (2..=4).contains(n));
        let shape = match rest.split_once('x') {
            None if rest.is_empty() => Shape::Scalar,
            None => Shape::Vector(dim(rest)?),
            Some((c, r)) if scalar == Scalar::Float => Shape::Matrix { columns: dim(c)?, rows: dim(r)? },
            Some(_) => return None,
        };
        let n = array.unwrap_or(1) as usize;
        (words.len() == n * shape.words()).then(|| Value { scalar, shape, array, words: words.to_vec() })
    }

    /// The words as floats (for GL's float uniform calls).
    pub fn as_f32(&self) -> Vec<f32> {
        self.words.iter().map(|w| f32::from_bits(*w)).collect()
    }
}

/// Values by name: the uniforms a pass or a draw sets.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Values(Vec<(String, Value)>);

impl Values {
    pub fn new() -> Values {
        Values::default()
    }

    /// Sets (or replaces) `name`.
    pub fn set(&mut self, name: &str, value: Value) -> &mut Values {
        match self.0.iter_mut().find(|(n, _)| n == name) {
            Some(slot) => slot.1 = value,
            None => self.0.push((name.to_string(), value)),
        }
        self
    }

    pub fn with(mut self, name: &str, value: Value) -> Values {
        self.set(name, value);
        self
    }

    pub fn get(&self, name: &str) -> Option<&Value> {
        self.0.iter().find(|(n, _)| n == name).map(|(_, v)| v)
    }

    pub fn names(&self) -> impl Iterator<Item = &str> {
        self.0.iter().map(|(n, _)| n.as_str())
    }

    pub fn iter(&self) -> impl Iterator<Item = (&str, &Value)> {
        self.0.iter().map(|(n, v)| (n.as_str(), v))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dsl_types() {
        assert_eq!(Value::float(1.0).dsl_type(), "float");
        assert_eq!(Value::vec3(Vec3::ONE).dsl_type(), "float3");
        assert_eq!(Value::mat4(Mat4::IDENTITY).dsl_type(), "float4x4");
        assert_eq!(Value::array(vec![Value::mat4(Mat4::IDENTITY); 3]).dsl_type(), "float4x4[3]");
        assert_eq!(Value::bool(true).dsl_type(), "bool");
        let m = Value::array(vec![Value::int(1), Value::int(2)]);
        assert_eq!((m.elements(), m.element(1)), (2, &[2u32][..]));
    }

    #[test]
    fn values_from_manifest_words() {
        for v in [Value::float(0.5), Value::bool(true), Value::mat4(Mat4::IDENTITY), Value::array(vec![Value::int(1), Value::int(2)])] {
            assert_eq!(Value::from_words(&v.dsl_type(), &v.words), Some(v.clone()));
        }
        let m = Value::from_words("float3x2", &[0; 6]).unwrap();
        assert_eq!(m.shape, Shape::Matrix { columns: 3, rows: 2 });
        assert_eq!(Value::from_words("float[9]", &[0; 9]).unwrap().elements(), 9);
        assert_eq!(Value::from_words("float2", &[0; 3]), None);
        assert_eq!(Value::from_words("Light[2]", &[0; 8]), None);
    }
}
