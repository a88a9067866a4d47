//! Issue 17, on the device: daslang's math module, matrix conversions,
//! packing, vector shifts, folded constants and `half` computed by every
//! consumer (tests/gpu/programs.rs). Expected values are computed here in
//! Rust, independently of the compiler's own constant folder, and the
//! folder's constants are compared with what the GPU computes at run time.

use super::programs::{assert_all_hold, assert_all_hold_for};

/// daslang's `uint32_hash` / `uint_noise_1D` (dag_uint_noise.h), written
/// out again for the expected values.
fn eiserloh(position: u32, seed: u32) -> u32 {
    let mut m = position.wrapping_mul(0x68E3_1DA4).wrapping_add(seed);
    m ^= m >> 8;
    m = m.wrapping_add(0xB529_7A4D);
    m ^= m << 8;
    m = m.wrapping_mul(0x1B56_C4E9);
    m ^ (m >> 8)
}

#[test]
fn math_module_functions_compute_daslangs_values() {
    let decls = "def sc(a : float) : float2 {\n    var s, c : float\n    sincos(a, s, c)\n    return float2(s, c)\n}\n\ndef near(a, b : float) : bool {\n    return abs(a - b) <= 1e-6 * max(1.0, abs(b))\n}";
    assert_all_hold(
        "math_module",
        decls,
        &[
            "mad(2.0 + fz, 3.0, 1.0) == 7.0",
            "mad(float2(1.0, 2.0) + fz, 3.0, float2(1.0)) == float2(4.0, 7.0)",
            "mad(int3(2) + z, int3(3), int3(-1)) == int3(5)",
            "length_sq(float3(1.0, 2.0, 2.0) + fz) == 9.0",
            "distance_sq(float2(4.0, 1.0) + fz, float2(1.0, -3.0)) == 25.0",
            "near(inv_length(float2(3.0, 4.0) + fz), 0.2)",
            "near(inv_length_sq(float2(3.0, 4.0) + fz), 0.04)",
            "near(inv_distance(float3(2.0, 3.0, 6.0) + fz, float3(0.0)), 1.0 / 7.0)",
            "near(inv_distance_sq(float3(2.0, 3.0, 6.0) + fz, float3(0.0)), 1.0 / 49.0)",
            "near(fast_normalize(float2(0.0, 5.0) + fz).y, 1.0)",
            "near(rcp_est(4.0 + fz), 0.25) && near(rsqrt_est(16.0 + fz), 0.25)",
            "floori(-1.5 + fz) == -2 && ceili(-1.5 + fz) == -1 && trunci(-1.7 + fz) == -1",
            // daslang's roundi rounds half to even, like the SSE conversion.
            "roundi(2.5 + fz) == 2 && roundi(3.5 + fz) == 4 && roundi(-2.5 + fz) == -2",
            "floori(float2(1.5, -0.5) + fz) == int2(1, -1)",
            "near(sc(fz).x, 0.0) && near(sc(fz).y, 1.0) && near(sc(PI * 0.5 + fz).x, 1.0)",
            "identity3x3() * (float3(1.0, 2.0, 3.0) + fz) == float3(1.0, 2.0, 3.0)",
            "identity4x4()[3] == float4(0.0, 0.0, 0.0, 1.0) + fz",
            "PI == 3.14159265 + fz && FLT_EPSILON == 1.1920929e-7 + fz",
            "INT_MAX - z == 2147483647 && UINT_MAX - uz == 4294967295u && INT_MIN + z == -2147483647 - 1",
            "float_bits_to_uint(1.0 + fz) == 0x3F800000u && int_bits_to_float(0x40000000 + z) == 2.0",
        ],
    );
}

#[test]
fn noise_hashes_match_daslang_and_the_constant_folder() {
    // uint32_hash has no seed: the seed-free mixing, as daslang's header.
    let hash = |v: u32| {
        let mut m = v.wrapping_mul(0x68E3_1DA4);
        m ^= m >> 8;
        m = m.wrapping_add(0xB529_7A4D);
        m ^= m << 8;
        m = m.wrapping_mul(0x1B56_C4E9);
        m ^ (m >> 8)
    };
    let n1 = eiserloh((-7i32) as u32, 3);
    let n2 = eiserloh((-3i32).wrapping_add(198_491_317i32.wrapping_mul(7)) as u32, 11);
    let n3 = eiserloh(5i32.wrapping_add(198_491_317i32.wrapping_mul(-2)).wrapping_add(6_542_989i32.wrapping_mul(1000)) as u32, 0xDEAD_BEEF);
    let decls = "let H = uint32_hash(123456789u)\nlet N2 = uint_noise_2D(int2(-3, 7), 11u)";
    let checks = [
        format!("uint32_hash(123456789u + uz) == {}u", hash(123_456_789)),
        format!("uint32_hash(0u + uz) == {}u", hash(0)),
        format!("uint_noise_1D(-7 + z, 3u) == {n1}u"),
        format!("uint_noise_2D(int2(-3, 7) + int2(z), 11u) == {n2}u"),
        format!("uint_noise_3D(int3(5, -2, 1000) + int3(z), 0xDEADBEEFu) == {n3}u"),
        // The compiler's folded constants are the GPU's values.
        "uint32_hash(123456789u + uz) == H".to_string(),
        "uint_noise_2D(int2(-3, 7) + int2(z), 11u) == N2".to_string(),
    ];
    let list: Vec<&str> = checks.iter().map(String::as_str).collect();
    assert_all_hold("noise_hashes", decls, &list);
}

#[test]
fn pack_and_unpack_agree_on_every_target() {
    let decls = "let PH = packHalf2x16(float2(0.1, 3.14159))\nlet PU = packUnorm4x8(float4(0.2, 0.4, 0.6, 0.8))\nlet PS = packSnorm2x16(float2(-0.3, 0.7))";
    assert_all_hold(
        "packing",
        decls,
        &[
            "packUnorm4x8(float4(0.0, 1.0, 0.5, 2.0) + fz) == 0xFF80FF00u",
            "packSnorm4x8(float4(-1.0, 1.0, 0.0, -2.0) + fz) == 0x81007F81u",
            "packUnorm2x16(float2(0.0, 1.0) + fz) == 0xFFFF0000u",
            "packSnorm2x16(float2(-1.0, 0.5) + fz) == 0x40008001u",
            "packHalf2x16(float2(1.0, -2.0) + fz) == 0xC0003C00u",
            // Subnormal, ties to even, the largest half and overflow.
            "packHalf2x16(float2(5.9604645e-8, 0.0) + fz) == 0x00000001u",
            "packHalf2x16(float2(1.00048828125, 1.00146484375) + fz) == 0x3C023C00u",
            "packHalf2x16(float2(65504.0, 65520.0) + fz) == 0x7C007BFFu",
            "packHalf2x16(float2(0.0, 0.333333333) + fz) == 0x35550000u",
            "unpackHalf2x16(0x3C00u + uz).x == 1.0 && unpackHalf2x16(0x00000001u + uz).x == 5.9604645e-8",
            "unpackHalf2x16((0xFC00u << 16u) + uz).y < -65504.0 && unpackHalf2x16(0x7BFFu + uz).x == 65504.0",
            "unpackUnorm4x8(0xFF800000u + uz) == float4(0.0, 0.0, 128.0 / 255.0, 1.0)",
            // -128 clamps to -1, like -127.
            "unpackSnorm4x8(0x7F810080u + uz).x == -1.0 && unpackSnorm4x8(0x7F810080u + uz).z == -1.0 && unpackSnorm4x8(0x7F810080u + uz).w == 1.0",
            "unpackUnorm2x16(0xFFFF0000u + uz) == float2(0.0, 1.0) && unpackSnorm2x16(0x80007FFFu + uz) == float2(1.0, -1.0)",
            // The compiler's folded constants are the GPU's values.
            "packHalf2x16(float2(0.1, 3.14159) + fz) == PH",
            "packUnorm4x8(float4(0.2, 0.4, 0.6, 0.8) + fz) == PU",
            "packSnorm2x16(float2(-0.3, 0.7) + fz) == PS",
        ],
    );
}

#[test]
fn matrices_from_matrices_follow_glsl() {
    let decls = "def m4(k : float) : float4x4 {\n    return float4x4(float4(1.0, 2.0, 3.0, 4.0) + k, float4(5.0, 6.0, 7.0, 8.0), float4(9.0, 10.0, 11.0, 12.0), float4(13.0, 14.0, 15.0, 16.0))\n}\nlet C3 = float3x3(float4x4(2.0))";
    assert_all_hold(
        "matrix_conversions",
        decls,
        &[
            "float3x3(m4(fz))[2] == float3(9.0, 10.0, 11.0)",
            "float3x3(m4(fz))[0] == float3(1.0, 2.0, 3.0)",
            "float2x3(m4(fz))[1] == float3(5.0, 6.0, 7.0)",
            "float4x4(float2x2(m4(fz)))[1] == float4(5.0, 6.0, 0.0, 0.0)",
            "float4x4(float2x2(m4(fz)))[2] == float4(0.0, 0.0, 1.0, 0.0)",
            "float4x4(float3x2(m4(fz)))[3] == float4(0.0, 0.0, 0.0, 1.0)",
            "float3x4(float2x2(m4(fz)))[2] == float4(0.0, 0.0, 1.0, 0.0)",
            "(-m4(fz))[0] == float4(-1.0, -2.0, -3.0, -4.0)",
            "C3[1] == float3(0.0, 2.0, 0.0) + fz",
        ],
    );
}

#[test]
fn integer_vectors_shift_by_a_scalar() {
    assert_all_hold(
        "vector_shifts",
        "",
        &[
            "(int3(1, 2, 3) + int3(z)) << 2 == int3(4, 8, 12)",
            "(uint4(256u) + uz) >> (4u + uz) == uint4(16u)",
            "(int2(-16, 16) + z) >> 2 == int2(-4, 4)",
            "(uint2(1u, 3u) + uz) << (31 + z) == uint2(0x80000000u)",
        ],
    );
}

#[test]
fn folded_constants_arrive_bit_exact() {
    // normalize, cos(radians(x)) and mix rounded once from f64: what the
    // folder must produce, computed here without it.
    let (x, y, z) = (0.45f32 as f64, 0.55f32 as f64, 0.85f32 as f64);
    let len = (x * x + y * y + z * z).sqrt();
    let sun: Vec<u32> = [x, y, z].iter().map(|c| ((c / len) as f32).to_bits()).collect();
    let cone = ((12.5f32 as f64) * (std::f64::consts::PI / 180.0)).cos() as f32;
    let sky = ((0.18f32 as f64) * (1.0 - 0.25) + (0.88f32 as f64) * 0.25) as f32;
    let decls = "let SUN : float3 = normalize(float3(0.45, 0.55, 0.85))\nlet CONE = cos(radians(12.5))\nlet SKY = mix(0.18, 0.88, 0.25)";
    let checks = [
        format!("floatBitsToUint(SUN.x + fz) == {}u", sun[0]),
        format!("floatBitsToUint(SUN.y + fz) == {}u", sun[1]),
        format!("floatBitsToUint(SUN.z + fz) == {}u", sun[2]),
        format!("floatBitsToUint(CONE + fz) == {}u", cone.to_bits()),
        format!("floatBitsToUint(SKY + fz) == {}u", sky.to_bits()),
        // And the GPU's own normalize is close to it.
        "abs(normalize(float3(0.45, 0.55, 0.85) + fz).y - SUN.y) < 1e-6".to_string(),
    ];
    let list: Vec<&str> = checks.iter().map(String::as_str).collect();
    assert_all_hold("folded_constants", decls, &list);
}

#[test]
fn half_computes_on_wgsl_and_spirv() {
    let opts = umbrac::Options { targets: vec![umbrac::Target::Wgsl, umbrac::Target::Spirv], ..Default::default() };
    let Some(r) = crate::support::gpu::vulkan() else { return };
    if !r.device().0.features().contains(wgpu::Features::SHADER_F16) {
        crate::support::skip("the Vulkan device lacks SHADER_F16: half not run");
        return;
    }
    let decls = "let THIRD = 1.0h / 3.0h\ndef tone(c : half3) : half3 {\n    return c / (c + half3(1.0h))\n}";
    assert_all_hold_for(
        "half",
        decls,
        &[
            // 1/3 in binary16 is 0x3555: 0.333251953125.
            "float(half(fz) + 1.0h / 3.0h) == 0.333251953125",
            "float(THIRD + half(fz)) == 0.333251953125",
            "tone(half3(1.0h) + half3(half(fz))) == half3(0.5h)",
            "float(half(2049.0 + fz)) == 2048.0",
            "float(half(65504.0 + fz)) == 65504.0",
            "float(sqrt(half(2.0 + fz))) == 1.4140625",
            "float(max(half2(0.25h, -1.0h) + half2(half(fz)), half2(0.0h)).x) == 0.25",
        ],
        &opts,
    );
}
