//! What a name says: the words of a uniform's or attribute's name
//! (`u_view_proj`, `iResolution`, `a_uv0`) matched against the
//! conventions docs/runner.md lists. Pure functions of the name and its
//! DSL type.

use super::{Attribute, Control, ControlKind, Convention, ValueSpec};

/// The lower-case words of a name: split at `_`, digits and lower-to-upper
/// changes (`iResolution` -> `i`, `resolution`; `a_uv0` -> `a`, `uv`).
pub fn words(name: &str) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    let mut cur = String::new();
    let mut prev_lower = false;
    for c in name.chars() {
        if c == '_' || c.is_ascii_digit() {
            if !cur.is_empty() {
                out.push(std::mem::take(&mut cur));
            }
            prev_lower = false;
            continue;
        }
        if c.is_uppercase() && prev_lower && !cur.is_empty() {
            out.push(std::mem::take(&mut cur));
        }
        prev_lower = c.is_lowercase();
        cur.extend(c.to_lowercase());
    }
    if !cur.is_empty() {
        out.push(cur);
    }
    out
}

fn has(w: &[String], any: &[&str]) -> bool {
    w.iter().any(|x| any.contains(&x.as_str()))
}

/// The mesh attribute a vertex input's name asks for.
pub fn attribute(name: &str) -> Option<Attribute> {
    let w = words(name);
    if has(&w, &["offset", "translation", "instance", "inst"]) {
        Some(Attribute::InstanceOffset)
    } else if has(&w, &["pos", "position", "vertex", "vert", "xyz"]) {
        Some(Attribute::Position)
    } else if has(&w, &["normal", "norm", "nrm", "n"]) {
        Some(Attribute::Normal)
    } else if has(&w, &["tangent", "tan"]) {
        Some(Attribute::Tangent)
    } else if has(&w, &["uv", "texcoord", "tex", "coord", "st", "tc"]) {
        Some(Attribute::Uv)
    } else if has(&w, &["color", "colour", "col", "rgb", "rgba", "tint"]) {
        Some(Attribute::Color)
    } else {
        None
    }
}

fn is_matrix(ty: &str) -> bool {
    ty == "float4x4" || ty == "float3x3"
}

/// The per-frame value a uniform's name and type ask for.
pub fn convention(name: &str, ty: &str) -> Option<Convention> {
    let w = words(name);
    let joined: String = w.concat();
    match ty {
        "float4x4" | "float3x3" => {
            let view = has(&w, &["view", "v", "camera", "cam"]);
            let proj = has(&w, &["proj", "projection", "persp", "p"]);
            let model = has(&w, &["model", "world", "object", "m"]);
            Some(if has(&w, &["normal"]) {
                Convention::NormalMatrix
            } else if has(&w, &["mvp", "wvp"]) || (model && view && proj) {
                Convention::ModelViewProjection
            } else if has(&w, &["light", "sun", "shadow"]) {
                Convention::LightViewProjection
            } else if has(&w, &["vp", "viewproj", "viewprojection"]) || joined.contains("viewproj") || (view && proj) {
                Convention::ViewProjection
            } else if view && has(&w, &["rot", "rotation", "sky", "dir"]) {
                Convention::ViewRotation
            } else if view {
                Convention::View
            } else if proj {
                Convention::Projection
            } else if model {
                Convention::Model
            } else {
                return None;
            })
        }
        "float" => {
            if has(&w, &["time", "seconds", "elapsed", "t"]) && !has(&w, &["dt", "delta"]) {
                Some(Convention::Time)
            } else if has(&w, &["frame"]) {
                Some(Convention::Frame)
            } else if has(&w, &["aspect"]) {
                Some(Convention::Aspect)
            } else {
                None
            }
        }
        "int" | "uint" => has(&w, &["frame"]).then_some(Convention::Frame),
        "float2" | "float3" | "float4" => {
            if has(&w, &["mouse", "pointer", "cursor"]) && ty != "float3" {
                Some(Convention::Mouse)
            } else if has(&w, &["rcp", "texel", "inv", "pixel"]) && ty == "float2" {
                Some(Convention::TexelSize)
            } else if has(&w, &["res", "resolution", "viewport", "screen"]) && ty != "float4" {
                Some(Convention::Resolution)
            } else if ty == "float3" && has(&w, &["light", "sun"]) && has(&w, &["dir", "direction"]) {
                Some(Convention::LightDirection)
            } else if ty == "float3" && has(&w, &["light", "lamp"]) && has(&w, &["pos", "position"]) {
                Some(Convention::LightPosition)
            } else if ty == "float3" && has(&w, &["spot"]) && has(&w, &["dir", "direction", "axis"]) {
                Some(Convention::SpotDirection)
            } else if ty == "float3" && has(&w, &["cam", "camera", "eye", "view"]) && has(&w, &["pos", "position", "origin"])
                || ty == "float3" && has(&w, &["eye"])
            {
                Some(Convention::CameraPosition)
            } else {
                None
            }
        }
        _ => None,
    }
}

fn looks_like_colour(name: &str) -> bool {
    has(&words(name), &["color", "colour", "col", "tint", "albedo", "diffuse", "emissive", "emission", "ambient", "specular", "sky", "fog", "rgb", "rgba"])
}

fn looks_like_angle(name: &str) -> bool {
    has(&words(name), &["angle", "rot", "rotation", "phase", "theta", "phi", "yaw", "pitch"])
}

/// The scalar kind and component count of a scalar or vector type.
fn vector(ty: &str) -> Option<(&'static str, usize)> {
    for s in ["float", "uint", "int", "bool"] {
        if let Some(rest) = ty.strip_prefix(s) {
            let n = match rest {
                "" => 1,
                "2" => 2,
                "3" => 3,
                "4" => 4,
                _ => return None,
            };
            return Some((s, n));
        }
    }
    None
}

/// The control a page shows for a uniform of type `ty`, given the value
/// the scene sets (which decides a slider's range).
pub fn control(name: &str, ty: &str, value: Option<&ValueSpec>) -> Control {
    let mut c = Control { name: name.to_string(), ty: ty.to_string(), kind: ControlKind::None, min: None, max: None, step: None };
    if let Some(ValueSpec::Convention(_) | ValueSpec::Element(_)) = value {
        c.kind = ControlKind::Convention;
        return c;
    }
    let Some((scalar, n)) = vector(ty) else {
        return c;
    };
    let numbers: Vec<f64> = match value {
        Some(ValueSpec::Number(x)) => vec![*x],
        Some(ValueSpec::Numbers(v)) => v.clone(),
        _ => Vec::new(),
    };
    let largest = numbers.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let negative = numbers.iter().any(|x| *x < 0.0);
    match scalar {
        "bool" => c.kind = if n == 1 { ControlKind::Checkbox } else { ControlKind::None },
        "float" if n >= 3 && looks_like_colour(name) && largest <= 1.0 && !negative => {
            c.kind = ControlKind::Color;
        }
        "float" => {
            let hi = if looks_like_angle(name) { std::f64::consts::TAU.max(largest) } else { (2.0 * largest).max(1.0) };
            c.kind = ControlKind::Slider;
            c.min = Some(if negative || (n > 1 && !looks_like_colour(name) && largest == 0.0) { -hi } else { 0.0 });
            c.max = Some(hi);
            c.step = Some(hi / 1000.0);
        }
        _ => {
            let hi = (2.0 * largest).max(10.0);
            c.kind = ControlKind::Slider;
            c.min = Some(if negative { -hi } else { 0.0 });
            c.max = Some(hi);
            c.step = Some(1.0);
        }
    }
    c
}

/// A value for a uniform nothing else sets: a colour's light grey, a
/// slider's middle, identity matrices, `false`, 1 for integers; arrays of
/// those. `None` for a struct.
pub fn fallback(name: &str, ty: &str) -> Option<ValueSpec> {
    if let Some((element, n)) = ty.strip_suffix(']').and_then(|t| t.rsplit_once('[')) {
        let n: usize = n.parse().ok()?;
        let one = match fallback(name, element)? {
            ValueSpec::Number(x) => vec![x],
            ValueSpec::Numbers(v) => v,
            ValueSpec::Bool(b) => vec![b as u8 as f64],
            ValueSpec::Convention(_) | ValueSpec::Element(_) => return None,
        };
        return Some(ValueSpec::Numbers(one.iter().copied().cycle().take(one.len() * n).collect()));
    }
    if is_matrix(ty) || ty.starts_with("float") && ty.contains('x') {
        let (c, r) = ty.strip_prefix("float")?.split_once('x')?;
        let (c, r): (usize, usize) = (c.parse().ok()?, r.parse().ok()?);
        return Some(ValueSpec::Numbers((0..c * r).map(|i| if i / r == i % r { 1.0 } else { 0.0 }).collect()));
    }
    let (scalar, n) = vector(ty)?;
    let x = match scalar {
        "bool" if n == 1 => return Some(ValueSpec::Bool(false)),
        "bool" => 0.0,
        "float" if looks_like_colour(name) => 0.8,
        "float" if looks_like_angle(name) => 0.5,
        "float" => 0.5,
        _ => 1.0,
    };
    Some(if n == 1 {
        ValueSpec::Number(x)
    } else {
        let mut v = vec![x; n];
        if n == 4 && looks_like_colour(name) {
            v[3] = 1.0;
        }
        ValueSpec::Numbers(v)
    })
}

/// The manifest's default words (`uniforms[].default`) as a value of `ty`.
pub fn from_words(ty: &str, words: &[u32]) -> Option<ValueSpec> {
    let element = ty.split('[').next()?;
    let scalar = ["float", "uint", "int", "bool"].into_iter().find(|s| element.starts_with(s))?;
    let numbers: Vec<f64> = words
        .iter()
        .map(|w| match scalar {
            "float" => f32::from_bits(*w) as f64,
            "int" => *w as i32 as f64,
            _ => *w as f64,
        })
        .collect();
    Some(match (scalar, numbers.as_slice()) {
        ("bool", [b]) if !ty.contains('[') => ValueSpec::Bool(*b != 0.0),
        (_, [x]) if !ty.contains('[') => ValueSpec::Number(*x),
        _ => ValueSpec::Numbers(numbers),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn words_split_at_underscores_digits_and_case() {
        assert_eq!(words("iResolution"), ["i", "resolution"]);
        assert_eq!(words("a_uv0"), ["a", "uv"]);
        assert_eq!(words("u_view_proj"), ["u", "view", "proj"]);
        assert_eq!(words("ViewProj"), ["view", "proj"]);
    }

    #[test]
    fn conventions_by_name_and_type() {
        assert_eq!(convention("u_time", "float"), Some(Convention::Time));
        assert_eq!(convention("iTime", "float"), Some(Convention::Time));
        assert_eq!(convention("u_dt", "float"), None);
        assert_eq!(convention("u_res", "float2"), Some(Convention::Resolution));
        assert_eq!(convention("iMouse", "float4"), Some(Convention::Mouse));
        assert_eq!(convention("u_view", "float4x4"), Some(Convention::View));
        assert_eq!(convention("u_view_rot", "float4x4"), Some(Convention::ViewRotation));
        assert_eq!(convention("u_proj", "float4x4"), Some(Convention::Projection));
        assert_eq!(convention("u_view_proj", "float4x4"), Some(Convention::ViewProjection));
        assert_eq!(convention("u_mvp", "float4x4"), Some(Convention::ModelViewProjection));
        assert_eq!(convention("u_light_vp", "float4x4"), Some(Convention::LightViewProjection));
        assert_eq!(convention("u_normal_matrix", "float3x3"), Some(Convention::NormalMatrix));
        assert_eq!(convention("u_cam_pos", "float3"), Some(Convention::CameraPosition));
        assert_eq!(convention("u_light_dir", "float3"), Some(Convention::LightDirection));
        assert_eq!(convention("u_light_pos", "float3"), Some(Convention::LightPosition));
        assert_eq!(convention("u_spot_dir", "float3"), Some(Convention::SpotDirection));
        assert_eq!(convention("u_src_rcp", "float2"), Some(Convention::TexelSize));
        assert_eq!(convention("u_time", "float4"), None, "a name fits only with its type");
        assert_eq!(convention("u_strength", "float"), None);
    }

    #[test]
    fn attributes_by_name() {
        assert_eq!(attribute("a_pos"), Some(Attribute::Position));
        assert_eq!(attribute("v_position"), Some(Attribute::Position));
        assert_eq!(attribute("a_normal"), Some(Attribute::Normal));
        assert_eq!(attribute("a_uv0"), Some(Attribute::Uv));
        assert_eq!(attribute("a_tangent"), Some(Attribute::Tangent));
        assert_eq!(attribute("v_color"), Some(Attribute::Color));
        assert_eq!(attribute("a_offset"), Some(Attribute::InstanceOffset));
        assert_eq!(attribute("a_phase"), None);
    }

    #[test]
    fn controls_fit_the_type_and_the_name() {
        assert_eq!(control("u_tint", "float3", Some(&ValueSpec::Numbers(vec![0.8; 3]))).kind, ControlKind::Color);
        assert_eq!(control("u_on", "bool", Some(&ValueSpec::Bool(true))).kind, ControlKind::Checkbox);
        assert_eq!(control("u_time", "float", Some(&ValueSpec::Convention(Convention::Time))).kind, ControlKind::Convention);
        let s = control("u_strength", "float", Some(&ValueSpec::Number(3.0)));
        assert_eq!((s.kind, s.min, s.max), (ControlKind::Slider, Some(0.0), Some(6.0)));
        let a = control("u_angle", "float", Some(&ValueSpec::Number(0.5)));
        assert_eq!(a.max, Some(std::f64::consts::TAU));
        let i = control("u_steps", "int", Some(&ValueSpec::Number(4.0)));
        assert_eq!((i.kind, i.step, i.max), (ControlKind::Slider, Some(1.0), Some(10.0)));
        assert_eq!(control("u_m", "float4x4", None).kind, ControlKind::None);
    }

    #[test]
    fn fallbacks_and_manifest_words() {
        assert_eq!(fallback("u_tint", "float4"), Some(ValueSpec::Numbers(vec![0.8, 0.8, 0.8, 1.0])));
        assert_eq!(fallback("u_m", "float2x2"), Some(ValueSpec::Numbers(vec![1.0, 0.0, 0.0, 1.0])));
        assert_eq!(fallback("u_w", "float[3]"), Some(ValueSpec::Numbers(vec![0.5; 3])));
        assert_eq!(fallback("u_s", "Light"), None);
        assert_eq!(from_words("float", &[2.5f32.to_bits()]), Some(ValueSpec::Number(2.5)));
        assert_eq!(from_words("bool", &[1]), Some(ValueSpec::Bool(true)));
        assert_eq!(from_words("int2", &[(-1i32) as u32, 3]), Some(ValueSpec::Numbers(vec![-1.0, 3.0])));
    }
}
