//! What each builtin function means, in a line, and the texture functions'
//! signatures (the table in `builtins.rs` has none for them: their checks
//! depend on the sampler). An editor shows these on hover, in signature
//! help and in completion (`crate::workspace`).

/// A builtin function's meaning, in a line.
pub fn meaning(name: &str) -> Option<&'static str> {
    Some(match name {
        "sin" | "cos" | "tan" => "the trigonometric function of an angle in radians, per component",
        "asin" | "acos" => "the inverse sine or cosine, in radians, per component; undefined outside [-1, 1]",
        "atan" => "the arc tangent, in radians in [-π/2, π/2], per component",
        "atan2" => "atan2(y, x): the angle of the point (x, y), in radians in [-π, π], per component",
        "sinh" | "cosh" | "tanh" => "the hyperbolic function, per component",
        "radians" => "degrees to radians, per component",
        "degrees" => "radians to degrees, per component",
        "exp" => "e raised to the argument, per component",
        "exp2" => "2 raised to the argument, per component",
        "log" => "the natural logarithm, per component; undefined for x <= 0",
        "log2" => "the base-2 logarithm, per component; undefined for x <= 0",
        "sqrt" => "the square root, per component; undefined for x < 0",
        "inversesqrt" | "rsqrt" => "1 / sqrt(x), per component; undefined for x <= 0",
        "floor" => "the largest whole number not above x, per component",
        "ceil" => "the smallest whole number not below x, per component",
        "fract" => "x - floor(x), per component",
        "trunc" => "x rounded toward zero, per component",
        "round" => "x rounded to the nearest whole number (halves: to even on every target), per component",
        "roundEven" => "x rounded to the nearest whole number, halves to even, per component",
        "abs" => "the absolute value, per component",
        "sign" => "-1, 0 or 1 by the sign of x, per component",
        "min" => "the smaller of two values, per component (NaN: undefined)",
        "max" => "the larger of two values, per component (NaN: undefined)",
        "clamp" => "clamp(x, lo, hi): min(max(x, lo), hi), per component; undefined when lo > hi",
        "saturate" => "clamp(x, 0, 1), per component",
        "rcp" => "1 / x, per component",
        "mix" | "lerp" => "mix(a, b, t): a * (1 - t) + b * t, the linear blend, per component",
        "step" => "step(edge, x): 0 where x < edge, else 1, per component",
        "smoothstep" => "smoothstep(lo, hi, x): 0 below lo, 1 above hi, a Hermite curve between; undefined when lo >= hi",
        "pow" => "x raised to y, per component; undefined for x < 0, or x = 0 with y <= 0",
        "mod" => "x - y * floor(x / y), GLSL's modulo (the sign of y), per component",
        "fma" => "fma(a, b, c): a * b + c, per component",
        "length" => "the length of a vector, sqrt(dot(v, v))",
        "distance" => "the distance between two points, length(a - b)",
        "dot" => "the dot product of two vectors",
        "cross" => "the cross product of two float3",
        "normalize" | "fast_normalize" => "the vector scaled to length 1; undefined for a zero vector",
        "reflect" => "reflect(i, n): i reflected about the unit normal n, i - 2 * dot(n, i) * n",
        "refract" => "refract(i, n, eta): i refracted through the surface with unit normal n at index ratio eta; zero on total internal reflection",
        "faceforward" => "faceforward(n, i, nref): n if dot(nref, i) < 0, else -n",
        "transpose" => "the transposed matrix",
        "determinant" => "the determinant of a square matrix",
        "inverse" => "the inverse of a square matrix (umbrac writes a helper where a target lacks one); undefined if singular",
        "any" => "true if any component is true",
        "all" => "true if every component is true",
        "not" => "the component-wise logical negation",
        "lessThan" | "lessThanEqual" | "greaterThan" | "greaterThanEqual" | "equal" | "notEqual" => "the component-wise comparison, a boolean vector",
        "floatBitsToInt" | "float_bits_to_int" => "the bits of a float as an int, per component",
        "floatBitsToUint" | "float_bits_to_uint" => "the bits of a float as a uint, per component",
        "intBitsToFloat" | "int_bits_to_float" => "the bits of an int as a float, per component",
        "uintBitsToFloat" | "uint_bits_to_float" => "the bits of a uint as a float, per component",
        "dFdx" => "the rate of change of a value across the screen in x (fragment entry points only)",
        "dFdy" => "the rate of change of a value across the screen in y (fragment entry points only)",
        "fwidth" => "abs(dFdx(p)) + abs(dFdy(p)) (fragment entry points only)",
        "rcp_est" => "1 / x, daslang's estimate (exact on GPUs), per component",
        "rsqrt_est" => "1 / sqrt(x), daslang's estimate (exact on GPUs), per component",
        "atan_est" => "the arc tangent, daslang's estimate (exact on GPUs), per component",
        "atan2_est" => "atan2(y, x), daslang's estimate (exact on GPUs), per component",
        "mad" => "mad(a, b, c): a * b + c, daslang's multiply-add, per component",
        "length_sq" => "the squared length of a vector, dot(v, v)",
        "distance_sq" => "the squared distance between two points",
        "inv_length" => "1 / length(v)",
        "inv_length_sq" => "1 / dot(v, v)",
        "inv_distance" => "1 / distance(a, b)",
        "inv_distance_sq" => "1 / the squared distance between a and b",
        "floori" => "floor(x) as an int, per component",
        "ceili" => "ceil(x) as an int, per component",
        "roundi" => "round(x) as an int, per component",
        "trunci" => "trunc(x) as an int, per component",
        "uint32_hash" => "daslang's 32-bit integer hash of a uint",
        "uint_noise_1D" | "uint_noise_2D" | "uint_noise_3D" => "daslang's integer noise of a position and a seed, a uint",
        "identity2x2" | "identity3x3" | "identity4x4" => "the identity matrix",
        "packUnorm4x8" => "a float4 in [0, 1] as four 8-bit unsigned normalized values in a uint",
        "packSnorm4x8" => "a float4 in [-1, 1] as four 8-bit signed normalized values in a uint",
        "packUnorm2x16" => "a float2 in [0, 1] as two 16-bit unsigned normalized values in a uint",
        "packSnorm2x16" => "a float2 in [-1, 1] as two 16-bit signed normalized values in a uint",
        "packHalf2x16" => "a float2 as two half floats in a uint",
        "unpackUnorm4x8" => "a uint's four 8-bit unsigned normalized values as a float4 in [0, 1]",
        "unpackSnorm4x8" => "a uint's four 8-bit signed normalized values as a float4 in [-1, 1]",
        "unpackUnorm2x16" => "a uint's two 16-bit unsigned normalized values as a float2 in [0, 1]",
        "unpackSnorm2x16" => "a uint's two 16-bit signed normalized values as a float2 in [-1, 1]",
        "unpackHalf2x16" => "a uint's two half floats as a float2",
        "texture" => "samples a texture with filtering at coordinates (implicit level of detail; an optional bias)",
        "textureLod" => "samples a texture at an explicit level of detail",
        "textureGrad" => "samples a texture with explicit derivatives of the coordinates (not on shadow samplers)",
        "textureCompare" => "a shadow sampler's depth comparison of `ref` against the texture, filtered: 0 to 1",
        "textureProj" => "samples with the coordinates divided by their last component",
        "texelFetch" => "reads one texel by integer coordinates and level, unfiltered",
        "textureSize" => "the size of a texture's level in texels",
        "textureOffset" => "texture() with a constant texel offset in [-8, 7]",
        "textureLodOffset" => "textureLod() with a constant texel offset in [-8, 7]",
        "textureCompareOffset" => "textureCompare() with a constant texel offset in [-8, 7]",
        "texelFetchOffset" => "texelFetch() with a constant texel offset in [-8, 7]",
        _ => return None,
    })
}

/// A texture function's forms (`sampler` stands for any sampler type the
/// function takes; docs/language.md, "Textures").
pub fn texture_signatures(name: &str) -> &'static [&'static str] {
    match name {
        "texture" => &["texture(s : sampler, uv : floatN) : float4", "texture(s : sampler, uv : floatN, bias : float) : float4"],
        "textureLod" => &["textureLod(s : sampler, uv : floatN, lod : float) : float4"],
        "textureGrad" => &["textureGrad(s : sampler, uv : floatN, dPdx : floatN, dPdy : floatN) : float4"],
        "textureCompare" => &["textureCompare(s : samplerShadow, uv : floatN, ref : float) : float"],
        "textureProj" => &["textureProj(s : sampler2D, uvq : float3/float4) : float4", "textureProj(s : sampler2DShadow, uvq : float4) : float"],
        "texelFetch" => &["texelFetch(s : sampler, icoord : intN, lod : int) : float4"],
        "textureSize" => &["textureSize(s : sampler, lod : int) : intN"],
        "textureOffset" => &["textureOffset(s : sampler, uv : floatN, offset : intN) : float4", "textureOffset(s : sampler, uv : floatN, offset : intN, bias : float) : float4"],
        "textureLodOffset" => &["textureLodOffset(s : sampler, uv : floatN, lod : float, offset : intN) : float4"],
        "textureCompareOffset" => &["textureCompareOffset(s : samplerShadow, uv : floatN, ref : float, offset : intN) : float"],
        "texelFetchOffset" => &["texelFetchOffset(s : sampler, icoord : intN, lod : int, offset : intN) : float4"],
        _ => &[],
    }
}

#[cfg(test)]
mod tests {
    /// A builtin added to the table needs a line here too, and a texture
    /// function its forms.
    #[test]
    fn every_builtin_has_a_meaning_and_a_signature() {
        for name in super::super::builtins::all_names() {
            assert!(super::meaning(name).is_some(), "builtin `{name}` has no meaning in sema/builtin_docs.rs");
            assert!(!super::super::builtins::signatures(name).is_empty(), "builtin `{name}` has no signature");
        }
    }
}
