//! Values into the bytes of a uniform buffer, at a layout: the one place
//! that knows how a value's words sit in memory given an offset, an array
//! stride and a matrix stride (whoever states them: the manifest, or a GL
//! driver asked by a by-name host).

pub use crate::render::plan::Unset;
use crate::render::plan::{Shape, Value};

/// Where one value lives in a buffer, and what it must be.
#[derive(Clone, Debug, PartialEq)]
pub struct Slot {
    /// The plan's value that fills it (`u_model`).
    pub value: String,
    /// DSL type the value must have (`float4x4`, `float[9]`).
    pub ty: String,
    pub offset: u32,
    /// Bytes between array elements.
    pub array_stride: Option<u32>,
    /// Bytes between matrix columns.
    pub matrix_stride: Option<u32>,
    /// Words to put there when the plan sets nothing (the manifest's
    /// `default`).
    pub default: Option<Vec<u32>>,
}

/// A uniform buffer's contents: its size and slots.
#[derive(Clone, Debug, PartialEq)]
pub struct BufferLayout {
    /// Names it in messages.
    pub name: String,
    pub size: u32,
    pub slots: Vec<Slot>,
}

/// Writes `value` at `slot` into `out`. Matrices go column by column
/// `matrix_stride` apart (16 when unstated), arrays element by element
/// `array_stride` apart (the element size rounded up to 16 when unstated).
pub fn write(out: &mut [u8], slot: &Slot, value: &Value) -> Result<(), String> {
    let rows = match value.shape {
        Shape::Matrix { rows, .. } => rows as usize,
        _ => 0,
    };
    let matrix_stride = slot.matrix_stride.unwrap_or(16) as usize;
    let element_size = match value.shape {
        Shape::Matrix { columns, .. } => matrix_stride * columns as usize,
        s => 4 * s.words(),
    };
    let array_stride = slot.array_stride.map_or_else(|| element_size.next_multiple_of(16), |s| s as usize);
    let overrun = || format!("uniform `{}` at offset {} overruns", slot.value, slot.offset);
    let mut put = |at: usize, words: &[u32]| -> Result<(), String> {
        let dst = out.get_mut(at..at + 4 * words.len()).ok_or_else(overrun)?;
        for (d, w) in dst.chunks_exact_mut(4).zip(words) {
            d.copy_from_slice(&w.to_le_bytes());
        }
        Ok(())
    };
    for i in 0..value.elements() {
        let base = slot.offset as usize + i * array_stride;
        let words = value.element(i);
        if rows > 0 {
            for (c, column) in words.chunks_exact(rows).enumerate() {
                put(base + c * matrix_stride, column)?;
            }
        } else {
            put(base, words)?;
        }
    }
    Ok(())
}

/// The buffer's bytes: every slot's default, then every value `lookup`
/// finds, type-checked. All problems are listed.
pub fn fill<'v>(layout: &BufferLayout, lookup: impl Fn(&str) -> Option<&'v Value>, known: &[String], unset: Unset) -> Result<Vec<u8>, Vec<String>> {
    let mut out = vec![0u8; layout.size as usize];
    let mut problems = Vec::new();
    for slot in &layout.slots {
        if let Some(words) = &slot.default {
            let at = slot.offset as usize;
            match out.get_mut(at..at + 4 * words.len()) {
                Some(dst) => {
                    for (d, w) in dst.chunks_exact_mut(4).zip(words) {
                        d.copy_from_slice(&w.to_le_bytes());
                    }
                }
                None => problems.push(format!("the default of uniform `{}` overruns its buffer `{}`", slot.value, layout.name)),
            }
        }
        match lookup(&slot.value) {
            Some(v) if v.dsl_type() != slot.ty => {
                problems.push(format!("uniform `{}` is {} but the scene sets a {}", slot.value, slot.ty, v.dsl_type()))
            }
            Some(v) => {
                if let Err(e) = write(&mut out, slot, v) {
                    problems.push(format!("{e} its buffer `{}` of {} bytes", layout.name, layout.size));
                }
            }
            None if slot.default.is_some() || unset == Unset::Zero => {}
            None => problems.push(format!(
                "uniform `{}` is not a value the scene sets (it sets {}) and has no default",
                slot.value,
                known.join(", ")
            )),
        }
    }
    if problems.is_empty() {
        Ok(out)
    } else {
        Err(problems)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Mat4;

    fn slot(ty: &str, offset: u32, array_stride: Option<u32>, matrix_stride: Option<u32>) -> Slot {
        Slot { value: "v".into(), ty: ty.into(), offset, array_stride, matrix_stride, default: None }
    }

    #[test]
    fn matrices_and_arrays_follow_their_strides() {
        let mut out = vec![0u8; 256];
        let m = Mat4::from_cols_array(&std::array::from_fn(|i| i as f32));
        write(&mut out, &slot("float4x4", 16, None, Some(16)), &Value::mat4(m)).unwrap();
        let at = |o: usize| f32::from_le_bytes(out[o..o + 4].try_into().unwrap());
        assert_eq!((at(16), at(32), at(76)), (0.0, 4.0, 15.0));
        // float[3] with a 16-byte stride (std140).
        let mut out = vec![0u8; 64];
        let a = Value::array(vec![Value::float(1.0), Value::float(2.0), Value::float(3.0)]);
        write(&mut out, &slot("float[3]", 0, Some(16), None), &a).unwrap();
        let at = |o: usize| f32::from_le_bytes(out[o..o + 4].try_into().unwrap());
        assert_eq!((at(0), at(16), at(32), at(4)), (1.0, 2.0, 3.0, 0.0));
        // A 3x2 matrix stored as vec4 columns (matrix stride 16).
        let mut out = vec![0u8; 48];
        let m = Value::floats(Shape::Matrix { columns: 3, rows: 2 }, &[1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
        write(&mut out, &slot("float3x2", 0, None, Some(16)), &m).unwrap();
        let at = |o: usize| f32::from_le_bytes(out[o..o + 4].try_into().unwrap());
        assert_eq!((at(0), at(4), at(16), at(36)), (1.0, 2.0, 3.0, 6.0));
        assert!(write(&mut [0u8; 8], &slot("float3", 0, None, None), &Value::vec3(glam::Vec3::ONE)).is_err());
    }

    #[test]
    fn fill_checks_types_and_lists_what_is_missing() {
        let layout = BufferLayout {
            name: "b".into(),
            size: 32,
            slots: vec![
                Slot { value: "a".into(), ..slot("float", 0, None, None) },
                Slot { value: "b".into(), ..slot("int", 4, None, None) },
                Slot { value: "c".into(), default: Some(vec![7]), ..slot("uint", 8, None, None) },
            ],
        };
        let a = Value::float(2.0);
        let err = fill(&layout, |n| (n == "a" || n == "b").then_some(&a), &["a".into()], Unset::Error).unwrap_err();
        assert_eq!(err, ["uniform `b` is int but the scene sets a float"]);
        let err = fill(&layout, |n| (n == "a").then_some(&a), &["a".into()], Unset::Error).unwrap_err();
        assert!(err[0].contains("`b` is not a value the scene sets (it sets a)"), "{err:?}");
        let bytes = fill(&layout, |n| (n == "a").then_some(&a), &[], Unset::Zero).unwrap();
        assert_eq!((&bytes[0..4], &bytes[8..12]), (&2.0f32.to_le_bytes()[..], &7u32.to_le_bytes()[..]));
    }
}
