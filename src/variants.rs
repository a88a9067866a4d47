//! Shader variants: one program compiled with many define sets.
//!
//! A [`Spec`] lists named variants and axes; the variants compiled are the
//! named ones, in order, then every combination of the axes' values (the
//! first axis varying slowest). A spec is written in TOML (feature `spec`,
//! [`Spec::parse_toml`]):
//!
//! ```toml
//! [variant.soft]                 # a variant named `soft`
//! defines = { PCF_RADIUS = "2", FOG = "" }
//!
//! [axes]                         # 3 x 2 = 6 more variants
//! PCF_RADIUS = ["0", "1", "2"]
//! FOG = [false, true]
//! ```
//!
//! A define's value is a string (`"2"`: `-D PCF_RADIUS=2`; `""`: defined
//! with no value, `-D FOG`), an integer or float (its text), `true`
//! (defined, like `""`) or `false` (not defined).
//!
//! A variant made from axes is named after its values ([`axis_name`]): each
//! axis in the spec's order gives `NAME` lowercased for a define with no
//! value, `NAME_VALUE` for one with a value, nothing for `false`; the parts
//! are joined by `__` and an empty name is `base`. Characters other than
//! ASCII letters, digits and `_` become `_`. `PCF_RADIUS = "2"`,
//! `FOG = true`: `pcf_radius_2__fog`. So names are directory names on every
//! file system and Rust identifiers (`umbrac::build` makes one module per
//! variant), stay the same when the spec gains a value or another named
//! variant, and two variants that would share a name are an error.

use std::fmt;

/// A define: `(NAME, None)` is `-D NAME`, `(NAME, Some(V))` is `-D NAME=V`.
pub type Define = (String, Option<String>);

/// One variant: a name and its defines.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Variant {
    pub name: String,
    pub defines: Vec<Define>,
}

/// A value an axis takes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum AxisValue {
    /// Not defined (`false`).
    Undefined,
    /// Defined, with a value or (`None`) without one.
    Defined(Option<String>),
}

/// One axis: a define name and the values it takes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Axis {
    pub name: String,
    pub values: Vec<AxisValue>,
}

/// What to compile: named variants and axes.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Spec {
    pub named: Vec<Variant>,
    pub axes: Vec<Axis>,
}

/// Why a spec is not valid (names that collide, an empty axis...), and
/// the part of the spec at fault.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SpecError(pub String, pub Place);

/// A part of a spec an error points at: the `[axes]` table, the `n`-th
/// named variant, or the spec as a whole (it names no variant). With the
/// [`SpecSpans`] of a parsed spec, a place in its file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Place {
    Spec,
    Axes,
    Named(usize),
}

/// Where the parts of a spec read from a file are ([`Spec::parse_toml_spanned`]).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct SpecSpans {
    /// The start of the file.
    pub start: crate::source::Span,
    /// The `axes` key.
    pub axes: Option<crate::source::Span>,
    /// Each named variant's name, in the spec's order.
    pub named: Vec<crate::source::Span>,
}

impl SpecSpans {
    /// Where an error at `place` points.
    pub fn of(&self, place: Place) -> crate::source::Span {
        match place {
            Place::Spec => self.start,
            Place::Axes => self.axes.unwrap_or(self.start),
            Place::Named(i) => self.named.get(i).copied().unwrap_or(self.start),
        }
    }
}

impl fmt::Display for SpecError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for SpecError {}

/// The most variants one spec may expand to.
pub const MAX_VARIANTS: usize = 1 << 16;

impl Spec {
    /// Every variant: the named ones, then the product of the axes.
    pub fn expand(&self) -> Result<Vec<Variant>, SpecError> {
        for a in &self.axes {
            if a.values.is_empty() {
                return Err(SpecError(format!("axis `{}` has no values", a.name), Place::Axes));
            }
            if !is_define_name(&a.name) {
                return Err(SpecError(format!("axis `{}` is not a preprocessor name", a.name), Place::Axes));
            }
        }
        let product = self.axes.iter().try_fold(1usize, |n, a| n.checked_mul(a.values.len()).filter(|&n| n <= MAX_VARIANTS));
        let Some(product) = product.filter(|p| p + self.named.len() <= MAX_VARIANTS) else {
            // The axes alone, or with the named variants.
            let place = if product.is_none() { Place::Axes } else { Place::Spec };
            return Err(SpecError(format!("the spec makes more than {MAX_VARIANTS} variants"), place));
        };
        let mut out = self.named.clone();
        for (i, v) in self.named.iter().enumerate() {
            if !is_variant_name(&v.name) {
                return Err(SpecError(format!("variant name `{}` must be ASCII letters, digits and `_`, not starting with a digit", v.name), Place::Named(i)));
            }
            if let Some((n, _)) = v.defines.iter().find(|(n, _)| !is_define_name(n)) {
                return Err(SpecError(format!("`{n}` in variant `{}` is not a preprocessor name", v.name), Place::Named(i)));
            }
        }
        // A variant of `out` by index: a named one, or one of the axes'.
        let place_of = |i: usize| if i < self.named.len() { Place::Named(i) } else { Place::Axes };
        if !self.axes.is_empty() {
            for i in 0..product {
                // Mixed-radix digits, the first axis most significant.
                let mut rest = i;
                let mut picks = vec![0; self.axes.len()];
                for (k, a) in self.axes.iter().enumerate().rev() {
                    picks[k] = rest % a.values.len();
                    rest /= a.values.len();
                }
                let chosen: Vec<(&str, &AxisValue)> = self.axes.iter().zip(&picks).map(|(a, &p)| (a.name.as_str(), &a.values[p])).collect();
                let defines = chosen
                    .iter()
                    .filter_map(|(n, v)| match v {
                        AxisValue::Undefined => None,
                        AxisValue::Defined(val) => Some((n.to_string(), val.clone())),
                    })
                    .collect();
                out.push(Variant { name: axis_name(&chosen), defines });
            }
        }
        let mut names: Vec<(&str, usize)> = out.iter().enumerate().map(|(i, v)| (v.name.as_str(), i)).collect();
        names.sort();
        if let Some(w) = names.windows(2).find(|w| w[0].0 == w[1].0) {
            let (a, b) = (&out[w[0].1], &out[w[1].1]);
            return Err(SpecError(
                format!(
                    "two variants are named `{}` ({} and {}); rename the named one or the values of an axis",
                    a.name,
                    describe(&a.defines),
                    describe(&b.defines)
                ),
                place_of(w[0].1.min(w[1].1)),
            ));
        }
        if out.is_empty() {
            return Err(SpecError("the spec names no variant: add [variant.NAME] tables or an [axes] table".into(), Place::Spec));
        }
        // Each name is a directory's: file systems take at most 255 bytes.
        if let Some((i, v)) = out.iter().enumerate().find(|(_, v)| v.name.len() > MAX_VARIANT_NAME_LEN) {
            let shown: String = v.name.chars().take(48).collect();
            return Err(SpecError(
                format!(
                    "variant `{shown}...` ({}) has a name of {} characters, and names its output directory, which can have at most {MAX_VARIANT_NAME_LEN}: shorten the axes' names or values",
                    describe(&v.defines),
                    v.name.len()
                ),
                place_of(i),
            ));
        }
        Ok(out)
    }
}

/// The longest variant name: it names a directory.
pub const MAX_VARIANT_NAME_LEN: usize = 255;

/// The name of the variant an axis combination makes (module docs).
pub fn axis_name(chosen: &[(&str, &AxisValue)]) -> String {
    let parts: Vec<String> = chosen
        .iter()
        .filter_map(|(name, v)| match v {
            AxisValue::Undefined => None,
            AxisValue::Defined(None) => Some(sanitize(name)),
            AxisValue::Defined(Some(val)) if val.is_empty() => Some(sanitize(name)),
            AxisValue::Defined(Some(val)) => Some(format!("{}_{}", sanitize(name), sanitize(val))),
        })
        .collect();
    if parts.is_empty() {
        "base".into()
    } else {
        parts.join("__")
    }
}

fn sanitize(s: &str) -> String {
    s.chars().map(|c| if c.is_ascii_alphanumeric() { c.to_ascii_lowercase() } else { '_' }).collect()
}

/// `-D A=1 -D B`, or `no defines`.
pub fn describe(defines: &[Define]) -> String {
    if defines.is_empty() {
        return "no defines".into();
    }
    defines
        .iter()
        .map(|(n, v)| match v {
            Some(v) => format!("-D {n}={v}"),
            None => format!("-D {n}"),
        })
        .collect::<Vec<_>>()
        .join(" ")
}

pub fn is_define_name(s: &str) -> bool {
    s.chars().next().is_some_and(|c| c.is_ascii_alphabetic() || c == '_') && s.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
}

/// Variant names: directory names and Rust identifiers alike.
pub fn is_variant_name(s: &str) -> bool {
    is_define_name(s)
}

#[cfg(feature = "spec")]
mod toml_spec {
    use super::*;
    use crate::diag::Diagnostic;
    use crate::source::{SourceMap, Span};
    use toml::de::{DeTable, DeValue};
    use toml::Spanned;

    impl Spec {
        /// Parses a TOML spec held in `map` as file `file` (module docs).
        /// Errors point into it.
        pub fn parse_toml(map: &SourceMap, file: crate::source::FileId) -> Result<Spec, Diagnostic> {
            Self::parse_toml_spanned(map, file).map(|(spec, _)| spec)
        }

        /// [`Spec::parse_toml`], with where its parts are, so that the
        /// errors of [`Spec::expand`] can point into the file too.
        pub fn parse_toml_spanned(map: &SourceMap, file: crate::source::FileId) -> Result<(Spec, SpecSpans), Diagnostic> {
            let f = map.file(file);
            let base = f.base;
            let at = |r: std::ops::Range<usize>| Span::new(base + r.start as u32, base + r.end as u32);
            let doc = DeTable::parse(&f.text).map_err(|e| {
                let span = e.span().map(&at).unwrap_or(Span::new(base, base));
                Diagnostic::error(format!("the variant spec is not valid TOML: {}", e.message().trim_end()), span).with_label("here")
            })?;
            let mut spec = Spec::default();
            let mut spans = SpecSpans { start: Span::new(base, base), ..Default::default() };
            for (key, value) in doc.get_ref() {
                match &**key.get_ref() {
                    "variant" => {
                        let table = value.get_ref().as_table().ok_or_else(|| expected(value, "a table of variants: [variant.NAME]", &at))?;
                        for (name, body) in table {
                            spec.named.push(named_variant(name, body, &at)?);
                            spans.named.push(at(name.span()));
                        }
                    }
                    "axes" => {
                        spans.axes = Some(at(key.span()));
                        let table = value.get_ref().as_table().ok_or_else(|| expected(value, "a table of axes: [axes] NAME = [values]", &at))?;
                        for (name, values) in table {
                            spec.axes.push(axis(name, values, &at)?);
                        }
                    }
                    other => {
                        return Err(Diagnostic::error(format!("unknown key `{other}` in the variant spec"), at(key.span()))
                            .with_label("not `variant` or `axes`")
                            .with_note("a spec has [variant.NAME] tables with `defines = { ... }` and an [axes] table"))
                    }
                }
            }
            Ok((spec, spans))
        }
    }

    fn expected(v: &Spanned<DeValue>, what: &str, at: &impl Fn(std::ops::Range<usize>) -> Span) -> Diagnostic {
        Diagnostic::error(format!("expected {what}, found a {}", v.get_ref().type_str()), at(v.span())).with_label(format!("this is a {}", v.get_ref().type_str()))
    }

    fn named_variant(
        name: &Spanned<toml::de::DeString>,
        body: &Spanned<DeValue>,
        at: &impl Fn(std::ops::Range<usize>) -> Span,
    ) -> Result<Variant, Diagnostic> {
        let n: &str = name.get_ref();
        if !is_variant_name(n) {
            return Err(Diagnostic::error(format!("variant name `{n}` is not usable as a directory and module name"), at(name.span()))
                .with_label("ASCII letters, digits and `_`, not starting with a digit"));
        }
        let table = body.get_ref().as_table().ok_or_else(|| expected(body, "a table with `defines = { ... }`", at))?;
        let mut defines = Vec::new();
        for (k, v) in table {
            if &**k.get_ref() != "defines" {
                return Err(Diagnostic::error(format!("unknown key `{}` in variant `{n}`", k.get_ref()), at(k.span())).with_label("only `defines` is known"));
            }
            let d = v.get_ref().as_table().ok_or_else(|| expected(v, "a table of defines: { NAME = \"VALUE\" }", at))?;
            for (dn, dv) in d {
                define_name(dn, at)?;
                match value(dv, at)? {
                    AxisValue::Undefined => {}
                    AxisValue::Defined(val) => defines.push((dn.get_ref().to_string(), val)),
                }
            }
        }
        Ok(Variant { name: n.to_string(), defines })
    }

    fn axis(name: &Spanned<toml::de::DeString>, values: &Spanned<DeValue>, at: &impl Fn(std::ops::Range<usize>) -> Span) -> Result<Axis, Diagnostic> {
        define_name(name, at)?;
        let list = values.get_ref().as_array().ok_or_else(|| expected(values, "an array of values: [\"0\", \"1\"] or [false, true]", at))?;
        if list.is_empty() {
            return Err(Diagnostic::error(format!("axis `{}` has no values", name.get_ref()), at(values.span())).with_label("empty"));
        }
        let mut out = Vec::new();
        for v in list {
            let parsed = value(v, at)?;
            if out.contains(&parsed) {
                return Err(Diagnostic::error(format!("axis `{}` lists a value twice", name.get_ref()), at(v.span())).with_label("again here"));
            }
            out.push(parsed);
        }
        Ok(Axis { name: name.get_ref().to_string(), values: out })
    }

    fn define_name(name: &Spanned<toml::de::DeString>, at: &impl Fn(std::ops::Range<usize>) -> Span) -> Result<(), Diagnostic> {
        if is_define_name(name.get_ref()) {
            Ok(())
        } else {
            Err(Diagnostic::error(format!("`{}` is not a preprocessor name", name.get_ref()), at(name.span())).with_label("letters, digits and `_`, not starting with a digit"))
        }
    }

    fn value(v: &Spanned<DeValue>, at: &impl Fn(std::ops::Range<usize>) -> Span) -> Result<AxisValue, Diagnostic> {
        Ok(match v.get_ref() {
            DeValue::String(s) if s.is_empty() => AxisValue::Defined(None),
            DeValue::String(s) => {
                if s.contains(['\n', '\r']) {
                    return Err(Diagnostic::error("a define's value must be one line", at(v.span())).with_label("has a line break"));
                }
                AxisValue::Defined(Some(s.to_string()))
            }
            DeValue::Integer(i) => AxisValue::Defined(Some(i.as_str().to_string())),
            DeValue::Float(f) => AxisValue::Defined(Some(f.as_str().to_string())),
            DeValue::Boolean(true) => AxisValue::Defined(None),
            DeValue::Boolean(false) => AxisValue::Undefined,
            _ => return Err(expected(v, "a string, a number or a boolean", at)),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn d(v: &str) -> AxisValue {
        AxisValue::Defined(if v.is_empty() { None } else { Some(v.into()) })
    }

    #[test]
    fn the_product_is_named_after_its_values_first_axis_slowest() {
        let spec = Spec {
            named: vec![Variant { name: "soft".into(), defines: vec![("PCF_RADIUS".into(), Some("2".into()))] }],
            axes: vec![
                Axis { name: "PCF_RADIUS".into(), values: vec![d("0"), d("1"), d("2")] },
                Axis { name: "FOG".into(), values: vec![AxisValue::Undefined, d("")] },
            ],
        };
        let v = spec.expand().unwrap();
        let names: Vec<&str> = v.iter().map(|v| v.name.as_str()).collect();
        assert_eq!(names, ["soft", "pcf_radius_0", "pcf_radius_0__fog", "pcf_radius_1", "pcf_radius_1__fog", "pcf_radius_2", "pcf_radius_2__fog"]);
        assert_eq!(v[2].defines, [("PCF_RADIUS".to_string(), Some("0".to_string())), ("FOG".to_string(), None)]);
        assert_eq!(describe(&v[2].defines), "-D PCF_RADIUS=0 -D FOG");
    }

    #[test]
    fn all_off_is_base_and_odd_values_stay_safe() {
        let spec = Spec { named: vec![], axes: vec![Axis { name: "Q".into(), values: vec![AxisValue::Undefined, d("1.5"), d("a/b")] }] };
        let names: Vec<String> = spec.expand().unwrap().into_iter().map(|v| v.name).collect();
        assert_eq!(names, ["base", "q_1_5", "q_a_b"]);
        for n in &names {
            assert!(is_variant_name(n), "{n}");
        }
    }

    #[test]
    fn a_name_too_long_for_a_directory_is_an_error() {
        let long = "V".repeat(200);
        let spec = Spec { named: vec![], axes: vec![Axis { name: long.clone(), values: vec![d("1")] }, Axis { name: "B".into(), values: vec![d("")] }] };
        assert!(spec.expand().is_ok(), "203 characters fit");
        let spec = Spec { named: vec![], axes: vec![Axis { name: long.clone(), values: vec![d("1")] }, Axis { name: "C".repeat(60), values: vec![d("")] }] };
        let e = spec.expand().unwrap_err();
        assert!(e.0.contains("has a name of 264 characters") && e.0.contains("at most 255"), "{e}");
    }

    #[test]
    fn colliding_names_and_empty_specs_are_errors() {
        let spec = Spec { named: vec![], axes: vec![Axis { name: "Q".into(), values: vec![d("a-b"), d("a_b")] }] };
        let e = spec.expand().unwrap_err();
        assert!(e.0.contains("two variants are named `q_a_b`") && e.0.contains("-D Q=a-b") && e.0.contains("-D Q=a_b"), "{e}");
        let spec = Spec { named: vec![Variant { name: "base".into(), defines: vec![] }], axes: vec![Axis { name: "A".into(), values: vec![AxisValue::Undefined] }] };
        assert!(spec.expand().unwrap_err().0.contains("`base`"));
        assert!(Spec::default().expand().unwrap_err().0.contains("names no variant"));
        let spec = Spec { named: vec![], axes: (0..17).map(|i| Axis { name: format!("A{i}"), values: vec![d("0"), d("1")] }).collect() };
        assert!(spec.expand().unwrap_err().0.contains("more than"));
    }

    #[cfg(feature = "spec")]
    #[test]
    fn toml_specs_parse_and_errors_point_into_them() {
        let parse = |text: &str| {
            let mut map = crate::SourceMap::new();
            let id = map.add("v.toml", None, text.to_string(), None);
            Spec::parse_toml(&map, id).map_err(|d| d.render(&map))
        };
        let spec = parse("[variant.soft]\ndefines = { PCF_RADIUS = \"2\", FOG = \"\", N = 3, OFF = false }\n\n[axes]\nPCF_RADIUS = [\"0\", 1]\nFOG = [false, true]\n").unwrap();
        assert_eq!(spec.named[0].defines, [("PCF_RADIUS".into(), Some("2".into())), ("FOG".into(), None), ("N".into(), Some("3".into()))]);
        assert_eq!(spec.axes[0], Axis { name: "PCF_RADIUS".into(), values: vec![d("0"), d("1")] });
        assert_eq!(spec.axes[1].values, [AxisValue::Undefined, d("")]);
        assert_eq!(spec.expand().unwrap().len(), 5);

        let e = parse("[axes]\nFOG = [false, [1]]\n").unwrap_err();
        assert!(e.contains("v.toml:2:15") && e.contains("a string, a number or a boolean"), "{e}");
        let e = parse("[axes]\nFOG = [true, true]\n").unwrap_err();
        assert!(e.contains("v.toml:2:14") && e.contains("twice"), "{e}");
        let e = parse("[variants.x]\n").unwrap_err();
        assert!(e.contains("v.toml:1:2") && e.contains("unknown key `variants`"), "{e}");
        let e = parse("[variant.\"a b\"]\ndefines = {}\n").unwrap_err();
        assert!(e.contains("v.toml:1:10") && e.contains("`a b`"), "{e}");
        let e = parse("[axes\n").unwrap_err();
        assert!(e.contains("v.toml:1:") && e.contains("not valid TOML"), "{e}");
        let e = parse("[variant.x]\ndefine = { A = \"1\" }\n").unwrap_err();
        assert!(e.contains("v.toml:2:1") && e.contains("unknown key `define`"), "{e}");
    }
}
