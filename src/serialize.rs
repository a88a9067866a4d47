//! `serde::Serialize` for umbrac's JSON types (the reflection manifest,
//! `--message-format json` diagnostics) without serde's derive macro.
//!
//! A build-dependency on umbrac would otherwise compile serde_derive (and
//! serde) for a handful of plain structs. `serialize_struct!` writes the
//! impl the derive would: the fields in the order listed, under the JSON
//! keys given, with `?` marking an `Option` field that is left out when
//! `None` (the derive's `skip_serializing_if = "Option::is_none"`). The
//! traits come from `serde_core`, which serde re-exports: these are the
//! `serde::Serialize` impls users see.

/// `serialize_struct!(Type { "key": field, "other": optional_field?, })`:
/// every field, in output order, followed by a comma.
macro_rules! serialize_struct {
    (@len $this:ident;) => {
        0usize
    };
    (@len $this:ident; $key:literal : $field:ident ?, $($rest:tt)*) => {
        usize::from($this.$field.is_some()) + serialize_struct!(@len $this; $($rest)*)
    };
    (@len $this:ident; $key:literal : $field:ident, $($rest:tt)*) => {
        1 + serialize_struct!(@len $this; $($rest)*)
    };
    (@fields $s:ident $this:ident;) => {};
    (@fields $s:ident $this:ident; $key:literal : $field:ident ?, $($rest:tt)*) => {
        match &$this.$field {
            Some(value) => $s.serialize_field($key, value)?,
            None => $s.skip_field($key)?,
        }
        serialize_struct!(@fields $s $this; $($rest)*);
    };
    (@fields $s:ident $this:ident; $key:literal : $field:ident, $($rest:tt)*) => {
        $s.serialize_field($key, &$this.$field)?;
        serialize_struct!(@fields $s $this; $($rest)*);
    };
    ($ty:ident { $($fields:tt)* }) => {
        impl serde_core::Serialize for $ty {
            fn serialize<S: serde_core::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
                use serde_core::ser::SerializeStruct;
                let mut s = serializer.serialize_struct(stringify!($ty), serialize_struct!(@len self; $($fields)*))?;
                serialize_struct!(@fields s self; $($fields)*);
                s.end()
            }
        }
    };
}
